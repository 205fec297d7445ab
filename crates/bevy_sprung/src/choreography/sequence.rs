//! A sequence of targets for one property's spring: the component and its builder.

use core::fmt;
use core::marker::PhantomData;

use bevy::prelude::*;
use sprung::Spring;

use crate::property::{SpringProperty, ValueOf};

/// When a sequence moves on from a step to the next.
#[derive(Clone, Copy, Debug, PartialEq, Reflect)]
#[reflect(Debug, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Advance {
    /// When the spring has settled on the step's target (its `SpringSettled` has fired).
    OnSettle,
    /// This many seconds after the step began, settled or not: the next target bends the motion,
    /// its velocity kept.
    After(f32),
    /// Whichever comes first: settled, or this many seconds.
    OnSettleOrAfter(f32),
    /// When the spring is visually there: within this distance of the step's target, in the
    /// property's units (the length of its offset: pixels for a UI length, radians for a
    /// rotation), and slow enough not to leave it again (its speed at most the distance times
    /// the spring's natural frequency). Half a pixel is a UI's "there"; the spring settles on
    /// the target afterwards as always, while the sequence goes on. A step that only waits for
    /// [`OnSettle`](Self::OnSettle) also waits out the last, invisible part of the motion.
    Within(f32),
}

/// How many times a sequence plays its steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Reflect)]
#[reflect(Debug, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Repeat {
    /// Once (the default).
    Once,
    /// This many times (0 counts as once).
    Times(u32),
    /// Until it is removed or interrupted.
    Forever,
}

/// How a repeating sequence goes round.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Reflect)]
#[reflect(Debug, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum LoopMode {
    /// First step to last, then from the first again.
    Cycle,
    /// First to last, then back from the last to the first (a pulse, a bob): each pass is one
    /// play.
    PingPong,
}

/// What a sequence does when something else retargets its spring mid-way.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Reflect)]
#[reflect(Debug, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum OnInterrupt {
    /// The sequence ends (it is finished and does nothing more); the new target stands.
    Cancel,
    /// The sequence waits until [`SpringSequence::resume`] and then goes on from the step it
    /// was in.
    Pause,
}

/// One step of a sequence: a target, when to move on, and optionally new spring parameters.
#[derive(Clone, Copy, Debug, Reflect)]
pub struct SequenceStep<V> {
    /// Where the spring heads in this step.
    pub target: V,
    /// When the sequence moves on to the next step.
    pub advance: Advance,
    /// Spring parameters for this step (`None`: keep the spring's).
    pub spring: Option<Spring<f32>>,
}

/// Where a sequence is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Reflect)]
#[reflect(Debug, Default, PartialEq, Clone)]
pub enum SequencePhase {
    /// Waiting out its delay.
    #[default]
    Delayed,
    /// Playing a step.
    Playing,
    /// Paused by an interruption (see [`OnInterrupt::Pause`]).
    Paused,
    /// Done: every play completed, or cancelled by an interruption.
    Finished,
}

