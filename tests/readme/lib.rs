//! The README's Rust examples, compiled and run as doc tests of the workspace's root package
//! (which otherwise only owns the runnable `examples/` and the integration tests in `tests/`,
//! and has no API of its own; see the `sprung` and `bevy_sprung` crates).

// The README's Rust examples are compiled and run as doc tests.
#[doc = include_str!("../../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
