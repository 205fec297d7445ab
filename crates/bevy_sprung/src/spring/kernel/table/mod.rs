//! Every distinct spring's transition, kept across frames: what the per-entity step reads.

use core::marker::PhantomData;
use core::sync::atomic::{AtomicBool, Ordering};

use bevy::math::Vec4;
use bevy::platform::collections::HashMap;
use bevy::utils::Parallel;
use sprung::Spring;

mod anchor;
mod slot;

use anchor::{Anchor, AnchorLanes};
use slot::{Key, Slot};

use super::parallel::{SplitRows, scope_threads, split_over_threads};
use crate::clock::FrameSteps;
use crate::space::FastPath;
use crate::space::{SpringVector, paired_increments};

/// The slots of every distinct `(spring, clock)` of one property, kept by its stepping system
/// across frames. A spring remembers its slot's ticket, so that while nothing touches it,
/// finding its transition is one indexed load, however many springs the scene has: one shared
/// spring, a handful, or one per entity.
///
/// A frame goes: [`prepare`](Self::prepare) makes every slot's increments those of this
/// frame's time steps (in parallel when the compute pool has threads to spare); the springs
/// step, reading the table only (so that they can step in parallel), and a spring whose
/// parameters have no slot yet [`request`](Self::request)s one and steps the general way;
/// [`finish`](Self::finish) adds the requested slots and collects the table.
///
/// Slots are added when a spring first needs one and never move; when the table has far more
/// slots than springs (springs despawned or changed), it is cleared, and every spring finds (or
/// makes) its slot again. A slot's ticket is its index plus the number of slots every earlier
/// clearing removed: tickets are never reused (a `u64` does not run out), so the one test that
/// a ticket is in the table's range both finds its slot and refuses a ticket from before a
/// clearing.
#[derive(Default)]
pub(crate) struct TransitionTable {
    slots: Vec<Slot>,
    /// Each slot's increments `D = M − I` over this frame's time step, row-major, by the same
    /// index (16 bytes: all the per-entity step reads, unless it reads `paired`), padded to a
    /// multiple of four.
    increments: Vec<Vec4>,
    /// Whether the table is for a vector that reads its increments in pairs
    /// ([`SpringVector::paired_increments`]).
    pairs: bool,
    /// Where `pairs`: each slot's increments as [`paired_increments`] makes them (32 bytes, all
    /// the step reads then), by the same index; empty otherwise.
    paired: Vec<[Vec4; 2]>,
    /// The anchors the slots' increments are extended from, four slots a lane each.
    lanes: Vec<AnchorLanes>,
    /// The clock index ([`FrameSteps`]) of each lane, by the same index as `lanes`.
    lane_clocks: Vec<[u8; 4]>,
    index: HashMap<Key, u32>,
    /// The ticket of the first slot: the slots every clearing removed, in all.
    first: u64,
    /// The steps every slot's increments are for, if they all are (no slot added since).
    prepared_for: Option<FrameSteps>,
    /// The clocks of the slots, a bit each (by [`FrameSteps`] index).
    clocks: u8,
    /// Slots springs asked for this frame, per thread.
    requests: Parallel<Vec<(Key, Spring<f32>)>>,
    /// Whether any spring asked for a slot since the last [`finish`](Self::finish): a frame
    /// without requests does not visit the per-thread buffers.
    requested: AtomicBool,
    /// The squared length of offset and velocity up to which one step by any slot's increments
    /// stays far inside `f32` (see [`step_limit`](Self::step_limit)).
    step_limit: f32,
    /// The largest [`bound`](Anchor::bound) of the anchors made since the lanes were last
    /// cleared: every slot's increments, extended or exact, are within it (replaced anchors'
    /// bounds stay in it, which only makes the limit more cautious).
    anchor_bound: f32,
}

/// This frame's increments of a [`TransitionTable`]'s slots, by ticket, and its
/// [`step_limit`](TransitionTable::step_limit): all the usual step reads of it.
#[derive(Clone, Copy)]
pub(crate) struct PreparedIncrements<'a> {
    increments: &'a [Vec4],
    paired: &'a [[Vec4; 2]],
    first: u64,
    step_limit: f32,
}

