//! Structural properties of the transition that hold for every valid spring: the determinant,
//! the semigroup law, energy, continuity through critical damping, frame-rate independence,
//! finiteness over the whole parameter range, and the increment form's benefit in `f32`.

mod reference;

use proptest::prelude::*;
use sprung::{Scalar, Spring, SpringState, Transition};

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// `10^e` for `e` uniform in `[low, high)`.
fn log_uniform(low: f64, high: f64) -> impl Strategy<Value = f64> {
    (low..high).prop_map(|e| 10f64.powf(e))
}

/// A log-uniform value or, one time in ten, exactly zero.
fn log_uniform_or_zero(low: f64, high: f64) -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 9 => log_uniform(low, high)]
}

/// Springs a user can reach: `m ∈ [1e-6, 1e6]`, `k, c ∈ {0} ∪ [1e-6, 1e8]`.
fn spring_parameters() -> impl Strategy<Value = (f64, f64, f64)> {
    (
        log_uniform(-6.0, 6.0),
        log_uniform_or_zero(-6.0, 8.0),
        log_uniform_or_zero(-6.0, 8.0),
    )
}

fn spring<T: Scalar>((m, k, c): (f64, f64, f64)) -> Spring<T> {
    Spring::new(T::from_f64(m), T::from_f64(k), T::from_f64(c)).expect("valid spring")
}

fn matrix_f64<T: Scalar>(transition: &Transition<T>) -> [[f64; 2]; 2] {
    transition.matrix().map(|row| row.map(Scalar::to_f64))
}

/// `(b, ω)` of the spring as `f64`, from its rounded parameters.
fn rates<T: Scalar>(spring: &Spring<T>) -> (f64, f64) {
    let (m, k, c) = (
        spring.mass().to_f64(),
        spring.stiffness().to_f64(),
        spring.damping().to_f64(),
    );
    (c / (2.0 * m), (k / m).sqrt())
}

/// `det M = e^{−ct/m}` to `8u·(1 + 2bt)·(|f0·g| + |ω²f1²|)`.
fn check_determinant<T: Scalar>(parameters: (f64, f64, f64), dt: f64) -> Result<(), TestCaseError> {
    let spring = spring::<T>(parameters);
    let dt = T::from_f64(dt);
    let [[f0, f1], [m10, g]] = matrix_f64(&spring.transition(dt));
    let (b, _) = rates(&spring);
    let t = dt.to_f64();
    let det = f0 * g - f1 * m10;
    let expected = (-2.0 * b * t).exp();
    let u = T::UNIT_ROUNDOFF.to_f64();
    let allowance = 8.0 * u * (1.0 + 2.0 * b * t) * ((f0 * g).abs() + (f1 * m10).abs())
        + 4.0 * T::min_positive_value().to_f64();
    prop_assert!(
        (det - expected).abs() <= allowance,
        "det {det:e} vs {expected:e} (allowance {allowance:e})"
    );
    Ok(())
}

/// `M(t₁ + t₂) = M(t₂)·M(t₁)` normwise in `(ω·x, v)` coordinates.
fn check_semigroup<T: Scalar>(
    parameters: (f64, f64, f64),
    t1: f64,
    t2: f64,
) -> Result<(), TestCaseError> {
    let spring = spring::<T>(parameters);
    let (t1, t2) = (T::from_f64(t1), T::from_f64(t2));
    let total = t1 + t2;
    let (b, omega) = rates(&spring);
    let t = total.to_f64();
    let scale = if omega > 0.0 {
        omega
    } else {
        1.0 / t.max(f64::MIN_POSITIVE)
    };
    let scaled = |m: [[f64; 2]; 2]| [[m[0][0], m[0][1] * scale], [m[1][0] / scale, m[1][1]]];
    let first = scaled(matrix_f64(&spring.transition(t1)));
    let second = scaled(matrix_f64(&spring.transition(t2)));
    let whole = scaled(matrix_f64(&spring.transition(total)));
    let norm = |m: &[[f64; 2]; 2]| m.iter().flatten().fold(0.0_f64, |a, x| a.max(x.abs()));
    let mut worst = 0.0_f64;
    for i in 0..2 {
        for j in 0..2 {
            let product = second[i][0] * first[0][j] + second[i][1] * first[1][j];
            worst = worst.max((product - whole[i][j]).abs());
        }
    }
    let u = T::UNIT_ROUNDOFF.to_f64();
    // Each factor is within a few u·cond, and cond grows with the rates times t; the rounding
    // of t₁ + t₂ itself moves M by u·t·‖A‖ ≤ u·(ω + 2b)·t.
    let allowance =
        16.0 * u * (1.0 + (omega + 2.0 * b) * t) * (norm(&whole) + norm(&second) * norm(&first))
            + 8.0 * T::min_positive_value().to_f64();
    prop_assert!(
        worst <= allowance,
        "‖M(t1+t2) − M(t2)M(t1)‖ = {worst:e} > {allowance:e}"
    );
    Ok(())
}

