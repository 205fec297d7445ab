//! What features built on springs (choreography, assets, interaction, juice) need of a spring:
//! one small trait, implemented by [`PropertySpring`](crate::spring::PropertySpring), so that
//! those modules and the spring mechanism never import each other.

use bevy::ecs::component::Mutable;
use bevy::prelude::*;
use sprung::{RestThreshold, Spring};

use crate::clock::SpringClock;
use crate::property::{OffsetOf, SpringProperty, ValueOf};

/// A spring component on property `P`, as the features built on springs drive it.
pub trait SpringControl<P: SpringProperty>: Component<Mutability = Mutable> {
    /// Where the spring is heading.
    fn target(&self) -> ValueOf<P>;
    /// The spring's parameters.
    fn parameters(&self) -> Spring<f32>;
    /// Retargets the spring, keeping its velocity (a non-finite target is refused).
    fn retarget(&mut self, target: ValueOf<P>);
    /// Changes the spring's parameters.
    fn set_parameters(&mut self, spring: Spring<f32>);
    /// Changes the rest tolerances.
    fn set_rest_threshold(&mut self, rest: RestThreshold<f32>);
    /// Adds to the velocity (a non-finite impulse is refused).
    fn kick(&mut self, impulse: OffsetOf<P>);
    /// The clock the spring advances with (`None`: the default clock).
    fn clock(&self) -> Option<SpringClock>;
}
