//! The systems that step springs, put them to sleep and wake them.

use bevy::ecs::change_detection::{ContiguousComponentTicksMut, ContiguousMut, MaybeLocation};
use bevy::ecs::change_detection::{ContiguousRef, MAX_CHANGE_AGE, Tick};
use bevy::ecs::system::{ParallelCommands, SystemParam};
use bevy::prelude::*;
use bevy::utils::Parallel;

use super::cache::TransitionCache;
use super::component::{PropertySpring, SpringAsleep, SpringMotion, Stepped, UsualStep};
use super::event::{SpringSettled, SpringWoke};
use super::parallel::{SplitRows, scope_threads, split_over_threads};
use super::preference::{KeepMotion, ReducedMotion};
use super::skip::SkipFrames;
use super::table::{PreparedIncrements, TransitionTable};
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
    every_frame: Query<
        'w,
        's,
        (
            Entity,
            &'static mut PropertySpring<P>,
            &'static mut SpringMotion<P>,
            &'static mut <P as SpringProperty>::Component,
        ),
        (Without<SpringAsleep<P>>, Without<SkipFrames>),
    >,
    skipping: Query<
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
    >,
}

/// Steps every awake spring on property `P`, a table's columns at a time (split into parts
/// that the compute pool's threads and this one claim, when there are enough springs), and puts
/// the ones that settle to sleep (triggering [`SpringSettled<P>`]).
///
/// This system runs in [`SpringUpdate`](crate::spring::SpringUpdate), which an exclusive system
/// runs on the thread that runs the schedule around it: the compute pool's threads are free,
/// and with the calling thread they use every core Bevy gives the pool, plus one (on a machine
/// with two cores, both). See [`SpringPlugin`](crate::SpringPlugin) for the task-pool setting
/// that uses every core on larger machines.
pub(crate) fn step_springs<P: SpringProperty>(
    settings: StepSettings,
    mut table: Local<TransitionTable>,
    caches: Local<Parallel<TransitionCache>>,
    mut awake: AwakeSprings<P>,
    commands: ParallelCommands,
) {
    let steps = settings.time.steps();
    let table = &mut *table;
    table.prepare_for::<OffsetOf<P>>(steps);
    let AwakeSprings {
        every_frame: springs,
        skipping,
    } = &mut awake;
    let count = springs.iter().len() + skipping.iter().len();
    let preference = settings
        .preference
        .map_or(ReducedMotion::Full, |preference| *preference);
    let mut cache = TransitionCache::default();
    if preference.is_reduced() {
        // An accessibility setting, not the hot path: spring by spring, those that may skip
        // frames too (a reduced motion is cheap, and never waits).
        let mut step_reduced = |(entity, mut config, mut motion, mut component): ReducedRow<P>| {
            // The step reads the configuration and changes it only to apply a velocity
            // change or to repair it: the spring is not changed by being stepped.
            let config = config.bypass_change_detection();
            let current = P::get(&component);
            let frame = if settings.keep_motion.contains(entity) {
                motion.step(config, current, steps, false, false, (table, &mut cache))
            } else {
                motion.step_reduced(config, current, steps, preference, (table, &mut cache))
            };
            if let Some(value) = frame.write {
                P::set(&mut component, value);
            }
            if frame.outcome == Stepped::Settled {
                put_to_sleep::<P>(&commands, entity);
            }
        };
        springs.iter_mut().for_each(&mut step_reduced);
        skipping
            .iter_mut()
            .for_each(|(entity, config, motion, component, _)| {
                step_reduced((entity, config, motion, component));
            });
        table.finish(count);
        return;
    }
    let shared: &TransitionTable = table;
    // A spring's unusual step takes its transition from its thread's cache (kept across
    // frames): only that path looks the cache up, so the usual step carries nothing from
    // entity to entity.
    let caches = &*caches;
    let threads = scope_threads();
    if let Ok(tables) = springs.contiguous_iter_mut() {
        // Each table's columns as slices, the step inlined into a plain loop over them, change
        // ticks read and written directly; split over the scope's threads if there are several.
        for (entities, configs, motions, components) in tables {
            step_table(
                (entities, configs, motions, components),
                (steps, shared, caches, &commands),
                threads,
            );
        }
    } else if threads > 1 {
        // A property on a sparse-set component: entity by entity.
        springs.par_iter_mut().for_each(|item| {
            step_entity(item, (steps, shared, caches, &commands));
        });
    } else {
        for item in springs.iter_mut() {
            step_entity(item, (steps, shared, caches, &commands));
        }
    }
    // Springs that may skip frames: while they do, the time is put aside for one exact step.
    for (entity, mut config, mut motion, mut component, skip) in skipping.iter_mut() {
        let config = config.bypass_change_detection();
        let stepped = motion.step_on(config, &mut component, steps, skip.0, (table, &mut cache));
        if stepped == Stepped::Settled {
            put_to_sleep::<P>(&commands, entity);
        }
    }
    table.finish(count);
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
    (entity, mut config, motion, mut component): (
        Entity,
        Mut<PropertySpring<P>>,
        Mut<SpringMotion<P>>,
        Mut<P::Component>,
    ),
    (steps, table, caches, commands): StepContext,
) {
    // Changed since this system last ran (a retarget, a kick, an edit through reflection): this
    // system does not mark the configuration changed, it only reads it.
    let untouched = !config.is_changed();
    // Written since by something else (this system's own write is as old as its last run).
    let unwritten = !component.is_changed();
    let config = config.bypass_change_detection();
    // The motion changes every frame it is stepped; the property only when it moves.
    let moved = step_row(
        (|| entity, || config),
        motion.into_inner(),
        component.bypass_change_detection(),
        (untouched, unwritten),
        table.prepared(),
        (&steps, table, caches, commands),
    );
    if moved {
        component.set_changed();
    }
}

