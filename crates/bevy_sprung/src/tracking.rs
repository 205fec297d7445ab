//! Tracking an entity's motion: where it is this frame (`WorldPositions`, internal), and
//! teleports — a target moved without travelling, told explicitly ([`TargetWarped`]) or caught
//! by a distance, so that no velocity estimate reads the jump as motion. Below every feature
//! that estimates a velocity from positions (following, camera rigs, squash & stretch).

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;

/// Where entities are in the world, from this frame's `Transform`s: the entity's own and its
/// ancestors', composed up to the root. Last frame's `GlobalTransform` would put a target
/// whose parent moved this frame one frame behind; this walk sees every move gameplay made
/// before the springs step, at any depth of the hierarchy.
#[derive(SystemParam)]
pub(crate) struct WorldPositions<'w, 's> {
    transforms: Query<'w, 's, (&'static Transform, Option<&'static ChildOf>)>,
}

impl WorldPositions<'_, '_> {
    /// The world position of `entity`, if it has a `Transform`. An ancestor without one ends
    /// the walk there (Bevy does not propagate through it either).
    pub(crate) fn of(&self, entity: Entity) -> Option<Vec3> {
        let (transform, mut parent) = self.transforms.get(entity).ok()?;
        let mut point = transform.translation;
        while let Some(child_of) = parent {
            let Ok((transform, grandparent)) = self.transforms.get(child_of.parent()) else {
                break;
            };
            point = transform.transform_point(point);
            parent = grandparent;
        }
        Some(point)
    }
}

/// Triggered on an entity that was moved without travelling — a respawn, a level change, a
/// portal — by `delta` (Cinemachine's `OnTargetObjectWarped`): every
/// [`SpringFollow`](crate::follow::SpringFollow) and camera rig that follows it moves by its
/// share of the jump at once, keeping its framing and its velocity, instead of reading the jump
/// as a frame of enormous speed, and its [`SquashStretch`](crate::juice::SquashStretch) does
/// not stretch at it. Trigger it in the frame
/// of the move, before the springs step (in `Update`, say).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::tracking::TargetWarped;
///
/// fn respawn(mut players: Query<(Entity, &mut Transform)>, mut commands: Commands) {
///     for (player, mut transform) in &mut players {
///         let spawn_point = Vec3::new(0.0, 2.0, 0.0);
///         let delta = spawn_point - transform.translation;
///         transform.translation = spawn_point;
///         commands.trigger(TargetWarped { entity: player, delta });
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Update, respawn);
/// # app.update();
/// ```
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq)]
pub struct TargetWarped {
    /// The entity that was moved.
    pub entity: Entity,
    /// How far it was moved, in world units.
    pub delta: Vec3,
}

/// How far a followed target was carried without travelling between `last` and `now` (zero if
/// it travelled), having been expected to travel `expected` (its last velocity times the
/// frame's step): all of the move beyond that if the move is further than
/// `teleport_distance`, else the explicit warps `pending` (used up).
pub(crate) fn take_warp(
    pending: &mut Vec3,
    teleport_distance: f32,
    (last, now): (Option<Vec3>, Vec3),
    expected: Vec3,
) -> Vec3 {
    let pending = core::mem::take(pending);
    match last.map(|last| now - last) {
        Some(moved) if moved.length() > teleport_distance => moved - expected,
        _ => pending,
    }
}
