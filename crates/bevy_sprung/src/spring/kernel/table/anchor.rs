//! The anchors a frame's transitions are extended from: an exact Taylor extension of each
//! slot's transition from the time step it was last computed at, four slots at a time (one per
//! SSE lane), so that a time step that changes every frame costs a few multiply-adds a slot
//! instead of an `exp` and a `sin`.

use bevy::math::{BVec4A, Mat4, Vec4};
use sprung::{Spring, Transition};

use super::slot::Slot;

/// The data a transition over a nearby time step is extended from: the Taylor coefficients,
/// at `dt`, of `f1` and of `g0 = ∫f1`, and the spring's rates.
#[derive(Clone, Copy, Debug)]
pub(super) struct Anchor {
    /// The time step the coefficients are at.
    dt: f32,
    /// `f1⁽ⁿ⁾(dt)/n!` for `n = 0..=4`.
    pub(super) f1: [f32; 5],
    /// `g0(dt)`: `g0⁽ⁿ⁾ = f1⁽ⁿ⁻¹⁾` for the rest of its series.
    g0: f32,
    /// `ω² = k/m` and `2b = c/m`: `f1'' = −2b·f1' − ω²·f1`.
    omega_squared: f32,
    rate: f32,
    /// The largest `|δ|` the extension is accurate for (below `f32`'s rounding); negative for
    /// no anchor at all.
    pub(super) reach: f32,
}

/// `(ρ·δ)` up to which the degree-4 Taylor extension stays below `f32`'s unit roundoff: its
/// first omitted term is `(ρδ)⁵/5!` of the leading one.
const TAYLOR_REACH: f32 = 0.03;

impl Anchor {
    /// No anchor: nothing is within its reach.
    pub(super) const NONE: Self = Self {
        dt: 0.0,
        f1: [0.0; 5],
        g0: 0.0,
        omega_squared: 0.0,
        rate: 0.0,
        reach: -1.0,
    };

    /// The anchor of `spring`'s `transition` over `dt`.
    pub(super) fn new(spring: &Spring<f32>, dt: f32, transition: &Transition<f32>) -> Self {
        let mass = spring.mass();
        let (omega_squared, rate) = (spring.stiffness() / mass, spring.damping() / mass);
        let [[_, f1], [_, g]] = transition.matrix();
        // ρ ≤ 2b + ω bounds the spectral radius of [[0, 1], [−ω², −2b]].
        let radius = rate + omega_squared.sqrt();
        let reach = if radius > 0.0 {
            TAYLOR_REACH / radius
        } else {
            f32::INFINITY
        };
        // The derivatives from the spring's own equation, computed once here rather than
        // every frame the anchor serves.
        let (w2, d0, d1) = (omega_squared, f1, g);
        let d2 = -rate * d1 - w2 * d0;
        let d3 = -rate * d2 - w2 * d1;
        let d4 = -rate * d3 - w2 * d2;
        Self {
            dt,
            f1: [d0, d1, d2 / 2.0, d3 / 6.0, d4 / 24.0],
            g0: transition.acceleration_gain(),
            omega_squared,
            rate,
            reach: reach.min(0.1 * dt),
        }
    }

    /// A bound on `|d₀₀| + |d₀₁| + |d₁₀| + |d₁₁|` for the increments
    /// [`AnchorLanes::increments`] gives at any `δ` within reach (infinite if not finite),
    /// made once when the anchor is so that a frame's preparation need not sum them.
    ///
    /// With `r` the reach, `F = Σ|cₙ|·rⁿ` bounds `|f1|` and `G = |g0| + Σ|cₙ|·rⁿ⁺¹/(n+1)` bounds
    /// `|g0|` over the reach (each polynomial's terms taken at their largest), and the entries
    /// `−ω²·g0`, `f1`, `−ω²·f1` and `−(ω²·g0 + 2b·f1)` sum to at most
    /// `2ω²·G + (1 + ω² + 2b)·F`. It is computed in `f64` from the same `f32` coefficients and
    /// enlarged by 10⁻⁵, far more than the `f32` evaluation's rounding (a few dozen `u`, with
    /// every coefficient's magnitude counted) can add.
    pub(super) fn bound(&self) -> f32 {
        let r = f64::from(self.reach.max(0.0));
        let c = self.f1.map(|c| f64::from(c).abs());
        let f = c[0] + r * (c[1] + r * (c[2] + r * (c[3] + r * c[4])));
        let g = f64::from(self.g0).abs()
            + r * (c[0] + r * (c[1] / 2.0 + r * (c[2] / 3.0 + r * (c[3] / 4.0 + r * c[4] / 5.0))));
        let (w2, rate) = (
            f64::from(self.omega_squared).abs(),
            f64::from(self.rate).abs(),
        );
        let bound = (2.0 * w2 * g + (1.0 + w2 + rate) * f) * (1.0 + 1.0e-5);
        #[expect(
            clippy::cast_possible_truncation,
            reason = "rounded to the nearest `f32`, within the 10⁻⁵ margin; above `f32`'s range \
                      it becomes infinite"
        )]
        let bound = bound as f32;
        if bound.is_nan() { f32::INFINITY } else { bound }
    }
}

