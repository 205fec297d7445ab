//! Exact damped-spring animation.
//!
//! For a spring `m·x'' + c·x' + k·x = f` and a frame's `dt`, `sprung` computes the exact 2×2
//! transition matrix in closed form and steps any vector-like value toward its target with it.
//! Because each step is the exact solution, the motion is the same at 30, 60, 144 or 240 fps
//! and after a one-second hitch, and retargeting mid-flight keeps the velocity.
//!
//! One evaluation covers every regime — under-, critically and over-damped, undamped,
//! unsprung (`k = 0`) and free (`k = c = 0`) — continuously through `ζ = 1`, without overflow,
//! cancellation or NaN for any valid finite input. Each matrix entry is within a few units of
//! roundoff times its condition number of the exact value (tested against a 320-bit reference).
//!
//! # Example
//! ```
//! use sprung::{Spring, SpringState};
//!
//! // SwiftUI's `.bouncy`, stepping a 2D position (any Copy + Add + Sub + Mul<f32> type works).
//! #[derive(Clone, Copy, Debug, PartialEq)]
//! struct Point(f32, f32);
//! impl core::ops::Add for Point { type Output = Self; fn add(self, o: Self) -> Self { Point(self.0 + o.0, self.1 + o.1) } }
//! impl core::ops::Sub for Point { type Output = Self; fn sub(self, o: Self) -> Self { Point(self.0 - o.0, self.1 - o.1) } }
//! impl core::ops::Mul<f32> for Point { type Output = Self; fn mul(self, s: f32) -> Self { Point(self.0 * s, self.1 * s) } }
//!
//! let spring = Spring::<f32>::bouncy();
//! let step = spring.transition(1.0 / 60.0); // compute once per frame, share across values
//! let mut state = SpringState::at_rest(Point(0.0, 0.0));
//! for _ in 0..120 {
//!     state = step.step(state, Point(100.0, 50.0));
//! }
//! assert!((state.position.0 - 100.0).abs() < 0.5 && (state.position.1 - 50.0).abs() < 0.5);
//! ```
//!
//! # Features
//! - `std` (default): the standard library's float functions.
//! - `libm`: [`libm`](https://docs.rs/libm) for the float functions, for `no_std` targets
//!   (build with `default-features = false, features = ["libm"]`).
//! - `serde`: `Serialize`/`Deserialize` for [`Spring`] (read from any parametrisation and
//!   validated: a file cannot make an invalid spring), [`RestThreshold`] and [`Regime`].
//! - `bevy_reflect`: `Reflect` for the value types, for Bevy components and inspectors.
#![no_std]
#![cfg_attr(docsrs, feature(doc_cfg))]

#[cfg(feature = "std")]
extern crate std;

#[cfg(not(any(feature = "std", feature = "libm")))]
compile_error!("sprung needs float functions: enable the `std` (default) or the `libm` feature");

mod approx_impls;
mod error;
mod kernel;
mod math;
mod modes;
mod rest;
mod scalar;
#[cfg(feature = "serde")]
mod serde_impls;
mod spring;
mod transition;

pub use error::{Parameter, SpringError};

/// What the file forms of types that hold springs share (feature `serde`).
#[cfg(feature = "serde")]
pub mod file_form {
    pub use crate::serde_impls::Given;
}

// The README's examples are compiled and run as doc tests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
pub use rest::RestThreshold;
pub use scalar::Scalar;
pub use spring::{Regime, Spring};
pub use transition::{SpringState, SpringValue, Transition};