/// A choreography for the spring on property `P` of this entity: a sequence of targets, each
/// taken when the spring settles on the last or after a time, with an optional delay before the
/// first, per-step spring parameters, and repeats (cycling or ping-pong, a number of times or
/// forever). Every step is a retarget, so the motion never pops: velocity carries over from one
/// step to the next, and into whatever interrupts it.
///
/// The entity needs the spring (`PropertySpring<P>`, e.g. a
/// [`TranslationSpring`](crate::transform::TranslationSpring)); the sequence drives its target.
/// When the last step is done it triggers [`SequenceCompleted<P>`](super::SequenceCompleted)
/// (the spring's own [`SpringSettled`](crate::spring::SpringSettled) fires as always). When
/// something else sets the spring's target mid-way the sequence is interrupted: cancelled or
/// paused as chosen ([`OnInterrupt`]), triggering
/// [`SequenceInterrupted<P>`](super::SequenceInterrupted).
///
/// A step moves on when the spring has settled ([`then`](Self::then)), after a time
/// ([`then_after`](Self::then_after)), as soon as it is visually there
/// ([`then_within`](Self::then_within) a distance, so that what follows starts when the motion
/// looks done rather than after its last, invisible part), or at whichever of settling and a
/// time comes first ([`step`](Self::step) with [`Advance::OnSettleOrAfter`]);
/// [`hold`](Self::hold) stays on the last target for a time.
///
/// A sequence with a delay is how a single spring starts late; the same sequence with
/// [`staggered`](Self::staggered) delays makes a group of entities start one after another.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::choreography::Repeat;
///
/// fn spawn_menu(mut commands: Commands) {
///     for index in 0..5 {
///         commands.spawn((
///             Transform::from_xyz(-400.0, index as f32 * -60.0, 0.0),
///             TranslationSpring::new(Spring::snappy(), Vec3::new(-400.0, index as f32 * -60.0, 0.0)),
///             // Fly in one after another, 60 ms apart, overshoot a little, settle home.
///             SpringSequence::<Translation>::new()
///                 .staggered(index, 0.06)
///                 .then(Vec3::new(20.0, index as f32 * -60.0, 0.0))
///                 .then(Vec3::new(0.0, index as f32 * -60.0, 0.0))
///                 .with_spring(Spring::smooth()),
///         ));
///     }
/// }
///
/// fn pulse(mut commands: Commands) {
///     // A button that pulses between two sizes until something else sets its scale.
///     commands.spawn((
///         Transform::default(),
///         ScaleSpring::new(Spring::gentle(), Vec3::ONE),
///         SpringSequence::<Scale>::new()
///             .then_after(0.4, Vec3::splat(1.08))
///             .then_after(0.4, Vec3::ONE)
///             .repeat(Repeat::Forever),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, (spawn_menu, pulse));
/// # app.update();
/// ```
#[derive(Component, Reflect)]
#[component(on_add = crate::spring::first_use::<Self>)]
#[reflect(Component, Debug)]
pub struct SpringSequence<P: SpringProperty> {
    steps: Vec<SequenceStep<ValueOf<P>>>,
    delay: f32,
    repeat: Repeat,
    mode: LoopMode,
    on_interrupt: OnInterrupt,
    /// Where it is.
    phase: SequencePhase,
    /// The step being played.
    index: usize,
    /// `+1` forward, `−1` backward (ping-pong).
    backward: bool,
    /// Plays completed.
    plays: u32,
    /// Seconds spent in the delay or the current step.
    elapsed: f32,
    #[reflect(ignore)]
    property: PhantomData<fn() -> P>,
}

impl<P: SpringProperty> Clone for SpringSequence<P> {
    fn clone(&self) -> Self {
        Self {
            steps: self.steps.clone(),
            delay: self.delay,
            repeat: self.repeat,
            mode: self.mode,
            on_interrupt: self.on_interrupt,
            phase: self.phase,
            index: self.index,
            backward: self.backward,
            plays: self.plays,
            elapsed: self.elapsed,
            property: PhantomData,
        }
    }
}

impl<P: SpringProperty> fmt::Debug for SpringSequence<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SpringSequence")
            .field("property", &P::short_type_path())
            .field("steps", &self.steps)
            .field("delay", &self.delay)
            .field("repeat", &self.repeat)
            .field("mode", &self.mode)
            .field("on_interrupt", &self.on_interrupt)
            .field("phase", &self.phase)
            .field("index", &self.index)
            .finish_non_exhaustive()
    }
}

impl<P: SpringProperty> Default for SpringSequence<P> {
    fn default() -> Self {
        Self::new()
    }
}

impl<P: SpringProperty> SpringSequence<P> {
    /// An empty sequence: no delay, played once, cancelled by an interruption. Add steps with
    /// [`then`](Self::then) and [`then_after`](Self::then_after).
    #[must_use]
    pub fn new() -> Self {
        Self {
            steps: Vec::new(),
            delay: 0.0,
            repeat: Repeat::Once,
            mode: LoopMode::Cycle,
            on_interrupt: OnInterrupt::Cancel,
            phase: SequencePhase::Delayed,
            index: 0,
            backward: false,
            plays: 0,
            elapsed: 0.0,
            property: PhantomData,
        }
    }

    /// A step to `target`, moving on when the spring has settled there.
    #[must_use]
    pub fn then(self, target: ValueOf<P>) -> Self {
        self.step(target, Advance::OnSettle)
    }

