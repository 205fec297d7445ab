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

/// [`SpringVector::stop_at_zero`] on arrays: `[after, remainder, velocity]`, out of line: it
/// runs only where a component may have crossed zero.
#[cold]
#[inline(never)]
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
        // The value keeps its sign (see the vectors' test below).
        if (coordinates + before) * (coordinates + after[0]) > 0.0 {
            return after;
        }
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
                // Every component keeps its sign, none is zero: none crossed zero (or reached
                // it), and the full test would change nothing. The usual case, tested on all
                // lanes at once so that the step around it keeps its vector arithmetic (a
                // product that underflows to 0, or a NaN, only sends it to the full test).
                let (was, is) = (coordinates + before, coordinates + after[0]);
                if (was * is).cmpgt(<$t>::ZERO).all() {
                    return after;
                }
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

#[cfg(test)]
mod tests {
    use bevy::math::{Vec2, Vec3A, Vec4};

    use super::{SpringVector, stop_at_zero};

    /// The vectors' `stop_at_zero`, which skips the full test where every component keeps its
    /// sign, agrees bit for bit with the full test, component by component: values on both
    /// sides of zero, on it (either zero), far from it, products that underflow or overflow,
    /// infinities and NaN.
    #[test]
    fn the_sign_test_skips_only_what_the_full_test_leaves() {
        let edges = [
            0.0,
            -0.0,
            1e-30,
            -1e-30,
            1e-45,
            -1e-45,
            0.5,
            -0.5,
            1.0,
            -1.0,
            3.0,
            -3.0,
            1e30,
            -1e30,
            f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        let same = |a: [f32; 3], b: [f32; 3]| {
            a.iter()
                .zip(b)
                .all(|(a, b)| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()))
        };
        let mut checked = 0;
        for &target in &edges {
            for &before in &edges {
                for &after in &edges {
                    let state = [after, 0.25, -2.0];
                    let full = stop_at_zero([target], [before], state.map(|x| [x])).map(|[x]| x);
                    let fast = f32::stop_at_zero(target, before, state);
                    assert!(
                        same(fast, full),
                        "{target} {before} {after}: {fast:?} {full:?}"
                    );
                    // The same component in each lane of a vector, the others crossing zero
                    // (so that one lane's sign never decides for another's).
                    let lanes = |x: f32, other: f32| [x, other, x, other];
                    let vectors = [
                        lanes(target, 1.0),
                        lanes(before, 2.0),
                        lanes(after, -0.5),
                        lanes(0.25, 0.125),
                        lanes(-2.0, 7.0),
                    ];
                    let [c, b, a, r, v] = vectors;
                    let full = stop_at_zero(c, b, [a, r, v]);
                    let check = |fast: [[f32; 4]; 3], lanes: usize| {
                        for (fast, full) in fast.iter().zip(&full) {
                            for lane in 0..lanes {
                                assert!(
                                    same([fast[lane], 0.0, 0.0], [full[lane], 0.0, 0.0]),
                                    "{target} {before} {after} lane {lane}: {fast:?} {full:?}"
                                );
                            }
                        }
                    };
                    let two = |x: [f32; 4]| Vec2::new(x[0], x[1]);
                    let fast = Vec2::stop_at_zero(two(c), two(b), [two(a), two(r), two(v)]);
                    check(fast.map(|x| [x.x, x.y, 0.0, 0.0]), 2);
                    let three = |x: [f32; 4]| Vec3A::new(x[0], x[1], x[2]);
                    let fast =
                        Vec3A::stop_at_zero(three(c), three(b), [three(a), three(r), three(v)]);
                    check(fast.map(|x| [x.x, x.y, x.z, 0.0]), 3);
                    let four = Vec4::from_array;
                    let fast = Vec4::stop_at_zero(four(c), four(b), [four(a), four(r), four(v)]);
                    check(fast.map(|x| x.to_array()), 4);
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, edges.len().pow(3));
    }
}
