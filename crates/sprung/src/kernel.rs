//! The stable evaluation of the transition of `x'' + 2b·x' + ω²·x = 0` over a time `t`.
//!
//! With `z = (b² − ω²)·t²`, `C(z) = Σ zⁿ/(2n)!` and `S(z) = Σ zⁿ/(2n+1)!` are entire in `z`, and
//!
//! ```text
//! f1 = e^{−bt}·t·S,   f0 = e^{−bt}·(C + bt·S),   g = e^{−bt}·(C − bt·S),
//! M  = [[f0, f1], [−ω²·f1, g]],   g0 = ∫₀ᵗ f1 = (1 − f0)/ω²,
//! ```
//!
//! analytic straight through critical damping. The regimes below only change how these are
//! evaluated so that no step cancels, overflows or divides by zero; each formula says which.
//!
//! A short step (`ρt ≤ 1`, a frame of any brisk spring) rounded to `f32` needs none of them:
//! its coefficients are sums of one Taylor series in `t` whose terms never cancel, and no
//! `exp`, `sin` or `cos` is called (see [`short_step`]). `f64` results keep the closed forms,
//! whose rounding is a few `f64` units smaller.
//!
//! The evaluation is in `f64` for `f32` springs too, from their exact `f32` parameters, and is
//! rounded to `f32` once: in pure `f32` the rounding of `ω²` alone moves the phase of a long
//! step by `u·ωt` (two radians at `ωt = 3e7`), which an `f64` evaluation avoids for the cost of
//! a few nanoseconds once per spring and frame.

use crate::math::{exp, exp_m1, ln, sin, sin_cos, sqrt};
use crate::modes;

/// Largest `y` for which `e^{−y}` is a normal `f64`: beyond it products with `e^{−y}` are
/// formed in the exponent (see [`Decay`]).
const EXP_NORMAL_LIMIT: f64 = 708.0;

/// `|z| = |b² − ω²|·t²` up to which the series in `z` is used (the band around critical
/// damping): with 4 terms its truncation, `z⁴/8!`, stays below one unit of roundoff.
const BAND_Z: f64 = 1e-3;

/// Most terms the `g0` time series takes: for `ρt ≤ 1` term `n` is at most
/// `t²·(ρt)ⁿ⁻¹/((n−1)!·(n+1))`, below the `f64` unit roundoff of the first from `n = 20` on.
/// Shorter steps need far fewer (12 at `ρt = 0.17`, a 60 fps frame of a brisk spring).
const TIME_SERIES_TERMS: usize = 20;

/// Reciprocals `1/((m+1)·m)` for the `g0` time series recurrence, `m = 1, 2, …`.
const SERIES_RECURRENCE: [f64; 24] = {
    let mut table = [0.0; 24];
    let mut m = 1;
    while m <= 24 {
        table[m - 1] = 1.0 / (((m + 1) * m) as f64);
        m += 1;
    }
    table
};

/// Reciprocals `1/(m+1)` for integrating the time series term by term, `m = 1, 2, …`.
const SERIES_INTEGRAL: [f64; 25] = {
    let mut table = [0.0; 25];
    let mut m = 1;
    while m <= 25 {
        table[m - 1] = 1.0 / ((m + 1) as f64);
        m += 1;
    }
    table
};

/// `1/mᵖ` for `m = 1, 2, …, N`.
const fn reciprocal_powers<const N: usize>(power: u32) -> [f64; N] {
    let mut table = [0.0; N];
    let mut m = 1;
    while m <= N {
        table[m - 1] = 1.0 / (m.pow(power) as f64);
        m += 1;
    }
    table
}

/// Reciprocals `1/m`: the a-priori bound `(ρt)ᵐ/m!` of the series' remaining terms, advanced by
/// a product instead of a division.
const RECIPROCALS: [f64; TIME_SERIES_TERMS] = reciprocal_powers(1);

