//! Reduced motion: springs that honour the user's accessibility preference.
//!
//! [`ReducedMotion`] (a resource: snap, no overshoot, or slower) and [`KeepMotion`] (a
//! component that opts an entity's springs out) are modes of the spring step itself; this
//! module registers them. Wire the preference from the platform's accessibility setting or
//! the app's own settings: insert the resource when it changes.

use bevy::prelude::*;

pub use crate::spring::{KeepMotion, ReducedMotion};

/// Registers [`ReducedMotion`] (inserted as `Full` if the app has none) and [`KeepMotion`]
/// (part of [`SpringPlugins`](crate::SpringPlugins)); the spring systems read them.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringReducedMotionPlugin;

impl Plugin for SpringReducedMotionPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<ReducedMotion>()
            .register_type::<ReducedMotion>()
            .register_type::<KeepMotion>();
    }
}
