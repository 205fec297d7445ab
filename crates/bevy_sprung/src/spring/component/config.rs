//! A spring's configuration: [`PropertySpring`], what a user sets (parameters, target, rest
//! tolerances, clock, velocity changes waiting for the next step), its hooks and setters, and
//! the typed refusal of a non-finite input.

use core::any::TypeId;
use core::fmt;

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::log::warn_once;
use bevy::math::VectorSpace;
use bevy::prelude::*;
use sprung::{RestThreshold, Spring};

use super::asleep::SpringAsleep;
use super::motion::SpringMotion;
use crate::clock::SpringClock;
use crate::property::{OffsetOf, SpringProperty, ValueOf, VelocityOf};
use crate::space::{SpringSpace, SpringVector};

/// Moves the property `P` of its entity toward a target with an exact damped spring.
///
/// The target can change at any time: the spring keeps its velocity, so a retarget mid-flight
/// bends the motion instead of restarting it. [`add_impulse`](Self::add_impulse) kicks it;
/// [`set_target_velocity`](Self::set_target_velocity) makes it follow a moving target without
/// lag jitter. When the offset and the velocity fall under its [`RestThreshold`], the spring
/// snaps onto the target, triggers [`SpringSettled<P>`](crate::spring::SpringSettled) once, and sleeps:
/// it is not iterated and writes nothing until the target changes, it is kicked, or something
/// else writes its property.
///
/// This component is the spring's configuration; its motion (the velocity, read with
/// [`SpringMotion::velocity`], and what it carries from frame to frame) is the required
/// [`SpringMotion<P>`] beside it. The plugin steps the motion every frame and reads this
/// component only in frames where something changed it.
///
/// It starts from wherever the property is, and follows what else writes it: something else may
/// move the property (a teleport, a drag) and the spring goes on from there. A write is seen
/// through Bevy's change detection (any write through `Mut`, as queries and `World::get_mut`
/// give): one made with `bypass_change_detection` may not be, and the spring then writes its
/// own value over it. Between its own writes it keeps the digits of the offset that the
/// property cannot hold, so it arrives at any magnitude and frame rate instead of stopping a
/// rounding short.
///
/// When the world changes under it: inserted (also over another spring, or again after it was
/// removed) it starts at rest from wherever the property is, awake, toward its target (the
/// velocity of a spring it replaces is not kept: retarget with the setters to keep it). Removed,
/// it leaves the property where it is. While the component it moves is missing, or its entity is
/// disabled, it pauses; back, it goes on from the property's value and takes up what was set
/// meanwhile. A settle event is never delivered for a despawned entity.
///
/// The common path cannot fail: [`set_target`](Self::set_target) and the other setters take any
/// finite value. A NaN or infinite target, velocity or impulse is refused with one warning and
/// the state kept; the `try_` forms say so in a `Result`. Values written through reflection (an
/// inspector, a scene) are checked when the spring next steps: a non-finite target is refused
/// (the last valid one is kept), a non-finite velocity is reset to zero, and invalid spring
/// parameters are replaced by the last valid ones, each with one warning.
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
///         // Only touches the component (and wakes the spring) when the target differs.
///         spring.set_target_if_neq(Vec3::new(-100.0, 50.0, 0.0));
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn).add_systems(Update, retarget);
/// # app.update();
/// ```
#[derive(Component, Reflect)]
#[component(on_add, on_insert)]
#[require(SpringMotion<P>)]
#[reflect(Component, Debug, Clone)]
pub struct PropertySpring<P: SpringProperty> {
    pub(in crate::spring) spring: Spring<f32>,
    pub(in crate::spring) target: ValueOf<P>,
    /// Kept as the getters return it (a `Vec3`, not a `Vec3A`): read only off the usual path.
    pub(in crate::spring) target_velocity: VelocityOf<P>,
    pub(in crate::spring) rest: RestThreshold<f32>,
    pub(in crate::spring) clock: Option<SpringClock>,
    /// A velocity set or impulse added since the spring last stepped, applied by its next step
    /// (the velocity itself is [`SpringMotion`]'s, which the per-frame step reads instead of
    /// this component).
    #[reflect(ignore)]
    pub(in crate::spring) velocity_change: VelocityChange<P>,
}

impl<P: SpringProperty> PropertySpring<P> {
    /// The component hook: the first spring on `P` brings in the property's systems.
    fn on_add(mut world: DeferredWorld, context: HookContext) {
        let property = (context.entity, P::short_type_path());
        crate::spring::first_use::spring_added(&mut world, TypeId::of::<Self>(), property);
    }

