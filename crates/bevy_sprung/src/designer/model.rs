//! What the designer edits, without any of its UI: the spring being tuned and the one it is
//! compared with, the fields of every parametrisation, the readouts, the code and the file it
//! writes.

use std::fmt::Write as _;

use bevy::prelude::*;
use sprung::{Parameter, Regime, Spring, SpringError};

/// One of the ways the crate builds a spring, as a group of the designer's fields.
///
/// Every group shows the same spring: editing a field of one group changes the spring, and
/// every other group reads it again ([`Spring::with_parameter`], [`Spring::parameter`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Reflect)]
pub enum Parametrisation {
    /// Mass, stiffness and damping: [`Spring::new`].
    Physical,
    /// Natural frequency and damping ratio: [`Spring::from_natural_frequency`].
    Frequency,
    /// The half-life of a critically damped spring: [`Spring::from_half_life`].
    HalfLife,
    /// SwiftUI's response and damping fraction: [`Spring::from_response`].
    Response,
    /// SwiftUI's and Motion's duration and bounce: [`Spring::from_duration_and_bounce`].
    #[default]
    DurationBounce,
    /// Unity `SmoothDamp`'s smooth time: [`Spring::from_smooth_time`].
    SmoothTime,
    /// react-spring's tension and friction: [`Spring::from_tension_and_friction`].
    TensionFriction,
}

impl Parametrisation {
    /// Every parametrisation, in the order the designer lists them.
    pub const ALL: [Self; 7] = [
        Self::Physical,
        Self::Frequency,
        Self::HalfLife,
        Self::Response,
        Self::DurationBounce,
        Self::SmoothTime,
        Self::TensionFriction,
    ];

    /// The group's title.
    #[must_use]
    pub const fn title(self) -> &'static str {
        match self {
            Self::Physical => "Physical",
            Self::Frequency => "Frequency and ratio",
            Self::HalfLife => "Half-life",
            Self::Response => "SwiftUI response",
            Self::DurationBounce => "Duration and bounce",
            Self::SmoothTime => "Unity smooth time",
            Self::TensionFriction => "react-spring",
        }
    }

    /// The group's fields, in the order its constructor takes them.
    #[must_use]
    pub const fn fields(self) -> &'static [Parameter] {
        match self {
            Self::Physical => &[Parameter::Mass, Parameter::Stiffness, Parameter::Damping],
            Self::Frequency => &[Parameter::NaturalFrequency, Parameter::DampingRatio],
            Self::HalfLife => &[Parameter::HalfLife],
            Self::Response => &[Parameter::Response, Parameter::DampingRatio],
            Self::DurationBounce => &[Parameter::Duration, Parameter::Bounce],
            Self::SmoothTime => &[Parameter::SmoothTime],
            Self::TensionFriction => &[Parameter::Tension, Parameter::Friction],
        }
    }

    /// The name of the constructor this group calls.
    #[must_use]
    pub const fn constructor(self) -> &'static str {
        match self {
            Self::Physical => "new",
            Self::Frequency => "from_natural_frequency",
            Self::HalfLife => "from_half_life",
            Self::Response => "from_response",
            Self::DurationBounce => "from_duration_and_bounce",
            Self::SmoothTime => "from_smooth_time",
            Self::TensionFriction => "from_tension_and_friction",
        }
    }

    /// The spring this group's constructor makes from `values` (in [`fields`](Self::fields)
    /// order; missing ones are an error).
    ///
    /// # Errors
    /// What the constructor refuses, or [`SpringError::OutOfRange`] of the mass for too few
    /// values.
    pub fn build(self, values: &[f32]) -> Result<Spring<f32>, SpringError> {
        let value = |i: usize| {
            values
                .get(i)
                .copied()
                .ok_or(SpringError::OutOfRange(Parameter::Mass))
        };
        match self {
            Self::Physical => Spring::new(value(0)?, value(1)?, value(2)?),
            Self::Frequency => Spring::from_natural_frequency(value(0)?, value(1)?),
            Self::HalfLife => Spring::from_half_life(value(0)?),
            Self::Response => Spring::from_response(value(0)?, value(1)?),
            Self::DurationBounce => Spring::from_duration_and_bounce(value(0)?, value(1)?),
            Self::SmoothTime => Spring::from_smooth_time(value(0)?),
            Self::TensionFriction => Spring::from_tension_and_friction(value(0)?, value(1)?),
        }
    }

    /// Whether this group can say `spring` at all: all but the physical one make springs of
    /// unit mass, the half-life and the smooth time critically damped ones, and the ratios
    /// need stiffness.
    #[must_use]
    pub fn speaks(self, spring: &Spring<f32>) -> bool {
        let fields = self.fields();
        // Exactly 1: the constructors other than `new` make that mass and no other.
        let unit_mass = self == Self::Physical || spring.mass().to_bits() == 1.0_f32.to_bits();
        let critical = !matches!(self, Self::HalfLife | Self::SmoothTime)
            || spring.regime() == Regime::CriticallyDamped;
        unit_mass && critical && fields.iter().all(|&p| spring.parameter(p).is_some())
    }
}

