//! The camera group: each rig's guides, drawn in the world where they act.

use bevy::color::palettes::css;
use bevy::gizmos::config::GizmoConfigGroup;
use bevy::prelude::*;

use crate::camera::{
    CameraFraming, CameraGoal, CameraTargets, Confiner, ConfinerVolume, GroupFraming, HardLimit,
    OrbitRig, RailMotion, RailState, RigMotion,
};

/// The camera group of the [debug overlay](super): for each
/// [`CameraRig`](crate::camera::CameraRig), Cinemachine's guides drawn in the world where
/// they act:
/// - the dead zone around the held point (green while the framed point moves inside it,
///   orange while it pushes an edge and the camera follows);
/// - the framed point (a ring), the goal (a cross) and the look-ahead between them;
/// - the view the camera is heading for (its centre and extent at the framed point);
/// - the hard limit around the point the camera looks at, and within it the band where the
///   target starts to carry the camera;
/// - the confiner's bounds, and within them the band where the camera slows;
/// - a camera's rail, with a ring where the camera is on it and a cross where it is going;
/// - each target with its radius and, with group framing, the extent the zoom fits;
/// - the orbit sphere, and the ray an occluder is looked for on (red while one pulls
///   the camera in);
/// - every shot ([`VirtualCamera`](crate::camera::VirtualCamera)) as a frame facing where it
///   looks, with its priority (gold for the one a blending camera shows), and the path a
///   blending camera will take to its shot with the seconds left.
///
/// Turn it on or off, and set its line width, through
/// [`GizmoConfigStore`](bevy::gizmos::config::GizmoConfigStore).
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Default)]
pub struct CameraRigGizmos {
    /// The size of markers, in world units (pixels in 2D): 8 by default; about 0.1 suits
    /// a 3D scene in metres.
    pub size: f32,
    /// Draw the view the camera is heading for.
    pub view: bool,
    /// Draw the targets and the group's extent.
    pub targets: bool,
}

impl Default for CameraRigGizmos {
    fn default() -> Self {
        Self {
            size: 8.0,
            view: true,
            targets: true,
        }
    }
}

impl GizmoConfigGroup for CameraRigGizmos {}

/// What the camera group reads of a rig.
type Rig = (
    &'static CameraFraming,
    &'static CameraGoal,
    &'static GlobalTransform,
    &'static RigMotion,
    Option<&'static Confiner>,
    Option<&'static ConfinerVolume>,
    Option<&'static CameraTargets>,
    Option<&'static GroupFraming>,
    Has<OrbitRig>,
    Option<&'static HardLimit>,
    Option<(&'static RailState, &'static RailMotion)>,
);

/// Draws every rig's guides.
pub(super) fn draw_rigs(
    mut gizmos: Gizmos<CameraRigGizmos>,
    rigs: Query<Rig>,
    globals: Query<&GlobalTransform>,
) {
    let options = *gizmos.config_ext;
    for (framing, goal, camera, motion, confiner, volume, targets, group, orbit, limit, rail) in
        &rigs
    {
        let facing = camera.rotation();
        let plane = |centre: Vec3| Isometry3d::new(centre, facing);
        draw_dead_zone(&mut gizmos, framing);
        let point = framing.point();
        gizmos.circle(plane(point), options.size, css::WHITE);
        gizmos.cross(plane(framing.goal()), options.size * 0.75, css::WHITE);
        if point.distance_squared(framing.goal()) > 0.0 {
            gizmos.arrow(framing.goal(), point, css::LIGHT_SKY_BLUE);
        }
        if options.view && framing.half_view() != Vec2::ZERO {
            gizmos.rect(
                plane(framing.centre()),
                2.0 * framing.half_view(),
                css::SLATE_GRAY,
            );
        }
        if let Some(limit) = limit {
            let (half, slowing) = limit.in_world(framing.half_view());
            // Where the camera looks, at the framed point's depth.
            let forward = camera.forward();
            let looked_at =
                camera.translation() + forward * (point - camera.translation()).dot(*forward);
            draw_limit(&mut gizmos, plane(looked_at), half, slowing);
        }
        if let Some((state, rail_motion)) = rail {
            draw_rail(&mut gizmos, state, rail_motion.distance(), options.size);
        }
        if let Some(confiner) = confiner {
            draw_bounds(
                &mut gizmos,
                confiner.bounds,
                point.z,
                confiner.slowing_distance,
            );
        }
        if let Some(volume) = volume {
            draw_volume(&mut gizmos, volume);
        }
        if options.targets {
            for target in targets.iter().flat_map(|targets| &targets.targets) {
                if let Ok(at) = globals.get(target.entity) {
                    let radius = target.radius.max(options.size * 0.5);
                    gizmos.circle(plane(at.translation()), radius, css::KHAKI);
                }
            }
            if group.is_some() && goal.spread != Vec2::ZERO {
                gizmos.rect(plane(goal.point), 2.0 * goal.spread, css::KHAKI);
            }
        }
        let eye = camera.translation();
        if orbit {
            let focus = framing.centre();
            gizmos
                .sphere(
                    Isometry3d::from_translation(focus),
                    eye.distance(focus),
                    css::DARK_SLATE_GRAY,
                )
                .resolution(24);
        }
        let clear = motion.clearance() >= 1.0;
        if orbit || !clear {
            gizmos.line(point, eye, if clear { css::DIM_GRAY } else { css::RED });
        }
    }
}

