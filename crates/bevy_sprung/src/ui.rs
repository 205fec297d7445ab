//! UI properties: `UiTransform` and `Node` geometry, in pixels.
//!
//! `Node` fields and `UiTransform::translation` are `Val`s. These properties spring
//! `Val::Px`: a field in another unit (`Percent`, `Auto`, …) is read as 0 px and written back as
//! `Val::Px`, so spring only fields you lay out in pixels.

use bevy::math::{Rot2, Vec2};
use bevy::prelude::*;
use bevy::reflect::TypePath;
use sprung::RestThreshold;

use crate::component::PropertySpring;
use crate::property::{LinearProperty, SpringProperty};

/// The pixels of a `Val::Px`, 0 for any other unit.
#[inline]
fn px(value: Val) -> f32 {
    match value {
        Val::Px(pixels) => pixels,
        _ => 0.0,
    }
}

/// Half a pixel is invisible; a pixel per second is a crawl.
fn pixel_rest() -> RestThreshold<f32> {
    RestThreshold::new(0.5, 1.0)
}

/// `UiTransform::translation` in pixels: moves a node without relayout (a hover lift, a
/// slide-in).
#[derive(TypePath, Debug, Clone, Copy)]
pub struct UiTransformTranslation;

impl LinearProperty for UiTransformTranslation {
    type Component = UiTransform;
    type Value = Vec2;

    fn default_rest() -> RestThreshold<f32> {
        pixel_rest()
    }

    #[inline]
    fn get(transform: &UiTransform) -> Vec2 {
        Vec2::new(px(transform.translation.x), px(transform.translation.y))
    }

    #[inline]
    fn set(transform: &mut UiTransform, value: Vec2) {
        transform.translation = Val2::new(Val::Px(value.x), Val::Px(value.y));
    }
}

/// `UiTransform::scale`, kept from passing through zero like [`Scale`](crate::Scale) (a
/// button that pops to 0 lands on 0 instead of mirroring).
#[derive(TypePath, Debug, Clone, Copy)]
pub struct UiTransformScale;

impl LinearProperty for UiTransformScale {
    type Component = UiTransform;
    type Value = Vec2;
    const NEVER_THROUGH_ZERO: bool = true;

    #[inline]
    fn get(transform: &UiTransform) -> Vec2 {
        transform.scale
    }

    #[inline]
    fn set(transform: &mut UiTransform, value: Vec2) {
        transform.scale = value;
    }
}

/// `UiTransform::rotation`, the short way round, in radians (clockwise, as `UiTransform`).
#[derive(TypePath, Debug, Clone, Copy)]
pub struct UiTransformRotation;

impl SpringProperty for UiTransformRotation {
    type Component = UiTransform;
    type Value = Rot2;
    type Linear = f32;

    fn default_rest() -> RestThreshold<f32> {
        RestThreshold::new(1e-3, 1e-2)
    }

    #[inline]
    fn get(transform: &UiTransform) -> Rot2 {
        transform.rotation
    }

    #[inline]
    fn set(transform: &mut UiTransform, value: Rot2) {
        transform.rotation = value;
    }

    #[inline]
    fn is_finite(value: Rot2) -> bool {
        value.is_finite() && value.length_squared() > 0.0
    }

    /// The angle of `target⁻¹·value`, in `(−π, π]`: the short way.
    #[inline]
    fn offset(value: Rot2, target: Rot2) -> f32 {
        (target.inverse() * value).as_radians()
    }

    #[inline]
    fn at_offset(target: Rot2, offset: f32) -> Rot2 {
        (target * Rot2::radians(offset)).normalize()
    }
}

macro_rules! node_property {
    ($(#[$doc:meta])* $name:ident, $alias:ident, $value:ty, |$n:ident| $get:expr, |$m:ident, $v:ident| $set:expr) => {
        $(#[$doc])*
        #[derive(TypePath, Debug, Clone, Copy)]
        pub struct $name;

        impl LinearProperty for $name {
            type Component = Node;
            type Value = $value;

            fn default_rest() -> RestThreshold<f32> {
                pixel_rest()
            }

            #[inline]
            fn get($n: &Node) -> $value {
                $get
            }

            #[inline]
            fn set($m: &mut Node, $v: $value) {
                $set;
            }
        }

        #[doc = concat!("A spring on [`", stringify!($name), "`].")]
        pub type $alias = PropertySpring<$name>;
    };
}

node_property!(
    /// `Node::width` and `Node::height` in pixels (a panel that grows).
    NodeSize, NodeSizeSpring, Vec2,
    |node| Vec2::new(px(node.width), px(node.height)),
    |node, size| { node.width = Val::Px(size.x); node.height = Val::Px(size.y) }
);
node_property!(
    /// `Node::left` and `Node::top` in pixels (an absolutely positioned node that moves).
    NodePosition, NodePositionSpring, Vec2,
    |node| Vec2::new(px(node.left), px(node.top)),
    |node, position| { node.left = Val::Px(position.x); node.top = Val::Px(position.y) }
);
node_property!(
    /// `Node::width` in pixels.
    NodeWidth, NodeWidthSpring, f32, |node| px(node.width), |node, value| node.width = Val::Px(value)
);
node_property!(
    /// `Node::height` in pixels.
    NodeHeight, NodeHeightSpring, f32, |node| px(node.height), |node, value| node.height = Val::Px(value)
);
node_property!(
    /// `Node::left` in pixels.
    NodeLeft, NodeLeftSpring, f32, |node| px(node.left), |node, value| node.left = Val::Px(value)
);
node_property!(
    /// `Node::top` in pixels.
    NodeTop, NodeTopSpring, f32, |node| px(node.top), |node, value| node.top = Val::Px(value)
);
node_property!(
    /// `Node::right` in pixels.
    NodeRight, NodeRightSpring, f32, |node| px(node.right), |node, value| node.right = Val::Px(value)
);
node_property!(
    /// `Node::bottom` in pixels.
    NodeBottom, NodeBottomSpring, f32, |node| px(node.bottom), |node, value| node.bottom = Val::Px(value)
);

/// A spring on [`UiTransformTranslation`].
pub type UiTranslationSpring = PropertySpring<UiTransformTranslation>;
/// A spring on [`UiTransformScale`].
pub type UiScaleSpring = PropertySpring<UiTransformScale>;
/// A spring on [`UiTransformRotation`].
pub type UiRotationSpring = PropertySpring<UiTransformRotation>;
