//! The public contract: invalid input is a typed error, every parametrisation round-trips,
//! presets are what they claim, and the rest and settle-time answers are right.

#![allow(clippy::float_cmp, reason = "exact results are asserted bit for bit")]
#![allow(
    clippy::cast_possible_truncation,
    reason = "test inputs are narrowed to f32 on purpose"
)]

use approx::assert_relative_eq;
use proptest::prelude::*;
use sprung::{Parameter, Regime, RestThreshold, Scalar, Spring, SpringError};

const BAD: [f64; 3] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];

#[test]
fn physical_parameters_are_validated() {
    fn check<T: Scalar>() {
        let n = T::from_f64;
        let one = T::one();
        for bad in BAD.map(|x| {
            if x.is_nan() {
                T::nan()
            } else if x > 0.0 {
                T::infinity()
            } else {
                T::neg_infinity()
            }
        }) {
            assert_eq!(
                Spring::new(bad, one, one),
                Err(SpringError::NotFinite(Parameter::Mass))
            );
            assert_eq!(
                Spring::new(one, bad, one),
                Err(SpringError::NotFinite(Parameter::Stiffness))
            );
            assert_eq!(
                Spring::new(one, one, bad),
                Err(SpringError::NotFinite(Parameter::Damping))
            );
        }
        assert_eq!(
            Spring::new(T::zero(), one, one),
            Err(SpringError::NotPositive(Parameter::Mass))
        );
        assert_eq!(
            Spring::new(n(-1.0), one, one),
            Err(SpringError::NotPositive(Parameter::Mass))
        );
        assert_eq!(
            Spring::new(one, n(-1e-30), one),
            Err(SpringError::Negative(Parameter::Stiffness))
        );
        assert_eq!(
            Spring::new(one, one, n(-1.0)),
            Err(SpringError::Negative(Parameter::Damping))
        );
        // −0 is zero: accepted, and stored as +0.
        let spring = Spring::new(one, n(-0.0), n(-0.0)).unwrap();
        assert!(spring.stiffness().is_sign_positive() && spring.damping().is_sign_positive());
        // Valid on their own, but k/m overflows the type.
        let tiny = T::min_positive_value();
        assert_eq!(
            Spring::new(tiny, T::max_value(), one),
            Err(SpringError::RatesOverflow)
        );
        assert_eq!(
            Spring::new(tiny, one, T::max_value()),
            Err(SpringError::RatesOverflow)
        );
    }
    check::<f32>();
    check::<f64>();
}

