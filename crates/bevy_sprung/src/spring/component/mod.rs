//! The spring component: its configuration ([`PropertySpring`], here), its motion
//! ([`SpringMotion`]) and its sleep marker. Beside them: retargeting through change detection
//! (`target_mut`), the file form (`serde_impls`), the stepping paths (`step`) and the slot
//! ticket (`ticket`).

#[cfg(feature = "serde")]
mod serde_impls;
pub(super) mod step;
pub(super) mod target_mut;
mod ticket;

use ticket::SlotTicket;

use core::any::TypeId;
use core::fmt;
use core::marker::PhantomData;

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::log::warn_once;
use bevy::math::{NormedVectorSpace, VectorSpace};
use bevy::prelude::*;
use sprung::{RestThreshold, Spring};

use super::table::TransitionTable;
use crate::clock::SpringClock;
use crate::property::{OffsetOf, SpringProperty, ValueOf, VelocityOf};
use crate::space::{Carried, SpringSpace, SpringVector};

/// Moves the property `P` of its entity toward a target with an exact damped spring.
///
/// The target can change at any time: the spring keeps its velocity, so a retarget mid-flight
/// bends the motion instead of restarting it. [`add_impulse`](Self::add_impulse) kicks it;
/// [`set_target_velocity`](Self::set_target_velocity) makes it follow a moving target without
/// lag jitter. When the offset and the velocity fall under its [`RestThreshold`], the spring
/// snaps onto the target, triggers [`SpringSettled<P>`](super::SpringSettled) once, and sleeps:
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
    spring: Spring<f32>,
    target: ValueOf<P>,
    /// Kept as the getters return it (a `Vec3`, not a `Vec3A`): read only off the usual path.
    target_velocity: VelocityOf<P>,
    rest: RestThreshold<f32>,
    clock: Option<SpringClock>,
    /// A velocity set or impulse added since the spring last stepped, applied by its next step
    /// (the velocity itself is [`SpringMotion`]'s, which the per-frame step reads instead of
    /// this component).
    #[reflect(ignore)]
    velocity_change: VelocityChange<P>,
}

