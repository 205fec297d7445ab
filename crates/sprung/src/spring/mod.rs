//! Validated spring parameters: the type, its constructor and accessors, the regime and the
//! transition. Parametrisations, presets and analysis (settle times, half-life) are in the
//! submodules.

mod analysis;
mod parametrisations;
mod presets;
mod tuning;

use crate::Scalar;
use crate::error::{Parameter, SpringError};
use crate::kernel;
use crate::transition::Transition;

/// `x` with `(1 + x)·e^{−x} = 1/2`: a critically damped spring from rest covers half the
/// distance to its target at `t = x/ω`.
const CRITICAL_HALFWAY: f64 = 1.678_346_990_016_660_8;

/// The damping regime of a [`Spring`], from its parameters.
///
/// The [transition](Spring::transition) does not branch on this: one evaluation covers all
/// regimes continuously. It is descriptive, for users and for choosing presets.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "bevy_reflect", derive(bevy_reflect::Reflect))]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(rename_all = "snake_case")
)]
pub enum Regime {
    /// `0 < ζ < 1`: oscillates with a decaying envelope.
    Underdamped,
    /// `ζ = 1` (to a few units of roundoff): the fastest approach without overshoot.
    CriticallyDamped,
    /// `ζ > 1`: approaches without overshoot, slowed by the excess damping.
    Overdamped,
    /// `c = 0`, `k > 0`: oscillates forever (`ζ = 0`).
    Undamped,
    /// `k = 0`, `c > 0`: no pull toward the target; velocity decays exponentially.
    Unsprung,
    /// `k = c = 0`: moves at constant velocity (or under a constant acceleration).
    Free,
}

/// A damped spring `m·x'' + c·x' + k·x = f` with validated parameters.
///
/// `T` is `f32` (the default, what games animate with) or `f64`. Build it from the physical
/// parameters with [`Spring::new`] or from whichever parametrisation your tools speak
/// ([`from_natural_frequency`](Spring::from_natural_frequency),
/// [`from_half_life`](Spring::from_half_life), [`from_response`](Spring::from_response),
/// [`from_duration_and_bounce`](Spring::from_duration_and_bounce),
/// [`from_smooth_time`](Spring::from_smooth_time),
/// [`from_tension_and_friction`](Spring::from_tension_and_friction)), or take a preset.
/// A `Spring` that exists is valid: its [`transition`](Spring::transition) over any finite
/// `dt ≥ 0` is finite.
///
/// # Example
/// ```
/// use sprung::{Regime, Spring};
///
/// let spring = Spring::<f32>::new(1.0, 100.0, 20.0)?;
/// assert_eq!(spring.regime(), Regime::CriticallyDamped);
/// assert_eq!(spring.natural_frequency(), 10.0);
///
/// // One exact step of 1/60 s from 1 unit away, at rest, toward 0.
/// let [[f0, _], [m10, _]] = spring.transition(1.0 / 60.0).matrix();
/// let (position, velocity) = (f0 * 1.0, m10 * 1.0);
/// assert!(position < 1.0 && velocity < 0.0);
/// # Ok::<(), sprung::SpringError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "bevy_reflect", derive(bevy_reflect::Reflect))]
pub struct Spring<T = f32> {
    mass: T,
    stiffness: T,
    damping: T,
}

impl<T: Scalar> Default for Spring<T> {
    /// [`Spring::smooth`]: critically damped, settling in about half a second.
    fn default() -> Self {
        Self::smooth()
    }
}

impl From<Spring<f32>> for Spring<f64> {
    /// The same spring in `f64`: every `f32` is exact there, so it is valid as the original
    /// was, with the same motion; what an `f32` spring's steps are measured against.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let wide = Spring::<f64>::from(Spring::<f32>::snappy());
    /// assert_eq!(wide.stiffness(), f64::from(Spring::<f32>::snappy().stiffness()));
    /// ```
    #[inline]
    fn from(spring: Spring<f32>) -> Self {
        Self {
            mass: f64::from(spring.mass),
            stiffness: f64::from(spring.stiffness),
            damping: f64::from(spring.damping),
        }
    }
}