/// What a spring's step response looks like: the numbers the designer shows beside its plot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Readouts {
    /// Underdamped, critically damped, overdamped, …
    pub regime: Regime,
    /// How far the response swings past its target, as a fraction of the distance.
    pub overshoot: f32,
    /// When the response last enters the tolerance band around the target and stays, in
    /// seconds; `None` for a spring that never settles.
    pub settle_time: Option<f32>,
    /// The period of the damped oscillation, in seconds; `None` if it does not oscillate.
    pub period: Option<f32>,
    /// When the response has covered half the distance, in seconds.
    pub half_life: Option<f32>,
}

impl Readouts {
    /// The readouts of `spring`, settling to within `tolerance` (a fraction of the distance).
    #[must_use]
    pub fn of(spring: &Spring<f32>, tolerance: f32) -> Self {
        Self {
            regime: spring.regime(),
            overshoot: spring.overshoot(),
            settle_time: step_settle_time(spring, tolerance),
            period: spring.period(),
            half_life: spring.half_life(),
        }
    }
}

/// The position and velocity at `t` seconds of a spring released at rest at 0 toward 1: its
/// unit step response, from the exact transition.
#[must_use]
pub fn step_response(spring: &Spring<f32>, t: f32) -> (f32, f32) {
    // The state is the offset from the target, −1 at rest: one column of M(t), no sum.
    let [[f0, _], [g0, _]] = spring.transition(t).matrix();
    (1.0 - f0, -g0)
}

/// The last time the unit step response is outside `1 ± tolerance`.
///
/// The envelope's settle time ([`Spring::settle_time`]) bounds it from above (it is late by
/// up to half a period for oscillating springs); the response is scanned below that bound and
/// the last crossing refined by bisection on the closed form.
fn step_settle_time(spring: &Spring<f32>, tolerance: f32) -> Option<f32> {
    const SCAN: u16 = 2048;
    let bound = spring.settle_time(1.0, tolerance)?;
    let outside = |t: f32| (1.0 - step_response(spring, t).0).abs() > tolerance;
    let step = bound / f32::from(SCAN);
    let last = (0..SCAN)
        .rev()
        .map(|i| f32::from(i) * step)
        .find(|&t| outside(t))?;
    let (mut inside_from, mut out) = (last + step, last);
    for _ in 0..32 {
        let mid = 0.5 * (out + inside_from);
        if outside(mid) {
            out = mid;
        } else {
            inside_from = mid;
        }
    }
    Some(inside_from)
}

/// How the preview plays: at which frame rate its steps are taken and how fast time runs.
#[derive(Clone, Copy, Debug, PartialEq, Reflect)]
pub struct PreviewSettings {
    /// Frames per second of the preview's steps.
    pub fps: f32,
    /// Seconds of spring time per second of real time (1 is real time).
    pub time_scale: f32,
}

impl Default for PreviewSettings {
    fn default() -> Self {
        Self {
            fps: 60.0,
            time_scale: 1.0,
        }
    }
}

