//! One spring, every parametrisation: read any parameter, set any one keeping the rest of its
//! parametrisation (what a spring designer's fields do), and what a response looks like
//! (overshoot, period).

use super::{CRITICAL_HALFWAY, Spring, finite, non_negative, positive};
use crate::error::{Parameter, SpringError};
use crate::{Scalar, modes};

impl Parameter {
    /// Every parameter a spring is tuned by (all but the time step), in the order a designer
    /// lists them: physical, frequency and ratio, then each tool's own.
    pub const TUNABLE: [Self; 12] = [
        Self::Mass,
        Self::Stiffness,
        Self::Damping,
        Self::NaturalFrequency,
        Self::DampingRatio,
        Self::HalfLife,
        Self::Response,
        Self::Duration,
        Self::Bounce,
        Self::SmoothTime,
        Self::Tension,
        Self::Friction,
    ];
}

impl<T: Scalar> Spring<T> {
    /// The value of `parameter` for this spring, whichever parametrisation it was made with:
    /// what [`with_parameter`](Self::with_parameter) would have to be given to make it.
    /// (SwiftUI's damping fraction is [`Parameter::DampingRatio`]; react-spring's tension and
    /// friction are the stiffness and damping.)
    ///
    /// `None` for the ratios and times of a spring without stiffness, and for the time step.
    /// The half-life is the time a spring released at rest takes to cover half the distance,
    /// for any spring; only a critically damped one is made from it (see
    /// [`with_parameter`](Self::with_parameter)).
    ///
    /// # Example
    /// ```
    /// use sprung::{Parameter, Spring};
    /// let spring = Spring::<f64>::from_duration_and_bounce(0.5, 0.25)?;
    /// let zeta = spring.parameter(Parameter::DampingRatio).unwrap();
    /// let response = spring.parameter(Parameter::Response).unwrap();
    /// assert!((zeta - 0.75).abs() < 1e-15 && (response - 0.5).abs() < 1e-15);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[must_use]
    pub fn parameter(&self, parameter: Parameter) -> Option<T> {
        match parameter {
            Parameter::Mass => Some(self.mass),
            Parameter::Stiffness | Parameter::Tension => Some(self.stiffness),
            Parameter::Damping | Parameter::Friction => Some(self.damping),
            Parameter::NaturalFrequency => Some(self.natural_frequency()),
            Parameter::DampingRatio => self.damping_ratio(),
            Parameter::HalfLife => self.half_life(),
            Parameter::Response | Parameter::Duration => self.response(),
            Parameter::Bounce => self.bounce(),
            Parameter::SmoothTime => self.smooth_time(),
            Parameter::TimeStep => None,
        }
    }

