//! The systems that step springs, put them to sleep and wake them.

use bevy::ecs::system::ParallelCommands;
use bevy::log::warn_once;
use bevy::prelude::*;
use sprung::{RestThreshold, Spring, SpringState, Transition};

use crate::component::{PropertySpring, SpringAsleep, SpringClock};
use crate::event::SpringSettled;
use crate::plugin::SpringSettings;
use crate::property::{SpringProperty, SpringVector};

/// A few transitions keyed by spring parameters and time step, kept for one batch of entities.
///
/// Entities usually share a handful of springs; each distinct `(spring, dt)` is computed once
/// per batch instead of once per entity, so the per-entity cost is the step itself. The entry
/// used last is checked first, with one 128-bit comparison: consecutive entities of a batch
/// mostly share their spring.
pub(crate) struct TransitionCache {
    /// The bits of `(mass, stiffness, damping, dt)` of each filled entry.
    keys: [u128; Self::SIZE],
    transitions: [Transition<f32>; Self::SIZE],
    /// How many entries are filled.
    len: usize,
    /// The entry to replace next once all are filled.
    next: usize,
    /// The entry that answered last.
    last: usize,
}

impl Default for TransitionCache {
    fn default() -> Self {
        Self {
            keys: [0; Self::SIZE],
            transitions: [Transition::identity(); Self::SIZE],
            len: 0,
            next: 0,
            last: 0,
        }
    }
}

impl TransitionCache {
    const SIZE: usize = 4;

    /// The transition of `spring` over `dt`, or `None` for parameters that are not a valid
    /// spring (possible through reflection, which bypasses `Spring::new`).
    #[inline]
    pub(crate) fn get(&mut self, spring: &Spring<f32>, dt: f32) -> Option<&Transition<f32>> {
        let key = u128::from(spring.mass().to_bits())
            | (u128::from(spring.stiffness().to_bits()) << 32)
            | (u128::from(spring.damping().to_bits()) << 64)
            | (u128::from(dt.to_bits()) << 96);
        if self.len > 0 && self.keys[self.last] == key {
            return Some(&self.transitions[self.last]);
        }
        self.lookup(spring, dt, key)
    }

    /// [`get`](Self::get) when the last entry does not match: search the others, or compute
    /// and insert.
    #[cold]
    #[inline(never)]
    fn lookup(&mut self, spring: &Spring<f32>, dt: f32, key: u128) -> Option<&Transition<f32>> {
        if let Some(index) = self.keys[..self.len]
            .iter()
            .position(|cached| *cached == key)
        {
            self.last = index;
            return Some(&self.transitions[index]);
        }
        let Ok(valid) = Spring::new(spring.mass(), spring.stiffness(), spring.damping()) else {
            warn_once!(
                "bevy_sprung: a spring has invalid parameters and is not stepped: {spring:?}"
            );
            return None;
        };
        let index = if self.len < Self::SIZE {
            self.len += 1;
            self.len - 1
        } else {
            let index = self.next;
            self.next = (self.next + 1) % Self::SIZE;
            index
        };
        self.keys[index] = key;
        self.transitions[index] = valid.transition(dt);
        self.last = index;
        Some(&self.transitions[index])
    }
}

/// What one step did to a spring.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Stepped {
    /// It moved and keeps moving.
    Moving,
    /// It reached rest and was snapped onto its target.
    Settled,
    /// It is hidden: the time was put aside for a later exact catch-up.
    Deferred,
}

/// Advances `(value, velocity)` by `dt` toward `target` (moving at `target_velocity`), in the
/// property's linear space, keeping the value in range. An invalid spring leaves it unchanged.
#[inline]
fn advance<P: SpringProperty>(
    spring: &Spring<f32>,
    cache: &mut TransitionCache,
    (value, velocity): (P::Value, P::Linear),
    target: P::Value,
    target_velocity: P::Linear,
    dt: f32,
) -> (P::Value, P::Linear) {
    let Some(transition) = cache.get(spring, dt) else {
        return (value, velocity);
    };
    let zero = P::Linear::default();
    let offset = P::offset(value, target);
    let state = SpringState::new(offset, velocity);
    let next = if target_velocity == zero {
        transition.step(state, zero)
    } else {
        transition.step_toward_moving(state, zero, target_velocity)
    };
    let stepped = P::advance(value, target, offset, next.position);
    let (stepped, stepped_velocity) = P::constrain(value, stepped, next.velocity, target);
    if P::is_finite(stepped) && stepped_velocity.is_finite() {
        (stepped, stepped_velocity)
    } else {
        // Unreachable for valid springs and finite inputs; never let a NaN reach a component.
        warn_once!("bevy_sprung: a step produced a non-finite value and was dropped");
        (value, velocity)
    }
}

