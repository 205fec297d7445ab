//! The systems of inertialization: where each player's offsets stand this frame, the offsets
//! added to the pose the animation gave; and the joints' state kept as players and joints come
//! and go.

use bevy::animation::AnimatedBy;
use bevy::prelude::*;

use super::Inertialization;
use super::joint::{BlendFrame, InertialJoint};
use super::pose::Pose;
use crate::clock::{SpringClock, SpringTime};

/// Each player's `BlendFrame`: where its last transition's decay stands this frame, on the
/// game clock the animation plays on.
pub(crate) fn prepare_frames(time: SpringTime, mut players: Query<&mut Inertialization>) {
    let dt = time.delta(Some(SpringClock::Game));
    for mut player in &mut players {
        player.prepare(dt);
    }
}

/// After animation: each joint of an inertialized player takes the pose the animation gave it,
/// starts a blend if its player switched, reads its offset off the decay, and shows clip +
/// offset. Joints of players that are gone or no longer inertialized drop their blend.
pub(crate) fn blend_joints(
    players: Query<&Inertialization>,
    mut joints: Query<(&AnimatedBy, &mut Transform, &mut InertialJoint)>,
) {
    // A player's joints are mostly stored together: look the player up once per run of them.
    let mut last: Option<(Entity, Option<BlendFrame>)> = None;
    for (&AnimatedBy(player), mut transform, mut joint) in &mut joints {
        let frame = match last {
            Some((entity, frame)) if entity == player => frame,
            _ => {
                let frame = players.get(player).ok().map(|player| *player.frame());
                last = Some((player, frame));
                frame
            }
        };
        let Some(frame) = frame else {
            joint.forget();
            continue;
        };
        let clip = joint.clip_pose(&transform);
        if let Some(shown) = joint.advance(clip, &frame) {
            transform.translation = shown.translation;
            transform.rotation = shown.rotation;
            transform.scale = shown.scale;
        }
    }
}

/// A joint animated by an inertialized player (a scene spawning under it, a joint moved to it)
/// is given a fresh state: it has seen the player's transitions so far.
pub(crate) fn track_animated_joint(
    animated: On<Insert, AnimatedBy>,
    joints: Query<(&AnimatedBy, &Transform)>,
    players: Query<&Inertialization>,
    mut commands: Commands,
) {
    let joint = animated.entity;
    if let Ok((&AnimatedBy(player), transform)) = joints.get(joint)
        && let Ok(player) = players.get(player)
    {
        commands
            .entity(joint)
            .try_insert(InertialJoint::at(Pose::of(transform), player.transitions()));
    }
}

/// A player given an [`Inertialization`] gives a fresh state to the joints it already animates
/// (any state from an earlier one is dropped).
pub(crate) fn track_player_joints(
    inertialized: On<Add, Inertialization>,
    joints: Query<(Entity, &AnimatedBy, &Transform)>,
    players: Query<&Inertialization>,
    mut commands: Commands,
) {
    let player = inertialized.entity;
    let transitions = players.get(player).map_or(0, Inertialization::transitions);
    for (joint, &AnimatedBy(by), transform) in &joints {
        if by == player {
            commands
                .entity(joint)
                .try_insert(InertialJoint::at(Pose::of(transform), transitions));
        }
    }
}
