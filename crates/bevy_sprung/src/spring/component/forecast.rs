//! What a spring will do: [`SpringForecast`], its future in closed form from the state of its
//! last step.

use core::fmt;

use bevy::math::{NormedVectorSpace, VectorSpace};
use sprung::{Spring, SpringState};

use super::config::PropertySpring;
use super::motion::{SpringMotion, rest_squared};
use crate::property::{OffsetOf, SpringProperty, ValueOf, VelocityOf};
use crate::space::{SpringSpace, is_within_rest};

/// The finest time step [`SpringForecast::settle_time`] scans the future with, in seconds.
const SCAN_STEP: f32 = 1.0 / 480.0;

/// The most time steps [`SpringForecast::settle_time`] scans: beyond `SCAN_STEP` times this,
/// the step grows so that the scan stays this long.
const SCAN_STEPS: u32 = 4096;

/// The longest future [`SpringForecast::settle_time`] looks into, in seconds.
const LONGEST_SETTLE: f32 = 3600.0;

/// The future of a spring if nothing changes it: where it will be and how fast at any time
/// from its last step, and when it will come to rest. Exact: it is the closed-form solution
/// the spring's steps follow (the same transition the plugin steps with), not a simulation, so
/// the path it predicts is the path the spring then takes at any frame rate.
///
/// A forecast starts from the state of the spring's last step, with what was set since
/// applied as its next step would: a new target (keeping the value and its velocity), a
/// velocity set or an impulse added. A target velocity moves the target on at that velocity
/// (in the offset's space); a spring asleep stays on its target. Get one from
/// [`PropertySpring::forecast`].
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::spring::SpringMotion;
///
/// fn report(springs: Query<(&TranslationSpring, &SpringMotion<Translation>)>) {
///     for (spring, motion) in &springs {
///         let forecast = spring.forecast(motion);
///         // Where it will be in a quarter of a second, and when it will be at rest.
///         let _soon: Vec3 = forecast.value_at(0.25);
///         let _left: Option<f32> = forecast.settle_time();
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Update, report);
/// # app.world_mut().spawn((Transform::default(), TranslationSpring::new(Spring::bouncy(), Vec3::X)));
/// # app.update();
/// ```
pub struct SpringForecast<P: SpringProperty> {
    spring: Spring<f32>,
    /// The target at time 0.
    target: ValueOf<P>,
    /// How fast the target moves, in the offset's space.
    rate: OffsetOf<P>,
    /// The offset from `target` and the velocity at time 0.
    offset: OffsetOf<P>,
    velocity: OffsetOf<P>,
    /// The squared rest tolerances as the spring applies them toward `target`.
    rest_squared: (f32, f32),
}

impl<P: SpringProperty> PropertySpring<P> {
    /// The future of this spring, whose motion is `motion`, if nothing changes it (see
    /// [`SpringForecast`]). A spring skipping frames (unseen) is forecast from the last frame
    /// it stepped.
    #[must_use]
    pub fn forecast(&self, motion: &SpringMotion<P>) -> SpringForecast<P> {
        // What the next step does first: retarget (the value and its velocity kept), then
        // apply the velocity set or kicked since.
        let (offset, velocity) = if self.target == motion.active_target {
            (motion.offset, motion.velocity)
        } else {
            P::Space::retarget(
                motion.active_target,
                self.target,
                motion.offset,
                motion.velocity,
            )
        };
        let velocity = self.velocity_change.applied_to(velocity);
        SpringForecast {
            spring: self.spring,
            target: self.target,
            rate: self.target_rate(),
            offset: offset.offset,
            velocity,
            rest_squared: rest_squared::<P>(self.rest, self.target),
        }
    }
}

impl<P: SpringProperty> SpringForecast<P> {
    /// The target the spring heads for (at time 0, for a moving target).
    #[inline]
    #[must_use]
    pub fn target(&self) -> ValueOf<P> {
        self.target
    }

    /// The offset from the target at time 0 and the velocity `seconds` from the spring's last
    /// step. Exact for any `seconds ≥ 0` (one evaluation of the spring's transition, stable in
    /// every regime); a negative or non-finite time gives the state at 0.
    #[inline]
    fn state_at(&self, seconds: f32) -> (OffsetOf<P>, OffsetOf<P>) {
        if !(seconds > 0.0 && seconds.is_finite()) {
            return (self.offset, self.velocity);
        }
        // Stable over long times: the transition matrix M itself, not the increment form
        // `x + (M − I)·x` the frames step with, which would lose the digits of a state that has
        // decayed far below where it started. Toward a target moving on at `r` (in the frame of
        // the target at time 0), the exact first-order hold:
        //   x = f0·y + f1·(v − r) + r·(t − 2b·g0),  v' = r + g·(v − r) − ω²f1·y − 2b·f1·r.
        let transition = self.spring.transition(seconds);
        let [[f0, f1], [minus_w2f1, g]] = transition.matrix();
        let rate = self.rate;
        let relative = self.velocity - rate;
        let pull = self.spring.damping() / self.spring.mass();
        let carried = (seconds - pull * transition.acceleration_gain()).max(0.0);
        (
            self.offset * f0 + relative * f1 + rate * carried,
            rate + relative * g + self.offset * minus_w2f1 - rate * (pull * f1),
        )
    }