/// A slot's increments as the usual step of a `V` reads them: `[d00, d01, d10, d11]`, or the
/// pairs of [`paired_increments`] for a vector that reads them so
/// ([`SpringVector::paired_increments`]).
#[derive(Clone, Copy)]
pub(crate) struct SlotIncrements<V>([Vec4; 2], PhantomData<V>);

impl<V: SpringVector> SlotIncrements<V> {
    /// A transition's `increments` `[d00, d01, d10, d11]`, as `V` reads them.
    #[inline]
    pub(crate) fn of(increments: Vec4) -> Self {
        let read = if V::paired_increments(FastPath) {
            paired_increments(increments)
        } else {
            [increments, Vec4::ZERO]
        };
        Self(read, PhantomData)
    }

    /// What one step adds to an `offset` and a `velocity` (see
    /// [`SpringVector::step_increments`]).
    #[inline]
    pub(crate) fn step(self, offset: V, velocity: V) -> (V, V) {
        if V::paired_increments(FastPath) {
            V::step_paired_increments(offset, velocity, self.0, FastPath)
        } else {
            V::step_increments(offset, velocity, self.0[0], FastPath)
        }
    }
}

impl PreparedIncrements<'_> {
    /// The increments of the slot with `ticket` as a `V` reads them, if the table has it:
    /// one subtraction and one bounds check find it.
    #[inline]
    pub(crate) fn increments<V: SpringVector>(self, ticket: u64) -> Option<SlotIncrements<V>> {
        // The padding past the last slot holds no ticket's increments, but reading it is
        // harmless: a ticket past the last slot was never handed out.
        let index = usize::try_from(ticket.wrapping_sub(self.first)).ok()?;
        if V::paired_increments(FastPath) {
            // Empty unless the table was prepared for such a vector (then declined: the
            // general step).
            let pairs = self.paired.get(index)?;
            Some(SlotIncrements(*pairs, PhantomData))
        } else {
            let rows = self.increments.get(index)?;
            Some(SlotIncrements([*rows, Vec4::ZERO], PhantomData))
        }
    }

    /// See [`TransitionTable::step_limit`].
    #[inline]
    pub(crate) fn step_limit(self) -> f32 {
        self.step_limit
    }
}

/// `2¹²⁶`: the squared length a step's result stays below, a factor of 4 under `f32::MAX`
/// for the rounding of the step's few operations.
const STEP_RESULT_BOUND: f32 = 85_070_591_730_234_615_865_843_651_857_942_052_864.0;

/// The step limit (see [`TransitionTable::step_limit`]) for increments whose row sums of
/// absolute entries are at most `bound`. A state whose parts' squared lengths are within the
/// limit has both parts no longer than its root; a step adds at most `bound` times that to
/// each: the result is no longer than `(1 + bound)·√limit`, whose square is the result bound
/// (0 for an infinite bound).
fn step_limit_for(bound: f32) -> f32 {
    STEP_RESULT_BOUND / ((1.0 + bound) * (1.0 + bound))
}

/// Slots above which the preparation is split over threads: enough work to outweigh waking
/// them.
const PREPARE_PARALLEL: usize = 4096;

/// Blocks of four slots a thread claims at least when the preparation is split (see
/// [`split_over_threads`]): about a microsecond of extending.
const PREPARE_GRAIN: usize = 64;

/// The blocks of a [`TransitionTable`] (or a part of them) that its preparation writes: the
/// anchor lanes, their clocks, and the increments (and their pairs, if the table keeps them)
/// and slots of their four slots each.
struct PrepareRows<'a> {
    lanes: &'a mut [AnchorLanes],
    clocks: &'a [[u8; 4]],
    increments: &'a mut [Vec4],
    paired: &'a mut [[Vec4; 2]],
    slots: &'a [Slot],
}

