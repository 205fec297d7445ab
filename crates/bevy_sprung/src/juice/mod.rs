//! Juice: the small physical reactions that make a game feel alive, each one opt-in component
//! (or one call) driven by springs.
//!
//! - **Punch**: [`PropertySpring::punch`](crate::spring::PropertySpring::punch) kicks any
//!   property spring so that it swings out by a given distance and returns — a scale pop, a
//!   rotation wobble, a UI offset nudge.
//! - **Shake**: [`Shake`] moves an entity (a camera) by seeded noise filtered through a spring,
//!   scaled by a decaying trauma: the same shake at any frame rate, added on top of whatever
//!   else moves the entity ([`SpringFollow`](crate::follow::SpringFollow) included) and
//!   removed before it runs again, so the two never fight.
//! - **Squash & stretch**: [`SquashStretch`] stretches an entity along its velocity and
//!   squashes it on impact, keeping its volume (or area), and returns to rest through its own
//!   spring: a layer of the scale ([`Squash`]), so it stacks on any other scale motion.
//!
//! Entities without these components cost nothing: the systems run only while some entity has
//! one, and iterate only those.

mod punch;
mod shake;
mod squash;

pub use shake::{JuiceSystems, Shake};
pub use squash::{Conserve, Squash, SquashStretch};

use bevy::app::AnimationSystems;
use bevy::prelude::*;
use bevy::transform::TransformSystems;

/// [`Shake`] and [`SquashStretch`] (part of [`SpringPlugins`](crate::SpringPlugins)): a shake
/// is added in `PostUpdate` after the springs (`AnimationSystems`) and before transform
/// propagation, in [`JuiceSystems`], and taken off again in `PreUpdate`, before gameplay reads
/// or writes the `Transform`; a squash writes its layer of the scale after the springs.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringJuicePlugin;

impl Plugin for SpringJuicePlugin {
    fn build(&self, app: &mut App) {
        app.configure_sets(
            PostUpdate,
            JuiceSystems
                .after(AnimationSystems)
                .before(TransformSystems::Propagate),
        );
        shake::build(app);
        squash::build(app);
    }
}
