//! A high-precision reference for the spring transition, with `dashu-float` at 320 bits.
//!
//! It shares no code with the crate: `b = c/(2m)` and `ω² = k/m` are formed exactly from the
//! inputs (so the rounding of `b` and `ω²` that any `f32`/`f64` algorithm suffers shows up as
//! error, bounded by the condition numbers computed here), and the regimes use the textbook
//! formulas, which are accurate at this precision: the modal form for `z > 1e-6` (the direct
//! `cosh`/`sinh` form would lose `2st·log₂e` bits), the trigonometric form for `z < −1e-6`, and
//! the series in `z` between.

#![allow(
    dead_code,
    reason = "each test crate uses a different part of this shared helper"
)]

use dashu_float::FBig;
use dashu_float::ops::Abs;
use dashu_float::round::mode::HalfEven;

/// Working precision in bits.
pub(crate) const PRECISION: usize = 320;

/// A 320-bit float.
pub(crate) type Big = FBig<HalfEven>;

/// `x` exactly, at the working precision.
pub(crate) fn big(x: f64) -> Big {
    Big::try_from(x)
        .expect("finite input")
        .with_precision(PRECISION)
        .value()
}

/// Rounds to the nearest `f64`.
pub(crate) fn to_f64(x: &Big) -> f64 {
    x.to_f64().value()
}

/// The exact transition quantities for one `(b, ω², t)`.
#[derive(Clone, Debug)]
pub(crate) struct Exact {
    /// `[[f0, f1], [−ω²f1, g]]`.
    pub(crate) matrix: [[Big; 2]; 2],
    /// `g0 = ∫₀ᵗ f1`.
    pub(crate) g0: Big,
}

/// Evaluates the transition for half-rate `b`, `ω²` and `t`, all at the working precision.
pub(crate) fn exact(b: &Big, w2: &Big, t: &Big) -> Exact {
    let zero = big(0.0);
    let one = big(1.0);
    let two = big(2.0);
    let z = (b * b - w2) * t * t;
    let threshold = big(1e-6);
    let bt = b * t;
    let (f0, f1, g);
    // Spectral radius times t, and g0 where the time series is not the right tool.
    let (rho_t, modal_g0);
    if z.clone().abs() <= threshold {
        // C(z) = Σ zⁿ/(2n)!, S(z) = Σ zⁿ/(2n+1)!, to far below the working precision.
        let mut c = one.clone();
        let mut s = one.clone();
        let mut term_c = one.clone();
        let mut term_s = one.clone();
        let tiny = big(2f64.powi(-340));
        for n in 1..200 {
            let n2 = big(f64::from(2 * n));
            term_c = &term_c * &z / (&n2 * (&n2 - &one));
            term_s = &term_s * &z / (&n2 * (&n2 + &one));
            c = &c + &term_c;
            s = &s + &term_s;
            if term_c.clone().abs() < tiny && term_s.clone().abs() < tiny {
                break;
            }
        }
        let e = (-bt.clone()).exp();
        f1 = &e * t * &s;
        f0 = &e * (&c + &bt * &s);
        g = &e * (&c - &bt * &s);
        rho_t = &bt + z.clone().abs().sqrt();
        modal_g0 = None;
    } else if z > zero {
        let s = (b * b - w2).sqrt();
        // λ = b − s without cancellation: ω²/(b + s).
        let fast = b + &s;
        let slow = w2 / &fast;
        let e1 = (-(&slow * t)).exp();
        let e2 = (-(&fast * t)).exp();
        f1 = (&e1 - &e2) / (&two * &s);
        f0 = &e1 + &slow * &f1;
        g = &e2 - &slow * &f1;
        rho_t = &fast * t;
        // g0 = [(1 − e^{−λt})/λ − (1 − e^{−μt})/μ]/(2s).
        let integral = |rate: &Big| {
            if rate == &zero {
                t.clone()
            } else {
                -(-(rate * t)).exp_m1() / rate
            }
        };
        modal_g0 = Some((integral(&slow) - integral(&fast)) / (&two * &s));
    } else {
        let kappa = (w2 - b * b).sqrt();
        let (sn, cs) = (&kappa * t).sin_cos();
        let e = (-bt.clone()).exp();
        f1 = &e * &sn / &kappa;
        f0 = &e * &cs + b * &f1;
        g = &e * &cs - b * &f1;
        rho_t = w2.sqrt() * t;
        modal_g0 = None;
    }
    let g0 = if rho_t <= one {
        time_series_g0(b, w2, t)
    } else if let Some(g0) = modal_g0 {
        g0
    } else {
        // ρt > 1 with z ≤ 1e-6 means ω > 0 and 1 − f0 of order one or inherently tiny; at this
        // precision the subtraction costs at most a few dozen of the 320 bits.
        (&one - &f0) / w2
    };
    Exact {
        matrix: [[f0, f1.clone()], [-(w2 * &f1), g]],
        g0,
    }
}

