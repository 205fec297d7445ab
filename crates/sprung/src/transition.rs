//! The exact per-`dt` transition and stepping with it.

use core::ops::{Add, Mul, Sub};

use crate::Scalar;
use crate::kernel::Coefficients;

/// A value a spring can move: anything closed under `+`, `−` and scaling by `T`.
///
/// Implemented automatically for `f32`, `f64`, glam's `Vec2`/`Vec3`/`Vec3A`/`Vec4` (with
/// `T = f32`) and `DVec*` (`T = f64`), Bevy's `LinearRgba`, `[T; N]`-like newtypes you write,
/// and so on. Each component moves independently with the same transition.
pub trait SpringValue<T>:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<T, Output = Self>
{
}

impl<T, V> SpringValue<T> for V where
    V: Copy + Add<Output = V> + Sub<Output = V> + Mul<T, Output = V>
{
}

/// Position and velocity of a sprung value, with the digits of the position that the position
/// itself cannot hold.
///
/// A spring approaching its target moves by less and less each step. Added to a position far
/// from zero, such a move rounds away (below half a unit in the last place of the position:
/// ~3e-5 at 1000 in `f32`), and a state that only held `position` would stop short of its
/// target for ever, with a velocity that never decays. So every step stores the part of the
/// new position that rounding dropped in a hidden [`remainder`](Self::remainder), and the
/// next step starts from `position + remainder`: the offset from the target keeps every digit
/// and decays exactly as the closed-form solution does, at any magnitude and frame rate.
///
/// `position` is always the nearest representable value to the exact position. To move a state
/// elsewhere, use [`set_position`](Self::set_position) or build a new one: writing `position`
/// directly keeps the old remainder (less than one unit in the last place of the old position or
/// of the old offset from the target).
///
/// # Example
/// ```
/// use sprung::{Spring, SpringState};
/// let spring = Spring::<f32>::smooth();
/// let mut state = SpringState::at_rest(0.0_f32);
/// for _ in 0..60 {
///     state = spring.transition(1.0 / 60.0).step(state, 10.0);
/// }
/// assert!((state.position - 10.0).abs() < 0.1);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "bevy_reflect", derive(bevy_reflect::Reflect))]
pub struct SpringState<V> {
    /// Where the value is, rounded to `V`'s precision.
    pub position: V,
    /// How fast it moves, in units of `position` per second.
    pub velocity: V,
    /// What the exact position adds to `position`: below one unit in its last place once the
    /// spring is near its target.
    remainder: V,
}

impl<V: Copy + Sub<Output = V>> SpringState<V> {
    /// A state at `position` moving with `velocity`.
    #[inline]
    #[must_use]
    #[expect(
        clippy::eq_op,
        reason = "x − x is the zero of any Sub type, with no zero constant to require"
    )]
    pub fn new(position: V, velocity: V) -> Self {
        Self {
            position,
            velocity,
            remainder: velocity - velocity,
        }
    }

    /// A state at `position` with zero velocity (`position − position`, so it works for any
    /// [`SpringValue`] without a zero constant).
    #[inline]
    #[must_use]
    #[expect(
        clippy::eq_op,
        reason = "x − x is the zero of any Sub type, with no zero constant to require"
    )]
    pub fn at_rest(position: V) -> Self {
        let zero = position - position;
        Self {
            position,
            velocity: zero,
            remainder: zero,
        }
    }

    /// The part of the exact position below `position`'s last digit: the exact position is
    /// `position + remainder`. Zero for a state built by [`new`](Self::new) or
    /// [`at_rest`](Self::at_rest).
    #[inline]
    #[must_use]
    pub fn remainder(&self) -> V {
        self.remainder
    }

    /// Moves the state to `position` exactly (the remainder is cleared), keeping its velocity.
    #[expect(
        clippy::eq_op,
        reason = "x − x is the zero of any Sub type, with no zero constant to require"
    )]
    #[inline]
    pub fn set_position(&mut self, position: V) {
        self.position = position;
        self.remainder = position - position;
    }
}

