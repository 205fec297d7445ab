//! What a spring can move: a property of a component, and the space it is sprung in.

use core::fmt::Debug;

use bevy::ecs::component::Mutable;
use bevy::math::{Quat, Vec2, Vec3, Vec3A, Vec4};
use bevy::prelude::*;
use bevy::reflect::{GetTypeRegistration, TypePath, Typed};
use sprung::{RestThreshold, SpringValue};

/// The bounds a type needs to be stored in a reflected spring component.
pub trait Reflectable: Reflect + FromReflect + TypePath + Typed + GetTypeRegistration {}

impl<T: Reflect + FromReflect + TypePath + Typed + GetTypeRegistration> Reflectable for T {}

/// A vector space a spring moves in: `f32`, `Vec2`, `Vec3`, `Vec3A` or `Vec4`.
///
/// Each component moves independently with the same transition; the length measures how far a
/// spring is from rest.
pub trait SpringVector:
    SpringValue<f32> + Default + PartialEq + Debug + Send + Sync + Reflectable
{
    /// The Euclidean length.
    #[must_use]
    fn length(self) -> f32;

    /// The squared Euclidean length; like the length, it is not finite when a component is not.
    /// The rest check compares it first and takes [`length`](Self::length) only near rest, and
    /// the step takes a finite squared velocity for a finite velocity. The default squares the
    /// length.
    #[must_use]
    fn length_squared(self) -> f32 {
        let length = self.length();
        length * length
    }

    /// Whether every component is finite.
    #[must_use]
    fn is_finite(self) -> bool;

    /// Per component: a step from `before` to `after` that carries the value across zero away
    /// from `target`'s side (an overshoot) stops at zero, with that component of `velocity`
    /// cleared. Crossing toward a target on the other side is left alone: it was asked for.
    #[must_use]
    fn stop_at_zero(before: Self, after: Self, velocity: Self, target: Self) -> (Self, Self);
}

/// [`SpringVector::stop_at_zero`] on the components.
#[inline]
fn stop_at_zero<const N: usize>(
    before: [f32; N],
    mut after: [f32; N],
    mut velocity: [f32; N],
    target: [f32; N],
) -> ([f32; N], [f32; N]) {
    for i in 0..N {
        let (b, a, t) = (before[i], after[i], target[i]);
        if (b >= 0.0 && a < 0.0 && t >= 0.0) || (b <= 0.0 && a > 0.0 && t <= 0.0) {
            after[i] = 0.0;
            velocity[i] = 0.0;
        }
    }
    (after, velocity)
}

impl SpringVector for f32 {
    #[inline]
    fn length(self) -> f32 {
        self.abs()
    }

    #[inline]
    fn length_squared(self) -> f32 {
        self * self
    }

    #[inline]
    fn is_finite(self) -> bool {
        f32::is_finite(self)
    }

    #[inline]
    fn stop_at_zero(before: f32, after: f32, velocity: f32, target: f32) -> (f32, f32) {
        let ([value], [velocity]) = stop_at_zero([before], [after], [velocity], [target]);
        (value, velocity)
    }
}

macro_rules! glam_vector {
    ($($t:ty),*) => {$(
        impl SpringVector for $t {
            #[inline]
            fn length(self) -> f32 {
                <$t>::length(self)
            }

            #[inline]
            fn length_squared(self) -> f32 {
                <$t>::length_squared(self)
            }

            #[inline]
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }

            #[inline]
            fn stop_at_zero(before: Self, after: Self, velocity: Self, target: Self) -> (Self, Self) {
                let (value, velocity) = stop_at_zero(
                    before.to_array(),
                    after.to_array(),
                    velocity.to_array(),
                    target.to_array(),
                );
                (<$t>::from_array(value), <$t>::from_array(velocity))
            }
        }
    )*};
}

glam_vector!(Vec2, Vec3, Vec3A, Vec4);

