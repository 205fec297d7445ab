//! Many springing sprites, with the count and the frame time on screen.
//!
//! Every sprite springs toward a spot on a grid; a wave kicks a band of them every frame,
//! sweeping the whole grid every 10 seconds, so some are moving and the rest have settled and
//! sleep (they are not iterated and write nothing). Press S to turn sleeping off and see what the resting ones would cost if
//! they were stepped every frame; +/- change the count.
//!
//! ```text
//! cargo run --release --example stress
//! ```

use bevy::diagnostic::{Diagnostic, DiagnosticsStore, FrameTimeDiagnosticsPlugin};
use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringAsleep;

/// Sprites to start with.
const START_COUNT: usize = 20_000;

/// Which sprites the wave will retarget next.
#[derive(Resource, Default)]
struct Wave {
    next: usize,
}

/// Whether resting springs may sleep.
#[derive(Resource)]
struct Sleeping(bool);

#[derive(Resource)]
struct Count(usize);

/// A stress sprite, and its place in the wave.
#[derive(Component)]
struct Home(usize);

#[derive(Component)]
struct Hud;

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: stress".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            FrameTimeDiagnosticsPlugin::default(),
            SpringPlugins::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.04, 0.05, 0.07)))
        .init_resource::<Wave>()
        .insert_resource(Sleeping(true))
        .insert_resource(Count(START_COUNT))
        .add_systems(Startup, setup)
        .add_systems(Update, (controls, respawn, wave, hud).chain())
        .run();
}

fn setup(mut commands: Commands) {
    commands.spawn(Camera2d);
    commands.spawn((
        Hud,
        Text::new(""),
        TextFont::from_font_size(18.0),
        TextColor(Color::WHITE),
        BackgroundColor(Color::srgba(0.0, 0.0, 0.0, 0.6)),
        Node {
            position_type: PositionType::Absolute,
            top: Val::Px(10.0),
            left: Val::Px(10.0),
            padding: UiRect::all(Val::Px(8.0)),
            ..default()
        },
    ));
}

/// The home of sprite `i` of `count`, on a grid filling the window.
fn home(i: usize, count: usize) -> Vec3 {
    let columns = (count * 17 / 10).isqrt().max(1);
    let rows = count.div_ceil(columns);
    let (width, height) = (1240.0, 640.0);
    let x = (i % columns) as f32 / columns as f32 * width - width / 2.0;
    let y = (i / columns) as f32 / rows.max(1) as f32 * height - height / 2.0 - 20.0;
    Vec3::new(x, y, 0.0)
}

/// Rest tolerances with sleeping on, and none (never at rest) with it off.
fn rest(sleeping: bool) -> RestThreshold {
    if sleeping {
        RestThreshold::new(0.05, 0.5)
    } else {
        RestThreshold::new(0.0, 0.0)
    }
}

fn respawn(
    mut commands: Commands,
    count: Res<Count>,
    sleeping: Res<Sleeping>,
    sprites: Query<Entity, With<Home>>,
) {
    if !count.is_changed() {
        return;
    }
    for entity in &sprites {
        commands.entity(entity).despawn();
    }
    let spring = Spring::from_natural_frequency(9.0, 0.35).unwrap();
    let resting = rest(sleeping.0);
    let total = count.0;
    commands.spawn_batch((0..total).map(move |i| {
        let spot = home(i, total);
        let hue = (i as f32 / total as f32) * 300.0;
        (
            Home(i),
            Sprite::from_color(Color::hsl(hue, 0.7, 0.6), Vec2::splat(4.0)),
            Transform::from_translation(spot + Vec3::new(0.0, -400.0, 0.0)),
            TranslationSpring::new(spring, spot).with_rest(resting),
        )
    }));
}

fn controls(
    keys: Res<ButtonInput<KeyCode>>,
    mut sleeping: ResMut<Sleeping>,
    mut count: ResMut<Count>,
    mut springs: Query<&mut TranslationSpring>,
) {
    if keys.just_pressed(KeyCode::KeyS) {
        sleeping.0 = !sleeping.0;
        for mut spring in &mut springs {
            spring.set_rest(rest(sleeping.0));
            // Wake everything so the new setting applies at once.
            spring.add_impulse(Vec3::Y * 1e-3);
        }
    }
    if keys.just_pressed(KeyCode::Equal) || keys.just_pressed(KeyCode::NumpadAdd) {
        count.0 = (count.0 * 2).min(400_000);
    }
    if keys.just_pressed(KeyCode::Minus) || keys.just_pressed(KeyCode::NumpadSubtract) {
        count.0 = (count.0 / 2).max(1000);
    }
}

/// Every frame, kick the next band of sprites off their home and back: a wave that sweeps the
/// grid every 600 frames.
fn wave(
    mut state: ResMut<Wave>,
    count: Res<Count>,
    mut sprites: Query<(&Home, &mut TranslationSpring)>,
) {
    let band = (count.0 / 600).max(1);
    let (from, to) = (state.next, state.next + band);
    for (home, mut spring) in &mut sprites {
        if (from..to).contains(&home.0) {
            spring.add_impulse(Vec3::new(0.0, 260.0, 0.0));
        }
    }
    state.next = if to >= count.0 { 0 } else { to };
}

fn hud(
    diagnostics: Res<DiagnosticsStore>,
    count: Res<Count>,
    sleeping: Res<Sleeping>,
    asleep: Query<(), With<SpringAsleep<Translation>>>,
    mut text: Single<&mut Text, With<Hud>>,
) {
    let frame_ms = diagnostics
        .get(&FrameTimeDiagnosticsPlugin::FRAME_TIME)
        .and_then(Diagnostic::smoothed)
        .unwrap_or(0.0);
    let resting = asleep.iter().count();
    text.0 = format!(
        "{} springs, {} asleep, {} moving\nframe time {frame_ms:.2} ms\n\
         sleeping: {} [S]   count: [+] / [-]",
        count.0,
        resting,
        count.0.saturating_sub(resting),
        if sleeping.0 { "on" } else { "off" }
    );
}
