//! The high-precision reference trajectory: the closed-form solution evaluated with
//! `dashu-float` at [`PRECISION`] bits at every frame's end time, piecewise between target
//! changes (the state at a retarget is carried over in full precision).
//!
//! The spring's `f64` parameters and frame times are taken exactly, so the reference is the
//! exact motion of the spring every method is given. Each regime uses a form that does not
//! cancel at this precision: the modal form `c₁e^{−λt} + c₂e^{−μt}` when over-damped (never
//! `cosh`/`sinh`, whose difference would cost `2st·log₂e` bits), the trigonometric form when
//! under-damped, and the exact critical form when `b = ω` exactly.

use std::cmp::Ordering;

use dashu_float::FBig;
use dashu_float::round::mode::HalfEven;

use crate::scenario::Scenario;

/// Working precision in bits.
pub const PRECISION: usize = 256;

/// A [`PRECISION`]-bit float.
type Big = FBig<HalfEven>;

/// `x` exactly, at the working precision.
fn big(x: f64) -> Big {
    Big::try_from(x)
        .expect("finite input")
        .with_precision(PRECISION)
        .value()
}

/// Rounds to the nearest `f64`.
fn to_f64(x: &Big) -> f64 {
    x.to_f64().value()
}

/// The spring `y'' + 2b·y' + ω²·y = 0` in high precision, with its regime's constants.
struct Solver {
    b: Big,
    w2: Big,
    regime: Regime,
}

enum Regime {
    /// `b = ω` exactly.
    Critical,
    /// `b > ω`: slow and fast rates `λ = ω²/(b + s)`, `μ = b + s`, and `2s = μ − λ`.
    Overdamped { slow: Big, fast: Big, two_s: Big },
    /// `b < ω`: the damped frequency `κ = √(ω² − b²)`.
    Underdamped { kappa: Big },
}

impl Solver {
    fn new(stiffness: f64, damping: f64) -> Self {
        let b = big(damping) / big(2.0);
        let w2 = big(stiffness);
        let z = &b * &b - &w2;
        let zero = big(0.0);
        let regime = match z.cmp(&zero) {
            Ordering::Equal => Regime::Critical,
            Ordering::Greater => {
                let s = z.sqrt();
                let fast = &b + &s;
                Regime::Overdamped {
                    slow: &w2 / &fast,
                    two_s: &s + &s,
                    fast,
                }
            }
            Ordering::Less => Regime::Underdamped { kappa: (-z).sqrt() },
        };
        Self { b, w2, regime }
    }

    /// `(y(t), v(t))` from `(y₀, v₀)` at time 0.
    fn solve(&self, y0: &Big, v0: &Big, t: &Big) -> (Big, Big) {
        let b = &self.b;
        match &self.regime {
            Regime::Critical => {
                let decay = (-(b * t)).exp();
                let coefficient = v0 + b * y0;
                (
                    &decay * (y0 + &coefficient * t),
                    &decay * (v0 - b * &coefficient * t),
                )
            }
            Regime::Overdamped { slow, fast, two_s } => {
                let c1 = (fast * y0 + v0) / two_s;
                let c2 = -(slow * y0 + v0) / two_s;
                let e1 = &c1 * (-(slow * t)).exp();
                let e2 = &c2 * (-(fast * t)).exp();
                (&e1 + &e2, -(slow * &e1) - fast * &e2)
            }
            Regime::Underdamped { kappa } => {
                let decay = (-(b * t)).exp();
                let (sn, cs) = (kappa * t).sin_cos();
                let position_gain = (v0 + b * y0) / kappa;
                let velocity_gain = (&self.w2 * y0 + b * v0) / kappa;
                (
                    &decay * (y0 * &cs + &position_gain * &sn),
                    &decay * (v0 * &cs - &velocity_gain * &sn),
                )
            }
        }
    }
}

/// The exact position at the end of every frame of `scenario`, rounded to `f64`.
#[must_use]
pub fn trajectory(scenario: &Scenario) -> Vec<f64> {
    let solver = Solver::new(scenario.spring.stiffness, scenario.spring.damping);
    let mut out = Vec::with_capacity(scenario.frames.len());
    let Some(first) = scenario.frames.first() else {
        return out;
    };
    // The current segment: its target, its start state (offset from that target) and the time
    // elapsed since it started.
    let mut target = first.target;
    let mut y0 = big(scenario.start.position) - big(target);
    let mut v0 = big(scenario.start.velocity);
    let mut elapsed = big(0.0);
    for frame in &scenario.frames {
        if frame.target.to_bits() != target.to_bits() {
            let (y, v) = solver.solve(&y0, &v0, &elapsed);
            y0 = y + big(target) - big(frame.target);
            v0 = v;
            target = frame.target;
            elapsed = big(0.0);
        }
        elapsed += big(frame.dt);
        let (y, _) = solver.solve(&y0, &v0, &elapsed);
        out.push(to_f64(&(y + big(target))));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::{ExactCached, Method};

    #[test]
    fn reference_matches_the_exact_step() {
        for scenario in crate::scenario::all()
            .iter()
            .filter(|s| s.frames.len() <= 200)
            .step_by(5)
        {
            let reference = trajectory(scenario);
            let mut method = ExactCached::new(&scenario.spring);
            let mut state = scenario.start;
            for (frame, exact) in scenario.frames.iter().zip(reference) {
                state = method.step(state, frame.target, frame.dt);
                assert!(
                    (state.position - exact).abs() < 1e-13,
                    "{}: {} vs {exact}",
                    scenario.label,
                    state.position
                );
            }
        }
    }
}
