//! Closed-form solutions as commonly written: exact in exact arithmetic, but evaluated with
//! the textbook formulas of each regime.

use super::{Method, PerDt, SpringParams, State};

/// The textbook closed form, evaluated every step, branching on the regime with an exact
/// comparison `ζ == 1` for critical damping and `cosh`/`sinh` for the over-damped case.
///
/// With `b = ζω`, `y = x − x*` and `B = (v₀ + b·y₀)`:
/// - under-damped, `κ = ω√(1 − ζ²)`: `y = e^{−bt}(y₀ cos κt + B/κ·sin κt)`,
///   `v = e^{−bt}(v₀ cos κt − (ω²y₀ + b·v₀)/κ·sin κt)`;
/// - critical: `y = e^{−bt}(y₀ + B·t)`, `v = e^{−bt}(v₀ − b·B·t)`;
/// - over-damped, `s = ω√(ζ² − 1)`: as under-damped with `cosh`/`sinh` (and the sign of the
///   `v` term flipped).
///
/// Once `st` exceeds ~710, `cosh(st)` is infinite while `e^{−bt}` is 0: the product is NaN.
/// Near `ζ = 1` (but not equal) it divides by a tiny `κ` or `s`.
#[derive(Clone, Copy, Debug)]
pub struct NaiveClosedForm {
    spring: SpringParams,
}

impl Method for NaiveClosedForm {
    const NAME: &'static str = "naive closed form";
    const NOTE: &'static str = "Textbook per-regime formula evaluated every step: `ζ == 1` \
        exact comparison, `e^{−bt}·cosh(st)` over-damped (NaN once `st > 710`).";

    fn new(spring: &SpringParams) -> Self {
        Self { spring: *spring }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let SpringParams { omega, zeta, .. } = self.spring;
        let b = zeta * omega;
        let y0 = state.position - target;
        let v0 = state.velocity;
        let decay = (-b * dt).exp();
        #[expect(
            clippy::float_cmp,
            reason = "the textbook's exact test for critical damping is what is studied"
        )]
        let (y, v) = if zeta < 1.0 {
            let kappa = omega * (1.0 - zeta * zeta).sqrt();
            let (sn, cs) = (kappa * dt).sin_cos();
            (
                decay * (y0 * cs + (v0 + b * y0) / kappa * sn),
                decay * (v0 * cs - (omega * omega * y0 + b * v0) / kappa * sn),
            )
        } else if zeta == 1.0 {
            let coefficient = v0 + b * y0;
            (
                decay * (y0 + coefficient * dt),
                decay * (v0 - b * coefficient * dt),
            )
        } else {
            let s = omega * (zeta * zeta - 1.0).sqrt();
            let (sh, ch) = ((s * dt).sinh(), (s * dt).cosh());
            (
                decay * (y0 * ch + (v0 + b * y0) / s * sh),
                decay * (v0 * ch - (omega * omega * y0 + b * v0) / s * sh),
            )
        };
        State::new(target + y, v)
    }
}

/// The four coefficients of Ryan Juckett's damped-spring update.
#[derive(Clone, Copy, Debug, Default)]
struct MotionParams {
    pos_pos: f64,
    pos_vel: f64,
    vel_pos: f64,
    vel_vel: f64,
}

/// `|ζ − 1|` below which Juckett's code treats the spring as critically damped.
const JUCKETT_EPSILON: f64 = 1e-4;

impl MotionParams {
    /// Juckett's `CalcDampedSpringMotionParams`, transcribed (in `f64`).
    fn new(omega: f64, zeta: f64, dt: f64) -> Self {
        if omega < JUCKETT_EPSILON {
            return Self {
                pos_pos: 1.0,
                pos_vel: 0.0,
                vel_pos: 0.0,
                vel_vel: 1.0,
            };
        }
        if zeta > 1.0 + JUCKETT_EPSILON {
            // Over-damped: the two real roots z1 < z2 < 0.
            let za = -omega * zeta;
            let zb = omega * (zeta * zeta - 1.0).sqrt();
            let z1 = za - zb;
            let z2 = za + zb;
            let e1 = (z1 * dt).exp();
            let e2 = (z2 * dt).exp();
            let inv_two_zb = 1.0 / (2.0 * zb);
            let e1_over_two_zb = e1 * inv_two_zb;
            let e2_over_two_zb = e2 * inv_two_zb;
            let z1e1_over_two_zb = z1 * e1_over_two_zb;
            let z2e2_over_two_zb = z2 * e2_over_two_zb;
            Self {
                pos_pos: e1_over_two_zb * z2 - z2e2_over_two_zb + e2,
                pos_vel: -e1_over_two_zb + e2_over_two_zb,
                vel_pos: (z1e1_over_two_zb - z2e2_over_two_zb + e2) * z2,
                vel_vel: -z1e1_over_two_zb + z2e2_over_two_zb,
            }
        } else if zeta < 1.0 - JUCKETT_EPSILON {
            // Under-damped.
            let omega_zeta = omega * zeta;
            let alpha = omega * (1.0 - zeta * zeta).sqrt();
            let exp_term = (-omega_zeta * dt).exp();
            let (sin_term, cos_term) = (alpha * dt).sin_cos();
            let inv_alpha = 1.0 / alpha;
            let exp_sin = exp_term * sin_term;
            let exp_cos = exp_term * cos_term;
            let exp_omega_zeta_sin_over_alpha = exp_term * omega_zeta * sin_term * inv_alpha;
            Self {
                pos_pos: exp_cos + exp_omega_zeta_sin_over_alpha,
                pos_vel: exp_sin * inv_alpha,
                vel_pos: -exp_sin * alpha - omega_zeta * exp_omega_zeta_sin_over_alpha,
                vel_vel: exp_cos - exp_omega_zeta_sin_over_alpha,
            }
        } else {
            // Critically damped (within the band).
            let exp_term = (-omega * dt).exp();
            let time_exp = dt * exp_term;
            let time_exp_freq = time_exp * omega;
            Self {
                pos_pos: time_exp_freq + exp_term,
                pos_vel: time_exp,
                vel_pos: -omega * time_exp_freq,
                vel_vel: -time_exp_freq + exp_term,
            }
        }
    }
}

/// Ryan Juckett's damped springs: exact per-regime coefficients computed once per `dt`, with
/// `|ζ − 1| < 10⁻⁴` treated as critical (an error of order `|ζ − 1|` inside that band).
#[derive(Clone, Copy, Debug)]
pub struct JuckettClosedForm {
    spring: SpringParams,
    coefficients: PerDt<MotionParams>,
}

impl Method for JuckettClosedForm {
    const NAME: &'static str = "ε-band closed form (Juckett)";
    const NOTE: &'static str = "Ryan Juckett's per-regime coefficients (in f64), cached per \
        `dt`; `|ζ − 1| < 1e-4` treated as critical; over-damped via `e^{z₁t}`, `e^{z₂t}`.";

    fn new(spring: &SpringParams) -> Self {
        Self {
            spring: *spring,
            coefficients: PerDt::new(f64::NAN, MotionParams::default()),
        }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let SpringParams { omega, zeta, .. } = self.spring;
        let m = self
            .coefficients
            .get(dt, |dt| MotionParams::new(omega, zeta, dt));
        let offset = state.position - target;
        State::new(
            target + offset * m.pos_pos + state.velocity * m.pos_vel,
            offset * m.vel_pos + state.velocity * m.vel_vel,
        )
    }
}
