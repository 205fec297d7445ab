//! One frame of a spring: the exact step in its property's space, the checks that keep it finite
//! and arriving, and the rest test.
#![expect(
    clippy::needless_bitwise_bool,
    reason = "non-short-circuit `&` on the per-entity hot path: one branch instead of several"
)]

use bevy::log::warn_once;
use bevy::math::{NormedVectorSpace, Vec4, VectorSpace};
use core::ops::DerefMut;

use sprung::{Spring, SpringState, Transition};

use super::cache::TransitionCache;
use super::table::{PreparedIncrements, SlotIncrements, TransitionTable};
use crate::clock::FrameSteps;
use crate::property::{OffsetOf, SpringProperty, ValueOf};
use crate::space::FastPath;
use crate::space::{Carried, SpringSpace, SpringVector};
use crate::spring::component::rest_squared;
use crate::spring::component::{PropertySpring, SpringMotion};
use crate::spring::preference::ReducedMotion;

/// What one frame did to a spring, and the value to write, if it changed.
#[derive(Clone, Copy, Debug)]
pub(super) struct Frame<V> {
    /// What happened.
    pub(super) outcome: Stepped,
    /// The new value of the property, if it differs from the one it holds.
    pub(super) write: Option<V>,
}

/// What the usual step did to a spring.
#[derive(Clone, Copy, Debug)]
pub(super) enum UsualStep<V> {
    /// It moved, and keeps moving: the property's new value.
    Moved(V),
    /// It keeps moving, but the property holds the value it would write.
    Still,
    /// The step is not the usual one; nothing was changed.
    Declined,
}

impl<V> UsualStep<V> {
    /// The frame of a spring that took the usual step (it keeps moving), or `None` where the
    /// step was declined.
    #[inline]
    fn frame(self) -> Option<Frame<V>> {
        let write = match self {
            Self::Moved(value) => Some(value),
            Self::Still => None,
            Self::Declined => return None,
        };
        Some(Frame {
            outcome: Stepped::Moving,
            write,
        })
    }
}

/// What one frame did to a spring.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Stepped {
    /// It moved and keeps moving.
    Moving,
    /// It reached rest and was snapped onto its target.
    Settled,
    /// It skips the frame: the time was put aside for a later exact catch-up.
    Deferred,
}

/// `2⁻⁶⁴` and `2⁶⁴`: an overflowing step is redone on the state scaled by the first (exactly,
/// a power of two) and scaled back by the second.
const DOWN: f32 = 1.0 / 18_446_744_073_709_551_616.0;
const UP: f32 = 18_446_744_073_709_551_616.0;

/// The exact step of offset `y` and velocity `v` toward a constant target, in the increment form
/// `(y, v) + D·(y, v)` (see [`Transition`]), the offset's increment added with compensation.
#[inline]
fn increment_step<V: SpringVector>(
    transition: &Transition<f32>,
    y: Carried<V>,
    v: V,
) -> (Carried<V>, V) {
    let [[d00, d01], [d10, d11]] = transition.increment_matrix();
    let increments = SlotIncrements::of(Vec4::new(d00, d01, d10, d11));
    step_by_increments(y, v, increments)
}

/// One step of offset `y` and velocity `v` by a transition's `increments`: what the general
/// step and the usual one both add.
#[inline]
fn step_by_increments<V: SpringVector>(
    y: Carried<V>,
    v: V,
    increments: SlotIncrements<V>,
) -> (Carried<V>, V) {
    let (moved, accelerated) = increments.step(y.offset, v);
    (y.plus(moved), v + accelerated)
}

/// The exact step of offset `y` (from the target's end-of-step position) and velocity `v`
/// toward a target moving at `rate`.
#[inline]
fn moving_step<V: SpringVector>(
    transition: &Transition<f32>,
    y: Carried<V>,
    v: V,
    rate: V,
) -> (Carried<V>, V) {
    let next = transition.step_toward_moving(SpringState::new(y.offset, v), V::ZERO, rate);
    // The core step carries its own remainder; fold ours in.
    (
        y.plus(next.position - y.offset).plus(next.remainder()),
        next.velocity,
    )
}