/// One awake, visible spring's frame (`untouched`: nothing but this system changed it since its
/// last step; `unwritten`: nor its property): the usual step inlined, the unusual one out of
/// line; writes the property if it moved (whether it did is returned, for its change tick), and puts the spring to sleep if it
/// settled. Its `entity` and `config` are fetched only for the unusual step: the entity fetched
/// for every row cost 4 instructions a spring, the steps passed by value 5 more, and walking the
/// configurations 1 more (callgrind).
#[expect(
    clippy::inline_always,
    reason = "the per-entity loop's body: measured cheaper inlined into it than called"
)]
#[inline(always)]
fn step_row<'a, P: SpringProperty>(
    (entity, config): (
        impl FnOnce() -> Entity,
        impl FnOnce() -> &'a mut PropertySpring<P>,
    ),
    motion: &mut SpringMotion<P>,
    component: &mut P::Component,
    (untouched, unwritten): (bool, bool),
    prepared: PreparedIncrements,
    (steps, table, caches, commands): (
        &FrameSteps,
        &TransitionTable,
        &Parallel<TransitionCache>,
        &ParallelCommands,
    ),
) -> bool {
    let current = P::get(component);
    match motion.step_usual(current, (untouched, unwritten), prepared) {
        UsualStep::Moved(value) => {
            P::set(component, value);
            true
        }
        UsualStep::Still => false,
        UsualStep::Declined => step_entity_unusual(
            entity(),
            (config(), motion),
            component,
            (*steps, untouched, table, caches),
            commands,
        ),
    }
}

/// What every spring's step reads: this frame's steps, the transition table, the threads'
/// caches and the commands that put springs to sleep.
type StepContext<'a> = (
    FrameSteps,
    &'a TransitionTable,
    &'a Parallel<TransitionCache>,
    &'a ParallelCommands<'a, 'a>,
);

/// Rows of a table a thread claims at least (see [`split_over_threads`]): a few blocks of
/// [`TOUCH_BLOCK`], about a microsecond of stepping, so that the threads finish close together
/// while claiming costs little.
const STEP_GRAIN: usize = 2 * TOUCH_BLOCK;

/// Rows of a table above which its springs are stepped on several threads: enough work to
/// outweigh waking them.
const STEP_PARALLEL: usize = 2048;

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