#[test]
fn every_parametrisation_refuses_bad_input() {
    type S = Spring<f64>;
    type Build = fn(f64) -> Result<S, SpringError>;
    let all: [(&str, Build, Parameter); 10] = [
        (
            "ω",
            |x| S::from_natural_frequency(x, 1.0),
            Parameter::NaturalFrequency,
        ),
        (
            "ζ",
            |x| S::from_natural_frequency(1.0, x),
            Parameter::DampingRatio,
        ),
        ("half-life", S::from_half_life, Parameter::HalfLife),
        (
            "response",
            |x| S::from_response(x, 1.0),
            Parameter::Response,
        ),
        (
            "fraction",
            |x| S::from_response(1.0, x),
            Parameter::DampingRatio,
        ),
        (
            "duration",
            |x| S::from_duration_and_bounce(x, 0.0),
            Parameter::Duration,
        ),
        (
            "bounce",
            |x| S::from_duration_and_bounce(1.0, x),
            Parameter::Bounce,
        ),
        ("smooth time", S::from_smooth_time, Parameter::SmoothTime),
        (
            "tension",
            |x| S::from_tension_and_friction(x, 1.0),
            Parameter::Tension,
        ),
        (
            "friction",
            |x| S::from_tension_and_friction(1.0, x),
            Parameter::Friction,
        ),
    ];
    for (name, build, parameter) in all {
        for bad in BAD {
            assert_eq!(
                build(bad),
                Err(SpringError::NotFinite(parameter)),
                "{name} = {bad}"
            );
        }
        let negative = build(-1.0).unwrap_err();
        assert!(
            matches!(
                negative,
                SpringError::Negative(p) | SpringError::NotPositive(p) | SpringError::OutOfRange(p)
                    if p == parameter
            ),
            "{name} = −1 gave {negative:?}"
        );
        assert!(!negative.to_string().is_empty());
    }
    // Durations and frequencies of zero cannot make a spring; a bounce must be in (−1, 1].
    assert_eq!(
        S::from_half_life(0.0),
        Err(SpringError::NotPositive(Parameter::HalfLife))
    );
    assert_eq!(
        S::from_response(0.0, 1.0),
        Err(SpringError::NotPositive(Parameter::Response))
    );
    assert_eq!(
        S::from_smooth_time(0.0),
        Err(SpringError::NotPositive(Parameter::SmoothTime))
    );
    assert_eq!(
        S::from_duration_and_bounce(0.0, 0.0),
        Err(SpringError::NotPositive(Parameter::Duration))
    );
    for bounce in [-1.0, -2.0, 1.0 + 1e-15, 5.0] {
        assert_eq!(
            S::from_duration_and_bounce(1.0, bounce),
            Err(SpringError::OutOfRange(Parameter::Bounce)),
            "bounce {bounce}"
        );
    }
    assert!(S::from_duration_and_bounce(1.0, 1.0).is_ok());
    assert!(S::from_duration_and_bounce(1.0, -0.999).is_ok());
    // So small a half-life that ω² overflows.
    assert_eq!(
        Spring::<f32>::from_half_life(1e-30),
        Err(SpringError::RatesOverflow)
    );
    // Every error is an std::error::Error with a message.
    let error: Box<dyn std::error::Error> = Box::new(SpringError::RatesOverflow);
    assert!(error.to_string().contains("overflow"));
}

