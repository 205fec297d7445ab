//! The parametrisations users' tools speak, each with its round-trip accessors.

use super::{CRITICAL_HALFWAY, Spring, finite, non_negative, positive};
use crate::Scalar;
use crate::error::{Parameter, SpringError};

impl<T: Scalar> Spring<T> {
    /// Unit mass, natural frequency `ω = √(k/m)` in rad/s and damping ratio `ζ`
    /// (`ζ = 1` critical, `< 1` bouncy, `> 1` sluggish); Android's `SpringForce` speaks
    /// `(ω², ζ)`.
    ///
    /// # Errors
    /// Non-finite or negative `natural_frequency` or `damping_ratio`, or rates that overflow.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f64>::from_natural_frequency(8.0, 0.5)?;
    /// assert_eq!(spring.stiffness(), 64.0);
    /// assert_eq!(spring.damping_ratio(), Some(0.5));
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    pub fn from_natural_frequency(
        natural_frequency: T,
        damping_ratio: T,
    ) -> Result<Self, SpringError> {
        let omega = non_negative(natural_frequency, Parameter::NaturalFrequency)?;
        let zeta = non_negative(damping_ratio, Parameter::DampingRatio)?;
        Self::new(T::one(), omega * omega, (zeta + zeta) * omega)
    }

