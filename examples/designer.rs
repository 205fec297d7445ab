//! The spring designer beside a small game: a ball that hops between two points on a
//! translation spring it loads from `assets/springs/ball.spring.ron`.
//!
//! - Edit any field: every parametrisation follows, the plot and the readouts change, and the
//!   ball hops with the new spring at once (the designer tunes it live).
//! - **Keep as B**, then edit: the old spring stays on the plot and in the preview, in grey.
//! - The preview plays the spring on a sprite, a button and a camera at the chosen frame rate
//!   and time scale; the plot's dots are the frames, on the same curve at every rate.
//! - **Save** writes `assets/springs/ball.spring.ron`, the file the ball loads: the game reloads
//!   it (here at once; a separate game with Bevy's `file_watcher` feature, when it changes).
//!   **Copy code** puts `Spring::from_duration_and_bounce(…)` on the clipboard.
//! - `<` `>` pick another spring of the game (none: the preview alone). F2 hides the panel.
//!
//! Without input, a short scripted tour keeps the ball's spring as B and makes A bouncier.
//!
//! ```text
//! cargo run --example designer
//! ```

#[path = "support/tour.rs"]
mod tour;

use bevy::prelude::*;
use bevy_sprung::asset::UseSpringPreset;
use bevy_sprung::designer::{Parametrisation, SpringDesign, SpringDesignerPlugin, TuneSpring};
use bevy_sprung::prelude::*;
use bevy_sprung::transform::Translation;
use sprung::Parameter;
use tour::{Tour, TourPlugin};

/// The two points the ball hops between, in the part of the window left of the panel.
const HOPS: [Vec3; 2] = [
    Vec3::new(-560.0, 140.0, 0.0),
    Vec3::new(-330.0, -160.0, 0.0),
];
/// Seconds between hops.
const HOP_EVERY: f32 = 1.4;

#[derive(Component)]
struct Ball;

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: spring designer".into(),
                    resolution: (1280, 800).into(),
                    ..default()
                }),
                ..default()
            }),
            SpringPlugins::default(),
            SpringDesignerPlugin::default()
                .toggled_by(KeyCode::F2)
                .saving_to("springs/ball.spring.ron"),
            TourPlugin::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.06, 0.07, 0.1)))
        .add_systems(Startup, setup)
        .add_systems(Update, (hop, tour_edits))
        .run();
}

fn setup(mut commands: Commands, assets: Res<AssetServer>) {
    commands.spawn(Camera2d);
    let ball = commands
        .spawn((
            Name::new("Ball"),
            Ball,
            Sprite::from_color(Color::srgb(0.43, 0.75, 1.0), Vec2::splat(36.0)),
            Transform::from_translation(HOPS[0]),
            TranslationSpring::new(Spring::snappy(), HOPS[0]),
            UseSpringPreset(assets.load("springs/ball.spring.ron")),
        ))
        .id();
    // The designer starts on the ball's spring.
    commands.trigger(TuneSpring::of::<Translation>(ball));
}

/// The game: the ball hops to the other point every `HOP_EVERY` seconds.
fn hop(time: Res<Time>, mut balls: Query<&mut TranslationSpring, With<Ball>>) {
    let hop = usize::from((time.elapsed_secs() / HOP_EVERY).rem_euclid(2.0) >= 1.0);
    for mut spring in &mut balls {
        if spring.target() != HOPS[hop] {
            spring.set_target(HOPS[hop]);
        }
    }
}

/// The tour: keep the ball's spring as B, then make A bouncier and preview it at 30 fps.
fn tour_edits(tour: Res<Tour>, mut design: ResMut<SpringDesign>) {
    if tour.passed(1.0) {
        design.keep_as_reference();
        if let Err(error) =
            design.set_field(Parametrisation::DurationBounce, Parameter::Bounce, 0.45)
        {
            warn!("{error}");
        }
    }
    if tour.passed(1.5) {
        design.preview.fps = 30.0;
    }
}