    /// The value `seconds` after the spring's last step (the value then, at `0`). Exact; a
    /// negative or non-finite time gives the value at `0`.
    #[must_use]
    pub fn value_at(&self, seconds: f32) -> ValueOf<P> {
        P::Space::at_offset(self.target, self.state_at(seconds).0)
    }

    /// The velocity `seconds` after the spring's last step, in the spring's space (as
    /// [`SpringMotion::velocity`]). Exact; a negative or non-finite time gives the velocity at
    /// `0`.
    #[must_use]
    pub fn velocity_at(&self, seconds: f32) -> VelocityOf<P> {
        self.state_at(seconds).1.into()
    }

    /// The values at `count` times `step` seconds apart, from `step` on: each found from the
    /// one before by the exact transition over `step`, as the plugin steps a spring whose
    /// frames are `step` long (so the points are those frames' values, to rounding). Nothing
    /// for a `step` that is not positive and finite.
    pub fn samples(&self, step: f32, count: usize) -> impl Iterator<Item = ValueOf<P>> + '_ {
        let valid = step > 0.0 && step.is_finite();
        let transition = self.spring.transition(if valid { step } else { 0.0 });
        let mut state = SpringState::new(self.offset, self.velocity);
        let mut moved = OffsetOf::<P>::ZERO;
        (0..if valid { count } else { 0 }).map(move |_| {
            moved = moved + self.rate * step;
            state = transition.step_toward_moving(state, moved, self.rate);
            P::Space::at_offset(self.target, state.position)
        })
    }

    /// Whether the state at time 0 is within the spring's rest tolerances toward a target
    /// that does not move: the spring then settles at its next step.
    #[must_use]
    pub fn is_at_rest(&self) -> bool {
        self.rate == OffsetOf::<P>::ZERO && self.within_rest(self.offset, self.velocity)
    }

    fn within_rest(&self, offset: OffsetOf<P>, velocity: OffsetOf<P>) -> bool {
        is_within_rest(
            (offset.norm_squared(), velocity.norm_squared()),
            self.rest_squared,
        )
    }

    /// How long from the spring's last step until its state is first within its rest
    /// tolerances (the spring settles, snapped onto its target, at the step after: the
    /// frame the state comes within them, or the next one). `Some(0)` for a spring at rest.
    ///
    /// Found on the exact future, not estimated from its envelope: scanned in steps of
    /// 1/480 s (longer beyond about 8 s, so that a scan is at most a few thousand
    /// multiplications) and refined by bisection, so it is the time the path first enters its
    /// tolerances, except a touch shorter than a scan step. `None` when the spring never
    /// settles: a moving target, no damping or no stiffness (and an offset), or more than an
    /// hour away.
    #[must_use]
    pub fn settle_time(&self) -> Option<f32> {
        if self.rate != OffsetOf::<P>::ZERO {
            return None;
        }
        if self.within_rest(self.offset, self.velocity) {
            return Some(0.0);
        }
        let horizon = self.settle_horizon()?;
        // Steps of one exact transition: cheap, and each sample exact to rounding.
        let count = (horizon / SCAN_STEP).ceil().clamp(1.0, SCAN_STEPS as f32);
        let step = horizon / count;
        let transition = self.spring.transition(step);
        let mut state = SpringState::new(self.offset, self.velocity);
        let mut before = 0.0_f32;
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "count is a whole number in 1..=SCAN_STEPS"
        )]
        for i in 1..=count as u32 {
            state = transition.step(state, OffsetOf::<P>::ZERO);
            let at = step * i as f32;
            if self.within_rest(state.position, state.velocity) {
                return Some(self.refine(before, at));
            }
            before = at;
        }
        None
    }

    /// An upper bound on the settle time, from the decay envelope of the spring released
    /// from the state's amplitude (its offset plus how far its speed carries it); `None` when
    /// the spring never settles or only after [`LONGEST_SETTLE`].
    fn settle_horizon(&self) -> Option<f32> {
        let omega = self.spring.natural_frequency();
        let speed = self.velocity.norm();
        let reach = if omega > 0.0 { speed / omega } else { speed };
        let amplitude = self.offset.norm() + reach;
        let tolerance = self
            .rest_squared
            .0
            .min(self.rest_squared.1 / omega.max(1.0).powi(2));
        let horizon = self
            .spring
            .settle_time(amplitude, tolerance.sqrt().max(f32::MIN_POSITIVE))?;
        // The envelope bounds the offset; the speed settles within a few more periods.
        let horizon = 2.0 * horizon + 4.0 / omega.max(f32::MIN_POSITIVE);
        (horizon.is_finite() && horizon <= LONGEST_SETTLE).then_some(horizon.max(SCAN_STEP))
    }

    /// The first time in `(outside, inside]` at which the state is within its tolerances, by
    /// bisection on the exact state (to a few microseconds).
    fn refine(&self, mut outside: f32, mut inside: f32) -> f32 {
        for _ in 0..16 {
            let middle = 0.5 * (outside + inside);
            let (offset, velocity) = self.state_at(middle);
            if self.within_rest(offset, velocity) {
                inside = middle;
            } else {
                outside = middle;
            }
        }
        inside
    }
}

impl<P: SpringProperty> Clone for SpringForecast<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for SpringForecast<P> {}

impl<P: SpringProperty> fmt::Debug for SpringForecast<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SpringForecast")
            .field("property", &P::short_type_path())
            .field("spring", &self.spring)
            .field("target", &self.target)
            .field("offset", &self.offset)
            .field("velocity", &self.velocity)
            .finish_non_exhaustive()
    }
}
