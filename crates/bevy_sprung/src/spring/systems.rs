//! The systems that step springs, put them to sleep and wake them.

use bevy::ecs::change_detection::{ContiguousComponentTicksMut, ContiguousMut, MaybeLocation};
use bevy::ecs::change_detection::{ContiguousRef, Tick};
use bevy::ecs::system::{ParallelCommands, SystemParam};
use bevy::prelude::*;
use bevy::utils::Parallel;

use super::cache::TransitionCache;
use super::component::step::{Stepped, Transitions, Unchanged, Unusual, UsualStep};
use super::component::{PropertySpring, SpringAsleep, SpringMotion};
use super::event::{SpringSettled, SpringWoke};
use super::parallel::{SplitRows, scope_threads, split_over_threads};
use super::preference::{KeepMotion, ReducedMotion};
use super::skip::SkipFrames;
use super::table::{PreparedIncrements, TransitionTable};
use super::ticks::{RowChanges, any_newer_in_each, for_each_changed_row};
use crate::clock::{FrameSteps, SpringTime};
use crate::property::{OffsetOf, SpringProperty};

/// What the stepping system reads besides the springs: this frame's time steps, the app-wide
/// motion preference and the entities that opt out of it.
#[derive(SystemParam)]
pub(crate) struct StepSettings<'w, 's> {
    time: SpringTime<'w>,
    preference: Option<Res<'w, ReducedMotion>>,
    keep_motion: Query<'w, 's, (), With<KeepMotion>>,
}

/// The springs on property `P` that are awake: those that step every frame (the common case,
/// with nothing to read about skipping), and those that may skip frames ([`SkipFrames`]).
#[derive(SystemParam)]
pub(crate) struct AwakeSprings<'w, 's, P: SpringProperty> {
    every_frame: EveryFrame<'w, 's, P>,
    skipping: Skipping<'w, 's, P>,
}

/// The awake springs on property `P` that step every frame.
type EveryFrame<'w, 's, P> = Query<
    'w,
    's,
    (
        Entity,
        &'static mut PropertySpring<P>,
        &'static mut SpringMotion<P>,
        &'static mut <P as SpringProperty>::Component,
    ),
    (Without<SpringAsleep<P>>, Without<SkipFrames>),
>;

/// The awake springs on property `P` that may skip frames.
type Skipping<'w, 's, P> = Query<
    'w,
    's,
    (
        Entity,
        &'static mut PropertySpring<P>,
        &'static mut SpringMotion<P>,
        &'static mut <P as SpringProperty>::Component,
        &'static SkipFrames,
    ),
    Without<SpringAsleep<P>>,
>;

/// Steps every awake spring on property `P`, a table's columns at a time (split into parts
/// that the compute pool's threads and this one claim, when there are enough springs), and puts
/// the ones that settle to sleep (triggering [`SpringSettled<P>`]).
///
/// This system runs in [`SpringUpdate`](crate::spring::SpringUpdate), which an exclusive system
/// runs on the thread that runs the schedule around it: the compute pool's threads are free,
/// and with the calling thread they use every core Bevy gives the pool, plus one (on a machine
/// with two cores, both). See [`SpringPlugins`](crate::SpringPlugins) for the task-pool setting
/// that uses every core on larger machines.
pub(crate) fn step_springs<P: SpringProperty>(
    settings: StepSettings,
    mut table: Local<TransitionTable>,
    caches: Local<Parallel<TransitionCache>>,
    mut awake: AwakeSprings<P>,
    commands: ParallelCommands,
) {
    let steps = settings.time.steps();
    table.prepare_for::<OffsetOf<P>>(steps);
    let count = awake.every_frame.iter().len() + awake.skipping.iter().len();
    let preference = settings
        .preference
        .as_deref()
        .copied()
        .unwrap_or(ReducedMotion::Full);
    let context = StepContext {
        steps,
        table: &table,
        prepared: table.prepared(),
        caches: &caches,
        commands: &commands,
    };
    if preference.is_reduced() {
        step_reduced(&mut awake, preference, &settings.keep_motion, &context);
    } else {
        step_every_frame(&mut awake.every_frame, &context);
        step_skipping(&mut awake.skipping, &context);
    }
    table.finish(count);
}

