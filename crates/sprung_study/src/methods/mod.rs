//! The methods under study, each behind the one [`Method`] trait so the harness treats them
//! uniformly.
//!
//! Every method animates the same spring `x'' + c·x' + k·(x − x*) = 0` (unit mass) from a
//! [`SpringParams`] and is advanced one frame at a time with [`Method::step`]. Methods that
//! have per-`dt` coefficients cache them and recompute only when `dt` changes, as a game would.

mod closed_form;
mod exact;
mod integrators;
mod smoothing;

pub use closed_form::{JuckettClosedForm, NaiveClosedForm};
pub use exact::{ExactCached, ExactCachedF32, ExactRecomputed};
pub use integrators::{
    ExplicitEuler, ImplicitEuler, RungeKutta4, SemiImplicitEuler, SemiImplicitEuler4,
    SemiImplicitEuler16, SubSteppedEuler, VelocityVerlet,
};
pub use smoothing::{ExponentialLerp, SmoothDamp, fit_first_order_rate};

/// Position and velocity, in `f64`.
pub type State = sprung::SpringState<f64>;

/// The spring every method animates: unit mass, natural frequency `ω` and damping ratio `ζ`.
///
/// The physical parameters are rounded to `f64` once, here, and every method (and the
/// high-precision reference) uses exactly these values, so differences between methods are the
/// methods' own and not those of their parameter rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpringParams {
    /// Natural frequency `ω` in rad/s.
    pub omega: f64,
    /// Damping ratio `ζ`.
    pub zeta: f64,
    /// Stiffness `k = ω²` (unit mass).
    pub stiffness: f64,
    /// Damping coefficient `c = 2ζω` (unit mass).
    pub damping: f64,
    /// The rate `r` of the first-order system `x' = r·(x* − x)` whose step response best fits
    /// (in the max norm) this spring's over `ω·t ∈ [0, 20]`: what the first-order smoothing
    /// methods use. See [`fit_first_order_rate`].
    pub first_order_rate: f64,
}

impl SpringParams {
    /// The spring with natural frequency `omega` and damping ratio `zeta`.
    #[must_use]
    pub fn new(omega: f64, zeta: f64) -> Self {
        Self {
            omega,
            zeta,
            stiffness: omega * omega,
            damping: (zeta + zeta) * omega,
            first_order_rate: fit_first_order_rate(omega, zeta),
        }
    }

    /// The acceleration `−k·y − c·v` at offset `y = x − x*` and velocity `v`.
    #[inline]
    #[must_use]
    pub fn acceleration(&self, offset: f64, velocity: f64) -> f64 {
        -self.stiffness * offset - self.damping * velocity
    }
}

/// One way of advancing a spring by a frame.
pub trait Method {
    /// Short name for tables and the plot legend.
    const NAME: &'static str;
    /// What the method is and the choices made implementing it, for the report's notes.
    const NOTE: &'static str;
    /// Unit roundoff of the arithmetic the method runs in: the growth factor of its step may
    /// exceed 1 by a few of these from rounding alone (see [`crate::evaluate`]).
    const UNIT_ROUNDOFF: f64 = f64::EPSILON / 2.0;

    /// Sets the method up for `spring` (no frame has been stepped yet).
    fn new(spring: &SpringParams) -> Self;

    /// Advances `state` by `dt` seconds toward the constant `target`.
    fn step(&mut self, state: State, target: f64, dt: f64) -> State;
}

/// Something to do with every method type: [`for_each_method`] calls
/// [`visit`](MethodVisitor::visit) once per method, monomorphised, so timing loops see the
/// concrete step and nothing is dispatched dynamically.
pub trait MethodVisitor {
    /// Called with each method type in turn.
    fn visit<M: Method>(&mut self);
}

/// Calls `visitor` with every method, in the order of the report.
pub fn for_each_method(visitor: &mut impl MethodVisitor) {
    visitor.visit::<ExactCached>();
    visitor.visit::<ExactRecomputed>();
    visitor.visit::<ExactCachedF32>();
    visitor.visit::<ExplicitEuler>();
    visitor.visit::<SemiImplicitEuler>();
    visitor.visit::<SemiImplicitEuler4>();
    visitor.visit::<SemiImplicitEuler16>();
    visitor.visit::<VelocityVerlet>();
    visitor.visit::<RungeKutta4>();
    visitor.visit::<ImplicitEuler>();
    visitor.visit::<NaiveClosedForm>();
    visitor.visit::<JuckettClosedForm>();
    visitor.visit::<ExponentialLerp>();
    visitor.visit::<SmoothDamp>();
}

