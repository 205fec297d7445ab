//! Running a method through a scenario and measuring its error against the reference.

use crate::methods::{Method, SpringParams, State};
use crate::scenario::Scenario;

/// How a method fared on one scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Finite, error at most the amplitude, and not growing.
    Stable,
    /// Error above the amplitude, or a per-step growth factor above 1 (the error would grow
    /// without bound given time); [`Outcome::grows`] tells which.
    Unstable,
    /// A NaN or infinity appeared.
    NonFinite,
}

/// The result of one method on one scenario.
#[derive(Clone, Copy, Debug)]
pub struct Outcome {
    /// Max over the frames of `|x − x_ref|` as a fraction of the amplitude (NaN if non-finite).
    pub max_error: f64,
    /// Spectral radius of the method's one-step map for fixed-`dt` scenarios (how much the
    /// state can grow per step; the exact value is `e^{−b·dt}` ≤ 1).
    pub growth: Option<f64>,
    /// Whether the growth factor exceeds 1 by more than rounding: the state grows without
    /// bound under repeated steps.
    pub grows: bool,
    /// The verdict.
    pub status: Status,
}

/// Units of the method's roundoff by which its growth factor may exceed 1 before the method
/// counts as growing: above what rounding the step's coefficients gives (a few units; an
/// `f32` undamped transition's determinant is 1 only to `f32` precision), far below any real
/// instability in the grid (the mildest, explicit Euler at `ζ = 0`, `ω·dt = 0.01`, grows by
/// `5·10⁻⁵` per step).
const GROWTH_ROUNDOFFS: f64 = 64.0;

/// The spectral radius of a linear one-step map `[[a, b], [c, d]]`.
fn spectral_radius([[a, b], [c, d]]: [[f64; 2]; 2]) -> f64 {
    let half_trace = 0.5 * (a + d);
    let det = a * d - b * c;
    let discriminant = half_trace * half_trace - det;
    if discriminant >= 0.0 {
        let root = discriminant.sqrt();
        (half_trace + root).abs().max((half_trace - root).abs())
    } else {
        det.sqrt()
    }
}

/// The one-step map of method `M` over `dt` toward target 0, found by stepping the unit
/// states (every method in the study is linear in `(x − x*, v)`).
fn step_matrix<M: Method>(spring: &SpringParams, dt: f64) -> [[f64; 2]; 2] {
    let from_position = M::new(spring).step(State::new(1.0, 0.0), 0.0, dt);
    let from_velocity = M::new(spring).step(State::new(0.0, 1.0), 0.0, dt);
    [
        [from_position.position, from_velocity.position],
        [from_position.velocity, from_velocity.velocity],
    ]
}

/// Runs `M` through `scenario`, comparing each frame's end position with `reference`.
#[must_use]
pub fn run<M: Method>(scenario: &Scenario, reference: &[f64]) -> Outcome {
    let mut method = M::new(&scenario.spring);
    let mut state = scenario.start;
    let amplitude = scenario.amplitude();
    let mut max_error: f64 = 0.0;
    let mut finite = true;
    for (frame, &exact) in scenario.frames.iter().zip(reference) {
        state = method.step(state, frame.target, frame.dt);
        if !(state.position.is_finite() && state.velocity.is_finite()) {
            finite = false;
            break;
        }
        max_error = max_error.max((state.position - exact).abs() / amplitude);
    }
    let growth = scenario
        .fixed_dt
        .map(|dt| spectral_radius(step_matrix::<M>(&scenario.spring, dt)));
    let tolerance = GROWTH_ROUNDOFFS * M::UNIT_ROUNDOFF;
    let grows = growth.is_some_and(|g| g.is_nan() || g > 1.0 + tolerance);
    let status = if !finite {
        Status::NonFinite
    } else if max_error > 1.0 || grows {
        Status::Unstable
    } else {
        Status::Stable
    };
    Outcome {
        max_error: if finite { max_error } else { f64::NAN },
        growth,
        grows,
        status,
    }
}

/// The error used for ranking: unstable and non-finite outcomes count as infinite.
#[must_use]
pub fn ranked_error(outcome: &Outcome) -> f64 {
    if outcome.status == Status::Stable {
        outcome.max_error
    } else {
        f64::INFINITY
    }
}

/// The median of `values` (the upper one for an even count); NaN when empty.
#[must_use]
pub fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spectral_radius_of_rotation_and_scaling() {
        let (s, c) = 0.3f64.sin_cos();
        assert!((spectral_radius([[c, -s], [s, c]]) - 1.0).abs() < 1e-15);
        assert!((spectral_radius([[0.5, 0.0], [0.0, -2.0]]) - 2.0).abs() < 1e-15);
    }
}