impl PreviewSettings {
    /// The spring time shown after `elapsed` real seconds: the time of the last frame taken
    /// at [`fps`](Self::fps), so the preview steps as a game at that rate would.
    #[must_use]
    pub fn shown_time(&self, elapsed: f32) -> f32 {
        (elapsed * self.time_scale * self.fps).floor() / self.fps
    }
}

/// The spring the designer is tuning, the one it is compared with (A/B), and how its plot,
/// readouts and preview are set.
///
/// Every edit goes through [`Spring::with_parameter`], so a refused value leaves the spring as
/// it was and returns the reason.
///
/// # Example
/// ```
/// use bevy_sprung::designer::{Parametrisation, SpringDesign};
/// use sprung::{Parameter, Spring};
///
/// let mut design = SpringDesign::new(Spring::snappy());
/// design.keep_as_reference();
/// design.set_field(Parametrisation::DurationBounce, Parameter::Bounce, 0.3)?;
/// assert!((design.field(Parameter::Bounce).unwrap() - 0.3).abs() < 1e-6);
/// assert_eq!(design.reference(), Some(Spring::snappy()));
/// assert_eq!(design.code(), "Spring::from_duration_and_bounce(0.5, 0.3)");
/// assert!(design.set_field(Parametrisation::Physical, Parameter::Mass, -1.0).is_err());
/// # Ok::<(), sprung::SpringError>(())
/// ```
#[derive(Resource, Clone, Debug, PartialEq, Reflect)]
#[reflect(opaque)]
pub struct SpringDesign {
    spring: Spring<f32>,
    reference: Option<Spring<f32>>,
    written_in: Parametrisation,
    /// The settle band, as a fraction of the distance (0.01 is within 1 %).
    pub tolerance: f32,
    /// How the preview plays.
    pub preview: PreviewSettings,
    /// Where [`save`](crate::designer::SpringDesignerPlugin) writes, relative to the asset
    /// folder.
    pub path: String,
}

impl Default for SpringDesign {
    fn default() -> Self {
        Self::new(Spring::default())
    }
}

impl SpringDesign {
    /// A design starting from `spring`, without a reference, written in the parametrisation
    /// that says it in the shortest numbers (a preset in the numbers it was made from).
    #[must_use]
    pub fn new(spring: Spring<f32>) -> Self {
        Self {
            spring,
            reference: None,
            written_in: shortest(&spring, Parametrisation::DurationBounce),
            tolerance: 0.01,
            preview: PreviewSettings::default(),
            path: "springs/designed.spring.ron".into(),
        }
    }

    /// The spring being tuned (A).
    #[must_use]
    pub fn spring(&self) -> Spring<f32> {
        self.spring
    }

    /// The spring it is compared with (B), if any.
    #[must_use]
    pub fn reference(&self) -> Option<Spring<f32>> {
        self.reference
    }

    /// The parametrisation the code is written in: the last one edited.
    #[must_use]
    pub fn written_in(&self) -> Parametrisation {
        self.written_in
    }

    /// Replaces the spring being tuned (a preset, an entity's spring); its code is then
    /// written in the parametrisation that says it in the shortest numbers.
    pub fn set_spring(&mut self, spring: Spring<f32>) {
        self.spring = spring;
        self.written_in = shortest(&spring, self.written_in);
    }

    /// The value of a field for the spring being tuned; `None` where the spring has none (the
    /// ratios of a spring without stiffness).
    #[must_use]
    pub fn field(&self, parameter: Parameter) -> Option<f32> {
        self.spring.parameter(parameter)
    }

    /// Sets one field of `group`, keeping the rest of the group.
    ///
    /// # Errors
    /// A value the parameter cannot take; the spring is then unchanged.
    pub fn set_field(
        &mut self,
        group: Parametrisation,
        parameter: Parameter,
        value: f32,
    ) -> Result<(), SpringError> {
        self.spring = self.spring.with_parameter(parameter, value)?;
        self.written_in = preferred(&self.spring, group);
        Ok(())
    }

