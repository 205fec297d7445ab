//! Change ticks read a block of rows at a time: whether any of a column's ticks is newer than a
//! system's last run, as Bevy's `Tick::is_newer_than` tells of one, in a form the compiler turns
//! into a few vector instructions per four ticks.
//!
//! Bevy's own test reads one tick at a time behind `Ref`/`Mut`. Scanning a table's tick columns
//! in blocks is what makes a scene of sleeping springs cost about an instruction per spring a
//! frame, and lets the stepping system leave out its per-row tests where a block holds no change
//! (the performance log has the counts). It is kept for that saving; the tests below check it
//! against Bevy's test, tick by tick and in blocks, across wraparound and clamped ages, so that
//! a Bevy upgrade that changes the rule fails here.

use bevy::ecs::change_detection::{MAX_CHANGE_AGE, Tick};

/// What changed in one spring's row since a system last ran.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct RowChanges {
    /// The spring's configuration (a retarget, a kick, an edit).
    pub(crate) spring: bool,
    /// Its property (written by something else, or by the spring's own last step).
    pub(crate) property: bool,
}

/// Calls `visit` with the index of every row whose tick in either column (the springs', the
/// properties') is newer than `last_run`, and which of the two are. Two levels: a scene at rest
/// settles each long stretch with one test of both columns, and a stretch that holds a change
/// is looked into block by block, so that one retarget among many sleeping springs costs a few
/// short blocks rather than the whole stretch row by row.
pub(crate) fn for_each_changed_row(
    (springs, properties): (&[Tick], &[Tick]),
    (last_run, this_run): (Tick, Tick),
    mut visit: impl FnMut(usize, RowChanges),
) {
    let rows = springs.len().min(properties.len());
    let changed_in = |range: core::ops::Range<usize>| {
        let (spring, property) = any_newer_in_each(
            [&springs[range.clone()], &properties[range]],
            last_run,
            this_run,
        );
        RowChanges { spring, property }
    };
    for stretch in (0..rows).step_by(WAKE_STRETCH) {
        let stretch_end = (stretch + WAKE_STRETCH).min(rows);
        let in_stretch = changed_in(stretch..stretch_end);
        if !(in_stretch.spring || in_stretch.property) {
            continue;
        }
        for block in (stretch..stretch_end).step_by(WAKE_BLOCK) {
            let block_end = (block + WAKE_BLOCK).min(stretch_end);
            let in_block = changed_in(block..block_end);
            for row in block..block_end {
                let changes = RowChanges {
                    spring: in_block.spring && springs[row].is_newer_than(last_run, this_run),
                    property: in_block.property
                        && properties[row].is_newer_than(last_run, this_run),
                };
                if changes.spring || changes.property {
                    visit(row, changes);
                }
            }
        }
    }
}

/// Springs whose change ticks the waking system tests together, inside a stretch that holds a
/// change.
const WAKE_BLOCK: usize = 256;

/// Springs whose change ticks the waking system tests together first: the test's setup and the
/// walk of the columns, paid once for this many rather than for every block.
const WAKE_STRETCH: usize = 16 * WAKE_BLOCK;