/// Squared reciprocals `1/m²`: the same bound, squared.
const SQUARED_RECIPROCALS: [f64; TIME_SERIES_TERMS] = reciprocal_powers(2);

/// A result tolerance from which on short steps are evaluated by [`short_step`] alone: that of
/// `f32` (`2⁻²⁴`) and coarser. The series rounds a few units of `f64` roundoff more than the
/// closed forms, invisible once rounded to `f32` but not in an `f64` result, which keeps them.
const SHORT_STEP_TOLERANCE: f64 = 1e-10;

/// `1/(2n)!` and `1/(2n+1)!` for `n = 1..=4`: the band series without their leading 1.
const COSH_SERIES: [f64; 4] = [1.0 / 2.0, 1.0 / 24.0, 1.0 / 720.0, 1.0 / 40_320.0];
const SINH_SERIES: [f64; 4] = [1.0 / 6.0, 1.0 / 120.0, 1.0 / 5_040.0, 1.0 / 362_880.0];

/// Everything one time step needs, computed once per `(spring, t)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Coefficients {
    /// `∂x₁/∂x₀`.
    pub f0: f64,
    /// `∂x₁/∂v₀`.
    pub f1: f64,
    /// `ω²·f1 = −∂v₁/∂x₀`.
    pub w2f1: f64,
    /// `∂v₁/∂v₀`.
    pub g: f64,
    /// `ω²·g0 = 1 − f0`, computed without forming `1 − f0`.
    pub w2g0: f64,
    /// `g0 = ∫₀ᵗ f1`: the response of `x` to a unit constant acceleration.
    pub g0: f64,
    /// `2b = c/m`.
    pub rate: f64,
}

/// The factor `e^{−y}`, `y ≥ 0`, that every entry of one regime shares, applied so that an
/// entry that is representable is never lost to an intermediate underflow.
///
/// While `e^{−y}` is a normal number it is computed once and multiplied in. Beyond that each
/// product is formed in the exponent, `exp(ln|x| − y)`, so a large factor (`ω²`, `b`, a long
/// `t`) still yields its representable product instead of `x·0`; the extra rounding of `ln|x|`
/// is far below what the condition number (`≥ y`) of such entries allows. An infinite `y`
/// gives 0 for any factor, never `∞·0 = NaN`.
#[derive(Clone, Copy)]
enum Decay {
    Factor(f64),
    Exponent(f64),
}

impl Decay {
    #[inline]
    fn new(y: f64) -> Self {
        if y <= EXP_NORMAL_LIMIT {
            Self::Factor(exp(-y))
        } else {
            Self::Exponent(y)
        }
    }

    /// `x·e^{−y}`.
    #[inline]
    fn apply(self, x: f64) -> f64 {
        match self {
            Self::Factor(e) => x * e,
            Self::Exponent(y) => Self::in_exponent(x.signum(), ln(x.abs()), y),
        }
    }

    /// `a·x·e^{−y}` for `a > 0`, without overflowing in `a·x` or underflowing in `x·e^{−y}`.
    #[inline]
    fn apply_scaled(self, a: f64, x: f64) -> f64 {
        match self {
            Self::Factor(e) => {
                let ax = a * x;
                if ax.is_finite() { ax * e } else { a * (x * e) }
            }
            Self::Exponent(y) => Self::in_exponent(x.signum(), ln(a) + ln(x.abs()), y),
        }
    }

    #[inline]
    fn in_exponent(sign: f64, log_magnitude: f64, y: f64) -> f64 {
        if y.is_finite() && log_magnitude.is_finite() {
            sign * exp(log_magnitude - y)
        } else {
            // x = 0 (ln x = −∞) or y = ∞: the decay wins.
            0.0
        }
    }
}