/// A property of a component that a [`PropertySpring`](crate::PropertySpring) moves toward a
/// target: how to read and write it, and the linear space it is sprung in.
///
/// Properties that are already vectors (a position, a size, a volume) only need
/// [`LinearProperty`], which implements this trait for them. Implement this trait directly
/// when the value is not a vector space: a rotation is sprung on the rotation vector of its
/// offset from the target, a scale refuses to pass through zero, a colour moves in a
/// perceptual space and keeps its channels in range.
///
/// The step works on the offset `y = offset(value, target)` and its velocity `v` in
/// [`Self::Linear`]: the exact transition moves `(y, v)` toward `y = 0`, and
/// [`advance`](Self::advance) turns the new offset back into a value.
pub trait SpringProperty: TypePath + Send + Sync + 'static {
    /// The component the property lives on.
    type Component: Component<Mutability = Mutable>;
    /// The value as the component stores it (for a rotation, a `Quat`).
    type Value: Copy + PartialEq + Debug + Send + Sync + Reflectable;
    /// The space the spring moves in (for a rotation, the rotation vector: `Vec3`).
    type Linear: SpringVector;

    /// Tolerances at which a spring of this property counts as at rest, in the property's units.
    #[must_use]
    fn default_rest() -> RestThreshold<f32> {
        RestThreshold::new(1e-3, 1e-2)
    }

    /// Reads the property.
    #[must_use]
    fn get(component: &Self::Component) -> Self::Value;

    /// Writes the property.
    fn set(component: &mut Self::Component, value: Self::Value);

    /// Whether a value is finite (a NaN or infinite target is refused).
    #[must_use]
    fn is_finite(value: Self::Value) -> bool;

    /// The offset of `value` from `target` in the linear space.
    #[must_use]
    fn offset(value: Self::Value, target: Self::Value) -> Self::Linear;

    /// The value at `offset` from `target`: the inverse of [`offset`](Self::offset).
    #[must_use]
    fn at_offset(target: Self::Value, offset: Self::Linear) -> Self::Value;

    /// The value after a step moved the offset from `offset` to `new_offset`. The default is
    /// [`at_offset`](Self::at_offset)`(target, new_offset)`; vector properties add the increment
    /// to `value` instead, which keeps all of `value`'s digits when the step is small.
    #[must_use]
    fn advance(
        value: Self::Value,
        target: Self::Value,
        offset: Self::Linear,
        new_offset: Self::Linear,
    ) -> Self::Value {
        let _ = (value, offset);
        Self::at_offset(target, new_offset)
    }

    /// Keeps a stepped value in its valid range (a scale that must not cross zero, alpha in
    /// `[0, 1]`), adjusting the velocity where it was clamped. `before` is the value at the start
    /// of the step. The default changes nothing.
    #[must_use]
    fn constrain(
        before: Self::Value,
        after: Self::Value,
        velocity: Self::Linear,
        target: Self::Value,
    ) -> (Self::Value, Self::Linear) {
        let _ = (before, target);
        (after, velocity)
    }

    /// The velocity to keep when the target changes from `old_target` to `new_target`. The
    /// default keeps it unchanged; a rotation re-expresses it in the new target's frame so that
    /// the angular velocity in the world is kept.
    #[must_use]
    fn retarget_velocity(
        old_target: Self::Value,
        new_target: Self::Value,
        velocity: Self::Linear,
    ) -> Self::Linear {
        let _ = (old_target, new_target);
        velocity
    }
}

/// A property whose value is itself a vector: the offset is `value − target`.
///
/// This is all a user needs to spring a field of their own component.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// #[derive(Component)]
/// struct Volume(f32);
///
/// /// Springs `Volume`'s value.
/// #[derive(Reflect)]
/// struct VolumeLevel;
///
/// impl LinearProperty for VolumeLevel {
///     type Component = Volume;
///     type Value = f32;
///     fn get(volume: &Volume) -> f32 { volume.0 }
///     fn set(volume: &mut Volume, value: f32) { volume.0 = value; }
/// }
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugin::default(), SpringPropertyPlugin::<VolumeLevel>::default()));
/// app.world_mut().spawn((Volume(0.0), PropertySpring::<VolumeLevel>::new(Spring::smooth(), 1.0)));
/// ```
pub trait LinearProperty: TypePath + Send + Sync + 'static {
    /// The component the property lives on.
    type Component: Component<Mutability = Mutable>;
    /// The value, a vector.
    type Value: SpringVector;

    /// Whether an overshoot may not carry a component across zero away from its target's side
    /// (a scale that must not mirror): see [`SpringVector::stop_at_zero`]. `false` by default.
    const NEVER_THROUGH_ZERO: bool = false;

    /// Tolerances at which a spring of this property counts as at rest.
    #[must_use]
    fn default_rest() -> RestThreshold<f32> {
        RestThreshold::new(1e-3, 1e-2)
    }

    /// Reads the property.
    #[must_use]
    fn get(component: &Self::Component) -> Self::Value;

    /// Writes the property.
    fn set(component: &mut Self::Component, value: Self::Value);
}

impl<P: LinearProperty> SpringProperty for P {
    type Component = P::Component;
    type Value = P::Value;
    type Linear = P::Value;

    #[inline]
    fn default_rest() -> RestThreshold<f32> {
        <P as LinearProperty>::default_rest()
    }

    #[inline]
    fn get(component: &Self::Component) -> Self::Value {
        <P as LinearProperty>::get(component)
    }

    #[inline]
    fn set(component: &mut Self::Component, value: Self::Value) {
        <P as LinearProperty>::set(component, value);
    }

