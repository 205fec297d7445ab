//! Rotations, the short way round.

use bevy::math::{DQuat, Quat, Rot2, Vec3, Vec3A};

use super::spring_space::{Carried, SpringSpace};

/// A 3D rotation (`Quat`), sprung on the rotation vector of the shortest arc from the target,
/// with an angular velocity in rad/s.
///
/// The offset is `log(target⁻¹·rotation)` taken in the hemisphere `w ≥ 0`, so the spring always
/// turns the short way round; the same transition moves its three components. Retargeting keeps
/// the angular velocity in the world. It rests within a thousandth of a radian (0.06°) and a
/// hundredth of a radian per second.
pub struct ShortestArc;

impl SpringSpace for ShortestArc {
    type Value = Quat;
    type Offset = Vec3A;
    type Velocity = Vec3;

    /// Finite, with a squared length that is a normal `f32` (neither zero, nor subnormal, nor
    /// overflowing): one that normalises exactly.
    #[inline]
    fn is_valid(value: Quat) -> bool {
        value.length_squared().is_normal()
    }

    #[inline]
    fn magnitude(_: Quat) -> f32 {
        1.0
    }

    #[inline]
    fn offset(value: Quat, target: Quat) -> Vec3A {
        rotation_vector(target.inverse() * value).into()
    }

    #[inline]
    fn at_offset(target: Quat, offset: Vec3A) -> Quat {
        (target * turn(offset)).normalize()
    }

    /// The velocity is re-expressed in the new target's frame, so that the angular velocity in
    /// the world is kept.
    #[inline]
    fn retarget(
        old_target: Quat,
        new_target: Quat,
        offset: Carried<Vec3A>,
        velocity: Vec3A,
    ) -> (Carried<Vec3A>, Vec3A) {
        let rotation = Self::at_offset(old_target, offset.offset);
        (
            Carried::new(Self::offset(rotation, new_target)),
            (new_target.inverse() * old_target) * velocity,
        )
    }
}

/// The rotation by the rotation vector `offset`. An angle whose square overflows `f32` (a
/// spring kicked at 10²⁵ rad/s) is turned in `f64`, where `Quat::from_scaled_axis` would divide
/// by an infinite length and return NaN: any finite offset is a rotation.
#[inline]
fn turn(offset: Vec3A) -> Quat {
    if offset.length_squared().is_finite() {
        Quat::from_scaled_axis(offset.into())
    } else {
        huge_turn(offset)
    }
}

/// [`turn`] for angles beyond `1.8·10¹⁹` rad, in `f64` (whose square of `f32::MAX` is finite).
#[cold]
fn huge_turn(offset: Vec3A) -> Quat {
    DQuat::from_scaled_axis(Vec3::from(offset).as_dvec3()).as_quat()
}

/// The rotation vector (axis × angle, angle in `[0, π]`) of a unit quaternion, accurate for small
/// angles: `2·atan2(|v|, w)` instead of glam's `2·acos(w)`, which loses half the digits near the
/// identity (an error of ~3e-4 rad in `f32`, far above a spring's rest tolerance).
///
/// # Example
/// ```
/// use bevy::math::{Quat, Vec3};
/// use bevy_sprung::space::rotation_vector;
///
/// let v = rotation_vector(Quat::from_axis_angle(Vec3::Z, 1e-4));
/// assert!((v.z - 1e-4).abs() < 1e-11);
/// // q and −q are the same rotation: the short way is taken.
/// assert_eq!(rotation_vector(-Quat::from_rotation_x(0.5)), rotation_vector(Quat::from_rotation_x(0.5)));
/// ```
#[inline]
#[must_use]
pub fn rotation_vector(rotation: Quat) -> Vec3 {
    let q = if rotation.w < 0.0 {
        -rotation
    } else {
        rotation
    };
    let v = q.xyz();
    let sine = v.length();
    if sine > 0.0 {
        v * (2.0 * sine.atan2(q.w) / sine)
    } else {
        // atan2(s, w)/s → 1/w as s → 0.
        v * (2.0 / q.w)
    }
}

/// A rotation in a plane (`Rot2`: `UiTransform::rotation`), sprung on the angle of the shortest
/// turn from the target, in radians.
pub struct ShortestAngle;

impl SpringSpace for ShortestAngle {
    type Value = Rot2;
    type Offset = f32;
    type Velocity = f32;

    /// Finite, with a squared length that is a normal `f32` (neither zero, nor subnormal, nor
    /// overflowing): one that normalises exactly (`Rot2::normalize` asserts that it does).
    #[inline]
    fn is_valid(value: Rot2) -> bool {
        value.length_squared().is_normal()
    }

    #[inline]
    fn magnitude(_: Rot2) -> f32 {
        1.0
    }

    /// The angle of `target⁻¹·value`, in `(−π, π]`: the short way.
    #[inline]
    fn offset(value: Rot2, target: Rot2) -> f32 {
        (target.inverse() * value).as_radians()
    }

    #[inline]
    fn at_offset(target: Rot2, offset: f32) -> Rot2 {
        (target * Rot2::radians(offset)).normalize()
    }
}
