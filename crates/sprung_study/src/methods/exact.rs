//! `sprung`'s exact step, in the three ways a game can use it.

use sprung::{Spring, SpringState, Transition};

use super::{Method, PerDt, SpringParams, State};

/// The spring as `sprung` sees it: exactly the study's `f64` parameters.
fn spring_f64(params: &SpringParams) -> Spring<f64> {
    Spring::new(1.0, params.stiffness, params.damping).expect("the study's springs are valid")
}

/// `sprung`'s exact transition computed once per `dt` and reused while `dt` stays the same.
#[derive(Clone, Copy, Debug)]
pub struct ExactCached {
    spring: Spring<f64>,
    transition: PerDt<Transition<f64>>,
}

impl Method for ExactCached {
    const NAME: &'static str = "sprung exact, cached (f64)";
    const NOTE: &'static str = "`Spring::transition(dt)` computed when `dt` changes, then \
        `Transition::step` per frame.";

    fn new(spring: &SpringParams) -> Self {
        Self {
            spring: spring_f64(spring),
            transition: PerDt::new(0.0, Transition::identity()),
        }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let spring = self.spring;
        self.transition
            .get(dt, |dt| spring.transition(dt))
            .step(state, target)
    }
}

/// `sprung`'s exact transition recomputed every step: the cost per frame when `dt` varies
/// every frame, or when every spring has its own parameters.
#[derive(Clone, Copy, Debug)]
pub struct ExactRecomputed {
    spring: Spring<f64>,
}

impl Method for ExactRecomputed {
    const NAME: &'static str = "sprung exact, recomputed (f64)";
    const NOTE: &'static str = "`Spring::transition(dt)` and `Transition::step` every frame: \
        the per-frame cost including the transition.";

    fn new(spring: &SpringParams) -> Self {
        Self {
            spring: spring_f64(spring),
        }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        self.spring.transition(dt).step(state, target)
    }
}

/// `sprung`'s exact transition in `f32`, cached per `dt`; the state is held in `f32` too (it
/// is rounded to `f32` on entry, which is a no-op after the first step).
#[derive(Clone, Copy, Debug)]
pub struct ExactCachedF32 {
    spring: Spring<f32>,
    transition: PerDt<Transition<f32>>,
}

#[expect(
    clippy::cast_possible_truncation,
    reason = "rounding to f32 is what this variant measures"
)]
fn to_f32(x: f64) -> f32 {
    x as f32
}

impl Method for ExactCachedF32 {
    const NAME: &'static str = "sprung exact, cached (f32)";
    const NOTE: &'static str = "As the cached f64 variant with `Spring<f32>`: parameters, \
        `dt`, state and target rounded to `f32`.";
    const UNIT_ROUNDOFF: f64 = f32::EPSILON as f64 / 2.0;

    fn new(spring: &SpringParams) -> Self {
        Self {
            spring: Spring::new(1.0, to_f32(spring.stiffness), to_f32(spring.damping))
                .expect("the study's springs are valid in f32"),
            transition: PerDt::new(0.0, Transition::identity()),
        }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let spring = self.spring;
        let next = self
            .transition
            .get(dt, |dt| spring.transition(to_f32(dt)))
            .step(
                SpringState::new(to_f32(state.position), to_f32(state.velocity)),
                to_f32(target),
            );
        State::new(f64::from(next.position), f64::from(next.velocity))
    }
}
