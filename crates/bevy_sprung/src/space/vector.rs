//! The vectors offsets move in: Bevy's [`NormedVectorSpace`] over `f32`, plus the component-wise
//! operations a spring needs to stay finite and in range.

use super::seal::FastPath;
use bevy::math::{NormedVectorSpace, Vec2, Vec3A, Vec4, Vec4Swizzles};
use bevy::reflect::{FromReflect, Reflectable};

/// A vector an offset and a velocity can be: `f32`, `Vec2`, `Vec3A` or `Vec4`, or a type of your
/// own with a norm. (A `Vec3` value springs with `Vec3A` offsets, see
/// [`LinearValue`](super::LinearValue).)
///
/// The spring arithmetic is [`NormedVectorSpace`]'s (`+`, `−`, scaling, the squared norm for the
/// rest test); this adds what it leaves out and a spring needs component by component.
pub trait SpringVector:
    NormedVectorSpace<Scalar = f32> + PartialEq + Send + Sync + Reflectable + FromReflect
{
    /// Whether every component is finite.
    #[must_use]
    fn is_finite(self) -> bool;

    /// Each component clamped into the finite range `[−f32::MAX, f32::MAX]`, NaN made 0: what a
    /// step that overflows keeps, so the spring stays finite and still arrives.
    #[must_use]
    fn saturate(self) -> Self;

    /// The largest component's magnitude.
    #[must_use]
    fn max_magnitude(self) -> f32;

    /// Per component `i`, with `c = coordinates`: where `c + before` and the value
    /// `(c + after) + remainder` lie on opposite sides of zero (the remainder counts only where
    /// `c + after` is zero: elsewhere it cannot change the sign), and `c` lies on the side of
    /// `c + before` (an overshoot carrying the value away from its target across zero), `after`
    /// becomes `−c` (the value exactly 0) and that component of `remainder` and `velocity` 0. See
    /// [`NeverThroughZero`](super::NeverThroughZero).
    #[must_use]
    fn stop_at_zero(coordinates: Self, before: Self, after: [Self; 3]) -> [Self; 3];

    // The plugin's fast path, below: sealed (each takes a `FastPath` token, which no code
    // outside this crate can name, so none can call or override them) and hidden from the
    // docs, with defaults that are right for any vector (from the methods above and
    // `NormedVectorSpace`). The plugin's own vectors override them with shorter sequences of
    // vector instructions, bit for bit the same results.

    /// Whether, with `c = coordinates`, every component of `c + before` and `c + after` has
    /// the same sign and none is zero: then [`stop_at_zero`](Self::stop_at_zero) changes
    /// nothing, and the usual step need not call it. Exact where both sums are finite (the
    /// usual step's are: its state is within the transition table's step limit); a component
    /// with an infinite or NaN sum may go either way. By default `false` (a step of a
    /// [`NeverThroughZero`](super::NeverThroughZero) spring is then always the general one).
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn keeps_sign(coordinates: Self, before: Self, after: Self, _: FastPath) -> bool {
        let _ = (coordinates, before, after);
        false
    }

    /// Whether a state of `offset` and `velocity` steps on: it is not at rest (the squared
    /// lengths of both within their tolerances `rest_squared`), and each squared length is at
    /// most `limit` (a NaN is not). By default from [`NormedVectorSpace::norm_squared`] of
    /// each.
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn steps_on(
        offset: Self,
        velocity: Self,
        rest_squared: (f32, f32),
        limit: f32,
        _: FastPath,
    ) -> bool {
        steps_on_by_norms(offset, velocity, rest_squared, limit)
    }

    /// What one step adds to an `offset` and a `velocity`, with a transition's increments
    /// `[d00, d01, d10, d11]` (its matrix less the identity): `offset·d00 + velocity·d01` and
    /// `velocity·d11 + offset·d10`. By default with the vector's own arithmetic.
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn step_increments(
        offset: Self,
        velocity: Self,
        increments: Vec4,
        _: FastPath,
    ) -> (Self, Self) {
        step_increments_by_parts(offset, velocity, increments)
    }

    /// Whether the usual step reads this vector's increments as pairs (see
    /// [`step_paired_increments`](Self::step_paired_increments)): the table of transitions
    /// then also keeps them so, 32 bytes a slot instead of 16, for a vector that multiplies
    /// them without a shuffle. `false` by default.
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn paired_increments(_: FastPath) -> bool {
        false
    }

    /// [`step_increments`](Self::step_increments) with the increments as the pairs
    /// `[d00, d00, d11, d11]` and `[d10, d10, d01, d01]` (see `paired_increments`): a two-lane
    /// vector multiplies its state `[offset, velocity]` by the first, and by the second with
    /// the halves of the product swapped. By default the increments are read back out of the
    /// pairs for [`step_increments`](Self::step_increments).
    #[doc(hidden)]
    #[inline]
    #[must_use]
    fn step_paired_increments(
        offset: Self,
        velocity: Self,
        [diagonal, cross]: [Vec4; 2],
        _: FastPath,
    ) -> (Self, Self) {
        let increments = Vec4::new(diagonal.x, cross.z, cross.x, diagonal.z);
        Self::step_increments(offset, velocity, increments, FastPath)
    }
}

