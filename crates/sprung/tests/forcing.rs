//! The forced steps (constant acceleration; a target moving at constant velocity) against the
//! exponential of the augmented system, computed independently at 320 bits.
//!
//! With the state `(x, v, x*, 1)` the forced spring is linear and autonomous:
//! `x' = v`, `v' = −ω²(x − x*) − 2b·v + a`, `x*' = r`. `exp(A·t)` by scaling and squaring of its
//! Taylor series is the exact step, sharing nothing with the crate's closed forms.

#![allow(clippy::float_cmp, reason = "exact results are asserted bit for bit")]

mod reference;

use proptest::prelude::*;
use reference::{Big, big, to_f64};
use sprung::{Scalar, Spring, SpringState};

type Matrix4 = [[Big; 4]; 4];

fn multiply(a: &Matrix4, b: &Matrix4) -> Matrix4 {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).fold(big(0.0), |sum, k| sum + &a[i][k] * &b[k][j]))
    })
}

/// `exp(A)` by scaling and squaring its Taylor series at the working precision.
fn exponential(a: &Matrix4) -> Matrix4 {
    let norm = (0..4)
        .map(|j| (0..4).map(|i| to_f64(&a[i][j]).abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let mut squarings = 0;
    while norm > 0.25 * 2f64.powi(squarings) {
        squarings += 1;
    }
    let scale = big(2f64.powi(-squarings));
    let scaled: Matrix4 = std::array::from_fn(|i| std::array::from_fn(|j| &a[i][j] * &scale));
    let identity: Matrix4 =
        std::array::from_fn(|i| std::array::from_fn(|j| big(if i == j { 1.0 } else { 0.0 })));
    let mut sum = identity.clone();
    let mut term = identity;
    for n in 1..80 {
        let divisor = big(f64::from(n));
        term = multiply(&term, &scaled);
        term = std::array::from_fn(|i| std::array::from_fn(|j| &term[i][j] / &divisor));
        sum = std::array::from_fn(|i| std::array::from_fn(|j| &sum[i][j] + &term[i][j]));
    }
    for _ in 0..squarings {
        sum = multiply(&sum, &sum);
    }
    sum
}

/// The exact `(x₁, v₁)` after `t` from `(x₀, v₀)` with the target at `target_start` moving at
/// `r`, under constant acceleration `a`, for `b = c/(2m)` and `ω² = k/m`.
fn exact_step(
    (m, k, c): (f64, f64, f64),
    t: f64,
    (x0, v0): (f64, f64),
    target_start: &Big,
    r: f64,
    a: f64,
) -> (f64, f64) {
    let (m, k, c, t) = (big(m), big(k), big(c), big(t));
    let w2 = &k / &m;
    let two_b = &c / &m;
    let zero = || big(0.0);
    let generator: Matrix4 = [
        [zero(), big(1.0), zero(), zero()],
        [-w2.clone(), -two_b, w2, big(a)],
        [zero(), zero(), zero(), big(r)],
        [zero(), zero(), zero(), zero()],
    ];
    let scaled: Matrix4 = std::array::from_fn(|i| std::array::from_fn(|j| &generator[i][j] * &t));
    let e = exponential(&scaled);
    let state = [big(x0), big(v0), target_start.clone(), big(1.0)];
    let row = |i: usize| (0..4).fold(big(0.0), |sum, j| sum + &e[i][j] * &state[j]);
    (to_f64(&row(0)), to_f64(&row(1)))
}

/// `((m, k, c), t, (x₀, v₀), target, r, a)`.
type ForcedCase = ((f64, f64, f64), f64, (f64, f64), f64, f64, f64);

/// Parameters where `exp(A·t)` by scaling and squaring stays far inside 320 bits: rates times
/// `t` up to ~40.
fn forced_case() -> impl Strategy<Value = ForcedCase> {
    (
        0.1..10.0_f64,
        prop_oneof![1 => Just(0.0), 4 => 0.0..400.0_f64],
        prop_oneof![1 => Just(0.0), 4 => 0.0..40.0_f64],
        prop_oneof![1 => Just(1.0 / 60.0), 4 => (-4.0..0.3_f64).prop_map(|e| 10f64.powf(e))],
        (-50.0..50.0_f64, -50.0..50.0_f64),
        -50.0..50.0_f64,
        -20.0..20.0_f64,
        -20.0..20.0_f64,
    )
        .prop_map(|(m, k, c, t, state, target, r, a)| ((m, k, c), t, state, target, r, a))
}

/// `16u·(1 + (ω + 2b)·t)` times the size of everything that enters the step.
fn allowance<T: Scalar>((m, k, c): (f64, f64, f64), t: f64, sizes: &[f64]) -> f64 {
    let (omega, two_b) = ((k / m).sqrt(), c / m);
    16.0 * T::UNIT_ROUNDOFF.to_f64()
        * (1.0 + (omega + two_b) * t)
        * sizes.iter().map(|x| x.abs()).sum::<f64>()
}

/// What drives the spring besides its target.
#[derive(Clone, Copy, Debug)]
enum Forcing {
    /// A constant acceleration; the target stands still.
    Acceleration(f64),
    /// The target moves at this velocity and ends the step at the given target.
    MovingTarget(f64),
}

/// The crate's forced step against the augmented exponential, in `T`.
fn check_forced<T: Scalar>(
    parameters: (f64, f64, f64),
    t: f64,
    (x0, v0): (f64, f64),
    target: f64,
    forcing: Forcing,
) -> Result<(), TestCaseError> {
    let n = T::from_f64;
    let f = Scalar::to_f64;
    let spring = Spring::new(n(parameters.0), n(parameters.1), n(parameters.2)).unwrap();
    let rounded = (f(spring.mass()), f(spring.stiffness()), f(spring.damping()));
    let (t, x0, v0, target) = (n(t), n(x0), n(v0), n(target));
    let time = f(t);
    let transition = spring.transition(t);
    let start = SpringState::new(x0, v0);
    // The exact step, and the sizes that enter it (the rounding budget of each row).
    let (stepped, (x1, v1), position_sizes, velocity_sizes) = match forcing {
        Forcing::Acceleration(a) => {
            let a = n(a);
            let exact = exact_step(rounded, time, (f(x0), f(v0)), &big(f(target)), 0.0, f(a));
            (
                transition.step_with_acceleration(start, target, a),
                exact,
                [f(v0) * time, f(a) * time * time],
                [f(v0), f(a) * time],
            )
        }
        Forcing::MovingTarget(r) => {
            let r = n(r);
            // The target starts where moving at r for t brings it to `target`, exactly.
            let target_start = big(f(target)) - big(f(r)) * big(time);
            let exact = exact_step(rounded, time, (f(x0), f(v0)), &target_start, f(r), 0.0);
            (
                transition.step_toward_moving(start, target, r),
                exact,
                [f(v0) * time, f(r) * time],
                [f(v0), f(r)],
            )
        }
    };
    let tolerance = allowance::<T>(
        rounded,
        time,
        &[[f(x0), f(target), x1].as_slice(), &position_sizes].concat(),
    );
    prop_assert!(
        (f(stepped.position) - x1).abs() <= tolerance,
        "{forcing:?}: x {} vs {x1} ({tolerance:e})",
        f(stepped.position)
    );
    let pull = (f(x0) - f(target)) / time.max(1e-300);
    let tolerance = allowance::<T>(
        rounded,
        time,
        &[[pull, v1].as_slice(), &velocity_sizes].concat(),
    );
    prop_assert!(
        (f(stepped.velocity) - v1).abs() <= tolerance,
        "{forcing:?}: v {} vs {v1} ({tolerance:e})",
        f(stepped.velocity)
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn constant_acceleration_matches_the_augmented_exponential(
        (parameters, t, state, target, _r, a) in forced_case(),
    ) {
        check_forced::<f64>(parameters, t, state, target, Forcing::Acceleration(a))?;
        check_forced::<f32>(parameters, t, state, target, Forcing::Acceleration(a))?;
    }

    #[test]
    fn moving_target_matches_the_augmented_exponential(
        (parameters, t, state, target, r, _a) in forced_case(),
    ) {
        check_forced::<f64>(parameters, t, state, target, Forcing::MovingTarget(r))?;
        check_forced::<f32>(parameters, t, state, target, Forcing::MovingTarget(r))?;
    }
}

/// With `k = 0` there is no target to pull toward: a damped projectile, `x` linear in `a`.
#[test]
fn unsprung_projectile_under_gravity() {
    let spring = Spring::<f64>::new(2.0, 0.0, 0.5).unwrap();
    let (b2, t) = (0.25_f64, 3.0_f64); // c/m
    let start = SpringState::new(1.0, 4.0);
    // Any target: k = 0 ignores it.
    for target in [0.0, 1e6, -3.0] {
        let s = spring
            .transition(t)
            .step_with_acceleration(start, target, -9.81);
        let decay = (-b2 * t).exp();
        let terminal = -9.81 / b2;
        let v = terminal + (4.0 - terminal) * decay;
        let x = 1.0 + terminal * t + (4.0 - terminal) * (1.0 - decay) / b2;
        assert!(
            (s.velocity - v).abs() < 1e-12 && (s.position - x).abs() < 1e-11,
            "{s:?} vs {x} {v}"
        );
    }
}

/// The steady state of following a target moving at `r` is a lag of `c·r/k` at velocity `r`,
/// and the moving-target step keeps it exactly under uneven frame times.
#[test]
fn steady_lag_is_kept_exactly_under_uneven_frames() {
    let spring = Spring::<f32>::from_natural_frequency(8.0, 0.7).unwrap();
    let r = 12.0_f32;
    let lag = spring.damping() * r / spring.stiffness();
    let mut target = 500.0_f32;
    let mut state = SpringState::new(target - lag, r);
    for (i, dt) in [1.0 / 60.0, 1.0 / 144.0, 0.05, 1.0 / 30.0, 0.002, 0.25]
        .iter()
        .cycle()
        .take(600)
        .enumerate()
    {
        target += r * dt;
        state = spring.transition(*dt).step_toward_moving(state, target, r);
        // Positions round to their ulp every frame; the spring turns a position error δ into a
        // velocity error of about ω·δ. Neither may accumulate.
        let ulps = 16.0 * f32::EPSILON * target.abs();
        assert!(
            (target - state.position - lag).abs() <= ulps,
            "frame {i}: lag {}",
            target - state.position
        );
        assert!(
            (state.velocity - r).abs() <= 8.0 * ulps,
            "frame {i}: velocity {}",
            state.velocity
        );
    }
}
