//! How a value springs: the linear space its offset from the target moves in, and what keeps the
//! value valid on the way.
//!
//! A spring never moves a value directly. It moves the value's *offset* from its target, a
//! vector `y` with a velocity `v`, by the exact transition of [`sprung`], and turns the offset
//! back into a value. A [`SpringSpace`] says how: [`Linear`] for values that are vectors
//! already, [`NeverThroughZero`] for scales and sizes that must not mirror, [`ShortestArc`] and
//! [`ShortestAngle`] for rotations, `OklabColor` for colours (feature `color`) and `Length`
//! for UI lengths in their units (feature `ui`).

#[cfg(feature = "color")]
mod color;
#[cfg(feature = "ui")]
mod length;
mod linear;
mod rotation;
mod seal;
mod spring_space;
mod vector;

#[cfg(feature = "color")]
pub use color::OklabColor;
#[cfg(feature = "ui")]
pub use length::{Length, Length2};
pub use linear::{AffineSpace, Linear, LinearValue, NeverThroughZero};
pub use rotation::{ShortestAngle, ShortestArc, rotation_vector};
pub(crate) use seal::FastPath;
pub use spring_space::{Carried, SpringSpace};
pub use vector::SpringVector;
pub(crate) use vector::is_within_rest;
pub(crate) use vector::paired_increments;
