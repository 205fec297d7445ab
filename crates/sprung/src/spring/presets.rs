//! The named presets of react-spring and SwiftUI.

use super::Spring;
use crate::Scalar;

impl<T: Scalar> Spring<T> {
    /// react-spring's `gentle` preset: tension 120, friction 14 (`ζ ≈ 0.64`).
    #[must_use]
    pub fn gentle() -> Self {
        Self::from_constants(1.0, 120.0, 14.0)
    }

    /// react-spring's `wobbly` preset: tension 180, friction 12 (`ζ ≈ 0.45`).
    #[must_use]
    pub fn wobbly() -> Self {
        Self::from_constants(1.0, 180.0, 12.0)
    }

    /// react-spring's `stiff` preset: tension 210, friction 20 (`ζ ≈ 0.69`).
    #[must_use]
    pub fn stiff() -> Self {
        Self::from_constants(1.0, 210.0, 20.0)
    }

    /// react-spring's `slow` preset: tension 280, friction 60 (`ζ ≈ 1.79`).
    #[must_use]
    pub fn slow() -> Self {
        Self::from_constants(1.0, 280.0, 60.0)
    }

    /// react-spring's `molasses` preset: tension 280, friction 120 (`ζ ≈ 3.6`).
    #[must_use]
    pub fn molasses() -> Self {
        Self::from_constants(1.0, 280.0, 120.0)
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

    /// Every preset with its name, react-spring's then SwiftUI's: for a preset picker, an
    /// inspector's list, or a test that runs them all. The names are those of the constructors
    /// and of the `preset` field in the `serde` form.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    ///
    /// let presets = Spring::<f32>::presets();
    /// assert_eq!(presets[0], ("gentle", Spring::gentle()));
    /// assert_eq!(Spring::<f32>::named_preset("bouncy"), Some(Spring::bouncy()));
    /// assert_eq!(Spring::<f32>::named_preset("springy"), None);
    /// ```
    #[must_use]
    pub fn presets() -> [(&'static str, Self); 8] {
        [
            ("gentle", Self::gentle()),
            ("wobbly", Self::wobbly()),
            ("stiff", Self::stiff()),
            ("slow", Self::slow()),
            ("molasses", Self::molasses()),
            ("smooth", Self::smooth()),
            ("snappy", Self::snappy()),
            ("bouncy", Self::bouncy()),
        ]
    }

    /// The preset named `name` (as [`presets`](Self::presets) spells it), or `None`.
    #[must_use]
    pub fn named_preset(name: &str) -> Option<Self> {
        Self::presets()
            .into_iter()
            .find_map(|(preset, spring)| (preset == name).then_some(spring))
    }

    fn preset_duration_bounce(duration: f64, bounce: f64) -> Self {
        let omega = core::f64::consts::TAU / duration;
        let zeta = 1.0 - bounce;
        Self::from_constants(1.0, omega * omega, 2.0 * zeta * omega)
    }

    /// For constants known to be valid (presets): falls back to [`Spring::smooth`]'s
    /// parameters could they ever be refused, so presets never panic.
    fn from_constants(mass: f64, stiffness: f64, damping: f64) -> Self {
        Self::new(
            T::from_f64(mass),
            T::from_f64(stiffness),
            T::from_f64(damping),
        )
        .unwrap_or_else(|_| Self::critical_unit_mass(T::from_f64(4.0 * core::f64::consts::PI)))
    }
}
