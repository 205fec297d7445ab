//! [`SpringSpace`]: how a value springs, through an offset from its target carried between
//! steps ([`Carried`]).

use core::fmt::Debug;

use bevy::reflect::{FromReflect, Reflectable};

use super::seal::FastPath;
use super::vector::SpringVector;

/// An offset carried between steps as an unevaluated sum `offset + remainder`, where the
/// remainder holds what rounding dropped from `offset` (compensated summation).
///
/// A step adds a small increment to the offset. Far from the target, an increment below half a
/// unit in the offset's last place (a slow spring's first frames, a high frame rate) would round
/// away and the spring would not start; near it, the value itself cannot hold the offset. With
/// the remainder neither happens: the offset moves exactly as the closed form says.
///
/// The remainder is laid out first, so that a [`SpringMotion`](crate::spring::SpringMotion) can
/// keep its velocity right after the offset: the state `[offset, velocity]` of a `Vec2` spring
/// is one 16-byte load.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Carried<V> {
    /// What the exact offset adds to `offset`: below a unit in its last place.
    pub remainder: V,
    /// The offset, rounded.
    pub offset: V,
}

impl<V: SpringVector> Carried<V> {
    /// An offset known exactly.
    #[inline]
    #[must_use]
    pub fn new(offset: V) -> Self {
        Self {
            offset,
            remainder: V::ZERO,
        }
    }

    /// `a − b` exactly, as a rounded difference and its error (Knuth's TwoSum, which needs no
    /// ordering of the magnitudes).
    #[inline]
    #[must_use]
    pub fn difference(a: V, b: V) -> Self {
        let minus_b = -b;
        let offset = a + minus_b;
        let b_part = offset - a;
        let a_part = offset - b_part;
        Self {
            offset,
            remainder: (a - a_part) + (minus_b - b_part),
        }
    }

    /// The offset plus `increment`: Dekker's Fast2Sum keeps in the remainder what the rounded
    /// sum drops (exact while the offset is at least as large as the increment, the case where
    /// it matters; otherwise within a unit in the last place of the increment).
    #[inline]
    #[must_use]
    pub fn plus(self, increment: V) -> Self {
        let increment = increment + self.remainder;
        let offset = self.offset + increment;
        Self {
            offset,
            remainder: increment - (offset - self.offset),
        }
    }
}

