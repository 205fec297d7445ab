//! The camera group's shots: every virtual camera, the one showing, and the blend to it.

use bevy::color::palettes::css;
use bevy::prelude::*;

use super::camera::CameraRigGizmos;
use super::springs::{PathSampling, UNSETTLED_HORIZON, settle_label};
use crate::camera::{BlendTrack, BlendTranslation, BlendTranslationSpring, VirtualCamera};
use crate::spring::{SpringAsleep, SpringMotion};

/// How wide a shot's frame is drawn, in markers ([`CameraRigGizmos::size`]); it is 2:3 high.
const FRAME: f32 = 3.0;

/// What the group reads of a blending camera.
type Blending = (
    &'static GlobalTransform,
    &'static BlendTrack,
    &'static BlendTranslationSpring,
    &'static SpringMotion<BlendTranslation>,
    Has<SpringAsleep<BlendTranslation>>,
);

/// Draws each [`VirtualCamera`] as a frame facing where it looks, with its priority: gold for
/// the shot a blending camera shows, grey for the others (not one a camera is at: it would be
/// seen from inside); and, while a camera blends to its
/// shot, the path it will take there (exact, from its blend's forecast, for a shot that holds
/// still) and the seconds left.
pub(super) fn draw_shots(
    mut gizmos: Gizmos<CameraRigGizmos>,
    shots: Query<(Entity, &VirtualCamera, &GlobalTransform, &Transform)>,
    cameras: Query<Blending>,
) {
    let options = *gizmos.config_ext;
    let showing: Vec<Entity> = cameras.iter().filter_map(|(_, t, ..)| t.shot()).collect();
    let frame = Vec2::new(FRAME, FRAME * 2.0 / 3.0) * options.size;
    for (entity, shot, global, _) in &shots {
        // A shot a camera is at is seen from inside: its frame would only clutter the view.
        let seen_from = cameras
            .iter()
            .any(|(eye, ..)| eye.translation().distance(global.translation()) < frame.x);
        if seen_from {
            continue;
        }
        let live = showing.contains(&entity);
        let color = if live { css::GOLD } else { css::GRAY };
        let pose = Isometry3d::new(global.translation(), global.rotation());
        gizmos.rect(pose, frame, color);
        gizmos.arrow(
            global.translation(),
            global.translation() + global.forward() * options.size * FRAME,
            color,
        );
        let label = format!("{}{}", shot.priority, if live { " live" } else { "" });
        let corner = global.translation() + global.rotation() * (frame * 0.5).extend(0.0);
        gizmos.text(
            Isometry3d::new(corner, global.rotation()),
            &label,
            options.size * 1.5,
            Vec2::new(-0.5, -0.5),
            color,
        );
    }
    for (_, track, spring, motion, asleep) in &cameras {
        let Some(shot) = track.shot().and_then(|shot| shots.get(shot).ok()) else {
            continue;
        };
        if asleep {
            continue;
        }
        // The camera is the shot plus the blend's offset, which springs to zero (both in the
        // space of their `Transform`s, as the blend writes them).
        let (at, rotation) = (shot.3.translation, shot.2.rotation());
        let forecast = spring.forecast(motion);
        let settle = forecast.settle_time();
        let sampling = PathSampling::over(settle.unwrap_or(UNSETTLED_HORIZON), 1.0 / 60.0);
        let path = core::iter::once(forecast.value_at(0.0))
            .chain(forecast.samples(sampling.step, sampling.count))
            .map(|offset| at + offset);
        gizmos.linestrip(path, css::AQUA);
        let here = at + forecast.value_at(0.0);
        settle_label(&mut gizmos, here, rotation, settle, options.size * 1.5);
    }
}
