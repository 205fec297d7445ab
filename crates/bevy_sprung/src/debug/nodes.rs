//! The UI group: springs on UI nodes, drawn in the nodes' own space (pixels of the viewport)
//! over the view of the camera their UI is on.

use bevy::color::palettes::css;
use bevy::gizmos::config::GizmoConfigGroup;
use bevy::prelude::*;

use super::springs::{PathSampling, UNSETTLED_HORIZON, settle_label};
use super::throws::REST_HORIZON;
#[cfg(feature = "picking")]
use super::throws::{LINE_REACH, LimitsView, ThrowLimits, draw_limits};
use super::ui_space::{NodeParts, ShownNode, UiNodes};
use crate::spring::{SpringAsleep, SpringForecast, SpringMotion};
use crate::ui::{
    LayoutOffset, LayoutScale, LayoutScaleSpring, LayoutSpring, LayoutTranslation,
    LayoutTranslationSpring, MomentumScroll, ScrollExtent, ScrollOffset, ScrollOffsetSpring,
    UiTransformTranslation, UiTransformTranslationSpring,
};

/// The UI group of the [debug overlay](super), drawn in each node's own space (its pixels on
/// screen) over the view of the camera its UI is on:
///
/// - each `UiTransform` translation spring's target (a cross), the exact path its centre will
///   take to rest and the seconds left, and a ring when it sleeps;
/// - each [`LayoutSpring`] node in flight: its box where it is drawn (aqua) and where layout
///   puts it (gold), the path its centre will take between them, and the seconds left;
/// - each [`MomentumScroll`] area: its box (yellow), how far past it the content can be
///   pulled (dim), the content's extent where it is shown (aqua) and, while it moves, where
///   it will come to rest (magenta, with a double ring where the content now at the area's
///   centre will stop);
/// - with the `picking` feature, each UI [`SpringDrag`](crate::interaction::SpringDrag)'s
///   bounds, their give, and the points, lines or grid it snaps to.
///
/// Sizes are in logical pixels, whatever the camera: the group draws the same in a 2D and a 3D
/// app. Turn it on or off through [`GizmoConfigStore`](bevy::gizmos::config::GizmoConfigStore).
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Default)]
pub struct UiSpringGizmos {
    /// The size of markers and labels, in logical pixels: 8 by default.
    pub size: f32,
    /// Draw the paths to rest.
    pub path: bool,
    /// Draw the seconds left until a spring settles.
    pub settle_time: bool,
    /// The time step the paths are sampled at, in seconds (a frame at 60 fps by default).
    pub path_step: f32,
    /// How many grid points are drawn each way around a drag that snaps to a grid.
    pub grid_reach: u8,
}

impl Default for UiSpringGizmos {
    fn default() -> Self {
        Self {
            size: 8.0,
            path: true,
            settle_time: true,
            path_step: 1.0 / 60.0,
            grid_reach: 3,
        }
    }
}

impl GizmoConfigGroup for UiSpringGizmos {}

/// Draws every `UiTransform` translation spring.
pub(super) fn draw_translations(
    mut gizmos: Gizmos<UiSpringGizmos>,
    springs: Query<(
        &UiTransformTranslationSpring,
        &SpringMotion<UiTransformTranslation>,
        NodeParts,
        Has<SpringAsleep<UiTransformTranslation>>,
    )>,
    nodes: UiNodes,
) {
    let options = *gizmos.config_ext;
    for (spring, motion, parts, asleep) in &springs {
        let Some(node) = nodes.shown(&parts) else {
            continue;
        };
        let facing = node.frame.facing;
        let marker = node.marker(options.size);
        let here = node.world(node.centre());
        if asleep {
            gizmos.circle(Isometry3d::new(here, facing), marker, css::GRAY);
            continue;
        }
        // The translation moves the centre along the parent's axes, from where it is drawn.
        let forecast = spring.forecast(motion);
        let now = node.resolve(forecast.value_at(0.0));
        let at = |value: Val2| {
            node.world(node.centre() + node.parent_axes * (node.resolve(value) - now))
        };
        gizmos.cross(
            Isometry3d::new(at(forecast.target()), facing),
            marker,
            css::GOLD,
        );
        let settle = forecast.settle_time();
        if options.path {
            let sampling =
                PathSampling::over(settle.unwrap_or(UNSETTLED_HORIZON), options.path_step);
            gizmos.linestrip(
                core::iter::once(here)
                    .chain(forecast.samples(sampling.step, sampling.count).map(at)),
                css::AQUA,
            );
        }
        if options.settle_time {
            settle_label(&mut gizmos, node.beside(), facing, settle, marker * 1.5);
        }
    }
}

