//! Presence: entities that spring in when they appear and spring out before they go — Motion's
//! `AnimatePresence`, SwiftUI's insertion and removal transitions — and children that enter one
//! after another (Motion's `staggerChildren`).
//!
//! An entity with [`Presence`] enters from the values its [`EnterFrom<P>`] components give (its
//! springs carry each property to its target), and leaves through
//! [`despawn_after_exit`](PresenceCommands::despawn_after_exit): each spring with an
//! [`ExitTo<P>`] retargets to its exit value, and once every spring of the entity has settled,
//! [`Exited`] is triggered and the entity is despawned with its descendants.
//! [`cancel_exit`](PresenceCommands::cancel_exit) turns it back on the way out, its springs
//! keeping their velocities. [`StaggerChildren`] on a parent spaces its children's entrances.
//! Entities without a `Presence` pay nothing for any of this.

mod lifecycle;
mod stagger;

pub use lifecycle::{
    EnterFrom, Entered, ExitTo, Exited, Presence, PresenceCommands, PresencePhase,
};
pub use stagger::{StaggerChildren, StaggerOrder, StaggerWhen};

use core::any::TypeId;

use bevy::prelude::*;

use crate::property::SpringProperty;
use crate::spring::{SpringSystems, add_systems_on_first_use, spring_schedule};

/// Presence (part of [`SpringPlugins`](crate::SpringPlugins)): entities with [`Presence`] report
/// when they have entered and leave once their exit has settled; the children of a
/// [`StaggerChildren`] wait their turn (its systems join the springs' schedule with the first
/// one, before the springs step).
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringPresencePlugin;

impl Plugin for SpringPresencePlugin {
    fn build(&self, app: &mut App) {
        let schedule = spring_schedule(app);
        app.register_type::<Presence>()
            .register_type::<PresencePhase>()
            .register_type::<StaggerChildren>()
            .register_type::<StaggerOrder>()
            .register_type::<StaggerWhen>()
            .add_observer(lifecycle::settled);
        add_systems_on_first_use(
            app,
            &[TypeId::of::<StaggerChildren>()],
            schedule,
            |schedule| {
                schedule.add_systems(
                    (stagger::schedule_entrances, stagger::release_entrances)
                        .chain()
                        .before(SpringSystems)
                        .run_if(any_with_component::<StaggerChildren>),
                );
            },
        );
    }
}

/// What [`SpringPropertyPlugin<P>`](crate::SpringPropertyPlugin) adds of presence: an
/// entity's [`ExitTo<P>`] is headed for when it leaves, and its [`EnterFrom<P>`] holds while
/// its entrance waits.
pub(crate) fn add_property<P: SpringProperty>(app: &mut App) {
    app.register_type::<EnterFrom<P>>()
        .register_type::<ExitTo<P>>()
        .add_observer(lifecycle::turn_property::<P>);
}