    /// The component hook: a spring inserted (or replaced, or inserted again after it was
    /// removed) starts from rest toward its target, as its [`SpringMotion`] says, from wherever
    /// the property is; a velocity it was given applies at its first step. A target that is not
    /// a valid value is not headed for: the motion rests where the property is, and the first
    /// step refuses the target. A spring that slept before is woken.
    fn on_insert(mut world: DeferredWorld, context: HookContext) {
        let entity = context.entity;
        let Some(&spring) = world.get::<Self>(entity) else {
            return;
        };
        let toward = if P::Space::is_valid(spring.target) {
            spring.target
        } else {
            world
                .get::<P::Component>(entity)
                .map(P::get)
                .filter(|&current| P::Space::is_valid(current))
                .unwrap_or_default()
        };
        if let Some(mut motion) = world.get_mut::<SpringMotion<P>>(entity) {
            *motion = SpringMotion::toward(toward, spring.rest);
        }
        // The marker of the spring this one replaced: its motion is gone, so nothing else would
        // wake it.
        if world.entity(entity).contains::<SpringAsleep<P>>() {
            world
                .commands()
                .entity(entity)
                .try_remove::<SpringAsleep<P>>();
        }
    }
}

/// A change to a spring's velocity that waits for its next step.
pub(in crate::spring) struct VelocityChange<P: SpringProperty> {
    /// The velocity is replaced by `change` (else `change` is added to it).
    pub(in crate::spring) replace: bool,
    /// The velocity set, or the sum of the impulses added since; in the narrower velocity type
    /// (a `Vec3`, not a `Vec3A`), which keeps a translation's configuration to 64 bytes.
    pub(in crate::spring) change: VelocityOf<P>,
}

impl<P: SpringProperty> VelocityChange<P> {
    /// The velocity replaced by `change`, or `change` added to it.
    pub(in crate::spring) fn new(replace: bool, change: OffsetOf<P>) -> Self {
        Self {
            replace,
            change: change.into(),
        }
    }

    /// The change, in the offset's space.
    #[inline]
    pub(in crate::spring) fn change(&self) -> OffsetOf<P> {
        self.change.into()
    }

    /// Whether there is a change to apply.
    #[inline]
    pub(in crate::spring) fn is_pending(&self) -> bool {
        self.replace | (self.change() != OffsetOf::<P>::ZERO)
    }

    /// `velocity` after the change.
    #[inline]
    pub(in crate::spring) fn applied_to(&self, velocity: OffsetOf<P>) -> OffsetOf<P> {
        if self.replace {
            self.change()
        } else {
            velocity + self.change()
        }
    }
}

impl<P: SpringProperty> Default for VelocityChange<P> {
    fn default() -> Self {
        Self::new(false, OffsetOf::<P>::ZERO)
    }
}

impl<P: SpringProperty> Clone for VelocityChange<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for VelocityChange<P> {}

impl<P: SpringProperty> fmt::Debug for VelocityChange<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("VelocityChange")
            .field("replace", &self.replace)
            .field("change", &self.change)
            .finish()
    }
}

impl<P: SpringProperty> Clone for PropertySpring<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for PropertySpring<P> {}

