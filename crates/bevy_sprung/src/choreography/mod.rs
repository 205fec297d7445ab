//! Choreography, spring-native: sequences of targets, delays, stagger, loops, and one event when
//! a group of springs has settled. The tween replacement for UI.
//!
//! Every step is a retarget of a spring, so nothing ever pops: a sequence interrupted mid-way
//! hands its velocity to whatever comes next, and a loop between two targets is a continuous
//! motion. Springs that use none of this pay nothing for it: the systems look only at entities
//! with a [`SpringSequence`] or a [`SpringGroup`].

mod group;
mod sequence;
mod systems;

pub(crate) use group::report_when_settled;
pub use group::{AllSpringsSettled, SpringGroup, SpringGroupSettled};
pub use sequence::{
    Advance, LoopMode, OnInterrupt, Repeat, SequencePhase, SequenceStep, SpringSequence,
};
pub use systems::{SequenceCompleted, SequenceInterrupted};

use core::any::TypeId;

use bevy::prelude::*;

use crate::property::SpringProperty;
use crate::spring::{
    PropertySpring, PropertySystems, SpringPhase, SpringSystems, SpringUpdate,
    add_systems_on_first_use, spring_schedule, warn_missing,
};

/// Group completion ([`SpringGroup`]) and the choreography types (part of
/// [`SpringPlugins`](crate::SpringPlugins)). The per-property systems that drive
/// [`SpringSequence`]s come with each property's
/// [`SpringPropertyPlugin`](crate::SpringPropertyPlugin).
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringChoreographyPlugin;

impl Plugin for SpringChoreographyPlugin {
    fn build(&self, app: &mut App) {
        let schedule = spring_schedule(app);
        app.init_resource::<group::SettleTracker>()
            .register_type::<SpringGroup>()
            .register_type::<Advance>()
            .register_type::<Repeat>()
            .register_type::<LoopMode>()
            .register_type::<OnInterrupt>()
            .register_type::<SequencePhase>();
        // With the first group.
        let groups = [TypeId::of::<SpringGroup>()];
        add_systems_on_first_use(app, &groups, schedule, |schedule| {
            schedule.add_systems(
                group::announce_settled
                    .after(SpringSystems)
                    .run_if(group::has_news),
            );
        });
    }
}

/// What [`SpringPropertyPlugin<P>`](crate::SpringPropertyPlugin) adds of choreography:
/// sequences of `P` drive its springs in [`SpringPhase::Choreograph`] (with the first
/// [`SpringSequence<P>`]), and groups note which of its springs move, in
/// [`SpringPhase::Observe`] and when one wakes (with the first [`SpringGroup`]).
pub(crate) fn add_property<P: SpringProperty>(app: &mut App) {
    app.register_type::<SpringSequence<P>>()
        .add_observer(group::note_woken::<P>);
    let sequences = [TypeId::of::<SpringSequence<P>>()];
    let outer = spring_schedule(app);
    add_systems_on_first_use(app, &sequences, outer, |schedule| {
        schedule.add_systems(
            warn_missing::<SpringSequence<P>, PropertySpring<P>>(
                "the sequence drives that spring and does nothing without it; add the spring",
            )
            .before(SpringSystems)
            .run_if(any_with_component::<SpringSequence<P>>),
        );
    });
    add_systems_on_first_use(app, &sequences, SpringUpdate, |schedule| {
        schedule.add_systems(
            systems::drive_sequences::<P>
                .in_set(PropertySystems::<P>::phase(SpringPhase::Choreograph))
                .run_if(any_with_component::<SpringSequence<P>>),
        );
    });
    let groups = [TypeId::of::<SpringGroup>()];
    add_systems_on_first_use(app, &groups, SpringUpdate, |schedule| {
        schedule.add_systems(
            group::note_awake::<P>
                .in_set(PropertySystems::<P>::phase(SpringPhase::Observe))
                .run_if(any_with_component::<SpringGroup>),
        );
    });
}