/// A transition's `increments` `[d00, d01, d10, d11]` as the pairs `[d00, d00, d11, d11]`
/// and `[d10, d10, d01, d01]` that [`SpringVector::step_paired_increments`] reads.
#[inline]
#[must_use]
pub(crate) fn paired_increments(increments: Vec4) -> [Vec4; 2] {
    [increments.xxww(), increments.zzyy()]
}

/// Whether squared offset and speed `(offset, speed)` are both within their rest tolerances
/// `rest_squared` (a NaN is not): what rest is, for the usual step and the general one.
#[expect(
    clippy::needless_bitwise_bool,
    reason = "non-short-circuit `&` on the per-entity hot path: one branch instead of several"
)]
#[inline]
pub(crate) fn is_within_rest((offset, speed): (f32, f32), rest_squared: (f32, f32)) -> bool {
    (offset <= rest_squared.0) & (speed <= rest_squared.1)
}

/// [`SpringVector::steps_on`] from each part's squared norm.
#[expect(
    clippy::needless_bitwise_bool,
    reason = "non-short-circuit `&` on the per-entity hot path: one branch instead of several"
)]
#[inline]
fn steps_on_by_norms<V: SpringVector>(
    offset: V,
    velocity: V,
    rest_squared: (f32, f32),
    limit: f32,
) -> bool {
    let squared = (offset.norm_squared(), velocity.norm_squared());
    (squared.0 <= limit) & (squared.1 <= limit) & !is_within_rest(squared, rest_squared)
}

/// [`SpringVector::step_increments`] with the vector's own arithmetic.
#[inline]
fn step_increments_by_parts<V: SpringVector>(offset: V, velocity: V, increments: Vec4) -> (V, V) {
    let [d00, d01, d10, d11] = increments.to_array();
    (offset * d00 + velocity * d01, velocity * d11 + offset * d10)
}

/// [`SpringVector::stop_at_zero`] on arrays: `[after, remainder, velocity]`, out of line: it
/// runs only where a component may have crossed zero.
#[cold]
#[inline(never)]
fn stop_at_zero<const N: usize>(
    coordinates: [f32; N],
    before: [f32; N],
    [mut after, mut remainder, mut velocity]: [[f32; N]; 3],
) -> [[f32; N]; 3] {
    for i in 0..N {
        let target = coordinates[i];
        // Where the value is, `(target + after) + remainder`: the remainder (below half a
        // unit in the last place of `after`) decides its sign only where `target + after` is
        // exactly zero, where an offset landing on zero with a negative remainder would
        // otherwise write a value a rounding below it.
        let rounded = target + after[i];
        let is = if rounded == 0.0 {
            remainder[i]
        } else {
            rounded
        };
        let was = target + before[i];
        if (was >= 0.0 && is < 0.0 && target >= 0.0) || (was <= 0.0 && is > 0.0 && target <= 0.0) {
            after[i] = -target;
            remainder[i] = 0.0;
            velocity[i] = 0.0;
        }
    }
    [after, remainder, velocity]
}

