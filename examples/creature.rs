//! Secondary motion and stacked motions: a creature that chases the cursor.
//!
//! - **Spring chains**: its tail and antennae are plain sprite hierarchies with a
//!   [`SpringChain`]: they trail when it speeds up, sway when it stops and droop under gravity.
//! - **Layers**: its scale carries three motions at once, each with its own spring — a
//!   [`SquashStretch`] along its velocity, a hover swell while the cursor is on it, and a
//!   punch (Space) — on top of its base scale, and its rotation a punch wobble: none bends the
//!   others ([`LayerSpring`]).
//! - **Inertia**: a right click flings it toward the cursor; it coasts to a stop exactly
//!   `v/deceleration` away, inside the window ([`Inertia`]).
//!
//! The debug overlay ([`SpringDebugPlugin`]) draws the chains' bones around their rest pose
//! and the body's spring: its target, velocity, the exact path it will take and the seconds
//! until it settles. D hides or shows it.
//!
//! Without a mouse the example plays a scripted tour (the "cursor" draws loops, hovers, punches
//! and flings), so CI screenshots show it.
//!
//! ```text
//! cargo run --example creature
//! ```

use bevy::gizmos::config::GizmoConfigStore;
use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use bevy_sprung::chain::SpringChain;
use bevy_sprung::debug::{ChainGizmos, SpringDebugPlugin, SpringGizmos};
use bevy_sprung::inertia::{DragBounds, Inertia};
use bevy_sprung::juice::Conserve;
use bevy_sprung::layers::{LayerSpring, SpringLayerPlugin};
use bevy_sprung::prelude::*;

#[path = "support/tour.rs"]
mod tour;

use tour::{Tour, TourPlugin};

/// The layers the creature's scale and rotation carry besides its squash.
#[derive(TypePath)]
struct Hover;
#[derive(TypePath)]
struct Punch;

#[derive(Component)]
struct Creature;

/// Where the cursor is (the mouse's, or the tour's), and until when the creature coasts.
#[derive(Resource, Default)]
struct Cursor {
    at: Vec2,
    coasting_until: f32,
}

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins,
            SpringPlugins::default(),
            SpringDebugPlugin::default().toggled_by(KeyCode::KeyD),
            TourPlugin::default(),
        ))
        .add_plugins((
            SpringLayerPlugin::<Scale, Hover>::default(),
            SpringLayerPlugin::<Scale, Punch>::default(),
            SpringLayerPlugin::<Rotation, Punch>::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.10, 0.11, 0.15)))
        .init_resource::<Cursor>()
        .add_systems(Startup, (spawn, overlay_in_pixels))
        .add_systems(Update, (read_cursor, chase, hover, punch, fling).chain())
        .run();
}

/// The overlay's markers sized for a scene in pixels.
fn overlay_in_pixels(mut store: ResMut<GizmoConfigStore>) {
    store.config_mut::<ChainGizmos>().1.size = 3.0;
    store.config_mut::<SpringGizmos>().1.size = 6.0;
}

/// A chain of `count` sprites of `size`, each `step` from the last, the first under `parent`.
fn spawn_chain(
    commands: &mut Commands,
    parent: Entity,
    at: Vec3,
    step: Vec3,
    count: usize,
    size: Vec2,
    chain: SpringChain,
) {
    let color = Color::srgb(0.95, 0.55, 0.35);
    let mut joint = commands
        .spawn((
            Sprite::from_color(color, size),
            Transform::from_translation(at),
            chain,
        ))
        .id();
    commands.entity(parent).add_child(joint);
    for index in 1..count {
        let shrink = 1.0 - index as f32 / (count as f32 + 2.0);
        let next = commands
            .spawn((
                Sprite::from_color(color, size * shrink),
                Transform::from_translation(step),
            ))
            .id();
        commands.entity(joint).add_child(next);
        joint = next;
    }
}

