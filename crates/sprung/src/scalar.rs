//! The floating-point types a [`Spring`](crate::Spring) can be built over.

use approx::{AbsDiffEq, RelativeEq, UlpsEq};
use core::fmt::{Debug, Display};
use num_traits::Float;

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}

/// A floating-point type the spring numerics are tuned for: `f32` or `f64`.
///
/// The trait is sealed: the transition is evaluated in `f64` and rounded to `T` once, which is
/// exact for these two types and cannot be promised for an arbitrary one.
pub trait Scalar:
    Float
    + Debug
    + Display
    + Default
    + Send
    + Sync
    + 'static
    + AbsDiffEq<Epsilon = Self>
    + RelativeEq
    + UlpsEq
    + sealed::Sealed
{
    /// Unit roundoff `u` (half the machine epsilon): `2⁻²⁴` for `f32`, `2⁻⁵³` for `f64`.
    const UNIT_ROUNDOFF: Self;

    /// Converts from `f64`, rounding to nearest; for `f32`, magnitudes beyond `f32::MAX` become
    /// `±f32::MAX` (never infinite).
    #[must_use]
    fn from_f64(value: f64) -> Self;

    /// Converts to `f64` exactly (`f32 → f64` is exact).
    #[must_use]
    fn to_f64(self) -> f64;

    /// The spacing of the type at `self`: the gap from `|self|` to the next larger value (one
    /// unit in its last place), or for the largest finite value the gap below it. At zero it is
    /// the smallest subnormal; NaN for NaN, infinite for an infinity.
    ///
    /// No value of the type lies strictly between `x` and `x ± x.spacing()`: it is the finest
    /// distance from `x` that a position can express.
    ///
    /// # Example
    /// ```
    /// use sprung::Scalar;
    /// assert_eq!(1.0_f32.spacing(), f32::EPSILON);
    /// assert_eq!(1e6_f32.spacing(), 0.0625);
    /// assert_eq!((-1e6_f32).spacing(), 0.0625);
    /// assert_eq!(f64::MAX.spacing(), f64::MAX - f64::MAX.next_down());
    /// ```
    #[must_use]
    fn spacing(self) -> Self;
}

impl Scalar for f32 {
    const UNIT_ROUNDOFF: Self = f32::EPSILON / 2.0;

    #[inline]
    #[expect(
        clippy::cast_possible_truncation,
        reason = "rounding an f64 result to f32 is the intent"
    )]
    fn from_f64(value: f64) -> Self {
        (value as f32).clamp(-f32::MAX, f32::MAX)
    }

    #[inline]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }

    #[inline]
    fn spacing(self) -> Self {
        let magnitude = self.abs();
        let above = magnitude.next_up();
        if above.is_finite() || magnitude.is_infinite() {
            above - magnitude
        } else {
            magnitude - magnitude.next_down()
        }
    }
}

impl Scalar for f64 {
    const UNIT_ROUNDOFF: Self = f64::EPSILON / 2.0;

    #[inline]
    fn from_f64(value: f64) -> Self {
        value
    }

    #[inline]
    fn to_f64(self) -> f64 {
        self
    }

    #[inline]
    fn spacing(self) -> Self {
        let magnitude = self.abs();
        let above = magnitude.next_up();
        if above.is_finite() || magnitude.is_infinite() {
            above - magnitude
        } else {
            magnitude - magnitude.next_down()
        }
    }
}
