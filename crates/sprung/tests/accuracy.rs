//! Every matrix entry against the 320-bit reference: within 8·u·cond, where `cond` is what any
//! algorithm inherits from rounding `b = c/(2m)`, `ω² = k/m` and `t` (plus the final rounding).

#![allow(
    clippy::float_cmp,
    reason = "exact special cases are asserted bit for bit"
)]

mod reference;

use proptest::prelude::*;
use reference::reference;
use sprung::{Scalar, Spring};

/// The bound every entry must meet, in units of `u·cond`.
const BOUND: f64 = 8.0;

/// A spring and step, as exact inputs.
#[derive(Clone, Copy, Debug)]
struct Case {
    name: &'static str,
    mass: f64,
    damping: f64,
    stiffness: f64,
    dt: f64,
}

const fn case(name: &'static str, damping: f64, stiffness: f64, dt: f64) -> Case {
    Case {
        name,
        mass: 1.0,
        damping,
        stiffness,
        dt,
    }
}

/// DESIGN.md's hard cases, `(c, k, dt)` at `m = 1` unless said.
fn hard_cases<T: Scalar>() -> Vec<Case> {
    let two = T::from_f64(2.0);
    let above_two = two.to_f64() + ulp_step::<T>(two, 1.0);
    let below_two = two.to_f64() + ulp_step::<T>(two, -1.0);
    let tiny_mass = if T::UNIT_ROUNDOFF.to_f64() < 1e-10 {
        1e-12
    } else {
        1e-6
    };
    vec![
        case("critical, 1/60 s", 2.0, 1.0, 1.0 / 60.0),
        case("critical, 10 s", 2.0, 1.0, 10.0),
        case("c = 2 + ulp, 1/60 s", above_two, 1.0, 1.0 / 60.0),
        case("c = 2 − ulp, 1/60 s", below_two, 1.0, 1.0 / 60.0),
        case("c = 2 + ulp, 10 s", above_two, 1.0, 10.0),
        case("c = 2 − ulp, 10 s", below_two, 1.0, 10.0),
        case("ζ = 1 + 1e-6", 200.0002, 1e4, 1.0 / 60.0),
        case("heavy (4000, 1e4, 1)", 4000.0, 1e4, 1.0),
        case("heavy (2e4, 1, 1e4)", 2e4, 1.0, 1e4),
        case("heavy (2e6, 1, 1e6)", 2e6, 1.0, 1e6),
        Case {
            name: "tiny mass",
            mass: tiny_mass,
            ..case("", 1.0, 1.0, 1.0 / 60.0)
        },
        case("stiff (2, 1e8, 1)", 2.0, 1e8, 1.0),
        case("huge dt (0.1, 1, 1e6)", 0.1, 1.0, 1e6),
        case("tiny dt (1, 1, 1e-12)", 1.0, 1.0, 1e-12),
        case("dt = 0", 1.0, 1.0, 0.0),
        case("k = 0 (1, 0, 100)", 1.0, 0.0, 100.0),
        case("c = 0 (0, 1, 1e6)", 0.0, 1.0, 1e6),
        case("c = k = 0", 0.0, 0.0, 0.75),
    ]
}

/// `x`'s distance to its neighbour in `T` toward `direction`, as an `f64`.
fn ulp_step<T: Scalar>(x: T, direction: f64) -> f64 {
    let up = direction > 0.0;
    if T::UNIT_ROUNDOFF.to_f64() < 1e-10 {
        let x = x.to_f64();
        let bits = if up { x.to_bits() + 1 } else { x.to_bits() - 1 };
        f64::from_bits(bits) - x
    } else {
        let x = f32::from_bits(f64_to_f32_bits(x.to_f64()));
        let bits = if up { x.to_bits() + 1 } else { x.to_bits() - 1 };
        f64::from(f32::from_bits(bits)) - f64::from(x)
    }
}

/// The bits of an `f64` that is exactly an `f32`.
fn f64_to_f32_bits(x: f64) -> u32 {
    let narrowed = <f32 as Scalar>::from_f64(x);
    assert_eq!(f64::from(narrowed), x, "{x} is not an f32");
    narrowed.to_bits()
}

/// The case's inputs rounded to `T`, and those rounded values back as exact `f64`s.
fn rounded<T: Scalar>(case: &Case) -> ([T; 4], [f64; 4]) {
    let t = [case.mass, case.stiffness, case.damping, case.dt].map(T::from_f64);
    (t, t.map(Scalar::to_f64))
}

/// Below this the `T` results may be subnormal or flushed: errors under it are not counted.
fn underflow_floor<T: Scalar>() -> f64 {
    4.0 * T::min_positive_value().to_f64()
}