    /// Keeps the spring as it is now as the reference (B), to compare the next edits with.
    pub fn keep_as_reference(&mut self) {
        self.reference = Some(self.spring);
    }

    /// Swaps the spring being tuned and the reference (A/B); nothing without a reference.
    pub fn swap(&mut self) {
        if let Some(reference) = self.reference.replace(self.spring) {
            self.set_spring(reference);
        }
    }

    /// Drops the reference.
    pub fn clear_reference(&mut self) {
        self.reference = None;
    }

    /// The readouts of the spring being tuned, at the design's tolerance.
    #[must_use]
    pub fn readouts(&self) -> Readouts {
        Readouts::of(&self.spring, self.tolerance)
    }

    /// The Rust that makes the spring, in the parametrisation last edited:
    /// `Spring::from_duration_and_bounce(0.5, 0.2)`. Each number is the shortest decimal within
    /// a few `f32` ulps (2·10⁻⁷ relative) of the field.
    #[must_use]
    pub fn code(&self) -> String {
        code(&self.spring, self.written_in)
    }

    /// The `*.spring.ron` text of the spring: its exact physical parameters (they read back
    /// to the same spring, bit for bit), with the code that makes it as a comment.
    ///
    /// # Example
    /// ```
    /// use bevy_sprung::asset::SpringPreset;
    /// use bevy_sprung::designer::SpringDesign;
    /// use sprung::Spring;
    ///
    /// let design = SpringDesign::new(Spring::from_duration_and_bounce(0.4, 0.25)?);
    /// let preset = SpringPreset::from_ron(design.to_ron().as_bytes()).unwrap();
    /// assert_eq!(preset.spring, design.spring());
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[must_use]
    pub fn to_ron(&self) -> String {
        let spring = &self.spring;
        format!(
            "// Made with the sprung designer: {}\n(\n    spring: (mass: {:?}, stiffness: {:?}, damping: {:?}),\n)\n",
            self.code(),
            spring.mass(),
            spring.stiffness(),
            spring.damping(),
        )
    }
}

/// `group` if it can say `spring`, else the first that can (the physical one always can).
fn preferred(spring: &Spring<f32>, group: Parametrisation) -> Parametrisation {
    if group.speaks(spring) {
        return group;
    }
    [Parametrisation::DurationBounce, Parametrisation::Physical]
        .into_iter()
        .find(|g| g.speaks(spring))
        .unwrap_or(Parametrisation::Physical)
}

/// The shortest decimal within 2·10⁻⁷ of `value` (a few `f32` ulps: `0.5` for the
/// `0.50000006` a preset's rounding leaves), as a float literal.
fn literal(value: f32) -> String {
    let close = |text: &str| {
        text.parse::<f32>()
            .is_ok_and(|read| (read - value).abs() <= 2e-7 * value.abs())
    };
    let shortest = (0..9)
        .map(|digits| format!("{value:.digits$e}"))
        .find(|text| close(text))
        .map_or_else(
            || format!("{value:?}"),
            |text| {
                // Back through f64, whose `Display` writes it without an exponent.
                format!("{}", text.parse::<f64>().unwrap_or(f64::from(value)))
            },
        );
    if shortest.contains(['.', 'e', 'i', 'N']) {
        shortest
    } else {
        shortest + ".0"
    }
}

/// The parametrisation whose code for `spring` is shortest; `first` wins a tie.
fn shortest(spring: &Spring<f32>, first: Parametrisation) -> Parametrisation {
    core::iter::once(first)
        .chain(Parametrisation::ALL)
        .filter(|group| group.speaks(spring))
        .min_by_key(|&group| code(spring, group).len())
        .unwrap_or(Parametrisation::Physical)
}

fn code(spring: &Spring<f32>, group: Parametrisation) -> String {
    let group = preferred(spring, group);
    let mut text = format!("Spring::{}(", group.constructor());
    for (i, &parameter) in group.fields().iter().enumerate() {
        let value = spring.parameter(parameter).unwrap_or_default();
        let separator = if i == 0 { "" } else { ", " };
        let _ = write!(text, "{separator}{}", literal(value));
    }
    text.push(')');
    text
}
