//! UI space in the world: where a point of a UI node's frame (physical pixels from the top-left
//! of its camera's viewport) is, so that world gizmos draw over the node.

use bevy::ecs::query::QueryData;
use bevy::ecs::system::SystemParam;
use bevy::math::{Affine2, Affine3A};
use bevy::prelude::*;
use bevy::ui::{ComputedUiRenderTargetInfo, ComputedUiTargetCamera, UiGlobalTransform};

/// Where points of one camera's UI are in the world: on a plane facing the camera, inside its
/// view volume, so that a gizmo drawn there covers the pixel the UI point is drawn at.
#[derive(Debug, Clone, Copy)]
pub(super) struct UiFrame {
    /// The viewport's size in physical pixels.
    size: Vec2,
    /// The inverse of the camera's projection.
    view_from_clip: Mat4,
    /// The camera's transform.
    world_from_view: Affine3A,
    /// The camera's rotation: markers and labels face it.
    pub(super) facing: Quat,
}

impl UiFrame {
    /// The depth, in normalised device coordinates, the UI is drawn at. Bevy's projections are
    /// reversed (1 at the near plane), so this is twice the near plane's distance for a
    /// perspective camera and halfway between near and far for an orthographic one: inside
    /// the view either way.
    const DEPTH: f32 = 0.5;

    /// The world point drawn at `pixel` of the viewport (physical pixels, y down).
    pub(super) fn point(&self, pixel: Vec2) -> Vec3 {
        let ndc = Vec2::new(
            pixel.x / self.size.x * 2.0 - 1.0,
            1.0 - pixel.y / self.size.y * 2.0,
        );
        let view = self.view_from_clip.project_point3(ndc.extend(Self::DEPTH));
        self.world_from_view.transform_point3(view)
    }

    /// How long `pixels` physical pixels at `pixel` are in the world (a marker's size).
    pub(super) fn length(&self, pixel: Vec2, pixels: f32) -> f32 {
        self.point(pixel)
            .distance(self.point(pixel + Vec2::X * pixels))
    }
}

/// What places a UI node on screen, as a query reads it.
#[derive(QueryData)]
pub(super) struct NodeParts {
    node: &'static ComputedNode,
    global: &'static UiGlobalTransform,
    camera: &'static ComputedUiTargetCamera,
    target: &'static ComputedUiRenderTargetInfo,
    parent: Option<&'static ChildOf>,
}

/// A UI node where it is drawn this frame, and where its camera draws UI space.
#[derive(Debug, Clone, Copy)]
pub(super) struct ShownNode {
    /// Its camera's UI space in the world.
    pub(super) frame: UiFrame,
    /// Its drawn transform: its centre and axes, in physical pixels.
    pub(super) global: Affine2,
    /// Its laid-out size, in physical pixels.
    pub(super) size: Vec2,
    /// The drawn axes of its parent, which its translation and layout offset move along.
    pub(super) parent_axes: Mat2,
    /// Physical pixels per logical pixel.
    pub(super) scale_factor: f32,
    /// Its viewport's size in physical pixels (what `Val::Vw` and `Val::Vh` are of).
    pub(super) viewport: Vec2,
}

impl ShownNode {
    /// Its centre on screen, in physical pixels.
    pub(super) fn centre(&self) -> Vec2 {
        self.global.translation
    }

    /// The world point at `pixel` (physical pixels).
    pub(super) fn world(&self, pixel: Vec2) -> Vec3 {
        self.frame.point(pixel)
    }

    /// How long `logical` logical pixels are in the world, at the node.
    pub(super) fn marker(&self, logical: f32) -> f32 {
        self.frame
            .length(self.centre(), logical * self.scale_factor)
    }

    /// `value` in physical pixels, resolved as `bevy_ui` resolves the node's translation
    /// (percentages of its own size).
    pub(super) fn resolve(&self, value: Val2) -> Vec2 {
        value.resolve(self.scale_factor, self.size, self.viewport)
    }

    /// The closed outline of a box `size` big with its centre at `centre` and axes `axes`
    /// (physical pixels), in the world, drawn [`OUTSET`] outside its edges.
    pub(super) fn outline(&self, centre: Vec2, axes: Mat2, size: Vec2) -> [Vec3; 5] {
        let outset = OUTSET * self.scale_factor;
        let grow = Vec2::new(
            outset / axes.x_axis.length().max(f32::MIN_POSITIVE),
            outset / axes.y_axis.length().max(f32::MIN_POSITIVE),
        );
        let half = 0.5 * size + grow;
        let corner = |x: f32, y: f32| self.world(centre + axes * Vec2::new(x, y));
        [
            corner(-half.x, -half.y),
            corner(half.x, -half.y),
            corner(half.x, half.y),
            corner(-half.x, half.y),
            corner(-half.x, -half.y),
        ]
    }

    /// Where a label about the node goes: just right of its drawn box, halfway down, where
    /// the node itself does not cover it.
    pub(super) fn beside(&self) -> Vec3 {
        let edge = self.global.matrix2 * Vec2::new(0.5 * self.size.x, 0.0);
        let outset = Vec2::X * OUTSET * self.scale_factor;
        self.world(self.centre() + edge + outset)
    }
}

/// How far outside a node's edges its boxes are drawn, in logical pixels: gizmos are drawn
/// under the UI, so a line on the edge would be half covered by the node's background.
const OUTSET: f32 = 2.0;

/// The cameras UI is drawn by and the nodes' transforms: what puts a node on screen.
#[derive(SystemParam)]
pub(super) struct UiNodes<'w, 's> {
    cameras: Query<'w, 's, (&'static Camera, &'static GlobalTransform)>,
    globals: Query<'w, 's, &'static UiGlobalTransform>,
}

impl UiNodes<'_, '_> {
    /// Where `parts`' node is drawn, if it is on a camera with a viewport (a node of no
    /// camera, or of one not rendering yet, is not drawn).
    pub(super) fn shown(&self, parts: &NodePartsItem<'_, '_>) -> Option<ShownNode> {
        let (camera, transform) = self.cameras.get(parts.camera.get()?).ok()?;
        let viewport = parts.target.physical_size().as_vec2();
        let view_from_clip = camera.clip_from_view().inverse();
        if viewport.min_element() <= 0.0 || !view_from_clip.is_finite() {
            return None;
        }
        let parent_axes = parts
            .parent
            .and_then(|parent| self.globals.get(parent.parent()).ok())
            .map_or(Mat2::IDENTITY, |parent| parent.matrix2);
        Some(ShownNode {
            frame: UiFrame {
                size: viewport,
                view_from_clip,
                world_from_view: transform.affine(),
                facing: transform.rotation(),
            },
            global: **parts.global,
            size: parts.node.size,
            parent_axes,
            scale_factor: parts.target.scale_factor(),
            viewport,
        })
    }
}