/// The anchors of four consecutive slots, one per lane: a frame's extension runs on the four
/// at once, each vector operation the scalar one in every lane (so a lane's result is, bit for
/// bit, what one anchor alone would give).
#[derive(Clone, Copy, Debug)]
pub(super) struct AnchorLanes {
    dt: Vec4,
    f1: [Vec4; 5],
    g0: Vec4,
    /// `−ω²` and `−2b`, negated once here rather than every frame: a product with a negated
    /// factor is the negated product, bit for bit.
    neg_omega_squared: Vec4,
    neg_rate: Vec4,
    reach: Vec4,
}

impl AnchorLanes {
    /// Every lane the same anchor.
    #[cfg(test)]
    pub(super) fn splat(anchor: &Anchor) -> Self {
        Self {
            dt: Vec4::splat(anchor.dt),
            f1: anchor.f1.map(Vec4::splat),
            g0: Vec4::splat(anchor.g0),
            neg_omega_squared: Vec4::splat(-anchor.omega_squared),
            neg_rate: Vec4::splat(-anchor.rate),
            reach: Vec4::splat(anchor.reach),
        }
    }

    /// Makes lane `lane` `anchor`.
    pub(super) fn set(&mut self, lane: usize, anchor: &Anchor) {
        self.dt[lane] = anchor.dt;
        for (coefficients, coefficient) in self.f1.iter_mut().zip(anchor.f1) {
            coefficients[lane] = coefficient;
        }
        self.g0[lane] = anchor.g0;
        self.neg_omega_squared[lane] = -anchor.omega_squared;
        self.neg_rate[lane] = -anchor.rate;
        self.reach[lane] = anchor.reach;
    }

    /// Each lane's increment matrix over its `dt` (the rows of `D` as vectors over the lanes),
    /// and which lanes are within reach (only those are valid): `f1` and `g0` continued by
    /// their Taylor series in `δ = dt − anchor` (Horner), and
    /// `D = [[−ω²·g0, f1], [−ω²·f1, −(ω²·g0 + 2b·f1)]]`: every entry a sum of terms of one sign
    /// at small `δ`, so nothing cancels (`D₁₁` is not formed as `g − 1`).
    #[inline]
    pub(super) fn increments(&self, dt: Vec4) -> ([Vec4; 4], BVec4A) {
        let h = dt - self.dt;
        // NaN-safe: a NaN or infinite delta is not within reach, nor anything of `NONE`.
        let within = h.abs().cmple(self.reach);
        let [c0, c1, c2, c3, c4] = self.f1;
        let f1 = c0 + h * (c1 + h * (c2 + h * (c3 + h * c4)));
        // g0(dt + h) = g0 + Σ f1⁽ⁿ⁾·hⁿ⁺¹/(n+1)!: the same coefficients over n + 1.
        let g0 = self.g0
            + h * (c0 + h * (c1 * 0.5 + h * (c2 * (1.0 / 3.0) + h * (c3 * 0.25 + h * (c4 * 0.2)))));
        let d00 = self.neg_omega_squared * g0;
        let d11 = d00 + self.neg_rate * f1;
        ([d00, f1, self.neg_omega_squared * f1, d11], within)
    }
}

/// The rows of four lanes' increment matrices, transposed: column `l` is lane `l`'s matrix,
/// row-major.
#[inline]
fn by_lane([d00, d01, d10, d11]: [Vec4; 4]) -> Mat4 {
    Mat4::from_cols(d00, d01, d10, d11).transpose()
}

impl AnchorLanes {
    /// Lanes of no slot yet: their (unused) increments the zeros that an anchor of zeros
    /// reaching everywhere extends to, so that they never need an exact transition.
    pub(super) const EMPTY: Self = Self {
        dt: Vec4::ZERO,
        f1: [Vec4::ZERO; 5],
        g0: Vec4::ZERO,
        neg_omega_squared: Vec4::ZERO,
        neg_rate: Vec4::ZERO,
        reach: Vec4::INFINITY,
    };

