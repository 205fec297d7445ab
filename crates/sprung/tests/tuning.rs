//! A spring designer's fields: every parametrisation read from one spring, any one edited and
//! every other read back consistently (to 1e-6 relative, in f64 and f32), and the response's
//! overshoot and period against the exact transition.

#![allow(clippy::float_cmp, reason = "exact results are asserted bit for bit")]
#![allow(
    clippy::cast_possible_truncation,
    reason = "test inputs are narrowed to f32 on purpose"
)]

use proptest::prelude::*;
use sprung::{Parameter, Scalar, Spring, SpringError};

/// Whether `a` and `b` agree to `tolerance` relative (absolute near zero).
fn close<T: Scalar>(a: T, b: T, tolerance: f64) -> bool {
    let (a, b) = (a.to_f64(), b.to_f64());
    (a - b).abs() <= tolerance * a.abs().max(b.abs()).max(1e-12)
}

/// Whether two springs are the same to `tolerance`: mass, stiffness and damping.
fn same<T: Scalar>(a: &Spring<T>, b: &Spring<T>, tolerance: f64) -> bool {
    close(a.mass(), b.mass(), tolerance)
        && close(a.stiffness(), b.stiffness(), tolerance)
        && close(a.damping(), b.damping(), tolerance)
}

/// A value `parameter` can take, from a unit draw `u` in [0, 1).
fn value_for(parameter: Parameter, u: f64) -> f64 {
    match parameter {
        Parameter::Bounce => -0.9 + 1.8 * u,
        Parameter::DampingRatio => 3.0 * u,
        Parameter::Mass
        | Parameter::HalfLife
        | Parameter::Response
        | Parameter::Duration
        | Parameter::SmoothTime => 0.05 * 40.0_f64.powf(u),
        Parameter::NaturalFrequency => 0.5 * 100.0_f64.powf(u),
        _ => 1000.0 * u,
    }
}