/// The energy `ω²x² + v²` (per unit of `m/2`) after one step, over the energy before, with
/// `ω² = k/m` and the step's products and sums taken exactly (320 bits): what is measured is
/// the transition's own error, not the rounding of the check (which alone reaches ~6u when the
/// two terms of `x'` nearly cancel, and made an f64 evaluation of this check fail at 10u in one
/// case in ~25 000).
fn energy_ratio<T: Scalar>(spring: &Spring<T>, dt: f64, x: f64, v: f64) -> f64 {
    use reference::{Big, big, to_f64};
    let w2 = big(spring.stiffness().to_f64()) / big(spring.mass().to_f64());
    let [[f0, f1], [m10, g]] =
        matrix_f64(&spring.transition(T::from_f64(dt))).map(|row| row.map(big));
    let energy = |x: &Big, v: &Big| &w2 * x * x + v * v;
    let (x, v) = (big(x), big(v));
    let after = energy(&(&f0 * &x + &f1 * &v), &(&m10 * &x + &g * &v));
    to_f64(&(after / energy(&x, &v)))
}

proptest! {
    #![proptest_config(config(2000))]

    #[test]
    fn determinant_is_the_exponential_of_the_trace(
        parameters in spring_parameters(),
        dt in log_uniform_or_zero(-9.0, 4.0),
    ) {
        check_determinant::<f64>(parameters, dt)?;
        check_determinant::<f32>(parameters, dt)?;
    }

    #[test]
    fn semigroup_law_holds_normwise(
        parameters in spring_parameters(),
        t1 in log_uniform(-6.0, 2.0),
        t2 in log_uniform(-6.0, 2.0),
    ) {
        check_semigroup::<f64>(parameters, t1, t2)?;
        check_semigroup::<f32>(parameters, t1, t2)?;
    }

    #[test]
    fn energy_never_increases_with_damping(
        parameters in spring_parameters(),
        dt in log_uniform(-9.0, 4.0),
        x in -1e3..1e3_f64,
        v in -1e3..1e3_f64,
    ) {
        for (ratio, u) in [
            (energy_ratio(&spring::<f64>(parameters), dt, x, v), f64::EPSILON / 2.0),
            (energy_ratio(&spring::<f32>(parameters), dt, x, v), f64::from(f32::EPSILON) / 2.0),
        ] {
            prop_assert!(ratio <= 1.0 + 8.0 * u, "energy grew by {:e}", ratio - 1.0);
        }
    }

    #[test]
    fn energy_is_conserved_without_damping(
        (m, k) in (log_uniform(-6.0, 6.0), log_uniform(-6.0, 8.0)),
        dt in log_uniform(-9.0, 4.0),
        x in -1e3..1e3_f64,
        v in -1e3..1e3_f64,
    ) {
        let ratio = energy_ratio(&spring::<f64>((m, k, 0.0)), dt, x, v);
        prop_assert!((ratio - 1.0).abs() <= 8.0 * f64::EPSILON / 2.0, "f64: {:e}", ratio - 1.0);
        let ratio = energy_ratio(&spring::<f32>((m, k, 0.0)), dt, x, v);
        prop_assert!((ratio - 1.0).abs() <= 8.0 * f64::from(f32::EPSILON) / 2.0, "f32: {:e}", ratio - 1.0);
    }
}