    /// Makes the increments of the four slots (`increments`, by lane; `slots`: the slots of
    /// the lanes' part, by reference so that the loop does not store the slice every block,
    /// and this block's index in it) those over their time steps `dt`,
    /// extended together (inline: a game's time step changes every frame, and this is a few
    /// vector multiply-adds per four slots), or computed exactly where out of reach. The
    /// anchors are only read unless one is out of reach: a frame's preparation streams them
    /// and writes the increments, nothing else.
    ///
    /// Raises `bound` to the [`bound`](Anchor::bound)s of the anchors it makes (those of the
    /// others were taken when they were made).
    #[inline]
    pub(super) fn prepare(
        &mut self,
        increments: &mut [Vec4; 4],
        (slots, block): (&&[Slot], usize),
        dt: Vec4,
        bound: &mut f32,
    ) {
        let (rows, within) = self.increments(dt);
        if within.all() {
            let by_lane = by_lane(rows);
            for (lane, increments) in increments.iter_mut().enumerate() {
                *increments = by_lane.col(lane);
            }
        } else {
            self.prepare_lanes(increments, (slots, block), dt, bound);
        }
    }

    /// [`prepare`](Self::prepare) lane by lane: the lanes within reach take their extension
    /// (computed again here rather than passed, which kept the common path storing it), the
    /// others a transition computed exactly (and are anchored there).
    #[cold]
    #[inline(never)]
    fn prepare_lanes(
        &mut self,
        increments: &mut [Vec4; 4],
        (slots, block): (&[Slot], usize),
        dt: Vec4,
        bound: &mut f32,
    ) {
        let slots = slots.get(4 * block..).unwrap_or_default();
        let (rows, within) = self.increments(dt);
        let by_lane = by_lane(rows);
        for (lane, increments) in increments.iter_mut().enumerate() {
            if within.test(lane) {
                *increments = by_lane.col(lane);
            } else if let Some(slot) = slots.get(lane) {
                let (spring, dt) = (slot.spring, dt[lane]);
                let transition = spring.transition(dt);
                let [[d00, d01], [d10, d11]] = transition.increment_matrix();
                *increments = Vec4::new(d00, d01, d10, d11);
                let anchor = Anchor::new(&spring, dt, &transition);
                // The exact increments, which the extension at `δ = 0` matches to a few `u`,
                // are within the anchor's bound too (or make it larger).
                let exact = increments.abs().element_sum();
                let exact = if exact.is_nan() { f32::INFINITY } else { exact };
                *bound = bound.max(anchor.bound()).max(exact);
                self.set(lane, &anchor);
            }
        }
    }
}

#[cfg(test)]
pub(super) mod testing {
    //! What the table's tests share with the anchors': an anchor's extension, and an error
    //! measure.

    use bevy::math::Vec4;
    use sprung::Spring;

    use super::{Anchor, AnchorLanes};

    /// `anchor`'s increments over `dt`, if within reach, from lane `lane` of lanes holding it
    /// there and other anchors elsewhere.
    pub(crate) fn extend(anchor: &Anchor, dt: f32, lane: usize) -> Option<[f32; 4]> {
        let other = Spring::from_natural_frequency(3.0, 0.7).unwrap();
        let mut lanes = AnchorLanes::splat(&Anchor::new(&other, 0.5, &other.transition(0.5)));
        lanes.set(lane, anchor);
        let mut steps = Vec4::splat(0.5);
        steps[lane] = dt;
        let (rows, within) = lanes.increments(steps);
        within.test(lane).then(|| rows.map(|row| row[lane]))
    }