impl<V: Copy + Add<Output = V> + Sub<Output = V>> SpringState<V> {
    /// The offset `(position + remainder) − target` of the exact position from `target`, with
    /// the digits `position` alone would lose: what the steps advance, and what a rest test
    /// should measure (it decays to zero instead of stopping at the rounding of `position`).
    ///
    /// # Example
    /// ```
    /// use sprung::{Spring, SpringState};
    /// let step = Spring::<f32>::molasses().transition(1.0 / 240.0);
    /// let mut state = SpringState::at_rest(0.0_f32);
    /// for _ in 0..240 * 20 {
    ///     state = step.step(state, 1000.0);
    /// }
    /// // The position has reached the target; the offset keeps decaying below its spacing.
    /// assert_eq!(state.position, 1000.0);
    /// assert!(state.offset_from(1000.0).abs() < 1e-12);
    /// ```
    #[inline]
    #[must_use]
    pub fn offset_from(&self, target: V) -> V {
        (self.position - target) + self.remainder
    }

    /// The state `increment` further on (the exact position plus `increment`), moving with
    /// `velocity`: compensated summation.
    ///
    /// `position` becomes `position + (increment + remainder)` rounded, and the remainder keeps
    /// what the rounding dropped: Dekker's Fast2Sum error term, exact whenever the position is
    /// at least as large as the step (the case of a spring near its target, where the dropped
    /// digits are all that is left of its motion), and otherwise within a unit in the last place
    /// of the step, which is already the step's own precision. The position keeps the precision
    /// of its own magnitude, whatever the target's.
    #[inline]
    #[must_use]
    fn advanced(self, increment: V, velocity: V) -> Self {
        let increment = increment + self.remainder;
        let position = self.position + increment;
        Self {
            position,
            velocity,
            remainder: increment - (position - self.position),
        }
    }
}

/// The exact transition of a [`Spring`](crate::Spring) over one time step `dt`.
///
/// Holds the matrix `M = [[f0, f1], [−ω²·f1, g]]` that maps `(x − x*, v)` at the start of the
/// step to the end, its increment form `D = M − I` (what the steps apply, see below), and the
/// forcing integral `g0 = ∫₀ᵈᵗ f1` for constant accelerations and moving targets. Compute it
/// once per `(spring, dt)` and apply it to as many values as share them.
///
/// Every step works on the exact offset `y = x − x*` (the state's position plus its
/// [remainder](SpringState::remainder), less the target) and adds `D·(y, v)` to it instead of
/// replacing it with `M·(y, v)`: `M₀₀ ≈ 1 − (ω·dt)²/2` rounds badly in `f32`, and at 240 fps
/// the plain form drifts far more over a minute than the increment form. Keeping the offset
/// whole is what makes the spring arrive: an increment added to the position itself is rounded
/// away once it falls below half a unit in the position's last place, and the spring then stops
/// short of its target for ever.
///
/// # Example
/// ```
/// use sprung::{Spring, SpringState};
/// let spring = Spring::<f32>::from_natural_frequency(10.0, 0.5)?;
/// let step = spring.transition(1.0 / 60.0);
/// // Any `Copy + Add + Sub + Mul<f32>` type works; here a plain array wrapper would too.
/// let mut state = SpringState::new(0.0_f32, 0.0);
/// state = step.step(state, 1.0);
/// assert!(state.position > 0.0 && state.velocity > 0.0);
/// # Ok::<(), sprung::SpringError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transition<T = f32> {
    // What a constant-target step reads comes first, together.
    /// `D₀₀ = −ω²·g0`.
    d00: T,
    f1: T,
    w2f1: T,
    /// `D₁₁ = −(ω²·g0 + 2b·f1)`.
    d11: T,
    f0: T,
    g: T,
    g0: T,
    /// `2b = c/m`.
    rate: T,
    dt: T,
}

impl<T: Scalar> Transition<T> {
    /// Rounds the `f64` coefficients to `T` once.
    pub(crate) fn from_coefficients(dt: T, c: &Coefficients) -> Self {
        Self {
            // `0 − x` rather than `−x`: a free spring's entries are +0, not −0.
            d00: T::from_f64(0.0 - c.w2g0),
            f1: T::from_f64(c.f1),
            w2f1: T::from_f64(c.w2f1),
            // Both terms are ≥ 0: no cancellation.
            d11: T::from_f64(0.0 - (c.w2g0 + c.rate * c.f1)),
            f0: T::from_f64(c.f0),
            g: T::from_f64(c.g),
            g0: T::from_f64(c.g0),
            // `c/m` in `f64` rounded to `f32` is the `f32` quotient (53 ≥ 2·24 + 2 bits: the
            // double rounding is innocuous), but for one beyond `f32::MAX`, which saturates.
            rate: T::from_f64(c.rate),
            dt,
        }
    }

