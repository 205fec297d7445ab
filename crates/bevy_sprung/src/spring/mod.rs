//! The mechanism every property shares: the spring component, its step, the systems that run
//! it, the schedule and sets they run in, and the events springs trigger. Everything built on
//! springs (choreography, groups, interaction, assets, juice, followers) stands on this module
//! and joins its sets or observes its events; this module imports none of them.
//!
//! Its public side is the components (`component`), the schedule and sets (`schedule`), the
//! events (`event`) and the plugins (`plugin`); its systems (`systems`) are the ECS side of the
//! private step kernel (`kernel`), whose module docs hold a spring's life cycle and the
//! invariants of its step.

mod component;
mod event;
mod first_use;
mod kernel;
mod misconfigured;
mod plugin;
mod preference;
mod schedule;
mod skip;
mod systems;

pub use component::target_mut::SpringTargetMut;
pub use component::{PropertySpring, SpringAsleep, SpringForecast, SpringInputError, SpringMotion};
pub use event::{SpringSettled, SpringWoke};
pub use plugin::{SpringPropertyStepPlugin, SpringSchedulePlugin};
pub use preference::{KeepMotion, ReducedMotion};
pub use schedule::{PropertySystems, SpringPhase, SpringSystems, SpringUpdate};
pub use skip::SkipFrames;

pub(crate) use event::{property_event, trigger_if_alive};
pub(crate) use first_use::{add_property_systems, add_systems_on_first_use, first_use};
#[cfg_attr(
    not(feature = "camera"),
    expect(
        unused_imports,
        reason = "only the camera rig names what it lacks by filters"
    )
)]
pub(crate) use misconfigured::warn_lacking;
pub(crate) use misconfigured::warn_missing;
pub(crate) use plugin::{is_registered, spring_schedule};