/// `g0` by the Taylor series of `f1` in `t` (used where `1 − f0` is tiny or `ω = 0`; converges
/// for any `t`, quickly for the `t` it is used at).
fn time_series_g0(b: &Big, w2: &Big, t: &Big) -> Big {
    let two_bt = big(2.0) * b * t;
    let w2t2 = w2 * t * t;
    let mut previous = big(0.0);
    let mut current = t.clone();
    let mut sum = t / big(2.0);
    let tiny = big(2f64.powi(-360));
    for m in 1..100_000 {
        let mf = big(f64::from(m));
        let next = -(&two_bt * &mf * &current + &w2t2 * &previous) / (&mf * (&mf + big(1.0)));
        previous = current;
        current = next;
        let term = &current / (&mf + big(2.0));
        sum = &sum + &term;
        // Two negligible terms in a row: single terms vanish exactly at times (every other one
        // when b = 0; u₃ when 2bt = ω²t² = 1).
        let negligible = |x: &Big| x.clone().abs() <= &tiny * sum.clone().abs();
        if negligible(&current) && negligible(&previous) {
            break;
        }
    }
    sum * t
}

/// The reference for one spring and step, with per-entry sensitivities.
#[derive(Clone, Debug)]
pub(crate) struct Reference {
    /// The exact matrix.
    pub(crate) matrix: [[f64; 2]; 2],
    /// The exact `D = M − I`.
    pub(crate) increment: [[f64; 2]; 2],
    /// The exact `g0`.
    pub(crate) g0: f64,
    /// `|b·∂M/∂b| + |ω²·∂M/∂ω²| + |t·∂M/∂t|` per entry: the error any algorithm inherits from
    /// rounding `b`, `ω²` and `t` is `u` times this.
    pub(crate) sensitivity: [[f64; 2]; 2],
    /// The same for `g0`.
    pub(crate) g0_sensitivity: f64,
}

impl Reference {
    /// `|computed − exact|/(u·(|exact| + sensitivity) + floor)` per matrix entry: the error in
    /// units of roundoff times the condition number, with `floor` added to the allowance for
    /// results at the underflow threshold.
    pub(crate) fn matrix_error_ratios(
        &self,
        computed: [[f64; 2]; 2],
        u: f64,
        floor: f64,
    ) -> [f64; 4] {
        ratios(&self.matrix, &self.sensitivity, computed, u, floor)
    }

    /// The same for `D = M − I`, whose entries are measured against their own size.
    pub(crate) fn increment_error_ratios(
        &self,
        computed: [[f64; 2]; 2],
        u: f64,
        floor: f64,
    ) -> [f64; 4] {
        ratios(&self.increment, &self.sensitivity, computed, u, floor)
    }

    /// The same for the forcing gain `g0`.
    pub(crate) fn g0_error_ratio(&self, computed: f64, u: f64, floor: f64) -> f64 {
        let error = (computed - self.g0).abs();
        let allowance = u * (self.g0.abs() + self.g0_sensitivity) + floor;
        if error == 0.0 { 0.0 } else { error / allowance }
    }
}