/// `∫₀ᵗ e^{−rate·τ} dτ = (1 − e^{−rate·t})/rate` for `rate, t ≥ 0`, equal to `t` at `rate = 0`.
///
/// `expm1` avoids the cancellation of `1 − e^{−x}` for small `x`; a product `rate·t` that
/// underflows to 0 takes the limit `t`, one that overflows gives `1/rate`.
#[inline]
pub(crate) fn decay_integral(rate: f64, t: f64) -> f64 {
    let x = rate * t;
    if x == 0.0 { t } else { -exp_m1(-x) / rate }
}

/// `(C(z) − 1, S(z) − 1)` by Horner in `z`; truncation is below one unit of roundoff for
/// `|z| ≤ BAND_Z`. Returning the parts past the leading 1 keeps `C − 1` exact in sign and size
/// for the `1 − f0` evaluation.
#[inline]
fn band_series(z: f64) -> (f64, f64) {
    let mut c = 0.0;
    let mut s = 0.0;
    for n in (0..COSH_SERIES.len()).rev() {
        c = (c + COSH_SERIES[n]) * z;
        s = (s + SINH_SERIES[n]) * z;
    }
    (c, s)
}

/// `g0 = ∫₀ᵗ f1` by the Taylor series of `f1` in `t`, for `ρ·t ≤ 1`, to relative precision
/// `tolerance`.
///
/// With `uₘ = aₘ·tᵐ` the scaled Taylor coefficients of `f1`, `u₁ = t` and
/// `(m+1)·m·uₘ₊₁ = −(2bt·m·uₘ + ω²t²·uₘ₋₁)`; `g0 = t·Σ uₘ/(m+1)`. When the spectral radius
/// `ρ` satisfies `ρt ≤ 1` every term is bounded by the first, so nothing cancels — unlike
/// `(1 − f0)/ω²`, which loses all digits as `t → 0`. The sum stops once the a-priori bound
/// `(ρt)ᵐ/m!` on the remaining terms falls below `tolerance/16` of the first (the sum is at
/// least `e⁻²` of it for `ρt ≤ 1`), so short steps and `f32` targets take only a few terms.
#[inline]
fn time_series_g0(b: f64, w2: f64, t: f64, rho_t: f64, tolerance: f64) -> f64 {
    let two_bt = (b + b) * t;
    let w2t2 = w2 * t * t;
    let mut previous = 0.0;
    let mut current = t;
    let mut sum = current * SERIES_INTEGRAL[0];
    let mut remaining = 1.0;
    let small_enough = tolerance / 16.0;
    for m in 1..TIME_SERIES_TERMS {
        remaining *= rho_t * RECIPROCALS[m - 1];
        if remaining < small_enough {
            break;
        }
        let next = -(two_bt * (m as f64) * current + w2t2 * previous) * SERIES_RECURRENCE[m - 1];
        previous = current;
        current = next;
        sum += current * SERIES_INTEGRAL[m];
    }
    sum * t
}

/// `1/n!` for `n = 0, 1, …`: the weights of [`short_step`]'s terms.
const INVERSE_FACTORIALS: [f64; TIME_SERIES_TERMS + 2] = {
    let mut table = [1.0; TIME_SERIES_TERMS + 2];
    let mut factorial = 1.0;
    let mut n = 1;
    while n < table.len() {
        factorial *= n as f64;
        table[n] = 1.0 / factorial;
        n += 1;
    }
    table
};

/// `1/7!²`: [`short_step`] always sums the series to `l₇`, and the squared bound on the terms it
/// leaves out is then `(ρt)¹⁴/7!²`.
const FIXED_BOUND_SQUARED: f64 = 1.0 / (5040.0 * 5040.0);

