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

pub use group::{AllSpringsSettled, SpringGroup, SpringGroupSettled};
pub use sequence::{
    Advance, LoopMode, OnInterrupt, Repeat, SequencePhase, SequenceStep, SpringSequence,
};
pub use systems::{SequenceCompleted, SequenceInterrupted};

pub(crate) use group::{SettleTracker, note_awake};
pub(crate) use systems::drive_sequences;

use bevy::prelude::*;

use crate::spring::SpringSystems;

/// Group completion ([`SpringGroup`]) and the choreography types (part of
/// [`SpringPlugin`](crate::SpringPlugin)). The per-property systems that drive
/// [`SpringSequence`]s come with each property's
/// [`SpringPropertyPlugin`](crate::spring::SpringPropertyPlugin).
#[derive(Debug, Default, Clone, Copy)]
pub struct ChoreographyPlugin;

impl Plugin for ChoreographyPlugin {
    fn build(&self, app: &mut App) {
        let schedule = crate::spring::spring_schedule(app);
        app.init_resource::<SettleTracker>()
            .register_type::<SpringGroup>()
            .register_type::<Advance>()
            .register_type::<Repeat>()
            .register_type::<LoopMode>()
            .register_type::<OnInterrupt>()
            .register_type::<SequencePhase>();
        // With the first group.
        let groups = [core::any::TypeId::of::<SpringGroup>()];
        crate::spring::add_systems_on_first_use(app, &groups, schedule, |schedule| {
            schedule.add_systems(
                group::announce_settled
                    .after(SpringSystems)
                    .run_if(group::has_news),
            );
        });
    }
}
