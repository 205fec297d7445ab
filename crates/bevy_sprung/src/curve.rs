//! A spring's exact motion as a Bevy [`Curve`]: for `bevy_animation` clips, for anything that
//! samples a curve, and as an easing for tween crates.

use bevy::math::curve::{Curve, Interval};
use bevy::math::{NormedVectorSpace, VectorSpace};
use bevy::reflect::Reflect;
use sprung::{RestThreshold, Spring};

use crate::space::LinearValue;

/// The exact motion of a spring from `start` (moving at an initial velocity) toward `target`,
/// as a [`Curve`] over `[0, duration]` seconds: what a [`PropertySpring`] on a vector field
/// would do from there, sampled anywhere without stepping.
///
/// Every sample is the closed-form solution at that time, evaluated independently (no error
/// accumulates over a long curve). The duration is when the motion stays within the rest
/// tolerance of the target ([`Spring::settle_time`] of the amplitude, counting what the
/// initial velocity adds), or what you set with [`with_duration`](Self::with_duration). At the
/// end of the domain the curve returns the target exactly, as a spring snaps there at rest.
///
/// It plugs into `bevy_animation` (`AnimatableCurve::new(animated_field!(Transform::translation),
/// curve)`) and everything else that takes a curve; `curve.resample_auto(n)` from Bevy's
/// `CurveResampleExt` turns it into a lookup table.
///
/// [`PropertySpring`]: crate::spring::PropertySpring
///
/// # Example
/// ```
/// use bevy::math::curve::Curve;
/// use bevy::prelude::*;
/// use bevy_sprung::curve::SpringCurve;
/// use bevy_sprung::prelude::*;
///
/// let curve = SpringCurve::new(Spring::bouncy(), Vec3::ZERO, Vec3::new(100.0, 0.0, 0.0));
/// let end = curve.domain().end();
/// assert!(end > 0.5 && end < 3.0);
/// // Bouncy: it overshoots on the way.
/// let peak = (0..100).map(|i| curve.sample_clamped(end * i as f32 / 100.0).x).fold(0.0, f32::max);
/// assert!(peak > 100.0);
/// assert_eq!(curve.sample_clamped(end), Vec3::new(100.0, 0.0, 0.0));
/// ```
#[derive(Clone, Copy, Debug, Reflect)]
pub struct SpringCurve<V: LinearValue> {
    spring: Spring<f32>,
    start: V,
    target: V,
    velocity: V,
    duration: f32,
}

impl<V: LinearValue> SpringCurve<V> {
    /// The motion from `start` at rest toward `target`, until it rests within the default
    /// tolerance ([`RestThreshold::DEFAULT`]).
    #[must_use]
    pub fn new(spring: Spring<f32>, start: V, target: V) -> Self {
        let zero = V::from_offset(V::Offset::ZERO);
        Self {
            spring,
            start,
            target,
            velocity: zero,
            duration: 0.0,
        }
        .with_rest(RestThreshold::DEFAULT)
    }

    /// The same motion starting with `velocity`, its duration recomputed for the default
    /// tolerance.
    #[must_use]
    pub fn with_velocity(mut self, velocity: V) -> Self {
        self.velocity = velocity;
        self.with_rest(RestThreshold::DEFAULT)
    }

    /// The same motion, ending when it stays within `rest.offset` of the target: the settle time
    /// of its amplitude, `|start − target| + |velocity|/λ` (the distance a velocity decaying at
    /// the spring's slowest rate `λ` can add). A spring that never settles (undamped, or without
    /// stiffness) gets a duration of 0; set one with [`with_duration`](Self::with_duration).
    #[must_use]
    pub fn with_rest(mut self, rest: RestThreshold<f32>) -> Self {
        let offset = (self.start.to_offset() - self.target.to_offset()).norm();
        let rate = self.spring.decay_rate();
        let speed = self.velocity.to_offset().norm();
        let amplitude = if rate > 0.0 {
            offset + speed / rate
        } else {
            offset
        };
        self.duration = self
            .spring
            .settle_time(amplitude, rest.offset)
            .unwrap_or(0.0);
        self
    }

