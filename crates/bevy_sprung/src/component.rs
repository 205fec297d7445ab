//! The spring component and its markers.

use core::fmt;
use core::marker::PhantomData;

use bevy::log::warn_once;
use bevy::prelude::*;
use sprung::{RestThreshold, Spring};

use crate::property::{Rotation, Scale, SignedScale, SpringProperty, SpringVector, Translation};

/// Which clock a spring advances with.
#[derive(Reflect, Debug, Default, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SpringClock {
    /// The schedule's own [`Time`]: `Time<Virtual>` in `PostUpdate` (it stops while the game is
    /// paused), `Time<Fixed>` in `FixedUpdate`.
    #[default]
    Game,
    /// `Time<Real>`: keeps going while the game is paused (menus, UI).
    Real,
}

/// Moves the property `P` of its entity toward a target with an exact damped spring.
///
/// The target can change at any time: the spring keeps its velocity, so a retarget mid-flight
/// bends the motion instead of restarting it. [`add_impulse`](Self::add_impulse) kicks it;
/// [`set_target_velocity`](Self::set_target_velocity) makes it follow a moving target without
/// lag jitter. When the offset and the velocity fall under its [`RestThreshold`], the spring
/// snaps onto the target, triggers [`SpringSettled<P>`](crate::SpringSettled) once, and sleeps:
/// it is not iterated and writes nothing until the target changes or it is kicked.
///
/// Invalid input is refused: a NaN or infinite target, velocity or impulse leaves the spring as
/// it was and logs one warning.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// fn spawn(mut commands: Commands) {
///     commands.spawn((
///         Transform::default(),
///         TranslationSpring::new(Spring::snappy(), Vec3::new(100.0, 0.0, 0.0)),
///         RotationSpring::new(Spring::bouncy(), Quat::from_rotation_z(1.0)),
///     ));
/// }
///
/// fn retarget(mut springs: Query<&mut TranslationSpring>) {
///     for mut spring in &mut springs {
///         spring.set_target(Vec3::new(-100.0, 50.0, 0.0));
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugin::default())).add_systems(Startup, spawn).add_systems(Update, retarget);
/// # app.update();
/// ```
#[derive(Component, Reflect, Clone, Copy)]
#[reflect(Component)]
pub struct PropertySpring<P: SpringProperty> {
    spring: Spring<f32>,
    target: P::Value,
    velocity: P::Linear,
    target_velocity: P::Linear,
    rest: RestThreshold<f32>,
    clock: Option<SpringClock>,
    /// The target the spring moved toward in its last step (what catch-up and retargeting
    /// start from).
    pub(crate) active_target: P::Value,
    /// Time not yet simulated while hidden, in seconds.
    pub(crate) pending: f32,
    #[reflect(ignore)]
    property: PhantomData<fn() -> P>,
}

/// A spring on [`Transform::translation`].
pub type TranslationSpring = PropertySpring<Translation>;
/// A spring on [`Transform::rotation`] (shortest arc, angular velocity in rad/s).
pub type RotationSpring = PropertySpring<Rotation>;
/// A spring on [`Transform::scale`] that does not pass through zero.
pub type ScaleSpring = PropertySpring<Scale>;
/// A spring on [`Transform::scale`] that may pass through zero (mirror).
pub type SignedScaleSpring = PropertySpring<SignedScale>;

/// Why an input to a [`PropertySpring`] was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpringInputError {
    /// A NaN or infinite target.
    NonFiniteTarget,
    /// A NaN or infinite velocity, impulse or target velocity.
    NonFiniteVelocity,
}

impl fmt::Display for SpringInputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::NonFiniteTarget => "spring target is not finite",
            Self::NonFiniteVelocity => "spring velocity is not finite",
        })
    }
}

impl core::error::Error for SpringInputError {}

impl<P: SpringProperty> fmt::Debug for PropertySpring<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("PropertySpring")
            .field("property", &P::short_type_path())
            .field("spring", &self.spring)
            .field("target", &self.target)
            .field("velocity", &self.velocity)
            .field("target_velocity", &self.target_velocity)
            .field("rest", &self.rest)
            .field("clock", &self.clock)
            .finish_non_exhaustive()
    }
}

impl<P: SpringProperty> PropertySpring<P> {
    /// A spring toward `target`, starting from wherever the property is, at rest.
    ///
    /// A non-finite `target` is refused when the spring first steps (with one warning): the
    /// spring then holds the property where it is.
    #[must_use]
    pub fn new(spring: Spring<f32>, target: P::Value) -> Self {
        Self {
            spring,
            target,
            velocity: P::Linear::default(),
            target_velocity: P::Linear::default(),
            rest: P::default_rest(),
            clock: None,
            active_target: target,
            pending: 0.0,
            property: PhantomData,
        }
    }

    /// The same spring with rest tolerances `rest` (in the property's units).
    #[must_use]
    pub fn with_rest(mut self, rest: RestThreshold<f32>) -> Self {
        self.rest = rest;
        self
    }

    /// The same spring advancing with `clock` instead of the plugin's default
    /// ([`SpringPlugin::clock`](crate::SpringPlugin::clock)): for example UI springs on
    /// [`SpringClock::Real`] keep animating while the game is paused.
    #[must_use]
    pub fn with_clock(mut self, clock: SpringClock) -> Self {
        self.clock = Some(clock);
        self
    }

    /// The same spring starting with `velocity` (refused with a warning if not finite).
    #[must_use]
    pub fn with_velocity(mut self, velocity: P::Linear) -> Self {
        let _ = self.set_velocity(velocity);
        self
    }

    /// The spring's physical parameters.
    #[inline]
    #[must_use]
    pub fn spring(&self) -> &Spring<f32> {
        &self.spring
    }

