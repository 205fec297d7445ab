//! The spring component: its configuration ([`PropertySpring`], in `config`), its motion
//! ([`SpringMotion`], in `motion`, with its slot ticket in `ticket`) and its sleep marker
//! ([`SpringAsleep`]). Beside them: retargeting through change detection (`target_mut`) and the
//! file form (`serde_impls`). The kernel (`spring::kernel`) steps the motion and states the
//! invariants that tie the two.

mod asleep;
mod config;
mod motion;
#[cfg(feature = "serde")]
mod serde_impls;
pub(super) mod target_mut;
mod ticket;

pub use asleep::SpringAsleep;
pub use config::{PropertySpring, SpringInputError};
pub use motion::SpringMotion;
pub(super) use motion::rest_squared;
#[cfg(test)]
pub(super) use ticket::SlotTicket;