/// Whether any of `ticks` is newer than `last_run` ([`Tick::is_newer_than`] for a block, in a
/// form the compiler vectorises to four instructions per four ticks, after a bitwise OR of the
/// block, two per four, that settles most blocks of old ticks alone).
///
/// A tick is newer if its age `k = this_run − tick` is below the system's,
/// `s = this_run − last_run` (clamped as Bevy does; an age past the clamp is past `s` too; with
/// `s = 0` none is), that
/// is if `tick − (this_run − s + 1) = s − 1 − k` lies in `[0, s)` (unsigned, wrapping). Biasing
/// both sides by 2³¹ turns that unsigned test into a signed one, which SSE2 has; the block is old
/// if every tick is past the last newer value.
#[inline]
fn any_newer(ticks: &[Tick], last_run: Tick, this_run: Tick) -> bool {
    const BIAS: u32 = 1 << 31;
    let since_system = this_run
        .get()
        .wrapping_sub(last_run.get())
        .min(MAX_CHANGE_AGE);
    if since_system == 0 {
        return false;
    }
    let first_newer = this_run.get().wrapping_sub(since_system).wrapping_add(1);
    // While the newer ticks do not wrap around (`first_newer ≤ this_run`), each is at least
    // `first_newer`, and so is the OR of a block that holds one: an OR below it means none
    // is newer. Half the instructions of the test below, which runs only where the OR is not
    // below (a tick from before the counter wrapped around, or recent ticks whose OR carries
    // past it).
    if first_newer <= this_run.get() && or_of([ticks])[0] < first_newer {
        return false;
    }
    let origin = first_newer.wrapping_add(BIAS);
    let last_newer = (since_system ^ BIAS).cast_signed().wrapping_sub(1);
    let old = |tick: &Tick| tick.get().wrapping_sub(origin).cast_signed() > last_newer;
    // Sixteen ticks (four vectors) a round: the loop's own instructions amortised over more of
    // them.
    let (rounds, rest) = ticks.as_chunks::<16>();
    // Per position in a round, all ones while every tick there is old (a vector lane's mask).
    let mut lanes = [-1_i32; 16];
    for round in rounds {
        for (lane, tick) in lanes.iter_mut().zip(round) {
            *lane &= -i32::from(old(tick));
        }
    }
    let all_old = lanes.iter().fold(-1, |all, lane| all & lane) != 0;
    !(all_old & rest.iter().fold(true, |all, tick| all & old(tick)))
}

/// [`any_newer`] of each of two blocks of ticks of the same rows: the ORs of both in one pass
/// first, which settles the usual pair, where neither holds a newer tick (an OR of each: old
/// ticks of two kinds, a spawn's and the last run's, in one OR would carry past the last run);
/// each tested on its own only where that cannot tell.
#[inline]
pub(crate) fn any_newer_in_each(
    [first, second]: [&[Tick]; 2],
    last_run: Tick,
    this_run: Tick,
) -> (bool, bool) {
    // As in `any_newer`; where `first_newer` wraps around (or no tick is newer), the OR
    // tells nothing and each block is tested.
    let since_system = this_run
        .get()
        .wrapping_sub(last_run.get())
        .min(MAX_CHANGE_AGE);
    let first_newer = this_run.get().wrapping_sub(since_system).wrapping_add(1);
    if first_newer <= this_run.get() && or_of([first, second]).iter().all(|&or| or < first_newer) {
        return (false, false);
    }
    (
        any_newer(first, last_run, this_run),
        any_newer(second, last_run, this_run),
    )
}

/// The bitwise OR of the ticks of each of the `blocks`, in one pass over all (they are of the
/// same rows: past the shortest's length, the others' rows are left out), sixteen (four
/// vectors) of each block a round.
#[inline]
fn or_of<const N: usize>(blocks: [&[Tick]; N]) -> [u32; N] {
    let rows = blocks.iter().map(|block| block.len()).min().unwrap_or(0);
    let rounds = blocks.map(|block| block[..rows].as_chunks::<16>());
    let mut lanes = [[0_u32; 16]; N];
    for round in 0..rows / 16 {
        for (lanes, (block, _)) in lanes.iter_mut().zip(rounds) {
            for (lane, tick) in lanes.iter_mut().zip(&block[round]) {
                *lane |= tick.get();
            }
        }
    }
    let mut ors = [0; N];
    for ((or, lanes), (_, rest)) in ors.iter_mut().zip(lanes).zip(rounds) {
        let all = lanes.iter().fold(0, |all, lane| all | lane);
        *or = rest.iter().fold(all, |all, tick| all | tick.get());
    }
    ors
}

#[cfg(test)]
mod tests {
    use bevy::ecs::change_detection::{MAX_CHANGE_AGE, Tick};

    use super::{any_newer, any_newer_in_each};