/// A component into `[−MAX, MAX]`, NaN to 0.
#[inline]
fn saturate(x: f32) -> f32 {
    if x.is_nan() {
        0.0
    } else {
        x.clamp(-f32::MAX, f32::MAX)
    }
}

impl SpringVector for f32 {
    #[inline]
    fn is_finite(self) -> bool {
        f32::is_finite(self)
    }

    #[inline]
    fn saturate(self) -> Self {
        saturate(self)
    }

    #[inline]
    fn max_magnitude(self) -> f32 {
        self.abs()
    }

    #[inline]
    fn stop_at_zero(coordinates: f32, before: f32, after: [f32; 3]) -> [f32; 3] {
        if Self::keeps_sign(coordinates, before, after[0], FastPath) {
            return after;
        }
        stop_at_zero([coordinates], [before], after.map(|x| [x])).map(|[x]| x)
    }

    /// See the vectors' test below.
    #[inline]
    fn keeps_sign(coordinates: f32, before: f32, after: f32, _: FastPath) -> bool {
        (coordinates + before) * (coordinates + after) > 0.0
    }
}

macro_rules! glam_vector {
    ($t:ty $(, { $($packed:tt)* })?) => {
        impl SpringVector for $t {
            #[inline]
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }

            #[inline]
            fn saturate(self) -> Self {
                <$t>::from_array(self.to_array().map(saturate))
            }

            #[inline]
            fn max_magnitude(self) -> f32 {
                self.abs().max_element()
            }

            #[inline]
            fn stop_at_zero(coordinates: Self, before: Self, after: [Self; 3]) -> [Self; 3] {
                // `keeps_sign`'s test, strict where a sum is infinite (`0·∞` is NaN): every
                // product positive.
                let (was, is) = (coordinates + before, coordinates + after[0]);
                if (was * is).cmpgt(<$t>::ZERO).all() {
                    return after;
                }
                stop_at_zero(
                    coordinates.to_array(),
                    before.to_array(),
                    after.map(|v| v.to_array()),
                )
                .map(<$t>::from_array)
            }

            /// Every component keeps its sign, none is zero: none crossed zero (or reached
            /// it), and the full test would change nothing. The usual case, tested on all
            /// lanes at once so that the step around it keeps its vector arithmetic (a product
            /// that underflows to 0 only sends it to the full test). No product `≤ 0`, against
            /// a zero the loop keeps in a register (every product `> 0` took a fresh zero every
            /// spring). The two differ only on a NaN product, which finite sums cannot give.
            #[inline]
            fn keeps_sign(coordinates: Self, before: Self, after: Self, _: FastPath) -> bool {
                let (was, is) = (coordinates + before, coordinates + after);
                !(was * is).cmple(<$t>::ZERO).any()
            }

            $($($packed)*)?
        }
    };
}

