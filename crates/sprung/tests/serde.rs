//! Springs and rest thresholds in RON: every parametrisation reads, writing round-trips
//! exactly, and an invalid file is a clear error, never a panic or an invalid spring.
#![cfg(feature = "serde")]
#![allow(clippy::float_cmp, reason = "round trips are exact")]

use sprung::{Regime, RestThreshold, Spring};

fn read<T>(text: &str) -> Result<Spring<T>, String>
where
    T: sprung::Scalar + for<'de> serde::Deserialize<'de>,
{
    ron::from_str::<Spring<T>>(text).map_err(|error| error.to_string())
}

#[test]
fn every_parametrisation_reads_as_its_constructor() {
    let cases: [(&str, Spring<f64>); 9] = [
        (
            "(mass: 2.0, stiffness: 50.0, damping: 4.0)",
            Spring::new(2.0, 50.0, 4.0).unwrap(),
        ),
        (
            "(stiffness: 50.0, damping: 4.0)",
            Spring::new(1.0, 50.0, 4.0).unwrap(),
        ),
        (
            "(natural_frequency: 8.0, damping_ratio: 0.5)",
            Spring::from_natural_frequency(8.0, 0.5).unwrap(),
        ),
        ("(half_life: 0.1)", Spring::from_half_life(0.1).unwrap()),
        (
            "(response: 0.5, damping_fraction: 0.825)",
            Spring::from_response(0.5, 0.825).unwrap(),
        ),
        (
            "(duration: 0.4, bounce: -0.5)",
            Spring::from_duration_and_bounce(0.4, -0.5).unwrap(),
        ),
        (
            "(duration: 0.4)",
            Spring::from_duration_and_bounce(0.4, 0.0).unwrap(),
        ),
        ("(smooth_time: 0.3)", Spring::from_smooth_time(0.3).unwrap()),
        (
            "(tension: 170.0, friction: 26.0)",
            Spring::from_tension_and_friction(170.0, 26.0).unwrap(),
        ),
    ];
    for (text, expected) in cases {
        assert_eq!(read::<f64>(text), Ok(expected), "{text}");
    }
    for (name, preset) in Spring::<f32>::presets() {
        assert_eq!(read::<f32>(&format!("(preset: {name})")), Ok(preset));
    }
}

#[test]
fn writing_round_trips_exactly() {
    let springs = [
        Spring::<f32>::bouncy(),
        Spring::molasses(),
        Spring::new(1e-6, 3.3e7, 0.0).unwrap(),
        Spring::from_half_life(0.123_456_79).unwrap(),
    ];
    for spring in springs {
        let text = ron::to_string(&spring).unwrap();
        assert_eq!(read::<f32>(&text), Ok(spring), "{text}");
    }
    let spring = Spring::<f64>::from_natural_frequency(std::f64::consts::PI, 0.1).unwrap();
    let text = ron::to_string(&spring).unwrap();
    assert_eq!(read::<f64>(&text), Ok(spring));
    let rest = RestThreshold::<f32>::new(0.5, 6.0);
    let back: RestThreshold<f32> = ron::from_str(&ron::to_string(&rest).unwrap()).unwrap();
    assert_eq!(back, rest);
    for regime in [Regime::Underdamped, Regime::CriticallyDamped, Regime::Free] {
        let back: Regime = ron::from_str(&ron::to_string(&regime).unwrap()).unwrap();
        assert_eq!(back, regime);
    }
}

/// Each invalid file names what is wrong.
#[test]
fn invalid_files_are_clear_errors() {
    let cases = [
        (
            "(stiffness: 100.0, damping: -1.0)",
            "damping must not be negative",
        ),
        (
            "(mass: 0.0, stiffness: 1.0, damping: 1.0)",
            "mass must be positive",
        ),
        ("(half_life: -0.1)", "half-life must be positive"),
        ("(duration: 0.5, bounce: 2.0)", "bounce is out of range"),
        (
            "(natural_frequency: inf, damping_ratio: 1.0)",
            "must be finite",
        ),
        ("(stiffness: 100.0)", "exactly one of"),
        ("(half_life: 0.1, smooth_time: 0.2)", "exactly one of"),
        ("()", "exactly one of"),
        ("(stifness: 100.0, damping: 1.0)", "stifness"),
        ("(preset: snapy)", "snapy"),
        ("(stiffness: \"hard\", damping: 1.0)", "Expected float"),
    ];
    for (text, needle) in cases {
        let error = read::<f32>(text).expect_err(text);
        assert!(error.contains(needle), "{text}: {error}");
    }
    let error = ron::from_str::<RestThreshold<f32>>("(offset: -1.0, speed: 1.0)")
        .unwrap_err()
        .to_string();
    assert!(error.contains("rest offset tolerance"), "{error}");
}