#[inline]
fn finite<T: Scalar>(value: T, parameter: Parameter) -> Result<T, SpringError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(SpringError::NotFinite(parameter))
    }
}

#[inline]
fn positive<T: Scalar>(value: T, parameter: Parameter) -> Result<T, SpringError> {
    if finite(value, parameter)? > T::zero() {
        Ok(value)
    } else {
        Err(SpringError::NotPositive(parameter))
    }
}

/// Finite and `≥ 0`; `−0` becomes `+0` so no negative zero leaks into the entries.
#[inline]
fn non_negative<T: Scalar>(value: T, parameter: Parameter) -> Result<T, SpringError> {
    if finite(value, parameter)? >= T::zero() {
        Ok(value + T::zero())
    } else {
        Err(SpringError::Negative(parameter))
    }
}

impl<T: Scalar> Spring<T> {
    /// A spring of mass `m > 0`, stiffness `k ≥ 0` and damping coefficient `c ≥ 0`, all finite.
    ///
    /// # Errors
    /// [`SpringError::NotFinite`], [`SpringError::NotPositive`] (mass) or
    /// [`SpringError::Negative`] (stiffness, damping) naming the offending parameter, and
    /// [`SpringError::RatesOverflow`] when `k/m` or `c/m` overflows `T` (for example
    /// `m = 1e-30, k = 1e30` in `f32`).
    ///
    /// # Example
    /// ```
    /// use sprung::{Parameter, Spring, SpringError};
    ///
    /// let spring = Spring::<f64>::new(2.0, 50.0, 4.0)?;
    /// assert_eq!(spring.natural_frequency(), 5.0);
    /// assert_eq!(
    ///     Spring::<f64>::new(1.0, -1.0, 0.0),
    ///     Err(SpringError::Negative(Parameter::Stiffness))
    /// );
    /// # Ok::<(), SpringError>(())
    /// ```
    pub fn new(mass: T, stiffness: T, damping: T) -> Result<Self, SpringError> {
        let mass = positive(mass, Parameter::Mass)?;
        let stiffness = non_negative(stiffness, Parameter::Stiffness)?;
        let damping = non_negative(damping, Parameter::Damping)?;
        if !(stiffness / mass).is_finite() || !(damping / mass).is_finite() {
            return Err(SpringError::RatesOverflow);
        }
        Ok(Self {
            mass,
            stiffness,
            damping,
        })
    }

    /// `(b, ω², ω)` in `T`: `b = c/(2m)`, `ω² = k/m`.
    #[inline]
    fn rates(&self) -> (T, T, T) {
        let omega_squared = self.stiffness / self.mass;
        let half_rate = self.damping / self.mass / (T::one() + T::one());
        (half_rate, omega_squared, omega_squared.sqrt())
    }

    /// The transition's coefficients over `t`, evaluated in `f64` from the exact parameters.
    #[inline]
    fn coefficients(&self, t: f64) -> kernel::Coefficients {
        let (m, k, c) = (
            self.mass.to_f64(),
            self.stiffness.to_f64(),
            self.damping.to_f64(),
        );
        let omega_squared = k / m;
        kernel::coefficients(c / m / 2.0, omega_squared, t, T::UNIT_ROUNDOFF.to_f64())
    }

    /// Critically damped, unit mass, natural frequency `omega` (validated by the caller).
    fn critical_unit_mass(omega: T) -> Self {
        Self {
            mass: T::one(),
            stiffness: omega * omega,
            damping: omega + omega,
        }
    }

    /// The mass `m`.
    #[inline]
    #[must_use]
    pub fn mass(&self) -> T {
        self.mass
    }

