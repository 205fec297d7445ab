//! The float functions the kernel needs, from `std` or `libm` through `num-traits`.
//!
//! Calling them through one place (as glam does) keeps the kernel free of `std`-only inherent
//! methods, so it builds unchanged with `--no-default-features --features libm`.

use num_traits::Float;

macro_rules! forward {
    ($($name:ident),*) => {$(
        #[inline]
        pub(crate) fn $name(x: f64) -> f64 {
            Float::$name(x)
        }
    )*};
}

forward!(exp, exp_m1, ln, ln_1p, sin, sqrt);

#[inline]
pub(crate) fn atan2(y: f64, x: f64) -> f64 {
    Float::atan2(y, x)
}

#[inline]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    Float::sin_cos(x)
}
