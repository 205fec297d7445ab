//! Values that are vectors, and values that must not cross zero.

use core::marker::PhantomData;

use bevy::math::{Vec3, Vec3A};
use bevy::reflect::{FromReflect, Reflectable};

use super::seal::FastPath;
use super::spring_space::{Carried, SpringSpace};
use super::vector::SpringVector;

/// A value that is itself a vector: the offset is `value − target`. Positions, sizes, volumes,
/// angles, anything a tween would lerp.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::space::Linear;
///
/// #[derive(Component)]
/// struct Volume(f32);
///
/// spring_property!(
///     /// `Volume`'s level.
///     VolumeLevel: Volume::0 as Linear<f32>
/// );
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugins::default(), SpringPropertyPlugin::<VolumeLevel>::default()));
/// app.world_mut().spawn((Volume(0.0), PropertySpring::<VolumeLevel>::new(Spring::smooth(), 1.0)));
/// ```
pub struct Linear<V>(PhantomData<fn() -> V>);

/// A value that is a vector, and the vector its offsets and velocities are kept in: the same
/// type, or for `Vec3` the SIMD-aligned `Vec3A` (the step then moves all three components in
/// one instruction each; the conversion is exact).
pub trait LinearValue:
    Copy
    + PartialEq
    + Default
    + core::fmt::Debug
    + Send
    + Sync
    + Reflectable
    + FromReflect
    + From<Self::Offset>
    + Into<Self::Offset>
{
    /// The vector the offsets and velocities are kept in.
    type Offset: SpringVector;

    /// The value in the offset's type (exactly).
    #[must_use]
    fn to_offset(self) -> Self::Offset;

    /// The value back from the offset's type (exactly).
    #[must_use]
    fn from_offset(offset: Self::Offset) -> Self;
}

impl<V: SpringVector + Default> LinearValue for V {
    type Offset = V;

    #[inline]
    fn to_offset(self) -> V {
        self
    }

    #[inline]
    fn from_offset(offset: V) -> V {
        offset
    }
}

impl LinearValue for Vec3 {
    type Offset = Vec3A;

    #[inline]
    fn to_offset(self) -> Vec3A {
        Vec3A::from(self)
    }

    #[inline]
    fn from_offset(offset: Vec3A) -> Vec3 {
        Vec3::from(offset)
    }
}

impl<V: LinearValue> SpringSpace for Linear<V> {
    type Value = V;
    type Offset = V::Offset;
    type Velocity = V;

    #[inline]
    fn is_valid(value: V) -> bool {
        value.to_offset().is_finite()
    }

    #[inline]
    fn magnitude(value: V) -> f32 {
        value.to_offset().max_magnitude()
    }

    #[inline]
    fn offset(value: V, target: V) -> V::Offset {
        value.to_offset() - target.to_offset()
    }

    #[inline]
    fn at_offset(target: V, offset: V::Offset) -> V {
        V::from_offset(target.to_offset() + offset)
    }

    #[inline]
    fn carried_offset(value: V, target: V) -> Carried<V::Offset> {
        Carried::difference(value.to_offset(), target.to_offset())
    }

    /// `(target + offset) + remainder`: exact where the value is far smaller than its target
    /// (the first sum cancels exactly, Sterbenz) and the remainder holds its fine digits.
    #[inline]
    fn at_carried(target: V, offset: Carried<V::Offset>) -> V {
        V::from_offset((target.to_offset() + offset.offset) + offset.remainder)
    }

    /// Compared in the offset's type: one vector comparison for a `Vec3`.
    #[inline]
    fn same(a: V, b: V, _: FastPath) -> bool {
        a.to_offset() == b.to_offset()
    }

    #[inline]
    fn is_written(current: V, target: V, offset: Carried<V::Offset>, _: FastPath) -> bool {
        (target.to_offset() + offset.offset) + offset.remainder == current.to_offset()
    }

    /// The offset from the new target is the old offset plus how far the target moved: no digit
    /// of the offset is lost to the value's rounding.
    #[inline]
    fn retarget(
        old_target: V,
        new_target: V,
        offset: Carried<V::Offset>,
        velocity: V::Offset,
    ) -> (Carried<V::Offset>, V::Offset) {
        (
            offset.plus(old_target.to_offset() - new_target.to_offset()),
            velocity,
        )
    }
}

/// A space whose value has linear coordinates with `value = coordinates(target) + offset`:
/// [`Linear`] and the UI lengths. [`NeverThroughZero`] needs it to find zero.
pub trait AffineSpace: SpringSpace {
    /// The coordinates of `value`, in the offset's space.
    #[must_use]
    fn coordinates(value: Self::Value) -> Self::Offset;
}

