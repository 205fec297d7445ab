//! UI lengths (`Val`), sprung in the unit of their target.

use bevy::math::Vec2;
use bevy::ui::{Val, Val2};

use super::linear::AffineSpace;
use super::seal::FastPath;
use super::spring_space::{Carried, SpringSpace};

/// The number of a length in its own unit (pixels for `Px`, percent for `Percent`, …); 0 for
/// `Auto`.
#[inline]
fn number(value: Val) -> f32 {
    match value {
        Val::Px(n) | Val::Percent(n) | Val::Vw(n) | Val::Vh(n) | Val::VMin(n) | Val::VMax(n) => n,
        Val::Auto => 0.0,
    }
}

/// `number` in the unit of `unit` (pixels where `unit` is `Auto`).
#[inline]
fn in_unit_of(unit: Val, number: f32) -> Val {
    let mut value = unit;
    match &mut value {
        Val::Px(n) | Val::Percent(n) | Val::Vw(n) | Val::Vh(n) | Val::VMin(n) | Val::VMax(n) => {
            *n = number;
        }
        Val::Auto => return Val::Px(number),
    }
    value
}

/// Whether two pairs of lengths are in the same units, axis by axis (`Auto` is its own): with
/// equal numbers, they are `==`.
#[inline]
fn same_units(a: Val2, b: Val2) -> bool {
    use core::mem::discriminant;
    (discriminant(&a.x) == discriminant(&b.x)) & (discriminant(&a.y) == discriminant(&b.y))
}

/// Whether `value` can be read in `target`'s unit: the same unit, or `Auto` (read as 0).
#[inline]
fn same_unit(value: Val, target: Val) -> bool {
    matches!(value, Val::Auto)
        || core::mem::discriminant(&value) == core::mem::discriminant(&target)
}

/// The offset of one length from its target, in the target's unit; 0 (start from the target)
/// when the units differ.
#[inline]
fn length_offset(value: Val, target: Val) -> f32 {
    if same_unit(value, target) {
        number(value) - number(target)
    } else {
        0.0
    }
}

/// A UI length (`Val`), sprung on its number in the target's unit.
///
/// A `left: Val::Percent(10.0)` sprung to `Val::Percent(50.0)` slides to 50 %, as a tween
/// between two values of one unit would. Units are not converted into one another (that needs
/// the layout): a field in another unit than its target jumps to the target and springs on from
/// there, and `Auto` reads as 0 in the target's unit (a target of `Auto` is 0 pixels). Rests
/// within a twentieth of a unit and half a unit per second: invisible in pixels, and about a
/// pixel in the relative units (a percent of a 1920-pixel parent is 19 pixels), where half a
/// pixel's tolerance would snap visibly.
pub struct Length;

impl SpringSpace for Length {
    type Value = Val;
    type Offset = f32;
    type Velocity = f32;

    #[inline]
    fn is_valid(value: Val) -> bool {
        number(value).is_finite()
    }

    #[inline]
    fn magnitude(value: Val) -> f32 {
        number(value).abs()
    }

    #[inline]
    fn offset(value: Val, target: Val) -> f32 {
        length_offset(value, target)
    }

    #[inline]
    fn at_offset(target: Val, offset: f32) -> Val {
        in_unit_of(target, number(target) + offset)
    }

    #[inline]
    fn carried_offset(value: Val, target: Val) -> Carried<f32> {
        if same_unit(value, target) {
            Carried::difference(number(value), number(target))
        } else {
            Carried::new(0.0)
        }
    }

    #[inline]
    fn at_carried(target: Val, offset: Carried<f32>) -> Val {
        in_unit_of(target, (number(target) + offset.offset) + offset.remainder)
    }

    #[inline]
    fn retarget(
        old_target: Val,
        new_target: Val,
        offset: Carried<f32>,
        velocity: f32,
    ) -> (Carried<f32>, f32) {
        if same_unit(old_target, new_target) {
            (
                offset.plus(number(old_target) - number(new_target)),
                velocity,
            )
        } else {
            (Carried::new(0.0), velocity)
        }
    }

    const DEFAULT_REST: sprung::RestThreshold<f32> = LENGTH_REST;
}

impl AffineSpace for Length {
    #[inline]
    fn coordinates(value: Val) -> f32 {
        number(value)
    }
}

/// A twentieth of a unit, and half a unit per second.
const LENGTH_REST: sprung::RestThreshold<f32> = sprung::RestThreshold {
    offset: 0.05,
    speed: 0.5,
};

/// A pair of UI lengths (`Val2`, as `UiTransform::translation`), each sprung as [`Length`] in
/// its target's unit.
pub struct Length2;

impl SpringSpace for Length2 {
    type Value = Val2;
    type Offset = Vec2;
    type Velocity = Vec2;

    #[inline]
    fn is_valid(value: Val2) -> bool {
        Length::is_valid(value.x) && Length::is_valid(value.y)
    }

    #[inline]
    fn magnitude(value: Val2) -> f32 {
        Length::magnitude(value.x).max(Length::magnitude(value.y))
    }

    #[inline]
    fn offset(value: Val2, target: Val2) -> Vec2 {
        Vec2::new(
            length_offset(value.x, target.x),
            length_offset(value.y, target.y),
        )
    }

    #[inline]
    fn at_offset(target: Val2, offset: Vec2) -> Val2 {
        Val2::new(
            Length::at_offset(target.x, offset.x),
            Length::at_offset(target.y, offset.y),
        )
    }

