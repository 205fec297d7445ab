//! The contract's second call: stepping rows. One entry point per path a row takes (a
//! table's columns, a query item, a spring that may skip frames, a reduced motion); the
//! usual step inlined into the loops over columns, the unusual one out of line.

use core::ops::DerefMut;

use bevy::ecs::change_detection::Tick;
use bevy::ecs::change_detection::{ContiguousComponentTicksMut, ContiguousMut, MaybeLocation};
use bevy::prelude::*;
use bevy::utils::Parallel;

use super::cache::TransitionCache;
use super::parallel::{SplitRows, split_over_threads};
use super::step::{Stepped, Transitions, Unchanged, Unusual, UsualStep};
use super::table::{PreparedIncrements, TransitionTable};
use super::ticks::any_newer_in_each;
use crate::clock::FrameSteps;
use crate::property::SpringProperty;
use crate::spring::component::{PropertySpring, SpringMotion};
use crate::spring::preference::ReducedMotion;

/// One frame's steps of one property, between [`Kernel::prepare`](super::Kernel::prepare) and
/// [`Kernel::finish`](super::Kernel::finish): what every spring's step reads besides the
/// spring (this frame's time steps, the transition table and its increments prepared for this
/// frame, the threads' caches of the transitions the unusual step computes, kept across frames:
/// only that path looks them up, so the usual step carries nothing from spring to spring), and
/// whom to tell of the springs that arrive. Its methods are the contract's second call, one per
/// path a row takes: table columns, a query item, a spring that may skip frames, a reduced
/// motion.
#[derive(Clone, Copy)]
pub(in crate::spring) struct StepContext<'a> {
    pub(super) steps: FrameSteps,
    pub(super) table: &'a TransitionTable,
    pub(super) prepared: PreparedIncrements<'a>,
    pub(super) caches: &'a Parallel<TransitionCache>,
    pub(super) report: &'a dyn StepReport,
}

/// What the kernel reports of the rows it steps besides their values: a row that moved has its
/// property's change tick set (the caller sees it through change detection), and a row that
/// arrived (came to rest, snapped onto its target) is told here. A refused input (a
/// non-finite target, velocity or parameters written through reflection) is repaired in place
/// with one warning; a sleeping row that wakes is told by [`wakes`](super::wakes).
pub(in crate::spring) trait StepReport: Sync {
    /// The spring of `entity` arrived this frame: it rests on its target and steps no more
    /// until something wakes it. Called from the threads that step, on the unusual path only.
    fn arrived(&self, entity: Entity);
}

/// A spring as a query yields it: its entity, configuration, motion and property.
pub(in crate::spring) type SpringRow<'a, P> = (
    Entity,
    Mut<'a, PropertySpring<P>>,
    Mut<'a, SpringMotion<P>>,
    Mut<'a, <P as SpringProperty>::Component>,
);

/// A table's columns of the springs on `P`, as a contiguous query yields them.
pub(in crate::spring) type SpringColumns<'a, P> = (
    ContiguousMut<'a, PropertySpring<P>>,
    ContiguousMut<'a, SpringMotion<P>>,
    ContiguousMut<'a, <P as SpringProperty>::Component>,
);

