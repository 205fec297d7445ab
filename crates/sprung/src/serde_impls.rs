//! `serde` support: a [`Spring`] is read from any of its parametrisations and validated, so a
//! file can never produce an invalid spring; it is written as its physical parameters.

use core::fmt;

use serde::de::{self, Deserializer};
use serde::ser::{SerializeStruct, Serializer};
use serde::{Deserialize, Serialize};

use crate::{RestThreshold, Scalar, Spring, SpringError};

/// The named presets, as a file spells them.
#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "snake_case")]
enum Preset {
    Gentle,
    Wobbly,
    Stiff,
    Slow,
    Molasses,
    Smooth,
    Snappy,
    Bouncy,
}

/// A field of a file form that may be left out: read from the plain value (`half_life: 0.1`,
/// not `Some(0.1)` as RON spells an `Option`), `None` where the field is absent (with
/// `#[serde(default)]`), and written back plainly. The file forms of [`Spring`] and of the
/// springs in `bevy_sprung` use it for their optional fields.
///
/// # Example
/// ```
/// use serde::{Deserialize, Serialize};
/// use sprung::file_form::Given;
///
/// #[derive(Deserialize, Serialize)]
/// struct Jump {
///     height: f32,
///     #[serde(default, skip_serializing_if = "Given::is_absent")]
///     hang_time: Given<f32>,
/// }
///
/// let jump: Jump = ron::from_str("(height: 2.0, hang_time: 0.25)").unwrap();
/// assert_eq!(jump.hang_time.0, Some(0.25));
/// let jump: Jump = ron::from_str("(height: 2.0)").unwrap();
/// assert_eq!(jump.hang_time.0, None);
/// assert_eq!(ron::to_string(&jump).unwrap(), "(height:2.0)");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Given<T>(pub Option<T>);

/// Absent: what a field left out of the file reads as.
impl<T> Default for Given<T> {
    fn default() -> Self {
        Self(None)
    }
}

impl<T> Given<T> {
    /// Whether the field was left out: for `skip_serializing_if`.
    #[inline]
    #[must_use]
    pub fn is_absent(&self) -> bool {
        self.0.is_none()
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Given<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        T::deserialize(deserializer).map(|value| Self(Some(value)))
    }
}

/// The value itself where present (as it is read back); an absent value is best left out of
/// the output with `skip_serializing_if = "Given::is_absent"`, and is otherwise written as a
/// unit `None`.
impl<T: Serialize> Serialize for Given<T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match &self.0 {
            Some(value) => value.serialize(serializer),
            None => serializer.serialize_none(),
        }
    }
}

/// Every field a spring can be given by. Exactly one parametrisation's fields may be present.
#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    default,
    rename = "Spring",
    bound = "T: Deserialize<'de>"
)]
struct SpringFields<T> {
    mass: Given<T>,
    stiffness: Given<T>,
    damping: Given<T>,
    natural_frequency: Given<T>,
    damping_ratio: Given<T>,
    half_life: Given<T>,
    response: Given<T>,
    damping_fraction: Given<T>,
    duration: Given<T>,
    bounce: Given<T>,
    smooth_time: Given<T>,
    tension: Given<T>,
    friction: Given<T>,
    preset: Given<Preset>,
}

impl<T> Default for SpringFields<T> {
    fn default() -> Self {
        Self {
            mass: Given::default(),
            stiffness: Given::default(),
            damping: Given::default(),
            natural_frequency: Given::default(),
            damping_ratio: Given::default(),
            half_life: Given::default(),
            response: Given::default(),
            damping_fraction: Given::default(),
            duration: Given::default(),
            bounce: Given::default(),
            smooth_time: Given::default(),
            tension: Given::default(),
            friction: Given::default(),
            preset: Given::default(),
        }
    }
}

/// The parametrisations, for the error message.
const WAYS: &str = "(stiffness, damping[, mass]), (natural_frequency, damping_ratio), \
                    (half_life), (response, damping_fraction), (duration[, bounce]), \
                    (smooth_time), (tension, friction) or (preset)";

/// Why a spring could not be read.
enum ReadError {
    /// Fields of no parametrisation, of several, or one missing.
    Shape,
    /// A parametrisation whose values are invalid.
    Invalid(SpringError),
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Shape => write!(
                f,
                "a spring is given by exactly one of {WAYS}, with all of its fields"
            ),
            Self::Invalid(error) => write!(f, "invalid spring: {error}"),
        }
    }
}

