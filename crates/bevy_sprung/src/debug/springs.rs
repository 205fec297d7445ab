//! The springs group: each translation spring's target, velocity, predicted path and settle
//! time, and the springs asleep.

use bevy::color::palettes::css;
use bevy::gizmos::config::GizmoConfigGroup;
use bevy::prelude::*;

use crate::spring::{SpringAsleep, SpringForecast, SpringMotion};
use crate::transform::{Translation, TranslationSpring};

/// The springs group of the [debug overlay](super): for each `Transform` translation spring,
/// its target (a cross), its velocity (an arrow, the distance it would cover in
/// [`velocity_seconds`](Self::velocity_seconds)), the path it will take to rest (exact, from
/// its [`SpringForecast`]) and the seconds left until it settles; a spring asleep is a grey
/// ring.
///
/// Turn it on or off, and set its line width, through
/// [`GizmoConfigStore`](bevy::gizmos::config::GizmoConfigStore).
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Default)]
pub struct SpringGizmos {
    /// The size of markers and labels, in world units (pixels in 2D): 8 by default; about
    /// 0.05 suits a 3D scene in metres.
    pub size: f32,
    /// Draw the path to rest.
    pub path: bool,
    /// Draw the seconds left until the spring settles.
    pub settle_time: bool,
    /// The velocity arrow is as long as the distance covered in this many seconds.
    pub velocity_seconds: f32,
    /// The time step the path is sampled at, in seconds (a frame at 60 fps by default); at
    /// most 1024 points are drawn, further apart for a long path.
    pub path_step: f32,
}

/// The most points a spring's predicted path is drawn with.
const MAX_PATH_POINTS: usize = 1024;

/// How far ahead the path of a spring that never settles (a moving target) is drawn, in
/// seconds.
pub(super) const UNSETTLED_HORIZON: f32 = 2.0;

impl Default for SpringGizmos {
    fn default() -> Self {
        Self {
            size: 8.0,
            path: true,
            settle_time: true,
            velocity_seconds: 0.1,
            path_step: 1.0 / 60.0,
        }
    }
}

impl GizmoConfigGroup for SpringGizmos {}

/// How a spring's future is drawn: its time step and how many points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct PathSampling {
    pub(super) step: f32,
    pub(super) count: usize,
}

impl PathSampling {
    /// The sampling of a path `seconds` long at `step` (at most [`MAX_PATH_POINTS`] points;
    /// a longer path is sampled more coarsely).
    pub(super) fn over(seconds: f32, step: f32) -> Self {
        let step = if step > 0.0 && step.is_finite() {
            step
        } else {
            SpringGizmos::default().path_step
        };
        let seconds = if seconds.is_finite() {
            seconds.max(0.0)
        } else {
            UNSETTLED_HORIZON
        };
        let wanted = (seconds / step).ceil();
        if wanted <= MAX_PATH_POINTS as f32 {
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "a whole number in 0..=MAX_PATH_POINTS"
            )]
            let count = wanted as usize;
            Self { step, count }
        } else {
            Self {
                step: seconds / MAX_PATH_POINTS as f32,
                count: MAX_PATH_POINTS,
            }
        }
    }
}

/// The predicted path of a spring in its own (parent's) space: where it is, then its value
/// at each step of `sampling`.
fn predicted_path(
    forecast: &SpringForecast<Translation>,
    sampling: PathSampling,
) -> impl Iterator<Item = Vec3> + '_ {
    core::iter::once(forecast.value_at(0.0)).chain(forecast.samples(sampling.step, sampling.count))
}

/// Draws every translation spring.
pub(super) fn draw_springs(
    mut gizmos: Gizmos<SpringGizmos>,
    springs: Query<(
        &TranslationSpring,
        &SpringMotion<Translation>,
        Option<&ChildOf>,
        Has<SpringAsleep<Translation>>,
    )>,
    globals: Query<&GlobalTransform>,
    cameras: Query<&GlobalTransform, With<Camera>>,
) {
    let options = *gizmos.config_ext;
    let size = options.size;
    let facing = label_rotation(&cameras);
    for (spring, motion, parent, asleep) in &springs {
        // The spring moves the local translation: the parent's transform puts it in the world.
        let to_world = parent_space(parent, &globals);
        let forecast = spring.forecast(motion);
        let here = to_world.transform_point(forecast.value_at(0.0));
        if asleep {
            gizmos.circle(Isometry3d::new(here, facing), size, css::GRAY);
            continue;
        }
        let target = to_world.transform_point(forecast.target());
        gizmos.cross(Isometry3d::new(target, facing), size, css::GOLD);
        let velocity = to_world
            .affine()
            .transform_vector3(forecast.velocity_at(0.0) * options.velocity_seconds);
        if velocity.length_squared() > 0.0 {
            gizmos.arrow(here, here + velocity, css::ORANGE_RED);
        }
        let settle = forecast.settle_time();
        if options.path {
            let sampling =
                PathSampling::over(settle.unwrap_or(UNSETTLED_HORIZON), options.path_step);
            gizmos.linestrip(
                predicted_path(&forecast, sampling).map(|point| to_world.transform_point(point)),
                css::AQUA,
            );
        }
        if options.settle_time {
            settle_label(&mut gizmos, here, facing, settle, size * 1.5);
        }
    }
}

/// The parent's transform, which puts a spring's local value in the world (the identity for an
/// entity without a parent, or one whose parent has no transform).
pub(super) fn parent_space(
    parent: Option<&ChildOf>,
    globals: &Query<&GlobalTransform>,
) -> GlobalTransform {
    parent
        .and_then(|parent| globals.get(parent.parent()).ok())
        .copied()
        .unwrap_or_default()
}

/// The seconds left until a spring at `here` settles (or "moving"), beside it, `size` high.
pub(super) fn settle_label<G: GizmoConfigGroup>(
    gizmos: &mut Gizmos<G>,
    here: Vec3,
    facing: Quat,
    settle: Option<f32>,
    size: f32,
) {
    let label = match settle {
        Some(seconds) => format!("{seconds:.2} s"),
        None => "moving".to_owned(),
    };
    let beside = here + facing * Vec3::new(size, size, 0.0);
    gizmos.text(
        Isometry3d::new(beside, facing),
        &label,
        size,
        Vec2::new(-0.5, -0.5),
        css::WHITE,
    );
}

/// The rotation labels are drawn with: facing the first camera, so that they read in 3D as in
/// 2D.
pub(super) fn label_rotation(cameras: &Query<&GlobalTransform, With<Camera>>) -> Quat {
    cameras
        .iter()
        .next()
        .map_or(Quat::IDENTITY, GlobalTransform::rotation)
}
