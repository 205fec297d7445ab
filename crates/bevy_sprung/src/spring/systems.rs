//! The systems that step springs, put them to sleep and wake them.

use bevy::ecs::system::ParallelCommands;
use bevy::prelude::*;

use super::cache::TransitionCache;
use super::component::{PropertySpring, SpringAsleep, Stepped};
use super::event::SpringSettled;
use crate::clock::SpringTime;
use crate::property::SpringProperty;

#[cfg(feature = "visibility")]
type Visibility = (
    Option<&'static ViewVisibility>,
    Has<crate::visibility::CatchUpWhenHidden>,
);
#[cfg(not(feature = "visibility"))]
type Visibility = ();

/// Whether a spring may skip this frame: it opted in and nobody saw it last frame.
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
    time: SpringTime,
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
    let steps = time.steps();
    // Boxed: the fold behind `for_each_init` moves its state through every item, and a pointer
    // moves for free where the cache itself would be copied twice per entity.
    springs.par_iter_mut().for_each_init(
        Box::<TransitionCache>::default,
        |cache, (entity, mut spring, mut component, visibility)| {
            let dt = steps.dt(spring.clock());
            if spring.step(&mut component, dt, is_hidden(visibility), cache) == Stepped::Settled {
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