/// Edits `parameter` of `spring` to `value` and checks the designer's contract.
fn edit_and_read_back<T: Scalar>(
    spring: Spring<T>,
    parameter: Parameter,
    value: T,
    tolerance: f64,
) {
    let edited = spring
        .with_parameter(parameter, value)
        .unwrap_or_else(|error| panic!("{parameter} = {value}: {error}"));
    let read = edited.parameter(parameter).unwrap();
    // A spring holds a bounce as ζ: a small bounce, read back as `1 − ζ` (or `1/ζ − 1`), keeps
    // its digits only relative to 1.
    let condition = if parameter == Parameter::Bounce {
        let bounce = value.to_f64().abs();
        ((1.0 - bounce) / bounce).max(1.0)
    } else {
        1.0
    };
    assert!(
        close(read, value, tolerance * condition),
        "{parameter}: set {value}, read {read} ({edited:?})"
    );
    // Every other field, read back and set again, is the same spring (the half-life makes a
    // critically damped one: it is checked on the exact path instead).
    for other in Parameter::TUNABLE {
        let Some(shown) = edited.parameter(other) else {
            continue;
        };
        if other == Parameter::HalfLife {
            let [[f0, _], _] = edited.transition(shown).matrix();
            assert!(
                close(f0, T::from_f64(0.5), tolerance),
                "half-life {shown}: f0 = {f0}"
            );
            continue;
        }
        let again = edited.with_parameter(other, shown).unwrap();
        // A bounce near ±1 (ζ ≪ 1 as `1 − bounce`, ζ ≫ 1 as `1/(1 + bounce)`) amplifies its
        // own rounding by `|bounce|/(1 − |bounce|)`: the field's condition, which no evaluation
        // can avoid.
        let condition = if other == Parameter::Bounce {
            let bounce = shown.to_f64().abs();
            (bounce / (1.0 - bounce)).max(1.0)
        } else {
            1.0
        };
        assert!(
            same(&again, &edited, tolerance * condition),
            "after {parameter} = {value}: {other} reads {shown}, which makes {again:?}, not \
             {edited:?}"
        );
    }
    // The mass is kept by every edit but the mass's.
    if parameter != Parameter::Mass {
        assert!(close(edited.mass(), spring.mass(), tolerance));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn every_field_edits_and_reads_back(
        mass in 0.1..10.0_f64,
        omega in 0.5..60.0_f64,
        zeta in 0.05..3.0_f64,
        which in 0..12_usize,
        u in 0.0..1.0_f64,
    ) {
        let parameter = Parameter::TUNABLE[which];
        let value = value_for(parameter, u);
        let spring = Spring::<f64>::new(mass, mass * omega * omega, 2.0 * zeta * mass * omega).unwrap();
        edit_and_read_back(spring, parameter, value, 1e-9);
        let narrow = Spring::<f32>::new(mass as f32, (mass * omega * omega) as f32, (2.0 * zeta * mass * omega) as f32).unwrap();
        edit_and_read_back(narrow, parameter, value as f32, 1e-6);
    }
}

#[test]
fn the_fields_of_a_known_spring() {
    // SwiftUI's default spring: response 0.55, damping fraction 0.825.
    let spring = Spring::<f64>::from_response(0.55, 0.825).unwrap();
    let read = |parameter| spring.parameter(parameter).unwrap();
    assert!(close(read(Parameter::Response), 0.55, 1e-15));
    assert!(close(read(Parameter::Duration), 0.55, 1e-15));
    assert!(close(read(Parameter::DampingRatio), 0.825, 1e-15));
    assert!(close(read(Parameter::Bounce), 0.175, 1e-14));
    let omega = std::f64::consts::TAU / 0.55;
    assert!(close(read(Parameter::NaturalFrequency), omega, 1e-15));
    assert!(close(read(Parameter::SmoothTime), 2.0 / omega, 1e-15));
    assert!(close(read(Parameter::Tension), omega * omega, 1e-15));
    assert!(close(read(Parameter::Friction), 1.65 * omega, 1e-15));
    assert_eq!(spring.parameter(Parameter::TimeStep), None);
}

#[test]
fn impossible_edits_are_typed_errors() {
    let free = Spring::<f64>::new(1.0, 0.0, 2.0).unwrap();
    assert_eq!(free.parameter(Parameter::DampingRatio), None);
    assert_eq!(
        free.with_parameter(Parameter::DampingRatio, 0.5),
        Err(SpringError::NotPositive(Parameter::Stiffness))
    );
    // A frequency for a spring without stiffness keeps its damping coefficient.
    let sprung = free
        .with_parameter(Parameter::NaturalFrequency, 3.0)
        .unwrap();
    assert_eq!((sprung.stiffness(), sprung.damping()), (9.0, 2.0));
    let spring = Spring::<f64>::snappy();
    for (parameter, value, error) in [
        (
            Parameter::Bounce,
            1.5,
            SpringError::OutOfRange(Parameter::Bounce),
        ),
        (
            Parameter::Bounce,
            -1.0,
            SpringError::OutOfRange(Parameter::Bounce),
        ),
        (
            Parameter::Response,
            0.0,
            SpringError::NotPositive(Parameter::Response),
        ),
        (
            Parameter::HalfLife,
            f64::NAN,
            SpringError::NotFinite(Parameter::HalfLife),
        ),
        (
            Parameter::Damping,
            -1.0,
            SpringError::Negative(Parameter::Damping),
        ),
        (
            Parameter::TimeStep,
            1.0,
            SpringError::OutOfRange(Parameter::TimeStep),
        ),
        (
            Parameter::NaturalFrequency,
            1e200,
            SpringError::RatesOverflow,
        ),
    ] {
        assert_eq!(
            spring.with_parameter(parameter, value),
            Err(error),
            "{parameter} = {value}"
        );
    }
}

#[test]
fn overshoot_and_period_are_the_exact_response_s() {
    for zeta in [0.05, 0.3, 0.7, 0.99, 0.999_999] {
        let spring = Spring::<f64>::from_natural_frequency(12.0, zeta).unwrap();
        let period = spring.period().unwrap();
        // The step response peaks past the target at half a damped period, by the overshoot.
        let [[f0, _], _] = spring.transition(period / 2.0).matrix();
        assert!(
            close(-f0, spring.overshoot(), 1e-12),
            "ζ = {zeta}: {f0} against {}",
            spring.overshoot()
        );
        // And is back at the same phase, a decayed swing later.
        let [[f1, _], _] = spring.transition(period * 1.5).matrix();
        assert!(close(-f1, spring.overshoot().powi(3), 1e-10), "ζ = {zeta}");
    }
    for spring in [
        Spring::<f64>::from_natural_frequency(12.0, 1.0).unwrap(),
        Spring::<f64>::from_natural_frequency(12.0, 2.0).unwrap(),
        Spring::<f64>::new(1.0, 0.0, 1.0).unwrap(),
    ] {
        assert_eq!(spring.overshoot(), 0.0);
        assert_eq!(spring.period(), None);
    }
    let undamped = Spring::<f64>::new(1.0, 4.0, 0.0).unwrap();
    assert_eq!(undamped.overshoot(), 1.0);
    assert!(close(
        undamped.period().unwrap(),
        std::f64::consts::PI,
        1e-15
    ));
}
