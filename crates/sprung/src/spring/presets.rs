//! The named presets of react-spring and SwiftUI.

use super::Spring;
use crate::Scalar;

impl<T: Scalar> Spring<T> {
    /// react-spring's `gentle` preset: tension 120, friction 14 (`ζ ≈ 0.64`).
    #[must_use]
    pub fn gentle() -> Self {
        Self::preset(1.0, 120.0, 14.0)
    }

    /// react-spring's `wobbly` preset: tension 180, friction 12 (`ζ ≈ 0.45`).
    #[must_use]
    pub fn wobbly() -> Self {
        Self::preset(1.0, 180.0, 12.0)
    }

    /// react-spring's `stiff` preset: tension 210, friction 20 (`ζ ≈ 0.69`).
    #[must_use]
    pub fn stiff() -> Self {
        Self::preset(1.0, 210.0, 20.0)
    }

    /// react-spring's `slow` preset: tension 280, friction 60 (`ζ ≈ 1.79`).
    #[must_use]
    pub fn slow() -> Self {
        Self::preset(1.0, 280.0, 60.0)
    }

    /// react-spring's `molasses` preset: tension 280, friction 120 (`ζ ≈ 3.6`).
    #[must_use]
    pub fn molasses() -> Self {
        Self::preset(1.0, 280.0, 120.0)
    }

    /// SwiftUI's `.smooth`: duration 0.5 s, bounce 0 (critically damped).
    #[must_use]
    pub fn smooth() -> Self {
        Self::preset_duration_bounce(0.5, 0.0)
    }

    /// SwiftUI's `.snappy`: duration 0.5 s, bounce 0.15.
    #[must_use]
    pub fn snappy() -> Self {
        Self::preset_duration_bounce(0.5, 0.15)
    }

    /// SwiftUI's `.bouncy`: duration 0.5 s, bounce 0.3.
    #[must_use]
    pub fn bouncy() -> Self {
        Self::preset_duration_bounce(0.5, 0.3)
    }

    fn preset_duration_bounce(duration: f64, bounce: f64) -> Self {
        let omega = core::f64::consts::TAU / duration;
        let zeta = 1.0 - bounce;
        Self::preset(1.0, omega * omega, 2.0 * zeta * omega)
    }

    /// For constants known to be valid (presets): falls back to [`Spring::smooth`]'s
    /// parameters could they ever be refused, so presets never panic.
    fn preset(mass: f64, stiffness: f64, damping: f64) -> Self {
        Self::new(
            T::from_f64(mass),
            T::from_f64(stiffness),
            T::from_f64(damping),
        )
        .unwrap_or_else(|_| Self::critical_unit_mass(T::from_f64(4.0 * core::f64::consts::PI)))
    }
}
