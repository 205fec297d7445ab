//! The workspace's root package: it owns the runnable `examples/` and the cross-crate
//! integration tests in `tests/`. It has no API of its own; see the `sprung` and
//! `bevy_sprung` crates.

// The README's Rust examples are compiled and run as doc tests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