impl StepContext<'_> {
    /// Steps the awake springs of one table, from its columns, split over a compute-pool
    /// scope's `threads` if there are several and the table is large. Every motion is marked
    /// changed (it was stepped), a property only where it moved; the configurations are read
    /// where they changed, and not marked.
    #[inline]
    pub(in crate::spring) fn step_columns<P: SpringProperty>(
        &self,
        entities: &[Entity],
        columns: SpringColumns<P>,
        threads: usize,
    ) {
        step_table(entities, columns, self, threads);
    }

    /// Steps one awake spring of a query item (a property on a sparse-set component, whose
    /// columns are not contiguous): the same step as [`step_columns`](Self::step_columns).
    #[inline]
    pub(in crate::spring) fn step_item<P: SpringProperty>(&self, row: SpringRow<P>) {
        step_entity(row, self);
    }

    /// Steps one awake spring that may skip frames: while `skipping`, the time is put aside for
    /// one exact step later. The configuration is changed only to apply a velocity change or
    /// to repair it: the spring is not changed by being stepped.
    pub(in crate::spring) fn step_skipping<P: SpringProperty>(
        &self,
        entity: Entity,
        (config, motion): (&mut PropertySpring<P>, &mut SpringMotion<P>),
        component: &mut impl DerefMut<Target = P::Component>,
        skipping: bool,
    ) {
        let stepped = self.with_transitions(|transitions| {
            motion.step_on(config, component, self.steps, skipping, transitions)
        });
        if stepped == Stepped::Settled {
            self.report.arrived(entity);
        }
    }

    /// Steps one awake spring under a reduced-motion `preference` (an accessibility setting, not
    /// the hot path), or as it is set up where there is none for it (an entity with
    /// [`KeepMotion`](crate::spring::KeepMotion)). A reduced motion never skips frames.
    pub(in crate::spring) fn step_reduced<P: SpringProperty>(
        &self,
        (entity, mut config, mut motion, mut component): SpringRow<P>,
        preference: Option<ReducedMotion>,
    ) {
        let config = config.bypass_change_detection();
        let current = P::get(&component);
        let frame = self.with_transitions(|transitions| match preference {
            Some(preference) => {
                motion.step_reduced(config, current, self.steps, preference, transitions)
            }
            None => motion.step(config, current, self.steps, false, transitions),
        });
        if let Some(value) = frame.write {
            P::set(&mut component, value);
        }
        if frame.outcome == Stepped::Settled {
            self.report.arrived(entity);
        }
    }

    /// The transitions of this thread's unusual steps, with this thread's cache.
    fn with_transitions<T>(&self, step: impl FnOnce(Transitions) -> T) -> T {
        let mut cache = self.caches.borrow_local_mut();
        step(Transitions {
            table: self.table,
            cache: &mut cache,
        })
    }
}

/// [`step_row`] for a spring of a query item.
fn step_entity<P: SpringProperty>(
    (entity, mut config, motion, mut component): SpringRow<P>,
    context: &StepContext,
) {
    // Changed since this system last ran (a retarget, a kick, an edit through reflection), or
    // written by something else: this system does not mark the configuration changed, it only
    // reads it, and its own write is as old as its last run.
    let unchanged = Unchanged {
        config: !config.is_changed(),
        property: !component.is_changed(),
    };
    let row = Row {
        index: 0,
        entities: core::slice::from_ref(&entity),
        configs: core::slice::from_mut(config.bypass_change_detection()),
    };
    // The motion changes every frame it is stepped; the property only when it moves.
    let moved = step_row(
        row,
        motion.into_inner(),
        component.bypass_change_detection(),
        unchanged,
        context,
    );
    if moved {
        component.set_changed();
    }
}

/// Where the unusual step finds a row's entity and configuration: the row's index in its
/// table's columns. The usual step reads neither, and walks no pointer alongside for them.
struct Row<'r, P: SpringProperty> {
    index: usize,
    entities: &'r [Entity],
    configs: &'r mut [PropertySpring<P>],
}

/// One awake spring's frame: the usual step inlined, the unusual one out of line; writes the
/// property if it moved (whether it did is returned, for its change tick), and puts the spring
/// to sleep if it settled.
#[expect(
    clippy::inline_always,
    reason = "the per-entity loop's body: measured cheaper inlined into it than called"
)]
#[inline(always)]
fn step_row<P: SpringProperty>(
    row: Row<P>,
    motion: &mut SpringMotion<P>,
    component: &mut P::Component,
    unchanged: Unchanged,
    context: &StepContext,
) -> bool {
    let current = P::get(component);
    match motion.step_usual(current, unchanged, context.prepared) {
        UsualStep::Moved(value) => {
            P::set(component, value);
            true
        }
        UsualStep::Still => false,
        UsualStep::Declined => {
            let entity = row.entities[row.index];
            let config = row_of(row.configs, row.index);
            step_unusual_row(entity, (config, motion), component, unchanged, context)
        }
    }
}

/// Rows of a table a thread claims at least (see [`split_over_threads`]): a few blocks of
/// [`TOUCH_BLOCK`], about a microsecond of stepping, so that the threads finish close together
/// while claiming costs little.
const STEP_GRAIN: usize = 2 * TOUCH_BLOCK;