/// Every coefficient of a short step from the Taylor series of `f1` in `t` that
/// [`time_series_g0`] sums, to relative precision `tolerance`: no `exp`, `sin`, `cos` or
/// square root. `rho_t_squared` bounds `(ρt)²` and is at most 1.
///
/// In the scaled terms `lₘ = m!·uₘ/t` (the Lucas sequence of the two roots, times `tᵐ⁻¹`) the
/// recurrence has constant coefficients, `lₘ₊₁ = β·lₘ + γ·lₘ₋₁` with `β = −2bt`, `γ = −ω²t²`,
/// `l₀ = 0`, `l₁ = 1`, and so has its square, `lₘ₊₂ = (β² + γ)·lₘ + βγ·lₘ₋₁`: the terms to `l₇`
/// (enough whenever `(ρt)⁷/7! ≤ tolerance/16`, i.e. `ρt ≲ 0.21` in `f32`: a 60 fps frame of a
/// spring with `ω ≤ 12`, or `ω ≤ 30` at 144 Hz) take three products and sums in a row, not six,
/// and no test per term. Past `l₇` the terms come one by one while the a-priori bound on what is
/// left is not yet below `tolerance/16` of the first. (`β² + γ` may cancel; its error is
/// absolute, a few `f64` roundoffs of terms bounded by the first, like every rounding here.)
///
/// `f1 = t·Σ lₘ/m!` and `g0 = t²·Σ lₘ/(m+1)!` are sums whose terms are bounded by the first, as
/// in `time_series_g0`, and `f1 ≥ e^{−ρt}·t ≥ t/e`, so neither cancels. The rest follow without
/// a subtraction that could: `ω²·g0 = 1 − f0` is a product, `f0 = 1 − ω²·g0` lies in
/// `[1 − (ρt)²/2, 1]`, and `g = 1 − (ω²·g0 + 2b·f1)` (the derivative of `f1`) subtracts two
/// positive terms, so its error is absolute, `~u` of `f64`, as in the closed forms (where `g`
/// cancels too). All of it is far below the `f32` rounding the result then takes.
#[inline]
fn short_step(b: f64, w2: f64, t: f64, rho_t_squared: f64, tolerance: f64) -> Coefficients {
    let two_b = b + b;
    let beta = 0.0 - two_b * t;
    let gamma = 0.0 - w2 * t * t;
    let (square_last, square_before) = (beta * beta + gamma, beta * gamma);
    let [l2, l3] = [beta, square_last];
    let l4 = beta * l3 + gamma * l2;
    let l5 = square_last * l3 + square_before * l2;
    let l6 = square_last * l4 + square_before * l3;
    let l7 = square_last * l5 + square_before * l4;
    let weigh = |shift: usize| {
        let weight = |m: usize| INVERSE_FACTORIALS[m + shift];
        (weight(1) + l2 * weight(2) + l3 * weight(3))
            + (l4 * weight(4) + l5 * weight(5))
            + (l6 * weight(6) + l7 * weight(7))
    };
    let (mut f1_sum, mut g0_sum) = (weigh(0), weigh(1));
    // (ρt)⁷/7!, squared so that `ρt` needs no square root.
    let small_enough = tolerance / 16.0;
    let small_enough_squared = small_enough * small_enough;
    let rho_t_4 = rho_t_squared * rho_t_squared;
    let mut remaining_squared = rho_t_4 * rho_t_4 * rho_t_4 * rho_t_squared * FIXED_BOUND_SQUARED;
    let (mut before, mut last) = (l6, l7);
    // To `l₂₀`, the last term `time_series_g0` may take too (its weights reach `1/21!`).
    for m in 8..INVERSE_FACTORIALS.len() - 1 {
        if remaining_squared < small_enough_squared {
            break;
        }
        (before, last) = (last, beta * last + gamma * before);
        f1_sum += last * INVERSE_FACTORIALS[m];
        g0_sum += last * INVERSE_FACTORIALS[m + 1];
        remaining_squared *= rho_t_squared * SQUARED_RECIPROCALS[m - 1];
    }
    let f1 = f1_sum * t;
    let g0 = g0_sum * t * t;
    let w2g0 = w2 * g0;
    Coefficients {
        f0: 1.0 - w2g0,
        f1,
        w2f1: w2 * f1,
        g: 1.0 - (w2g0 + two_b * f1),
        w2g0,
        g0,
        rate: two_b,
    }
}

