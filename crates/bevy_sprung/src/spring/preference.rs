//! How springs honour a preference for reduced motion, app-wide, and the per-entity opt-out:
//! modes of the step itself. The [`reduced_motion`](crate::reduced_motion) module registers them
//! and says how an app wires the preference.

use bevy::prelude::*;
use sprung::Spring;

/// How springs honour a preference for reduced motion: the place an app wires the operating
/// system's or its own settings' "reduce motion" switch to. Off (`Full`) by default.
///
/// - [`Snap`](Self::Snap): every spring jumps to its target at once; settle events still fire,
///   so sequences and UI logic that wait for them go on as before.
/// - [`NoOvershoot`](Self::NoOvershoot): springs are at least critically damped (the damping
///   ratio raised to 1, the natural frequency kept, so the motion takes about as long), and
///   never overshoot or bounce.
/// - [`Scaled`](Self::Scaled)`(s)`: every spring runs `1/s` times as fast (`s = 0.5`: motion in
///   half the time); the motion keeps its shape.
///
/// Springs on entities with [`KeepMotion`] are exempt: motion that carries meaning (a character
/// in a game, a progress indicator).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default()));
/// // From the app's settings menu, or the platform's accessibility setting:
/// let user_prefers_reduced_motion = true;
/// if user_prefers_reduced_motion {
///     app.insert_resource(ReducedMotion::NoOvershoot);
/// }
/// ```
#[derive(Resource, Reflect, Debug, Default, Clone, Copy, PartialEq)]
#[reflect(Resource, Debug, Default, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum ReducedMotion {
    /// Springs move as they are set up.
    #[default]
    Full,
    /// Springs jump to their targets; settle events still fire.
    Snap,
    /// Springs are at least critically damped: no overshoot, about the same duration.
    NoOvershoot,
    /// Springs run `1/scale` times as fast (a `scale` that is not positive and finite means
    /// `Full`).
    Scaled(f32),
}

impl ReducedMotion {
    /// Whether this changes anything.
    #[inline]
    #[must_use]
    pub fn is_reduced(self) -> bool {
        match self {
            Self::Full => false,
            Self::Snap | Self::NoOvershoot => true,
            Self::Scaled(scale) => scale.is_finite() && scale > 0.0,
        }
    }

    /// The spring a spring becomes under this preference: critically damped at least for
    /// [`NoOvershoot`](Self::NoOvershoot), itself otherwise.
    #[must_use]
    pub fn spring(self, spring: Spring<f32>) -> Spring<f32> {
        if self != Self::NoOvershoot {
            return spring;
        }
        let critical = 2.0 * (spring.stiffness() * spring.mass()).sqrt();
        if spring.damping() >= critical {
            return spring;
        }
        Spring::new(spring.mass(), spring.stiffness(), critical).unwrap_or(spring)
    }

    /// The time step a spring advances by under this preference: `dt/scale` for
    /// [`Scaled`](Self::Scaled), `dt` otherwise.
    #[must_use]
    pub fn dt(self, dt: f32) -> f32 {
        match self {
            Self::Scaled(scale) if scale.is_finite() && scale > 0.0 => dt / scale,
            _ => dt,
        }
    }
}

/// Exempts this entity's springs from [`ReducedMotion`]: for motion that carries meaning.
#[derive(Component, Reflect, Debug, Default, Clone, Copy)]
#[reflect(Component, Default, Debug, Clone)]
pub struct KeepMotion;
