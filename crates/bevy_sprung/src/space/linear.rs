//! Values that are vectors, and values that must not cross zero.

use core::marker::PhantomData;

use super::{Carried, SpringSpace, SpringVector};

/// A value that is itself a vector: the offset is `value − target`. Positions, sizes, volumes,
/// angles, anything a tween would lerp.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
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
/// app.add_plugins((MinimalPlugins, SpringPlugin::default(), SpringPropertyPlugin::<VolumeLevel>::default()));
/// app.world_mut().spawn((Volume(0.0), PropertySpring::<VolumeLevel>::new(Spring::smooth(), 1.0)));
/// ```
pub struct Linear<V>(PhantomData<fn() -> V>);

impl<V: SpringVector + Default> SpringSpace for Linear<V> {
    type Value = V;
    type Offset = V;

    #[inline]
    fn is_valid(value: V) -> bool {
        value.is_finite()
    }

    #[inline]
    fn magnitude(value: V) -> f32 {
        value.max_magnitude()
    }

    #[inline]
    fn offset(value: V, target: V) -> V {
        value - target
    }

    #[inline]
    fn at_offset(target: V, offset: V) -> V {
        target + offset
    }

    /// The offset from the new target is the old offset plus how far the target moved: no digit
    /// of the offset is lost to the value's rounding.
    #[inline]
    fn retarget(old_target: V, new_target: V, offset: Carried<V>, velocity: V) -> (Carried<V>, V) {
        (offset.plus(old_target - new_target), velocity)
    }
}

/// A space whose value has linear coordinates with `value = coordinates(target) + offset`:
/// [`Linear`] and the UI lengths. [`NeverThroughZero`] needs it to find zero.
pub trait AffineSpace: SpringSpace {
    /// The coordinates of `value`, in the offset's space.
    #[must_use]
    fn coordinates(value: Self::Value) -> Self::Offset;
}

impl<V: SpringVector + Default> AffineSpace for Linear<V> {
    #[inline]
    fn coordinates(value: V) -> V {
        value
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
    fn is_written(current: Self::Value, target: Self::Value, offset: Self::Offset) -> bool {
        S::is_written(current, target, offset)
    }

    #[inline]
    fn retarget(
        old_target: Self::Value,
        new_target: Self::Value,
        offset: Carried<Self::Offset>,
        velocity: Self::Offset,
    ) -> (Carried<Self::Offset>, Self::Offset) {
        S::retarget(old_target, new_target, offset, velocity)
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
        (Carried { offset, remainder }, velocity)
    }

    const DEFAULT_REST: sprung::RestThreshold<f32> = S::DEFAULT_REST;
}

impl<S: AffineSpace> AffineSpace for NeverThroughZero<S> {
    #[inline]
    fn coordinates(value: Self::Value) -> Self::Offset {
        S::coordinates(value)
    }
}
