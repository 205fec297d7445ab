//! The rates of a damped spring's two modes, in the forms that do not cancel: one home for
//! the kernel (in `f64`) and the analysis (in the spring's own type).
//!
//! With `b = c/(2m)` and `ω = √(k/m)` the characteristic roots are `−b ± √(b² − ω²)`. Forming
//! `b² − ω²` overflows long before `b` does and cancels near critical damping, and the slow
//! root `b − √(b² − ω²)` cancels completely for large damping ratios (in `f32` from `ζ ≈ 1e4`,
//! where a spring computed that way would never settle). The forms here avoid all three.

use num_traits::Float;

/// `s = √(b² − ω²)` for `b ≥ ω ≥ 0`, `b > 0`, as `b·√((1 − r)(1 + r))` with `r = ω/b`: no `b²`
/// to overflow, and `1 − r` is exact (Sterbenz) near `r = 1`.
#[inline]
pub(crate) fn overdamped_split<F: Float>(b: F, w: F) -> F {
    let one = F::one();
    let r = w / b;
    b * ((one - r) * (one + r)).sqrt()
}

/// `κ = √(ω² − b²)` for `ω ≥ b ≥ 0`, `ω > 0`: the damped angular frequency, as
/// `ω·√((1 − q)(1 + q))` with `q = b/ω`, for the same reasons as [`overdamped_split`].
#[inline]
pub(crate) fn damped_frequency<F: Float>(b: F, w: F) -> F {
    let one = F::one();
    let q = b / w;
    w * ((one - q) * (one + q)).sqrt()
}

/// The slow decay rate `λ = b − s` of an over-damped spring with split `s`
/// ([`overdamped_split`]), as `ω·(ω/(b + s))`: the product of the roots is `ω²`, so this equals
/// `b − s` without subtracting.
#[inline]
pub(crate) fn slow_rate<F: Float>(b: F, w: F, s: F) -> F {
    w * (w / (b + s))
}