/// Rows of a table above which its springs are stepped on several threads: enough work to
/// outweigh waking them.
const STEP_PARALLEL: usize = 2048;

/// Rows whose configurations' and properties' change ticks [`step_rows`] tests together.
const TOUCH_BLOCK: usize = 256;

/// The columns of a table's awake springs (or a part of them), and their change ticks.
struct TableRows<'a, P: SpringProperty> {
    entities: &'a [Entity],
    configs: &'a mut [PropertySpring<P>],
    motions: &'a mut [SpringMotion<P>],
    components: &'a mut [P::Component],
    config_changed: &'a [Tick],
    component_changed: &'a mut [Tick],
    motion_changed: &'a mut [Tick],
}

impl<P: SpringProperty> SplitRows for TableRows<'_, P> {
    #[inline]
    fn len(&self) -> usize {
        self.motions.len()
    }

    #[inline]
    fn take_front(&mut self, rows: usize) -> Self {
        let rows = rows.min(self.len());
        Self {
            entities: self.entities.split_off(..rows).unwrap_or_default(),
            configs: self.configs.split_off_mut(..rows).unwrap_or_default(),
            motions: self.motions.split_off_mut(..rows).unwrap_or_default(),
            components: self.components.split_off_mut(..rows).unwrap_or_default(),
            config_changed: self.config_changed.split_off(..rows).unwrap_or_default(),
            component_changed: self
                .component_changed
                .split_off_mut(..rows)
                .unwrap_or_default(),
            motion_changed: self
                .motion_changed
                .split_off_mut(..rows)
                .unwrap_or_default(),
        }
    }
}

/// [`StepContext::step_columns`]: [`step_entity`] for each row, without the per-entity `Mut`
/// wrappers, split over the scope's `threads` (the pool's and this one,
/// [`scope_threads`](super::parallel::scope_threads)).
fn step_table<P: SpringProperty>(
    entities: &[Entity],
    (configs, motions, components): SpringColumns<P>,
    context: &StepContext,
    threads: usize,
) {
    let (configs, config_ticks) = ContiguousMut::bypass_change_detection_split(configs);
    let (motions, mut motion_ticks) = ContiguousMut::bypass_change_detection_split(motions);
    let (components, mut component_ticks) =
        ContiguousMut::bypass_change_detection_split(components);
    let runs = (config_ticks.last_run(), config_ticks.this_run());
    // Every stepped motion is changed: marked part by part on the threads that step them,
    // not in a pass of its own on this thread afterwards.
    let rows = TableRows {
        entities,
        configs,
        motions,
        components,
        config_changed: config_ticks.changed(),
        component_changed: component_ticks.changed_mut(),
        motion_changed: motion_ticks.changed_mut(),
    };
    let threads = if rows.len() > STEP_PARALLEL {
        threads
    } else {
        1
    };
    split_over_threads(
        rows,
        (threads, STEP_GRAIN),
        |rows| step_rows(rows, runs, context),
        ((), |(), ()| ()),
    );
    mark_changed_by(&mut motion_ticks, |_| true);
    let this_run = component_ticks.this_run();
    mark_changed_by(&mut component_ticks, |tick| tick == this_run);
}

/// [`step_table`]'s loop over rows, a block of [`TOUCH_BLOCK`] rows at a time: the
/// configurations' changed ticks are read (one changed since the last run was touched by
/// something else), the properties' read (one changed since was written by something else:
/// this system's own writes are as old as its last run) and written where they moved, the
/// motions' all written. "Since the last run" is "since the spring's last step": a spring that
/// was not stepped in the last run (its entity disabled, or asleep) has its configuration
/// marked changed when it returns (see `touch_on_return`).
///
/// A block's ticks are tested together first ([`any_newer_in_each`]): the rows of a block
/// where nothing changed (nearly all of them, in a frame) step with no test of their own, and
/// without comparing the property with what the spring wrote. A block where anything else
/// wrote the property (another spring on another field of the same component counts) compares
/// every row's value with what its spring wrote.
#[inline(never)]
fn step_rows<P: SpringProperty>(
    mut rows: TableRows<P>,
    (last_run, this_run): (Tick, Tick),
    context: &StepContext,
) {
    rows.motion_changed.fill(this_run);
    while rows.len() > 0 {
        let block = rows.take_front(TOUCH_BLOCK);
        let (touched, written) = any_newer_in_each(
            [block.config_changed, block.component_changed],
            last_run,
            this_run,
        );
        // Three copies of the loop over the block's rows, each knowing what it can.
        if touched {
            let untouched =
                |changed: &[Tick], row: usize| !changed[row].is_newer_than(last_run, this_run);
            step_block(block, untouched, false, this_run, context);
        } else if written {
            step_block(block, |_, _| true, false, this_run, context);
        } else {
            step_block(block, |_, _| true, true, this_run, context);
        }
    }
}