    #[inline]
    fn is_finite(value: Self::Value) -> bool {
        SpringVector::is_finite(value)
    }

    #[inline]
    fn offset(value: Self::Value, target: Self::Value) -> Self::Value {
        value - target
    }

    #[inline]
    fn at_offset(target: Self::Value, offset: Self::Value) -> Self::Value {
        target + offset
    }

    #[inline]
    fn advance(
        value: Self::Value,
        _target: Self::Value,
        offset: Self::Value,
        new_offset: Self::Value,
    ) -> Self::Value {
        value + (new_offset - offset)
    }

    #[inline]
    fn constrain(
        before: Self::Value,
        after: Self::Value,
        velocity: Self::Value,
        target: Self::Value,
    ) -> (Self::Value, Self::Value) {
        if P::NEVER_THROUGH_ZERO {
            SpringVector::stop_at_zero(before, after, velocity, target)
        } else {
            (after, velocity)
        }
    }
}

/// `Transform::translation`.
#[derive(Reflect, Debug, Clone, Copy)]
pub struct Translation;

impl LinearProperty for Translation {
    type Component = Transform;
    type Value = Vec3;

    #[inline]
    fn get(transform: &Transform) -> Vec3 {
        transform.translation
    }

    #[inline]
    fn set(transform: &mut Transform, value: Vec3) {
        transform.translation = value;
    }
}

/// `Transform::rotation`, sprung on the rotation vector of the shortest arc from the target,
/// with an angular velocity in rad/s.
///
/// The offset is `log(target⁻¹·rotation)` taken in the hemisphere `w ≥ 0`, so the spring always
/// turns the short way round; the same transition moves its three components. It rests within
/// a thousandth of a radian (0.06°) and a hundredth of a radian per second.
#[derive(Reflect, Debug, Clone, Copy)]
pub struct Rotation;

impl SpringProperty for Rotation {
    type Component = Transform;
    type Value = Quat;
    type Linear = Vec3;

    #[inline]
    fn get(transform: &Transform) -> Quat {
        transform.rotation
    }

    #[inline]
    fn set(transform: &mut Transform, value: Quat) {
        transform.rotation = value;
    }

    #[inline]
    fn is_finite(value: Quat) -> bool {
        value.is_finite() && value.length_squared() > 0.0
    }

    #[inline]
    fn offset(value: Quat, target: Quat) -> Vec3 {
        rotation_vector(target.inverse() * value)
    }

    #[inline]
    fn at_offset(target: Quat, offset: Vec3) -> Quat {
        (target * Quat::from_scaled_axis(offset)).normalize()
    }

    #[inline]
    fn retarget_velocity(old_target: Quat, new_target: Quat, velocity: Vec3) -> Vec3 {
        (new_target.inverse() * old_target) * velocity
    }
}

/// The rotation vector (axis × angle, angle in `[0, π]`) of a unit quaternion, accurate for small
/// angles: `2·atan2(|v|, w)` instead of glam's `2·acos(w)`, which loses half the digits near the
/// identity (an error of ~3e-4 rad in `f32`, far above a spring's rest tolerance).
#[inline]
#[must_use]
pub fn rotation_vector(rotation: Quat) -> Vec3 {
    // q and −q are the same rotation: take the short way.
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

/// `Transform::scale`, kept from passing through zero: when an overshoot would carry a
/// component across zero away from its target, it stops at zero (a pop-out to scale 0 lands on
/// 0 instead of flipping the sprite). A target of the other sign is still reached: that
/// crossing is asked for. Use [`SignedScale`] to let the spring mirror freely.
#[derive(Reflect, Debug, Clone, Copy)]
pub struct Scale;

impl LinearProperty for Scale {
    type Component = Transform;
    type Value = Vec3;
    const NEVER_THROUGH_ZERO: bool = true;

    #[inline]
    fn default_rest() -> RestThreshold<f32> {
        RestThreshold::new(1e-4, 1e-3)
    }

    #[inline]
    fn get(transform: &Transform) -> Vec3 {
        transform.scale
    }

    #[inline]
    fn set(transform: &mut Transform, value: Vec3) {
        transform.scale = value;
    }
}

/// `Transform::scale` with no constraint: overshoot may carry it through zero (a mirror flip).
#[derive(Reflect, Debug, Clone, Copy)]
pub struct SignedScale;

impl LinearProperty for SignedScale {
    type Component = Transform;
    type Value = Vec3;

    #[inline]
    fn default_rest() -> RestThreshold<f32> {
        RestThreshold::new(1e-4, 1e-3)
    }

    #[inline]
    fn get(transform: &Transform) -> Vec3 {
        transform.scale
    }

    #[inline]
    fn set(transform: &mut Transform, value: Vec3) {
        transform.scale = value;
    }
}