/// Draws every layout spring in flight: its box now and at its place, and the way between.
pub(super) fn draw_layouts(
    mut gizmos: Gizmos<UiSpringGizmos>,
    layouts: Query<
        (
            &LayoutOffset,
            &LayoutTranslationSpring,
            &SpringMotion<LayoutTranslation>,
            &LayoutScaleSpring,
            &SpringMotion<LayoutScale>,
            NodeParts,
        ),
        With<LayoutSpring>,
    >,
    nodes: UiNodes,
) {
    let options = *gizmos.config_ext;
    for (offset, translation, moving, scale, growing, parts) in &layouts {
        if *offset == LayoutOffset::ZERO {
            continue;
        }
        let Some(node) = nodes.shown(&parts) else {
            continue;
        };
        // Drawn = placed, shifted by the offset along the parent's axes and scaled by it about
        // the centre: undo both for the place.
        let drawn_axes = node.global.matrix2;
        let place = node.centre() - node.parent_axes * offset.translation;
        let place_axes = drawn_axes * Mat2::from_diagonal(offset.scale().recip());
        gizmos.linestrip(
            node.outline(node.centre(), drawn_axes, node.size),
            css::AQUA,
        );
        gizmos.linestrip(node.outline(place, place_axes, node.size), css::GOLD);
        let forecast = translation.forecast(moving);
        let settle = later(
            forecast.settle_time(),
            scale.forecast(growing).settle_time(),
        );
        if options.path {
            let sampling =
                PathSampling::over(settle.unwrap_or(UNSETTLED_HORIZON), options.path_step);
            let at = |offset: Vec2| node.world(place + node.parent_axes * offset);
            gizmos.linestrip(
                core::iter::once(forecast.value_at(0.0))
                    .chain(forecast.samples(sampling.step, sampling.count))
                    .map(at),
                css::AQUA,
            );
        }
        if options.settle_time {
            let marker = node.marker(options.size);
            let facing = node.frame.facing;
            settle_label(&mut gizmos, node.beside(), facing, settle, marker * 1.5);
        }
    }
}

/// The later of two settle times (`None`, never, if either is).
fn later(a: Option<f32>, b: Option<f32>) -> Option<f32> {
    Some(a?.max(b?))
}

/// Draws every scroll area: its box, the give past it, the content where it is shown, and
/// where a moving scroll will rest.
pub(super) fn draw_scrolls(
    mut gizmos: Gizmos<UiSpringGizmos>,
    areas: Query<(
        &MomentumScroll,
        &ScrollExtent,
        &ScrollPosition,
        &ScrollOffsetSpring,
        &SpringMotion<ScrollOffset>,
        NodeParts,
        Has<SpringAsleep<ScrollOffset>>,
    )>,
    nodes: UiNodes,
) {
    let options = *gizmos.config_ext;
    for (scroll, extent, position, spring, motion, parts, asleep) in &areas {
        let Some(node) = nodes.shown(&parts) else {
            continue;
        };
        let area = ScrollArea {
            node,
            max: extent.max(),
        };
        let axes = node.global.matrix2;
        gizmos.linestrip(node.outline(node.centre(), axes, node.size), css::YELLOW);
        let give = Vec2::select(
            area.max.cmpgt(Vec2::ZERO),
            Vec2::splat(2.0 * scroll.give * node.scale_factor),
            Vec2::ZERO,
        );
        gizmos.linestrip(
            node.outline(node.centre(), axes, node.size + give),
            css::YELLOW.with_alpha(0.35),
        );
        let shown = position.0 + extent.shown_past();
        gizmos.linestrip(area.content_at(shown), css::AQUA.with_alpha(0.6));
        if asleep {
            continue;
        }
        let rest = area.rest(&spring.forecast(motion));
        gizmos.linestrip(area.content_at(rest), css::MAGENTA);
        // The content now at the area's centre comes to rest here.
        let stop = node.world(node.centre() + axes * ((shown - rest) * node.scale_factor));
        let marker = node.marker(options.size);
        let facing = node.frame.facing;
        gizmos.circle(Isometry3d::new(stop, facing), marker, css::MAGENTA);
        gizmos.circle(Isometry3d::new(stop, facing), marker * 0.5, css::MAGENTA);
    }
}

/// A scroll area on screen and how far it scrolls.
struct ScrollArea {
    node: ShownNode,
    /// The largest scroll position, in logical pixels.
    max: Vec2,
}

impl ScrollArea {
    /// The outline of the content scrolled to `position` (logical pixels): the area's box
    /// grown by the scroll range, its top-left corner `position` before the area's.
    fn content_at(&self, position: Vec2) -> [Vec3; 5] {
        let node = &self.node;
        let range = self.max * node.scale_factor;
        let centre =
            node.centre() + node.global.matrix2 * (0.5 * range - position * node.scale_factor);
        node.outline(centre, node.global.matrix2, node.size + range)
    }

    /// Where a scroll moving as `forecast` says comes to rest: the end of its exact future,
    /// inside the range (a coast that would pass an end springs back to it).
    fn rest(&self, forecast: &SpringForecast<ScrollOffset>) -> Vec2 {
        let end = forecast.settle_time().unwrap_or(REST_HORIZON);
        forecast.value_at(end).clamp(Vec2::ZERO, self.max)
    }
}

/// Draws the bounds and snap targets of every drag on a UI node.
#[cfg(feature = "picking")]
pub(super) fn draw_drags(
    mut gizmos: Gizmos<UiSpringGizmos>,
    drags: Query<
        (&crate::interaction::SpringDrag, &UiTransform, NodeParts),
        With<UiTransformTranslationSpring>,
    >,
    nodes: UiNodes,
) {
    let options = *gizmos.config_ext;
    for (drag, transform, parts) in &drags {
        let Some(node) = nodes.shown(&parts) else {
            continue;
        };
        // A drag's positions are the translation in logical pixels: offsets from the one now
        // drawn, along the parent's axes.
        let here = crate::interaction::pixels(transform.translation);
        let view = LimitsView {
            to_world: |point: Vec3| {
                let moved = (point - here).truncate() * node.scale_factor;
                node.world(node.centre() + node.parent_axes * moved)
            },
            marker: node.marker(options.size),
            facing: node.frame.facing,
            grid_reach: options.grid_reach,
            line_reach: options.size * LINE_REACH,
        };
        let limits = ThrowLimits {
            bounds: drag.bounds,
            snap: &drag.snap,
        };
        draw_limits(&mut gizmos, &limits, here, &view);
    }
}