impl SplitRows for PrepareRows<'_> {
    #[inline]
    fn len(&self) -> usize {
        self.lanes.len()
    }

    #[inline]
    fn take_front(&mut self, blocks: usize) -> Self {
        let blocks = blocks.min(self.len());
        let slots = (4 * blocks).min(self.slots.len());
        let paired = (4 * blocks).min(self.paired.len());
        Self {
            lanes: self.lanes.split_off_mut(..blocks).unwrap_or_default(),
            clocks: self.clocks.split_off(..blocks).unwrap_or_default(),
            increments: self
                .increments
                .split_off_mut(..4 * blocks)
                .unwrap_or_default(),
            paired: self.paired.split_off_mut(..paired).unwrap_or_default(),
            slots: self.slots.split_off(..slots).unwrap_or_default(),
        }
    }
}

impl TransitionTable {
    /// The index of the slot with `ticket`, if the table has it.
    #[inline]
    fn index_of(&self, ticket: u64) -> Option<usize> {
        // A ticket from before a clearing wraps far past the end (as do those from `SlotTicket::NO_SLOT`
        // up).
        usize::try_from(ticket.wrapping_sub(self.first))
            .ok()
            .filter(|&index| index < self.slots.len())
    }

    /// Makes every slot's increments those over its clock's time step in `steps`. A frame with
    /// the same time steps as the last costs one vector comparison per four slots; with new
    /// ones (Bevy's virtual time varies from frame to frame), the slots are extended four at a
    /// time or recomputed, split over a compute-pool scope's threads (the pool's and this one)
    /// when there are several.
    pub(crate) fn prepare(&mut self, steps: FrameSteps) {
        // The same steps as the frame before (a fixed time step): nothing to look at.
        if self
            .prepared_for
            .is_some_and(|prepared| prepared.same(steps))
            && (!self.pairs || self.paired.len() == self.increments.len())
        {
            return;
        }
        self.prepared_for = Some(steps);
        // Every slot on one clock (nearly always): its step splat once for the whole table.
        if self.clocks.is_power_of_two() {
            // The one bit's index (below 8, so the conversion never fails).
            let clock = u8::try_from(self.clocks.trailing_zeros()).unwrap_or_default();
            let dt = Vec4::splat(steps.of(clock));
            self.prepare_with(move |_| dt);
        } else {
            self.prepare_with(move |&[a, b, c, d]: &[u8; 4]| {
                Vec4::new(steps.of(a), steps.of(b), steps.of(c), steps.of(d))
            });
        }
    }

    /// [`prepare`](Self::prepare) for the springs of a property whose offsets are `V`s: with
    /// the increments also in pairs if `V` reads them so ([`SpringVector::paired_increments`]).
    pub(crate) fn prepare_for<V: SpringVector>(&mut self, steps: FrameSteps) {
        self.pairs = V::paired_increments(FastPath);
        self.prepare(steps);
    }

    /// [`prepare`](Self::prepare) with `steps_of` giving the time steps of lanes on its clocks.
    #[inline]
    fn prepare_with(&mut self, steps_of: impl Fn(&[u8; 4]) -> Vec4 + Copy + Send + Sync) {
        // The steps copied into the closure: captured by reference, a slot cost more where the
        // closure was not inlined.
        // Each part returns the largest bound of the anchors it made.
        let prepare = move |part: PrepareRows| {
            let (increments, _) = part.increments.as_chunks_mut::<4>();
            let blocks = part.lanes.iter_mut().zip(part.clocks).zip(increments);
            let mut bound = 0.0_f32;
            // The slots by block index: only a lane that needs an exact transition reads one.
            for (block, ((lanes, clocks), increments)) in blocks.enumerate() {
                lanes.prepare(
                    increments,
                    (&part.slots, block),
                    steps_of(clocks),
                    &mut bound,
                );
            }
            // The pairs (none unless the table keeps them) from the part's increments, while
            // they are in this thread's cache.
            for (pairs, rows) in part.paired.iter_mut().zip(&*part.increments) {
                *pairs = paired_increments(*rows);
            }
            bound
        };
        let threads = if self.slots.len() > PREPARE_PARALLEL {
            scope_threads()
        } else {
            1
        };
        let pairs = if self.pairs { self.increments.len() } else { 0 };
        self.paired.resize(pairs, [Vec4::ZERO; 2]);
        let rows = PrepareRows {
            lanes: &mut self.lanes,
            clocks: &self.lane_clocks,
            increments: &mut self.increments,
            paired: &mut self.paired,
            slots: &self.slots,
        };
        let made = split_over_threads(rows, (threads, PREPARE_GRAIN), prepare, (0.0, f32::max));
        self.anchor_bound = self.anchor_bound.max(made);
        self.step_limit = step_limit_for(self.anchor_bound);
    }

