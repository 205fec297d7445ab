//! The workspace's root package: it owns the runnable `examples/` and the cross-crate
//! integration tests in `tests/`. It has no API of its own; see the `sprung` and
//! `bevy_sprung` crates.
