//! A ship follows the cursor on a spring and turns, on a second spring, to face where it is
//! going. Move the mouse fast and change direction: every retarget keeps the ship's momentum,
//! so it swings round in an arc instead of stopping and restarting.
//!
//! Until the mouse moves, the ship chases waypoints on its own.
//!
//! ```text
//! cargo run --example follow
//! ```

use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::{SpringMotion, SpringSystems};

/// Waypoints for when there is no cursor (milliseconds per waypoint, then the points).
const AUTOPILOT_PERIOD_MS: u128 = 900;
const WAYPOINTS: [Vec2; 6] = [
    Vec2::new(-380.0, 160.0),
    Vec2::new(320.0, 200.0),
    Vec2::new(-100.0, -220.0),
    Vec2::new(420.0, -120.0),
    Vec2::new(-420.0, -60.0),
    Vec2::new(80.0, 240.0),
];

#[derive(Component)]
struct Ship;

/// Whether the mouse has moved yet: until then the autopilot steers.
#[derive(Resource, Default)]
struct CursorMoved(bool);

/// Where the ship has been, for the trail.
#[derive(Component, Default)]
struct Trail(Vec<Vec2>);

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: follow the cursor".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            SpringPlugins::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.05, 0.06, 0.09)))
        .init_resource::<CursorMoved>()
        .add_systems(Startup, setup)
        .add_systems(Update, (steer, face_travel).chain())
        .add_systems(PostUpdate, draw.after(SpringSystems))
        .run();
}

fn setup(mut commands: Commands) {
    commands.spawn(Camera2d);
    commands
        .spawn((
            Ship,
            Trail::default(),
            Sprite::from_color(Color::srgb(0.35, 0.75, 0.95), Vec2::new(56.0, 22.0)),
            Transform::default(),
            // A lively position spring and a quicker, critically damped heading.
            TranslationSpring::new(
                Spring::from_natural_frequency(5.0, 0.45).unwrap(),
                Vec3::ZERO,
            ),
            RotationSpring::new(
                Spring::from_natural_frequency(12.0, 1.0).unwrap(),
                Quat::IDENTITY,
            ),
        ))
        .with_child((
            // The nose, so the heading is visible.
            Sprite::from_color(Color::srgb(0.95, 0.85, 0.4), Vec2::new(16.0, 10.0)),
            Transform::from_xyz(30.0, 0.0, 0.1),
        ));
    commands.spawn((
        Text::new(
            "move the mouse: the ship springs to the cursor and turns to face its travel\n\
             retargeting keeps momentum (exact spring steps, any frame rate)",
        ),
        TextFont::from_font_size(16.0),
        TextColor(Color::srgb(0.75, 0.78, 0.85)),
        Node {
            position_type: PositionType::Absolute,
            top: Val::Px(12.0),
            left: Val::Px(14.0),
            ..default()
        },
    ));
}

/// The target: the cursor once the mouse has moved, the autopilot's waypoint until then.
fn steer(
    time: Res<Time>,
    mut moved: ResMut<CursorMoved>,
    mut motion: MessageReader<bevy::input::mouse::MouseMotion>,
    window: Single<&Window>,
    camera: Single<(&Camera, &GlobalTransform)>,
    mut ship: Single<&mut TranslationSpring, With<Ship>>,
) {
    moved.0 |= motion.read().count() > 0;
    let (camera, camera_transform) = *camera;
    let cursor = window
        .cursor_position()
        .filter(|_| moved.0)
        .and_then(|cursor| camera.viewport_to_world_2d(camera_transform, cursor).ok());
    let target = cursor.unwrap_or_else(|| {
        let period = time.elapsed().as_millis() / AUTOPILOT_PERIOD_MS;
        let index = usize::try_from(period).unwrap_or(0) % WAYPOINTS.len();
        WAYPOINTS[index]
    });
    if ship.target().truncate() != target {
        // Retargeting keeps the velocity: the ship bends toward the new point.
        ship.set_target(target.extend(0.0));
    }
}

/// Turn to face the direction of travel (while moving noticeably).
fn face_travel(mut ship: Single<(&SpringMotion<Translation>, &mut RotationSpring), With<Ship>>) {
    let (motion, rotation) = &mut *ship;
    let velocity = motion.velocity().truncate();
    if velocity.length() > 40.0 {
        let heading = Quat::from_rotation_z(velocity.to_angle());
        if rotation.target() != heading {
            rotation.set_target(heading);
        }
    }
}

fn draw(
    mut gizmos: Gizmos,
    mut ship: Single<
        (
            &Transform,
            &TranslationSpring,
            &SpringMotion<Translation>,
            &mut Trail,
        ),
        With<Ship>,
    >,
) {
    let (transform, spring, motion, trail) = &mut *ship;
    trail.0.push(transform.translation.truncate());
    if trail.0.len() > 90 {
        trail.0.remove(0);
    }
    gizmos.linestrip_2d(trail.0.iter().copied(), Color::srgba(0.35, 0.75, 0.95, 0.5));
    gizmos.circle_2d(
        spring.target().truncate(),
        10.0,
        Color::srgb(0.95, 0.85, 0.4),
    );
    // The velocity the spring carries, as an arrow.
    let from = transform.translation.truncate();
    gizmos.arrow_2d(
        from,
        from + motion.velocity().truncate() * 0.15,
        Color::srgb(0.9, 0.4, 0.5),
    );
}