impl<P: SpringProperty> PropertySpring<P> {
    /// The component hook: the first spring on `P` brings in the property's systems.
    fn on_add(mut world: DeferredWorld, context: HookContext) {
        let property = (context.entity, P::short_type_path());
        super::first_use::spring_added(&mut world, TypeId::of::<Self>(), property);
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
struct VelocityChange<P: SpringProperty> {
    /// The velocity is replaced by `change` (else `change` is added to it).
    replace: bool,
    /// The velocity set, or the sum of the impulses added since; in the narrower velocity type
    /// (a `Vec3`, not a `Vec3A`), which keeps a translation's configuration to 64 bytes.
    change: VelocityOf<P>,
}

impl<P: SpringProperty> VelocityChange<P> {
    /// The velocity replaced by `change`, or `change` added to it.
    fn new(replace: bool, change: OffsetOf<P>) -> Self {
        Self {
            replace,
            change: change.into(),
        }
    }

    /// The change, in the offset's space.
    #[inline]
    fn change(&self) -> OffsetOf<P> {
        self.change.into()
    }

    /// Whether there is a change to apply.
    #[inline]
    fn is_pending(&self) -> bool {
        self.replace | (self.change() != OffsetOf::<P>::ZERO)
    }

    /// `velocity` after the change.
    #[inline]
    fn applied_to(&self, velocity: OffsetOf<P>) -> OffsetOf<P> {
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

/// The motion of the spring on property `P`: its velocity, and the state it carries from frame
/// to frame. Every [`PropertySpring<P>`] has one (a required component), which the plugin
/// steps; the spring's configuration is not read while nothing changes it.
///
/// Configuration and motion live in two components so that the per-frame step streams only
/// what moves (80 bytes for a translation) and not the parameters, tolerances and clock
/// beside it. Set or kick the velocity through the spring
/// ([`PropertySpring::set_velocity`], [`add_impulse`](PropertySpring::add_impulse)): the
/// change applies at its next step.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::spring::SpringMotion;
///
/// // A squash that follows how fast each sprung entity moves.
/// fn speeds(springs: Query<&SpringMotion<Translation>>) {
///     for motion in &springs {
///         let _speed = motion.velocity().length();
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Update, speeds);
/// # app.world_mut().spawn((Transform::default(), TranslationSpring::new(Spring::bouncy(), Vec3::X)));
/// # app.update();
/// ```
#[derive(Component, Reflect)]
#[reflect(Component, Default, Debug, Clone)]
#[repr(C)]
pub struct SpringMotion<P: SpringProperty> {
    /// The offset of the value from `active_target` after the last step, with the digits the
    /// value itself cannot hold, and those the offset cannot.
    #[reflect(ignore)]
    offset: Carried<OffsetOf<P>>,
    /// The velocity in the offset's space: right after the offset (the last field of
    /// [`Carried`]; the fields are in declared order), so that a `Vec2` spring's state
    /// `[offset, velocity]` is one 16-byte load.
    velocity: OffsetOf<P>,
    /// The target the spring moved toward in its last step: a `target` that differs was set
    /// since (a retarget), and a hidden spring catches up under this one first. While nothing
    /// but the stepping system touches the spring, it is the spring's target.
    #[reflect(ignore)]
    active_target: ValueOf<P>,
    /// The squared offset and speed tolerances as applied at `active_target` (raised to what
    /// `f32` resolves there): the rest test is two comparisons.
    #[reflect(ignore)]
    rest_squared: (f32, f32),
    /// The ticket of the spring's slot in its property's transition table (see
    /// [`ticket`](Self::ticket)), or where it has none, the time not yet simulated while hidden
    /// (see [`pending`](Self::pending)). While nothing but the stepping system touches the
    /// spring, its transition is one indexed load.
    #[reflect(ignore)]
    ticket: SlotTicket,
}

impl<P: SpringProperty> Default for SpringMotion<P> {
    fn default() -> Self {
        Self::toward(ValueOf::<P>::default(), P::DEFAULT_REST)
    }
}

impl<P: SpringProperty> SpringMotion<P> {
    /// At rest toward `target`, with tolerances `rest`.
    pub(crate) fn toward(target: ValueOf<P>, rest: RestThreshold<f32>) -> Self {
        Self {
            velocity: OffsetOf::<P>::ZERO,
            active_target: target,
            offset: Carried::new(OffsetOf::<P>::ZERO),
            rest_squared: rest_squared::<P>(rest, target),
            ticket: SlotTicket::pending(0.0),
        }
    }

    /// The velocity in the spring's space (units per second; for a rotation, the rate of the
    /// rotation vector relative to the target, in rad/s), as of the spring's last step. A
    /// velocity set or kicked since applies at the next step.
    #[inline]
    #[must_use]
    pub fn velocity(&self) -> VelocityOf<P> {
        self.velocity.into()
    }

    /// Whether the spring, heading for `target`, is within `distance` of it and slow enough not
    /// to leave it again: the length of its offset at most `distance`, its speed at most
    /// `distance × omega` (its natural frequency). A spring heading elsewhere is not.
    #[inline]
    pub(crate) fn is_within(&self, target: ValueOf<P>, distance: f32, omega: f32) -> bool {
        let reach = distance * distance;
        self.active_target == target
            && self.offset.offset.norm_squared() <= reach
            && self.velocity.norm_squared() <= reach * omega * omega
    }

    /// Whether the property's `current` value is the one this motion put there: the target
    /// it snapped to when it came to rest, or what its last step wrote (a spring put to sleep
    /// by hand mid-flight). Something else wrote any other value.
    #[inline]
    pub(crate) fn holds(&self, current: ValueOf<P>) -> bool {
        let zero = OffsetOf::<P>::ZERO;
        if self.offset.offset == zero && self.offset.remainder == zero {
            // Snapped: the target itself was written (not `at_offset(target, 0)`, which a
            // space may clamp or re-encode).
            P::Space::same(current, self.active_target)
        } else {
            P::Space::is_written(current, self.active_target, self.offset)
        }
    }

    /// The value this motion put on the property: the target it snapped to at rest, or what its
    /// last step wrote ([`holds`](Self::holds) is true of it).
    #[inline]
    pub(crate) fn shown(&self) -> ValueOf<P> {
        let zero = OffsetOf::<P>::ZERO;
        if self.offset.offset == zero && self.offset.remainder == zero {
            self.active_target
        } else {
            P::Space::at_carried(self.active_target, self.offset)
        }
    }

    /// The ticket of the spring's slot in its property's transition table; from
    /// [`TransitionTable::NO_TICKET`] up, it has none.
    #[inline]
    pub(crate) fn ticket(&self) -> u64 {
        self.ticket.get()
    }

    /// Remembers `ticket` as the spring's slot's (a spring with time pending has no slot: the
    /// caller has checked there is none).
    #[inline]
    pub(crate) fn set_ticket(&mut self, ticket: u64) {
        debug_assert!(
            self.pending() == 0.0 && ticket < TransitionTable::NO_TICKET,
            "a slot for a spring with time pending, or a ticket no slot has"
        );
        self.ticket = SlotTicket::slot(ticket);
    }

    /// Forgets the spring's slot, keeping the time pending.
    #[inline]
    pub(crate) fn clear_ticket(&mut self) {
        self.ticket = SlotTicket::pending(self.pending());
    }

    /// Time not yet simulated while hidden, in seconds (0 for a spring with a slot).
    #[inline]
    pub(crate) fn pending(&self) -> f32 {
        self.ticket.time_pending()
    }

    /// Sets the time not yet simulated, which forgets the spring's slot.
    #[inline]
    pub(crate) fn set_pending(&mut self, seconds: f32) {
        self.ticket = SlotTicket::pending(seconds);
    }
}

impl<P: SpringProperty> Clone for SpringMotion<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for SpringMotion<P> {}

impl<P: SpringProperty> fmt::Debug for SpringMotion<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SpringMotion")
            .field("property", &P::short_type_path())
            .field("velocity", &self.velocity)
            .field("active_target", &self.active_target)
            .field("offset", &self.offset)
            .field("pending", &self.pending())
            .finish_non_exhaustive()
    }
}

/// The smallest tolerance the rest test applies: squared offsets and speeds are compared in
/// `f32`, whose squares of values below this would underflow.
const FINEST_REST: f32 = 1e-18;

/// The squared tolerances of `rest` as applied toward `target`: raised to what `f32` resolves
/// near the target ([`RestThreshold::at_magnitude`]) and to [`FINEST_REST`].
fn rest_squared<P: SpringProperty>(rest: RestThreshold<f32>, target: ValueOf<P>) -> (f32, f32) {
    let magnitude = P::Space::magnitude(target);
    let applied = rest.at_magnitude(if magnitude.is_finite() {
        magnitude
    } else {
        0.0
    });
    let square = |tolerance: f32| {
        let tolerance = f64::from(tolerance.max(FINEST_REST));
        #[expect(
            clippy::cast_possible_truncation,
            reason = "an f32 threshold; squares beyond f32::MAX become infinite (all at rest)"
        )]
        let squared = (tolerance * tolerance) as f32;
        squared
    };
    (square(applied.offset), square(applied.speed))
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

/// Present while the spring on property `P` of this entity rests; the plugin adds and removes
/// it. Resting springs are not iterated, so a scene of sleeping springs costs almost nothing;
/// one whose target changes, that is kicked, or whose property something else writes, wakes.
/// Removed (by the plugin, or by hand, as from an entity disabled meanwhile), it marks the
/// spring's configuration changed: what changed while the spring was not stepped is taken up.
#[derive(Component, Reflect)]
#[reflect(Component, Default, Debug)]
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

impl<P: SpringProperty> fmt::Debug for SpringAsleep<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "SpringAsleep<{}>", P::short_type_path())
    }
}