/// A per-`dt` cache: recomputes its value only when `dt` changes (bit for bit).
#[derive(Clone, Copy, Debug)]
pub(crate) struct PerDt<C> {
    dt: f64,
    value: C,
}

impl<C: Copy> PerDt<C> {
    /// A cache holding `value` for `dt`.
    pub(crate) fn new(dt: f64, value: C) -> Self {
        Self { dt, value }
    }

    /// The value for `dt`, from `compute` if `dt` differs from the cached one.
    #[inline]
    pub(crate) fn get(&mut self, dt: f64, compute: impl FnOnce(f64) -> C) -> C {
        if dt.to_bits() != self.dt.to_bits() {
            self.dt = dt;
            self.value = compute(dt);
        }
        self.value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run<M: Method>(spring: &SpringParams, dt: f64, steps: usize) -> State {
        let mut method = M::new(spring);
        (0..steps).fold(State::new(0.3, -2.0), |state, _| {
            method.step(state, 1.0, dt)
        })
    }

    fn close(a: State, b: State, tolerance: f64) -> bool {
        (a.position - b.position).abs() <= tolerance && (a.velocity - b.velocity).abs() <= tolerance
    }

    #[test]
    fn closed_forms_agree_with_the_exact_step() {
        for zeta in [0.0, 0.3, 1.0, 3.0] {
            let spring = SpringParams::new(10.0, zeta);
            for dt in [0.01, 0.5] {
                let exact = run::<ExactCached>(&spring, dt, 10);
                assert!(close(run::<ExactRecomputed>(&spring, dt, 10), exact, 0.0));
                assert!(close(run::<NaiveClosedForm>(&spring, dt, 10), exact, 1e-12));
                assert!(close(
                    run::<JuckettClosedForm>(&spring, dt, 10),
                    exact,
                    1e-12
                ));
                assert!(close(run::<ExactCachedF32>(&spring, dt, 10), exact, 1e-4));
            }
        }
    }

    #[test]
    fn implicit_euler_solves_the_backward_system() {
        let spring = SpringParams::new(7.0, 0.4);
        let (start, dt) = (State::new(0.3, -2.0), 0.2);
        let end = ImplicitEuler::new(&spring).step(start, 1.0, dt);
        let acceleration = spring.acceleration(end.position - 1.0, end.velocity);
        assert!((end.position - (start.position + dt * end.velocity)).abs() < 1e-15);
        assert!((end.velocity - (start.velocity + dt * acceleration)).abs() < 1e-14);
    }

    /// Global error at `dt` over that at `dt/2`, after 1 s.
    fn error_ratio<M: Method>() -> f64 {
        let spring = SpringParams::new(10.0, 0.5);
        let exact = run::<ExactCached>(&spring, 0.01, 100).position;
        let coarse = (run::<M>(&spring, 0.01, 100).position - exact).abs();
        let fine = (run::<M>(&spring, 0.005, 200).position - exact).abs();
        coarse / fine
    }

    #[test]
    fn integrators_converge_at_their_order() {
        let first = 1.7..2.3;
        assert!(first.contains(&error_ratio::<ExplicitEuler>()));
        assert!(first.contains(&error_ratio::<SemiImplicitEuler>()));
        assert!(first.contains(&error_ratio::<SemiImplicitEuler4>()));
        assert!(first.contains(&error_ratio::<ImplicitEuler>()));
        let r = error_ratio::<VelocityVerlet>();
        assert!((3.4..4.6).contains(&r), "verlet {r}");
        assert!((14.0..18.0).contains(&error_ratio::<RungeKutta4>()));
    }

    #[test]
    fn smooth_damp_approximates_the_critical_spring() {
        let spring = SpringParams::new(10.0, 1.0);
        let exact = run::<ExactCached>(&spring, 1.0 / 60.0, 60);
        assert!(close(
            run::<SmoothDamp>(&spring, 1.0 / 60.0, 60),
            exact,
            1e-2
        ));
    }

    #[test]
    fn first_order_fit_misses_a_critical_spring_by_ten_percent() {
        let rate = fit_first_order_rate(10.0, 1.0) / 10.0;
        assert!((0.40..0.43).contains(&rate), "r/ω = {rate}");
        // The misfit at that rate: max |(1 + τ)e^{−τ} − e^{−rτ}|.
        let misfit = (0..20_000)
            .map(|i| f64::from(i) * 1e-3)
            .map(|tau| ((1.0 + tau) * (-tau).exp() - (-rate * tau).exp()).abs())
            .fold(0.0, f64::max);
        assert!((0.09..0.11).contains(&misfit), "misfit {misfit}");
    }
}
