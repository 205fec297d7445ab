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

    /// Whether an offset of length `offset` from the target at speed `speed` is at rest.
    #[inline]
    #[must_use]
    pub fn is_at_rest(&self, offset: T, speed: T) -> bool {
        offset.abs() <= self.offset && speed.abs() <= self.speed
    }
}

impl<T: Scalar> Default for RestThreshold<T> {
    /// 0.001 units and 0.01 units per second: for values of order 1 (metres, normalised
    /// colours). Use [`RestThreshold::new`] for pixels.
    fn default() -> Self {
        Self::new(T::from_f64(1e-3), T::from_f64(1e-2))
    }
}