/// Walks the damping through ±60 ulps of `center` and checks that no step between neighbours
/// moves an entry by more than a few `u·cond` (no seam where evaluation forms meet), with
/// `cond` from the 320-bit reference at `center`.
fn check_continuity<T: Scalar>(m: f64, k: f64, center: f64, dt: f64) -> Result<f64, TestCaseError> {
    let (m, k, center, dt) = (
        T::from_f64(m),
        T::from_f64(k),
        T::from_f64(center),
        T::from_f64(dt),
    );
    let reference = reference::reference(m.to_f64(), k.to_f64(), center.to_f64(), dt.to_f64());
    let u = T::UNIT_ROUNDOFF.to_f64();
    let mut damping = center;
    for _ in 0..60 {
        damping = next_down(damping);
    }
    let mut previous = matrix_f64(&Spring::new(m, k, damping).unwrap().transition(dt));
    let mut worst = 0.0_f64;
    for _ in 0..120 {
        damping = next_up(damping);
        let current = matrix_f64(&Spring::new(m, k, damping).unwrap().transition(dt));
        for i in 0..2 {
            for j in 0..2 {
                let cond = reference.matrix[i][j].abs() + reference.sensitivity[i][j];
                let jump = (current[i][j] - previous[i][j]).abs();
                let allowed = u * cond + T::min_positive_value().to_f64();
                worst = worst.max(jump / allowed);
            }
        }
        previous = current;
    }
    prop_assert!(
        worst <= 8.0,
        "a 1-ulp change of c moved M by {worst:.1}·u·cond"
    );
    Ok(worst)
}

fn next_up<T: Scalar>(x: T) -> T {
    step_ulp(x, 1)
}

fn next_down<T: Scalar>(x: T) -> T {
    step_ulp(x, -1)
}

/// The neighbour of a positive `x` in `T`.
fn step_ulp<T: Scalar>(x: T, direction: i64) -> T {
    let value = x.to_f64();
    if T::UNIT_ROUNDOFF.to_f64() < 1e-10 {
        let bits = value.to_bits().wrapping_add_signed(direction);
        T::from_f64(f64::from_bits(bits))
    } else {
        let narrow = <f32 as Scalar>::from_f64(value);
        let bits = narrow
            .to_bits()
            .wrapping_add_signed(i32::try_from(direction).unwrap());
        T::from_f64(f64::from(f32::from_bits(bits)))
    }
}

proptest! {
    #![proptest_config(config(64))]

    #[test]
    fn continuous_through_critical_damping(
        m in log_uniform(-3.0, 3.0),
        k in log_uniform(-3.0, 6.0),
        omega_dt in log_uniform(-6.0, 6.0),
    ) {
        let dt = omega_dt / (k / m).sqrt();
        let critical = 2.0 * (k * m).sqrt();
        check_continuity::<f64>(m, k, critical, dt)?;
        check_continuity::<f32>(m, k, critical, dt)?;
    }
}

/// At the edges of the band, `|b² − ω²|·t² = 1e-3`, where the series meets the modal (above)
/// and trigonometric (below) forms, for `bt` from 0.1 to 30 where the entries are far from
/// underflow: the seams themselves. (`f32` springs share the `f64` evaluation, so this covers
/// both.)
#[test]
fn continuous_across_the_band_edges() {
    for bt in [0.1, 0.5, 1.0, 3.0, 10.0, 30.0] {
        for side in [1.0, -1.0] {
            // m = k = 1, so ω = 1, b = bt/t and (b² − 1)·t² = ±1e-3.
            let t = (bt * bt - side * 1e-3_f64).sqrt();
            let damping = 2.0 * bt / t;
            let worst = check_continuity::<f64>(1.0, 1.0, damping, t).unwrap();
            println!(
                "bt = {bt}, {} edge: largest 1-ulp jump {worst:.2}·u·cond",
                if side > 0.0 { "upper" } else { "lower" }
            );
        }
    }
}

