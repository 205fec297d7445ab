//! The vectors offsets move in: Bevy's [`NormedVectorSpace`] over `f32`, plus the component-wise
//! operations a spring needs to stay finite and in range.

use bevy::math::{NormedVectorSpace, Vec2, Vec3A, Vec4};
use bevy::reflect::{FromReflect, Reflectable};

/// A vector an offset and a velocity can be: `f32`, `Vec2`, `Vec3A` or `Vec4`, or a type of your
/// own with a norm. (A `Vec3` value springs with `Vec3A` offsets, see
/// [`LinearValue`](super::LinearValue).)
///
/// The spring arithmetic is [`NormedVectorSpace`]'s (`+`, `−`, scaling, the squared norm for the
/// rest test); this adds what it leaves out and a spring needs component by component.
pub trait SpringVector:
    NormedVectorSpace<Scalar = f32> + PartialEq + Send + Sync + Reflectable + FromReflect
{
    /// Whether every component is finite.
    #[must_use]
    fn is_finite(self) -> bool;

    /// Each component clamped into the finite range `[−f32::MAX, f32::MAX]`, NaN made 0: what a
    /// step that overflows keeps, so the spring stays finite and still arrives.
    #[must_use]
    fn saturate(self) -> Self;

    /// The largest component's magnitude.
    #[must_use]
    fn max_magnitude(self) -> f32;

    /// Per component `i`, with `c = coordinates`: where `c + before` and `c + after` lie on
    /// opposite sides of zero, and `c` lies on the side of `c + before` (an overshoot carrying
    /// the value away from its target across zero), `after` becomes `−c` (the value exactly 0)
    /// and that component of `remainder` and `velocity` 0. See
    /// [`NeverThroughZero`](super::NeverThroughZero).
    #[must_use]
    fn stop_at_zero(coordinates: Self, before: Self, after: [Self; 3]) -> [Self; 3];
}

/// [`SpringVector::stop_at_zero`] on arrays: `[after, remainder, velocity]`.
#[inline]
fn stop_at_zero<const N: usize>(
    coordinates: [f32; N],
    before: [f32; N],
    [mut after, mut remainder, mut velocity]: [[f32; N]; 3],
) -> [[f32; N]; 3] {
    for i in 0..N {
        let target = coordinates[i];
        let (was, is) = (target + before[i], target + after[i]);
        if (was >= 0.0 && is < 0.0 && target >= 0.0) || (was <= 0.0 && is > 0.0 && target <= 0.0) {
            after[i] = -target;
            remainder[i] = 0.0;
            velocity[i] = 0.0;
        }
    }
    [after, remainder, velocity]
}

/// A component into `[−MAX, MAX]`, NaN to 0.
#[inline]
fn saturate(x: f32) -> f32 {
    if x.is_nan() {
        0.0
    } else {
        x.clamp(-f32::MAX, f32::MAX)
    }
}

impl SpringVector for f32 {
    #[inline]
    fn is_finite(self) -> bool {
        f32::is_finite(self)
    }

    #[inline]
    fn saturate(self) -> Self {
        saturate(self)
    }

    #[inline]
    fn max_magnitude(self) -> f32 {
        self.abs()
    }

    #[inline]
    fn stop_at_zero(coordinates: f32, before: f32, after: [f32; 3]) -> [f32; 3] {
        stop_at_zero([coordinates], [before], after.map(|x| [x])).map(|[x]| x)
    }
}

macro_rules! glam_vector {
    ($($t:ty),*) => {$(
        impl SpringVector for $t {
            #[inline]
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }

            #[inline]
            fn saturate(self) -> Self {
                <$t>::from_array(self.to_array().map(saturate))
            }

            #[inline]
            fn max_magnitude(self) -> f32 {
                self.abs().max_element()
            }

            #[inline]
            fn stop_at_zero(coordinates: Self, before: Self, after: [Self; 3]) -> [Self; 3] {
                stop_at_zero(
                    coordinates.to_array(),
                    before.to_array(),
                    after.map(|v| v.to_array()),
                )
                .map(<$t>::from_array)
            }
        }
    )*};
}

glam_vector!(Vec2, Vec3A, Vec4);