    /// The squared length up to which, for the offset `|y|²` and the velocity `|v|²` both,
    /// one step by any slot's prepared increments gives a result of squared length at most
    /// `2¹²⁶`: finite, and far from overflowing, so the step needs no test of its result. It
    /// is that of the anchors' bounds (see [`Anchor::bound`]), which hold for every step within
    /// their reach, and of the increments computed exactly: a frame's preparation adds nothing
    /// up. 0 (only a state at zero is within it) before the first preparation and when a bound
    /// is not finite.
    #[inline]
    #[must_use]
    pub(crate) fn step_limit(&self) -> f32 {
        self.step_limit
    }

    /// The increments of the slot with `ticket` (prepared for this frame), if the table has
    /// it: one subtraction and one bounds check find it.
    #[inline]
    pub(crate) fn increments(&self, ticket: u64) -> Option<Vec4> {
        self.index_of(ticket)
            .and_then(|index| self.increments.get(index).copied())
    }

    /// What the usual step reads of the table, copied out of it: a loop over springs keeps it
    /// in registers (the table itself, with its request buffers, may change behind a shared
    /// reference, so its fields would be loaded again for every spring).
    #[inline]
    #[must_use]
    pub(crate) fn prepared(&self) -> PreparedIncrements<'_> {
        PreparedIncrements {
            increments: &self.increments,
            paired: &self.paired,
            first: self.first,
            step_limit: self.step_limit,
        }
    }

    /// The ticket of the slot of `spring` on clock `clock`, if the table has one.
    #[inline]
    pub(crate) fn lookup(&self, spring: &Spring<f32>, clock: u8) -> Option<u64> {
        self.index
            .get(&Key::new(spring, clock))
            .map(|&index| self.first.wrapping_add(u64::from(index)))
    }

    /// Asks for a slot for `spring` on clock `clock`, added when the frame
    /// [`finish`](Self::finish)es: from the next frame on, the spring finds it.
    #[cold]
    pub(crate) fn request(&self, spring: &Spring<f32>, clock: u8) {
        // Read after the frame's parallel steps are joined, which orders this store before it.
        self.requested.store(true, Ordering::Relaxed);
        self.requests
            .borrow_local_mut()
            .push((Key::new(spring, clock), *spring));
    }

    /// After a frame that stepped `springs` springs: adds the slots requested (for parameters
    /// that are a valid spring; reflection can write others), then clears the table when it
    /// holds more than twice as many slots as there are springs (and a few more), so that
    /// springs despawned or changed do not keep slots for ever.
    pub(crate) fn finish(&mut self, springs: usize) {
        if core::mem::take(self.requested.get_mut()) {
            self.add_requested();
        }
        if self.slots.len() > 2 * springs + 64 {
            self.first = self.first.wrapping_add(self.slots.len() as u64);
            self.slots.clear();
            self.increments.clear();
            self.paired.clear();
            self.lanes.clear();
            self.anchor_bound = 0.0;
            self.lane_clocks.clear();
            self.index.clear();
            self.clocks = 0;
            self.prepared_for = None;
        }
    }

    /// [`finish`](Self::finish)'s first part: adds the slots requested.
    #[cold]
    fn add_requested(&mut self) {
        let mut requests = core::mem::take(&mut self.requests);
        for (key, spring) in requests.iter_mut().flat_map(|requests| requests.drain(..)) {
            if self.index.contains_key(&key)
                || Spring::new(spring.mass(), spring.stiffness(), spring.damping()).is_err()
            {
                continue;
            }
            let Ok(index) = u32::try_from(self.slots.len()) else {
                break;
            };
            let lane = self.slots.len() % 4;
            if lane == 0 {
                self.lanes.push(AnchorLanes::EMPTY);
                // The padding lanes on the default clock.
                self.lane_clocks.push([2; 4]);
                self.increments.extend([Vec4::ZERO; 4]);
            }
            if let (Some(lanes), Some(clocks)) =
                (self.lanes.last_mut(), self.lane_clocks.last_mut())
            {
                clocks[lane] = key.clock;
                lanes.set(lane, &Anchor::NONE);
            }
            self.slots.push(Slot { key, spring });
            self.index.insert(key, index);
            self.clocks |= 1 << (key.clock & 3);
            self.prepared_for = None;
        }
        // The per-thread buffers keep their capacity for the next frame.
        self.requests = requests;
    }

    /// The parameters of the slot with `ticket`, if the table has it: the last valid
    /// parameters of the spring that remembers it.
    pub(crate) fn parameters(&self, ticket: u64) -> Option<Spring<f32>> {
        self.index_of(ticket).map(|index| self.slots[index].spring)
    }

    /// Whether `spring` is what the slot with `ticket` was made for (after it was touched).
    #[inline]
    pub(crate) fn holds(&self, ticket: u64, spring: &Spring<f32>, clock: u8) -> bool {
        self.index_of(ticket)
            .is_some_and(|index| self.slots[index].key == Key::new(spring, clock))
    }
}