/// What every spring's step reads besides the spring: this frame's time steps, the transition
/// table and its increments prepared for this frame, the threads' caches of the transitions
/// the unusual step computes (kept across frames: only that path looks them up, so the usual
/// step carries nothing from spring to spring), and the commands that put springs to sleep.
#[derive(Clone, Copy)]
struct StepContext<'a> {
    steps: FrameSteps,
    table: &'a TransitionTable,
    prepared: PreparedIncrements<'a>,
    caches: &'a Parallel<TransitionCache>,
    commands: &'a ParallelCommands<'a, 'a>,
}

impl StepContext<'_> {
    /// The transitions of this thread's unusual steps, with this thread's cache.
    fn with_transitions<T>(&self, step: impl FnOnce(Transitions) -> T) -> T {
        let mut cache = self.caches.borrow_local_mut();
        step(Transitions {
            table: self.table,
            cache: &mut cache,
        })
    }
}

/// The springs that step every frame: a table's columns at a time where the components are in
/// tables, entity by entity otherwise.
fn step_every_frame<P: SpringProperty>(springs: &mut EveryFrame<P>, context: &StepContext) {
    let threads = scope_threads();
    if let Ok(tables) = springs.contiguous_iter_mut() {
        // Each table's columns as slices, the step inlined into a plain loop over them, change
        // ticks read and written directly; split over the scope's threads if there are several.
        for (entities, configs, motions, components) in tables {
            step_table(entities, (configs, motions, components), context, threads);
        }
    } else if threads > 1 {
        // A property on a sparse-set component: entity by entity.
        springs
            .par_iter_mut()
            .for_each(|item| step_entity(item, context));
    } else {
        for item in springs.iter_mut() {
            step_entity(item, context);
        }
    }
}

/// The springs that may skip frames ([`SkipFrames`]): while they do, the time is put aside
/// for one exact step.
fn step_skipping<P: SpringProperty>(springs: &mut Skipping<P>, context: &StepContext) {
    for (entity, mut config, mut motion, mut component, skip) in springs.iter_mut() {
        // The step reads the configuration and changes it only to apply a velocity change or
        // to repair it: the spring is not changed by being stepped.
        let config = config.bypass_change_detection();
        let stepped = context.with_transitions(|transitions| {
            motion.step_on(config, &mut component, context.steps, skip.0, transitions)
        });
        if stepped == Stepped::Settled {
            put_to_sleep::<P>(context.commands, entity);
        }
    }
}

/// Every awake spring under a reduced-motion `preference` (an accessibility setting, not the
/// hot path): spring by spring, those that may skip frames too (a reduced motion never waits),
/// those of entities with [`KeepMotion`] as they are set up.
fn step_reduced<P: SpringProperty>(
    awake: &mut AwakeSprings<P>,
    preference: ReducedMotion,
    keep_motion: &Query<(), With<KeepMotion>>,
    context: &StepContext,
) {
    let mut step = |(entity, mut config, mut motion, mut component): ReducedRow<P>| {
        let config = config.bypass_change_detection();
        let current = P::get(&component);
        let frame = context.with_transitions(|transitions| {
            if keep_motion.contains(entity) {
                motion.step(config, current, context.steps, false, transitions)
            } else {
                motion.step_reduced(config, current, context.steps, preference, transitions)
            }
        });
        if let Some(value) = frame.write {
            P::set(&mut component, value);
        }
        if frame.outcome == Stepped::Settled {
            put_to_sleep::<P>(context.commands, entity);
        }
    };
    awake.every_frame.iter_mut().for_each(&mut step);
    awake
        .skipping
        .iter_mut()
        .for_each(|(entity, config, motion, component, _)| {
            step((entity, config, motion, component));
        });
}