#[test]
fn invalid_time_steps() {
    let spring = Spring::<f32>::wobbly();
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(
            spring.try_transition(bad).unwrap_err(),
            SpringError::NotFinite(Parameter::TimeStep)
        );
        assert_eq!(spring.transition(bad).matrix(), [[1.0, 0.0], [0.0, 1.0]]);
    }
    assert_eq!(
        spring.try_transition(-1e-9).unwrap_err(),
        SpringError::Negative(Parameter::TimeStep)
    );
    assert_eq!(spring.transition(-1.0).matrix(), [[1.0, 0.0], [0.0, 1.0]]);
    assert_eq!(spring.transition(-1.0).dt(), 0.0);
    assert_eq!(spring.try_transition(0.5).unwrap(), spring.transition(0.5));
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn parametrisations_round_trip(
        omega in 1e-3..1e3_f64,
        zeta in 0.0..20.0_f64,
        time in 1e-3..100.0_f64,
        bounce in -0.99..1.0_f64,
    ) {
        let spring = Spring::<f64>::from_natural_frequency(omega, zeta).unwrap();
        assert_relative_eq!(spring.natural_frequency(), omega, max_relative = 1e-15);
        assert_relative_eq!(spring.damping_ratio().unwrap(), zeta, max_relative = 1e-15);

        let spring = Spring::<f64>::from_response(time, zeta).unwrap();
        assert_relative_eq!(spring.response().unwrap(), time, max_relative = 1e-15);
        assert_relative_eq!(spring.damping_ratio().unwrap(), zeta, max_relative = 1e-15);

        let spring = Spring::<f64>::from_duration_and_bounce(time, bounce).unwrap();
        assert_relative_eq!(spring.duration().unwrap(), time, max_relative = 1e-15);
        assert_relative_eq!(spring.bounce().unwrap(), bounce, epsilon = 1e-14, max_relative = 1e-13);

        let spring = Spring::<f64>::from_smooth_time(time).unwrap();
        assert_relative_eq!(spring.smooth_time().unwrap(), time, max_relative = 1e-15);
        prop_assert_eq!(spring.regime(), Regime::CriticallyDamped);

        let spring = Spring::<f64>::from_half_life(time).unwrap();
        prop_assert_eq!(spring.regime(), Regime::CriticallyDamped);
        assert_relative_eq!(spring.half_life().unwrap(), time, max_relative = 1e-13);

        let spring = Spring::<f64>::from_tension_and_friction(omega, zeta).unwrap();
        prop_assert_eq!((spring.mass(), spring.stiffness(), spring.damping()), (1.0, omega, zeta));

        // And in f32, to its precision.
        let spring = Spring::<f32>::from_duration_and_bounce(time as f32, bounce as f32).unwrap();
        assert_relative_eq!(spring.bounce().unwrap(), bounce as f32, epsilon = 1e-5, max_relative = 1e-5);
        let spring = Spring::<f32>::from_half_life(time as f32).unwrap();
        assert_relative_eq!(spring.half_life().unwrap(), time as f32, max_relative = 1e-6);
    }

    /// The half-life is where the step response first reaches half-way, for every regime.
    #[test]
    fn half_life_is_the_halfway_time(
        (m, k, c) in (1e-3..1e3_f64, 1e-3..1e4_f64, 0.0..1e3_f64),
    ) {
        let spring = Spring::<f64>::new(m, k, c).unwrap();
        let h = spring.half_life().unwrap();
        let [[f0, _], _] = spring.transition(h).matrix();
        prop_assert!((f0 - 0.5).abs() < 1e-9, "f0(h) = {f0}");
        // Not reached before: f0 > 1/2 on a grid below h.
        for i in 1..50 {
            let [[before, _], _] = spring.transition(h * f64::from(i) / 50.0).matrix();
            prop_assert!(before > 0.5 - 1e-12, "f0({}) = {before}", h * f64::from(i) / 50.0);
        }
    }

    /// After the settle time the offset stays within the tolerance; for non-oscillating springs
    /// the estimate is tight (the offset is at the tolerance then).
    #[test]
    fn settle_time_bounds_the_remaining_offset(
        (omega, zeta) in (0.1..100.0_f64, prop_oneof![Just(1.0), 0.01..10.0_f64]),
        distance in 1.0..1000.0_f64,
        fraction in 1e-6..0.5_f64,
    ) {
        let spring = Spring::<f64>::from_natural_frequency(omega, zeta).unwrap();
        let tolerance = distance * fraction;
        let settle = spring.settle_time(distance, tolerance).unwrap();
        for i in 0..200 {
            let t = settle * (1.0 + f64::from(i) / 20.0);
            let [[f0, _], _] = spring.transition(t).matrix();
            prop_assert!((distance * f0).abs() <= tolerance * (1.0 + 1e-9), "|x({t})| = {}", distance * f0);
        }
        if zeta >= 1.0 {
            let [[f0, _], _] = spring.transition(settle).matrix();
            prop_assert!(distance * f0 >= tolerance * 0.5, "loose: x = {} at {settle}", distance * f0);
        }
    }
}

#[test]
fn settle_time_edges() {
    let spring = Spring::<f32>::snappy();
    assert_eq!(spring.settle_time(0.1, 0.5), Some(0.0));
    assert_eq!(spring.settle_time(f32::NAN, 0.5), None);
    assert_eq!(spring.settle_time(1.0, 0.0), None);
    assert_eq!(spring.settle_time(1.0, -1.0), None);
    assert!(spring.settle_time(-100.0, 0.5).unwrap() > 0.0);
    // Never settles: undamped, unsprung, free.
    for (k, c) in [(1.0, 0.0), (0.0, 1.0), (0.0, 0.0)] {
        assert_eq!(
            Spring::<f32>::new(1.0, k, c)
                .unwrap()
                .settle_time(1.0, 0.01),
            None
        );
    }
    // A strongly over-damped spring settles on its slow rate, not on b.
    let heavy = Spring::<f64>::from_natural_frequency(1.0, 1e4).unwrap();
    let t = heavy.settle_time(1.0, 0.01).unwrap();
    assert!(t > 2e4 * 4.0 && t < 2e4 * 5.0, "{t}");
}