/// The transition coefficients for half-rate `b = c/(2m) ≥ 0`, `ω² = k/m ≥ 0` and step
/// `t ≥ 0`, all finite. `tolerance` is the unit roundoff of the type the result is rounded to:
/// series whose truncation could not show in it stop early.
#[inline]
pub(crate) fn coefficients(b: f64, w2: f64, t: f64, tolerance: f64) -> Coefficients {
    // (ρt)², squared to need no root: the spectral radius ρ is ω up to critical damping and
    // b + √(b² − ω²) ≤ 2b beyond it.
    let two_bt = (b + b) * t;
    let rho_t_squared = if b * b <= w2 {
        w2 * t * t
    } else {
        two_bt * two_bt
    };
    if tolerance >= SHORT_STEP_TOLERANCE && rho_t_squared <= 1.0 {
        short_step(b, w2, t, rho_t_squared, tolerance)
    } else {
        long_step(b, w2, t, tolerance)
    }
}

/// [`coefficients`] by the closed form of the regime: out of line, so that the short path
/// inlines into its caller without the long one's frame.
#[inline(never)]
fn long_step(b: f64, w2: f64, t: f64, tolerance: f64) -> Coefficients {
    let w = sqrt(w2);
    // z = (b − ω)t·(b + ω)t: never forms b² (which overflows long before b does). An exact zero
    // difference is caught first so that 0·∞ cannot arise when (b + ω)t overflows.
    let difference_t = (b - w).abs() * t;
    let z_magnitude = if difference_t == 0.0 {
        0.0
    } else {
        difference_t * ((b + w) * t)
    };
    if z_magnitude <= BAND_Z {
        let z = if b >= w { z_magnitude } else { -z_magnitude };
        band(b, w2, w, t, z, tolerance)
    } else if b > w {
        overdamped(b, w2, w, t, tolerance)
    } else {
        underdamped(b, w2, w, t, tolerance)
    }
}

/// Band around critical damping (also `c = k = 0` and tiny `t`): the series in `z` is exact to
/// rounding and continuous through `ζ = 1`, where the modal and trigonometric forms divide by
/// `s → 0` or `κ → 0`.
#[inline]
fn band(b: f64, w2: f64, w: f64, t: f64, z: f64, tolerance: f64) -> Coefficients {
    let one = 1.0;
    let bt = b * t;
    let (c_minus_1, s_minus_1) = band_series(z);
    let c = one + c_minus_1;
    let s = one + s_minus_1;
    let decay = Decay::new(bt);
    let ts = t * s;
    let (f1, w2f1) = if ts.is_finite() {
        (decay.apply(ts), decay.apply_scaled(w2, ts))
    } else {
        // `t` within S(z) − 1 of f64::MAX: `t·S` overflows where `e^{−bt}·t·S` (at most `t`)
        // does not, so `t` is scaled in with the decay. (`ω²·t` is small here: the band needs
        // `ω ≈ b ≲ 1/t`.)
        (decay.apply_scaled(t, s), decay.apply_scaled(w2 * t, s))
    };
    let f0 = decay.apply(c + bt * s);
    let g = decay.apply(c - bt * s);
    // Roots −b ± √z/t: |root|·t ≤ max(b, ω)·t + √|z|.
    let rho_t = bt.max(w * t) + sqrt(z.abs());
    finish(b, w2, t, [f0, f1, w2f1, g], (rho_t, tolerance), || {
        // 1 − f0 = (1 − e^{−x}) − x·e^{−x} − e^{−x}·((C − 1) + x·(S − 1)), x = bt. Used only
        // for ρt > 1 (so x ≳ 1 and ω > 0), where the first two terms differ by a factor
        // ≥ e − 1 and the last is ≤ BAND_Z in size: only a small constant factor is lost.
        let one_minus_f0 = -exp_m1(-bt) - decay.apply(bt) - decay.apply(c_minus_1 + bt * s_minus_1);
        (one_minus_f0, one_minus_f0 / w2)
    })
}

