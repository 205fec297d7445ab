//! The step kernel: everything that steps a spring, behind three calls the systems make each
//! frame for one property.
//!
//! 1. [`Kernel::prepare`]: this frame's increments for every slot of the property's transition
//!    table (every distinct `(spring, clock)`), for this frame's time steps.
//! 2. Step rows, through the [`StepContext`] that `prepare` returns, one entry point per path a
//!    row takes: [`step_columns`](StepContext::step_columns) (a table's columns, the common
//!    case, split over threads when large), [`step_item`](StepContext::step_item) (a query
//!    item, for a property on a sparse-set component),
//!    [`step_skipping`](StepContext::step_skipping) (a spring that may skip frames) and
//!    [`step_reduced`](StepContext::step_reduced) (a reduced-motion preference). What happened
//!    is reported: a row that moved has its property's change tick set, a row that arrived is
//!    told to the caller's [`StepReport`], a refused input is repaired with one warning.
//! 3. [`Kernel::finish`]: the slots that unusual steps requested are added, and the table is
//!    collected when it holds far more slots than springs.
//!
//! Sleeping springs are not stepped; [`wake_columns`] tells which of them wake.
//!
//! Inside, the table (`table`, with the anchors its increments are computed from), the threads'
//! caches of the transitions the unusual step computes (`cache`), the block test of change ticks (`ticks`), the split over threads (`parallel`), the step of one
//! spring (`step`) and the loops over rows (`rows`). Nothing outside `spring/` sees any of it.
//!
//! # A spring's life
//!
//! ```text
//!                  inserted (the insert hook rests it where the property is)
//!                      │
//!                      ▼
//!   ┌───────────► AWAKE, unusual step ◄──────────────────────────────────┐
//!   │            (general step: repair, catch up, retarget, velocity      │
//!   │             change, a transition from the cache; finds or requests │
//!   │             its slot, remembered as its ticket)                    │
//!   │                  │                     ▲                           │
//!   │          has a slot, nothing changed   │ touched, written by       │
//!   │                  ▼                     │ another, near rest, out   │
//!   │            AWAKE, usual step ──────────┘ of range, time pending    │
//!   │            (ticket → increments, straight line, no configuration   │
//!   │             read; moves, or holds its value)                       │
//!   │                  │                                                 │
//!   │       state within its tolerances, target not moving:              │
//!   │       snapped onto the target (the unusual step)                   │
//!   │                  ▼                                                 │
//!   │            ARRIVED: reported; the caller marks it asleep           │
//!   │                  ▼                                                 │
//!   │            ASLEEP: not stepped, nothing written ───────────────────┘
//!   │                  target changed, kicked, property written by another,
//!   │                  back from a disabled entity ([`wake_columns`])
//!   │
//!   └── SKIPPING ([`SkipFrames`](crate::spring::SkipFrames)): time put aside as pending,
//!       caught up in one exact step when it shows again or is retargeted
//! ```
//!
//! # Invariants
//!
//! - `SpringMotion::active_target` is the target the last step headed for, and always a valid
//!   value: the insert hook rests a spring with an invalid target where its property is, and
//!   `repair` keeps a target written through reflection from replacing it.
//! - `SpringMotion::rest_squared` is the configuration's rest tolerances as applied at
//!   `active_target`: every step that reads the configuration (a touched spring, the general
//!   step, a reduced motion) computes it again.
//! - `SpringMotion::ticket` holds a slot ticket or the time pending, never both: a spring with
//!   time pending has no slot, and its next visible step is the general one, which catches up.
//! - A ticket in the table's range finds the slot of the spring's `(spring, clock)` for as long
//!   as its configuration is unchanged. The usual step trusts it only when the configuration's
//!   change tick is older than the system's last run; a touched spring checks its slot again.
//! - A velocity change set on the configuration is applied by the next general step; it marks
//!   the configuration changed, so the usual step never runs past one.
//! - Outside rest and within the table's step limit (a NaN is not), the usual step's result is
//!   finite: it needs no test of its own. Everything else steps the general way.
//! - The stepping system never marks a configuration changed; it marks every motion it steps,
//!   and a property only where it moved. A property whose change tick is older than the last
//!   run holds what its spring wrote, and is not compared with it.

