//! UI properties: `UiTransform` and `Node` geometry, in the units they are laid out in.
//!
//! `Node` fields and `UiTransform::translation` are `Val`s. Their springs move the number of
//! each field in the unit the field has (`Px`, `Percent`, `Vw`, `Vh`, `VMin` or `VMax`), as a
//! tween between two values of one unit would: a `left: Val::Percent(10.0)` sprung to `50.0`
//! slides to 50 %. Units are not converted into one another (that needs the layout), so the
//! target is in the field's unit; an `Auto` field is read as 0 and written in pixels.

use bevy::math::{Rot2, Vec2};
use bevy::prelude::*;
use bevy::reflect::TypePath;
use sprung::RestThreshold;

use crate::component::PropertySpring;
use crate::property::{LinearProperty, SpringProperty};

/// The number of a length in its own unit (pixels for `Px`, percent for `Percent`, …); 0 for
/// `Auto`.
#[inline]
fn number(value: Val) -> f32 {
    match value {
        Val::Px(n) | Val::Percent(n) | Val::Vw(n) | Val::Vh(n) | Val::VMin(n) | Val::VMax(n) => n,
        Val::Auto => 0.0,
    }
}

/// `number` in the unit of `old`, the field it replaces (pixels where `old` is `Auto`).
#[inline]
fn in_unit_of(old: Val, number: f32) -> Val {
    match old {
        Val::Px(_) | Val::Auto => Val::Px(number),
        Val::Percent(_) => Val::Percent(number),
        Val::Vw(_) => Val::Vw(number),
        Val::Vh(_) => Val::Vh(number),
        Val::VMin(_) => Val::VMin(number),
        Val::VMax(_) => Val::VMax(number),
    }
}

/// Writes `value` into the length `field`, keeping its unit.
#[inline]
fn set_length(field: &mut Val, value: f32) {
    *field = in_unit_of(*field, value);
}

/// A twentieth of a unit, moving slower than half a unit per second: invisible in pixels, and
/// about a pixel in the relative units (a percent of a 1920-pixel parent is 19 pixels), where
/// half a pixel's tolerance would snap visibly.
fn length_rest() -> RestThreshold<f32> {
    RestThreshold::new(0.05, 0.5)
}

/// `UiTransform::translation`, each axis in its own unit: moves a node without relayout (a hover
/// lift, a slide-in).
///
/// Like every `Val` property here, it springs the number of each field in the unit the field
/// has (`Px`, `Percent`, `Vw`, `Vh`, `VMin` or `VMax`), as a tween between two values of one
/// unit would: an axis at `Val::Percent(10.0)` sprung to `50.0` slides to 50 %. Units are not
/// converted into one another (that needs the layout), so the target is in the field's unit; an
/// `Auto` field is read as 0 and written in pixels.
#[derive(TypePath, Debug, Clone, Copy)]
pub struct UiTransformTranslation;

impl LinearProperty for UiTransformTranslation {
    type Component = UiTransform;
    type Value = Vec2;

    fn default_rest() -> RestThreshold<f32> {
        length_rest()
    }

    #[inline]
    fn get(transform: &UiTransform) -> Vec2 {
        Vec2::new(
            number(transform.translation.x),
            number(transform.translation.y),
        )
    }

    #[inline]
    fn set(transform: &mut UiTransform, value: Vec2) {
        set_length(&mut transform.translation.x, value.x);
        set_length(&mut transform.translation.y, value.y);
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
    ($(#[$doc:meta])* $name:ident, $alias:ident, $value:ty, never_through_zero: $never:expr, |$n:ident| $get:expr, |$m:ident, $v:ident| $set:expr) => {
        $(#[$doc])*
        #[derive(TypePath, Debug, Clone, Copy)]
        pub struct $name;

        impl LinearProperty for $name {
            type Component = Node;
            type Value = $value;
            const NEVER_THROUGH_ZERO: bool = $never;

            fn default_rest() -> RestThreshold<f32> {
                length_rest()
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
    /// `Node::width` and `Node::height`, each in its own unit as for [`UiTransformTranslation`]
    /// (a panel that grows). Sizes do not
    /// pass through zero: a panel that collapses with a bounce stops at 0 instead of going
    /// negative.
    NodeSize, NodeSizeSpring, Vec2, never_through_zero: true,
    |node| Vec2::new(number(node.width), number(node.height)),
    |node, size| { set_length(&mut node.width, size.x); set_length(&mut node.height, size.y) }
);
node_property!(
    /// `Node::left` and `Node::top`, each in its own unit as for [`UiTransformTranslation`] (an
    /// absolutely positioned node that moves).
    NodePosition, NodePositionSpring, Vec2, never_through_zero: false,
    |node| Vec2::new(number(node.left), number(node.top)),
    |node, position| { set_length(&mut node.left, position.x); set_length(&mut node.top, position.y) }
);
node_property!(
    /// `Node::width` in its unit; it does not pass through zero, as [`NodeSize`].
    NodeWidth, NodeWidthSpring, f32, never_through_zero: true,
    |node| number(node.width), |node, value| set_length(&mut node.width, value)
);
node_property!(
    /// `Node::height` in its unit; it does not pass through zero, as [`NodeSize`].
    NodeHeight, NodeHeightSpring, f32, never_through_zero: true,
    |node| number(node.height), |node, value| set_length(&mut node.height, value)
);
node_property!(
    /// `Node::left` in its unit.
    NodeLeft, NodeLeftSpring, f32, never_through_zero: false,
    |node| number(node.left), |node, value| set_length(&mut node.left, value)
);
node_property!(
    /// `Node::top` in its unit.
    NodeTop, NodeTopSpring, f32, never_through_zero: false,
    |node| number(node.top), |node, value| set_length(&mut node.top, value)
);
node_property!(
    /// `Node::right` in its unit.
    NodeRight, NodeRightSpring, f32, never_through_zero: false,
    |node| number(node.right), |node, value| set_length(&mut node.right, value)
);
node_property!(
    /// `Node::bottom` in its unit.
    NodeBottom, NodeBottomSpring, f32, never_through_zero: false,
    |node| number(node.bottom), |node, value| set_length(&mut node.bottom, value)
);

/// A spring on [`UiTransformTranslation`].
pub type UiTranslationSpring = PropertySpring<UiTransformTranslation>;
/// A spring on [`UiTransformScale`].
pub type UiScaleSpring = PropertySpring<UiTransformScale>;
/// A spring on [`UiTransformRotation`].
pub type UiRotationSpring = PropertySpring<UiTransformRotation>;