/// The largest error ratio over the matrix entries, and over `D = M − I` and the forcing gain
/// `g0`, or a message.
fn error_ratios<T: Scalar>(case: &Case) -> Result<(f64, f64), String> {
    let ([m, k, c, dt], exact) = rounded::<T>(case);
    let spring = Spring::new(m, k, c).map_err(|e| format!("{}: refused: {e}", case.name))?;
    let transition = spring.transition(dt);
    let to_f64 = |a: [[T; 2]; 2]| a.map(|row| row.map(Scalar::to_f64));
    let matrix = to_f64(transition.matrix());
    let increment = to_f64(transition.increment_matrix());
    let g0 = transition.acceleration_gain().to_f64();
    if matrix
        .iter()
        .flatten()
        .chain(increment.iter().flatten())
        .chain([&g0])
        .any(|x| !x.is_finite())
    {
        return Err(format!(
            "{}: non-finite entry {matrix:?} {increment:?}",
            case.name
        ));
    }
    let reference = reference(exact[0], exact[1], exact[2], exact[3]);
    let u = T::UNIT_ROUNDOFF.to_f64();
    let floor = underflow_floor::<T>();
    let worst = |ratios: [f64; 4]| ratios.into_iter().fold(0.0, f64::max);
    Ok((
        worst(reference.matrix_error_ratios(matrix, u, floor)),
        worst(reference.increment_error_ratios(increment, u, floor))
            .max(reference.g0_error_ratio(g0, u, floor)),
    ))
}

fn check_hard_cases<T: Scalar>(label: &str) {
    let mut failures = Vec::new();
    println!("{label}: case | max |M − ref|/(u·cond) | max over D and g0 of |· − ref|/(u·cond)");
    for case in hard_cases::<T>() {
        match error_ratios::<T>(&case) {
            Ok((matrix, increment)) => {
                println!("{label}: {} | {matrix:.2} | {increment:.2}", case.name);
                if matrix > BOUND || increment > BOUND {
                    failures.push(format!("{}: {matrix:.2}, {increment:.2}", case.name));
                }
            }
            Err(message) => failures.push(message),
        }
    }
    assert!(
        failures.is_empty(),
        "{label}: over {BOUND}·u·cond: {failures:#?}"
    );
}

#[test]
fn hard_cases_f64_within_8_u_cond() {
    check_hard_cases::<f64>("f64");
}

#[test]
fn hard_cases_f32_within_8_u_cond() {
    check_hard_cases::<f32>("f32");
}

/// The exact identities of the hard cases hold bit for bit.
#[test]
fn exact_special_cases() {
    fn check<T: Scalar>() {
        let spring = Spring::<T>::new(T::one(), T::one(), T::one()).unwrap();
        let one = T::one();
        let zero = T::zero();
        assert_eq!(spring.transition(zero).matrix(), [[one, zero], [zero, one]]);
        assert_eq!(spring.transition(zero).increment_matrix(), [[zero; 2]; 2]);
        let free = Spring::<T>::new(one, zero, zero).unwrap();
        let dt = T::from_f64(0.75);
        assert_eq!(free.transition(dt).matrix(), [[one, dt], [zero, one]]);
        assert_eq!(
            free.transition(dt).acceleration_gain(),
            dt * dt / T::from_f64(2.0)
        );
        // No negative zeros leak out of the free spring.
        let [[_, _], [m10, _]] = free.transition(dt).matrix();
        assert!(m10.is_sign_positive());
    }
    check::<f32>();
    check::<f64>();
}

/// A deterministic grid over damping ratio, ω·dt and mass: 14 × 10 × 3 springs in each type.
fn grid() -> Vec<Case> {
    let zetas = [
        0.0, 1e-3, 0.1, 0.5, 0.9, 0.999, 0.999_999, 1.0, 1.000_001, 1.001, 1.5, 10.0, 1e3, 1e6,
    ];
    let omega_dts = [0.0, 1e-8, 1e-4, 0.01, 0.3, 1.0, 3.0, 30.0, 1e3, 1e5];
    let masses = [1e-6, 1.0, 1e6];
    let mut cases = Vec::new();
    for &zeta in &zetas {
        for &omega_dt in &omega_dts {
            for &mass in &masses {
                let omega: f64 = 7.0;
                let stiffness = mass * omega * omega;
                cases.push(Case {
                    name: "grid",
                    mass,
                    damping: 2.0 * zeta * omega * mass,
                    stiffness,
                    dt: omega_dt / omega,
                });
            }
        }
    }
    cases
}