/// One frame of one awake spring; writes the property only if it changed.
///
/// Out of line: the per-entity closure around it then inlines into the query's loop, which
/// measured fewer instructions per entity than inlining this into the closure.
#[inline(never)]
pub(crate) fn step_spring<P: SpringProperty>(
    spring: &mut PropertySpring<P>,
    component: &mut Mut<P::Component>,
    dt: f32,
    hidden: bool,
    cache: &mut TransitionCache,
) -> Stepped {
    let current = P::get(component);
    let zero = P::Linear::default();
    // The common case, straight-line: a visible spring with no time pending, toward the target
    // of its last step, which does not move. It computes what the general path computes for
    // it; any other case, and a non-finite result (from a non-finite target, which compares
    // equal to itself when infinite), goes the general way from the same, untouched state.
    // (Calling `advance` here instead, with its moving-target branch and checks, measured 46%
    // slower per frame for 100k springs.)
    if !hidden
        && dt > 0.0
        && spring.pending == 0.0
        && spring.target() == spring.active_target
        && spring.target_velocity() == zero
        && let Some(transition) = cache.get(spring.spring(), dt)
    {
        let target = spring.target();
        let offset = P::offset(current, target);
        let next = transition.step(SpringState::new(offset, spring.velocity()), zero);
        let stepped = P::advance(current, target, offset, next.position);
        let (value, velocity) = P::constrain(current, stepped, next.velocity, target);
        // A finite squared length means finite components; the rest check reuses it.
        if P::is_finite(value) && velocity.length_squared().is_finite() {
            return settle_or_store(spring, component, current, (value, velocity), target, zero);
        }
    }
    step_spring_general(spring, component, current, dt, hidden, cache)
}

/// [`step_spring`] in every case: retargets, catch-up, moving targets, invalid input.
#[inline(never)]
fn step_spring_general<P: SpringProperty>(
    spring: &mut PropertySpring<P>,
    component: &mut Mut<P::Component>,
    current: P::Value,
    dt: f32,
    hidden: bool,
    cache: &mut TransitionCache,
) -> Stepped {
    let target = valid_target(spring, current);
    let retargeted = target != spring.active_target;
    if hidden && !retargeted {
        spring.pending += dt;
        return Stepped::Deferred;
    }
    let parameters = *spring.spring();
    let (velocity, target_velocity) = spring.motion();
    let mut state = (current, velocity);
    // Catch up the hidden time under the target that was in effect, then retarget.
    if spring.pending > 0.0 {
        let pending = core::mem::take(&mut spring.pending);
        state = advance::<P>(
            &parameters,
            cache,
            state,
            spring.active_target,
            target_velocity,
            pending,
        );
    }
    if retargeted {
        state.1 = P::retarget_velocity(spring.active_target, target, state.1);
        spring.active_target = target;
    }
    if dt > 0.0 {
        state = advance::<P>(&parameters, cache, state, target, target_velocity, dt);
    }
    settle_or_store(spring, component, current, state, target, target_velocity)
}

/// The end of a step to `(value, velocity)`: at rest (toward a target that does not move) the
/// spring snaps onto `target` and settles; the velocity is stored, and the property written if
/// it changed.
#[inline]
fn settle_or_store<P: SpringProperty>(
    spring: &mut PropertySpring<P>,
    component: &mut Mut<P::Component>,
    current: P::Value,
    (mut value, mut velocity): (P::Value, P::Linear),
    target: P::Value,
    target_velocity: P::Linear,
) -> Stepped {
    let zero = P::Linear::default();
    let outcome = if target_velocity == zero
        && is_at_rest(spring.rest(), P::offset(value, target), velocity)
    {
        // Snapping is what makes sleeping exact: nothing moves until the target changes.
        value = target;
        velocity = zero;
        Stepped::Settled
    } else {
        Stepped::Moving
    };
    spring.store_velocity(velocity);
    if value != current {
        P::set(component, value);
    }
    outcome
}