/// [`step_rows`] for one block of rows: whether each row's configuration is `untouched` (told
/// from the block's changed ticks and the row), and whether every row's property is known
/// `unwritten`. Rows whose property moved get `this_run` as their changed tick.
#[expect(
    clippy::inline_always,
    reason = "three copies of the per-entity loop, two that know every row is untouched, one \
              of them that every row is unwritten"
)]
#[inline(always)]
fn step_block<P: SpringProperty>(
    block: TableRows<P>,
    untouched: impl Fn(&[Tick], usize) -> bool,
    unwritten: bool,
    this_run: Tick,
    context: &StepContext,
) {
    let TableRows {
        entities,
        configs,
        motions,
        components,
        config_changed,
        component_changed,
        ..
    } = block;
    let rows = motions
        .iter_mut()
        .zip(components.iter_mut())
        .zip(component_changed);
    for (index, ((motion, component), component_changed)) in rows.enumerate() {
        let unchanged = Unchanged {
            config: untouched(config_changed, index),
            property: unwritten,
        };
        // Found by index, not walked alongside: the configuration is read only on the unusual
        // path.
        let row = Row {
            index,
            entities,
            configs: &mut *configs,
        };
        if step_row(row, motion, component, unchanged, context) {
            *component_changed = this_run;
        }
    }
}

/// `&mut rows[row]`, out of line: inlined, the compiler would walk a pointer to it alongside
/// the other columns for the rare row that reads it.
#[cold]
#[inline(never)]
fn row_of<T>(rows: &mut [T], row: usize) -> &mut T {
    &mut rows[row]
}

/// Where Bevy tracks change locations (feature `track_location`), records this system as what
/// changed the rows it marked changed in this run (those whose change tick is `marked`; the
/// system's `this_run` is unique to it).
#[cold]
#[track_caller]
fn mark_changed_by(ticks: &mut ContiguousComponentTicksMut, marked: impl Fn(Tick) -> bool) {
    if ticks.changed_by().into_option().is_none() {
        return;
    }
    let marked: Vec<bool> = ticks.changed().iter().map(|tick| marked(*tick)).collect();
    let caller = MaybeLocation::caller();
    ticks
        .changed_by_mut()
        .zip(caller)
        .map(|(changed_by, caller)| {
            for (slot, marked) in changed_by.iter_mut().zip(marked) {
                if marked {
                    *slot = caller;
                }
            }
        });
}

/// [`step_row`] when the usual step declined: the unusual step, with this thread's cache of
/// transitions, its write and its settling. Whether it wrote the property.
#[cold]
#[inline(never)]
fn step_unusual_row<P: SpringProperty>(
    entity: Entity,
    (config, motion): (&mut PropertySpring<P>, &mut SpringMotion<P>),
    component: &mut P::Component,
    unchanged: Unchanged,
    context: &StepContext,
) -> bool {
    // Read again rather than passed: as an argument, the value would leave the vector
    // registers on the usual path too.
    let current = P::get(component);
    let unusual = Unusual {
        skipping: false,
        slot_found: unchanged.config,
    };
    let frame = context.with_transitions(|transitions| {
        motion.step_unusual(config, current, context.steps, unusual, transitions)
    });
    if frame.outcome == Stepped::Settled {
        context.report.arrived(entity);
    }
    frame.write.is_some_and(|value| {
        P::set(component, value);
        true
    })
}
