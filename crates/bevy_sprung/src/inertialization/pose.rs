//! A joint's pose and the differences between poses that inertialization decays.

use core::ops::{Add, Mul, Sub};

use bevy::prelude::*;

use crate::space::rotation_vector;

/// A joint's local pose: the three parts of its `Transform`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pose {
    pub(crate) translation: Vec3,
    pub(crate) rotation: Quat,
    pub(crate) scale: Vec3,
}

/// A difference between two poses, or a pose's rate of change: translation, rotation as a
/// rotation vector (axis × angle, in the parent's axes) and scale, each a `Vec3`. Closed under
/// `+`, `−` and scaling, so the decay moves all nine numbers with the same two coefficients.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct PoseDelta {
    pub(crate) translation: Vec3,
    pub(crate) rotation: Vec3,
    pub(crate) scale: Vec3,
}

impl Pose {
    /// The pose of `transform`.
    #[inline]
    pub(crate) fn of(transform: &Transform) -> Self {
        Self {
            translation: transform.translation,
            rotation: transform.rotation,
            scale: transform.scale,
        }
    }

    /// `self − from`: the translation and scale differences and the rotation that takes `from`
    /// to `self` on the short arc, as a rotation vector.
    #[inline]
    pub(crate) fn minus(&self, from: &Self) -> PoseDelta {
        PoseDelta {
            translation: self.translation - from.translation,
            rotation: rotation_vector(self.rotation * from.rotation.inverse()),
            scale: self.scale - from.scale,
        }
    }

    /// `self + delta`: the inverse of [`minus`](Self::minus).
    #[inline]
    pub(crate) fn plus(&self, delta: &PoseDelta) -> Self {
        Self {
            translation: self.translation + delta.translation,
            // Both factors are unit quaternions: the product is one to rounding.
            rotation: Quat::from_scaled_axis(delta.rotation) * self.rotation,
            scale: self.scale + delta.scale,
        }
    }

    /// The rate at which the pose moved from `before` to `self` over `dt` seconds (zero when
    /// `dt` is not positive: no time, no rate).
    #[inline]
    pub(crate) fn rate_since(&self, before: &Self, dt: f32) -> PoseDelta {
        if dt > 0.0 {
            self.minus(before) * dt.recip()
        } else {
            PoseDelta::default()
        }
    }
}

impl PoseDelta {
    /// Whether every number is finite.
    #[inline]
    pub(crate) fn is_finite(&self) -> bool {
        self.translation.is_finite() && self.rotation.is_finite() && self.scale.is_finite()
    }
}

impl Add for PoseDelta {
    type Output = Self;
    #[inline]
    fn add(self, other: Self) -> Self {
        Self {
            translation: self.translation + other.translation,
            rotation: self.rotation + other.rotation,
            scale: self.scale + other.scale,
        }
    }
}

impl Sub for PoseDelta {
    type Output = Self;
    #[inline]
    fn sub(self, other: Self) -> Self {
        Self {
            translation: self.translation - other.translation,
            rotation: self.rotation - other.rotation,
            scale: self.scale - other.scale,
        }
    }
}

impl Mul<f32> for PoseDelta {
    type Output = Self;
    #[inline]
    fn mul(self, factor: f32) -> Self {
        Self {
            translation: self.translation * factor,
            rotation: self.rotation * factor,
            scale: self.scale * factor,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(translation: Vec3, rotation: Quat, scale: Vec3) -> Pose {
        Pose {
            translation,
            rotation,
            scale,
        }
    }

    #[test]
    fn minus_then_plus_is_the_identity() {
        let a = pose(
            Vec3::new(1.0, -2.0, 3.0),
            Quat::from_euler(EulerRot::XYZ, 0.3, -1.2, 2.9),
            Vec3::new(1.0, 2.0, 0.5),
        );
        let b = pose(
            Vec3::new(-4.0, 0.5, 8.0),
            Quat::from_euler(EulerRot::XYZ, -2.0, 0.7, -0.4),
            Vec3::new(0.2, 1.0, 3.0),
        );
        let back = b.plus(&a.minus(&b));
        assert!(back.translation.distance(a.translation) < 1e-5);
        assert!(back.rotation.angle_between(a.rotation) < 1e-5);
        assert!(back.scale.distance(a.scale) < 1e-6);
    }

    #[test]
    fn the_rotation_vector_takes_the_short_arc() {
        // 350° one way is 10° the other.
        let q = Quat::from_rotation_z(350_f32.to_radians());
        let v = rotation_vector(q);
        assert!((v.z + 10_f32.to_radians()).abs() < 1e-5, "{v}");
        assert!(rotation_vector(-q).abs_diff_eq(v, 1e-6));
    }

    #[test]
    fn tiny_rotations_keep_their_digits() {
        // A frame's turn at 240 fps of 0.01 rad/s: acos(w) would give 0 in f32.
        for angle in [4e-5_f32, 1e-3, 1e-7, 1e-12] {
            let v = rotation_vector(Quat::from_axis_angle(Vec3::new(0.6, 0.0, 0.8), angle));
            assert!(
                ((v.length() - angle) / angle).abs() < 1e-5,
                "{angle}: {}",
                v.length()
            );
        }
        assert_eq!(rotation_vector(Quat::IDENTITY), Vec3::ZERO);
    }

    #[test]
    fn a_rate_over_no_time_is_zero() {
        let a = pose(Vec3::ONE, Quat::from_rotation_x(1.0), Vec3::ONE);
        let b = pose(Vec3::ZERO, Quat::IDENTITY, Vec3::ONE);
        assert_eq!(a.rate_since(&b, 0.0), PoseDelta::default());
        let rate = a.rate_since(&b, 0.5);
        assert!(rate.translation.abs_diff_eq(Vec3::splat(2.0), 1e-6));
        assert!(rate.rotation.abs_diff_eq(Vec3::X * 2.0, 1e-5));
    }
}