/// What Bevy's change ticks say of a spring since its last step, so that its usual step need
/// not read it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Unchanged {
    /// Nothing but the stepping system changed the spring's configuration: the usual step
    /// then needs none of it (its slot's ticket is in its motion).
    pub(super) config: bool,
    /// Nothing but the spring wrote its property: its value is what the spring wrote, and is
    /// not compared with it.
    pub(super) property: bool,
}

/// What the unusual step is told of how a spring came to it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Unusual {
    /// The spring skips this frame (its time is put aside for one exact step later).
    pub(super) skipping: bool,
    /// The usual step found the spring's slot, and declined for its state or its value.
    pub(super) slot_found: bool,
}

/// The transitions a spring's step reads: the property's table of this frame, and a cache of
/// the transitions the step computes itself (retargets, catch-up, unusual time steps).
pub(super) struct Transitions<'a> {
    /// The table of every distinct spring's transition over this frame.
    pub(super) table: &'a TransitionTable,
    /// Transitions computed for this thread, kept across frames.
    pub(super) cache: &'a mut TransitionCache,
}

impl<P: SpringProperty> SpringMotion<P> {
    /// One frame of the spring over `dt` on a component, writing its property if it changed
    /// (through a `Mut`, a write is a change). `skipping`: the frame is put aside for later.
    #[inline]
    pub(super) fn step_on<C: DerefMut<Target = P::Component>>(
        &mut self,
        config: &mut PropertySpring<P>,
        component: &mut C,
        steps: FrameSteps,
        skipping: bool,
        transitions: Transitions,
    ) -> Stepped {
        let frame = self.step(config, P::get(&**component), steps, skipping, transitions);
        if let Some(value) = frame.write {
            P::set(&mut **component, value);
        }
        frame.outcome
    }

    /// One frame of the spring configured by `config` from the property's `current` value
    /// (`skipping`: put aside for later), reading everything: the new value, only if it
    /// changed. The stepping system's own loop takes the usual step
    /// ([`step_usual`](Self::step_usual)) first, which reads nothing it need not; this is the
    /// step for springs it does not loop over (reduced motion, frames skipped).
    #[inline]
    pub(super) fn step(
        &mut self,
        config: &mut PropertySpring<P>,
        current: ValueOf<P>,
        steps: FrameSteps,
        skipping: bool,
        transitions: Transitions,
    ) -> Frame<ValueOf<P>> {
        let unusual = Unusual {
            skipping,
            slot_found: false,
        };
        self.step_unusual(config, current, steps, unusual, transitions)
    }

