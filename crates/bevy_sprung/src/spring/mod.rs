//! The mechanism every property shares: the spring component, its step, the systems that run
//! it, the set they run in, and the event a settled spring triggers.

mod cache;
mod component;
mod event;
mod parallel;
mod plugin;
mod systems;
mod table;
#[cfg(test)]
mod tests;

pub use component::{
    PropertySpring, SpringAsleep, SpringInputError, SpringMotion, SpringTargetMut,
};
pub use event::SpringSettled;
pub use plugin::{
    PropertySystems, SpringPropertyPlugin, SpringSchedulePlugin, SpringSystems, SpringUpdate,
};

pub(crate) use event::trigger_if_alive;
pub(crate) use plugin::{
    add_property_systems, add_systems_on_first_use, first_use, spring_schedule,
};
pub(crate) use systems::step_springs;