glam_vector!(Vec2, {
    /// Both at once, in one four-lane vector `[offset, velocity]` (a `Vec2` is two lanes of
    /// one): each square added to its neighbour's (`x + y` as `Vec2::length_squared` sums,
    /// and `y + x`, the same bits), so that the squared lengths come out in pairs without a
    /// shuffle of their own, compared with `[rest offset, limit, rest speed, limit]`, and the
    /// four outcomes read as one bit of a constant (shorter than the shared test).
    #[inline]
    fn steps_on(
        offset: Vec2,
        velocity: Vec2,
        rest_squared: (f32, f32),
        limit: f32,
        _: FastPath,
    ) -> bool {
        let state = offset.extend(velocity.x).extend(velocity.y);
        let squares = state * state;
        // [|offset|², |offset|², |velocity|², |velocity|²] (x + y and y + x: the same bits).
        let lengths = squares + squares.yxwz();
        let rest = Vec2::from(rest_squared).extend(0.0).extend(0.0);
        let bounds = interleave_low(rest, Vec4::splat(limit));
        // Bits 0 and 2: at rest; 1 and 3: in range. In range and not both at rest: 10, 11 or
        // 14 (a NaN length is neither).
        let within = lengths.cmple(bounds).bitmask();
        (0b0100_1100_0000_0000_u32 >> within) & 1 != 0
    }

    /// Both at once, in one four-lane vector `[offset, velocity]`: the
    /// [`paired`](paired_increments) step, the same products and sums as two `Vec2`s', in a
    /// third of the instructions.
    #[inline]
    fn step_increments(
        offset: Vec2,
        velocity: Vec2,
        increments: Vec4,
        _: FastPath,
    ) -> (Vec2, Vec2) {
        Self::step_paired_increments(offset, velocity, paired_increments(increments), FastPath)
    }

    #[inline]
    fn paired_increments(_: FastPath) -> bool {
        true
    }

    /// `[d00, d00, d11, d11]` times `[offset, velocity]`, plus `[d10, d10, d01, d01]` times
    /// it with the product's halves swapped: the same products and sums as
    /// [`step_increments`](SpringVector::step_increments)', the pairs multiplied as the table
    /// keeps them and one shuffle, of a product (the state's own halves the compiler would
    /// gather from memory again).
    #[inline]
    fn step_paired_increments(
        offset: Vec2,
        velocity: Vec2,
        [diagonal, cross]: [Vec4; 2],
        _: FastPath,
    ) -> (Vec2, Vec2) {
        let state = offset.extend(velocity.x).extend(velocity.y);
        let sums = diagonal * state + (cross * state).zwxy();
        (sums.xy(), sums.zw())
    }
});
glam_vector!(Vec3A, {
    /// Both squared lengths at once, the squares interleaved (`[x, x', y, y']` and
    /// `[z, z', ·, ·]`) and summed in the order of `Vec3A::length_squared`: `x + y` in lanes 0
    /// and 1 and `y + x`, the same bits, in lanes 2 and 3, so that no shuffle copies them.
    #[inline]
    fn steps_on(
        offset: Vec3A,
        velocity: Vec3A,
        rest_squared: (f32, f32),
        limit: f32,
        _: FastPath,
    ) -> bool {
        let (offset, velocity) = (offset * offset, velocity * velocity);
        let xy = Vec4::new(offset.x, velocity.x, offset.y, velocity.y);
        let z = Vec4::new(offset.z, velocity.z, offset.z, velocity.z);
        steps_on_by_lengths((xy + xy.zwxy()) + z, rest_squared, limit)
    }
});
glam_vector!(Vec4, {
    /// Both squared lengths at once, the squares interleaved (`[x, x', y, y']` and
    /// `[z, z', w, w']`) and summed in the order of `Vec4::length_squared` (lanes 2 and 3 with
    /// the last sum's terms swapped: the same bits).
    #[inline]
    fn steps_on(
        offset: Vec4,
        velocity: Vec4,
        rest_squared: (f32, f32),
        limit: f32,
        _: FastPath,
    ) -> bool {
        let (offset, velocity) = (offset * offset, velocity * velocity);
        let xy = Vec4::new(offset.x, velocity.x, offset.y, velocity.y);
        let zw = Vec4::new(offset.z, velocity.z, offset.w, velocity.w);
        let sums = xy + zw;
        steps_on_by_lengths(sums + sums.zwxy(), rest_squared, limit)
    }
});

/// `[a.x, b.x, a.y, b.y]`: on x86-64 one `unpcklps`. (Built from the lanes, the compiler makes it
/// of scalar moves instead.)
#[inline]
fn interleave_low(a: Vec4, b: Vec4) -> Vec4 {
    #[cfg(all(target_arch = "x86_64", target_feature = "sse"))]
    {
        use core::arch::x86_64::{_mm_loadu_ps, _mm_storeu_ps, _mm_unpacklo_ps};
        let (a, b, mut interleaved) = (a.to_array(), b.to_array(), [0.0; 4]);
        #[expect(
            unsafe_code,
            reason = "an SSE intrinsic: the compiler does not find this shuffle itself"
        )]
        // SAFETY: SSE is enabled (the `cfg` above); each pointer is to a local array of four
        // `f32`s, which the unaligned load and store allow.
        unsafe {
            let lanes = _mm_unpacklo_ps(_mm_loadu_ps(a.as_ptr()), _mm_loadu_ps(b.as_ptr()));
            _mm_storeu_ps(interleaved.as_mut_ptr(), lanes);
        }
        Vec4::from_array(interleaved)
    }
    #[cfg(not(all(target_arch = "x86_64", target_feature = "sse")))]
    {
        Vec4::new(a.x, b.x, a.y, b.y)
    }
}