    /// The common case, which needs neither the configuration nor a transition of its own: for
    /// a spring whose configuration is `unchanged`, its ticket finds its increments in the
    /// table `prepared` for this frame, and the spring keeps moving (and this is the value to
    /// write, if it changed); otherwise the step is declined (the state untouched) for
    /// [`step_unusual`](Self::step_unusual) to do. A property `unchanged` holds what the spring
    /// wrote, and `current` is not compared with it.
    ///
    /// It is straight-line, a handful of vector instructions. Every other case goes out of line
    /// from the same, untouched state: a spring that was touched first checks that its step is
    /// still the usual one (the target of its last step, no moving target, no time pending)
    /// and finds its slot; a state at rest or too large for the table's
    /// [`step_limit`](TransitionTable::step_limit) (which covers NaN) steps the general way (a
    /// state at rest settles there, without a step).
    #[expect(
        clippy::inline_always,
        reason = "the per-entity loop's hot path: measured cheaper inlined into it than called"
    )]
    #[inline(always)]
    pub(super) fn step_usual(
        &mut self,
        current: ValueOf<P>,
        unchanged: Unchanged,
        prepared: PreparedIncrements,
    ) -> UsualStep<ValueOf<P>> {
        let found = if unchanged.config {
            prepared.increments::<OffsetOf<P>>(self.ticket())
        } else {
            None
        };
        match found {
            Some(increments) => self.step_by(
                increments,
                current,
                unchanged.property,
                prepared.step_limit(),
            ),
            None => UsualStep::Declined,
        }
    }

    /// The usual step by `increments` from the property's `current` value, or declined (the
    /// state untouched) where the value was written by something else (not tested where it is
    /// known `unwritten`), the state is at rest or above the table's step `limit`.
    #[expect(
        clippy::inline_always,
        reason = "the per-entity loop's hot path (see `step_usual`)"
    )]
    #[inline(always)]
    fn step_by(
        &mut self,
        increments: SlotIncrements<OffsetOf<P>>,
        current: ValueOf<P>,
        unwritten: bool,
        limit: f32,
    ) -> UsualStep<ValueOf<P>> {
        // The spring's target (a usual step is toward the target of the last one): read from
        // the motion, the configuration is not read at all while nothing changes it.
        let target = self.active_target;
        let before = self.offset;
        let (y, v) = (before.offset, self.velocity);
        // A value written by something else since (rare) is stepped the general way: here
        // the offset is always the carried one, and its sum with the target is shared with
        // the step's own. A space whose step may be declined after it tests this then too, in
        // the same branch (`SpringSpace::constrains_usual_step`). Where the change tick
        // already says that nothing else wrote it, the test is left out.
        let written = unwritten || P::Space::is_written(current, target, before, FastPath);
        let (written_now, written_after) = if P::Space::constrains_usual_step(FastPath) {
            (true, written)
        } else {
            (written, true)
        };
        // Rest, and range, are tested on the state the step starts from: the test then waits
        // on nothing the step computes, and the two run side by side (faster than testing the
        // result). A spring settles the frame after its state came within
        // its tolerances. Within the table's limit (a NaN is not), the step's result is finite
        // and of finite squared length: it needs no test of its own.
        if !(written_now & SpringVector::steps_on(y, v, self.rest_squared, limit, FastPath)) {
            return UsualStep::Declined;
        }
        let (after, velocity) = step_by_increments(before, v, increments);
        let constrained = P::Space::constrain_usual(target, y, after, velocity, FastPath);
        let (Some((after, velocity)), true) = (constrained, written_after) else {
            return UsualStep::Declined;
        };
        self.offset = after;
        self.velocity = velocity;
        let value = P::Space::at_carried(target, after);
        if P::Space::same(value, current, FastPath) {
            UsualStep::Still
        } else {
            UsualStep::Moved(value)
        }
    }

    /// [`step`](Self::step) when [`step_usual`](Self::step_usual) declined: out of line, the
    /// usual step from the spring's slot if it was touched and its step is still the usual one,
    /// otherwise the general step, with a transition computed (once per distinct spring and
    /// time step, in `cache`).
    #[inline(never)]
    pub(super) fn step_unusual(
        &mut self,
        config: &mut PropertySpring<P>,
        current: ValueOf<P>,
        steps: FrameSteps,
        unusual: Unusual,
        transitions: Transitions,
    ) -> Frame<ValueOf<P>> {
        // A spring whose increments the usual step found was declined for its state, or for
        // its value: the general step. One that was touched (or whose table was cleared) may
        // still step the usual way, from its slot.
        let table = transitions.table;
        let found = unusual.slot_found && table.increments(self.ticket()).is_some();
        if !found
            && let Some(increments) =
                self.touched_increments(config, &steps, unusual.skipping, table)
            && let Some(frame) = self
                .step_by(increments, current, false, table.step_limit())
                .frame()
        {
            return frame;
        }
        let dt = steps.dt(config.clock);
        let frame = self.step_general(config, current, dt, unusual.skipping, transitions);
        self.clear_ticket();
        frame
    }

    /// One frame under a reduced-motion `preference` (out of line: an accessibility setting,
    /// not the hot path). `Snap` jumps to the target (and settles, unless the target moves);
    /// the others step the spring the general way, critically damped at least or with its time
    /// scaled.
    #[inline(never)]
    pub(super) fn step_reduced(
        &mut self,
        config: &mut PropertySpring<P>,
        current: ValueOf<P>,
        steps: FrameSteps,
        preference: ReducedMotion,
        transitions: Transitions,
    ) -> Frame<ValueOf<P>> {
        let dt = steps.dt(config.clock);
        self.clear_ticket();
        if preference == ReducedMotion::Snap {
            self.repair(config, current, transitions.table);
            let target = config.target;
            self.active_target = target;
            self.offset = Carried::new(OffsetOf::<P>::ZERO);
            self.set_pending(0.0);
            self.rest_squared = rest_squared::<P>(config.rest, target);
            self.velocity = OffsetOf::<P>::ZERO;
            let outcome = if config.target_rate() == OffsetOf::<P>::ZERO {
                Stepped::Settled
            } else {
                Stepped::Moving
            };
            return Frame {
                outcome,
                write: (!P::Space::same(target, current, FastPath)).then_some(target),
            };
        }
        let spring = config.spring;
        config.spring = preference.spring(spring);
        let frame = self.step_general(config, current, preference.dt(dt), false, transitions);
        config.spring = spring;
        frame
    }

    /// The increments of the spring's slot when its ticket did not find them (it was touched,
    /// or its table was cleared), if this frame's step is the usual one.
    #[inline]
    fn touched_increments(
        &mut self,
        config: &PropertySpring<P>,
        steps: &FrameSteps,
        skipping: bool,
        table: &TransitionTable,
    ) -> Option<SlotIncrements<OffsetOf<P>>> {
        let clock = FrameSteps::index(config.clock);
        let ticket = self.usual_slot(config, steps.of(clock), clock, skipping, table)?;
        table.prepared().increments::<OffsetOf<P>>(ticket)
    }

    /// The ticket of the spring's slot if this frame's step is the usual one (a visible spring
    /// toward the target of its last step, which does not move, with no time pending and the
    /// tolerances it was set up with), remembered for the frames that follow; `None` otherwise.
    #[inline]
    fn usual_slot(
        &mut self,
        config: &PropertySpring<P>,
        dt: f32,
        clock: u8,
        skipping: bool,
        table: &TransitionTable,
    ) -> Option<u64> {
        let usual = !skipping
            & (dt > 0.0)
            & (self.pending() == 0.0)
            & (config.target == self.active_target)
            & (config.target_rate() == OffsetOf::<P>::ZERO)
            & !config.velocity_change.is_pending();
        if !usual {
            return None;
        }
        // Touched: the tolerances may have changed too (a `rest` set through reflection).
        self.rest_squared = rest_squared::<P>(config.rest, config.target);
        let ticket = if table.holds(self.ticket(), &config.spring, clock) {
            self.ticket()
        } else if let Some(ticket) = table.lookup(&config.spring, clock) {
            ticket
        } else {
            // New parameters: stepped the general way this frame, from its slot the next.
            table.request(&config.spring, clock);
            return None;
        };
        self.set_ticket(ticket);
        Some(ticket)
    }

    /// [`step`](Self::step) in every case: retargets, catch-up, moving targets, input written
    /// through reflection, steps that overflow.
    #[inline(never)]
    fn step_general(
        &mut self,
        config: &mut PropertySpring<P>,
        current: ValueOf<P>,
        dt: f32,
        skipping: bool,
        transitions: Transitions,
    ) -> Frame<ValueOf<P>> {
        let Transitions { table, cache } = transitions;
        self.repair(config, current, table);
        let target = config.target;
        let retargeted = target != self.active_target;
        if skipping && !retargeted {
            self.set_pending(self.pending() + dt);
            return Frame {
                outcome: Stepped::Deferred,
                write: None,
            };
        }
        let active = self.active_target;
        // A property something made invalid (a NaN written into a `Transform`) is overwritten
        // from the spring's own state.
        let carried = self.offset;
        let mut offset = if !P::Space::is_valid(current)
            || P::Space::is_written(current, active, carried, FastPath)
        {
            carried
        } else {
            P::Space::carried_offset(current, active)
        };
        if !P::Space::is_valid(current) {
            warn_once!(
                "bevy_sprung: a sprung property is not finite ({current:?}); the spring restores it"
            );
        }
        let mut velocity = self.velocity;
        // Catch up the time skipped under the target that was in effect, then retarget.
        let pending = self.pending();
        if pending > 0.0 {
            self.set_pending(0.0);
            (offset, velocity) = Self::advance(config, cache, active, (offset, velocity), pending);
        }
        if retargeted {
            (offset, velocity) = P::Space::retarget(active, target, offset, velocity);
            self.active_target = target;
        }
        // The tolerances as applied toward this target (and any `rest` reflection wrote).
        self.rest_squared = rest_squared::<P>(config.rest, target);
        // A state already at rest is not stepped: it settles now. (The usual step tests the
        // state it starts from and declines at rest: this is where it settles.)
        let mut squared = (offset.offset.norm_squared(), velocity.norm_squared());
        let still = config.target_rate() == OffsetOf::<P>::ZERO && self.is_at_rest(squared);
        if dt > 0.0 && !still {
            (offset, velocity) = Self::advance(config, cache, target, (offset, velocity), dt);
            squared = (offset.offset.norm_squared(), velocity.norm_squared());
        }
        self.finish(config, current, (offset, velocity), squared)
    }

    /// Restores a valid state where reflection (an inspector, a scene) wrote an invalid one,
    /// with one warning each: the last valid target, zero velocities, the last valid parameters.
    /// Then applies the velocity set or kicked through `config` since the last step.
    #[cold]
    fn repair(
        &mut self,
        config: &mut PropertySpring<P>,
        current: ValueOf<P>,
        table: &TransitionTable,
    ) {
        // The target the motion heads for is valid by construction (the insert hook rests it
        // where the property is when the target is not); one written through reflection is
        // replaced the same way, so that nothing is ever sprung from an invalid value.
        if !P::Space::is_valid(self.active_target) {
            self.active_target = [current, config.target]
                .into_iter()
                .find(|&value| P::Space::is_valid(value))
                .unwrap_or_default();
            self.offset = Carried::new(OffsetOf::<P>::ZERO);
        }
        if !P::Space::is_valid(config.target) {
            warn_once!(
                "bevy_sprung: a spring's target is not finite ({:?}); it keeps its last valid \
                 target",
                config.target
            );
            config.target = self.active_target;
        }
        if !self.velocity.is_finite() {
            warn_once!("bevy_sprung: a spring's velocity is not finite; it is reset to zero");
            self.velocity = OffsetOf::<P>::ZERO;
        }
        // A velocity set or kicked since the last step (each finite, checked when given).
        let change = core::mem::take(&mut config.velocity_change);
        let changed = change.applied_to(self.velocity);
        if changed.is_finite() {
            self.velocity = changed;
        } else {
            warn_once!(
                "bevy_sprung: refused a spring impulse that would make its velocity infinite"
            );
        }
        if !config.target_rate().is_finite() {
            warn_once!(
                "bevy_sprung: a spring's target velocity is not finite; it is reset to zero"
            );
            config.target_velocity = OffsetOf::<P>::ZERO.into();
        }
        if !(self.offset.offset.is_finite() && self.offset.remainder.is_finite()) {
            self.offset = Carried::new(OffsetOf::<P>::ZERO);
        }
        let spring = config.spring;
        if Spring::new(spring.mass(), spring.stiffness(), spring.damping()).is_err() {
            warn_once!(
                "bevy_sprung: a spring has invalid parameters ({spring:?}); it keeps its last \
                 valid ones"
            );
            // Its slot holds the parameters it last stepped with, which were valid.
            config.spring = table.parameters(self.ticket()).unwrap_or_default();
        }
    }

    /// Advances `(offset, velocity)` by `dt` toward `target` (moving at the spring's target
    /// velocity), in range. A step whose result overflows `f32` is redone on the state scaled
    /// down by `2⁶⁴` and scaled back with each component saturated at `±f32::MAX`: the state
    /// stays finite and the spring still comes back.
    fn advance(
        config: &PropertySpring<P>,
        cache: &mut TransitionCache,
        target: ValueOf<P>,
        (offset, velocity): (Carried<OffsetOf<P>>, OffsetOf<P>),
        dt: f32,
    ) -> (Carried<OffsetOf<P>>, OffsetOf<P>) {
        let Some(transition) = cache.get(&config.spring, dt) else {
            // Unreachable: `repair` made the parameters valid.
            return (offset, velocity);
        };
        let rate = config.target_rate();
        let step = |y: Carried<OffsetOf<P>>, v, r| {
            let (after, v) = if r == OffsetOf::<P>::ZERO {
                increment_step(transition, y, v)
            } else {
                moving_step(transition, y, v, r)
            };
            P::Space::constrain(target, y.offset, after, v)
        };
        let (after, next_velocity) = step(offset, velocity, rate);
        if after.offset.is_finite() && after.remainder.is_finite() && next_velocity.is_finite() {
            return (after, next_velocity);
        }
        warn_once!(
            "bevy_sprung: a spring step overflowed f32; the state is held at the largest finite \
             values"
        );
        let scaled = Carried::new(offset.offset * DOWN);
        let (after, next_velocity) = step(scaled, velocity * DOWN, rate * DOWN);
        (
            Carried::new((after.offset * UP).saturate()),
            (next_velocity * UP).saturate(),
        )
    }

    /// Whether a state of squared offset and speed is within the spring's rest tolerances (a
    /// NaN is not): the test the usual step's [`SpringVector::steps_on`] makes too.
    #[inline]
    fn is_at_rest(&self, squared: (f32, f32)) -> bool {
        crate::space::is_within_rest(squared, self.rest_squared)
    }

    /// The value at `offset` from `target`, and the offset: where the value would leave `f32`
    /// (a target near `f32::MAX` and an offset past it), the offset is halved until it fits —
    /// the spring meets the edge of `f32` as a wall and comes back from there. Exact halvings,
    /// at most a few for any finite state; the usual step's states never get there (its limit
    /// keeps the offset far below a target's `ulp` at `f32::MAX`).
    fn within_range(
        target: ValueOf<P>,
        mut offset: Carried<OffsetOf<P>>,
    ) -> (ValueOf<P>, Carried<OffsetOf<P>>) {
        for _ in 0..300 {
            let value = P::Space::at_carried(target, offset);
            if P::Space::is_valid(value) {
                return (value, offset);
            }
            offset = Carried::new(offset.offset * 0.5);
        }
        warn_once!("bevy_sprung: a spring's value left f32; it is put on its target");
        (target, Carried::new(OffsetOf::<P>::ZERO))
    }

    /// The end of a step to `(offset, velocity)` with squared lengths `squared`: at rest (toward
    /// a target that does not move) the spring snaps onto its target and settles; the state is
    /// stored, and the new value returned if it differs from `current`.
    #[inline]
    fn finish(
        &mut self,
        config: &mut PropertySpring<P>,
        current: ValueOf<P>,
        (offset, velocity): (Carried<OffsetOf<P>>, OffsetOf<P>),
        (offset_squared, speed_squared): (f32, f32),
    ) -> Frame<ValueOf<P>> {
        let target = config.target;
        let zero = OffsetOf::<P>::ZERO;
        let (value, offset, velocity, outcome) =
            if config.target_rate() == zero && self.is_at_rest((offset_squared, speed_squared)) {
                // Snapping is what makes sleeping exact: nothing moves until the target changes.
                (target, Carried::new(zero), zero, Stepped::Settled)
            } else {
                let (value, offset) = Self::within_range(target, offset);
                (value, offset, velocity, Stepped::Moving)
            };
        self.offset = offset;
        self.velocity = velocity;
        Frame {
            outcome,
            write: (value != current).then_some(value),
        }
    }
}
