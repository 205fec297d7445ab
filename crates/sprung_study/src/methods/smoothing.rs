//! The smoothing formulas games use in place of a spring: Bevy's `smooth_nudge` (an
//! exponential lerp, first order) and Unity's `SmoothDamp` (a rational approximation of a
//! critically damped spring).

use sprung::Spring;

use super::{Method, SpringParams, State};

/// Samples of the step response on `ω·t ∈ [0, FIT_HORIZON]` used to fit the first-order rate.
const FIT_SAMPLES: usize = 2001;
/// `ω·t` up to which the first-order response is fitted (about three periods).
const FIT_HORIZON: f64 = 20.0;

/// The rate `r` for which `e^{−r·t}` best fits, in the max norm over `ω·t ∈ [0, 20]`, the
/// spring's step response from rest (`x − x*` starting at 1, velocity 0).
///
/// A first-order system cannot reproduce a spring: it starts with nonzero velocity and never
/// overshoots. This is the best any choice of `r` can do, so the exponential lerp is compared
/// at its best. (For a critical spring `r ≈ 0.42·ω` and the fit still misses by 10% of the
/// amplitude; the simple choice `r = ω` misses by `1/e ≈ 37%`.) Deterministic: a log-spaced
/// scan followed by a golden-section refinement.
///
/// # Panics
/// If `omega` or `zeta` is negative or not finite.
#[must_use]
pub fn fit_first_order_rate(omega: f64, zeta: f64) -> f64 {
    let spring = Spring::<f64>::new(1.0, omega * omega, (zeta + zeta) * omega)
        .expect("the study's springs are valid");
    let times: Vec<f64> = (0..FIT_SAMPLES)
        .map(|i| FIT_HORIZON / omega * i as f64 / (FIT_SAMPLES - 1) as f64)
        .collect();
    let response: Vec<f64> = times
        .iter()
        .map(|&t| spring.transition(t).matrix()[0][0])
        .collect();
    let misfit = |ratio: f64| {
        let rate = ratio * omega;
        times
            .iter()
            .zip(&response)
            .map(|(&t, &y)| ((-rate * t).exp() - y).abs())
            .fold(0.0, f64::max)
    };
    // Scan r/ω over [1e-3, 1e2] in log steps, then refine around the best.
    let steps = 100;
    let ratio_at = |i: i32| 10f64.powf(-3.0 + 5.0 * f64::from(i) / f64::from(steps));
    let best = (0..=steps)
        .min_by(|&a, &b| misfit(ratio_at(a)).total_cmp(&misfit(ratio_at(b))))
        .unwrap_or(0);
    let (mut low, mut high) = (ratio_at(best - 1), ratio_at(best + 1));
    let golden = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..60 {
        let a = high - golden * (high - low);
        let b = low + golden * (high - low);
        if misfit(a) < misfit(b) {
            high = b;
        } else {
            low = a;
        }
    }
    0.5 * (low + high) * omega
}

/// Bevy's `StableInterpolate::smooth_nudge`: `x ← lerp(x, x*, 1 − e^{−r·dt})`, with `r`
/// from [`fit_first_order_rate`] (its best possible fit to the spring).
///
/// Exact for the first-order system `x' = r·(x* − x)` at any `dt`, but that is not a spring:
/// it keeps no velocity (the reported velocity is the frame's average), so it neither
/// overshoots nor carries momentum through a retarget.
#[derive(Clone, Copy, Debug)]
pub struct ExponentialLerp {
    rate: f64,
}

impl Method for ExponentialLerp {
    const NAME: &'static str = "exponential lerp (smooth_nudge)";
    const NOTE: &'static str = "Bevy's `smooth_nudge`, `lerp(x, x*, 1 − e^{−r·dt})` with \
        `e^{−r·dt}` evaluated every step; `r` is the max-norm best fit of `e^{−rt}` to the \
        spring's step response over `ωt ∈ [0, 20]` (≈ 0.42ω for ζ = 1): first order, no velocity.";

    fn new(spring: &SpringParams) -> Self {
        Self {
            rate: spring.first_order_rate,
        }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let fraction = 1.0 - (-self.rate * dt).exp();
        let position = state.position + (target - state.position) * fraction;
        let velocity = if dt > 0.0 {
            (position - state.position) / dt
        } else {
            0.0
        };
        State::new(position, velocity)
    }
}

/// Unity's `Mathf.SmoothDamp` (Game Programming Gems 4, 8.1): a critically damped spring with
/// `e^{−x}` replaced by the rational `1/(1 + x + 0.48x² + 0.235x³)`.
///
/// It is critical-only: for every `ζ` it runs with `smoothTime = 2/ω`, the critical spring of
/// the same natural frequency, so for `ζ ≠ 1` it shows what using it in place of that spring
/// costs. Unity's own version additionally clamps the speed (`maxSpeed`) and snaps to the
/// target when a step would overshoot it; neither is modelled here (the published formula).
#[derive(Clone, Copy, Debug)]
pub struct SmoothDamp {
    /// `omega = 2/smoothTime`.
    omega: f64,
}

impl Method for SmoothDamp {
    const NAME: &'static str = "SmoothDamp (Unity)";
    const NOTE: &'static str = "Unity's `SmoothDamp` rational approximation of a critical \
        spring, `smoothTime = 2/ω` for every ζ (it is critical-only); no `maxSpeed` or \
        overshoot clamp.";

    fn new(spring: &SpringParams) -> Self {
        let smooth_time = 2.0 / spring.omega;
        Self {
            omega: 2.0 / smooth_time,
        }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let omega = self.omega;
        let x = omega * dt;
        let exp = 1.0 / (1.0 + x + 0.48 * x * x + 0.235 * x * x * x);
        let change = state.position - target;
        let temp = (state.velocity + omega * change) * dt;
        let velocity = (state.velocity - omega * temp) * exp;
        State::new(target + (change + temp) * exp, velocity)
    }
}