#[cfg(test)]
mod tests {
    use bevy::math::{Vec2, Vec3A, Vec4};
    use sprung::Spring;

    use super::anchor::Anchor;
    use super::anchor::testing::{error_in_u, extend};
    use super::{STEP_RESULT_BOUND, TransitionTable, step_limit_for};
    use crate::clock::FrameSteps;
    use crate::space::paired_increments;

    /// The worst [`error_in_u`] of every slot's prepared increments over its clock's step in
    /// `steps`.
    fn worst_prepared_error(
        table: &TransitionTable,
        slots: &[(Spring<f32>, u8)],
        steps: FrameSteps,
    ) -> f64 {
        let mut worst = 0.0_f64;
        let first = slots
            .first()
            .and_then(|(spring, clock)| table.lookup(spring, *clock));
        for (index, (spring, clock)) in (0_u64..).zip(slots) {
            let slot = table.lookup(spring, *clock).unwrap();
            assert_eq!(
                Some(slot - index),
                first,
                "slots are made in the order asked for"
            );
            let rows = table.increments(slot).unwrap();
            // What the usual step reads: the rows, and where the table keeps them, the pairs.
            let prepared = table.prepared();
            let bits = |vectors: [Vec4; 2]| vectors.map(|v| v.to_array().map(f32::to_bits));
            let read = prepared.increments::<Vec3A>(slot).unwrap().0;
            assert_eq!(bits(read)[0], bits([rows; 2])[0]);
            if table.pairs {
                let read = prepared.increments::<Vec2>(slot).unwrap().0;
                assert_eq!(bits(read), bits(paired_increments(rows)), "slot {slot}");
            }
            let got = rows.to_array();
            worst = worst.max(error_in_u(got, *spring, f64::from(steps.of(*clock))));
        }
        worst
    }