/// Over-damped, modal form.
///
/// `s = √(b² − ω²)` and the slow rate `λ = b − s` are formed without overflow or cancellation
/// (see [`modes`]). With `e^{−bt}·sinh(st)/s = e^{−λt}·φ`,
/// `φ = (1 − e^{−2st})/(2s)` by `expm1`, no `cosh` or `sinh` is ever formed, so nothing
/// overflows for any `st`.
#[inline]
fn overdamped(b: f64, w2: f64, w: f64, t: f64, tolerance: f64) -> Coefficients {
    let one = 1.0;
    let s = modes::overdamped_split(b, w);
    let fast_rate = b + s;
    let slow_rate = modes::slow_rate(b, w, s);
    let slow_t = slow_rate * t;
    let phi = decay_integral(s + s, t);
    let decay = Decay::new(slow_t);
    let f1 = decay.apply(phi);
    let w2f1 = decay.apply_scaled(w2, phi);
    // f0 = e^{−λt}·(1 + λφ): both terms positive. g = e^{−μt} − λ·f1: the one subtraction is
    // the genuine sign change of g.
    let f0 = decay.apply(one + slow_rate * phi);
    let g = exp(-(fast_rate * t)) - decay.apply_scaled(slow_rate, phi);
    finish(
        b,
        w2,
        t,
        [f0, f1, w2f1, g],
        (fast_rate * t, tolerance),
        || {
            // g0 = (∫₀ᵗ e^{−λτ}dτ − f1)/μ: for ρt = μt > 1 outside the band the integral exceeds
            // f1 = e^{−λt}·φ by a constant factor, so the subtraction loses at most a few bits.
            // Valid for ω = 0 too (then λ = 0 and g0 = (t − f1)/(2b)).
            let g0 = (decay_integral(slow_rate, t) - f1) / fast_rate;
            (w2 * g0, g0)
        },
    )
}

/// Under-damped: `κ = √(ω² − b²)` formed without overflow or cancellation (see [`modes`]).
#[inline]
fn underdamped(b: f64, w2: f64, w: f64, t: f64, tolerance: f64) -> Coefficients {
    let two = 2.0;
    let bt = b * t;
    let kappa = modes::damped_frequency(b, w);
    // The phase is clamped to the largest finite value: beyond it the phase carries no digits
    // in this precision anyway, and sin_cos(∞) would be NaN.
    let theta = (kappa * t).min(f64::MAX);
    let (sn, cs) = sin_cos(theta);
    // sin(κt)/κ → t as κ → 0 (reachable only when q rounds to 1 far outside the band).
    let sin_over_kappa = if kappa > 0.0 { sn / kappa } else { t };
    let decay = Decay::new(bt);
    let f1 = decay.apply(sin_over_kappa);
    let w2f1 = decay.apply_scaled(w2, sin_over_kappa);
    let b_sin_over_kappa = b * sin_over_kappa;
    let f0 = decay.apply(cs + b_sin_over_kappa);
    let g = decay.apply(cs - b_sin_over_kappa);
    finish(b, w2, t, [f0, f1, w2f1, g], (w * t, tolerance), || {
        // 1 − f0 = (1 − e^{−bt}) + 2e^{−bt}·sin²(κt/2) − b·f1: the half-angle form replaces
        // 1 − cos κt, which cancels whenever the spring swings back near its start.
        let half = sin(theta / two);
        let one_minus_f0 =
            -exp_m1(-bt) + two * decay.apply(half * half) - decay.apply(b_sin_over_kappa);
        (one_minus_f0, one_minus_f0 / w2)
    })
}

