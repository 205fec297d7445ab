//! Punch: a kick measured in distance.

use bevy::log::warn_once;
use bevy::math::VectorSpace;

use crate::property::{OffsetOf, SpringProperty};
use crate::spring::PropertySpring;

impl<P: SpringProperty> PropertySpring<P> {
    /// Kicks the spring so that, from rest on its target, it swings out by exactly
    /// `displacement` before it returns (with overshoot as its damping gives): a punch.
    /// `displacement` is in the property's offset space — units for a translation, a factor
    /// offset for a scale (`Vec3::splat(0.3)` pops a unit scale to 1.3), a rotation vector in
    /// radians for a rotation, pixels for a UI offset.
    ///
    /// It adds the velocity `displacement / spring.impulse_peak()`
    /// ([`Spring::impulse_peak`](sprung::Spring::impulse_peak)), so a spring already moving
    /// keeps its motion and the punch adds to it; the target does not change. A spring with
    /// neither stiffness nor damping has no finite swing: the punch is refused with one warning,
    /// as is a non-finite `displacement`.
    ///
    /// # Example
    /// ```
    /// use bevy::prelude::*;
    /// use bevy_sprung::prelude::*;
    ///
    /// // A coin pickup pops the score counter by a third of its size.
    /// fn pop(mut counters: Query<&mut ScaleSpring>) {
    ///     for mut scale in &mut counters {
    ///         scale.punch(Vec3::splat(0.33));
    ///     }
    /// }
    /// # let mut app = App::new();
    /// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Update, pop);
    /// # app.world_mut().spawn((Transform::default(), ScaleSpring::new(Spring::bouncy(), Vec3::ONE)));
    /// # app.update();
    /// ```
    pub fn punch(&mut self, displacement: impl Into<OffsetOf<P>>) {
        let displacement = displacement.into();
        match self.spring().impulse_peak() {
            Some(peak) if peak > 0.0 && peak.is_finite() => {
                self.add_impulse(displacement * peak.recip());
            }
            _ if displacement == OffsetOf::<P>::ZERO => {}
            _ => warn_once!(
                "bevy_sprung: refused a punch on a spring without stiffness or damping ({:?})",
                self.spring()
            ),
        }
    }
}
