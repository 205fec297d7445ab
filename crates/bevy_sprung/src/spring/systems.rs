//! The systems that step springs, put them to sleep and wake them: the ECS side of the
//! kernel's contract (prepare, step rows, finish; see `kernel`).

use core::marker::PhantomData;

use bevy::ecs::system::{ParallelCommands, SystemParam};
use bevy::prelude::*;

use super::component::{PropertySpring, SpringAsleep, SpringMotion};
use super::event::{SpringSettled, SpringWoke};
use super::kernel::{self, Kernel, RowChanges, StepContext, StepReport};
use super::preference::{KeepMotion, ReducedMotion};
use super::skip::SkipFrames;
use crate::clock::SpringTime;
use crate::property::SpringProperty;

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
    mut kernel: Local<Kernel>,
    mut awake: AwakeSprings<P>,
    commands: ParallelCommands,
) {
    let count = awake.every_frame.iter().len() + awake.skipping.iter().len();
    let preference = settings
        .preference
        .as_deref()
        .copied()
        .unwrap_or(ReducedMotion::Full);
    let report = PutToSleep::<P> {
        commands: &commands,
        property: PhantomData,
    };
    let context = kernel.prepare::<P>(settings.time.steps(), &report);
    if preference.is_reduced() {
        step_reduced(&mut awake, preference, &settings.keep_motion, &context);
    } else {
        step_every_frame(&mut awake.every_frame, &context);
        step_skipping(&mut awake.skipping, &context);
    }
    kernel.finish(count);
}

/// The springs that step every frame: a table's columns at a time where the components are in
/// tables, entity by entity otherwise.
fn step_every_frame<P: SpringProperty>(springs: &mut EveryFrame<P>, context: &StepContext) {
    let threads = kernel::scope_threads();
    if let Ok(tables) = springs.contiguous_iter_mut() {
        // Each table's columns as slices, the step inlined into a plain loop over them, change
        // ticks read and written directly; split over the scope's threads if there are several.
        for (entities, configs, motions, components) in tables {
            context.step_columns(entities, (configs, motions, components), threads);
        }
    } else if threads > 1 {
        // A property on a sparse-set component: entity by entity.
        springs
            .par_iter_mut()
            .for_each(|item| context.step_item(item));
    } else {
        for item in springs.iter_mut() {
            context.step_item(item);
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
        context.step_skipping(entity, (config, &mut motion), &mut component, skip.0);
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
    let preference_of = |entity| (!keep_motion.contains(entity)).then_some(preference);
    for row in awake.every_frame.iter_mut() {
        let preference = preference_of(row.0);
        context.step_reduced(row, preference);
    }
    for (entity, config, motion, component, _) in awake.skipping.iter_mut() {
        context.step_reduced((entity, config, motion, component), preference_of(entity));
    }
}

/// What [`step_springs`] does with the springs on `P` that arrive: marks them asleep and
/// triggers [`SpringSettled<P>`], through commands the stepping threads share.
struct PutToSleep<'a, P> {
    commands: &'a ParallelCommands<'a, 'a>,
    property: PhantomData<fn() -> P>,
}

impl<P: SpringProperty> StepReport for PutToSleep<'_, P> {
    #[cold]
    #[inline(never)]
    fn arrived(&self, entity: Entity) {
        self.commands.command_scope(|mut commands| {
            commands
                .entity(entity)
                .try_insert(SpringAsleep::<P>::default());
            super::event::trigger_if_alive(&mut commands, SpringSettled::<P>::new(entity));
        });
    }
}

/// Wakes sleeping springs on property `P` whose target changed or that were kicked, and those
/// whose property something else moved away from where they rest (a teleport, a value written
/// by hand): sleeping saves work, and changes nothing a spring does.
///
/// Only springs whose configuration or property changed since the last run are looked at.
/// Their change ticks are scanned a table column at a time, in blocks tested without a branch
/// per spring ([`kernel::wake_columns`]): a scene of sleeping springs costs about one
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
            if kernel::wakes(changes, &spring, motion, &component) {
                wake(entity);
            }
        }
        return;
    };
    for (entities, springs, motions, components) in tables {
        kernel::wake_columns(entities, (springs, motions, components), &mut wake);
    }
}