mod cache;
mod parallel;
mod rows;
mod step;
mod table;
#[cfg(test)]
mod tests;
mod ticks;

use bevy::ecs::change_detection::ContiguousRef;
use bevy::prelude::*;
use bevy::utils::Parallel;

use cache::TransitionCache;
pub(in crate::spring) use parallel::scope_threads;
pub(in crate::spring) use rows::{StepContext, StepReport};
use table::TransitionTable;
pub(in crate::spring) use ticks::RowChanges;

use crate::clock::FrameSteps;
use crate::property::{OffsetOf, SpringProperty};
use crate::spring::component::{PropertySpring, SpringMotion};

/// The state the kernel keeps for one property across frames, in its stepping system: the
/// transition table, and each thread's cache of the transitions the unusual step computes.
#[derive(Default)]
pub(in crate::spring) struct Kernel {
    table: TransitionTable,
    caches: Parallel<TransitionCache>,
}

impl Kernel {
    /// The contract's first call: prepares every slot's increments for this frame's `steps`
    /// (in parallel when the compute pool has threads to spare), and returns what the rows
    /// step through; springs that arrive are told to `report`.
    pub(in crate::spring) fn prepare<'a, P: SpringProperty>(
        &'a mut self,
        steps: FrameSteps,
        report: &'a dyn StepReport,
    ) -> StepContext<'a> {
        self.table.prepare_for::<OffsetOf<P>>(steps);
        let kernel: &'a Self = self;
        StepContext {
            steps,
            table: &kernel.table,
            prepared: kernel.table.prepared(),
            caches: &kernel.caches,
            report,
        }
    }

    /// The contract's last call, after this frame's rows (`springs` of them) stepped: adds the
    /// slots their unusual steps requested, and clears the table when it holds far more slots
    /// than springs.
    pub(in crate::spring) fn finish(&mut self, springs: usize) {
        self.table.finish(springs);
    }
}

/// Calls `wake` with each sleeping spring of one table whose spring wakes ([`wakes`]). Only
/// rows whose configuration or property changed since the last run are looked at: their change
/// ticks are scanned a column at a time, in blocks tested without a branch per spring, so a
/// scene of sleeping springs costs about one instruction per spring a frame.
pub(in crate::spring) fn wake_columns<P: SpringProperty>(
    entities: &[Entity],
    (springs, motions, components): (
        ContiguousRef<PropertySpring<P>>,
        &[SpringMotion<P>],
        ContiguousRef<P::Component>,
    ),
    mut wake: impl FnMut(Entity),
) {
    let (springs, spring_ticks) = ContiguousRef::split(springs);
    let (components, component_ticks) = ContiguousRef::split(components);
    let runs = (spring_ticks.last_run(), spring_ticks.this_run());
    let ticks = (spring_ticks.changed(), component_ticks.changed());
    ticks::for_each_changed_row(ticks, runs, |row, changes| {
        if wakes(changes, &springs[row], &motions[row], &components[row]) {
            wake(entities[row]);
        }
    });
}

/// Whether the sleeping spring with `motion` wakes, given what `changes` in its row: its
/// configuration asks it to move, or something else wrote its property. A configuration marked
/// changed is also how a spring whose entity was disabled says it is back (see
/// `touch_on_return`): its property may have been written while the systems did not see it, so
/// it is compared too.
#[inline]
pub(in crate::spring) fn wakes<P: SpringProperty>(
    changes: RowChanges,
    spring: &PropertySpring<P>,
    motion: &SpringMotion<P>,
    component: &P::Component,
) -> bool {
    let written = || !motion.holds(P::get(component));
    (changes.spring && (spring.wants_to_move(motion) || written()))
        || (changes.property && written())
}