fn check_grid<T: Scalar>(label: &str) {
    let mut worst = (0.0, 0.0);
    let mut failures = Vec::new();
    for case in grid() {
        match error_ratios::<T>(&case) {
            Ok((matrix, increment)) => {
                worst = (f64::max(worst.0, matrix), f64::max(worst.1, increment));
                if matrix > BOUND || increment > BOUND {
                    failures.push(format!("{case:?}: {matrix:.2}, {increment:.2}"));
                }
            }
            Err(message) => failures.push(format!("{case:?}: {message}")),
        }
    }
    println!(
        "{label} grid: max |M − ref| = {:.2}·u·cond, max over D, g0 = {:.2}·u·cond",
        worst.0, worst.1
    );
    assert!(failures.is_empty(), "{label}: {failures:#?}");
}

#[test]
fn grid_f64_within_8_u_cond() {
    check_grid::<f64>("f64");
}

#[test]
fn grid_f32_within_8_u_cond() {
    check_grid::<f32>("f32");
}

/// Log-uniform over the ranges a user can reach, with exact zeros mixed in.
fn random_case() -> impl Strategy<Value = Case> {
    let log_uniform = |low: f64, high: f64| (low.log10()..high.log10()).prop_map(|e| 10f64.powf(e));
    let maybe_zero = move |low, high| prop_oneof![1 => Just(0.0), 9 => log_uniform(low, high)];
    (
        log_uniform(1e-6, 1e6),
        maybe_zero(1e-6, 1e8),
        maybe_zero(1e-6, 1e8),
        maybe_zero(1e-9, 1e4),
    )
        .prop_map(|(mass, stiffness, damping, dt)| Case {
            name: "random",
            mass,
            damping,
            stiffness,
            dt,
        })
}

/// Near critical damping, where the band and the modal/trigonometric forms meet.
fn near_critical_case() -> impl Strategy<Value = Case> {
    (-30.0..30.0_f64, -3.0..6.0_f64, -2.0..2.0_f64).prop_map(
        |(log_excess, log_omega_dt, log_mass)| {
            let mass = 10f64.powf(log_mass);
            let zeta = 1.0 + log_excess.signum() * 10f64.powf(-log_excess.abs() / 2.0);
            let omega: f64 = 3.0;
            Case {
                name: "near critical",
                mass,
                damping: 2.0 * zeta * omega * mass,
                stiffness: mass * omega * omega,
                dt: 10f64.powf(log_omega_dt) / omega,
            }
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 1000,
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_springs_within_8_u_cond(case in random_case()) {
        for (matrix, increment) in [error_ratios::<f64>(&case), error_ratios::<f32>(&case)]
            .into_iter()
            .map(|r| r.unwrap())
        {
            prop_assert!(matrix <= BOUND && increment <= BOUND, "{case:?}: {matrix} {increment}");
        }
    }

    #[test]
    fn near_critical_springs_within_8_u_cond(case in near_critical_case()) {
        for (matrix, increment) in [error_ratios::<f64>(&case), error_ratios::<f32>(&case)]
            .into_iter()
            .map(|r| r.unwrap())
        {
            prop_assert!(matrix <= BOUND && increment <= BOUND, "{case:?}: {matrix} {increment}");
        }
    }
}

/// A fixed pseudo-random sweep (`SplitMix64`), so the worst ratio it prints is reproducible: the
/// README quotes it.
#[test]
fn seeded_sweep_reports_worst_ratio() {
    const CASES: usize = 4000;
    let mut state = 0x5eed_5eed_u64;
    let mut next = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut log_uniform = |low: f64, high: f64, zero_chance: f64| {
        if next() < zero_chance {
            0.0
        } else {
            10f64.powf(low + (high - low) * next())
        }
    };
    let mut worst = [(0.0_f64, 0.0_f64); 2];
    for _ in 0..CASES {
        let case = Case {
            name: "sweep",
            mass: log_uniform(-6.0, 6.0, 0.0),
            stiffness: log_uniform(-6.0, 8.0, 0.1),
            damping: log_uniform(-6.0, 8.0, 0.1),
            dt: log_uniform(-9.0, 4.0, 0.05),
        };
        for (slot, result) in [error_ratios::<f64>(&case), error_ratios::<f32>(&case)]
            .into_iter()
            .enumerate()
        {
            let (matrix, increment) = result.unwrap();
            assert!(
                matrix <= BOUND && increment <= BOUND,
                "{case:?}: {matrix} {increment}"
            );
            worst[slot] = (worst[slot].0.max(matrix), worst[slot].1.max(increment));
        }
    }
    for (label, (matrix, increment)) in ["f64", "f32"].into_iter().zip(worst) {
        println!(
            "{label} sweep of {CASES}: max |M − ref| = {matrix:.2}·u·cond, max over D, g0 = {increment:.2}·u·cond"
        );
    }
}