/// Adds `g0` and `ω²·g0 = 1 − f0` to the matrix entries `[f0, f1, ω²·f1, g]`: by the time series in
/// `t` when `ρt ≤ 1` (where `1 − f0` would cancel), otherwise from the regime's own
/// cancellation-free `(1 − f0, g0)`.
#[inline]
fn finish(
    b: f64,
    w2: f64,
    t: f64,
    [f0, f1, w2f1, g]: [f64; 4],
    (rho_t, tolerance): (f64, f64),
    far: impl FnOnce() -> (f64, f64),
) -> Coefficients {
    let (w2g0, g0) = if rho_t <= 1.0 {
        let g0 = time_series_g0(b, w2, t, rho_t, tolerance);
        (w2 * g0, g0)
    } else {
        far()
    };
    // g0 ≤ t²/2 outgrows f64 only for ω ≈ 0 and steps beyond ~1e154 s. It saturates at the
    // largest finite value, as the phase does, and ω²·g0 is re-formed from it: the product above
    // was 0·∞ = NaN for ω = 0.
    let (w2g0, g0) = if g0.is_finite() {
        (w2g0, g0)
    } else {
        (w2 * f64::MAX, f64::MAX)
    };
    Coefficients {
        f0,
        f1,
        w2f1,
        g,
        w2g0,
        g0,
        rate: b + b,
    }
}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::{Coefficients, long_step, short_step};
    use std::println;

    /// `f32`'s unit roundoff, the tolerance the short path serves.
    const F32_ROUNDOFF: f64 = f32::EPSILON as f64 / 2.0;

    /// The short path against the closed forms over its whole domain, `ρt ≤ 1`, on both sides
    /// of critical damping: within a quarter of `f32`'s unit roundoff, relative for the entries
    /// that keep their relative precision and absolute for `f0` and `g` (which may cross zero).
    /// A term dropped from the fixed part alone errs by `(ρt)⁷/7!`, ~400 times more at `ρt = 1`.
    #[test]
    fn the_short_step_agrees_with_the_closed_forms() {
        let mut worst = 0.0_f64;
        for zeta in [0.0, 0.05, 0.3, 0.5, 0.7, 0.99, 1.0, 1.01, 1.5, 3.0, 20.0] {
            for rho_t in [1e-6, 0.01, 0.1, 0.2, 0.21, 0.22, 0.35, 0.5, 0.75, 0.9, 1.0] {
                for w in [0.5, 10.0, 4000.0] {
                    let b = zeta * w;
                    let (w2, two_b) = (w * w, b + b);
                    let rho = if b <= w { w } else { two_b };
                    let t = rho_t / rho;
                    let short = short_step(b, w2, t, (rho * t) * (rho * t), F32_ROUNDOFF);
                    let closed = long_step(b, w2, t, 1e-17);
                    let relative = |x: f64, y: f64| ((x - y) / y).abs();
                    let errors = [
                        relative(short.f1, closed.f1),
                        relative(short.w2f1, closed.w2f1),
                        relative(short.g0, closed.g0),
                        relative(short.w2g0, closed.w2g0),
                        (short.f0 - closed.f0).abs(),
                        (short.g - closed.g).abs(),
                    ];
                    let error = errors.into_iter().fold(0.0, f64::max);
                    assert!(
                        error <= F32_ROUNDOFF / 4.0,
                        "ζ = {zeta}, ρt = {rho_t}, ω = {w}: {short:?} vs {closed:?}"
                    );
                    worst = worst.max(error);
                }
            }
        }
        println!("worst: {:.3} u of f32", worst / F32_ROUNDOFF);
    }

    /// A free body's step is exact: `f1 = t`, `g0 = t²/2`, `f0 = g = 1`.
    #[test]
    #[expect(clippy::float_cmp, reason = "the free step is exact, bit for bit")]
    fn a_free_short_step_is_exact() {
        let t = 0.75;
        let Coefficients {
            f0,
            f1,
            w2f1,
            g,
            w2g0,
            g0,
            rate,
        } = short_step(0.0, 0.0, t, 0.0, F32_ROUNDOFF);
        assert_eq!(
            [f0, f1, w2f1, g, w2g0, g0, rate],
            [1.0, t, 0.0, 1.0, 0.0, t * t / 2.0, 0.0]
        );
    }
}