/// How a value of type [`Value`](Self::Value) springs: the vector space
/// ([`Offset`](Self::Offset)) its offset from the target moves in, and the maps between the
/// two.
///
/// The maps must be inverse to rounding: `offset(at_offset(t, y), t) ≈ y`, and
/// `at_offset(t, 0) == t` exactly (a spring at rest writes its target exactly). For any
/// finite offset whose squared norm is finite, [`at_offset`](Self::at_offset) must return a
/// valid value (clamped where the space has a range); that is what lets the plugin check only
/// the offset on its hot path.
///
/// # Example
/// A space of your own: a brightness kept in `[0, 1]`.
/// ```
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::space::SpringSpace;
///
/// struct UnitInterval;
///
/// impl SpringSpace for UnitInterval {
///     type Value = f32;
///     type Offset = f32;
///     type Velocity = f32;
///     fn is_valid(value: f32) -> bool { value.is_finite() }
///     fn magnitude(_: f32) -> f32 { 1.0 }
///     fn offset(value: f32, target: f32) -> f32 { value - target }
///     fn at_offset(target: f32, offset: f32) -> f32 { (target + offset).clamp(0.0, 1.0) }
/// }
/// ```
pub trait SpringSpace: Send + Sync + 'static {
    /// The value as the component stores it, and the type of the target (for a rotation, a
    /// `Quat`).
    type Value: Copy + PartialEq + Default + Debug + Send + Sync + Reflectable + FromReflect;
    /// The space the offset from the target moves in (for a rotation, the rotation vector):
    /// what the step computes with, a SIMD type where one helps (`Vec3A` for `Vec3` values).
    type Offset: SpringVector;
    /// The type velocities and impulses are read in: usually the offset's, but the value's own
    /// vector type where the offset is a SIMD stand-in for it (`Vec3`, not `Vec3A`). A spring
    /// stores its target velocity in this type (the narrower one keeps the component small).
    type Velocity: Copy
        + PartialEq
        + core::fmt::Debug
        + Send
        + Sync
        + Reflectable
        + FromReflect
        + From<Self::Offset>
        + Into<Self::Offset>;

    /// Whether `value` can be a target (finite, and for a rotation of non-zero length).
    #[must_use]
    fn is_valid(value: Self::Value) -> bool;

    /// The size of a value, for what `f32` resolves near it: a rest tolerance below the
    /// spacing of `f32` at this magnitude is raised to it (see
    /// [`RestThreshold::at_magnitude`](sprung::RestThreshold::at_magnitude)). For vectors the
    /// largest component; for rotations and colours 1.
    #[must_use]
    fn magnitude(value: Self::Value) -> f32;

    /// The offset of `value` from `target`.
    #[must_use]
    fn offset(value: Self::Value, target: Self::Value) -> Self::Offset;

    /// The value at `offset` from `target`: the inverse of [`offset`](Self::offset), kept in the
    /// value's valid range.
    #[must_use]
    fn at_offset(target: Self::Value, offset: Self::Offset) -> Self::Value;

    /// The offset of `value` from `target` as a carried sum (see [`Carried`]). The default
    /// rounds [`offset`](Self::offset); a vector space keeps the exact difference, so that a
    /// value far smaller than its target loses none of its digits to the offset.
    #[inline]
    #[must_use]
    fn carried_offset(value: Self::Value, target: Self::Value) -> Carried<Self::Offset> {
        Carried::new(Self::offset(value, target))
    }

    /// The value at the carried offset `offset` from `target`: what the spring writes. The
    /// default is [`at_offset`](Self::at_offset) of the rounded offset; a vector space adds the
    /// remainder too, so that a value far smaller than its target (a scale springing from 1
    /// toward 700) keeps the digits its offset cannot hold.
    #[inline]
    #[must_use]
    fn at_carried(target: Self::Value, offset: Carried<Self::Offset>) -> Self::Value {
        Self::at_offset(target, offset.offset)
    }

    /// The offset after the target moved from `old_target` to `new_target`, as a sum
    /// `(offset, remainder)` (see [`Carried`]), and the velocity. The default keeps the value
    /// where it is and the velocity as it is; a rotation re-expresses the velocity so that the
    /// angular velocity in the world is kept; a vector keeps every digit of its offset.
    #[inline]
    #[must_use]
    fn retarget(
        old_target: Self::Value,
        new_target: Self::Value,
        offset: Carried<Self::Offset>,
        velocity: Self::Offset,
    ) -> (Carried<Self::Offset>, Self::Offset) {
        let value = Self::at_offset(old_target, offset.offset);
        (Carried::new(Self::offset(value, new_target)), velocity)
    }

    /// Keeps a step's result in range: `before` is the offset at the start of the step toward
    /// `target`, `after` the offset and `velocity` the velocity at its end. The default changes
    /// nothing; [`NeverThroughZero`](super::NeverThroughZero) stops a value at zero.
    ///
    /// For a finite `after` and `velocity` it must return finite ones for which
    /// [`at_carried`](Self::at_carried) gives a valid value: the plugin's usual step bounds
    /// the step's result, and does not test it again after this.
    #[inline]
    #[must_use]
    fn constrain(
        target: Self::Value,
        before: Self::Offset,
        after: Carried<Self::Offset>,
        velocity: Self::Offset,
    ) -> (Carried<Self::Offset>, Self::Offset) {
        let _ = (target, before);
        (after, velocity)
    }

    /// The tolerances at which a spring in this space counts as at rest, in its units:
    /// [`RestThreshold::DEFAULT`](sprung::RestThreshold::DEFAULT) (a thousandth of a unit, a
    /// hundredth of a unit per second) unless the space says otherwise.
    const DEFAULT_REST: sprung::RestThreshold<f32> = sprung::RestThreshold::<f32>::DEFAULT;

    // The plugin's fast path, below: sealed (each takes a `FastPath` token, which no code
    // outside this crate can name, so none can call or override them) and hidden from the
    // docs, with defaults that are right for any space (from the maps above). A space of the
    // plugin's overrides them with cheaper exact tests.

    /// Whether two values are the same (a spring writes a value only if it is not the same as
    /// the one the property holds). `==` unless the space knows a cheaper exact test.
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn same(a: Self::Value, b: Self::Value, _: FastPath) -> bool {
        a == b
    }

    /// Whether the property holds what the spring wrote for `offset` from `target`: then the
    /// spring goes on from its own, carried offset (the value holds fewer digits than the
    /// offset; keeping them is what makes springs arrive); otherwise something else wrote
    /// `current`, and the spring starts over from [`offset`](Self::offset)`(current, target)`.
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn is_written(
        current: Self::Value,
        target: Self::Value,
        offset: Carried<Self::Offset>,
        _: FastPath,
    ) -> bool {
        Self::at_carried(target, offset) == current
    }

    /// [`constrain`](Self::constrain) in the plugin's usual step, which may leave the step to
    /// the general one (`None`, the state untouched) where constraining it is the uncommon
    /// case: the per-spring loop then holds no code for it. By default `constrain`'s result;
    /// [`NeverThroughZero`](super::NeverThroughZero) leaves a step that may cross zero to the
    /// general step.
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn constrain_usual(
        target: Self::Value,
        before: Self::Offset,
        after: Carried<Self::Offset>,
        velocity: Self::Offset,
        _: FastPath,
    ) -> Option<(Carried<Self::Offset>, Self::Offset)> {
        Some(Self::constrain(target, before, after, velocity))
    }

    /// Whether [`constrain_usual`](Self::constrain_usual) may leave a step to the general one
    /// (`false` by default; [`NeverThroughZero`](super::NeverThroughZero) may). The usual step
    /// then tests whether something else wrote the value together with the constraint, after
    /// the step, in one branch for both; otherwise it tests it before the step, where the test
    /// waits on nothing.
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn constrains_usual_step(_: FastPath) -> bool {
        false
    }
}