    #[inline]
    fn carried_offset(value: Val2, target: Val2) -> Carried<Vec2> {
        let (x, y) = (
            Length::carried_offset(value.x, target.x),
            Length::carried_offset(value.y, target.y),
        );
        Carried {
            offset: Vec2::new(x.offset, y.offset),
            remainder: Vec2::new(x.remainder, y.remainder),
        }
    }

    #[inline]
    fn at_carried(target: Val2, offset: Carried<Vec2>) -> Val2 {
        let axis = |pick: fn(Vec2) -> f32| Carried {
            offset: pick(offset.offset),
            remainder: pick(offset.remainder),
        };
        Val2::new(
            Length::at_carried(target.x, axis(|v| v.x)),
            Length::at_carried(target.y, axis(|v| v.y)),
        )
    }

    /// `==`, which needs equal numbers (`Val` counts zeros of any two units equal, and `Auto`
    /// as 0 only to itself): tested first, as one vector, so that values that differ (a
    /// moving spring's) are told apart without `==`'s branches on the units.
    #[inline]
    fn same(a: Val2, b: Val2, _: FastPath) -> bool {
        Self::coordinates(a) == Self::coordinates(b) && a == b
    }

    /// `==` of `current` and [`at_carried`](SpringSpace::at_carried)'s value, the usual case
    /// (the units are the target's, pixels for `Auto`, and the numbers the carried sums, added
    /// as one vector in the same order) told without building the value; the rest (another
    /// unit, or numbers that differ, which `==` may still count equal at zero) by `==`.
    #[inline]
    fn is_written(current: Val2, target: Val2, offset: Carried<Vec2>, _: FastPath) -> bool {
        let units = Val2::new(in_unit_of(target.x, 0.0), in_unit_of(target.y, 0.0));
        let numbers = (Self::coordinates(target) + offset.offset) + offset.remainder;
        (same_units(current, units) & (Self::coordinates(current) == numbers))
            || current == Self::at_carried(target, offset)
    }

    #[inline]
    fn retarget(
        old_target: Val2,
        new_target: Val2,
        offset: Carried<Vec2>,
        velocity: Vec2,
    ) -> (Carried<Vec2>, Vec2) {
        let axis = |offset: Carried<Vec2>, pick: fn(Vec2) -> f32| Carried {
            offset: pick(offset.offset),
            remainder: pick(offset.remainder),
        };
        let (x, vx) = Length::retarget(
            old_target.x,
            new_target.x,
            axis(offset, |v| v.x),
            velocity.x,
        );
        let (y, vy) = Length::retarget(
            old_target.y,
            new_target.y,
            axis(offset, |v| v.y),
            velocity.y,
        );
        (
            Carried {
                offset: Vec2::new(x.offset, y.offset),
                remainder: Vec2::new(x.remainder, y.remainder),
            },
            Vec2::new(vx, vy),
        )
    }

    const DEFAULT_REST: sprung::RestThreshold<f32> = LENGTH_REST;
}

impl AffineSpace for Length2 {
    #[inline]
    fn coordinates(value: Val2) -> Vec2 {
        Vec2::new(number(value.x), number(value.y))
    }
}

#[cfg(test)]
mod tests {
    use crate::space::seal::FastPath;
    use bevy::math::Vec2;
    use bevy::ui::{Val, Val2};

    use super::Length2;
    use crate::space::spring_space::{Carried, SpringSpace};

    /// Lengths in every unit and `Auto`, with numbers at the edges: zeros of both signs, a
    /// subnormal, the largest, an infinity and NaN.
    fn lengths() -> Vec<Val> {
        let numbers = [
            0.0,
            -0.0,
            1.5,
            -700.25,
            1.0e-40,
            f32::MAX,
            f32::INFINITY,
            f32::NAN,
        ];
        let mut all = vec![Val::Auto];
        for n in numbers {
            all.extend([
                Val::Px(n),
                Val::Percent(n),
                Val::Vw(n),
                Val::Vh(n),
                Val::VMin(n),
                Val::VMax(n),
            ]);
        }
        all
    }

    /// `Length2`'s `same` and `is_written`, which compare units and numbers apart, decide as
    /// `==` of the values does, on every pair of edge lengths in one axis (and a few in the
    /// other), toward every target, from carried offsets with and without a remainder.
    #[test]
    fn the_pair_tests_decide_as_the_values_compare() {
        let lengths = lengths();
        let others = [
            Val::Auto,
            Val::Px(3.0),
            Val::Percent(3.0),
            Val::Px(f32::NAN),
            Val::Percent(0.0),
            Val::Vw(-0.0),
        ];
        let offsets = [
            Carried::new(Vec2::ZERO),
            Carried {
                offset: Vec2::new(2.5, -0.75),
                remainder: Vec2::new(1.0e-7, -2.0e-8),
            },
            Carried::new(Vec2::new(-1.5, 700.25)),
        ];
        let mut checked = 0;
        for &ax in &lengths {
            for &bx in &lengths {
                for &ay in &others {
                    for &by in &others {
                        let (a, b) = (Val2::new(ax, ay), Val2::new(bx, by));
                        assert_eq!(Length2::same(a, b, FastPath), a == b, "{a:?} {b:?}");
                        for offset in offsets {
                            let written = Length2::at_carried(b, offset) == a;
                            assert_eq!(
                                Length2::is_written(a, b, offset, FastPath),
                                written,
                                "{a:?} toward {b:?} at {offset:?}"
                            );
                            checked += usize::from(written);
                        }
                    }
                }
            }
        }
        // Written values among them, not only refusals.
        assert!(checked > 100, "{checked}");
    }
}