    /// This spring with `parameter` set to `value`, the rest of its parametrisation kept, as a
    /// designer's field edits it:
    /// - mass, stiffness (tension), damping (friction): that coefficient alone;
    /// - natural frequency, response, duration, smooth time (all times of `ω`): `ω`, keeping
    ///   the damping ratio (the damping coefficient for a spring without stiffness);
    /// - damping ratio, bounce: `ζ`, keeping `ω`;
    /// - half-life: a critically damped spring with that half-life (its definition).
    ///
    /// The mass is kept by all but the mass. [`parameter`](Self::parameter) then reads back
    /// `value` (to rounding), and every other parameter read from the result makes the same
    /// spring again (but the half-life, which makes a critically damped one).
    ///
    /// # Errors
    /// A value the parameter cannot take (as the constructors of each parametrisation say),
    /// a ratio for a spring without stiffness ([`SpringError::NotPositive`] of the stiffness),
    /// or rates that overflow. The time step is not a spring's parameter
    /// ([`SpringError::OutOfRange`]).
    ///
    /// # Example
    /// ```
    /// use sprung::{Parameter, Spring};
    /// let spring = Spring::<f64>::from_response(0.5, 0.6)?;
    /// // A little less bounce, the same duration.
    /// let calmer = spring.with_parameter(Parameter::Bounce, 0.2)?;
    /// assert!((calmer.bounce().unwrap() - 0.2).abs() < 1e-15);
    /// assert!((calmer.duration().unwrap() - 0.5).abs() < 1e-15);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    pub fn with_parameter(&self, parameter: Parameter, value: T) -> Result<Self, SpringError> {
        let (m, k, c) = (self.mass, self.stiffness, self.damping);
        let tau = T::from_f64(core::f64::consts::TAU);
        let two = T::one() + T::one();
        match parameter {
            Parameter::Mass => Self::new(value, k, c),
            Parameter::Stiffness | Parameter::Tension => {
                Self::new(m, non_negative(value, parameter)?, c)
            }
            Parameter::Damping | Parameter::Friction => {
                Self::new(m, k, non_negative(value, parameter)?)
            }
            Parameter::NaturalFrequency => self.with_frequency(non_negative(value, parameter)?),
            Parameter::Response | Parameter::Duration => {
                self.with_frequency(tau / positive(value, parameter)?)
            }
            Parameter::SmoothTime => self.with_frequency(two / positive(value, parameter)?),
            Parameter::DampingRatio => self.with_ratio(non_negative(value, parameter)?),
            Parameter::Bounce => {
                let bounce = finite(value, parameter)?;
                let one = T::one();
                if bounce <= -one || bounce > one {
                    return Err(SpringError::OutOfRange(parameter));
                }
                self.with_ratio(if bounce >= T::zero() {
                    one - bounce
                } else {
                    one / (one + bounce)
                })
            }
            Parameter::HalfLife => {
                let omega = T::from_f64(CRITICAL_HALFWAY) / positive(value, parameter)?;
                Self::from_mass_frequency_ratio(m, omega, T::one())
            }
            Parameter::TimeStep => Err(SpringError::OutOfRange(parameter)),
        }
    }

    /// Natural frequency `omega`, the damping ratio kept (the damping coefficient where there is
    /// no ratio: without stiffness).
    fn with_frequency(&self, omega: T) -> Result<Self, SpringError> {
        match self.damping_ratio() {
            Some(zeta) => Self::from_mass_frequency_ratio(self.mass, omega, zeta),
            None => Self::new(self.mass, self.mass * omega * omega, self.damping),
        }
    }

    /// Damping ratio `zeta`, the natural frequency kept (there must be one).
    fn with_ratio(&self, zeta: T) -> Result<Self, SpringError> {
        let omega = self.natural_frequency();
        if omega > T::zero() {
            Self::from_mass_frequency_ratio(self.mass, omega, zeta)
        } else {
            Err(SpringError::NotPositive(Parameter::Stiffness))
        }
    }

    /// `k = m·ω²`, `c = 2ζ·m·ω`.
    fn from_mass_frequency_ratio(mass: T, omega: T, zeta: T) -> Result<Self, SpringError> {
        let stiffness = mass * omega * omega;
        let damping = (zeta + zeta) * mass * omega;
        if stiffness.is_finite() && damping.is_finite() {
            Self::new(mass, stiffness, damping)
        } else {
            Err(SpringError::RatesOverflow)
        }
    }

    /// How far a spring released at rest swings past its target, as a fraction of the distance
    /// it started from: `e^{−πζ/√(1−ζ²)}` under critical damping (the first peak of the step
    /// response, `e^{−b·π/κ}` with the damped frequency `κ`), 1 undamped, 0 at and above
    /// critical damping and without stiffness.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f64>::from_natural_frequency(10.0, 0.5)?;
    /// // The first peak, at half the damped period, read off the exact transition.
    /// let half_period = spring.period().unwrap() / 2.0;
    /// let [[f0, _], _] = spring.transition(half_period).matrix();
    /// assert!((spring.overshoot() + f0).abs() < 1e-14);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[must_use]
    pub fn overshoot(&self) -> T {
        let (b, _, w) = self.rates();
        if w <= T::zero() || b >= w {
            return T::zero();
        }
        // κ from (1 − q)(1 + q), q = b/ω: no cancellation as ζ → 1 (the exponent → −∞).
        let kappa = modes::damped_frequency(b, w);
        (-(b * T::from_f64(core::f64::consts::PI)) / kappa).exp()
    }

    /// The period of the damped oscillation `2π/κ` (`κ = ω·√(1 − ζ²)`), in seconds; `None`
    /// for a spring that does not oscillate (critically or over-damped, or without
    /// stiffness).
    #[must_use]
    pub fn period(&self) -> Option<T> {
        let (b, _, w) = self.rates();
        (w > T::zero() && b < w)
            .then(|| T::from_f64(core::f64::consts::TAU) / modes::damped_frequency(b, w))
    }
}
