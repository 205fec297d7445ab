//! The preview: the design moving real things — a sprite to a target, a button's scale, a
//! camera following a target that jumps — as a game at the chosen frame rate would show it,
//! at the chosen time scale, replayed when it has settled.
//!
//! Each frame shows the state at the last step a game at that rate would have taken: the
//! closed form at that time, which is what the plugin's steps give (to `f32` rounding) at any
//! rate, so 30 and 240 fps follow the same curve, one in coarser steps.

use bevy::prelude::*;
use sprung::Spring;

use super::model::{SpringDesign, step_response};
use crate::clock::{SpringClock, SpringTime};

/// How far a lane's travel is, in logical pixels.
pub(super) const TRAVEL: f32 = 440.0;
/// The scale a button springs to from 1.
const PRESSED_SCALE: f32 = 1.35;
/// Seconds the preview holds at rest before replaying.
const HOLD: f32 = 0.6;

/// Real seconds since the preview (re)started.
#[derive(Resource, Debug, Default, Clone, Copy)]
pub(super) struct PreviewClock {
    pub(super) elapsed: f32,
}

/// Which thing a preview node is, and whether it shows the reference (B).
#[derive(Component, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) enum PreviewThing {
    /// A sprite moving to a target.
    #[default]
    Sprite,
    /// A button's scale.
    Button,
    /// A camera's view following a target.
    Camera,
}

/// Marks the preview node that shows the reference spring.
#[derive(Component, Clone, Copy, Debug, Default)]
pub(super) struct ShowsReference;

/// The playhead over the plot.
#[derive(Component, Clone, Copy, Debug, Default)]
pub(super) struct Playhead;

/// Advances the preview on the real clock (it plays while the game is paused) and replays it
/// once both springs have settled.
pub(super) fn advance(
    time: SpringTime,
    design: Res<SpringDesign>,
    plot: Res<super::plot::ResponsePlot>,
    mut clock: ResMut<PreviewClock>,
) {
    if design.is_changed() {
        clock.elapsed = 0.0;
        return;
    }
    clock.elapsed += time.delta(Some(SpringClock::Real));
    let spring_time = clock.elapsed * design.preview.time_scale;
    if spring_time > plot.span + HOLD * design.preview.time_scale {
        clock.elapsed = 0.0;
    }
}

/// Moves the preview's nodes to the shown state of their spring.
pub(super) fn show(
    design: Res<SpringDesign>,
    clock: Res<PreviewClock>,
    plot: Res<super::plot::ResponsePlot>,
    mut things: Query<(
        &PreviewThing,
        Has<ShowsReference>,
        &mut Node,
        &mut UiTransform,
        &mut Visibility,
    )>,
    mut playhead: Query<&mut Node, (With<Playhead>, Without<PreviewThing>)>,
) {
    let t = design
        .preview
        .shown_time(clock.elapsed)
        .min(plot.span + HOLD);
    for (thing, reference, mut node, mut transform, mut visibility) in &mut things {
        let spring: Option<Spring<f32>> = if reference {
            design.reference()
        } else {
            Some(design.spring())
        };
        let Some(spring) = spring else {
            *visibility = Visibility::Hidden;
            continue;
        };
        *visibility = Visibility::Inherited;
        let (x, _) = step_response(&spring, t);
        match thing {
            PreviewThing::Sprite | PreviewThing::Camera => node.left = Val::Px(x * TRAVEL),
            PreviewThing::Button => {
                transform.scale = Vec2::splat(1.0 + (PRESSED_SCALE - 1.0) * x);
            }
        }
    }
    for mut node in &mut playhead {
        let share = (t / plot.span).clamp(0.0, 1.0);
        node.left = Val::Px(share * (super::plot::PLOT_SIZE.x as f32 - 1.0));
    }
}
