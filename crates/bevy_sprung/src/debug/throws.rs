//! The throws group: where drags and flings may go and where they will stop.

use bevy::color::palettes::css;
use bevy::gizmos::config::GizmoConfigGroup;
use bevy::prelude::*;

use super::springs::{label_rotation, parent_space};
use crate::inertia::Inertia;
use crate::spring::{SpringAsleep, SpringMotion};
use crate::throw::{DragBounds, Snap};
use crate::transform::{Translation, TranslationSpring};

/// The throws group of the [debug overlay](super): for each [`Inertia`] (and, with the
/// `picking` feature, each [`SpringDrag`](crate::interaction::SpringDrag) on a `Transform`),
/// the box it stays in and how far past it a pull can give (dim), the points, lines or grid it
/// snaps to, and, while it moves, where it will come to rest (a double ring: the end of its
/// exact future).
///
/// Drawn in the entity's parent space mapped to the world, as the springs group is. Turn it on
/// or off through [`GizmoConfigStore`](bevy::gizmos::config::GizmoConfigStore).
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Default)]
pub struct ThrowGizmos {
    /// The size of snap points and rest rings, in world units (pixels in 2D): 8 by default.
    pub size: f32,
    /// How many grid points are drawn each way around the entity, for a [`Snap::Grid`].
    pub grid_reach: u8,
}

impl Default for ThrowGizmos {
    fn default() -> Self {
        Self {
            size: 8.0,
            grid_reach: 3,
        }
    }
}

impl GizmoConfigGroup for ThrowGizmos {}

/// How far a snap line is drawn each way from its origin, in markers.
pub(super) const LINE_REACH: f32 = 200.0;
/// How far ahead a rest point is looked for when the spring does not say when it settles.
pub(super) const REST_HORIZON: f32 = 60.0;

/// What a throw may do: its bounds and snap, in the entity's parent space.
pub(super) struct ThrowLimits<'a> {
    pub(super) bounds: Option<DragBounds>,
    pub(super) snap: &'a Snap,
}

/// Draws every inertia's bounds, snap and rest point.
pub(super) fn draw_inertia(
    mut gizmos: Gizmos<ThrowGizmos>,
    throws: Query<(
        &Inertia,
        Option<&TranslationSpring>,
        Option<&SpringMotion<Translation>>,
        Option<&ChildOf>,
        Has<SpringAsleep<Translation>>,
    )>,
    globals: Query<&GlobalTransform>,
    cameras: Query<&GlobalTransform, With<Camera>>,
) {
    let facing = label_rotation(&cameras);
    for (inertia, spring, motion, parent, asleep) in &throws {
        let to_world = parent_space(parent, &globals);
        let limits = ThrowLimits {
            bounds: inertia.bounds,
            snap: &inertia.snap,
        };
        let Some((spring, motion)) = spring.zip(motion) else {
            continue;
        };
        let forecast = spring.forecast(motion);
        let here = forecast.value_at(0.0);
        let view = world_view(*gizmos.config_ext, to_world, facing);
        draw_limits(&mut gizmos, &limits, here, &view);
        if !asleep {
            let end = forecast.settle_time().unwrap_or(REST_HORIZON);
            let rest = to_world.transform_point(forecast.value_at(end));
            let size = gizmos.config_ext.size;
            gizmos.circle(Isometry3d::new(rest, facing), size, css::MAGENTA);
            gizmos.circle(Isometry3d::new(rest, facing), size * 0.5, css::MAGENTA);
        }
    }
}

/// Draws the bounds and snap targets of every drag in the world.
#[cfg(feature = "picking")]
pub(super) fn draw_drags(
    mut gizmos: Gizmos<ThrowGizmos>,
    drags: Query<(
        &crate::interaction::SpringDrag,
        &Transform,
        Option<&ChildOf>,
    )>,
    globals: Query<&GlobalTransform>,
    cameras: Query<&GlobalTransform, With<Camera>>,
) {
    let facing = label_rotation(&cameras);
    for (drag, transform, parent) in &drags {
        let limits = ThrowLimits {
            bounds: drag.bounds,
            snap: &drag.snap,
        };
        let view = world_view(*gizmos.config_ext, parent_space(parent, &globals), facing);
        draw_limits(&mut gizmos, &limits, transform.translation, &view);
    }
}

