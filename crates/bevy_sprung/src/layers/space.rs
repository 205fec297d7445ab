//! How a layer's offset composes with a value, per space.

use bevy::math::{Quat, Rot2, Vec2, Vec3};

use crate::space::{
    Linear, LinearValue, NeverThroughZero, ShortestAngle, ShortestArc, SpringSpace,
};

/// A [`SpringSpace`] whose values take layers: offsets, each a vector that springs on its own,
/// applied on top of a base value.
///
/// Laws (to rounding): applying [`Layer::default()`](Default) (zero) leaves a value as it is;
/// [`remove`](Self::remove) undoes [`apply`](Self::apply): `remove(apply(v, l), l) = v`; and
/// for every space but rotations applying two layers is applying their sum, in either order.
/// Rotations compose as products, in the order the layers were added.
///
/// | Space | A layer is | Applied as |
/// |---|---|---|
/// | [`Linear<V>`] | a `V` | `value + layer` |
/// | [`NeverThroughZero<Linear<V>>`] (scale) | the logarithm of a factor per axis | `value · exp(layer)`: never through zero |
/// | [`ShortestArc`] | a rotation vector (radians) | `value · exp(layer)`, turned in the value's own axes |
/// | [`ShortestAngle`] | an angle (radians) | `value · Rot2(layer)` |
/// | `OklabColor` | an offset in Oklab and alpha | added in Oklab, kept in range |
///
/// # Example
/// A space of your own: a brightness in `[0, 1]`, layered by sums, clamped.
/// ```
/// use bevy_sprung::layers::LayerSpace;
/// use bevy_sprung::space::SpringSpace;
///
/// struct UnitInterval;
/// # impl SpringSpace for UnitInterval {
/// #     type Value = f32;
/// #     type Offset = f32;
/// #     type Velocity = f32;
/// #     fn is_valid(value: f32) -> bool { value.is_finite() }
/// #     fn magnitude(_: f32) -> f32 { 1.0 }
/// #     fn offset(value: f32, target: f32) -> f32 { value - target }
/// #     fn at_offset(target: f32, offset: f32) -> f32 { (target + offset).clamp(0.0, 1.0) }
/// # }
///
/// impl LayerSpace for UnitInterval {
///     type Layer = f32;
///     fn apply(value: f32, layer: f32) -> f32 { (value + layer).clamp(0.0, 1.0) }
///     fn remove(value: f32, layer: f32) -> f32 { (value - layer).clamp(0.0, 1.0) }
/// }
/// assert_eq!(UnitInterval::apply(0.5, 0.25), 0.75);
/// ```
pub trait LayerSpace: SpringSpace {
    /// A layer's value: a vector that springs linearly, zero when the layer does nothing.
    type Layer: LinearValue;

    /// `value` with `layer` applied on top.
    #[must_use]
    fn apply(value: Self::Value, layer: Self::Layer) -> Self::Value;

    /// `value` with `layer` taken off: the inverse of [`apply`](Self::apply).
    #[must_use]
    fn remove(value: Self::Value, layer: Self::Layer) -> Self::Value;
}

impl<V: LinearValue> LayerSpace for Linear<V> {
    type Layer = V;

    #[inline]
    fn apply(value: V, layer: V) -> V {
        V::from_offset(value.to_offset() + layer.to_offset())
    }

    #[inline]
    fn remove(value: V, layer: V) -> V {
        V::from_offset(value.to_offset() - layer.to_offset())
    }
}

/// Scales layer by factors: the layer is their logarithm, so layers multiply, a layer never
/// carries a scale through zero, and a squash that keeps the volume (logarithms summing to 0)
/// keeps it on any base scale.
macro_rules! log_scale_layers {
    ($($vector:ty),*) => {$(
        impl LayerSpace for NeverThroughZero<Linear<$vector>> {
            type Layer = $vector;

            #[inline]
            fn apply(value: $vector, layer: $vector) -> $vector {
                value * layer.exp()
            }

            #[inline]
            fn remove(value: $vector, layer: $vector) -> $vector {
                value * (-layer).exp()
            }
        }
    )*};
}

log_scale_layers!(f32, Vec2, Vec3);

impl LayerSpace for ShortestArc {
    type Layer = Vec3;

    #[inline]
    fn apply(value: Quat, layer: Vec3) -> Quat {
        (value * Quat::from_scaled_axis(layer)).normalize()
    }

    #[inline]
    fn remove(value: Quat, layer: Vec3) -> Quat {
        (value * Quat::from_scaled_axis(-layer)).normalize()
    }
}

impl LayerSpace for ShortestAngle {
    type Layer = f32;

    #[inline]
    fn apply(value: Rot2, layer: f32) -> Rot2 {
        (value * Rot2::radians(layer)).normalize()
    }

    #[inline]
    fn remove(value: Rot2, layer: f32) -> Rot2 {
        (value * Rot2::radians(-layer)).normalize()
    }
}

#[cfg(feature = "color")]
impl LayerSpace for crate::space::OklabColor {
    type Layer = bevy::math::Vec4;

    #[inline]
    fn apply(value: bevy::color::Color, layer: bevy::math::Vec4) -> bevy::color::Color {
        Self::at_offset(value, layer)
    }

    #[inline]
    fn remove(value: bevy::color::Color, layer: bevy::math::Vec4) -> bevy::color::Color {
        Self::at_offset(value, -layer)
    }
}