/// [`SpringVector::steps_on`] from the squared `lengths` `[offset, velocity, offset,
/// velocity]` (each pair computed alike, so that no shuffle copies them): compared at once
/// with `[rest offset, rest speed, limit, limit]`.
#[inline]
fn steps_on_by_lengths(lengths: Vec4, rest_squared: (f32, f32), limit: f32) -> bool {
    let bounds = Vec2::from(rest_squared).extend(limit).extend(limit);
    // Bits 0 and 1: at rest; 2 and 3: in range. Both in range and not both at rest is 12, 13
    // or 14 (a NaN length is neither).
    let within = lengths.cmple(bounds).bitmask();
    within.wrapping_sub(0b1100) < 0b11
}

#[cfg(test)]
mod tests {
    use bevy::math::{Vec2, Vec3A, Vec4};

    use super::{
        FastPath, SpringVector, paired_increments, step_increments_by_parts, stop_at_zero,
    };

    /// What the fast path's examples said: moving and in range steps on; at rest, out of
    /// range or NaN does not; the increments multiply as the matrix says; the paired form gives
    /// the same; the pairs are the increments reordered.
    #[test]
    fn the_fast_path_does_what_its_docs_say() {
        let rest = (0.01_f32.powi(2), 0.1_f32.powi(2));
        assert!(Vec2::steps_on(
            Vec2::new(3.0, 4.0),
            Vec2::ZERO,
            rest,
            1.0e30,
            FastPath
        ));
        assert!(!Vec2::steps_on(
            Vec2::splat(0.001),
            Vec2::splat(0.01),
            rest,
            1.0e30,
            FastPath
        ));
        assert!(!Vec2::steps_on(
            Vec2::new(3.0, 4.0),
            Vec2::ZERO,
            rest,
            24.0,
            FastPath
        ));
        assert!(!Vec2::steps_on(
            Vec2::new(f32::NAN, 0.0),
            Vec2::ZERO,
            rest,
            1.0e30,
            FastPath
        ));
        let increments = Vec4::new(-0.5, 0.25, -2.0, -0.125);
        let (moved, accelerated) = Vec2::step_increments(Vec2::X, Vec2::Y, increments, FastPath);
        assert_eq!(moved, Vec2::new(-0.5, 0.25));
        assert_eq!(accelerated, Vec2::new(-2.0, -0.125));
        let (offset, velocity) = (Vec2::new(1.0, 3.0), Vec2::new(-2.0, 0.5));
        assert_eq!(
            Vec2::step_paired_increments(offset, velocity, paired_increments(increments), FastPath),
            Vec2::step_increments(offset, velocity, increments, FastPath),
        );
        let [diagonal, cross] = paired_increments(Vec4::new(1.0, 2.0, 3.0, 4.0));
        assert_eq!(diagonal, Vec4::new(1.0, 1.0, 4.0, 4.0));
        assert_eq!(cross, Vec4::new(3.0, 3.0, 2.0, 2.0));
    }

    /// Offsets and velocities at the edges: zeros of both signs, tiny, ordinary, huge (squares
    /// that overflow), infinite and NaN components.
    const EDGES: [f32; 12] = [
        0.0,
        -0.0,
        1.0e-30,
        -1.0e-3,
        0.5,
        -3.0,
        1.0e15,
        -1.0e19,
        f32::MAX,
        f32::NEG_INFINITY,
        f32::INFINITY,
        f32::NAN,
    ];

    /// Every `Vec2` whose components are two of [`EDGES`].
    fn edge_vectors() -> impl Iterator<Item = Vec2> {
        EDGES
            .into_iter()
            .flat_map(|x| EDGES.into_iter().map(move |y| Vec2::new(x, y)))
    }