    /// The block test agrees with Bevy's own, tick by tick and in long blocks, across
    /// wraparound, clamped ages and a system that ran this very tick.
    #[test]
    fn the_block_change_test_is_bevys() {
        let edges = [
            0,
            1,
            2,
            3,
            1 << 31,
            (1 << 31) + 1,
            MAX_CHANGE_AGE - 1,
            MAX_CHANGE_AGE,
        ];
        let mut seed = 0x9e37_79b9_u32;
        let mut random = move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        for this_run in [0, 1, 5, 1 << 31, u32::MAX, u32::MAX - 3, 0x1234_5678] {
            let mut ages: Vec<u32> = edges.to_vec();
            ages.extend(edges.iter().map(|edge| edge.wrapping_neg()));
            ages.extend((0..64).map(|_| random()));
            for &system_age in &ages {
                let last_run = Tick::new(this_run.wrapping_sub(system_age));
                let this_run = Tick::new(this_run);
                for &age in &ages {
                    let tick = Tick::new(this_run.get().wrapping_sub(age));
                    assert_eq!(
                        any_newer(&[tick], last_run, this_run),
                        tick.is_newer_than(last_run, this_run),
                        "tick {tick:?}, last run {last_run:?}, this run {this_run:?}"
                    );
                }
                // Blocks longer than a round of sixteen: the tick placed anywhere among old
                // ones (or none) decides, in a round and in the rest past the last one.
                let old = Tick::new(last_run.get());
                for &age in ages.iter().step_by(7) {
                    let tick = Tick::new(this_run.get().wrapping_sub(age));
                    for position in [0, 5, 15, 16, 31, 32, 36] {
                        let mut block = [old; 37];
                        block[position] = tick;
                        assert_eq!(
                            any_newer(&block, last_run, this_run),
                            tick.is_newer_than(last_run, this_run),
                            "tick {tick:?} at {position}, last run {last_run:?}"
                        );
                    }
                }
                assert!(!any_newer(&[old; 37], last_run, this_run));
                // Old ticks spread over thousands of ticks (their OR carries past the last run
                // where they straddle a power of two), with and without a newer one.
                let spread: Vec<Tick> = (1..=40_u32)
                    .map(|i| Tick::new(last_run.get().wrapping_sub(i * i * 3)))
                    .collect();
                let newer = Tick::new(this_run.get());
                for position in [None, Some(0), Some(17), Some(39)] {
                    let mut block = spread.clone();
                    if let Some(position) = position {
                        block[position] = newer;
                    }
                    let expected = block
                        .iter()
                        .any(|tick| tick.is_newer_than(last_run, this_run));
                    assert_eq!(
                        any_newer(&block, last_run, this_run),
                        expected,
                        "spread block, newer at {position:?}, last run {last_run:?}, this run \
                         {this_run:?}"
                    );
                }
            }
        }
    }

    /// The pair test answers as Bevy's test of each block: blocks of old ticks of one kind and
    /// of two (a spawn's and the last run's, whose OR carries past the last run), with a newer
    /// tick in neither, either or both, at the start, inside and past the last round.
    #[test]
    fn the_pair_change_test_is_bevys() {
        for this_run in [0x1234_5678_u32, 3, u32::MAX - 2] {
            for system_age in [1_u32, 2, 7, 1000] {
                let last_run = Tick::new(this_run.wrapping_sub(system_age));
                let this_run = Tick::new(this_run);
                let spawned = Tick::new(last_run.get().wrapping_sub(0x0f0f));
                let newer = Tick::new(this_run.get());
                let kinds = [vec![last_run; 37], {
                    let mut mixed = vec![last_run; 37];
                    mixed.iter_mut().step_by(3).for_each(|tick| *tick = spawned);
                    mixed
                }];
                for first in &kinds {
                    for second in &kinds {
                        for placed in [None, Some((0, 0)), Some((17, 36)), Some((36, 5))] {
                            for which in 0..3 {
                                let (mut first, mut second) = (first.clone(), second.clone());
                                if let Some((in_first, in_second)) = placed {
                                    if which != 1 {
                                        first[in_first] = newer;
                                    }
                                    if which != 0 {
                                        second[in_second] = newer;
                                    }
                                }
                                let bevys = |ticks: &[Tick]| {
                                    ticks
                                        .iter()
                                        .any(|tick| tick.is_newer_than(last_run, this_run))
                                };
                                assert_eq!(
                                    any_newer_in_each([&first, &second], last_run, this_run),
                                    (bevys(&first), bevys(&second)),
                                    "{placed:?} in {which}, last run {last_run:?}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }
}