fn ratios(
    exact: &[[f64; 2]; 2],
    sensitivity: &[[f64; 2]; 2],
    computed: [[f64; 2]; 2],
    u: f64,
    floor: f64,
) -> [f64; 4] {
    let mut out = [0.0; 4];
    for i in 0..2 {
        for j in 0..2 {
            let error = (computed[i][j] - exact[i][j]).abs();
            let allowance = u * (exact[i][j].abs() + sensitivity[i][j]) + floor;
            out[2 * i + j] = if error == 0.0 { 0.0 } else { error / allowance };
        }
    }
    out
}

/// The reference for mass `m`, stiffness `k`, damping `c` and step `dt`, all exact inputs.
pub(crate) fn reference(m: f64, k: f64, c: f64, dt: f64) -> Reference {
    let (m, k, c, t) = (big(m), big(k), big(c), big(dt));
    let b = &c / (big(2.0) * &m);
    let w2 = &k / &m;
    let center = exact(&b, &w2, &t);
    // Logarithmic derivatives x·∂M/∂x by central differences with a relative step of 2⁻⁶⁰:
    // the truncation error is ~2⁻¹²⁰ relative, far below what the ratios resolve.
    let h = big(2f64.powi(-60));
    let log_derivative = |perturb: &dyn Fn(&Big) -> Exact| -> ([[Big; 2]; 2], Big) {
        let plus = perturb(&(big(1.0) + &h));
        let minus = perturb(&(big(1.0) - &h));
        let d = |a: &Big, b: &Big| (a - b) / (big(2.0) * &h);
        (
            [
                [
                    d(&plus.matrix[0][0], &minus.matrix[0][0]),
                    d(&plus.matrix[0][1], &minus.matrix[0][1]),
                ],
                [
                    d(&plus.matrix[1][0], &minus.matrix[1][0]),
                    d(&plus.matrix[1][1], &minus.matrix[1][1]),
                ],
            ],
            d(&plus.g0, &minus.g0),
        )
    };
    let (db, db_g0) = log_derivative(&|scale| exact(&(&b * scale), &w2, &t));
    let (dw, dw_g0) = log_derivative(&|scale| exact(&b, &(&w2 * scale), &t));
    // t·∂M/∂t = t·A·M with A = [[0, 1], [−ω², −2b]]; t·∂g0/∂t = t·f1.
    let mm = &center.matrix;
    let dt_m = [
        [&t * &mm[1][0], &t * &mm[1][1]],
        [
            &t * (-(&w2 * &mm[0][0]) - big(2.0) * &b * &mm[1][0]),
            &t * (-(&w2 * &mm[0][1]) - big(2.0) * &b * &mm[1][1]),
        ],
    ];
    let dt_g0 = &t * &mm[0][1];
    let f = |x: &Big| to_f64(x).abs();
    let mut sensitivity = [[0.0; 2]; 2];
    let mut matrix = [[0.0; 2]; 2];
    let mut increment = [[0.0; 2]; 2];
    for i in 0..2 {
        for j in 0..2 {
            sensitivity[i][j] = f(&db[i][j]) + f(&dw[i][j]) + f(&dt_m[i][j]);
            matrix[i][j] = to_f64(&mm[i][j]);
            increment[i][j] = to_f64(&mm[i][j]);
        }
    }
    // D₀₀ = f0 − 1 = −ω²·g0 and D₁₁ = g − 1 = −(ω²·g0 + 2b·f1): the identities give D to full
    // relative precision even where M − I would cancel (to 2⁻³²⁰ of 1, not of D).
    let w2g0 = &w2 * &center.g0;
    increment[0][0] = to_f64(&-w2g0.clone());
    increment[1][1] = to_f64(&-(&w2g0 + big(2.0) * &b * &mm[0][1]));
    Reference {
        matrix,
        increment,
        g0: to_f64(&center.g0),
        sensitivity,
        g0_sensitivity: f(&db_g0) + f(&dw_g0) + f(&dt_g0),
    }
}
