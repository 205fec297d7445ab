//! What a spring will do: its energy, decay rate, half-life and settle time.

use super::{CRITICAL_HALFWAY, Spring};
use crate::{Scalar, modes};

impl<T: Scalar> Spring<T> {
    /// The time a spring released at rest takes to first cover half the distance to its target.
    ///
    /// The round trip of [`from_half_life`](Self::from_half_life), and defined for every
    /// regime: found by safeguarded Newton iteration on the exact step response. `None` when
    /// `k = 0` (nothing pulls the spring toward its target).
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f64>::from_half_life(0.25)?;
    /// assert!((spring.half_life().unwrap() - 0.25).abs() < 1e-14);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[must_use]
    #[expect(
        clippy::float_cmp,
        reason = "the iteration has converged exactly when it stops moving"
    )]
    pub fn half_life(&self) -> Option<T> {
        if self.stiffness <= T::zero() {
            return None;
        }
        let (m, k) = (self.mass.to_f64(), self.stiffness.to_f64());
        let omega = crate::math::sqrt(k / m);
        // f0 falls from 1 and first reaches 1/2 at the root; start from the critically damped
        // answer for this ω (exact when critical, late when under-damped) and double until f0 is
        // at or below 1/2 (over-damped springs are slower).
        let mut low = 0.0;
        let mut high = CRITICAL_HALFWAY / omega;
        while self.coefficients(high).f0 > 0.5 {
            low = high;
            high *= 2.0;
            if !high.is_finite() {
                return None;
            }
        }
        // Newton on f0(t) − 1/2 with f0' = −ω²·f1, kept inside [low, high] by bisection.
        let mut t = high;
        for _ in 0..200 {
            let c = self.coefficients(t);
            let residual = c.f0 - 0.5;
            if residual > 0.0 {
                low = t;
            } else {
                high = t;
            }
            let newton = t + residual / c.w2f1;
            let next = if c.w2f1 > 0.0 && newton > low && newton < high {
                newton
            } else {
                low + (high - low) / 2.0
            };
            if next == t || high - low <= f64::EPSILON * high {
                return Some(T::from_f64(next));
            }
            t = next;
        }
        Some(T::from_f64(t))
    }

    /// The largest displacement that a unit change of velocity gives a spring resting on its
    /// target: the peak of the impulse response `x(t) = f1(t)` (the transition's upper right
    /// entry). A kick of `d / impulse_peak()` swings the spring out by exactly `d` before it
    /// returns: a *punch* measured in distance instead of velocity.
    ///
    /// The peak is at `t* = atan2(κ, b)/κ` below critical damping, `1/ω` at it, and
    /// `ln(λ₂/λ₁)/(λ₂ − λ₁) = ln1p((b − ω + s)/ω)/s` above it (the ratio of the two rates formed
    /// from `b + s` without subtracting, and `b − ω` exact near critical damping, where `s` is
    /// small); `f1(t*)` is then the exact transition entry. Without stiffness the response only
    /// approaches its supremum `m/c`, which is returned; `None` when the spring has neither
    /// stiffness nor damping (a kick then carries it away for ever).
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f64>::from_natural_frequency(10.0, 1.0)?;
    /// // Critically damped: the peak is at t = 1/ω and equals 1/(e·ω).
    /// let peak = spring.impulse_peak().unwrap();
    /// assert!((peak - 1.0 / (10.0 * std::f64::consts::E)).abs() < 1e-15);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[must_use]
    pub fn impulse_peak(&self) -> Option<T> {
        let (m, k, c) = (
            self.mass.to_f64(),
            self.stiffness.to_f64(),
            self.damping.to_f64(),
        );
        let b = c / m / 2.0;
        let w = crate::math::sqrt(k / m);
        if w <= 0.0 {
            return (b > 0.0).then(|| T::from_f64(0.5 / b));
        }
        let peak_time = if b < w {
            let kappa = modes::damped_frequency(b, w);
            crate::math::atan2(kappa, b) / kappa
        } else if b > w {
            let s = modes::overdamped_split(b, w);
            crate::math::ln_1p(((b - w) + s) / w) / s
        } else {
            1.0 / w
        };
        Some(T::from_f64(self.coefficients(peak_time).f1))
    }

    /// The decay rate of the slowest mode in 1/s: `b = c/(2m)` up to critical damping and the
    /// slow rate `λ = b − √(b² − ω²)` (formed without cancellation) beyond it. 0 for undamped
    /// and unsprung springs (whose offset never decays).
    #[must_use]
    pub fn decay_rate(&self) -> T {
        let (b, _, w) = self.rates();
        if b <= w {
            b
        } else {
            modes::slow_rate(b, w, modes::overdamped_split(b, w))
        }
    }

    /// The energy `½k·x² + ½m·v²` of an offset of length `offset` from the target moving at
    /// `speed`: the natural single measure of how far from rest a spring is.
    #[inline]
    #[must_use]
    pub fn energy(&self, offset: T, speed: T) -> T {
        let half = T::from_f64(0.5);
        half * (self.stiffness * offset * offset + self.mass * speed * speed)
    }

    /// How long a spring released at rest `distance` away from its target takes until it stays
    /// within `tolerance` of it, from the decay envelope of the exact step response.
    ///
    /// The envelope bounds `|x(t)|/distance` by `e^{−bt}·min(ω/κ, 1 + bt)` under critical
    /// damping and `e^{−λt}·(1 + λ·min(t, 1/(2s)))` above it; both are continuous through
    /// `ζ = 1`, so the estimate is an upper bound that is tight for non-oscillating springs and
    /// within one half-period for oscillating ones.
    ///
    /// `Some(0)` when `distance ≤ tolerance`. `None` when the spring never settles (undamped,
    /// unsprung or free) or when `distance` or `tolerance` is not finite, or `tolerance` is not
    /// positive.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f64>::from_natural_frequency(10.0, 1.0)?;
    /// // From 100 px away to within half a pixel:
    /// let t = spring.settle_time(100.0, 0.5).unwrap();
    /// let [[f0, _], _] = spring.transition(t).matrix();
    /// assert!((100.0 * f0 - 0.5).abs() < 1e-9);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[must_use]
    pub fn settle_time(&self, distance: T, tolerance: T) -> Option<T> {
        let zero = T::zero();
        let one = T::one();
        if !(distance.is_finite() && tolerance.is_finite() && tolerance > zero) {
            return None;
        }
        let distance = distance.abs();
        if distance <= tolerance {
            return Some(zero);
        }
        let rate = self.decay_rate();
        if rate <= zero {
            return None;
        }
        let (b, _, w) = self.rates();
        // ln of the envelope's polynomial factor P(t); the envelope is e^{−rate·t}·P(t).
        let log_factor = |t: T| -> T {
            if b <= w {
                let kappa = modes::damped_frequency(b, w);
                let linear = (b * t).ln_1p();
                if kappa > zero {
                    linear.min((w / kappa).ln())
                } else {
                    linear
                }
            } else {
                let s = modes::overdamped_split(b, w);
                let reach = if s > zero { t.min(one / (s + s)) } else { t };
                (rate * reach).ln_1p()
            }
        };
        // Solve −rate·t + ln P(t) = ln(tolerance/distance) by the fixed point
        // t = (ln(distance/tolerance) + ln P(t))/rate: ln P grows slower than rate·t
        // (d ln P/dt ≤ rate/(1 + rate·t)), so the iteration increases monotonically to the root.
        let target = (distance / tolerance).ln();
        let mut t = target / rate;
        for _ in 0..64 {
            let next = (target + log_factor(t)) / rate;
            if !next.is_finite() {
                return None;
            }
            if (next - t).abs() <= T::from_f64(4.0) * T::UNIT_ROUNDOFF * next {
                return Some(next);
            }
            t = next;
        }
        Some(t)
    }
}
