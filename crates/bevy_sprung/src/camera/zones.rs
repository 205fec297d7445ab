//! Zone events: a rig's framed point leaving or re-entering its [`DeadZone`], its target
//! reaching or leaving its [`HardLimit`](super::HardLimit), and its camera reaching or leaving
//! its [`Confiner`](super::Confiner)'s edge.

use bevy::prelude::*;
use bevy::window::{PrimaryWindow, Window};

use super::components::{DeadZone, RigMotion, RigTracking, ZoneContact};
use super::framing::CameraFraming;
use super::systems::Posed;
use crate::spring::trigger_if_alive;

/// Triggered on a rig's entity when its framed point leaves its [`DeadZone`]: it reaches an
/// edge and pushes the zone, and the camera starts to follow. Never for a rig despawned
/// before the event is delivered.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::camera::DeadZoneExited;
///
/// fn spawn(mut commands: Commands) {
///     commands.spawn(Camera2d).observe(|exited: On<DeadZoneExited>| {
///         info!("{} starts to follow", exited.entity);
///     });
/// }
/// # bevy::ecs::system::assert_is_system(spawn);
/// ```
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct DeadZoneExited {
    /// The rig.
    pub entity: Entity,
}

/// Triggered on a rig's entity when its framed point is back inside its [`DeadZone`], off
/// its edges: the camera stops following (and comes to rest).
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct DeadZoneEntered {
    /// The rig.
    pub entity: Entity,
}

/// Triggered on a rig's entity when its goal's point reaches its
/// [`HardLimit`](super::HardLimit): the camera is carried along by the target.
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct HardLimitReached {
    /// The rig.
    pub entity: Entity,
}

/// Triggered on a rig's entity when its goal's point is back inside its
/// [`HardLimit`](super::HardLimit), off its edge.
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct HardLimitLeft {
    /// The rig.
    pub entity: Entity,
}

/// Triggered on a rig's entity when its camera reaches its confiner's edge: the view stands on
/// the bounds on some axis (within a ten-thousandth of the view's size), past the slowing band.
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ConfinerEdgeReached {
    /// The rig.
    pub entity: Entity,
}

/// Triggered on a rig's entity when its camera leaves its confiner's edge, back into the
/// bounds.
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ConfinerEdgeLeft {
    /// The rig.
    pub entity: Entity,
}

/// After the cameras are placed: each rig's contact with its zones, and an event for each
/// change since the last frame (none on a rig's first frame, which only notes where it
/// stands).
pub(super) fn announce_zones(
    mut rigs: Query<(
        Entity,
        &CameraFraming,
        &RigMotion,
        &mut RigTracking,
        Has<DeadZone>,
        Posed,
    )>,
    window: Query<&Window, With<PrimaryWindow>>,
    mut commands: Commands,
) {
    let window = window.single().ok();
    for (entity, framing, motion, mut tracking, has_zone, posed) in &mut rigs {
        let area = posed.view_area(motion, window);
        let now = ZoneContact {
            pushes_dead_zone: has_zone && framing.pushes_dead_zone(),
            at_hard_limit: posed.at_hard_limit(motion, area),
            at_confiner_edge: posed.at_confiner_edge(motion, area),
        };
        let Some(before) = tracking.contact.replace(now) else {
            continue;
        };
        if now.pushes_dead_zone != before.pushes_dead_zone {
            if now.pushes_dead_zone {
                trigger_if_alive(&mut commands, DeadZoneExited { entity });
            } else {
                trigger_if_alive(&mut commands, DeadZoneEntered { entity });
            }
        }
        if now.at_hard_limit != before.at_hard_limit {
            if now.at_hard_limit {
                trigger_if_alive(&mut commands, HardLimitReached { entity });
            } else {
                trigger_if_alive(&mut commands, HardLimitLeft { entity });
            }
        }
        if now.at_confiner_edge != before.at_confiner_edge {
            if now.at_confiner_edge {
                trigger_if_alive(&mut commands, ConfinerEdgeReached { entity });
            } else {
                trigger_if_alive(&mut commands, ConfinerEdgeLeft { entity });
            }
        }
    }
}
