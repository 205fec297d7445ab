//! The chain step's internal mirror of `Transform`: the same pose, in four-lane vectors, so
//! that composing poses down a chain is done a vector at a time.

use bevy::prelude::*;

/// A translation, rotation and scale, composed as [`Transform`]'s are.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Pose {
    pub(super) translation: Vec3A,
    pub(super) rotation: Quat,
    pub(super) scale: Vec3A,
}

impl From<Transform> for Pose {
    #[inline]
    fn from(transform: Transform) -> Self {
        Self {
            translation: transform.translation.into(),
            rotation: transform.rotation,
            scale: transform.scale.into(),
        }
    }
}

impl Pose {
    /// The pose of `local` under this one (as [`Transform::mul_transform`]).
    #[inline]
    #[must_use]
    pub(super) fn then(self, local: Self) -> Self {
        Self {
            translation: self.point(local.translation),
            rotation: self.rotation * local.rotation,
            scale: self.scale * local.scale,
        }
    }

    /// Where `point`, given in this pose's axes, is (as [`Transform::transform_point`]).
    #[inline]
    #[must_use]
    pub(super) fn point(self, point: Vec3A) -> Vec3A {
        self.translation + self.rotation * (self.scale * point)
    }
}
