//! The chains group: each spring chain's joints, bones, rest pose and colliders.

use bevy::color::palettes::css;
use bevy::gizmos::config::GizmoConfigGroup;
use bevy::prelude::*;

use crate::chain::{ChainCollider, SpringChain};

/// The chains group of the [debug overlay](super): for each [`SpringChain`], every bone from
/// its joint to where the spring holds its tip (a ring on each tip), the rest pose the bone
/// springs around (dim), and the spheres and capsules of its colliders.
///
/// Turn it on or off, and set its line width, through
/// [`GizmoConfigStore`](bevy::gizmos::config::GizmoConfigStore).
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Default)]
pub struct ChainGizmos {
    /// The size of the joints' rings, in world units: 0.02 by default (a 3D scene in metres;
    /// a few pixels in 2D).
    pub size: f32,
    /// Draw the rest pose.
    pub rest_pose: bool,
    /// Draw the colliders.
    pub colliders: bool,
}

impl Default for ChainGizmos {
    fn default() -> Self {
        Self {
            size: 0.02,
            rest_pose: true,
            colliders: true,
        }
    }
}

impl GizmoConfigGroup for ChainGizmos {}

/// Draws every chain.
pub(super) fn draw_chains(
    mut gizmos: Gizmos<ChainGizmos>,
    chains: Query<&SpringChain>,
    globals: Query<&GlobalTransform>,
    colliders: Query<(&ChainCollider, &GlobalTransform)>,
) {
    let options = *gizmos.config_ext;
    for chain in &chains {
        for bone in chain.bones() {
            let Ok(joint) = globals.get(bone.joint) else {
                continue;
            };
            let origin = joint.translation();
            if options.rest_pose {
                gizmos.line(origin, bone.rest_tip, css::DIM_GRAY);
            }
            gizmos.line(origin, bone.tip, css::LIME);
            gizmos.sphere(
                Isometry3d::from_translation(bone.tip),
                options.size,
                css::LIME,
            );
        }
        if options.colliders {
            for (collider, global) in chain
                .colliders
                .iter()
                .filter_map(|&entity| colliders.get(entity).ok())
            {
                draw_collider(&mut gizmos, *collider, global);
            }
        }
    }
}

/// A sphere, or a capsule along the entity's local y, in the world.
fn draw_collider(
    gizmos: &mut Gizmos<ChainGizmos>,
    collider: ChainCollider,
    global: &GlobalTransform,
) {
    let (scale, rotation, translation) = global.to_scale_rotation_translation();
    let size = scale.abs().max_element();
    let radius = collider.radius.max(0.0) * size;
    let half_length = collider.half_length.max(0.0) * size;
    if half_length > 0.0 {
        gizmos.primitive_3d(
            &Capsule3d::new(radius, 2.0 * half_length),
            Isometry3d::new(translation, rotation),
            css::TOMATO,
        );
    } else {
        gizmos.sphere(Isometry3d::new(translation, rotation), radius, css::TOMATO);
    }
}