    /// A step to `target`, moving on `seconds` after it began, settled or not.
    #[must_use]
    pub fn then_after(self, seconds: f32, target: ValueOf<P>) -> Self {
        self.step(target, Advance::After(seconds))
    }

    /// A step to `target`, moving on as soon as the spring is visually there: within
    /// `distance` of it ([`Advance::Within`]). With [`hold`](Self::hold) after it, the hold
    /// starts when the motion looks done.
    ///
    /// # Example
    /// ```
    /// use bevy::prelude::*;
    /// use bevy_sprung::prelude::*;
    ///
    /// // A toast that slides in, stays 2 s once it is there, and slides out.
    /// let toast = SpringSequence::<Translation>::new()
    ///     .then_within(0.5, Vec3::new(0.0, 40.0, 0.0))
    ///     .hold(2.0)
    ///     .then(Vec3::new(0.0, -80.0, 0.0));
    /// assert_eq!(toast.steps().len(), 3);
    /// ```
    #[must_use]
    pub fn then_within(self, distance: f32, target: ValueOf<P>) -> Self {
        self.step(target, Advance::Within(distance))
    }

    /// Stays where the last step went for `seconds` (from when that step moved on), before the
    /// next step: a step to the same target that moves on after `seconds`. As the first step
    /// it waits before the sequence starts, as [`delayed`](Self::delayed) does.
    #[must_use]
    pub fn hold(mut self, seconds: f32) -> Self {
        if let Some(last) = self.steps.last() {
            let target = last.target;
            self.step(target, Advance::After(seconds))
        } else {
            self.delay += seconds.max(0.0);
            self
        }
    }

    /// A step to `target`, moving on as `advance` says.
    #[must_use]
    pub fn step(mut self, target: ValueOf<P>, advance: Advance) -> Self {
        self.steps.push(SequenceStep {
            target,
            advance,
            spring: None,
        });
        self
    }

    /// The last step added springs with `spring` (the spring keeps it afterwards, until a later
    /// step sets another).
    #[must_use]
    pub fn with_spring(mut self, spring: Spring<f32>) -> Self {
        if let Some(step) = self.steps.last_mut() {
            step.spring = Some(spring);
        }
        self
    }

    /// Waits `seconds` before the first step.
    #[must_use]
    pub fn delayed(mut self, seconds: f32) -> Self {
        self.delay = if seconds > 0.0 { seconds } else { 0.0 };
        self
    }

    /// Waits `index × interval` seconds before the first step: entity `index` of a group starts
    /// that much after the first (menu items flying in one after another).
    #[must_use]
    pub fn staggered(self, index: usize, interval: f32) -> Self {
        #[expect(clippy::cast_precision_loss, reason = "an index in a group")]
        let index = index as f32;
        self.delayed(index * interval)
    }

    /// Plays the steps `repeat` times.
    #[must_use]
    pub fn repeat(mut self, repeat: Repeat) -> Self {
        self.repeat = repeat;
        self
    }

    /// Goes back and forth through the steps ([`LoopMode::PingPong`]) instead of cycling.
    #[must_use]
    pub fn ping_pong(mut self) -> Self {
        self.mode = LoopMode::PingPong;
        self
    }

    /// What an interruption does: [`OnInterrupt::Cancel`] (the default) or
    /// [`OnInterrupt::Pause`].
    #[must_use]
    pub fn on_interrupt(mut self, on_interrupt: OnInterrupt) -> Self {
        self.on_interrupt = on_interrupt;
        self
    }

    /// The steps.
    #[must_use]
    pub fn steps(&self) -> &[SequenceStep<ValueOf<P>>] {
        &self.steps
    }

    /// Where the sequence is.
    #[must_use]
    pub fn phase(&self) -> SequencePhase {
        self.phase
    }

    /// The index of the step being played (or next to play).
    #[must_use]
    pub fn index(&self) -> usize {
        self.index
    }

    /// How many plays have completed.
    #[must_use]
    pub fn plays(&self) -> u32 {
        self.plays
    }

    /// Whether it is done (completed or cancelled).
    #[must_use]
    pub fn is_finished(&self) -> bool {
        self.phase == SequencePhase::Finished
    }