/// `rest.is_at_rest(offset.length(), velocity.length())`, without the square roots for a
/// spring that is clearly away from rest (the common case, every frame of every moving spring).
///
/// `|x| > t` is certain when `|x|² > t²·(1 + 2⁻²⁰)`: the margin covers the rounding of the
/// square root and of `|x|²` (both within 2⁻²⁴ relative while `|x|²` is a normal number), and
/// `t²` is formed in `f64`, where it neither overflows nor loses digits to subnormals. A zero,
/// subnormal or infinite `|x|²` is left to the exact check. So this answers exactly as the
/// check on the lengths does.
#[inline]
fn is_at_rest<V: SpringVector>(rest: RestThreshold<f32>, offset: V, velocity: V) -> bool {
    const MARGIN: f64 = 1.0 + 1.0 / 1_048_576.0;
    let beyond = |squared: f32, tolerance: f32| {
        let tolerance = f64::from(tolerance);
        squared.is_normal() && f64::from(squared) > tolerance * tolerance * MARGIN
    };
    if beyond(offset.length_squared(), rest.offset) || beyond(velocity.length_squared(), rest.speed)
    {
        return false;
    }
    rest.is_at_rest(offset.length(), velocity.length())
}

/// The spring's target if finite; otherwise one warning, and the last valid target (or the
/// current value, for a spring created with an invalid one) is restored.
#[inline]
fn valid_target<P: SpringProperty>(spring: &mut PropertySpring<P>, current: P::Value) -> P::Value {
    let target = spring.target();
    if P::is_finite(target) {
        if !P::is_finite(spring.active_target) {
            spring.active_target = target;
        }
        return target;
    }
    warn_once!(
        "bevy_sprung: a spring's target is not finite ({target:?}); it keeps its last valid target"
    );
    let kept = if P::is_finite(spring.active_target) {
        spring.active_target
    } else {
        current
    };
    spring.active_target = kept;
    // Restoring cannot fail: `kept` is finite.
    let _ = spring.set_target(kept);
    kept
}

#[cfg(feature = "visibility")]
type Visibility = (
    Option<&'static ViewVisibility>,
    Has<crate::component::CatchUpWhenHidden>,
);
#[cfg(not(feature = "visibility"))]
type Visibility = ();

#[cfg(feature = "visibility")]
#[inline]
fn is_hidden((visibility, catch_up): (Option<&ViewVisibility>, bool)) -> bool {
    catch_up && visibility.is_some_and(|visibility| !visibility.get())
}

#[cfg(not(feature = "visibility"))]
#[inline]
fn is_hidden((): ()) -> bool {
    false
}

/// Steps every awake spring on property `P`, in parallel, and puts the ones that settle to
/// sleep (triggering [`SpringSettled<P>`]).
pub(crate) fn step_springs<P: SpringProperty>(
    time: Res<Time>,
    real_time: Res<Time<Real>>,
    settings: Res<SpringSettings>,
    mut springs: Query<
        (
            Entity,
            &mut PropertySpring<P>,
            &mut P::Component,
            Visibility,
        ),
        Without<SpringAsleep<P>>,
    >,
    commands: ParallelCommands,
) {
    let game_dt = time.delta_secs();
    let real_dt = real_time.delta_secs();
    let default_clock = settings.default_clock;
    // Boxed: the fold behind `for_each_init` moves its state through every item, and a
    // pointer moves for free where the cache itself would be copied twice per entity.
    springs.par_iter_mut().for_each_init(
        Box::<TransitionCache>::default,
        |cache, (entity, mut spring, mut component, visibility)| {
            let dt = match spring.clock().unwrap_or(default_clock) {
                SpringClock::Game => game_dt,
                SpringClock::Real => real_dt,
            };
            let hidden = is_hidden(visibility);
            if step_spring(&mut spring, &mut component, dt, hidden, cache) == Stepped::Settled {
                put_to_sleep::<P>(&commands, entity);
            }
        },
    );
}

/// Marks a spring that settled as asleep and triggers [`SpringSettled<P>`]; out of line, so
/// that the per-entity loop stays small.
#[cold]
#[inline(never)]
fn put_to_sleep<P: SpringProperty>(commands: &ParallelCommands, entity: Entity) {
    commands.command_scope(|mut commands| {
        commands
            .entity(entity)
            .try_insert(SpringAsleep::<P>::default());
        commands.trigger(SpringSettled::<P>::new(entity));
    });
}

/// Wakes sleeping springs on property `P` whose target changed or that were kicked.
///
/// Only springs changed since the last run are looked at (a change-tick scan), so a scene of
/// sleeping springs costs one comparison per spring per frame.
pub(crate) fn wake_springs<P: SpringProperty>(
    mut commands: Commands,
    springs: Query<
        (Entity, &PropertySpring<P>),
        (With<SpringAsleep<P>>, Changed<PropertySpring<P>>),
    >,
) {
    for (entity, spring) in &springs {
        if spring.wants_to_move() {
            commands.entity(entity).try_remove::<SpringAsleep<P>>();
        }
    }
}