/// A spring stepped under a reduced-motion preference: its entity, configuration, motion and
/// property.
type ReducedRow<'a, P> = (
    Entity,
    Mut<'a, PropertySpring<P>>,
    Mut<'a, SpringMotion<P>>,
    Mut<'a, <P as SpringProperty>::Component>,
);

/// [`step_row`] for a spring of a query item (a property on a sparse-set component, whose
/// columns are not contiguous).
fn step_entity<P: SpringProperty>(
    (entity, mut config, motion, mut component): ReducedRow<P>,
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

/// The awake springs of one table, from its columns: [`step_entity`] for each, without the
/// per-entity `Mut` wrappers, split over a compute-pool scope's `threads` (the pool's and this
/// one, [`scope_threads`]) if there are several. Every motion is marked changed (it was
/// stepped), a property only where it moved; the configurations are read where they changed,
/// and not marked.
fn step_table<P: SpringProperty>(
    entities: &[Entity],
    (configs, motions, components): (
        ContiguousMut<PropertySpring<P>>,
        ContiguousMut<SpringMotion<P>>,
        ContiguousMut<P::Component>,
    ),
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
        put_to_sleep::<P>(context.commands, entity);
    }
    frame.write.is_some_and(|value| {
        P::set(component, value);
        true
    })
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
        super::event::trigger_if_alive(&mut commands, SpringSettled::<P>::new(entity));
    });
}

/// Wakes sleeping springs on property `P` whose target changed or that were kicked, and those
/// whose property something else moved away from where they rest (a teleport, a value written
/// by hand): sleeping saves work, and changes nothing a spring does.
///
/// Only springs whose configuration or property changed since the last run are looked at.
/// Their change ticks are scanned a table column at a time, in blocks tested without a branch
/// per spring ([`for_each_changed_row`]): a scene of sleeping springs costs about one
/// instruction per spring per frame.
pub(crate) fn wake_springs<P: SpringProperty>(
    mut commands: Commands,
    asleep: Query<
        (
            Entity,
            Ref<PropertySpring<P>>,
            &SpringMotion<P>,
            Ref<P::Component>,
        ),
        With<SpringAsleep<P>>,
    >,
) {
    // Woken (perhaps to settle again this very frame): whoever follows which springs move
    // hears of it.
    let mut wake = |entity: Entity| {
        commands.entity(entity).try_remove::<SpringAsleep<P>>();
        super::event::trigger_if_alive(&mut commands, SpringWoke::<P>::new(entity));
    };
    let Ok(tables) = asleep.contiguous_iter() else {
        // Not reached (the components are in tables): the same, spring by spring.
        for (entity, spring, motion, component) in &asleep {
            let changes = RowChanges {
                spring: spring.is_changed(),
                property: component.is_changed(),
            };
            if wakes(changes, &spring, motion, &component) {
                wake(entity);
            }
        }
        return;
    };
    for (entities, springs, motions, components) in tables {
        let (springs, spring_ticks) = ContiguousRef::split(springs);
        let (components, component_ticks) = ContiguousRef::split(components);
        let runs = (spring_ticks.last_run(), spring_ticks.this_run());
        let ticks = (spring_ticks.changed(), component_ticks.changed());
        for_each_changed_row(ticks, runs, |row, changes| {
            if wakes(changes, &springs[row], &motions[row], &components[row]) {
                wake(entities[row]);
            }
        });
    }
}

/// Whether the sleeping spring with `motion` wakes, given what `changes` in its row: its
/// configuration asks it to move, or something else wrote its property. A configuration marked
/// changed is also how a spring whose entity was disabled says it is back (see
/// `touch_on_return`): its property may have been written while the systems did not see it, so
/// it is compared too.
#[inline]
fn wakes<P: SpringProperty>(
    changes: RowChanges,
    spring: &PropertySpring<P>,
    motion: &SpringMotion<P>,
    component: &P::Component,
) -> bool {
    let written = || !motion.holds(P::get(component));
    (changes.spring && (spring.wants_to_move(motion) || written()))
        || (changes.property && written())
}
