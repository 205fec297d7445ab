//! Typed errors for invalid spring parameters and time steps.

use core::fmt;

/// Which input a [`SpringError`] is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Parameter {
    /// The mass `m`.
    Mass,
    /// The stiffness `k`.
    Stiffness,
    /// The damping coefficient `c`.
    Damping,
    /// A time step `dt`.
    TimeStep,
    /// The natural (undamped angular) frequency `ω = √(k/m)`.
    NaturalFrequency,
    /// The damping ratio `ζ = c / (2√(k·m))` (also SwiftUI's damping fraction).
    DampingRatio,
    /// The half-life of a critically damped spring.
    HalfLife,
    /// SwiftUI's `response`: the period `2π/ω` of the undamped spring.
    Response,
    /// The perceptual duration of SwiftUI's and Motion's duration + bounce spring.
    Duration,
    /// The bounce of SwiftUI's and Motion's duration + bounce spring.
    Bounce,
    /// Unity `SmoothDamp`'s smooth time.
    SmoothTime,
    /// react-spring's tension (the stiffness at unit mass).
    Tension,
    /// react-spring's friction (the damping at unit mass).
    Friction,
}

impl Parameter {
    /// The parameter's name as the documentation spells it.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Mass => "mass",
            Self::Stiffness => "stiffness",
            Self::Damping => "damping",
            Self::TimeStep => "time step",
            Self::NaturalFrequency => "natural frequency",
            Self::DampingRatio => "damping ratio",
            Self::HalfLife => "half-life",
            Self::Response => "response",
            Self::Duration => "duration",
            Self::Bounce => "bounce",
            Self::SmoothTime => "smooth time",
            Self::Tension => "tension",
            Self::Friction => "friction",
        }
    }
}

impl fmt::Display for Parameter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why spring parameters or a time step were refused.
///
/// Every constructor of [`Spring`](crate::Spring) and every fallible query returns this instead
/// of panicking, and a spring that was accepted never yields NaN or infinity later.
///
/// # Example
/// ```
/// use sprung::{Parameter, Spring, SpringError};
///
/// assert_eq!(
///     Spring::<f32>::new(0.0, 100.0, 10.0),
///     Err(SpringError::NotPositive(Parameter::Mass))
/// );
/// assert_eq!(
///     Spring::<f64>::new(1.0, f64::NAN, 10.0),
///     Err(SpringError::NotFinite(Parameter::Stiffness))
/// );
/// assert_eq!(
///     SpringError::Negative(Parameter::Damping).to_string(),
///     "damping must not be negative"
/// );
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum SpringError {
    /// The value is NaN or infinite.
    NotFinite(Parameter),
    /// The value must be strictly positive (mass, durations, frequencies).
    NotPositive(Parameter),
    /// The value must not be negative (stiffness, damping, time steps, ratios).
    Negative(Parameter),
    /// The value is finite and has the right sign but lies outside the range the quantity
    /// allows (a bounce of −1 or less, or above 1).
    OutOfRange(Parameter),
    /// Each parameter is valid alone, but the rates `k/m` or `c/m` they imply overflow the
    /// float type, so no finite transition exists in it.
    RatesOverflow,
}

impl fmt::Display for SpringError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NotFinite(p) => write!(f, "{p} must be finite"),
            Self::NotPositive(p) => write!(f, "{p} must be positive"),
            Self::Negative(p) => write!(f, "{p} must not be negative"),
            Self::OutOfRange(p) => write!(f, "{p} is out of range"),
            Self::RatesOverflow => {
                f.write_str("stiffness/mass or damping/mass overflows the float type")
            }
        }
    }
}

impl core::error::Error for SpringError {}
