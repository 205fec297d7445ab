//! A third-person orbit camera: a [`CameraRig`] with an [`OrbitRig`] around a player walking
//! among pillars. Yaw, pitch and distance spring in polar coordinates (orbiting never changes
//! the distance); [`CameraOcclusion`] pulls the camera in front of a pillar that comes between
//! it and the player, and lets it spring back out once the way is clear. Tab switches to a
//! dolly shot: a camera on a curved rail along the front of the arena ([`CameraRail`]), which
//! slides along it to the place nearest the player and turns to watch them. The two rigs are
//! [`VirtualCamera`]s and the rendering camera's [`CameraBlend`] springs from one to the other
//! with its velocity kept.
//!
//! D shows the rigs' guides (the debug overlay, [`SpringDebugPlugin`]): the point each shot
//! frames, the orbit sphere, the ray occlusion is looked for on (red while a pillar pulls the
//! camera in), and the dolly's rail with the place its camera is at.
//!
//! Drag with the left mouse button to orbit, scroll to zoom, Tab for the dolly. Without input
//! the camera turns slowly round the player on its own, the dolly shot comes and goes, and the
//! guides are shown for the last part.
//!
//! ```text
//! cargo run --example orbit
//! ```

use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::gizmos::config::GizmoConfigStore;
use bevy::input::mouse::{AccumulatedMouseMotion, AccumulatedMouseScroll};
use bevy::math::cubic_splines::{CubicCardinalSpline, CubicGenerator};
use bevy::prelude::*;
use bevy_sprung::camera::{BlendTrack, RigMotion};
use bevy_sprung::camera::{
    CameraBlend, CameraOcclusion, CameraRail, CameraTargets, OrbitRig, VirtualCamera,
};
use bevy_sprung::debug::{CameraRigGizmos, SpringDebugPlugin};
use bevy_sprung::prelude::*;

#[path = "support/tour.rs"]
mod tour;

use tour::{Tour, TourPlugin};

#[derive(Component)]
struct Player;

/// The two shots.
#[derive(Component)]
struct OrbitShot;
#[derive(Component)]
struct Dolly;

