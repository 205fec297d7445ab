//! Numeric integrators of `y'' = −k·y − c·y'` (`y = x − x*`), the way spring code in games
//! and UI libraries steps springs.
//!
//! Stability limits (`h = dt`), from the design document: explicit Euler is never stable at
//! `c = 0`; semi-implicit Euler needs `ωh < 2(√(ζ²+1) − ζ)`; velocity Verlet `ωh < 2` at
//! `c = 0`; RK4 `ωh < 2√2` at `ζ = 0` and `(ζ + √(ζ²−1))·ωh < 2.785` for `ζ ≥ 1`; implicit
//! Euler is always stable but over-damps.

use super::{Method, SpringParams, State};

/// Explicit (forward) Euler: both updates use the state at the start of the step.
#[derive(Clone, Copy, Debug)]
pub struct ExplicitEuler {
    spring: SpringParams,
}

impl Method for ExplicitEuler {
    const NAME: &'static str = "explicit Euler";
    const NOTE: &'static str = "`x += v·h`, `v += a(x₀, v₀)·h`: first order, gains energy.";

    fn new(spring: &SpringParams) -> Self {
        Self { spring: *spring }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let offset = state.position - target;
        let acceleration = self.spring.acceleration(offset, state.velocity);
        State::new(
            state.position + state.velocity * dt,
            state.velocity + acceleration * dt,
        )
    }
}

/// One semi-implicit (symplectic) Euler step: velocity first, then position with the new
/// velocity.
#[inline]
fn semi_implicit(spring: &SpringParams, state: State, target: f64, h: f64) -> State {
    let velocity =
        state.velocity + spring.acceleration(state.position - target, state.velocity) * h;
    State::new(state.position + velocity * h, velocity)
}

/// Semi-implicit (symplectic) Euler, the usual game-physics step.
#[derive(Clone, Copy, Debug)]
pub struct SemiImplicitEuler {
    spring: SpringParams,
}

impl Method for SemiImplicitEuler {
    const NAME: &'static str = "semi-implicit Euler";
    const NOTE: &'static str = "`v += a(x, v)·h`, then `x += v·h`: first order, symplectic; \
        the baseline of the cost ratios.";

    fn new(spring: &SpringParams) -> Self {
        Self { spring: *spring }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        semi_implicit(&self.spring, state, target, dt)
    }
}

/// Semi-implicit Euler with `N` sub-steps of `dt/N` per frame.
#[derive(Clone, Copy, Debug)]
pub struct SubSteppedEuler<const N: usize> {
    spring: SpringParams,
}

/// Semi-implicit Euler, 4 sub-steps per frame.
pub type SemiImplicitEuler4 = SubSteppedEuler<4>;
/// Semi-implicit Euler, 16 sub-steps per frame.
pub type SemiImplicitEuler16 = SubSteppedEuler<16>;

impl<const N: usize> Method for SubSteppedEuler<N> {
    const NAME: &'static str = match N {
        4 => "semi-implicit Euler ×4",
        16 => "semi-implicit Euler ×16",
        _ => "semi-implicit Euler ×N",
    };
    const NOTE: &'static str = "Semi-implicit Euler with `dt` split into equal sub-steps: \
        the cheap way to buy accuracy and stability (cost grows with the count).";

    fn new(spring: &SpringParams) -> Self {
        Self { spring: *spring }
    }

    #[inline]
    fn step(&mut self, mut state: State, target: f64, dt: f64) -> State {
        let h = dt / N as f64;
        for _ in 0..N {
            state = semi_implicit(&self.spring, state, target, h);
        }
        state
    }
}

/// Velocity Verlet. The force depends on the velocity (damping), so the end-of-step
/// acceleration `a(x₁, v₁)` is solved for `v₁` (it is linear in `v₁`), which keeps the method
/// second order and time-symmetric; at `c = 0` this is exactly the textbook method. (Using
/// the half-step velocity in the damping instead, as some game code does, makes it first
/// order for any `c > 0`.)
#[derive(Clone, Copy, Debug)]
pub struct VelocityVerlet {
    spring: SpringParams,
}

impl Method for VelocityVerlet {
    const NAME: &'static str = "velocity Verlet";
    const NOTE: &'static str = "`v½ = v + a₀·h/2`, `x += v½·h`, `v = v½ + a(x₁, v)·h/2` solved \
        for the new `v` (damping is linear in it): second order, symplectic at `c = 0`.";

    fn new(spring: &SpringParams) -> Self {
        Self { spring: *spring }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let half = 0.5 * dt;
        let a0 = self
            .spring
            .acceleration(state.position - target, state.velocity);
        let half_velocity = state.velocity + a0 * half;
        let position = state.position + half_velocity * dt;
        let velocity = (half_velocity - half * self.spring.stiffness * (position - target))
            / (1.0 + half * self.spring.damping);
        State::new(position, velocity)
    }
}

/// The classic fourth-order Runge–Kutta method on `(y, v)`.
#[derive(Clone, Copy, Debug)]
pub struct RungeKutta4 {
    spring: SpringParams,
}

impl Method for RungeKutta4 {
    const NAME: &'static str = "RK4";
    const NOTE: &'static str = "Classic 4-stage Runge–Kutta on `(x − x*, v)`: fourth order, \
        four force evaluations.";

    fn new(spring: &SpringParams) -> Self {
        Self { spring: *spring }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let s = &self.spring;
        let half = 0.5 * dt;
        let y0 = state.position - target;
        let v0 = state.velocity;
        let (k1y, k1v) = (v0, s.acceleration(y0, v0));
        let (y1, v1) = (y0 + k1y * half, v0 + k1v * half);
        let (k2y, k2v) = (v1, s.acceleration(y1, v1));
        let (y2, v2) = (y0 + k2y * half, v0 + k2v * half);
        let (k3y, k3v) = (v2, s.acceleration(y2, v2));
        let (y3, v3) = (y0 + k3y * dt, v0 + k3v * dt);
        let (k4y, k4v) = (v3, s.acceleration(y3, v3));
        let sixth = dt / 6.0;
        State::new(
            state.position + (k1y + 2.0 * (k2y + k3y) + k4y) * sixth,
            v0 + (k1v + 2.0 * (k2v + k3v) + k4v) * sixth,
        )
    }
}

/// Implicit (backward) Euler, with its 2×2 linear system solved exactly:
/// `v₁ = (v₀ − h·k·y₀)/(1 + h·c + h²·k)`, `y₁ = y₀ + h·v₁`.
#[derive(Clone, Copy, Debug)]
pub struct ImplicitEuler {
    spring: SpringParams,
}

impl Method for ImplicitEuler {
    const NAME: &'static str = "implicit Euler";
    const NOTE: &'static str = "Backward Euler, the 2×2 system solved in closed form: \
        unconditionally stable, first order, over-damps.";

    fn new(spring: &SpringParams) -> Self {
        Self { spring: *spring }
    }

    #[inline]
    fn step(&mut self, state: State, target: f64, dt: f64) -> State {
        let (k, c) = (self.spring.stiffness, self.spring.damping);
        let offset = state.position - target;
        let velocity = (state.velocity - dt * k * offset) / (1.0 + dt * (c + dt * k));
        State::new(state.position + velocity * dt, velocity)
    }
}