    /// The worst error of the increment matrix `got` against `spring`'s exact one over `dt`
    /// (computed in `f64` for the same `f32` parameters), in units of `f32`'s roundoff
    /// relative to each entry.
    pub(crate) fn error_in_u(got: [f32; 4], spring: Spring<f32>, dt: f64) -> f64 {
        let unit = f64::from(f32::EPSILON) / 2.0;
        let [[e00, e01], [e10, e11]] = Spring::<f64>::from(spring)
            .transition(dt)
            .increment_matrix();
        got.into_iter()
            .zip([e00, e01, e10, e11])
            .map(|(got, want)| (f64::from(got) - want).abs() / (unit * want.abs()))
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use sprung::Spring;

    use super::Anchor;
    use super::testing::{error_in_u, extend};

    /// The worst [`error_in_u`] of an extended increment matrix: over springs from nearly undamped to heavily over-damped, slow to stiff, at frame
    /// rates from 30 to 360 fps, time steps across the anchor's reach on both sides, and every
    /// lane.
    fn worst_extension_error() -> f64 {
        let mut worst = 0.0_f64;
        let mut lane = 0;
        for omega in [0.1_f32, 1.0, 8.0, 40.0, 300.0, 2000.0] {
            for zeta in [0.02_f32, 0.3, 1.0, 1.0001, 4.0, 60.0] {
                let spring = Spring::from_natural_frequency(omega, zeta).unwrap();
                for fps in [30.0_f32, 60.0, 144.0, 360.0] {
                    let dt = 1.0 / fps;
                    let anchor = Anchor::new(&spring, dt, &spring.transition(dt));
                    assert!(anchor.reach > 0.0);
                    for fraction in [-0.99_f32, -0.5, -0.01, 0.01, 0.5, 0.99] {
                        let step = dt + fraction * anchor.reach;
                        lane = (lane + 1) % 4;
                        let extended = extend(&anchor, step, lane).unwrap();
                        worst = worst.max(error_in_u(extended, spring, f64::from(step)));
                    }
                }
            }
        }
        worst
    }

    /// The extension is as accurate as an exactly computed `f32` transition (a few `u` per
    /// entry; every entry is a sum of terms of one sign, so relative error is the measure).
    #[test]
    fn an_extended_transition_is_accurate_to_a_few_roundoffs() {
        let worst = worst_extension_error();
        println!("worst extension error: {worst:.2} u");
        assert!(worst < 8.0, "{worst} u");
    }

    /// Out of reach, and for no anchor at all, there is no extension (a NaN step included).
    #[test]
    fn nothing_is_extended_out_of_reach() {
        let spring = Spring::from_natural_frequency(10.0, 0.5).unwrap();
        let dt = 1.0 / 60.0;
        let anchor = Anchor::new(&spring, dt, &spring.transition(dt));
        for lane in 0..4 {
            assert!(extend(&anchor, dt + 0.99 * anchor.reach, lane).is_some());
            assert!(extend(&anchor, dt + 1.01 * anchor.reach, lane).is_none());
            assert!(extend(&anchor, dt - 1.01 * anchor.reach, lane).is_none());
            assert!(extend(&anchor, f32::NAN, lane).is_none());
            assert!(extend(&anchor, f32::INFINITY, lane).is_none());
            assert!(extend(&Anchor::NONE, 0.0, lane).is_none());
            assert!(extend(&Anchor::NONE, 1.0 / 60.0, lane).is_none());
        }
    }

    /// An anchor's bound holds for every step within its reach: over springs from nearly
    /// undamped to heavily over-damped, slow to stiff, at frame rates from 30 to 360 fps, and
    /// steps across the reach on both sides, the extended increments' absolute sum is within
    /// it, and within a factor 1.5 of the largest of them (the limit stays useful).
    #[test]
    fn an_anchor_bounds_its_extensions() {
        let mut loosest = 1.0_f32;
        for omega in [0.1_f32, 1.0, 8.0, 40.0, 300.0, 2000.0, 1.0e5] {
            for zeta in [0.02_f32, 0.3, 1.0, 1.0001, 4.0, 60.0] {
                let spring = Spring::from_natural_frequency(omega, zeta).unwrap();
                for fps in [30.0_f32, 60.0, 144.0, 360.0] {
                    let dt = 1.0 / fps;
                    let anchor = Anchor::new(&spring, dt, &spring.transition(dt));
                    let bound = anchor.bound();
                    let mut largest = 0.0_f32;
                    for fraction in [-1.0_f32, -0.99, -0.5, 0.0, 0.5, 0.99, 1.0] {
                        for lane in 0..4 {
                            let step = dt + fraction * anchor.reach;
                            let Some(extended) = extend(&anchor, step, lane) else {
                                continue;
                            };
                            let sum: f32 = extended.iter().map(|d| d.abs()).sum();
                            assert!(sum <= bound, "{spring:?} {fps} fps: {sum} > {bound}");
                            largest = largest.max(sum);
                        }
                    }
                    assert!(largest > 0.0, "{spring:?} {fps} fps");
                    loosest = loosest.max(bound / largest);
                }
            }
        }
        println!("loosest anchor bound: {loosest} times the largest sum");
        assert!(loosest < 1.5, "{loosest}");
    }
}
