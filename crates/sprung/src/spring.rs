//! Validated spring parameters and their parametrisations.

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
        kernel::coefficients(
            c / m / 2.0,
            omega_squared,
            crate::math::sqrt(omega_squared),
            t,
            T::UNIT_ROUNDOFF.to_f64(),
        )
    }

    /// For constants known to be valid (presets): falls back to [`Spring::smooth`]'s
    /// parameters could they ever be refused, so presets never panic.
    fn preset(mass: f64, stiffness: f64, damping: f64) -> Self {
        Self::new(
            T::from_f64(mass),
            T::from_f64(stiffness),
            T::from_f64(damping),
        )
        .unwrap_or_else(|_| Self::critical_unit_mass(T::from_f64(4.0 * core::f64::consts::PI)))
    }

    /// Critically damped, unit mass, natural frequency `omega` (validated by the caller).
    fn critical_unit_mass(omega: T) -> Self {
        Self {
            mass: T::one(),
            stiffness: omega * omega,
            damping: omega + omega,
        }
    }

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

    /// react-spring's `gentle` preset: tension 120, friction 14 (`ζ ≈ 0.64`).
    #[must_use]
    pub fn gentle() -> Self {
        Self::preset(1.0, 120.0, 14.0)
    }

    /// react-spring's `wobbly` preset: tension 180, friction 12 (`ζ ≈ 0.45`).
    #[must_use]
    pub fn wobbly() -> Self {
        Self::preset(1.0, 180.0, 12.0)
    }

    /// react-spring's `stiff` preset: tension 210, friction 20 (`ζ ≈ 0.69`).
    #[must_use]
    pub fn stiff() -> Self {
        Self::preset(1.0, 210.0, 20.0)
    }

    /// react-spring's `slow` preset: tension 280, friction 60 (`ζ ≈ 1.79`).
    #[must_use]
    pub fn slow() -> Self {
        Self::preset(1.0, 280.0, 60.0)
    }

    /// react-spring's `molasses` preset: tension 280, friction 120 (`ζ ≈ 3.6`).
    #[must_use]
    pub fn molasses() -> Self {
        Self::preset(1.0, 280.0, 120.0)
    }

    /// SwiftUI's `.smooth`: duration 0.5 s, bounce 0 (critically damped).
    #[must_use]
    pub fn smooth() -> Self {
        Self::preset_duration_bounce(0.5, 0.0)
    }

    /// SwiftUI's `.snappy`: duration 0.5 s, bounce 0.15.
    #[must_use]
    pub fn snappy() -> Self {
        Self::preset_duration_bounce(0.5, 0.15)
    }

    /// SwiftUI's `.bouncy`: duration 0.5 s, bounce 0.3.
    #[must_use]
    pub fn bouncy() -> Self {
        Self::preset_duration_bounce(0.5, 0.3)
    }

    fn preset_duration_bounce(duration: f64, bounce: f64) -> Self {
        let omega = core::f64::consts::TAU / duration;
        let zeta = 1.0 - bounce;
        Self::preset(1.0, omega * omega, 2.0 * zeta * omega)
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

    /// The decay rate of the slowest mode in 1/s: `b = c/(2m)` up to critical damping and the
    /// slow rate `λ = b − √(b² − ω²)` (formed without cancellation) beyond it. 0 for undamped
    /// and unsprung springs (whose offset never decays).
    #[must_use]
    pub fn decay_rate(&self) -> T {
        let (b, _, w) = self.rates();
        if b <= w {
            b
        } else {
            let one = T::one();
            let r = w / b;
            let s = b * ((one - r) * (one + r)).sqrt();
            w * (w / (b + s))
        }
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
        Transition::from_coefficients(
            dt,
            self.damping / self.mass,
            &self.coefficients(dt.to_f64()),
        )
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
                let q = b / w;
                let kappa = w * ((one - q) * (one + q)).sqrt();
                let linear = (b * t).ln_1p();
                if kappa > zero {
                    linear.min((w / kappa).ln())
                } else {
                    linear
                }
            } else {
                let r = w / b;
                let s = b * ((one - r) * (one + r)).sqrt();
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
