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
        remaining *= rho_t / (m as f64);
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

/// The transition coefficients for half-rate `b = c/(2m) ≥ 0`, `ω² = k/m ≥ 0`, `ω = √ω²` and
/// step `t ≥ 0`, all finite. `tolerance` is the unit roundoff of the type the result is rounded
/// to: series whose truncation could not show in it stop early.
pub(crate) fn coefficients(b: f64, w2: f64, w: f64, t: f64, tolerance: f64) -> Coefficients {
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
    }
}