    /// A table of a number of slots that fills no whole set of lanes, on all three clocks:
    /// every slot's increments are its own spring's over its own clock's step, whether computed
    /// exactly (first frame, and a step out of reach), extended (a step nearby), or kept (the
    /// same step, bit for bit); a clock whose step alone changed changes only its slots.
    #[test]
    fn every_slot_is_prepared_for_its_own_clock() {
        let slots: Vec<(Spring<f32>, u8)> = (0..11_u8)
            .map(|i| {
                let omega = 2.0 + 7.0 * f32::from(i);
                let zeta = [0.1, 1.0, 3.0][usize::from(i % 3)];
                (Spring::from_natural_frequency(omega, zeta).unwrap(), i % 3)
            })
            .collect();
        let mut table = TransitionTable::default();
        for (spring, clock) in &slots {
            table.request(spring, *clock);
        }
        table.finish(slots.len());
        let frames = [
            FrameSteps::each(1.0 / 60.0, 1.0 / 144.0, 1.0 / 30.0),
            // Within every anchor's reach (below a tenth of the step).
            FrameSteps::each(1.0 / 60.0 * 1.001, 1.0 / 144.0 * 0.999, 1.0 / 30.0 * 1.002),
            FrameSteps::each(1.0 / 60.0 * 1.001, 1.0 / 144.0 * 0.999, 1.0 / 30.0 * 1.002),
            // Only the real clock's step changes, and far.
            FrameSteps::each(1.0 / 60.0 * 1.001, 0.25, 1.0 / 30.0 * 1.002),
        ];
        let mut before: Vec<[u32; 4]> = Vec::new();
        for (frame, steps) in frames.into_iter().enumerate() {
            table.prepare(steps);
            let worst = worst_prepared_error(&table, &slots, steps);
            assert!(worst < 8.0, "frame {frame}: {worst} u");
            let now: Vec<[u32; 4]> = (0..11)
                .map(|i| table.increments(i).unwrap().to_array().map(f32::to_bits))
                .collect();
            if frame == 2 {
                assert_eq!(now, before, "the same steps keep the increments");
            }
            if frame == 3 {
                for (i, (_, clock)) in slots.iter().enumerate() {
                    assert_eq!(now[i] == before[i], *clock != 1, "slot {i}");
                }
            }
            before = now;
        }
    }

    /// Blocks of lanes within reach before and after ones that are not (soft springs, whose
    /// anchors reach far, around stiff ones, whose anchors do not): every slot is prepared,
    /// extended or computed exactly, and the step limit bounds every slot's increments, those
    /// of the blocks out of reach and after them included.
    #[test]
    fn blocks_after_one_out_of_reach_are_prepared_and_bounded() {
        let soft = |i: u16| Spring::from_natural_frequency(2.0 + f32::from(i), 0.5).unwrap();
        let stiff = |i: u16| Spring::from_natural_frequency(3000.0 + f32::from(i), 0.2).unwrap();
        let stiffest =
            |i: u16| Spring::from_natural_frequency(9000.0 + f32::from(i), 0.01).unwrap();
        // The first block out of reach has the largest bound, a block within reach and one
        // out of reach follow it.
        let springs: Vec<(Spring<f32>, u8)> = (0..4)
            .map(soft)
            .chain((0..4).map(stiffest))
            .chain((4..8).map(soft))
            .chain((0..4).map(stiff))
            .map(|spring| (spring, 0))
            .collect();
        let mut table = TransitionTable::default();
        for (spring, clock) in &springs {
            table.request(spring, *clock);
        }
        table.finish(springs.len());
        let (dt, nearby) = (1.0 / 60.0, 1.0 / 60.0 + 2.0e-4);
        table.prepare(FrameSteps::all(dt));
        assert!(worst_prepared_error(&table, &springs, FrameSteps::all(dt)) < 8.0);
        // The soft springs' anchors reach the nearby step; the stiff ones' do not.
        for (spring, expected) in [(soft(0), true), (stiff(0), false)] {
            let anchor = Anchor::new(&spring, dt, &spring.transition(dt));
            assert_eq!(extend(&anchor, nearby, 0).is_some(), expected, "{spring:?}");
        }
        table.prepare(FrameSteps::all(nearby));
        let worst = worst_prepared_error(&table, &springs, FrameSteps::all(nearby));
        assert!(worst < 8.0, "{worst} u");
        // The limit is that of a bound on every slot's increments (the anchors' bounds, made
        // when each was anchored), and not far above the largest.
        let largest = springs
            .iter()
            .map(|(spring, clock)| {
                let slot = table.lookup(spring, *clock).unwrap();
                table.increments(slot).unwrap().abs().element_sum()
            })
            .fold(0.0, f32::max);
        let limit = table.step_limit();
        assert!(limit <= step_limit_for(largest), "largest {largest}");
        assert!(limit >= step_limit_for(1.5 * largest), "largest {largest}");
    }