#[test]
fn regimes_and_presets() {
    let regime = |m: f64, k: f64, c: f64| Spring::<f64>::new(m, k, c).unwrap().regime();
    assert_eq!(regime(1.0, 0.0, 0.0), Regime::Free);
    assert_eq!(regime(1.0, 0.0, 1.0), Regime::Unsprung);
    assert_eq!(regime(1.0, 4.0, 0.0), Regime::Undamped);
    assert_eq!(regime(1.0, 4.0, 3.9), Regime::Underdamped);
    assert_eq!(regime(1.0, 4.0, 4.0), Regime::CriticallyDamped);
    assert_eq!(regime(1.0, 4.0, 4.1), Regime::Overdamped);
    assert_eq!(regime(2.0, 8.0, 8.0), Regime::CriticallyDamped);

    // react-spring's presets are (tension, friction) at unit mass.
    for (spring, (k, c)) in [
        (Spring::<f32>::gentle(), (120.0, 14.0)),
        (Spring::wobbly(), (180.0, 12.0)),
        (Spring::stiff(), (210.0, 20.0)),
        (Spring::slow(), (280.0, 60.0)),
        (Spring::molasses(), (280.0, 120.0)),
    ] {
        assert_eq!(
            (spring.mass(), spring.stiffness(), spring.damping()),
            (1.0, k, c)
        );
    }
    assert_eq!(Spring::<f32>::slow().regime(), Regime::Overdamped);
    assert_eq!(Spring::<f32>::wobbly().regime(), Regime::Underdamped);
    // SwiftUI's presets are (duration, bounce).
    for (spring, bounce) in [
        (Spring::<f64>::smooth(), 0.0),
        (Spring::snappy(), 0.15),
        (Spring::bouncy(), 0.3),
    ] {
        assert_relative_eq!(spring.duration().unwrap(), 0.5, max_relative = 1e-15);
        assert_relative_eq!(spring.bounce().unwrap(), bounce, epsilon = 1e-15);
    }
    assert_eq!(Spring::<f64>::smooth().regime(), Regime::CriticallyDamped);
    assert_eq!(Spring::<f32>::default(), Spring::<f32>::smooth());
    // The list of presets: eight distinct springs under distinct names, each found by its name.
    let presets = Spring::<f64>::presets();
    for (i, (name, spring)) in presets.iter().enumerate() {
        assert_eq!(Spring::named_preset(name), Some(*spring), "{name}");
        for (other_name, other) in &presets[..i] {
            assert!(
                name != other_name && spring != other,
                "{name} and {other_name}"
            );
        }
    }
    assert_eq!(presets[6], ("snappy", Spring::snappy()));
    assert_eq!(Spring::<f32>::named_preset("Snappy"), None);
    // Accessors that do not exist without stiffness say so.
    let unsprung = Spring::<f32>::new(1.0, 0.0, 1.0).unwrap();
    assert_eq!(
        (
            unsprung.damping_ratio(),
            unsprung.response(),
            unsprung.bounce(),
            unsprung.half_life()
        ),
        (None, None, None, None)
    );
    assert_eq!(unsprung.natural_frequency(), 0.0);
    assert_eq!(unsprung.decay_rate(), 0.0);
}

#[test]
fn decay_rate_is_the_slowest_mode() {
    let under = Spring::<f64>::from_natural_frequency(10.0, 0.3).unwrap();
    assert_relative_eq!(under.decay_rate(), 3.0, max_relative = 1e-15);
    // ζ = 1e6 in f32: b − s would cancel to nothing; λ ≈ ω/(2ζ).
    let heavy = Spring::<f32>::from_natural_frequency(1.0, 1e6).unwrap();
    assert_relative_eq!(heavy.decay_rate(), 5e-7, max_relative = 1e-5);
}

