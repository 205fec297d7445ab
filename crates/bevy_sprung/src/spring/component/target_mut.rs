//! [`SpringTargetMut`]: retargeting through Bevy's change detection.

use core::ops::DerefMut;

use bevy::log::warn_once;
use bevy::prelude::*;

use super::PropertySpring;
use crate::property::{SpringProperty, ValueOf, VelocityOf};
use crate::space::SpringSpace;

/// Retargeting through Bevy's change detection: on a `Mut<PropertySpring<P>>` from a query (or
/// any [`DetectChangesMut`]), [`set_target_if_neq`](Self::set_target_if_neq) retargets only
/// when the target differs, and otherwise leaves the component untouched — not marked changed,
/// so a sleeping spring stays asleep. It replaces the `if spring.target() != x` guard, as Bevy's
/// `set_if_neq` does for whole components; [`set_target_velocity_if_neq`](Self::set_target_velocity_if_neq)
/// does the same for a moving target's velocity.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// #[derive(Component)]
/// struct Selected(bool);
///
/// // Runs every frame; only a change of selection touches (and wakes) a spring.
/// fn grow_selected(mut pieces: Query<(&Selected, &mut ScaleSpring)>) {
///     for (selected, mut scale) in &mut pieces {
///         let size = if selected.0 { 1.2 } else { 1.0 };
///         scale.set_target_if_neq(Vec3::splat(size));
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Update, grow_selected);
/// # app.world_mut().spawn((Transform::default(), Selected(true), ScaleSpring::new(Spring::bouncy(), Vec3::ONE)));
/// # app.update();
/// ```
pub trait SpringTargetMut {
    /// The target's type.
    type Value;

    /// Retargets (as [`PropertySpring::set_target`]) if `target` differs from the current
    /// target, and returns whether it did. A non-finite `target` is refused with one warning and
    /// returns `false`.
    fn set_target_if_neq(&mut self, target: Self::Value) -> bool;

    /// The target velocity's type.
    type Velocity;

    /// Sets the target's velocity (as [`PropertySpring::set_target_velocity`]) if it differs
    /// from the current one, and returns whether it did. A non-finite velocity is refused with
    /// one warning and returns `false`.
    fn set_target_velocity_if_neq(&mut self, velocity: Self::Velocity) -> bool;
}

impl<P, D> SpringTargetMut for D
where
    P: SpringProperty,
    D: DetectChangesMut<Inner = PropertySpring<P>> + DerefMut<Target = PropertySpring<P>>,
{
    type Value = ValueOf<P>;

    #[inline]
    fn set_target_if_neq(&mut self, target: ValueOf<P>) -> bool {
        if self.bypass_change_detection().target == target {
            return false;
        }
        if !P::Space::is_valid(target) {
            warn_once!("bevy_sprung: refused a non-finite spring target {target:?}");
            return false;
        }
        let spring: &mut PropertySpring<P> = self;
        spring.target = target;
        true
    }

    type Velocity = VelocityOf<P>;

    #[inline]
    fn set_target_velocity_if_neq(&mut self, velocity: VelocityOf<P>) -> bool {
        if self.bypass_change_detection().target_velocity == velocity {
            return false;
        }
        let spring: &mut PropertySpring<P> = self;
        spring.try_set_target_velocity(velocity).is_ok()
    }
}
