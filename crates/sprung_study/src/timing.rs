//! Time per step, measured with [`Instant`] in the same run as the errors.
//!
//! A measurement steps [`SPRINGS`] independent springs (each its own method instance, as
//! components in a game would be) for a number of frames, calibrated so that one measurement
//! takes at least [`MIN_MEASUREMENT`]; the reported time is the median of [`REPETITIONS`]
//! measurements divided by the number of steps. `dt` and the target pass through
//! [`black_box`] every frame and the states and instances after it, so per-`dt` work cannot be
//! hoisted out of the frame loop and no step is optimised away.

use std::hint::black_box;
use std::time::{Duration, Instant};

use crate::methods::{Method, SpringParams, State};

/// Springs stepped per frame.
pub const SPRINGS: usize = 64;
/// Shortest time one measurement may take.
pub const MIN_MEASUREMENT: Duration = Duration::from_millis(20);
/// Measurements per figure (the median is reported).
pub const REPETITIONS: usize = 7;
/// Frames between flips of the target between +1 and −1 (keeps the states far from the
/// subnormal range that a spring settling for a long time would reach).
const FLIP_EVERY: usize = 32;

/// The measured cost of one method.
#[derive(Clone, Copy, Debug)]
pub struct Timing {
    /// Nanoseconds per step with a constant `dt` (per-`dt` caches stay valid).
    pub fixed_dt_ns: f64,
    /// Nanoseconds per step when `dt` changes every frame (per-`dt` caches are recomputed
    /// every frame, as with a variable frame rate).
    pub varying_dt_ns: f64,
}

/// Runs `frames` frames of `SPRINGS` springs and returns the elapsed time.
fn measure<M: Method>(
    methods: &mut [M],
    states: &mut [State],
    frames: usize,
    dt: f64,
    vary: bool,
) -> Duration {
    let start = Instant::now();
    for frame in 0..frames {
        let target = black_box(if (frame / FLIP_EVERY).is_multiple_of(2) {
            1.0
        } else {
            -1.0
        });
        // A 1% jitter on odd frames when varying: every frame's dt differs from the previous.
        let dt = black_box(if vary && frame % 2 == 1 {
            dt * 1.01
        } else {
            dt
        });
        for (method, state) in methods.iter_mut().zip(states.iter_mut()) {
            *state = method.step(*state, target, dt);
        }
        black_box(&mut *methods);
        black_box(&mut *states);
    }
    start.elapsed()
}

/// Median nanoseconds per step of `M` on `spring` at `dt`.
fn ns_per_step<M: Method>(spring: &SpringParams, dt: f64, vary: bool) -> f64 {
    let mut methods: Vec<M> = (0..SPRINGS).map(|_| M::new(spring)).collect();
    let mut states: Vec<State> = (0..SPRINGS)
        .map(|i| State::new(-(i as f64) / SPRINGS as f64, 0.0))
        .collect();
    // Calibrate (this also warms up caches and the branch predictor).
    let mut frames = 16;
    while measure(&mut methods, &mut states, frames, dt, vary) < MIN_MEASUREMENT {
        frames *= 2;
    }
    let mut samples: Vec<f64> = (0..REPETITIONS)
        .map(|_| measure(&mut methods, &mut states, frames, dt, vary).as_secs_f64())
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[REPETITIONS / 2] * 1e9 / (frames * SPRINGS) as f64
}

/// Measures `M` on `spring` at `dt`, with `dt` fixed and with `dt` varying every frame.
#[must_use]
pub fn time<M: Method>(spring: &SpringParams, dt: f64) -> Timing {
    Timing {
        fixed_dt_ns: ns_per_step::<M>(spring, dt, false),
        varying_dt_ns: ns_per_step::<M>(spring, dt, true),
    }
}