#[test]
fn rest_threshold() {
    let spring = Spring::<f32>::from_natural_frequency(5.0, 1.0).unwrap();
    let rest = RestThreshold::for_spring(&spring, 0.01);
    assert_eq!(rest.offset, 0.01);
    assert_relative_eq!(rest.speed, 0.05);
    assert!(rest.is_at_rest(-0.01, rest.speed));
    assert!(!rest.is_at_rest(0.011, 0.0));
    assert!(!rest.is_at_rest(0.0, -0.06));
    assert!(!rest.is_at_rest(f32::NAN, 0.0));
    // Equal energies at the two tolerances.
    assert_relative_eq!(
        spring.energy(rest.offset, 0.0),
        spring.energy(0.0, rest.speed)
    );
    let clean = RestThreshold::new(f32::NAN, -1.0);
    assert_eq!((clean.offset, clean.speed), (0.0, 0.0));
    let free = Spring::<f32>::new(1.0, 0.0, 0.0).unwrap();
    assert_eq!(RestThreshold::for_spring(&free, 0.5).speed, 0.5);
}

/// The impulse response `f1(t)` sampled densely around the claimed peak never exceeds it, and
/// the peak is attained (within the sampling's resolution), in every regime: under-damped,
/// critical, one ulp either side of critical, over-damped up to ζ = 1e4, and without stiffness.
#[test]
fn impulse_peak_is_the_maximum_of_the_impulse_response() {
    let mut springs: Vec<Spring<f64>> = [
        0.0, 0.05, 0.3, 0.7, 0.999_999, 1.0, 1.000_001, 1.5, 5.0, 50.0, 1e4,
    ]
    .iter()
    .flat_map(|&zeta| {
        [0.5, 10.0, 300.0].map(|omega| Spring::from_natural_frequency(omega, zeta).unwrap())
    })
    .collect();
    let critical = Spring::<f64>::new(2.0, 50.0, 20.0).unwrap();
    let c = critical.damping();
    springs.push(critical);
    springs.push(Spring::new(2.0, 50.0, f64::from_bits(c.to_bits() + 1)).unwrap());
    springs.push(Spring::new(2.0, 50.0, f64::from_bits(c.to_bits() - 1)).unwrap());
    for spring in springs {
        let peak = spring.impulse_peak().unwrap();
        // The peak lies before 2/ω for every damping (π/(2ω) without damping).
        let end = 2.0 / spring.natural_frequency();
        let samples = 20_000;
        let sampled = (0..=samples)
            .map(|i| {
                spring
                    .transition(end * f64::from(i) / f64::from(samples))
                    .matrix()[0][1]
            })
            .fold(f64::MIN, f64::max);
        assert!(
            sampled <= peak * (1.0 + 1e-12),
            "{spring:?}: {sampled} > {peak}"
        );
        assert!(
            sampled >= peak * (1.0 - 1e-6),
            "{spring:?}: {sampled} << {peak}"
        );
    }
    // No stiffness: the supremum m/c; neither stiffness nor damping: unbounded.
    assert_relative_eq!(
        Spring::<f64>::new(2.0, 0.0, 8.0)
            .unwrap()
            .impulse_peak()
            .unwrap(),
        0.25
    );
    assert_eq!(
        Spring::<f64>::new(2.0, 0.0, 0.0).unwrap().impulse_peak(),
        None
    );
    // f32 springs: the same peak, rounded once.
    let spring = Spring::<f32>::bouncy();
    let wide = Spring::<f64>::from(spring);
    assert_eq!(
        spring.impulse_peak().unwrap(),
        wide.impulse_peak().unwrap() as f32
    );
}
