//! The spring's configuration in a file: parameters, target, velocities, tolerances and
//! clock. Everything read is validated as the setters would; an invalid value is an error
//! that names it.

use bevy::math::VectorSpace;
use serde::de::{self, Deserializer};
use serde::{Deserialize, Serialize, Serializer};
use sprung::file_form::Given;
use sprung::{RestThreshold, Spring};

use super::PropertySpring;
use super::config::VelocityChange;
use crate::clock::SpringClock;
use crate::property::{OffsetOf, SpringProperty, ValueOf};
use crate::space::{SpringSpace, SpringVector};

/// What a file says of a spring.
#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    rename = "PropertySpring",
    bound = "V: Deserialize<'de>, O: Deserialize<'de>"
)]
struct Read<V, O> {
    spring: Spring<f32>,
    target: V,
    #[serde(default)]
    velocity: Given<O>,
    #[serde(default)]
    target_velocity: Given<O>,
    #[serde(default)]
    rest: Given<RestThreshold<f32>>,
    #[serde(default)]
    clock: Given<SpringClock>,
}

/// What is written.
#[derive(Serialize)]
#[serde(rename = "PropertySpring")]
struct Written<'a, V, O> {
    spring: &'a Spring<f32>,
    target: &'a V,
    #[serde(skip_serializing_if = "Given::is_absent")]
    velocity: Given<O>,
    target_velocity: &'a O,
    rest: &'a RestThreshold<f32>,
    #[serde(skip_serializing_if = "Given::is_absent")]
    clock: Given<SpringClock>,
}

/// Writes `(spring, target[, velocity], target_velocity, rest[, clock])`, `velocity` if one
/// was set that the spring has not yet applied (a starting velocity); its motion
/// ([`SpringMotion`](super::SpringMotion)) is not configuration and is not written (a
/// spring read back starts from wherever its property is).
impl<P: SpringProperty> Serialize for PropertySpring<P>
where
    ValueOf<P>: Serialize,
    OffsetOf<P>: Serialize,
{
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let target_velocity = self.target_rate();
        Written {
            spring: &self.spring,
            target: &self.target,
            velocity: Given(
                self.velocity_change
                    .replace
                    .then(|| self.velocity_change.change()),
            ),
            target_velocity: &target_velocity,
            rest: &self.rest,
            clock: Given(self.clock),
        }
        .serialize(serializer)
    }
}

/// Reads a spring: `spring` (any parametrisation, see [`Spring`]'s `Deserialize`) and
/// `target` are required; `velocity`, `target_velocity`, `rest` and `clock` default to
/// zero, the property's tolerances and the default clock. A non-finite target or velocity
/// is an error, as is an invalid spring.
impl<'de, P: SpringProperty> Deserialize<'de> for PropertySpring<P>
where
    ValueOf<P>: Deserialize<'de>,
    OffsetOf<P>: Deserialize<'de>,
{
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let read = Read::<ValueOf<P>, OffsetOf<P>>::deserialize(deserializer)?;
        if !P::Space::is_valid(read.target) {
            return Err(de::Error::custom(format_args!(
                "spring target {:?} is not finite",
                read.target
            )));
        }
        let mut spring = Self::new(read.spring, read.target);
        let mut target_velocity = spring.target_rate();
        let starts_moving = read.velocity.0.is_some();
        let mut velocity = OffsetOf::<P>::ZERO;
        for (name, given, field) in [
            ("velocity", read.velocity, &mut velocity),
            (
                "target_velocity",
                read.target_velocity,
                &mut target_velocity,
            ),
        ] {
            if let Given(Some(value)) = given {
                if !value.is_finite() {
                    return Err(de::Error::custom(format_args!(
                        "spring {name} {value:?} is not finite"
                    )));
                }
                *field = value;
            }
        }
        spring.target_velocity = target_velocity.into();
        spring.velocity_change = VelocityChange::new(starts_moving, velocity);
        spring.clock = read.clock.0;
        if let Given(Some(rest)) = read.rest {
            spring.set_rest(rest);
        }
        Ok(spring)
    }
}