    /// The transition over no time: the identity.
    #[must_use]
    pub fn identity() -> Self {
        let (zero, one) = (T::zero(), T::one());
        Self {
            d00: zero,
            f1: zero,
            w2f1: zero,
            d11: zero,
            f0: one,
            g: one,
            g0: zero,
            rate: zero,
            dt: zero,
        }
    }

    /// The time step this transition covers.
    #[inline]
    #[must_use]
    pub fn dt(&self) -> T {
        self.dt
    }

    /// The transition matrix, row-major:
    /// `[[∂x₁/∂x₀, ∂x₁/∂v₀], [∂v₁/∂x₀, ∂v₁/∂v₀]]` for the offset `x − x*` from a constant
    /// target and the velocity `v`.
    ///
    /// # Example
    /// ```
    /// use sprung::Spring;
    /// let m = Spring::<f64>::new(1.0, 1.0, 0.0)?.transition(core::f64::consts::PI).matrix();
    /// // Half a period of the undamped unit oscillator flips the state.
    /// assert!((m[0][0] + 1.0).abs() < 1e-15 && m[0][1].abs() < 1e-15);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn matrix(&self) -> [[T; 2]; 2] {
        [[self.f0, self.f1], [T::zero() - self.w2f1, self.g]]
    }

    /// The increment matrix `D = M − I` that the steps apply, computed without cancellation
    /// (so it keeps full relative accuracy even when `dt` is tiny and `M ≈ I`).
    #[inline]
    #[must_use]
    pub fn increment_matrix(&self) -> [[T; 2]; 2] {
        [[self.d00, self.f1], [T::zero() - self.w2f1, self.d11]]
    }

    /// `g0 = ∫₀ᵈᵗ f1(τ) dτ`: how far a unit constant acceleration moves the value over the step
    /// (`dt²/2` for a free spring). Where the integral exceeds the largest finite `T` (a step
    /// beyond ~1.3e154 s of an almost free spring in `f64`) it saturates there; it is never
    /// infinite.
    #[inline]
    #[must_use]
    pub fn acceleration_gain(&self) -> T {
        self.g0
    }

    /// One step toward a constant `target`.
    ///
    /// # Example
    /// ```
    /// use sprung::{Spring, SpringState};
    /// let spring = Spring::<f64>::from_natural_frequency(4.0, 1.0)?;
    /// let state = SpringState::new(0.0, 0.0);
    /// // One step of 1 s equals 240 steps of 1/240 s (to rounding): the step is exact.
    /// let once = spring.transition(1.0).step(state, 1.0);
    /// let fine = spring.transition(1.0 / 240.0);
    /// let many = (0..240).fold(state, |s, _| fine.step(s, 1.0));
    /// assert!((once.position - many.position).abs() < 1e-13);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn step<V: SpringValue<T>>(&self, state: SpringState<V>, target: V) -> SpringState<V> {
        let offset = state.offset_from(target);
        let velocity = state.velocity;
        state.advanced(
            offset * self.d00 + velocity * self.f1,
            velocity + (velocity * self.d11 - offset * self.w2f1),
        )
    }

    /// One step toward a constant `target` under a constant `acceleration` (gravity, wind, a
    /// thrust): `m·x'' + c·x' + k·(x − x*) = m·a`. Exact, and it works for `k = 0` (a damped
    /// projectile) where there is no target to pull toward.
    ///
    /// # Example
    /// ```
    /// use sprung::{Spring, SpringState};
    /// // A free body under gravity: x = v·t + a·t²/2, exactly.
    /// let free = Spring::<f64>::new(1.0, 0.0, 0.0)?;
    /// let s = free.transition(2.0).step_with_acceleration(SpringState::new(0.0, 1.0), 0.0, -9.81);
    /// assert_eq!(s.position, 2.0 - 9.81 * 2.0);
    /// assert_eq!(s.velocity, 1.0 - 9.81 * 2.0);
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn step_with_acceleration<V: SpringValue<T>>(
        &self,
        state: SpringState<V>,
        target: V,
        acceleration: V,
    ) -> SpringState<V> {
        let offset = state.offset_from(target);
        let velocity = state.velocity;
        state.advanced(
            offset * self.d00 + velocity * self.f1 + acceleration * self.g0,
            velocity + (velocity * self.d11 - offset * self.w2f1 + acceleration * self.f1),
        )
    }

    /// One step toward a target that moves at constant `target_velocity` during the step and is
    /// at `target` at its end (exact first-order hold): what a camera or follower needs.
    ///
    /// Relative to the moving target the spring sees a constant forcing `−c·r/m`, so its steady
    /// lag `c·r/k` behind a target moving at `r` is reproduced exactly at any frame rate instead
    /// of showing up as jitter when frame times vary.
    ///
    /// # Example
    /// ```
    /// use sprung::{Spring, SpringState};
    /// let spring = Spring::<f64>::from_natural_frequency(5.0, 1.0)?;
    /// let (speed, lag) = (3.0, 2.0 * 5.0 * 3.0 / 25.0); // lag = c·r/k
    /// // Start in the steady state: trailing the target by `lag`, at the target's speed.
    /// let mut state = SpringState::new(-lag, speed);
    /// let mut target = 0.0;
    /// for dt in [0.01, 0.05, 0.003, 0.1] {
    ///     target += speed * dt;
    ///     state = spring.transition(dt).step_toward_moving(state, target, speed);
    ///     assert!((target - state.position - lag).abs() < 1e-12);
    ///     assert!((state.velocity - speed).abs() < 1e-12);
    /// }
    /// # Ok::<(), sprung::SpringError>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn step_toward_moving<V: SpringValue<T>>(
        &self,
        state: SpringState<V>,
        target: V,
        target_velocity: V,
    ) -> SpringState<V> {
        // Offset from the target's position at the start of the step, and velocity relative
        // to the target's.
        let offset = state.offset_from(target) + target_velocity * self.dt;
        let relative_velocity = state.velocity - target_velocity;
        // rate·g0 = dt − f1 − ω²·∫g0 ≤ dt: bounding it by dt changes nothing but a rounding
        // that would overflow at dt ≈ T::MAX (and then give 0·∞ = NaN for a resting target).
        let forcing_position = self.rate * self.g0;
        let forcing_position = if forcing_position > self.dt {
            self.dt
        } else {
            forcing_position
        };
        let forcing_velocity = self.rate * self.f1;
        // The spring moves with the target (`r·dt`) plus its response relative to it.
        state.advanced(
            target_velocity * self.dt + offset * self.d00 + relative_velocity * self.f1
                - target_velocity * forcing_position,
            state.velocity
                + (relative_velocity * self.d11
                    - offset * self.w2f1
                    - target_velocity * forcing_velocity),
        )
    }

    /// Steps every state toward the target at the same index (one transition shared by all).
    ///
    /// Pairs are formed as with [`Iterator::zip`]: if the slices differ in length, the extra
    /// states are left unchanged.
    ///
    /// # Example
    /// ```
    /// use sprung::{Spring, SpringState};
    /// let step = Spring::<f32>::snappy().transition(1.0 / 60.0);
    /// let mut states = [SpringState::at_rest(0.0_f32); 3];
    /// step.step_each(&mut states, &[1.0, 2.0, 3.0]);
    /// assert!(states[0].position < states[1].position && states[1].position < states[2].position);
    /// ```
    #[inline]
    pub fn step_each<V: SpringValue<T>>(&self, states: &mut [SpringState<V>], targets: &[V]) {
        for (state, &target) in states.iter_mut().zip(targets) {
            *state = self.step(*state, target);
        }
    }

    /// Steps every state toward one shared `target`.
    ///
    /// # Example
    /// ```
    /// use sprung::{Spring, SpringState};
    /// let step = Spring::<f32>::smooth().transition(1.0 / 60.0);
    /// let mut states = vec![SpringState::at_rest(0.0_f32); 1000];
    /// step.step_all(&mut states, 1.0);
    /// assert!(states.iter().all(|s| s.position > 0.0));
    /// ```
    #[inline]
    pub fn step_all<V: SpringValue<T>>(&self, states: &mut [SpringState<V>], target: V) {
        for state in states {
            *state = self.step(*state, target);
        }
    }
}

impl<T: Scalar> Default for Transition<T> {
    /// The identity.
    fn default() -> Self {
        Self::identity()
    }
}