    /// Goes on after a pause ([`OnInterrupt::Pause`]): the current step's target is set again
    /// and its time starts over. Does nothing unless paused.
    pub fn resume(&mut self) {
        if self.phase == SequencePhase::Paused {
            self.phase = SequencePhase::Playing;
            self.elapsed = f32::NAN;
        }
    }

    /// Plays again from the start (the delay included).
    pub fn restart(&mut self) {
        self.phase = SequencePhase::Delayed;
        self.index = 0;
        self.backward = false;
        self.plays = 0;
        self.elapsed = 0.0;
    }

    /// Whether it was resumed and has yet to set its step's target again.
    pub(super) fn is_resuming(&self) -> bool {
        self.phase == SequencePhase::Playing && self.elapsed.is_nan()
    }

    /// The target of the current step.
    pub(super) fn current(&self) -> Option<&SequenceStep<ValueOf<P>>> {
        self.steps.get(self.index)
    }

    /// How many plays it makes in all (`None`: forever).
    fn total_plays(&self) -> Option<u32> {
        match self.repeat {
            Repeat::Once => Some(1),
            Repeat::Times(times) => Some(times.max(1)),
            Repeat::Forever => None,
        }
    }

    /// Advances the sequence's clock by `dt` and says what to do: start the current step (set
    /// its target), or nothing. `arrived`: the spring has settled on the current target, or
    /// for a [`Within`](Advance::Within) step is within its distance.
    pub(super) fn tick(&mut self, dt: f32, arrived: bool) -> Tick {
        match self.phase {
            SequencePhase::Paused | SequencePhase::Finished => Tick::Idle,
            SequencePhase::Delayed => {
                if self.steps.is_empty() {
                    self.phase = SequencePhase::Finished;
                    return Tick::Completed;
                }
                self.elapsed += dt;
                if self.elapsed >= self.delay {
                    self.phase = SequencePhase::Playing;
                    self.elapsed = 0.0;
                    Tick::Start
                } else {
                    Tick::Idle
                }
            }
            SequencePhase::Playing => {
                if self.elapsed.is_nan() {
                    // Resumed: set the step's target again.
                    self.elapsed = 0.0;
                    return Tick::Start;
                }
                self.elapsed += dt;
                let Some(step) = self.current() else {
                    self.phase = SequencePhase::Finished;
                    return Tick::Completed;
                };
                let done = match step.advance {
                    Advance::OnSettle | Advance::Within(_) => arrived,
                    Advance::After(seconds) => self.elapsed >= seconds,
                    Advance::OnSettleOrAfter(seconds) => arrived || self.elapsed >= seconds,
                };
                if !done {
                    return Tick::Idle;
                }
                if self.next_step() {
                    self.elapsed = 0.0;
                    Tick::Start
                } else {
                    self.phase = SequencePhase::Finished;
                    Tick::Completed
                }
            }
        }
    }

    /// Moves to the next step, counting plays; `false` when every play is done.
    fn next_step(&mut self) -> bool {
        let last = self.steps.len() - 1;
        let at_end = if self.backward {
            self.index == 0
        } else {
            self.index == last
        };
        if !at_end {
            if self.backward {
                self.index -= 1;
            } else {
                self.index += 1;
            }
            return true;
        }
        self.plays = self.plays.saturating_add(1);
        if self.total_plays().is_some_and(|total| self.plays >= total) {
            return false;
        }
        match self.mode {
            LoopMode::Cycle => self.index = 0,
            LoopMode::PingPong => {
                // A single step has nothing to come back through: it just plays again.
                if last > 0 {
                    self.backward = !self.backward;
                    if self.backward {
                        self.index = last - 1;
                    } else {
                        self.index = 1;
                    }
                }
            }
        }
        true
    }

    /// Handles an interruption: cancels or pauses as chosen.
    pub(super) fn interrupt(&mut self) {
        self.phase = match self.on_interrupt {
            OnInterrupt::Cancel => SequencePhase::Finished,
            OnInterrupt::Pause => SequencePhase::Paused,
        };
    }
}

/// What [`SpringSequence::tick`] asks of the spring.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Tick {
    /// Nothing this frame.
    Idle,
    /// Retarget to the current step (and set its spring parameters).
    Start,
    /// The last step is done.
    Completed,
}