fn spawn(mut commands: Commands) {
    commands.spawn(Camera2d);
    let body = commands
        .spawn((
            Creature,
            Sprite::from_color(Color::srgb(0.98, 0.66, 0.38), Vec2::splat(90.0)),
            Transform::default(),
            TranslationSpring::new(Spring::gentle(), Vec3::ZERO),
            SquashStretch::new(0.0008, 1.35).conserving(Conserve::Area),
            LayerSpring::<Scale, Hover>::new(Spring::bouncy(), Vec3::ZERO),
            LayerSpring::<Scale, Punch>::new(Spring::wobbly(), Vec3::ZERO),
            LayerSpring::<Rotation, Punch>::new(Spring::wobbly(), Vec3::ZERO),
            Inertia::new(2.5).bounded(DragBounds {
                min: Vec3::new(-560.0, -300.0, 0.0),
                max: Vec3::new(560.0, 300.0, 0.0),
                give: 0.0,
            }),
        ))
        .id();
    for x in [-20.0, 20.0] {
        let eye = commands
            .spawn((
                Sprite::from_color(Color::WHITE, Vec2::splat(16.0)),
                Transform::from_xyz(x, 14.0, 1.0),
            ))
            .id();
        commands.entity(body).add_child(eye);
    }
    let tail = SpringChain::new(Spring::wobbly())
        .with_gravity(Vec3::new(0.0, -900.0, 0.0))
        .planar();
    spawn_chain(
        &mut commands,
        body,
        Vec3::new(-50.0, -20.0, -1.0),
        Vec3::new(-24.0, 0.0, 0.0),
        9,
        Vec2::new(26.0, 18.0),
        tail,
    );
    for x in [-22.0, 22.0] {
        let antenna = SpringChain::new(Spring::bouncy())
            .with_gravity(Vec3::new(0.0, -600.0, 0.0))
            .planar();
        spawn_chain(
            &mut commands,
            body,
            Vec3::new(x, 48.0, -1.0),
            Vec3::new(x * 0.3, 18.0, 0.0),
            5,
            Vec2::new(8.0, 18.0),
            antenna,
        );
    }
}

/// The tour's cursor (loops, then a rest on the creature) while it runs; then the mouse's.
fn read_cursor(
    tour: Res<Tour>,
    window: Single<&Window, With<PrimaryWindow>>,
    camera: Single<(&Camera, &GlobalTransform)>,
    mut cursor: ResMut<Cursor>,
) {
    if let Some(t) = tour.time() {
        cursor.at = if t < 3.0 {
            Vec2::new((t * 2.1).sin() * 380.0, (t * 4.2).sin() * 170.0)
        } else {
            Vec2::new(-250.0, 120.0)
        };
        return;
    }
    let (camera, placed) = *camera;
    if let Some(at) = window
        .cursor_position()
        .and_then(|at| camera.viewport_to_world_2d(placed, at).ok())
    {
        cursor.at = at;
    }
}

/// The creature chases the cursor, unless it coasts from a fling.
fn chase(
    time: Res<Time>,
    cursor: Res<Cursor>,
    mut creature: Single<&mut TranslationSpring, With<Creature>>,
) {
    if time.elapsed_secs() >= cursor.coasting_until {
        creature.set_target_if_neq(cursor.at.extend(0.0));
    }
}

/// The cursor on the creature swells it by 20 % (the logarithm of the factor: scale layers
/// multiply).
fn hover(
    cursor: Res<Cursor>,
    creature: Single<(&Transform, &mut LayerSpring<Scale, Hover>), With<Creature>>,
) {
    let (transform, mut swell) = creature.into_inner();
    let on = transform.translation.truncate().distance(cursor.at) < 60.0;
    swell.set_target_if_neq(Vec3::splat(if on { 1.2_f32.ln() } else { 0.0 }));
}

/// Space, or every 1.5 s of the tour: a punch of the scale and a wobble of the rotation.
fn punch(
    time: Res<Time>,
    keys: Res<ButtonInput<KeyCode>>,
    tour: Res<Tour>,
    mut creature: Single<
        (
            &mut LayerSpring<Scale, Punch>,
            &mut LayerSpring<Rotation, Punch>,
        ),
        With<Creature>,
    >,
) {
    let tour_punch = tour
        .time()
        .is_some_and(|t| t > 0.5 && (t % 1.5) < time.delta_secs());
    if keys.just_pressed(KeyCode::Space) || tour_punch {
        creature.0.punch(Vec3::splat(0.25));
        creature.1.punch(Vec3::new(0.0, 0.0, 0.35));
    }
}

/// A right click (or the tour at 3.2 s) flings the creature toward the cursor.
fn fling(
    time: Res<Time>,
    buttons: Res<ButtonInput<MouseButton>>,
    tour: Res<Tour>,
    mut cursor: ResMut<Cursor>,
    creature: Single<(&Transform, &mut Inertia), With<Creature>>,
) {
    let t = time.elapsed_secs();
    if buttons.just_pressed(MouseButton::Right) || tour.passed(3.2) {
        let (transform, mut inertia) = creature.into_inner();
        let toward = (cursor.at - transform.translation.truncate()).normalize_or_zero();
        inertia.fling((toward * 1600.0).extend(0.0));
        cursor.coasting_until = t + 2.0;
    }
}
