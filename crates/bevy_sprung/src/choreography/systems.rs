//! Driving sequences, and the events they trigger.

use core::marker::PhantomData;

use bevy::prelude::*;

use super::sequence::{Advance, SequencePhase, SpringSequence, Tick};
use crate::clock::SpringTime;
use crate::property::SpringProperty;
use crate::spring::{PropertySpring, SpringAsleep, SpringMotion, property_event, trigger_if_alive};

/// Triggered on an entity when its [`SpringSequence<P>`] has played its last step: the
/// tween-completion event for a whole choreography.
#[derive(EntityEvent)]
pub struct SequenceCompleted<P: SpringProperty> {
    /// The entity whose sequence completed.
    pub entity: Entity,
    property: PhantomData<fn() -> P>,
}

/// Triggered on an entity when something else retargeted the spring its
/// [`SpringSequence<P>`] drives: the sequence was cancelled or paused (see
/// [`OnInterrupt`](super::OnInterrupt)).
#[derive(EntityEvent)]
pub struct SequenceInterrupted<P: SpringProperty> {
    /// The entity whose sequence was interrupted.
    pub entity: Entity,
    property: PhantomData<fn() -> P>,
}

property_event!(SequenceCompleted);
property_event!(SequenceInterrupted);

/// Before property `P`'s springs step: moves every playing sequence on (a delay that ran out,
/// a step that settled or timed out), detects interruptions, and triggers the events.
pub(super) fn drive_sequences<P>(
    time: SpringTime,
    mut commands: Commands,
    mut sequences: Query<(
        Entity,
        &mut SpringSequence<P>,
        &mut PropertySpring<P>,
        Option<&SpringMotion<P>>,
        Has<SpringAsleep<P>>,
    )>,
) where
    P: SpringProperty,
{
    let steps = time.steps();
    for (entity, mut sequence, mut spring, motion, asleep) in &mut sequences {
        if matches!(
            sequence.phase(),
            SequencePhase::Finished | SequencePhase::Paused
        ) {
            continue;
        }
        let target = spring.target();
        let on_step = sequence.current().is_some_and(|step| step.target == target);
        // Something else set the spring's target while a step played.
        if sequence.phase() == SequencePhase::Playing && !sequence.is_resuming() && !on_step {
            sequence.interrupt();
            trigger_if_alive(&mut commands, SequenceInterrupted::<P>::new(entity));
            continue;
        }
        let arrived = on_step
            && match sequence.current().map(|step| step.advance) {
                Some(Advance::Within(distance)) => motion.is_some_and(|motion| {
                    let omega = spring.spring().natural_frequency();
                    asleep || motion.is_within(target, distance, omega)
                }),
                _ => asleep,
            };
        let dt = steps.dt(spring.clock());
        match sequence.tick(dt, arrived) {
            Tick::Idle => {}
            Tick::Start => {
                if let Some(step) = sequence.current().copied() {
                    if let Some(parameters) = step.spring {
                        spring.set_spring(parameters);
                    }
                    spring.set_target(step.target);
                }
            }
            Tick::Completed => {
                trigger_if_alive(&mut commands, SequenceCompleted::<P>::new(entity));
            }
        }
    }
}
