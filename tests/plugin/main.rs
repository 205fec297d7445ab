//! The Bevy plugin in headless apps: motion, sleeping, events, clocks, schedules, bad input,
//! ordering, custom properties and exact catch-up.

#![allow(
    clippy::float_cmp,
    reason = "snapped and frozen values are asserted bit for bit"
)]

mod harness;

mod arrival;
mod assets;
mod bad_input;
mod camera;
mod catch_up;
mod chain;
mod chaos;
mod choreography;
mod clocks;
mod debug;
mod designer;
mod disabling;
mod first_hour;
mod follow;
mod forecast;
mod implicit;
mod inertia;
mod inertialization;
mod interaction;
mod juice;
mod layers;
mod layout;
mod motion;
mod presence;
mod properties;
mod rail;
mod scheduling;
mod serde;
mod sleeping;
mod soak;
mod spin;
mod ui;
mod world_changes;