#[derive(Component)]
struct Hud;

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: orbit camera".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            SpringPlugins::default(),
            SpringDebugPlugin::hidden().toggled_by(KeyCode::KeyD),
            TourPlugin::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.55, 0.7, 0.85)))
        .insert_resource(GlobalAmbientLight {
            brightness: 600.0,
            ..default()
        })
        .add_systems(Startup, (setup, guides_in_metres))
        .add_systems(Update, (walk, orbit_input, switch_shot, show_guides, hud))
        .run();
}

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    commands.spawn((
        Mesh3d(meshes.add(Plane3d::default().mesh().size(60.0, 60.0))),
        MeshMaterial3d(materials.add(Color::srgb(0.62, 0.68, 0.58))),
    ));
    // A ring of pillars the player walks among.
    let pillar = meshes.add(Cuboid::new(1.0, 5.0, 1.0));
    let stone = materials.add(Color::srgb(0.5, 0.45, 0.6));
    for k in 0..10 {
        let angle = k as f32 * std::f32::consts::TAU / 10.0;
        commands.spawn((
            Mesh3d(pillar.clone()),
            MeshMaterial3d(stone.clone()),
            Transform::from_xyz(7.0 * angle.cos(), 2.5, 7.0 * angle.sin()),
        ));
    }
    let player = commands
        .spawn((
            Player,
            Mesh3d(meshes.add(Capsule3d::new(0.45, 1.0))),
            MeshMaterial3d(materials.add(Color::srgb(0.95, 0.45, 0.2))),
            Transform::from_xyz(4.0, 0.95, 0.0),
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
    // The shots: an orbit behind the player, pulled in by pillars, and a dolly on a rail.
    commands.spawn((
        OrbitShot,
        VirtualCamera::new(1),
        Projection::Perspective(default()),
        CameraRig::new(Spring::smooth()),
        CameraTargets::single(player),
        OrbitRig::new(11.0)
            .with_angles(0.0, 0.35)
            .with_limits(Vec2::new(-0.2, 1.3), Vec2::new(4.0, 20.0)),
        CameraOcclusion::new(0.4),
    ));
    // The rail: a curve along the front of the arena, rising at the middle.
    let rail = CubicCardinalSpline::new_catmull_rom([
        Vec3::new(-16.0, 3.0, 11.0),
        Vec3::new(-8.0, 6.0, 15.0),
        Vec3::new(0.0, 7.0, 16.0),
        Vec3::new(8.0, 6.0, 15.0),
        Vec3::new(16.0, 3.0, 11.0),
    ])
    .to_curve()
    .expect("five points make a curve");
    commands.spawn((
        Dolly,
        VirtualCamera::new(0),
        Projection::Perspective(default()),
        CameraRig::new(Spring::smooth()),
        CameraTargets::single(player),
        CameraRail::new(rail).with_spring(Spring::gentle()),
    ));
    commands.spawn((
        Camera3d::default(),
        // No tonemapping LUTs are built into this example's Bevy features.
        Tonemapping::None,
        CameraBlend::new(Spring::smooth()),
    ));
    commands.spawn((
        Hud,
        Text::new(""),
        TextFont::from_font_size(18.0),
        TextColor(Color::srgb(0.05, 0.07, 0.12)),
        BackgroundColor(Color::srgba(1.0, 1.0, 1.0, 0.75)),
        Node {
            position_type: PositionType::Absolute,
            top: Val::Px(12.0),
            left: Val::Px(14.0),
            padding: UiRect::all(Val::Px(6.0)),
            ..default()
        },
    ));
}

/// The player walks a slow figure eight through the ring of pillars.
fn walk(time: Res<Time>, mut player: Single<&mut Transform, With<Player>>) {
    let t = time.elapsed_secs() * 0.35;
    player.translation = Vec3::new(5.0 * t.cos(), 0.95, 3.0 * (2.0 * t).sin());
}

/// Mouse drag orbits, the wheel zooms; during the tour the camera turns slowly on its own.
fn orbit_input(
    time: Res<Time>,
    tour: Res<Tour>,
    buttons: Res<ButtonInput<MouseButton>>,
    motion: Res<AccumulatedMouseMotion>,
    scroll: Res<AccumulatedMouseScroll>,
    mut orbit: Single<&mut OrbitRig, With<OrbitShot>>,
) {
    if tour.is_running() {
        orbit.rotate(Vec2::new(0.5 * time.delta_secs(), 0.0));
        return;
    }
    if buttons.pressed(MouseButton::Left) && motion.delta != Vec2::ZERO {
        orbit.rotate(-motion.delta * 0.005);
    }
    if scroll.delta.y != 0.0 {
        orbit.zoom_by((-scroll.delta.y * 0.1).exp());
    }
}

/// Tab (or the tour: from 3.5 s to 5.5 s) raises the dolly above the orbit.
fn switch_shot(
    tour: Res<Tour>,
    keys: Res<ButtonInput<KeyCode>>,
    mut dolly: Single<&mut VirtualCamera, With<Dolly>>,
) {
    let wanted = match tour.time() {
        Some(t) if (3.5..5.5).contains(&t) => 2,
        Some(_) => 0,
        None if keys.just_pressed(KeyCode::Tab) => 2 - dolly.priority,
        None => dolly.priority,
    };
    if dolly.priority != wanted {
        dolly.priority = wanted;
    }
}

/// The guides' markers sized for a scene in metres.
fn guides_in_metres(mut store: ResMut<GizmoConfigStore>) {
    store.config_mut::<CameraRigGizmos>().1.size = 0.15;
}

/// The tour shows the guides once it is back on the orbit.
fn show_guides(tour: Res<Tour>, mut store: ResMut<GizmoConfigStore>) {
    if tour.passed(5.6) {
        store.config_mut::<CameraRigGizmos>().0.enabled = true;
    }
}

fn hud(
    mut text: Single<&mut Text, With<Hud>>,
    orbit: Single<(Entity, &RigMotion), With<OrbitShot>>,
    blend: Single<&BlendTrack>,
    tour: Res<Tour>,
) {
    let (orbit_shot, motion) = *orbit;
    let shot = if blend.shot() == Some(orbit_shot) {
        "orbit"
    } else {
        "dolly"
    };
    let clearance = motion.clearance();
    text.0 = format!(
        "{}\nshot: {shot} (Tab)   D: camera guides\nyaw {:.2} rad  pitch {:.2} rad  distance {:.1}\nclearance {:.1} %{}",
        if tour.is_running() {
            "scripted tour (move the mouse or press a key)"
        } else {
            "drag to orbit, scroll to zoom"
        },
        motion.orbit().x,
        motion.orbit().y,
        motion.orbit().z,
        clearance * 100.0,
        if clearance < 0.99 {
            ": pulled in front of a pillar"
        } else {
            ""
        },
    );
}