    /// The stiffness `k` (react-spring's tension at unit mass).
    #[inline]
    #[must_use]
    pub fn stiffness(&self) -> T {
        self.stiffness
    }

    /// The damping coefficient `c` (react-spring's friction at unit mass).
    #[inline]
    #[must_use]
    pub fn damping(&self) -> T {
        self.damping
    }

    /// The damping regime. Critical damping is recognised within 8 units of roundoff of
    /// `c = 2√(k·m)`.
    ///
    /// # Example
    /// ```
    /// use sprung::{Regime, Spring};
    /// assert_eq!(Spring::<f32>::new(1.0, 0.0, 0.0)?.regime(), Regime::Free);
    /// assert_eq!(Spring::<f32>::new(1.0, 0.0, 1.0)?.regime(), Regime::Unsprung);
    /// assert_eq!(Spring::<f32>::new(1.0, 1.0, 0.0)?.regime(), Regime::Undamped);
    /// assert_eq!(Spring::<f32>::new(1.0, 1.0, 1.0)?.regime(), Regime::Underdamped);
    /// assert_eq!(Spring::<f32>::new(1.0, 1.0, 3.0)?.regime(), Regime::Overdamped);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[must_use]
    pub fn regime(&self) -> Regime {
        let zero = T::zero();
        let (b, _, w) = self.rates();
        match (w > zero, b > zero) {
            (false, false) => Regime::Free,
            (false, true) => Regime::Unsprung,
            (true, false) => Regime::Undamped,
            (true, true) => {
                let tolerance = T::from_f64(8.0) * T::UNIT_ROUNDOFF * w;
                if (b - w).abs() <= tolerance {
                    Regime::CriticallyDamped
                } else if b < w {
                    Regime::Underdamped
                } else {
                    Regime::Overdamped
                }
            }
        }
    }

    /// The exact transition over `dt` seconds.
    ///
    /// A negative, NaN or infinite `dt` gives the identity (nothing moves): use
    /// [`try_transition`](Self::try_transition) to have it refused instead.
    ///
    /// Compute it once per spring and `dt` and share it: for an `f32` spring over a frame
    /// (`ρ·dt ≤ 1`, with `ρ` the faster decay rate or the natural frequency) it is a short
    /// Taylor series, about 20 ns; longer steps, heavy damping and `f64` springs take the closed
    /// forms (`exp`, `sin`, `cos` in `f64`), 40–140 ns.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let spring = Spring::<f64>::new(1.0, 0.0, 0.0)?; // free
    /// assert_eq!(spring.transition(0.5).matrix(), [[1.0, 0.5], [0.0, 1.0]]);
    /// assert_eq!(spring.transition(-1.0).matrix(), [[1.0, 0.0], [0.0, 1.0]]);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn transition(&self, dt: T) -> Transition<T> {
        let dt = if dt.is_finite() && dt > T::zero() {
            dt
        } else {
            T::zero()
        };
        Transition::from_coefficients(dt, &self.coefficients(dt.to_f64()))
    }

    /// The exact transition over `dt` seconds, refusing an invalid `dt`.
    ///
    /// # Errors
    /// [`SpringError::NotFinite`] or [`SpringError::Negative`] for
    /// [`Parameter::TimeStep`].
    ///
    /// # Example
    /// ```
    /// use sprung::{Parameter, Spring, SpringError};
    /// let spring = Spring::<f32>::default();
    /// assert!(spring.try_transition(1.0 / 60.0).is_ok());
    /// assert_eq!(
    ///     spring.try_transition(f32::NAN).unwrap_err(),
    ///     SpringError::NotFinite(Parameter::TimeStep)
    /// );
    /// ```
    #[inline]
    pub fn try_transition(&self, dt: T) -> Result<Transition<T>, SpringError> {
        let dt = non_negative(dt, Parameter::TimeStep)?;
        Ok(self.transition(dt))
    }
}