/// The dead zone: a box of the zone's half extents around its centre (a rectangle seen from a
/// 2D camera), and a cross on its anchor, the held point.
fn draw_dead_zone(gizmos: &mut Gizmos<CameraRigGizmos>, framing: &CameraFraming) {
    let half = framing.dead_zone();
    if half == Vec3::ZERO {
        return;
    }
    let color = if framing.pushes_dead_zone() {
        css::ORANGE
    } else {
        css::LIME
    };
    gizmos.cube(
        Transform::from_translation(framing.dead_zone_centre()).with_scale(2.0 * half),
        color,
    );
    gizmos.cross(
        Isometry3d::from_translation(framing.held()),
        half.min_element().max(1e-3) * 0.25,
        color,
    );
}

/// A hard limit of half extents `half` placed at `at`, and the band `slowing` wide inside it.
fn draw_limit(gizmos: &mut Gizmos<CameraRigGizmos>, at: Isometry3d, half: Vec2, slowing: f32) {
    if half != Vec2::ZERO {
        draw_banded(
            gizmos,
            at,
            2.0 * half,
            slowing,
            [css::TOMATO, css::DARK_SALMON],
        );
    }
}

/// A rectangle `size` placed at `at` in `colors[0]`, and in `colors[1]` the edge of the band
/// `slowing` wide inside it (when there is room for one).
fn draw_banded(
    gizmos: &mut Gizmos<CameraRigGizmos>,
    at: Isometry3d,
    size: Vec2,
    slowing: f32,
    [outer, inner]: [Srgba; 2],
) {
    gizmos.rect(at, size, outer);
    let within = size - Vec2::splat(2.0 * slowing);
    if slowing > 0.0 && within.cmpgt(Vec2::ZERO).all() {
        gizmos.rect(at, within, inner);
    }
}

/// A camera's rail, a ring where the camera is on it and a cross where it springs to.
fn draw_rail(gizmos: &mut Gizmos<CameraRigGizmos>, state: &RailState, distance: f32, size: f32) {
    let Some(track) = state.track() else {
        return;
    };
    gizmos.linestrip(track.points().iter().copied(), css::TEAL);
    let at = |distance: f32| Isometry3d::from_translation(track.position_at(distance));
    gizmos.sphere(at(distance), size, css::AQUAMARINE);
    if let Some(goal) = state.goal() {
        gizmos.cross(at(goal), size * 0.75, css::AQUAMARINE);
    }
}

/// A confiner's bounds in the plane `z`, and the band `slowing` wide inside them.
fn draw_bounds(gizmos: &mut Gizmos<CameraRigGizmos>, bounds: Rect, z: f32, slowing: f32) {
    let at = Isometry3d::from_translation(bounds.center().extend(z));
    draw_banded(
        gizmos,
        at,
        bounds.size(),
        slowing,
        [css::CRIMSON, css::DARK_RED],
    );
}

/// A confiner volume, and the band `slowing_distance` wide inside it.
fn draw_volume(gizmos: &mut Gizmos<CameraRigGizmos>, volume: &ConfinerVolume) {
    let box_of =
        |min: Vec3, max: Vec3| Transform::from_translation((min + max) * 0.5).with_scale(max - min);
    gizmos.cube(box_of(volume.min, volume.max), css::CRIMSON);
    let slowing = Vec3::splat(volume.slowing_distance.max(0.0));
    let (min, max) = (volume.min + slowing, volume.max - slowing);
    if volume.slowing_distance > 0.0 && min.cmplt(max).all() {
        gizmos.cube(box_of(min, max), css::DARK_RED);
    }
}
