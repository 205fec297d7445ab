//! One step with a cached exact [`Transition`] against one step of the integrators games use
//! instead, and the batch form [`Transition::step_all`], for `f32` and glam's `Vec3`.
//!
//! The target is "a cached exact step costs no more than a semi-implicit Euler step": each
//! criterion group holds the exact step and its comparisons, so their ratio reads off one run.
//! Semi-implicit Euler and RK4 are defined here, as the comparison only (the library has no
//! integrators); they step the same spring (`ω = 10`, `ζ = 0.5`, unit mass) at 60 fps.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;
use sprung::{Spring, SpringState, SpringValue, Transition};

const OMEGA: f32 = 10.0;
const ZETA: f32 = 0.5;
const DT: f32 = 1.0 / 60.0;

/// The spring's parameters as a numeric integrator holds them: stiffness, damping and the
/// frame's `dt` (unit mass).
#[derive(Clone, Copy)]
struct Integrator {
    stiffness: f32,
    damping: f32,
    dt: f32,
}

impl Integrator {
    fn new() -> Self {
        Self {
            stiffness: OMEGA * OMEGA,
            damping: 2.0 * ZETA * OMEGA,
            dt: DT,
        }
    }

    /// `−k·y − c·v` for the offset `y = x − x*`.
    #[inline]
    fn acceleration<V: SpringValue<f32>>(&self, offset: V, velocity: V) -> V {
        offset * -self.stiffness - velocity * self.damping
    }

    /// Semi-implicit (symplectic) Euler: `v += a·h`, then `x += v·h` with the new `v`.
    #[inline]
    fn semi_implicit_euler<V: SpringValue<f32>>(
        &self,
        state: SpringState<V>,
        target: V,
    ) -> SpringState<V> {
        let velocity =
            state.velocity + self.acceleration(state.position - target, state.velocity) * self.dt;
        SpringState::new(state.position + velocity * self.dt, velocity)
    }

    /// The classic fourth-order Runge–Kutta step on `(x − x*, v)`.
    #[inline]
    fn rk4<V: SpringValue<f32>>(&self, state: SpringState<V>, target: V) -> SpringState<V> {
        let (h, half) = (self.dt, 0.5 * self.dt);
        let y0 = state.position - target;
        let v0 = state.velocity;
        let (k1y, k1v) = (v0, self.acceleration(y0, v0));
        let (y1, v1) = (y0 + k1y * half, v0 + k1v * half);
        let (k2y, k2v) = (v1, self.acceleration(y1, v1));
        let (y2, v2) = (y0 + k2y * half, v0 + k2v * half);
        let (k3y, k3v) = (v2, self.acceleration(y2, v2));
        let (y3, v3) = (y0 + k3y * h, v0 + k3v * h);
        let (k4y, k4v) = (v3, self.acceleration(y3, v3));
        let sixth = h / 6.0;
        SpringState::new(
            state.position + (k1y + (k2y + k3y) * 2.0 + k4y) * sixth,
            v0 + (k1v + (k2v + k3v) * 2.0 + k4v) * sixth,
        )
    }
}

fn transition() -> Transition<f32> {
    Spring::<f32>::from_natural_frequency(OMEGA, ZETA)
        .expect("valid bench spring")
        .transition(DT)
}

/// One step of each method on one value. The inputs are read through `black_box(&…)` from
/// memory that nothing writes (passing them by value makes the state's stack slot also the
/// previous iteration's output slot for some methods, and a partial store forwarded to a wider
/// load then serialises the iterations: a measurement artefact of 3–4× for `Vec3`), and the
/// output goes through `black_box`.
fn single_step<V: SpringValue<f32>>(
    c: &mut Criterion,
    name: &str,
    state: SpringState<V>,
    target: V,
) {
    let exact = transition();
    let euler = Integrator::new();
    let mut group = c.benchmark_group(format!("step/{name}"));
    group.bench_function("exact_cached", |b| {
        b.iter(|| black_box(&exact).step(*black_box(&state), *black_box(&target)));
    });
    group.bench_function("semi_implicit_euler", |b| {
        b.iter(|| black_box(&euler).semi_implicit_euler(*black_box(&state), *black_box(&target)));
    });
    group.bench_function("rk4", |b| {
        b.iter(|| black_box(&euler).rk4(*black_box(&state), *black_box(&target)));
    });
    group.finish();
}

/// Each method over `len` values per iteration (the exact one through `step_all`). The
/// target flips sign every iteration so the states never settle into the subnormal range.
fn batch<V: SpringValue<f32>>(c: &mut Criterion, name: &str, len: usize, value: impl Fn(f32) -> V) {
    let exact = transition();
    let euler = Integrator::new();
    let states: Vec<SpringState<V>> = (0..len)
        .map(|i| SpringState::at_rest(value(i as f32 / len as f32)))
        .collect();
    let targets = [value(1.0), value(-1.0)];
    let mut group = c.benchmark_group(format!("step_all/{name}"));
    group.throughput(Throughput::Elements(len as u64));
    if len > 100_000 {
        group.sample_size(20);
    }
    let mut run = |method: &str, step: &dyn Fn(&mut [SpringState<V>], V)| {
        let mut states = states.clone();
        let mut flip = 0;
        group.bench_function(BenchmarkId::new(method, len), |b| {
            b.iter(|| {
                flip ^= 1;
                step(black_box(&mut states), black_box(targets[flip]));
            });
        });
    };
    run("exact_cached", &|states, target| {
        exact.step_all(states, target);
    });
    run("semi_implicit_euler", &|states, target| {
        for state in states {
            *state = euler.semi_implicit_euler(*state, target);
        }
    });
    run("rk4", &|states, target| {
        for state in states {
            *state = euler.rk4(*state, target);
        }
    });
    group.finish();
}

fn bench(c: &mut Criterion) {
    single_step(c, "f32", SpringState::new(0.25_f32, -1.5), 1.0);
    single_step(
        c,
        "vec3",
        SpringState::new(Vec3::new(0.25, -0.5, 2.0), Vec3::new(-1.5, 0.5, 0.0)),
        Vec3::ONE,
    );
    for len in [1024, 1 << 20] {
        batch(c, "f32", len, |x| x);
        batch(c, "vec3", len, |x| Vec3::new(x, -x, 0.5 * x));
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