/// The awake, visible springs of one table, from its columns: [`step_entity`] for each, without
/// the per-entity `Mut` wrappers, split over a compute-pool scope's `threads` (the pool's and
/// this one, [`scope_threads`]) if there are several.
/// Every motion is marked changed (it was stepped), a property only where it moved; the
/// configurations are read where they changed, and not marked.
fn step_table<P: SpringProperty>(
    (entities, configs, motions, components): (
        &[Entity],
        ContiguousMut<PropertySpring<P>>,
        ContiguousMut<SpringMotion<P>>,
        ContiguousMut<P::Component>,
    ),
    context: StepContext,
    threads: usize,
) {
    let (configs, config_ticks) = ContiguousMut::bypass_change_detection_split(configs);
    let (motions, mut motion_ticks) = ContiguousMut::bypass_change_detection_split(motions);
    let (components, mut component_ticks) =
        ContiguousMut::bypass_change_detection_split(components);
    let ticks = (config_ticks.last_run(), config_ticks.this_run());
    // Every stepped motion is changed: marked part by part on the threads that step them,
    // not in a pass of its own on this thread afterwards (a 400 kB write at 100 000 springs).
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
        |rows| step_rows(rows, ticks, context),
        ((), |(), ()| ()),
    );
    mark_changed_by(&mut motion_ticks, |_| true);
    let this_run = component_ticks.this_run();
    mark_changed_by(&mut component_ticks, |tick| tick == this_run);
}

/// [`step_table`]'s loop over rows: the configurations' changed ticks are read (one changed
/// since the last run was touched by something else), the properties' read (one changed since
/// was written by something else: this system's own writes are as old as its last run) and
/// written where they moved, the motions' all written. "Since the last run" is "since the
/// spring's last step": a spring that was not stepped in the last run (its entity disabled, or
/// asleep) has its configuration marked changed when it returns (see `touch_on_return`).
///
/// The ticks are tested a block of rows at a time first ([`any_newer_in_each`], an
/// instruction and a half a row for both): the rows of a block where nothing changed (nearly
/// all of them, in a frame) step with no test of their own, about 3 instructions a spring
/// fewer for the configurations, and without comparing the property with what the spring
/// wrote, 9 fewer for a translation and 22 for a UI translation (callgrind). A block where
/// anything else wrote the property (another spring on another field of the same component
/// counts) compares every row's value with what its spring wrote.
#[inline(never)]
fn step_rows<P: SpringProperty>(
    rows: TableRows<P>,
    (last_run, this_run): (Tick, Tick),
    context: StepContext,
) {
    let TableRows {
        entities,
        configs,
        motions,
        components,
        config_changed,
        component_changed,
        motion_changed,
    } = rows;
    motion_changed.fill(this_run);
    let (_, table, _, _) = context;
    let prepared = table.prepared();
    let blocks = entities
        .chunks(TOUCH_BLOCK)
        .zip(configs.chunks_mut(TOUCH_BLOCK))
        .zip(motions.chunks_mut(TOUCH_BLOCK))
        .zip(components.chunks_mut(TOUCH_BLOCK))
        .zip(config_changed.chunks(TOUCH_BLOCK))
        .zip(component_changed.chunks_mut(TOUCH_BLOCK));
    for (((((entities, configs), motions), components), config_changed), component_changed) in
        blocks
    {
        let block = (entities, (configs, motions), components);
        let (touched, written) =
            any_newer_in_each([config_changed, component_changed], last_run, this_run);
        let changed = (component_changed, this_run);
        if touched {
            // The configuration changed since this system last ran (see `step_entity`).
            let untouched = |row: usize| !config_changed[row].is_newer_than(last_run, this_run);
            step_block(block, (untouched, false), changed, prepared, &context);
        } else if !written {
            step_block(block, (|_| true, true), changed, prepared, &context);
        } else {
            step_block(block, (|_| true, false), changed, prepared, &context);
        }
    }
}

/// Rows whose configurations' and properties' change ticks [`step_rows`] tests together.
const TOUCH_BLOCK: usize = 256;

/// [`step_rows`] for one block of rows, whether each is `untouched` (see [`step_row`]) told by
/// row, and whether all are `unwritten`.
#[expect(
    clippy::inline_always,
    reason = "three copies of the per-entity loop, two that know every row is untouched, one \
              of them that every row is unwritten"
)]
#[inline(always)]
fn step_block<P: SpringProperty>(
    (entities, (configs, motions), components): (
        &[Entity],
        (&mut [PropertySpring<P>], &mut [SpringMotion<P>]),
        &mut [P::Component],
    ),
    (untouched, unwritten): (impl Fn(usize) -> bool, bool),
    (component_changed, this_run): (&mut [Tick], Tick),
    prepared: PreparedIncrements,
    (steps, table, caches, commands): &StepContext,
) {
    let rows = motions
        .iter_mut()
        .zip(components.iter_mut())
        .zip(component_changed);
    for (row, ((motion, component), component_changed)) in rows.enumerate() {
        // Found by index, not walked alongside: the configuration is read only on the unusual
        // path.
        let configs = &mut *configs;
        if step_row(
            (|| entities[row], || row_of(configs, row)),
            motion,
            component,
            (untouched(row), unwritten),
            prepared,
            (steps, table, caches, commands),
        ) {
            *component_changed = this_run;
        }
    }
}

