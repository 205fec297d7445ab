//! The cost of computing a [`Transition`](sprung::Transition), per damping regime, in `f32`
//! and `f64`: what a game pays once per spring parameters and frame `dt` (or per spring and
//! frame when every spring has its own parameters and the frame time varies).
//!
//! The regimes are the kernel's branches: under-damped (trigonometric), critical (the series
//! band around `ζ = 1`), over-damped and heavy over-damped (modal form), undamped (`c = 0`),
//! unsprung (`k = 0`) and free (`k = c = 0`). All at 60 fps (`ω = 10`, so `ω·dt = 1/6` and the
//! forcing integral comes from its time series), plus the under-damped case at `dt = 0.5 s`,
//! where it comes from the closed form instead.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use sprung::{Scalar, Spring};

/// `(name, mass, stiffness, damping, dt)`.
const CASES: [(&str, f64, f64, f64, f64); 8] = [
    ("underdamped", 1.0, 100.0, 10.0, 1.0 / 60.0),
    ("critical", 1.0, 100.0, 20.0, 1.0 / 60.0),
    ("overdamped", 1.0, 100.0, 40.0, 1.0 / 60.0),
    ("heavy_overdamped", 1.0, 100.0, 2e4, 1.0 / 60.0),
    ("undamped", 1.0, 100.0, 0.0, 1.0 / 60.0),
    ("unsprung", 1.0, 0.0, 10.0, 1.0 / 60.0),
    ("free", 1.0, 0.0, 0.0, 1.0 / 60.0),
    ("underdamped_long_dt", 1.0, 100.0, 10.0, 0.5),
];

fn transitions<T: Scalar>(c: &mut Criterion, precision: &str) {
    let mut group = c.benchmark_group(format!("transition/{precision}"));
    for (name, m, k, damping, dt) in CASES {
        let spring = Spring::<T>::new(T::from_f64(m), T::from_f64(k), T::from_f64(damping))
            .expect("valid bench spring");
        let dt = T::from_f64(dt);
        group.bench_function(name, |b| {
            b.iter(|| black_box(&spring).transition(black_box(dt)));
        });
    }
    group.finish();
}

fn bench(c: &mut Criterion) {
    transitions::<f32>(c, "f32");
    transitions::<f64>(c, "f64");
}

criterion_group!(benches, bench);
criterion_main!(benches);
