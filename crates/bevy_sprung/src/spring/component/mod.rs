//! The spring component: its configuration ([`PropertySpring`], in `config`), its motion
//! ([`SpringMotion`], in `motion`, with its slot ticket in `ticket`), its sleep marker
//! ([`SpringAsleep`]) and its future ([`SpringForecast`], in `forecast`). Beside them: retargeting through change detection (`target_mut`) and the
//! file form (`serde_impls`). The kernel (`spring::kernel`) steps the motion and states the
//! invariants that tie the two.

mod asleep;
mod config;
mod forecast;
mod motion;
#[cfg(feature = "serde")]
mod serde_impls;
pub(super) mod target_mut;
mod ticket;

pub use asleep::SpringAsleep;
pub use config::{PropertySpring, SpringInputError};
pub use forecast::SpringForecast;
pub use motion::SpringMotion;
pub(super) use motion::rest_squared;
#[cfg(test)]
pub(super) use ticket::SlotTicket;
