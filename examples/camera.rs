//! Camera smoothing over fixed-timestep gameplay.
//!
//! The player moves in `FixedUpdate` at 64 Hz (arrow keys or WASD; it drives a figure eight
//! on its own otherwise). The camera follows and looks at it with a [`SpringFollow`]: it reads
//! the player after this frame's fixed steps, follows it along its fixed-step velocity between
//! steps, and steps an exact moving-target spring, so it holds a steady lag with no jitter even
//! though frames and fixed steps do not line up.
//!
//! Press C to switch to Bevy's `smooth_nudge` (first-order smoothing of the raw position, as
//! most games do it) and compare: the player stutters against the background as frames and
//! fixed steps drift in and out of phase. F toggles a frame-rate limiter that makes the frame
//! times uneven on purpose.
//!
//! ```text
//! cargo run --example camera
//! ```

use std::time::Duration;

use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::math::StableInterpolate;
use bevy::prelude::*;
use bevy::transform::TransformSystems;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringSystems;

/// Where the camera sits relative to the player, and where it looks.
const OFFSET: Vec3 = Vec3::new(0.0, 5.0, 11.0);
const LOOK_AT: Vec3 = Vec3::new(0.0, 0.8, 0.0);
const SPEED: f32 = 7.0;

#[derive(Component)]
struct Player {
    /// The autopilot's phase along its figure eight.
    phase: f32,
}

#[derive(Component)]
struct FollowCamera;

#[derive(Resource, PartialEq, Eq, Clone, Copy)]
enum Smoothing {
    Spring,
    SmoothNudge,
}

/// Sleep a varying amount each frame to make frame times uneven.
#[derive(Resource)]
struct UnevenFrames(bool);

