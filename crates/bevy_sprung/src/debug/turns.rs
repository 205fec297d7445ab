//! The springs group's rotation and scale springs: what a turn or a swell is heading for and
//! how it will get there.

use bevy::color::palettes::css;
use bevy::prelude::*;

use super::springs::{
    PathSampling, SpringGizmos, UNSETTLED_HORIZON, label_rotation, parent_space, settle_label,
};
use crate::spring::{SpringAsleep, SpringMotion};
use crate::transform::{Rotation, RotationSpring, Scale, ScaleSpring};

/// How long an orientation's pointer is, in markers ([`SpringGizmos::size`]).
const POINTER: f32 = 4.0;

/// Draws every rotation spring as a pointer along the entity's local x axis: where it points
/// now (white), where it is heading (gold), the path its tip will take to rest (exact), and the
/// seconds left.
pub(super) fn draw_rotations(
    mut gizmos: Gizmos<SpringGizmos>,
    springs: Query<(
        Entity,
        &RotationSpring,
        &SpringMotion<Rotation>,
        Option<&ChildOf>,
        Has<SpringAsleep<Rotation>>,
    )>,
    globals: Query<&GlobalTransform>,
    cameras: Query<&GlobalTransform, With<Camera>>,
) {
    let options = *gizmos.config_ext;
    let facing = label_rotation(&cameras);
    let length = options.size * POINTER;
    for (entity, spring, motion, parent, asleep) in &springs {
        let Ok(global) = globals.get(entity) else {
            continue;
        };
        let here = global.translation();
        let turn = parent_space(parent, &globals).rotation();
        let tip = |rotation: Quat| here + turn * rotation * Vec3::X * length;
        let forecast = spring.forecast(motion);
        if asleep {
            gizmos.line(here, tip(forecast.value_at(0.0)), css::GRAY);
            continue;
        }
        gizmos.line(here, tip(forecast.target()), css::GOLD);
        gizmos.line(here, tip(forecast.value_at(0.0)), css::WHITE);
        let settle = forecast.settle_time();
        if options.path {
            let sampling =
                PathSampling::over(settle.unwrap_or(UNSETTLED_HORIZON), options.path_step);
            let path = core::iter::once(forecast.value_at(0.0))
                .chain(forecast.samples(sampling.step, sampling.count))
                .map(tip);
            gizmos.linestrip(path, css::AQUA);
        }
        if options.settle_time {
            let at = tip(forecast.value_at(0.0));
            settle_label(&mut gizmos, at, facing, settle, options.size * 1.5);
        }
    }
}

/// Draws every scale spring as two boxes around the entity, [`SpringGizmos::size`] times its
/// scale: now (white) and heading for (gold), and the seconds left.
pub(super) fn draw_scales(
    mut gizmos: Gizmos<SpringGizmos>,
    springs: Query<(
        Entity,
        &ScaleSpring,
        &SpringMotion<Scale>,
        Has<SpringAsleep<Scale>>,
    )>,
    globals: Query<&GlobalTransform>,
    cameras: Query<&GlobalTransform, With<Camera>>,
) {
    let options = *gizmos.config_ext;
    let facing = label_rotation(&cameras);
    let marker = Vec2::splat(options.size * POINTER);
    for (entity, spring, motion, asleep) in &springs {
        let Ok(global) = globals.get(entity) else {
            continue;
        };
        // The box is the entity's own marker, scaled as the entity is (with its parents'
        // scale, which the spring does not move).
        let (outer, rotation, here) = global.to_scale_rotation_translation();
        let forecast = spring.forecast(motion);
        let now = forecast.value_at(0.0);
        let inherited = outer / now.abs().max(Vec3::splat(f32::MIN_POSITIVE));
        let extent = |scale: Vec3| marker * (scale * inherited).truncate();
        let pose = Isometry3d::new(here, rotation);
        if asleep {
            gizmos.rect(pose, extent(now), css::GRAY);
            continue;
        }
        gizmos.rect(pose, extent(forecast.target()), css::GOLD);
        gizmos.rect(pose, extent(now), css::WHITE);
        if options.settle_time {
            let corner = here + rotation * (extent(now) * 0.5).extend(0.0);
            let settle = forecast.settle_time();
            settle_label(&mut gizmos, corner, facing, settle, options.size * 1.5);
        }
    }
}