    /// Changes the spring's parameters; position and velocity carry over.
    #[inline]
    pub fn set_spring(&mut self, spring: Spring<f32>) {
        self.spring = spring;
    }

    /// Where the spring is heading.
    #[inline]
    #[must_use]
    pub fn target(&self) -> P::Value {
        self.target
    }

    /// Retargets the spring, keeping its velocity; wakes it if it slept.
    ///
    /// # Errors
    /// A NaN or infinite `target` is refused (one warning is logged) and nothing changes.
    pub fn set_target(&mut self, target: P::Value) -> Result<(), SpringInputError> {
        if P::is_finite(target) {
            self.target = target;
            Ok(())
        } else {
            warn_once!("bevy_sprung: refused a non-finite spring target {target:?}");
            Err(SpringInputError::NonFiniteTarget)
        }
    }

    /// The velocity in the spring's linear space (units per second; for a rotation, the rate
    /// of the rotation vector relative to the target, in rad/s).
    #[inline]
    #[must_use]
    pub fn velocity(&self) -> P::Linear {
        self.velocity
    }

    /// Sets the velocity; wakes the spring.
    ///
    /// # Errors
    /// A non-finite velocity is refused (one warning is logged) and nothing changes.
    pub fn set_velocity(&mut self, velocity: P::Linear) -> Result<(), SpringInputError> {
        self.velocity = finite_velocity(velocity, "velocity")?;
        Ok(())
    }

    /// Adds `velocity_change` to the velocity (a kick); wakes the spring.
    ///
    /// # Errors
    /// A non-finite impulse is refused (one warning is logged) and nothing changes.
    pub fn add_impulse(&mut self, velocity_change: P::Linear) -> Result<(), SpringInputError> {
        finite_velocity(velocity_change, "impulse")?;
        self.velocity =
            finite_velocity(self.velocity + velocity_change, "velocity after an impulse")?;
        Ok(())
    }

    /// How fast the target itself moves. With a non-zero target velocity each step follows a
    /// target moving at that velocity during the frame and ending at [`target`](Self::target)
    /// (an exact first-order hold): the steady lag `c·r/k` is reproduced exactly, with no
    /// jitter from uneven frame times. A spring following a moving target does not sleep.
    #[inline]
    #[must_use]
    pub fn target_velocity(&self) -> P::Linear {
        self.target_velocity
    }

    /// Sets how fast the target moves (see [`target_velocity`](Self::target_velocity)).
    ///
    /// # Errors
    /// A non-finite velocity is refused (one warning is logged) and nothing changes.
    pub fn set_target_velocity(&mut self, velocity: P::Linear) -> Result<(), SpringInputError> {
        self.target_velocity = finite_velocity(velocity, "target velocity")?;
        Ok(())
    }

    /// The rest tolerances.
    #[inline]
    #[must_use]
    pub fn rest(&self) -> RestThreshold<f32> {
        self.rest
    }

    /// Changes the rest tolerances.
    #[inline]
    pub fn set_rest(&mut self, rest: RestThreshold<f32>) {
        self.rest = rest;
    }

    /// The clock the spring advances with, if it overrides the plugin's default.
    #[inline]
    #[must_use]
    pub fn clock(&self) -> Option<SpringClock> {
        self.clock
    }

    /// Whether the spring has something to do: a target other than where it rests, a velocity,
    /// or a moving target.
    #[inline]
    pub(crate) fn wants_to_move(&self) -> bool {
        self.target != self.active_target
            || self.velocity != P::Linear::default()
            || self.target_velocity != P::Linear::default()
    }

    /// Velocity and target velocity, for the step.
    #[inline]
    pub(crate) fn motion(&self) -> (P::Linear, P::Linear) {
        (self.velocity, self.target_velocity)
    }

    /// Stores the velocity a step produced (already checked finite).
    #[inline]
    pub(crate) fn store_velocity(&mut self, velocity: P::Linear) {
        self.velocity = velocity;
    }
}

/// `velocity` if finite; otherwise one warning naming `what`, and an error.
fn finite_velocity<V: SpringVector>(velocity: V, what: &str) -> Result<V, SpringInputError> {
    if velocity.is_finite() {
        Ok(velocity)
    } else {
        warn_once!("bevy_sprung: refused a non-finite spring {what}: {velocity:?}");
        Err(SpringInputError::NonFiniteVelocity)
    }
}

/// Present while the spring on property `P` of this entity rests; the plugin adds and removes
/// it. Resting springs are not iterated, so a scene of sleeping springs costs almost nothing.
#[derive(Component, Reflect, Debug)]
#[reflect(Component)]
pub struct SpringAsleep<P: SpringProperty>(#[reflect(ignore)] PhantomData<fn() -> P>);

impl<P: SpringProperty> Default for SpringAsleep<P> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P: SpringProperty> Clone for SpringAsleep<P> {
    fn clone(&self) -> Self {
        Self::default()
    }
}

/// Opt-in for springs that nobody sees: while the entity's `ViewVisibility` is false its
/// springs skip frames, and are advanced exactly, in one step over the accumulated time, when
/// it is seen again or their target changes (under the old target first). Because every step
/// is the exact solution, the result equals stepping every frame (to rounding).
///
/// `ViewVisibility` reflects the previous frame. Use this where being seen does not depend on
/// the spring's own motion (hidden menus, far-away props, things behind the camera that the
/// camera turns toward): a spring whose motion would carry it into view while it is culled
/// waits to be seen or retargeted.
#[cfg(feature = "visibility")]
#[derive(Component, Reflect, Debug, Default, Clone, Copy)]
#[reflect(Component, Default)]
pub struct CatchUpWhenHidden;