/// `&mut rows[row]`, out of line: inlined, the compiler would walk a pointer to it alongside
/// the other columns (1 instruction a spring) for the rare row that reads it.
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

/// [`step_entity`] when the usual step declined: the general step, with a transition from this
/// thread's cache, its write and its settling. Whether it wrote the property.
#[cold]
#[inline(never)]
fn step_entity_unusual<P: SpringProperty>(
    entity: Entity,
    (config, motion): (&mut PropertySpring<P>, &mut SpringMotion<P>),
    component: &mut P::Component,
    (steps, untouched, table, caches): (
        FrameSteps,
        bool,
        &TransitionTable,
        &Parallel<TransitionCache>,
    ),
    commands: &ParallelCommands,
) -> bool {
    // Read again rather than passed: as an argument, the value would leave the vector
    // registers on the usual path too.
    let current = P::get(component);
    let frame = motion.step_unusual(
        config,
        current,
        steps,
        (false, untouched),
        (table, &mut caches.borrow_local_mut()),
    );
    if frame.outcome == Stepped::Settled {
        put_to_sleep::<P>(commands, entity);
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
        super::trigger_if_alive(&mut commands, SpringSettled::<P>::new(entity));
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
        super::trigger_if_alive(&mut commands, SpringWoke::<P>::new(entity));
    };
    let Ok(tables) = asleep.contiguous_iter() else {
        // Not reached (the components are in tables): the same, spring by spring.
        for (entity, spring, motion, component) in &asleep {
            let changes = RowChanges {
                spring: spring.is_changed(),
                property: component.is_changed(),
            };
            if changes.wake(&spring, motion, &component) {
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
            if changes.wake(&springs[row], &motions[row], &components[row]) {
                wake(entities[row]);
            }
        });
    }
}

/// What changed in one sleeping spring's row since the waking system last ran.
#[derive(Clone, Copy, Debug, Default)]
struct RowChanges {
    /// The spring's configuration (a retarget, a kick, an edit).
    spring: bool,
    /// Its property (written by something else, or by the spring's own last step).
    property: bool,
}

impl RowChanges {
    /// Whether the sleeping spring with `motion` wakes: its configuration asks it to move, or
    /// something else wrote its property. A configuration marked changed is also how a spring
    /// whose entity was disabled says it is back (see `touch_on_return`): its property may have
    /// been written while the systems did not see it, so it is compared too.
    #[inline]
    fn wake<P: SpringProperty>(
        self,
        spring: &PropertySpring<P>,
        motion: &SpringMotion<P>,
        component: &P::Component,
    ) -> bool {
        let written = || !motion.holds(P::get(component));
        (self.spring && (spring.wants_to_move(motion) || written())) || (self.property && written())
    }
}

/// Calls `visit` with the index of every row whose tick in either column (the springs', the
/// properties') is newer than `last_run`, and which of the two are. Two levels: a scene at rest
/// settles each long stretch with one test of both columns, and a stretch that holds a change
/// is looked into block by block, so that one retarget among many sleeping springs costs a few
/// short blocks rather than the whole stretch row by row.
fn for_each_changed_row(
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

/// Springs whose change ticks [`wake_springs`] tests together, inside a stretch that holds a
/// change.
const WAKE_BLOCK: usize = 256;

/// Springs whose change ticks [`wake_springs`] tests together first: the test's setup and the
/// walk of four columns' chunks, about 40 instructions, paid once for this many (0.2 an
/// instruction a spring at the block size alone; callgrind).
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
    // is newer. Two instructions per four ticks against the four of the test below, which
    // runs only where the OR is not below (a tick from before the counter wrapped around, or
    // recent ticks whose OR carries past it).
    if first_newer <= this_run.get() && or_of([ticks])[0] < first_newer {
        return false;
    }
    let origin = first_newer.wrapping_add(BIAS);
    let last_newer = (since_system ^ BIAS).cast_signed().wrapping_sub(1);
    let old = |tick: &Tick| tick.get().wrapping_sub(origin).cast_signed() > last_newer;
    // Sixteen ticks (four vectors) a round: the loop's own three instructions amortised over
    // more of them (1.4 -> 1.2 instructions a tick).
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
fn any_newer_in_each(
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
