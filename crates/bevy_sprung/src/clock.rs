//! Which clock springs advance with.

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;

/// Which clock a spring advances with.
#[derive(Reflect, Debug, Default, Clone, Copy, PartialEq, Eq, Hash)]
#[reflect(Debug, Default, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum SpringClock {
    /// The schedule's own [`Time`]: `Time<Virtual>` in `PostUpdate` (it stops while the game is
    /// paused), `Time<Fixed>` in `FixedUpdate`.
    #[default]
    Game,
    /// `Time<Real>`: keeps going while the game is paused (menus, UI).
    Real,
}

/// The clock of every spring that does not choose its own
/// ([`PropertySpring::with_clock`](crate::spring::PropertySpring::with_clock)). Change it at
/// any time; [`SpringPlugins::with_clock`](crate::SpringPlugins::with_clock) sets it at startup.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::clock::{DefaultSpringClock, SpringClock};
///
/// // A menu-only app: every spring on the real clock, so pausing the game never stops the UI.
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugins::default()));
/// app.insert_resource(DefaultSpringClock(SpringClock::Real));
/// ```
#[derive(Resource, Reflect, Debug, Default, Clone, Copy, PartialEq, Eq)]
#[reflect(Resource, Debug, Default, PartialEq, Clone)]
pub struct DefaultSpringClock(pub SpringClock);

/// The one source of time in the crate: this frame's step and the elapsed time on each spring
/// clock, and where the fixed-timestep clock stands. Every timed system reads it (springs,
/// stagger delays, shake, squash, chains, scroll and drag samples, targets that move in
/// `FixedUpdate`), so a pause menu on [`SpringClock::Real`] moves all of them alike; nothing
/// else in the crate reads Bevy's `Time`.
#[derive(SystemParam)]
pub(crate) struct SpringTime<'w> {
    time: Res<'w, Time>,
    real: Res<'w, Time<Real>>,
    fixed: Res<'w, Time<Fixed>>,
    default: Res<'w, DefaultSpringClock>,
}

/// Where the fixed-timestep clock stands within this frame: its step, and how far past its
/// last step the frame is (Bevy's overstep), in seconds. What places a target that moves in
/// `FixedUpdate` between its steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FixedStep {
    /// The fixed timestep.
    pub(crate) timestep: f32,
    /// The time accumulated since the last fixed step.
    pub(crate) overstep: f32,
}

/// This frame's time steps, read once per system run: by clock, and for springs that use the
/// default one. The default's step is there twice, so that any two-bit index is one (a clock
/// index is masked rather than bounds-checked: the frame's preparation looks up four at a time).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FrameSteps([f32; 4]);

impl SpringTime<'_> {
    /// The clock `clock` stands for: itself, or the default clock for `None`.
    fn resolve(&self, clock: Option<SpringClock>) -> SpringClock {
        clock.unwrap_or(self.default.0)
    }

    /// This frame's step on `clock` (`None`: the default clock), in seconds.
    pub(crate) fn delta(&self, clock: Option<SpringClock>) -> f32 {
        match self.resolve(clock) {
            SpringClock::Game => self.time.delta_secs(),
            SpringClock::Real => self.real.delta_secs(),
        }
    }

    /// The seconds elapsed on `clock` (`None`: the default clock).
    pub(crate) fn elapsed(&self, clock: Option<SpringClock>) -> f64 {
        match self.resolve(clock) {
            SpringClock::Game => self.time.elapsed_secs_f64(),
            SpringClock::Real => self.real.elapsed_secs_f64(),
        }
    }

    /// When a pointer sample is taken: the real clock's elapsed seconds. A pointer moves in
    /// the user's time, so its velocity is measured in it whatever the springs' clock is (the
    /// fling it starts then moves on the spring's own clock).
    #[cfg(feature = "picking")]
    pub(crate) fn pointer_now(&self) -> f64 {
        self.elapsed(Some(SpringClock::Real))
    }

    /// Where the fixed-timestep clock stands within this frame.
    pub(crate) fn fixed_step(&self) -> FixedStep {
        FixedStep {
            timestep: self.fixed.timestep().as_secs_f32(),
            overstep: self.fixed.overstep().as_secs_f32(),
        }
    }

    /// The time steps of this frame.
    pub(crate) fn steps(&self) -> FrameSteps {
        let (game, real) = (self.time.delta_secs(), self.real.delta_secs());
        let default = match self.default.0 {
            SpringClock::Game => game,
            SpringClock::Real => real,
        };
        FrameSteps([game, real, default, default])
    }
}

impl FrameSteps {
    /// The index of `clock` among the steps (`None`: the default clock): the option's three
    /// states are the indices, so this is free.
    #[inline]
    pub(crate) fn index(clock: Option<SpringClock>) -> u8 {
        match clock {
            Some(SpringClock::Game) => 0,
            Some(SpringClock::Real) => 1,
            None => 2,
        }
    }

    /// Whether `other` has the same steps, bit for bit.
    #[inline]
    pub(crate) fn same(self, other: Self) -> bool {
        self.0.map(f32::to_bits) == other.0.map(f32::to_bits)
    }

    /// The step of the clock at `index`.
    #[inline]
    pub(crate) fn of(self, index: u8) -> f32 {
        self.0[usize::from(index & 3)]
    }

    /// The step of `clock`, or of the default clock for `None`.
    #[inline]
    pub(crate) fn dt(self, clock: Option<SpringClock>) -> f32 {
        self.of(Self::index(clock))
    }

    /// The steps of a test: `dt` on every clock.
    #[cfg(test)]
    pub(crate) fn all(dt: f32) -> Self {
        Self([dt; 4])
    }

    /// The steps of a test: the game clock's, the real clock's and the default clock's.
    #[cfg(test)]
    pub(crate) fn each(game: f32, real: f32, default: f32) -> Self {
        Self([game, real, default, default])
    }
}

/// Registers [`SpringClock`] and inserts the [`DefaultSpringClock`] (part of
/// [`SpringPlugins`](crate::SpringPlugins)).
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringClockPlugin {
    /// The default clock to insert if the app has none yet.
    pub default: SpringClock,
}

impl Plugin for SpringClockPlugin {
    fn build(&self, app: &mut App) {
        if !app.world().contains_resource::<DefaultSpringClock>() {
            app.insert_resource(DefaultSpringClock(self.default));
        }
        app.register_type::<SpringClock>()
            .register_type::<DefaultSpringClock>();
    }

    /// Adding it again keeps the clock already set.
    fn is_unique(&self) -> bool {
        false
    }
}