/// Why an input to a [`PropertySpring`] was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SpringInputError {
    /// A NaN or infinite target.
    NonFiniteTarget,
    /// A NaN or infinite velocity, impulse or target velocity (or a velocity that an impulse
    /// would make infinite).
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
            .field("velocity_change", &self.velocity_change)
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
    pub fn new(spring: Spring<f32>, target: ValueOf<P>) -> Self {
        Self {
            spring,
            target,
            target_velocity: OffsetOf::<P>::ZERO.into(),
            rest: P::DEFAULT_REST,
            clock: None,
            velocity_change: VelocityChange::default(),
        }
    }

    /// The same spring with rest tolerances `rest` (in the property's units).
    #[must_use]
    pub fn with_rest(mut self, rest: RestThreshold<f32>) -> Self {
        self.set_rest(rest);
        self
    }

    /// The same spring advancing with `clock` instead of the [default
    /// clock](crate::clock::DefaultSpringClock): for example UI springs on
    /// [`SpringClock::Real`] keep animating while the game is paused.
    #[must_use]
    pub fn with_clock(mut self, clock: SpringClock) -> Self {
        self.clock = Some(clock);
        self
    }

    /// The same spring starting with `velocity` (refused with a warning if not finite), from
    /// its first step.
    #[must_use]
    pub fn with_velocity(mut self, velocity: impl Into<OffsetOf<P>>) -> Self {
        self.set_velocity(velocity);
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
    pub fn target(&self) -> ValueOf<P> {
        self.target
    }

    /// Retargets the spring, keeping its velocity; wakes it if it slept. A NaN or infinite
    /// `target` is refused: one warning is logged and nothing changes
    /// ([`try_set_target`](Self::try_set_target) returns the refusal).
    ///
    /// Through a `Mut` from a query,
    /// [`set_target_if_neq`](crate::spring::SpringTargetMut::set_target_if_neq) does the same
    /// without marking the component changed when the target is already `target`.
    #[inline]
    pub fn set_target(&mut self, target: ValueOf<P>) {
        let _refused = self.try_set_target(target);
    }

    /// [`set_target`](Self::set_target), returning the refusal of a non-finite `target`.
    ///
    /// # Errors
    /// [`SpringInputError::NonFiniteTarget`] (also logged once); nothing changes.
    pub fn try_set_target(&mut self, target: ValueOf<P>) -> Result<(), SpringInputError> {
        if P::Space::is_valid(target) {
            self.target = target;
            Ok(())
        } else {
            warn_once!("bevy_sprung: refused a non-finite spring target {target:?}");
            Err(SpringInputError::NonFiniteTarget)
        }
    }

    /// Sets the velocity, from the spring's next step (the velocity it has is its
    /// [`SpringMotion::velocity`]); wakes the spring. A non-finite velocity is refused with one
    /// warning and nothing changes. It replaces any impulse added since the last step; impulses
    /// added after it add to it.
    #[inline]
    pub fn set_velocity(&mut self, velocity: impl Into<OffsetOf<P>>) {
        let _refused = self.try_set_velocity(velocity);
    }

    /// [`set_velocity`](Self::set_velocity), returning the refusal.
    ///
    /// # Errors
    /// [`SpringInputError::NonFiniteVelocity`] (also logged once); nothing changes.
    pub fn try_set_velocity(
        &mut self,
        velocity: impl Into<OffsetOf<P>>,
    ) -> Result<(), SpringInputError> {
        self.velocity_change =
            VelocityChange::new(true, finite_velocity(velocity.into(), "velocity")?);
        Ok(())
    }

    /// Adds `velocity_change` to the velocity (a kick, a punch) at the spring's next step; wakes
    /// the spring. A non-finite impulse, or one that would make the impulses added since the
    /// last step sum to infinity, is refused with one warning and nothing changes; one that
    /// would make the velocity itself infinite is refused (with one warning) when applied.
    #[inline]
    pub fn add_impulse(&mut self, velocity_change: impl Into<OffsetOf<P>>) {
        let _refused = self.try_add_impulse(velocity_change);
    }

    /// [`add_impulse`](Self::add_impulse), returning the refusal.
    ///
    /// # Errors
    /// [`SpringInputError::NonFiniteVelocity`] (also logged once); nothing changes.
    pub fn try_add_impulse(
        &mut self,
        velocity_change: impl Into<OffsetOf<P>>,
    ) -> Result<(), SpringInputError> {
        let velocity_change = finite_velocity(velocity_change.into(), "impulse")?;
        let sum = finite_velocity(
            self.velocity_change.change() + velocity_change,
            "sum of impulses",
        )?;
        self.velocity_change = VelocityChange::new(self.velocity_change.replace, sum);
        Ok(())
    }

    /// How fast the target itself moves. With a non-zero target velocity each step follows a
    /// target moving at that velocity during the frame and ending at [`target`](Self::target)
    /// (an exact first-order hold): the steady lag `c·r/k` is reproduced exactly, with no
    /// jitter from uneven frame times. A spring following a moving target does not sleep.
    #[inline]
    #[must_use]
    pub fn target_velocity(&self) -> VelocityOf<P> {
        self.target_velocity
    }

    /// Sets how fast the target moves (see [`target_velocity`](Self::target_velocity)). A
    /// non-finite velocity is refused with one warning and nothing changes.
    #[inline]
    pub fn set_target_velocity(&mut self, velocity: impl Into<OffsetOf<P>>) {
        let _refused = self.try_set_target_velocity(velocity);
    }

    /// [`set_target_velocity`](Self::set_target_velocity), returning the refusal.
    ///
    /// # Errors
    /// [`SpringInputError::NonFiniteVelocity`] (also logged once); nothing changes.
    pub fn try_set_target_velocity(
        &mut self,
        velocity: impl Into<OffsetOf<P>>,
    ) -> Result<(), SpringInputError> {
        self.target_velocity = finite_velocity(velocity.into(), "target velocity")?.into();
        Ok(())
    }

    /// The rest tolerances, as set. The spring applies them raised to what `f32` resolves at the
    /// target ([`RestThreshold::at_magnitude`]): near `1e6` an offset tolerance below `0.0625`
    /// is `0.0625`.
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

    /// The clock the spring advances with, if it overrides the default.
    #[inline]
    #[must_use]
    pub fn clock(&self) -> Option<SpringClock> {
        self.clock
    }

    /// Changes the clock (`None`: the [default clock](crate::clock::DefaultSpringClock)).
    #[inline]
    pub fn set_clock(&mut self, clock: Option<SpringClock>) {
        self.clock = clock;
    }

    /// Whether the spring with `motion` has something to do: a target other than where it
    /// rests, a velocity (or a change to it), or a moving target.
    #[inline]
    pub(crate) fn wants_to_move(&self, motion: &SpringMotion<P>) -> bool {
        self.target != motion.active_target
            || motion.velocity != OffsetOf::<P>::ZERO
            || self.velocity_change.is_pending()
            || self.target_rate() != OffsetOf::<P>::ZERO
    }

    /// The target velocity in the offset's space, as the step uses it.
    #[inline]
    pub(crate) fn target_rate(&self) -> OffsetOf<P> {
        self.target_velocity.into()
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
