//! When a spring counts as at rest.

use crate::{Scalar, Spring};

/// Tolerances, in the user's units, under which a spring is at rest: the offset from the target
/// and the speed must both be within them.
///
/// Snapping a spring at rest onto its target is what makes sleeping exact: the snap moves it by
/// less than `offset`, and nothing moves afterwards until the target changes.
///
/// # Example
/// ```
/// use sprung::{RestThreshold, Spring};
///
/// // Half a pixel, and the speed at which a spring of this frequency carries the same energy.
/// let spring = Spring::<f32>::from_natural_frequency(12.0, 0.8)?;
/// let rest = RestThreshold::for_spring(&spring, 0.5);
/// assert_eq!(rest.speed, 6.0);
/// assert!(rest.is_at_rest(0.2, 1.0));
/// assert!(!rest.is_at_rest(0.2, 10.0));
/// # Ok::<(), sprung::SpringError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "bevy_reflect", derive(bevy_reflect::Reflect))]
pub struct RestThreshold<T = f32> {
    /// Largest distance from the target that counts as arrived.
    pub offset: T,
    /// Largest speed that counts as stopped, in units per second.
    pub speed: T,
}

impl<T: Scalar> RestThreshold<T> {
    /// Tolerances `offset` (distance) and `speed` (distance per second). Negative or NaN values
    /// are taken as 0 (only an exact rest counts).
    #[inline]
    #[must_use]
    pub fn new(offset: T, speed: T) -> Self {
        let clean = |value: T| if value > T::zero() { value } else { T::zero() };
        Self {
            offset: clean(offset),
            speed: clean(speed),
        }
    }

    /// An offset tolerance and the speed tolerance of equal energy for `spring`:
    /// `½k·offset² = ½m·speed²`, so `speed = ω·offset`. For `k = 0` (nothing pulls back) the
    /// speed tolerance is `offset` per second.
    #[inline]
    #[must_use]
    pub fn for_spring(spring: &Spring<T>, offset: T) -> Self {
        let omega = spring.natural_frequency();
        let rate = if omega > T::zero() { omega } else { T::one() };
        Self::new(offset, offset * rate)
    }

    /// These tolerances raised to what `T` can resolve near a target of size `magnitude`.
    ///
    /// A position next to a target at `1e6` in `f32` moves in steps of `0.0625` (the type's
    /// [spacing](Scalar::spacing) there), so an offset tolerance of `0.001` asks for more than
    /// the position can show: the spring's offset keeps decaying below it (a
    /// [`SpringState`](crate::SpringState) keeps those digits), but every frame after the
    /// position reached the target is invisible work. Here the offset tolerance becomes at least
    /// that spacing, and the speed tolerance grows by the same factor, so the two keep the ratio
    /// you chose ([`for_spring`](Self::for_spring): equal energy). Both are at least the
    /// smallest normal value of `T`, above which every damped spring decays (a tolerance of
    /// exactly 0 would wait on subnormals that rounding holds up).
    ///
    /// Tolerances the type can resolve are returned unchanged; a non-finite `magnitude`
    /// changes nothing but those floors. `bevy_sprung` applies this rule to every spring.
    ///
    /// # Example
    /// ```
    /// use sprung::RestThreshold;
    /// let pixels = RestThreshold::<f32>::new(0.01, 0.1);
    /// // Near 100 px the type resolves a hundredth of a pixel: nothing changes.
    /// assert_eq!(pixels.at_magnitude(100.0), pixels);
    /// // Near 1e6 it resolves 1/16: the tolerances grow 6.25×, together.
    /// let far = pixels.at_magnitude(1e6);
    /// assert_eq!(far.offset, 0.0625);
    /// assert!((far.speed - 0.625).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn at_magnitude(self, magnitude: T) -> Self {
        let tiny = T::min_positive_value();
        let spacing = magnitude.spacing();
        let floor = if spacing.is_finite() && spacing > tiny {
            spacing
        } else {
            tiny
        };
        let (offset, speed) = if self.offset >= floor {
            (self.offset, self.speed)
        } else if self.offset > T::zero() {
            (floor, self.speed * (floor / self.offset))
        } else {
            (floor, self.speed)
        };
        Self {
            offset,
            speed: if speed >= tiny { speed } else { tiny },
        }
    }

    /// Whether an offset of length `offset` from the target at speed `speed` is at rest.
    #[inline]
    #[must_use]
    pub fn is_at_rest(&self, offset: T, speed: T) -> bool {
        offset.abs() <= self.offset && speed.abs() <= self.speed
    }
}

/// The default offset tolerance, in units.
const DEFAULT_OFFSET: f64 = 1e-3;
/// The default speed tolerance, in units per second.
const DEFAULT_SPEED: f64 = 1e-2;

impl RestThreshold<f32> {
    /// 0.001 units and 0.01 units per second: for values of order 1 (metres, radians,
    /// normalised colours). Use [`RestThreshold::new`] for pixels. (For `f64`,
    /// [`RestThreshold::default`] gives the same.)
    #[expect(
        clippy::cast_possible_truncation,
        reason = "the constants are exact enough in f32"
    )]
    pub const DEFAULT: Self = Self {
        offset: DEFAULT_OFFSET as f32,
        speed: DEFAULT_SPEED as f32,
    };
}

impl<T: Scalar> Default for RestThreshold<T> {
    /// [`RestThreshold::DEFAULT`]: 0.001 units and 0.01 units per second, for values of order
    /// 1 (metres, radians, normalised colours). Use [`RestThreshold::new`] for pixels.
    fn default() -> Self {
        Self::new(T::from_f64(DEFAULT_OFFSET), T::from_f64(DEFAULT_SPEED))
    }
}