    /// A critically damped unit-mass spring that, released at rest, covers half the distance to
    /// its target in `half_life` seconds (`ω = 1.678…/half_life`).
    ///
    /// Daniel Holden's "Spring-It-On" calls a different quantity half-life: his `h` is this
    /// function's `half_life · 2 ln 2 / 1.678…`.
    ///
    /// # Errors
    /// `half_life` not finite or not positive, or so small that the rates overflow.
    ///
    /// # Example
    /// ```
    /// use sprung::{Regime, Spring};
    /// let spring = Spring::<f64>::from_half_life(0.1)?;
    /// assert_eq!(spring.regime(), Regime::CriticallyDamped);
    /// let [[f0, _], _] = spring.transition(0.1).matrix();
    /// assert!((f0 - 0.5).abs() < 1e-12);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    pub fn from_half_life(half_life: T) -> Result<Self, SpringError> {
        let half_life = positive(half_life, Parameter::HalfLife)?;
        let omega = T::from_f64(CRITICAL_HALFWAY) / half_life;
        Self::critical_checked(omega)
    }

    fn critical_checked(omega: T) -> Result<Self, SpringError> {
        if (omega * omega).is_finite() && (omega + omega).is_finite() {
            Ok(Self::critical_unit_mass(omega))
        } else {
            Err(SpringError::RatesOverflow)
        }
    }

    /// SwiftUI's `Spring(response:dampingFraction:)`: unit mass, `ω = 2π/response`, and
    /// `damping_fraction` is the damping ratio `ζ`.
    ///
    /// # Errors
    /// `response` not finite and positive, `damping_fraction` not finite and non-negative.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f64>::from_response(0.5, 0.825)?;
    /// assert!((spring.response().unwrap() - 0.5).abs() < 1e-15);
    /// assert!((spring.damping_ratio().unwrap() - 0.825).abs() < 1e-15);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    pub fn from_response(response: T, damping_fraction: T) -> Result<Self, SpringError> {
        let response = positive(response, Parameter::Response)?;
        let zeta = non_negative(damping_fraction, Parameter::DampingRatio)?;
        let omega = T::from_f64(core::f64::consts::TAU) / response;
        Self::new(T::one(), omega * omega, (zeta + zeta) * omega)
    }

    /// SwiftUI's and Motion's `Spring(duration:bounce:)`: unit mass, `k = (2π/duration)²`,
    /// `ζ = 1 − bounce` for `bounce ≥ 0` and `ζ = 1/(1 + bounce)` for `bounce < 0`.
    ///
    /// `bounce` lies in `(−1, 1]`: `0` is critical, `1` undamped, negative values are
    /// over-damped ("flattened").
    ///
    /// # Errors
    /// `duration` not finite and positive; `bounce` not finite or outside `(−1, 1]`.
    ///
    /// # Example
    /// ```
    /// use sprung::{Regime, Spring};
    /// let snappy = Spring::<f32>::from_duration_and_bounce(0.5, 0.15)?;
    /// assert_eq!(snappy.regime(), Regime::Underdamped);
    /// let flat = Spring::<f32>::from_duration_and_bounce(0.5, -0.5)?;
    /// assert_eq!(flat.damping_ratio(), Some(2.0));
    /// assert!((flat.bounce().unwrap() + 0.5).abs() < 1e-6);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    pub fn from_duration_and_bounce(duration: T, bounce: T) -> Result<Self, SpringError> {
        let duration = positive(duration, Parameter::Duration)?;
        let bounce = finite(bounce, Parameter::Bounce)?;
        let one = T::one();
        if bounce <= -one || bounce > one {
            return Err(SpringError::OutOfRange(Parameter::Bounce));
        }
        let zeta = if bounce >= T::zero() {
            one - bounce
        } else {
            one / (one + bounce)
        };
        let omega = T::from_f64(core::f64::consts::TAU) / duration;
        Self::new(one, omega * omega, (zeta + zeta) * omega)
    }

    /// Unity's `SmoothDamp`: a critically damped unit-mass spring with `ω = 2/smooth_time`.
    /// Unlike `SmoothDamp`'s rational approximation, the motion here is exact at any frame rate.
    ///
    /// # Errors
    /// `smooth_time` not finite and positive, or so small that the rates overflow.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f64>::from_smooth_time(0.3)?;
    /// assert!((spring.smooth_time().unwrap() - 0.3).abs() < 1e-15);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    pub fn from_smooth_time(smooth_time: T) -> Result<Self, SpringError> {
        let smooth_time = positive(smooth_time, Parameter::SmoothTime)?;
        Self::critical_checked((T::one() + T::one()) / smooth_time)
    }

    /// react-spring's `{ tension, friction }` at unit mass: `k = tension`, `c = friction`.
    /// (react-spring's `mass` option is [`Spring::new`]'s first argument.)
    ///
    /// # Errors
    /// Non-finite or negative `tension` or `friction`.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f32>::from_tension_and_friction(170.0, 26.0)?;
    /// assert_eq!((spring.stiffness(), spring.damping()), (170.0, 26.0));
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    pub fn from_tension_and_friction(tension: T, friction: T) -> Result<Self, SpringError> {
        let tension = non_negative(tension, Parameter::Tension)?;
        let friction = non_negative(friction, Parameter::Friction)?;
        Self::new(T::one(), tension, friction)
    }

    /// The natural frequency `ω = √(k/m)` in rad/s; 0 without stiffness.
    #[inline]
    #[must_use]
    pub fn natural_frequency(&self) -> T {
        self.rates().2
    }

    /// The damping ratio `ζ = c/(2√(k·m))` (SwiftUI's damping fraction).
    ///
    /// `None` when `k = 0`, where `ζ` is infinite (`c > 0`) or undefined (`c = 0`).
    #[inline]
    #[must_use]
    pub fn damping_ratio(&self) -> Option<T> {
        let (b, _, w) = self.rates();
        (w > T::zero()).then(|| b / w)
    }

    /// SwiftUI's response: the undamped period `2π/ω`. `None` when `k = 0`.
    #[inline]
    #[must_use]
    pub fn response(&self) -> Option<T> {
        let w = self.natural_frequency();
        (w > T::zero()).then(|| T::from_f64(core::f64::consts::TAU) / w)
    }

    /// The duration of the duration + bounce parametrisation: `2π/ω`, the same as
    /// [`response`](Self::response). `None` when `k = 0`.
    #[inline]
    #[must_use]
    pub fn duration(&self) -> Option<T> {
        self.response()
    }

    /// The bounce of the duration + bounce parametrisation: `1 − ζ` for `ζ ≤ 1`, `1/ζ − 1` for
    /// `ζ > 1`. `None` when `k = 0`.
    #[inline]
    #[must_use]
    pub fn bounce(&self) -> Option<T> {
        self.damping_ratio().map(|zeta| {
            if zeta <= T::one() {
                T::one() - zeta
            } else {
                T::one() / zeta - T::one()
            }
        })
    }

    /// Unity `SmoothDamp`'s smooth time `2/ω`. `None` when `k = 0`.
    #[inline]
    #[must_use]
    pub fn smooth_time(&self) -> Option<T> {
        let w = self.natural_frequency();
        (w > T::zero()).then(|| (T::one() + T::one()) / w)
    }
}