    /// `V::steps_on` decides as the test by each part's norm does, for every pair of
    /// `vectors` and tolerances and limits from zero to infinite; both outcomes are met often.
    fn check_steps_on<V: SpringVector + core::fmt::Debug + Copy>(vectors: &[V]) {
        let rests = [
            (0.0, 0.0),
            (1.0e-6, 1.0e-4),
            (0.25, 9.0),
            (f32::MAX, f32::MAX),
        ];
        let limits = [0.0, 0.25, 9.0, 1.0e30, f32::MAX, f32::INFINITY];
        let mut stepping = 0;
        for &offset in vectors {
            for &velocity in vectors {
                for rest in rests {
                    for limit in limits {
                        let packed = V::steps_on(offset, velocity, rest, limit, FastPath);
                        let by_norms = super::steps_on_by_norms(offset, velocity, rest, limit);
                        assert_eq!(
                            packed, by_norms,
                            "{offset:?} {velocity:?} rest {rest:?} limit {limit}"
                        );
                        stepping += usize::from(packed);
                    }
                }
            }
        }
        let all = vectors.len().pow(2) * rests.len() * limits.len();
        assert!(
            stepping > all / 20 && stepping < all - all / 20,
            "{stepping} of {all}"
        );
    }

    /// The vectors' tests of rest and range, the squared lengths of offset and velocity in
    /// one four-lane vector, decide as the test by each part's norm does: on the boundaries,
    /// where a square overflows, and where a component is infinite or NaN. (They sum the
    /// squares in the order the norms do, so they agree bit for bit.)
    #[test]
    fn the_packed_rest_and_range_tests_agree_with_the_norms() {
        let pairs: Vec<Vec2> = edge_vectors().collect();
        check_steps_on(&pairs);
        // Each lane of the wider vectors meets every edge value, beside others.
        let third = |i: usize| EDGES[(i * 5 + 3) % EDGES.len()];
        let threes: Vec<Vec3A> = (pairs.iter().enumerate())
            .map(|(i, v)| Vec3A::new(v.x, v.y, third(i)))
            .collect();
        check_steps_on(&threes);
        let rotated: Vec<Vec3A> = threes.iter().map(|v| Vec3A::new(v.z, v.x, v.y)).collect();
        check_steps_on(&rotated);
        let fours: Vec<Vec4> = (pairs.iter().enumerate())
            .map(|(i, v)| Vec4::new(v.x, third(i), v.y, third(i + 1)))
            .collect();
        check_steps_on(&fours);
    }

    /// The `Vec2` step, in one four-lane vector, from the increments and from their pairs (the
    /// usual step's), gives the same bits as two `Vec2`s' products and sums (the same
    /// operations on each component, in the same order), on edge values.
    #[test]
    fn the_packed_step_gives_the_same_bits() {
        let increments = [
            Vec4::new(-0.013, 0.016, -1.6, -0.19),
            Vec4::new(-1.0, 0.0, 0.0, -1.0),
            Vec4::new(1.0e-7, -2.5e-3, 3.0e5, 0.5),
            Vec4::new(f32::MAX, -0.0, f32::MIN_POSITIVE, 1.0e-38),
        ];
        let bits = |v: Vec2| v.to_array().map(f32::to_bits);
        for offset in edge_vectors() {
            for velocity in edge_vectors() {
                for increments in increments {
                    let by_parts = step_increments_by_parts(offset, velocity, increments);
                    let packed = Vec2::step_increments(offset, velocity, increments, FastPath);
                    let pairs = paired_increments(increments);
                    let paired = Vec2::step_paired_increments(offset, velocity, pairs, FastPath);
                    for (packed, by_parts) in [
                        (packed.0, by_parts.0),
                        (packed.1, by_parts.1),
                        (paired.0, by_parts.0),
                        (paired.1, by_parts.1),
                    ] {
                        let same = bits(packed) == bits(by_parts)
                            || (packed.is_nan()
                                && by_parts.is_nan()
                                && packed.to_array().map(f32::is_nan)
                                    == by_parts.to_array().map(f32::is_nan));
                        assert!(
                            same,
                            "{offset} {velocity} {increments}: {packed} {by_parts}"
                        );
                    }
                }
            }
        }
    }