#[derive(Component)]
struct Hud;

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: camera smoothing".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            SpringPlugins::default(),
        ))
        .insert_resource(Time::<Fixed>::from_hz(64.0))
        .insert_resource(Smoothing::Spring)
        .insert_resource(UnevenFrames(true))
        .insert_resource(ClearColor(Color::srgb(0.55, 0.7, 0.85)))
        .add_systems(Startup, setup)
        .add_systems(FixedUpdate, move_player)
        .add_systems(Update, (switch, hud, uneven_frames))
        // The comparison overrides the springs: after them, before propagation.
        .add_systems(
            PostUpdate,
            smooth_nudge
                .after(SpringSystems)
                .before(TransformSystems::Propagate),
        )
        .run();
}

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    // A checkered ground so camera motion is easy to judge.
    let light = materials.add(Color::srgb(0.82, 0.84, 0.8));
    let dark = materials.add(Color::srgb(0.55, 0.6, 0.52));
    let tile = meshes.add(Plane3d::default().mesh().size(4.0, 4.0));
    for i in -12..12 {
        for j in -12..12 {
            let material = if (i + j) % 2 == 0 {
                light.clone()
            } else {
                dark.clone()
            };
            commands.spawn((
                Mesh3d(tile.clone()),
                MeshMaterial3d(material),
                Transform::from_xyz(i as f32 * 4.0 + 2.0, 0.0, j as f32 * 4.0 + 2.0),
            ));
        }
    }
    let pillar = meshes.add(Cuboid::new(0.6, 3.0, 0.6));
    let pillar_material = materials.add(Color::srgb(0.45, 0.4, 0.55));
    for k in 0..16 {
        let angle = k as f32 * std::f32::consts::TAU / 16.0;
        commands.spawn((
            Mesh3d(pillar.clone()),
            MeshMaterial3d(pillar_material.clone()),
            Transform::from_xyz(18.0 * angle.cos(), 1.5, 18.0 * angle.sin()),
        ));
    }
    let player = commands
        .spawn((
            Player { phase: 0.0 },
            Mesh3d(meshes.add(Cuboid::new(1.0, 1.6, 1.0))),
            MeshMaterial3d(materials.add(Color::srgb(0.95, 0.45, 0.2))),
            Transform::from_xyz(0.0, 0.8, 0.0),
        ))
        .id();
    commands.spawn((
        DirectionalLight {
            illuminance: 6000.0,
            shadow_maps_enabled: false,
            ..default()
        },
        Transform::from_xyz(4.0, 10.0, 6.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
    let start = Transform::from_translation(OFFSET + Vec3::Y * 0.8).looking_at(LOOK_AT, Vec3::Y);
    commands.spawn((
        FollowCamera,
        Camera3d::default(),
        // No tonemapping LUTs are built into this example's Bevy features.
        Tonemapping::None,
        start,
        TranslationSpring::new(
            Spring::from_natural_frequency(4.0, 1.0).unwrap(),
            start.translation,
        ),
        RotationSpring::new(
            Spring::from_natural_frequency(6.0, 1.0).unwrap(),
            start.rotation,
        ),
        SpringFollow::new(player, OFFSET)
            .looking_at(LOOK_AT - Vec3::Y * 0.8)
            .moving_in_fixed_update(),
    ));
    commands.spawn((
        Hud,
        Text::new(""),
        TextFont::from_font_size(17.0),
        TextColor(Color::srgb(0.05, 0.07, 0.12)),
        Node {
            position_type: PositionType::Absolute,
            top: Val::Px(12.0),
            left: Val::Px(14.0),
            ..default()
        },
    ));
}

/// Gameplay at 64 Hz: keys steer; without input the player drives a figure eight.
fn move_player(
    time: Res<Time>,
    keys: Res<ButtonInput<KeyCode>>,
    mut player: Single<(&mut Player, &mut Transform)>,
) {
    let (player, transform) = &mut *player;
    let dt = time.delta_secs();
    let key = |codes: [KeyCode; 2]| if keys.any_pressed(codes) { 1.0 } else { 0.0 };
    let input = Vec3::new(
        key([KeyCode::ArrowRight, KeyCode::KeyD]) - key([KeyCode::ArrowLeft, KeyCode::KeyA]),
        0.0,
        key([KeyCode::ArrowDown, KeyCode::KeyS]) - key([KeyCode::ArrowUp, KeyCode::KeyW]),
    );
    if input == Vec3::ZERO {
        player.phase += dt * 0.45;
        let p = player.phase;
        transform.translation = Vec3::new(12.0 * p.sin(), 0.8, 7.0 * (2.0 * p).sin());
    } else {
        transform.translation += input.normalize() * SPEED * dt;
    }
}

fn switch(
    keys: Res<ButtonInput<KeyCode>>,
    mut smoothing: ResMut<Smoothing>,
    mut uneven: ResMut<UnevenFrames>,
    mut commands: Commands,
    camera: Single<Entity, With<FollowCamera>>,
    player: Single<Entity, With<Player>>,
) {
    if keys.just_pressed(KeyCode::KeyF) {
        uneven.0 = !uneven.0;
    }
    if !keys.just_pressed(KeyCode::KeyC) {
        return;
    }
    *smoothing = match *smoothing {
        Smoothing::Spring => {
            commands.entity(*camera).remove::<SpringFollow>();
            Smoothing::SmoothNudge
        }
        Smoothing::SmoothNudge => {
            commands.entity(*camera).insert(
                SpringFollow::new(*player, OFFSET)
                    .looking_at(LOOK_AT - Vec3::Y * 0.8)
                    .moving_in_fixed_update(),
            );
            Smoothing::Spring
        }
    };
}

/// The comparison: first-order smoothing toward the raw player position, as most games do.
fn smooth_nudge(
    smoothing: Res<Smoothing>,
    time: Res<Time>,
    player: Single<&Transform, (With<Player>, Without<FollowCamera>)>,
    mut camera: Single<
        (&mut Transform, &mut TranslationSpring, &mut RotationSpring),
        With<FollowCamera>,
    >,
) {
    if *smoothing != Smoothing::SmoothNudge {
        return;
    }
    let (transform, position, rotation) = &mut *camera;
    let dt = time.delta_secs();
    let goal = player.translation + OFFSET;
    transform.translation.smooth_nudge(&goal, 4.0, dt);
    let look = transform
        .looking_at(player.translation + LOOK_AT - Vec3::Y * 0.8, Vec3::Y)
        .rotation;
    transform.rotation.smooth_nudge(&look, 6.0, dt);
    // Keep the springs where the camera is, so switching back continues smoothly.
    let (here, facing) = (transform.translation, transform.rotation);
    position.set_target(here);
    position.set_target_velocity(Vec3::ZERO);
    rotation.set_target(facing);
}

fn hud(
    smoothing: Res<Smoothing>,
    uneven: Res<UnevenFrames>,
    mut text: Single<&mut Text, With<Hud>>,
) {
    let mode = match *smoothing {
        Smoothing::Spring => "exact spring follow (fixed-step aware)",
        Smoothing::SmoothNudge => "smooth_nudge (first order, raw position)",
    };
    text.0 = format!(
        "player moves in FixedUpdate at 64 Hz   camera: {mode}   [C] switch\n\
         uneven frame times: {}   [F] toggle   arrows/WASD steer",
        if uneven.0 { "on" } else { "off" }
    );
}

/// Uneven frames on purpose: sleep 0 to 12 ms in a repeating irregular pattern.
fn uneven_frames(uneven: Res<UnevenFrames>, mut frame: Local<u32>) {
    if !uneven.0 {
        return;
    }
    *frame += 1;
    let pattern = [0, 9, 2, 12, 0, 5, 11, 1];
    std::thread::sleep(Duration::from_millis(
        pattern[*frame as usize % pattern.len()],
    ));
}