/// Steps 1 s of motion as `frames` equal steps with the increment form.
fn simulate<T: Scalar>(
    spring: &Spring<T>,
    frames: u32,
    start: SpringState<T>,
    target: T,
) -> SpringState<T> {
    let transition = spring.transition(T::one() / T::from_f64(f64::from(frames)));
    (0..frames).fold(start, |state, _| transition.step(state, target))
}

fn check_frame_rate_independence<T: Scalar>(
    omega: f64,
    zeta: f64,
    start: (f64, f64),
    target: f64,
) -> Result<(), TestCaseError> {
    let spring =
        Spring::<T>::from_natural_frequency(T::from_f64(omega), T::from_f64(zeta)).unwrap();
    let start = SpringState::new(T::from_f64(start.0), T::from_f64(start.1));
    let target = T::from_f64(target);
    let once = simulate(&spring, 1, start, target);
    let (b, w) = rates(&spring);
    let scale = (start.position - target).to_f64().abs()
        + start.velocity.to_f64().abs() / w
        + target.to_f64().abs();
    let u = T::UNIT_ROUNDOFF.to_f64();
    for frames in [60, 144, 240] {
        let stepped = simulate(&spring, frames, start, target);
        // Each step rounds the sum and the increment (∝ frames) and the entries' errors add up
        // along the trajectory (∝ (ω + 2b)·1 s); dt = 1/frames is itself rounded.
        let allowance = 4.0 * u * (f64::from(frames) + w + 2.0 * b) * scale;
        let position = (stepped.position - once.position).to_f64().abs();
        let velocity = (stepped.velocity - once.velocity).to_f64().abs() / w;
        prop_assert!(
            position <= allowance && velocity <= allowance,
            "{frames} frames: Δx = {position:e}, Δv/ω = {velocity:e}, allowance {allowance:e}"
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(1000))]

    #[test]
    fn one_second_is_the_same_at_any_frame_rate(
        omega in log_uniform(-0.5, 2.0),
        zeta in prop_oneof![Just(0.0), Just(1.0), 0.0..5.0_f64],
        start in (-100.0..100.0_f64, -100.0..100.0_f64),
        target in -100.0..100.0_f64,
    ) {
        check_frame_rate_independence::<f64>(omega, zeta, start, target)?;
        check_frame_rate_independence::<f32>(omega, zeta, start, target)?;
    }
}

/// The step inputs of a finiteness check, in `f64`: state, target, acceleration and target
/// velocity.
type StepInputs = ((f64, f64), f64, f64, f64);

/// Every entry of `transition`, `D` and `g0` finite, and each step form from `inputs` finite.
fn check_transition_finite<T: Scalar>(
    case: (f64, f64, f64, f64),
    transition: &Transition<T>,
    ((position, velocity), target, acceleration, target_velocity): StepInputs,
) -> Result<(), TestCaseError> {
    let entries = transition
        .matrix()
        .into_iter()
        .chain(transition.increment_matrix())
        .flatten()
        .chain([transition.acceleration_gain()]);
    for entry in entries {
        prop_assert!(entry.is_finite(), "{case:?}: {transition:?}");
    }
    let state = SpringState::new(T::from_f64(position), T::from_f64(velocity));
    let (target, acceleration, target_velocity) = (
        T::from_f64(target),
        T::from_f64(acceleration),
        T::from_f64(target_velocity),
    );
    for stepped in [
        transition.step(state, target),
        transition.step_with_acceleration(state, target, acceleration),
        transition.step_toward_moving(state, target, target_velocity),
    ] {
        prop_assert!(
            stepped.position.is_finite() && stepped.velocity.is_finite(),
            "{case:?}: {stepped:?}"
        );
    }
    Ok(())
}