impl<V: LinearValue> AffineSpace for Linear<V> {
    #[inline]
    fn coordinates(value: V) -> V::Offset {
        value.to_offset()
    }
}

/// The space `S` (by default [`Linear`]), with overshoot kept from carrying a value across zero:
/// scales and sizes.
///
/// When a step would carry a component across zero *away from* its target's side (a bouncy
/// pop-out to scale 0, a panel collapsing to width 0), the component stops exactly at zero with
/// its velocity cleared, instead of mirroring the sprite or giving layout a negative size. A
/// target on the other side of zero is still reached: that crossing is asked for.
pub struct NeverThroughZero<S>(PhantomData<fn() -> S>);

impl<S: AffineSpace> SpringSpace for NeverThroughZero<S> {
    type Value = S::Value;
    type Offset = S::Offset;
    type Velocity = S::Velocity;

    #[inline]
    fn is_valid(value: Self::Value) -> bool {
        S::is_valid(value)
    }

    #[inline]
    fn magnitude(value: Self::Value) -> f32 {
        S::magnitude(value)
    }

    #[inline]
    fn offset(value: Self::Value, target: Self::Value) -> Self::Offset {
        S::offset(value, target)
    }

    #[inline]
    fn at_offset(target: Self::Value, offset: Self::Offset) -> Self::Value {
        S::at_offset(target, offset)
    }

    #[inline]
    fn carried_offset(value: Self::Value, target: Self::Value) -> Carried<Self::Offset> {
        S::carried_offset(value, target)
    }

    #[inline]
    fn at_carried(target: Self::Value, offset: Carried<Self::Offset>) -> Self::Value {
        S::at_carried(target, offset)
    }

    #[inline]
    fn is_written(
        current: Self::Value,
        target: Self::Value,
        offset: Carried<Self::Offset>,
        _: FastPath,
    ) -> bool {
        S::is_written(current, target, offset, FastPath)
    }

    /// A retarget moves no value, but the offset from the new target is rounded: where that
    /// would put the value a rounding across zero (a size at exactly 0 given a larger target),
    /// it is put exactly on zero (the velocity is kept).
    #[inline]
    fn retarget(
        old_target: Self::Value,
        new_target: Self::Value,
        offset: Carried<Self::Offset>,
        velocity: Self::Offset,
    ) -> (Carried<Self::Offset>, Self::Offset) {
        let (after, velocity) = S::retarget(old_target, new_target, offset, velocity);
        let coordinates = S::coordinates(new_target);
        // The value before the retarget, measured from the new target (only its sign counts).
        let was = ((S::coordinates(old_target) + offset.offset) + offset.remainder) - coordinates;
        let [offset, remainder, _] =
            SpringVector::stop_at_zero(coordinates, was, [after.offset, after.remainder, velocity]);
        (Carried { remainder, offset }, velocity)
    }

    #[inline]
    fn constrain(
        target: Self::Value,
        before: Self::Offset,
        after: Carried<Self::Offset>,
        velocity: Self::Offset,
    ) -> (Carried<Self::Offset>, Self::Offset) {
        let (after, velocity) = S::constrain(target, before, after, velocity);
        let [offset, remainder, velocity] = SpringVector::stop_at_zero(
            S::coordinates(target),
            before,
            [after.offset, after.remainder, velocity],
        );
        (Carried { remainder, offset }, velocity)
    }

    /// Only where no component may have crossed zero: a step that may is the general one.
    #[inline]
    fn constrain_usual(
        target: Self::Value,
        before: Self::Offset,
        after: Carried<Self::Offset>,
        velocity: Self::Offset,
        _: FastPath,
    ) -> Option<(Carried<Self::Offset>, Self::Offset)> {
        let (after, velocity) = S::constrain_usual(target, before, after, velocity, FastPath)?;
        SpringVector::keeps_sign(S::coordinates(target), before, after.offset, FastPath)
            .then_some((after, velocity))
    }

    #[inline]
    fn constrains_usual_step(_: FastPath) -> bool {
        true
    }

    const DEFAULT_REST: sprung::RestThreshold<f32> = S::DEFAULT_REST;
}

impl<S: AffineSpace> AffineSpace for NeverThroughZero<S> {
    #[inline]
    fn coordinates(value: Self::Value) -> Self::Offset {
        S::coordinates(value)
    }
}