impl<T: Scalar> SpringFields<T> {
    fn into_spring(self) -> Result<Spring<T>, ReadError> {
        let invalid = ReadError::Invalid;
        let Self {
            mass: Given(mass),
            stiffness: Given(stiffness),
            damping: Given(damping),
            natural_frequency: Given(natural_frequency),
            damping_ratio: Given(damping_ratio),
            half_life: Given(half_life),
            response: Given(response),
            damping_fraction: Given(damping_fraction),
            duration: Given(duration),
            bounce: Given(bounce),
            smooth_time: Given(smooth_time),
            tension: Given(tension),
            friction: Given(friction),
            preset: Given(preset),
        } = self;
        let groups = [
            mass.is_some() || stiffness.is_some() || damping.is_some(),
            natural_frequency.is_some() || damping_ratio.is_some(),
            half_life.is_some(),
            response.is_some() || damping_fraction.is_some(),
            duration.is_some() || bounce.is_some(),
            smooth_time.is_some(),
            tension.is_some() || friction.is_some(),
            preset.is_some(),
        ];
        if groups.iter().filter(|&&given| given).count() != 1 {
            return Err(ReadError::Shape);
        }
        let spring = match (
            (mass, stiffness, damping),
            (natural_frequency, damping_ratio),
            (half_life, response, damping_fraction),
            (duration, bounce, smooth_time),
            (tension, friction, preset),
        ) {
            ((mass, Some(k), Some(c)), ..) => Spring::new(mass.unwrap_or_else(T::one), k, c),
            (_, (Some(w), Some(z)), ..) => Spring::from_natural_frequency(w, z),
            (_, _, (Some(h), ..), ..) => Spring::from_half_life(h),
            (_, _, (_, Some(r), Some(z)), ..) => Spring::from_response(r, z),
            (.., (Some(d), b, _), _) => {
                Spring::from_duration_and_bounce(d, b.unwrap_or_else(T::zero))
            }
            (.., (_, _, Some(s)), _) => Spring::from_smooth_time(s),
            (.., (Some(t), Some(f), _)) => Spring::from_tension_and_friction(t, f),
            (.., (_, _, Some(preset))) => Ok(match preset {
                Preset::Gentle => Spring::gentle(),
                Preset::Wobbly => Spring::wobbly(),
                Preset::Stiff => Spring::stiff(),
                Preset::Slow => Spring::slow(),
                Preset::Molasses => Spring::molasses(),
                Preset::Smooth => Spring::smooth(),
                Preset::Snappy => Spring::snappy(),
                Preset::Bouncy => Spring::bouncy(),
            }),
            _ => return Err(ReadError::Shape),
        };
        spring.map_err(invalid)
    }
}

/// Reads a spring from any one parametrisation, by its field names:
/// `(stiffness: 170.0, damping: 26.0)` (mass 1 unless given), `(natural_frequency: 10.0,
/// damping_ratio: 0.5)`, `(half_life: 0.1)`, `(response: 0.5, damping_fraction: 0.8)`,
/// `(duration: 0.5, bounce: 0.2)` (bounce 0 unless given), `(smooth_time: 0.3)`,
/// `(tension: 170.0, friction: 26.0)` or `(preset: snappy)`. Invalid values, unknown fields and
/// mixed or incomplete parametrisations are errors that say which, never a panic.
///
/// # Example
/// ```
/// # #[cfg(feature = "serde")] {
/// use sprung::Spring;
///
/// let spring: Spring = ron::from_str("(duration: 0.5, bounce: 0.3)").unwrap();
/// assert!((spring.damping_ratio().unwrap() - 0.7).abs() < 1e-6);
/// assert_eq!(ron::from_str::<Spring>("(preset: bouncy)").unwrap(), Spring::bouncy());
/// let error = ron::from_str::<Spring>("(stiffness: 100.0, damping: -1.0)").unwrap_err();
/// assert!(error.to_string().contains("damping must not be negative"));
/// # }
/// ```
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for Spring<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        SpringFields::<T>::deserialize(deserializer)?
            .into_spring()
            .map_err(de::Error::custom)
    }
}

/// Writes the physical parameters `(mass, stiffness, damping)`, which read back exactly.
impl<T: Scalar + Serialize> Serialize for Spring<T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut fields = serializer.serialize_struct("Spring", 3)?;
        fields.serialize_field("mass", &self.mass())?;
        fields.serialize_field("stiffness", &self.stiffness())?;
        fields.serialize_field("damping", &self.damping())?;
        fields.end()
    }
}

/// The fields of a [`RestThreshold`], before validation.
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields, rename = "RestThreshold")]
struct RestFields<T> {
    offset: T,
    speed: T,
}

/// Reads `(offset, speed)`; a negative or non-finite tolerance is an error.
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for RestThreshold<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let RestFields { offset, speed } = RestFields::<T>::deserialize(deserializer)?;
        for (name, value) in [("offset", offset), ("speed", speed)] {
            if !(value.is_finite() && value >= T::zero()) {
                return Err(de::Error::custom(format_args!(
                    "rest {name} tolerance must be finite and not negative, not {value}"
                )));
            }
        }
        Ok(Self::new(offset, speed))
    }
}

impl<T: Scalar + Serialize> Serialize for RestThreshold<T> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        RestFields {
            offset: self.offset,
            speed: self.speed,
        }
        .serialize(serializer)
    }
}