    /// The same motion over `[0, duration]` seconds (a negative or NaN duration is 0).
    #[must_use]
    pub fn with_duration(mut self, duration: f32) -> Self {
        self.duration = if duration > 0.0 { duration } else { 0.0 };
        self
    }

    /// How long the curve is, in seconds.
    #[inline]
    #[must_use]
    pub fn duration(&self) -> f32 {
        self.duration
    }

    /// The exact state `(position, velocity)` at `t` seconds (any `t ≥ 0`, also past the end).
    #[must_use]
    pub fn state(&self, t: f32) -> (V, V) {
        let [[f0, f1], [m10, g]] = self.spring.transition(t).matrix();
        let (x, v) = (
            self.start.to_offset() - self.target.to_offset(),
            self.velocity.to_offset(),
        );
        let target = self.target.to_offset();
        (
            V::from_offset(target + (x * f0 + v * f1)),
            V::from_offset(x * m10 + v * g),
        )
    }
}

impl<V: LinearValue> Curve<V> for SpringCurve<V> {
    #[inline]
    fn domain(&self) -> Interval {
        Interval::new(0.0, self.duration).unwrap_or(Interval::UNIT)
    }

    /// The exact position at `t`; the target itself at the end of the domain and past it.
    fn sample_unchecked(&self, t: f32) -> V {
        if t >= self.duration {
            self.target
        } else {
            self.state(t.max(0.0)).0
        }
    }
}

/// A spring's step response, normalised: an easing `[0, 1] → [0, 1]` for tween crates and
/// anything that takes an easing curve. `ease(s)` is how far a spring released at rest has gone
/// toward its target at `s` times its settle time (within `1e-3` of the distance); a bouncy
/// spring overshoots past 1 on the way, and `ease(1) = 1` exactly.
///
/// # Example
/// ```
/// use bevy::math::curve::{Curve, CurveResampleExt};
/// use bevy_sprung::curve::SpringEasing;
/// use bevy_sprung::prelude::*;
///
/// let easing = SpringEasing::new(Spring::snappy());
/// assert_eq!(easing.ease(0.0), 0.0);
/// assert_eq!(easing.ease(1.0), 1.0);
/// assert!(easing.ease(0.3) > 0.8);
/// // A lookup table of 64 segments, as cheap to sample as any tween's easing.
/// let table = easing.resample_auto(64).unwrap();
/// assert!((table.sample_clamped(0.3) - easing.ease(0.3)).abs() < 0.02);
/// ```
#[derive(Clone, Copy, Debug, Reflect)]
pub struct SpringEasing {
    curve: SpringCurve<f32>,
}

impl SpringEasing {
    /// The normalised step response of `spring`.
    #[must_use]
    pub fn new(spring: Spring<f32>) -> Self {
        Self {
            curve: SpringCurve::new(spring, 0.0, 1.0),
        }
    }

    /// How long the spring takes to settle from a unit distance, in seconds: the time one unit
    /// of the easing stands for.
    #[must_use]
    pub fn settle_time(&self) -> f32 {
        self.curve.duration()
    }

    /// The easing at `s ∈ [0, 1]` (clamped).
    #[must_use]
    pub fn ease(&self, s: f32) -> f32 {
        let s = if s.is_nan() { 0.0 } else { s.clamp(0.0, 1.0) };
        self.curve.sample_unchecked(s * self.curve.duration())
    }
}

impl Curve<f32> for SpringEasing {
    #[inline]
    fn domain(&self) -> Interval {
        Interval::UNIT
    }

    #[inline]
    fn sample_unchecked(&self, t: f32) -> f32 {
        self.ease(t)
    }
}
