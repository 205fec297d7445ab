//! The scripted tour an example plays while nobody is at the mouse (as under CI's Xvfb), so
//! that its screenshots show what it does. Mouse motion or a key press ends it and hands the
//! example to the user.
//!
//! An example includes it with `#[path = "support/tour.rs"] mod tour;`, adds [`TourPlugin`]
//! and reads [`Tour`] in its own systems; `support/pointer.rs` adds a scripted mouse pointer
//! for examples that go through picking.

#![allow(dead_code, reason = "each example uses the part of the tour it needs")]

use bevy::input::mouse::MouseMotion;
use bevy::prelude::*;

/// Plays the tour from the first frame: [`Tour`]'s clock runs on real time (a tour goes on
/// while a game is paused) until mouse motion, a key press, or the end set with
/// [`ends_after`](Self::ends_after).
#[derive(Default)]
pub(crate) struct TourPlugin {
    end: Option<f32>,
}

impl TourPlugin {
    /// A tour that also ends by itself `seconds` after it started.
    pub(crate) fn ends_after(seconds: f32) -> Self {
        Self { end: Some(seconds) }
    }
}

impl Plugin for TourPlugin {
    fn build(&self, app: &mut App) {
        app.insert_resource(Tour {
            running: true,
            elapsed: 0.0,
            previous: 0.0,
            end: self.end.unwrap_or(f32::INFINITY),
        })
        .add_systems(First, advance_tour.in_set(TourSystems));
    }
}

/// Where the tour's clock advances, in `First`: everything after it in the frame sees the
/// frame's tour time.
#[derive(SystemSet, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct TourSystems;

/// The tour's clock: seconds since it started, while it runs.
#[derive(Resource)]
pub(crate) struct Tour {
    running: bool,
    elapsed: f32,
    /// The elapsed time of the previous frame, to tell when a moment of the tour passes.
    previous: f32,
    end: f32,
}

impl Tour {
    /// Seconds since the tour started, while it runs; `None` once it is over.
    pub(crate) fn time(&self) -> Option<f32> {
        self.running.then_some(self.elapsed)
    }

    /// Whether the tour runs.
    pub(crate) fn is_running(&self) -> bool {
        self.running
    }

    /// Whether the tour runs and passed `moment` (seconds from its start) this frame.
    pub(crate) fn passed(&self, moment: f32) -> bool {
        self.running && self.previous < moment && self.elapsed >= moment
    }
}

/// Advances the tour, and ends it on mouse motion, a key press or its end.
fn advance_tour(
    time: Res<Time<Real>>,
    mut tour: ResMut<Tour>,
    mut motion: MessageReader<MouseMotion>,
    keys: Res<ButtonInput<KeyCode>>,
) {
    if !tour.running {
        return;
    }
    let user = motion.read().count() > 0 || keys.get_just_pressed().count() > 0;
    tour.previous = tour.elapsed;
    tour.elapsed += time.delta_secs();
    if user || tour.elapsed >= tour.end {
        tour.running = false;
        info!("scripted tour over: the example is yours");
    }
}