    /// A frame with the same steps as the last skips the table, yet slots added since (in a
    /// block already prepared, and in a new one) are prepared for them, as are all slots after
    /// a clearing; for a `Vec2`, in pairs too.
    #[test]
    fn slots_added_under_the_same_steps_are_prepared() {
        let springs: Vec<(Spring<f32>, u8)> = (0..7_u8)
            .map(|i| {
                let omega = 3.0 + 5.0 * f32::from(i);
                (Spring::from_natural_frequency(omega, 0.6).unwrap(), 2)
            })
            .collect();
        let steps = FrameSteps::all(1.0 / 144.0);
        let mut table = TransitionTable::default();
        for count in [2, 3, 7] {
            for (spring, clock) in &springs[..count] {
                if table.lookup(spring, *clock).is_none() {
                    table.request(spring, *clock);
                }
            }
            table.finish(count);
            table.prepare_for::<Vec2>(steps);
            let worst = worst_prepared_error(&table, &springs[..count], steps);
            assert!(worst < 8.0, "{count} slots: {worst} u");
            table.prepare_for::<Vec2>(steps);
        }
        table.finish(0);
        let (spring, clock) = springs[6];
        table.request(&spring, clock);
        table.finish(1);
        table.prepare_for::<Vec2>(steps);
        assert!(worst_prepared_error(&table, &[(spring, clock)], steps) < 8.0);
    }

    /// A table that is collected (more than twice as many slots as springs) starts over: no
    /// spring finds its old slot (by key or by ticket), the tickets go on from where they
    /// were, and the slots made next fill the lanes from the first again, each prepared for its
    /// own spring (for a `Vec2`, in pairs too).
    #[test]
    fn a_collected_table_starts_its_lanes_over() {
        let springs = |count: u16, base: f32| -> Vec<(Spring<f32>, u8)> {
            (0..count)
                .map(|i| {
                    let omega = base + f32::from(i);
                    (Spring::from_natural_frequency(omega, 0.8).unwrap(), 2)
                })
                .collect()
        };
        let mut table = TransitionTable::default();
        let first = springs(70, 5.0);
        for (spring, clock) in &first {
            table.request(spring, *clock);
        }
        table.finish(first.len());
        let steps = FrameSteps::all(1.0 / 60.0);
        table.prepare_for::<Vec2>(steps);
        assert!(worst_prepared_error(&table, &first, steps) < 8.0);
        let tickets: Vec<u64> = first
            .iter()
            .map(|(spring, clock)| table.lookup(spring, *clock).unwrap())
            .collect();
        table.finish(0);
        assert!(
            first
                .iter()
                .all(|(spring, clock)| table.lookup(spring, *clock).is_none())
        );
        let second = springs(5, 300.0);
        for (spring, clock) in &second {
            table.request(spring, *clock);
        }
        table.finish(second.len());
        let new_tickets: Vec<u64> = second
            .iter()
            .map(|(spring, clock)| table.lookup(spring, *clock).unwrap())
            .collect();
        assert_eq!(new_tickets, (70..75).collect::<Vec<u64>>());
        for (ticket, (spring, clock)) in tickets.iter().zip(&first) {
            assert!(table.increments(*ticket).is_none(), "old ticket {ticket}");
            assert!(!table.holds(*ticket, spring, *clock));
            assert!(table.parameters(*ticket).is_none());
        }
        assert!(
            table
                .increments(crate::spring::component::SlotTicket::NO_SLOT)
                .is_none()
        );
        for dt in [1.0 / 60.0, 1.0 / 60.0 * 1.0005] {
            let steps = FrameSteps::all(dt);
            table.prepare_for::<Vec2>(steps);
            let worst = worst_prepared_error(&table, &second, steps);
            assert!(worst < 8.0, "{worst} u");
        }
    }