/// Every entry, `D` and `g0` finite, and every step from a finite state finite.
fn check_finite<T: Scalar>(m: f64, k: f64, c: f64, dt: f64) -> Result<(), TestCaseError> {
    let Ok(spring) = Spring::new(T::from_f64(m), T::from_f64(k), T::from_f64(c)) else {
        // Only rates that overflow T may be refused in this range.
        prop_assert!(
            T::UNIT_ROUNDOFF.to_f64() > 1e-10 && (k / m > 3e38 || c / m > 3e38),
            "refused ({m}, {k}, {c})"
        );
        return Ok(());
    };
    let transition = spring.transition(T::from_f64(dt));
    check_transition_finite((m, k, c, dt), &transition, ((3.0, -40.0), -7.0, -9.81, 2.5))
}

proptest! {
    #![proptest_config(config(20_000))]

    /// DESIGN.md's sweep: `m ∈ [1e-12, 1e12]`, `k, c ∈ [0, 1e12]`, `dt ∈ [0, 1e6]`.
    #[test]
    fn finite_over_the_whole_range(
        m in log_uniform(-12.0, 12.0),
        k in prop_oneof![1 => Just(0.0), 1 => Just(1e12), 8 => log_uniform(-12.0, 12.0)],
        c in prop_oneof![1 => Just(0.0), 1 => Just(1e12), 8 => log_uniform(-12.0, 12.0)],
        dt in prop_oneof![1 => Just(0.0), 1 => Just(1e6), 8 => log_uniform(-12.0, 6.0)],
    ) {
        check_finite::<f64>(m, k, c, dt)?;
        check_finite::<f32>(m, k, c, dt)?;
    }
}

/// Any value of the type's range: zero (if allowed), the extremes (the largest finite value, the
/// smallest normal and subnormals) or a log-uniform value over every exponent.
fn anywhere_in_f64(zero: bool) -> impl Strategy<Value = f64> {
    prop_oneof![
        u32::from(zero) => Just(0.0),
        1 => Just(f64::MAX),
        1 => (0.5..1.0).prop_map(|x: f64| x * f64::MAX),
        1 => Just(f64::MIN_POSITIVE),
        1 => (1e-10..1.0).prop_map(|x: f64| x * f64::MIN_POSITIVE),
        12 => log_uniform(-307.0, 308.0),
    ]
}

/// Beyond DESIGN.md's range, to the ends of `f64`: a spring is refused (a typed error, when
/// `k/m` or `c/m` overflows) or its transition and steps are finite. Accelerations and target
/// velocities are 0 here, since a real one over a step of 1e300 s legitimately overflows the
/// state. (A free spring's `g0 = dt²/2` once overflowed to ∞ and gave `0·∞ = NaN` in `D`; a step
/// of `f64::MAX` overflowed `t·S(z)` in the band form.)
fn check_finite_anywhere<T: Scalar>(m: f64, k: f64, c: f64, dt: f64) -> Result<(), TestCaseError> {
    let Ok(spring) = Spring::new(T::from_f64(m), T::from_f64(k), T::from_f64(c)) else {
        return Ok(());
    };
    let transition = spring.transition(T::from_f64(dt));
    check_transition_finite((m, k, c, dt), &transition, ((1.0, -1.0), 0.0, 0.0, 0.0))
}

proptest! {
    #![proptest_config(config(20_000))]

    /// Every exponent of `f64`, and its extremes, for the spring and the step.
    #[test]
    fn finite_to_the_ends_of_the_type(
        m in anywhere_in_f64(false),
        k in anywhere_in_f64(true),
        c in anywhere_in_f64(true),
        dt in anywhere_in_f64(true),
    ) {
        check_finite_anywhere::<f64>(m, k, c, dt)?;
        check_finite_anywhere::<f32>(m, k, c, dt)?;
    }
}

