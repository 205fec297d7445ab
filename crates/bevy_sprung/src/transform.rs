//! `Transform`s: translation, rotation and scale.

use bevy::prelude::*;
use sprung::RestThreshold;

use crate::space::{Linear, NeverThroughZero, ShortestArc};
use crate::spring::PropertySpring;

/// A scale rests ten times finer than a position: a ten-thousandth of its size.
const SCALE_REST: RestThreshold<f32> = RestThreshold {
    offset: 1e-4,
    speed: 1e-3,
};

spring_property!(
    /// `Transform::translation`.
    pub Translation: Transform::translation as Linear<Vec3>
);

spring_property!(
    /// `Transform::rotation`, the short way round ([`ShortestArc`]), with an angular velocity in
    /// rad/s.
    pub Rotation: Transform::rotation as ShortestArc
);

spring_property!(
    /// `Transform::scale`, kept from passing through zero ([`NeverThroughZero`]): a pop-out to
    /// scale 0 lands on 0 instead of flipping the sprite. A target of the other sign is still
    /// reached. Use [`SignedScale`] to let the spring mirror freely.
    pub Scale: Transform::scale as NeverThroughZero<Linear<Vec3>>, rest: SCALE_REST
);

spring_property!(
    /// `Transform::scale` with no constraint: overshoot may carry it through zero (a mirror
    /// flip).
    pub SignedScale: Transform::scale as Linear<Vec3>, rest: SCALE_REST
);

/// A spring on [`Transform::translation`].
pub type TranslationSpring = PropertySpring<Translation>;
/// A spring on [`Transform::rotation`] (shortest arc, angular velocity in rad/s).
pub type RotationSpring = PropertySpring<Rotation>;
/// A spring on [`Transform::scale`] that does not pass through zero.
pub type ScaleSpring = PropertySpring<Scale>;
/// A spring on [`Transform::scale`] that may pass through zero (mirror).
pub type SignedScaleSpring = PropertySpring<SignedScale>;