    /// A step from a state within the table's limit, by any slot's increments, gives a result
    /// of squared length below `2¹²⁶`, so the usual step needs no test of its result: for
    /// springs from slow to absurdly stiff (ω = 10⁶) and nearly undamped to heavily
    /// over-damped, at steps from 360 fps to a quarter-second hitch, and states on the limit
    /// in every direction of offset and velocity. Ordinary springs leave any scene's states
    /// (below `10¹⁵`) far inside it.
    #[test]
    fn a_step_from_below_the_limit_stays_finite() {
        use bevy::math::Vec3A;

        let springs: Vec<(Spring<f32>, u8)> = [0.1_f32, 8.0, 300.0, 1.0e4, 1.0e6]
            .into_iter()
            .flat_map(|omega| {
                [0.01_f32, 1.0, 50.0]
                    .map(|zeta| (Spring::from_natural_frequency(omega, zeta).unwrap(), 2))
            })
            .collect();
        assert_eq!(
            TransitionTable::default().step_limit().to_bits(),
            0.0_f32.to_bits(),
            "nothing is stepped before a preparation"
        );
        let directions = [
            Vec3A::X,
            Vec3A::NEG_X,
            Vec3A::ONE.normalize(),
            -Vec3A::ONE.normalize(),
        ];
        // Tables whose stiffest springs have ω = 300, 10⁴ and 10⁶: each limit is its own
        // table's. Each step far from the last is computed exactly, each a hair from the last
        // is extended from its anchor (where in reach): both give the bound.
        for count in [9, 12, 15] {
            let springs = &springs[..count];
            let mut table = TransitionTable::default();
            for (spring, clock) in springs {
                table.request(spring, *clock);
            }
            table.finish(springs.len());
            for dt in [
                1.0 / 360.0,
                1.0 / 60.0,
                1.0 / 60.0 + 1.0e-8,
                0.25,
                0.25 + 1.0e-7,
            ] {
                table.prepare(FrameSteps::all(dt));
                let limit = table.step_limit();
                assert!(limit > 0.0, "dt {dt}: the limit is {limit}");
                // Both parts at the limit: the largest state within it.
                let mut length = limit.sqrt();
                while length * length > limit {
                    length = length.next_down();
                }
                for (spring, clock) in springs {
                    let slot = table.lookup(spring, *clock).unwrap();
                    let [d00, d01, d10, d11] = table.increments(slot).unwrap().to_array();
                    for y in directions.map(|d| d * length) {
                        for v in directions.map(|d| d * length) {
                            let after = y + (y * d00 + v * d01);
                            let velocity = v + (v * d11 + y * d10);
                            for part in [after, velocity] {
                                let squared = part.length_squared();
                                assert!(squared < STEP_RESULT_BOUND, "{spring:?} dt {dt}: {part}");
                            }
                        }
                    }
                }
            }
        }
        // Ordinary springs only: any scene's states are far below the limit.
        let mut ordinary = TransitionTable::default();
        for (spring, clock) in &springs[..9] {
            ordinary.request(spring, *clock);
        }
        ordinary.finish(9);
        ordinary.prepare(FrameSteps::all(1.0 / 60.0));
        assert!(ordinary.step_limit() > 1.0e30, "{}", ordinary.step_limit());
        // An anchor whose bound is not finite (a coefficient NaN or infinite) makes it
        // infinite, and the limit 0.
        let spring = Spring::from_natural_frequency(8.0, 0.5).unwrap();
        let anchor = Anchor::new(&spring, 1.0 / 60.0, &spring.transition(1.0 / 60.0));
        assert!(anchor.bound().is_finite() && anchor.bound() > 0.0);
        for broken in [f32::NAN, f32::INFINITY] {
            let mut anchor = anchor;
            anchor.f1[3] = broken;
            assert_eq!(anchor.bound().to_bits(), f32::INFINITY.to_bits());
        }
        assert_eq!(step_limit_for(f32::INFINITY).to_bits(), 0.0_f32.to_bits());
    }
}