/// How the limits of a throw in a parent space are drawn in the world.
fn world_view(
    options: ThrowGizmos,
    parent: GlobalTransform,
    facing: Quat,
) -> LimitsView<impl Fn(Vec3) -> Vec3> {
    LimitsView {
        to_world: move |point| parent.transform_point(point),
        marker: options.size,
        facing,
        grid_reach: options.grid_reach,
        line_reach: options.size * LINE_REACH,
    }
}

/// How a throw's limits are drawn: where a point of its space is in the world, and the
/// markers' look.
pub(super) struct LimitsView<F: Fn(Vec3) -> Vec3> {
    /// A point of the throw's space (its parent's, or a UI node's translation) in the world.
    pub(super) to_world: F,
    /// The size of a snap point's ring, in the world.
    pub(super) marker: f32,
    /// The rotation rings are drawn with (facing the camera).
    pub(super) facing: Quat,
    /// How many grid points are drawn each way around the entity.
    pub(super) grid_reach: u8,
    /// How far a snap line is drawn each way from its origin, in the throw's space.
    pub(super) line_reach: f32,
}

/// The bounds (and their give) and the snap targets near `here`, from the throw's space.
pub(super) fn draw_limits<G: GizmoConfigGroup>(
    gizmos: &mut Gizmos<G>,
    limits: &ThrowLimits<'_>,
    here: Vec3,
    view: &LimitsView<impl Fn(Vec3) -> Vec3>,
) {
    let world = &view.to_world;
    if let Some(bounds) = limits.bounds {
        let (low, high) = (bounds.min.min(bounds.max), bounds.max.max(bounds.min));
        draw_box(gizmos, low, high, here.z, world, css::YELLOW);
        if bounds.give > 0.0 {
            let give = Vec3::splat(bounds.give);
            let dim = css::YELLOW.with_alpha(0.35);
            draw_box(gizmos, low - give, high + give, here.z, world, dim);
        }
    }
    let point = |gizmos: &mut Gizmos<G>, at: Vec3| {
        gizmos.circle(
            Isometry3d::new(world(at), view.facing),
            view.marker * 0.6,
            css::DEEP_SKY_BLUE,
        );
    };
    match limits.snap {
        Snap::Free | Snap::Home => {}
        Snap::Points(points) => {
            for &at in points {
                point(gizmos, at);
            }
        }
        Snap::Lines(lines) => {
            for line in lines {
                let reach = line.direction.normalize_or_zero() * view.line_reach;
                gizmos.line(
                    world(line.origin - reach),
                    world(line.origin + reach),
                    css::DEEP_SKY_BLUE,
                );
            }
        }
        Snap::Grid { spacing, .. } => {
            // The grid points around the one nearest the entity, in the x–y plane.
            let reach = i32::from(view.grid_reach);
            let nearest = limits.snap.choose(here, here).0;
            for i in -reach..=reach {
                for j in -reach..=reach {
                    point(
                        gizmos,
                        nearest + Vec3::new(i as f32 * spacing.x, j as f32 * spacing.y, 0.0),
                    );
                }
            }
        }
    }
}

/// An axis-aligned box of the throw's space in the world; flat (a rectangle at `z`) if its
/// depth is not finite or zero, as a 2D bound is.
fn draw_box<G: GizmoConfigGroup>(
    gizmos: &mut Gizmos<G>,
    low: Vec3,
    high: Vec3,
    z: f32,
    world: impl Fn(Vec3) -> Vec3,
    color: impl Into<Color> + Copy,
) {
    let flat = !(high.z - low.z).is_finite() || high.z <= low.z;
    let (low, high) = if flat {
        (low.with_z(z), high.with_z(z))
    } else {
        (low, high)
    };
    let corners = [
        Vec3::new(low.x, low.y, low.z),
        Vec3::new(high.x, low.y, low.z),
        Vec3::new(high.x, high.y, low.z),
        Vec3::new(low.x, high.y, low.z),
    ];
    gizmos.linestrip(
        corners.iter().chain(&corners[..1]).map(|&c| world(c)),
        color,
    );
    if !flat {
        let depth = Vec3::Z * (high.z - low.z);
        gizmos.linestrip(
            corners
                .iter()
                .chain(&corners[..1])
                .map(|&c| world(c + depth)),
            color,
        );
        for &c in &corners {
            gizmos.line(world(c), world(c + depth), color);
        }
    }
}