/// Drift of one minute at 240 fps in `f32` against an `f64` run of the same steps:
/// `(crate's step, increment added to the position without a remainder, plain matrix)`.
fn drift_over_a_minute(omega: f32) -> (f64, f64, f64) {
    let spring32 = Spring::<f32>::from_natural_frequency(omega, 0.0).unwrap();
    let spring64 = Spring::<f64>::from(spring32);
    let dt = 1.0_f32 / 240.0;
    let (step32, step64) = (spring32.transition(dt), spring64.transition(f64::from(dt)));
    let [[f0, f1], [m10, g]] = step32.matrix();
    let [[d00, d01], [d10, d11]] = step32.increment_matrix();
    let plain = |s: SpringState<f32>, target: f32| {
        let offset = s.position - target;
        SpringState::new(
            target + (f0 * offset + f1 * s.velocity),
            m10 * offset + g * s.velocity,
        )
    };
    let increment = |s: SpringState<f32>, target: f32| {
        let offset = s.position - target;
        SpringState::new(
            s.position + (d00 * offset + d01 * s.velocity),
            s.velocity + (d10 * offset + d11 * s.velocity),
        )
    };
    let mut states = [SpringState::new(0.0_f32, 0.0); 3];
    let mut exact = SpringState::new(0.0_f64, 0.0);
    let mut errors = [0.0_f64; 3];
    for frame in 0..(240 * 60) {
        // The target moves every 2 s, so the oscillation keeps being re-excited.
        let target = (frame / 480) % 5;
        exact = step64.step(exact, f64::from(target));
        #[expect(clippy::cast_precision_loss, reason = "small integers")]
        let target = target as f32;
        states[0] = step32.step(states[0], target);
        states[1] = increment(states[1], target);
        states[2] = plain(states[2], target);
        for (error, state) in errors.iter_mut().zip(&states) {
            *error = error.max((f64::from(state.position) - exact.position).abs());
        }
    }
    (errors[0], errors[1], errors[2])
}

/// DESIGN.md: `M₀₀ ≈ 1 − (ωt)²/2` rounds badly in `f32`, so stepping with `M` drifts far more
/// than stepping with the increment `D = M − I`: the bias of the rounded `M₀₀` acts on every
/// step and adds up where nothing damps it away. The crate's step is the increment form with the
/// rounding of each position update carried over (which also makes springs arrive, see
/// `tests/arrival.rs`); it must keep the increment form's advantage.
#[test]
fn increment_form_drifts_far_less_than_the_plain_matrix_in_f32() {
    let mut ratios = Vec::new();
    for omega in [1.0, 2.0, 3.0, 6.0, 10.0, 20.0] {
        let (carried, increment, plain) = drift_over_a_minute(omega);
        println!(
            "ω = {omega}: step {carried:.2e}, increment without remainder {increment:.2e}, \
             plain M {plain:.2e}, ratio to plain {:.0}",
            plain / carried
        );
        // Amplitudes are O(1): the step stays within ~1e3 ulps after 14400 steps.
        assert!(carried < 1e-4, "ω = {omega}: the step drifted {carried:e}");
        assert!(
            plain > 10.0 * carried,
            "ω = {omega}: plain {plain:e} vs the step {carried:e}"
        );
        assert!(
            carried <= 2.0 * increment,
            "ω = {omega}: the step {carried:e} vs the increment form {increment:e}"
        );
        ratios.push(plain / carried);
    }
    ratios.sort_by(f64::total_cmp);
    let median = f64::midpoint(ratios[2], ratios[3]);
    assert!(median > 30.0, "median drift ratio {median:.1}");
}

/// The case that made the f64 evaluation of the energy check fail (ωt ≈ 6·10⁴, the two terms
/// of `x'` nearly cancelling): the transition itself conserves the energy to 8u.
#[test]
fn energy_check_regression() {
    let spring = spring::<f64>((2.061_959_297_002_045e-6, 0.877_262_412_634_271_4, 0.0));
    let ratio = energy_ratio(
        &spring,
        91.870_485_780_348_66,
        -654.181_659_378_822_5,
        196.852_376_273_362_67,
    );
    assert!(
        (ratio - 1.0).abs() <= 8.0 * f64::EPSILON / 2.0,
        "{:e}",
        ratio - 1.0
    );
}
