//! Colours, sprung in Oklab with their channels kept in range.

use bevy::color::{Color, ColorToComponents, LinearRgba, Oklaba};
use bevy::math::Vec4;

use super::spring_space::SpringSpace;

/// A `Color`, sprung in Oklab (lightness, a, b) plus alpha.
///
/// Oklab is perceptually even, so a spring moves through colours that look like an even blend
/// (no muddy midpoints from mixing in sRGB) and an overshoot reads as "a little brighter", not
/// as a hue jump. Every value written keeps alpha in `[0, 1]` and the linear RGB channels in
/// `[0, max(1, target's channel)]` (HDR targets stay reachable); the spring's own offset is not
/// clamped, so an overshoot past the gamut comes back along the same curve. Values are written
/// as `Color::LinearRgba`; at rest the target is written exactly as given.
pub struct OklabColor;

/// `(L, a, b, alpha)` of a colour.
#[inline]
fn oklab(color: Color) -> Vec4 {
    let c = Oklaba::from(color);
    Vec4::new(c.lightness, c.a, c.b, c.alpha)
}

impl SpringSpace for OklabColor {
    type Value = Color;
    type Offset = Vec4;
    type Velocity = Vec4;

    #[inline]
    fn is_valid(value: Color) -> bool {
        Vec4::from(LinearRgba::from(value).to_f32_array()).is_finite()
    }

    #[inline]
    fn magnitude(_: Color) -> f32 {
        1.0
    }

    #[inline]
    fn offset(value: Color, target: Color) -> Vec4 {
        oklab(value) - oklab(target)
    }

    #[inline]
    fn at_offset(target: Color, offset: Vec4) -> Color {
        let c = oklab(target) + offset;
        let value = LinearRgba::from(Oklaba::new(c.x, c.y, c.z, c.w));
        let limit = LinearRgba::from(target);
        // A channel that overflowed (an offset of ~1e13 cubes past f32) is NaN-free here: the
        // clamps turn ±∞ into the bounds, and `max` picks the bound over a NaN.
        let channel = |x: f32, top: f32| x.max(0.0).min(top.max(1.0));
        Color::LinearRgba(LinearRgba::new(
            channel(value.red, limit.red),
            channel(value.green, limit.green),
            channel(value.blue, limit.blue),
            channel(value.alpha, 1.0),
        ))
    }
}