    /// The vectors' `stop_at_zero`, which skips the full test where every component keeps its
    /// sign, agrees bit for bit with the full test, component by component: values on both
    /// sides of zero, on it (either zero), far from it, products that underflow or overflow,
    /// infinities and NaN.
    #[test]
    fn the_sign_test_skips_only_what_the_full_test_leaves() {
        let edges = [
            0.0,
            -0.0,
            1e-30,
            -1e-30,
            1e-45,
            -1e-45,
            0.5,
            -0.5,
            1.0,
            -1.0,
            3.0,
            -3.0,
            1e30,
            -1e30,
            f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        let same = |a: [f32; 3], b: [f32; 3]| {
            a.iter()
                .zip(b)
                .all(|(a, b)| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()))
        };
        let (mut checked, mut keeps_checked) = (0, 0);
        for &target in &edges {
            for &before in &edges {
                for &after in &edges {
                    let state = [after, 0.25, -2.0];
                    let full = stop_at_zero([target], [before], state.map(|x| [x])).map(|[x]| x);
                    let fast = f32::stop_at_zero(target, before, state);
                    assert!(
                        same(fast, full),
                        "{target} {before} {after}: {fast:?} {full:?}"
                    );
                    // The same component in each lane of a vector, the others crossing zero
                    // (so that one lane's sign never decides for another's).
                    let lanes = |x: f32, other: f32| [x, other, x, other];
                    let vectors = [
                        lanes(target, 1.0),
                        lanes(before, 2.0),
                        lanes(after, -0.5),
                        lanes(0.25, 0.125),
                        lanes(-2.0, 7.0),
                    ];
                    let [c, b, a, r, v] = vectors;
                    let full = stop_at_zero(c, b, [a, r, v]);
                    let check = |fast: [[f32; 4]; 3], lanes: usize| {
                        for (fast, full) in fast.iter().zip(&full) {
                            for lane in 0..lanes {
                                assert!(
                                    same([fast[lane], 0.0, 0.0], [full[lane], 0.0, 0.0]),
                                    "{target} {before} {after} lane {lane}: {fast:?} {full:?}"
                                );
                            }
                        }
                    };
                    let two = |x: [f32; 4]| Vec2::new(x[0], x[1]);
                    let fast = Vec2::stop_at_zero(two(c), two(b), [two(a), two(r), two(v)]);
                    check(fast.map(|x| [x.x, x.y, 0.0, 0.0]), 2);
                    let three = |x: [f32; 4]| Vec3A::new(x[0], x[1], x[2]);
                    let fast =
                        Vec3A::stop_at_zero(three(c), three(b), [three(a), three(r), three(v)]);
                    check(fast.map(|x| [x.x, x.y, x.z, 0.0]), 3);
                    let four = Vec4::from_array;
                    let fast = Vec4::stop_at_zero(four(c), four(b), [four(a), four(r), four(v)]);
                    check(fast.map(|x| x.to_array()), 4);
                    // `keeps_sign` itself, where it is exact: both sums finite.
                    let (was, is) = (target + before, target + after);
                    if was.is_finite() && is.is_finite() {
                        let keeps = was * is > 0.0;
                        assert_eq!(f32::keeps_sign(target, before, after, FastPath), keeps);
                        let lanes = |x: f32| [x, 1.0, x, 1.0];
                        let [c, b, a] = [lanes(target), lanes(before), lanes(after)];
                        assert_eq!(Vec2::keeps_sign(two(c), two(b), two(a), FastPath), keeps);
                        assert_eq!(
                            Vec3A::keeps_sign(three(c), three(b), three(a), FastPath),
                            keeps,
                            "{target} {before} {after}"
                        );
                        assert_eq!(Vec4::keeps_sign(four(c), four(b), four(a), FastPath), keeps);
                        keeps_checked += 1;
                    }
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, edges.len().pow(3));
        assert!(keeps_checked > edges.len().pow(3) / 2, "{keeps_checked}");
    }
}
