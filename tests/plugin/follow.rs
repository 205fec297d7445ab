//! Camera smoothing: a follower over a target that moves in `FixedUpdate` at 64 Hz while frames
//! come at uneven rates.

use bevy::prelude::*;
use bevy_sprung::follow::TargetMotion;
use bevy_sprung::prelude::*;
use bevy_sprung::tracking::TargetWarped;

use crate::harness::{app, run_pattern};

/// Frame-time patterns (seconds), cycled: steady, alternating, bursty, irregular.
const PATTERNS: [&[f64]; 5] = [
    &[1.0 / 60.0],
    &[1.0 / 144.0, 1.0 / 30.0],
    &[0.004, 0.004, 0.004, 0.05],
    &[
        1.0 / 60.0,
        1.0 / 144.0,
        1.0 / 30.0,
        1.0 / 90.0,
        0.021,
        1.0 / 240.0,
        0.013,
    ],
    &[0.0151, 0.0173, 0.0162, 0.0149, 0.0188],
];

/// The target's speed, units per second.
const SPEED: Vec3 = Vec3::new(6.0, 0.0, -2.0);

/// Where the camera wants to be relative to the target.
const OFFSET: Vec3 = Vec3::new(0.0, 5.0, 10.0);

#[derive(Component)]
struct Player;

/// Gameplay: the player moves at a constant speed, one fixed step at a time.
fn move_player(time: Res<Time>, mut players: Query<&mut Transform, With<Player>>) {
    for mut transform in &mut players {
        transform.translation += SPEED * time.delta_secs();
    }
}

/// Runs 4 s of frames with `pattern` and returns, for each frame after the first 2.5 s, the
/// camera's offset from the target's continuous-time position `p₀ + v·t` (what the fixed steps
/// sample), minus the desired `OFFSET`.
fn camera_offsets(pattern: &[f64], motion: TargetMotion) -> (Vec<Vec3>, f32) {
    let mut app = app(60);
    app.insert_resource(Time::<Fixed>::from_hz(64.0))
        .add_systems(FixedUpdate, move_player);
    let player = app.world_mut().spawn((Player, Transform::default())).id();
    let spring = Spring::from_natural_frequency(4.0, 1.0).unwrap();
    let mut follow = SpringFollow::new(player, OFFSET);
    follow.motion = motion;
    app.world_mut().spawn((
        Transform::from_translation(OFFSET),
        TranslationSpring::new(spring, OFFSET),
        follow,
    ));
    let mut offsets = Vec::new();
    run_pattern(&mut app, pattern, 4.0, |app, t| {
        let seconds = app.world().resource::<Time<Virtual>>().elapsed_secs();
        if t > 2.5 {
            let mut cameras = app
                .world_mut()
                .query_filtered::<&Transform, With<SpringFollow>>();
            let camera = cameras.single(app.world()).unwrap().translation;
            let target = SPEED * seconds;
            offsets.push(camera - target - OFFSET);
        }
    });
    // The steady lag of a spring following a target moving at v is c·v/k, behind it.
    let lag = spring.damping() / spring.stiffness();
    (offsets, lag)
}

#[test]
fn camera_settles_at_the_steady_lag_without_jitter_under_uneven_frames() {
    for pattern in PATTERNS {
        let (offsets, lag) = camera_offsets(pattern, TargetMotion::FixedTimestep);
        let expected = -SPEED * lag;
        for (i, offset) in offsets.iter().enumerate() {
            assert!(
                offset.distance(expected) < 2e-4 * SPEED.length(),
                "{pattern:?}, frame {i}: offset {offset} vs steady lag {expected}"
            );
        }
        let jitter = offsets
            .windows(2)
            .map(|w| w[1].distance(w[0]))
            .fold(0.0_f32, f32::max);
        println!("{pattern:?}: largest frame-to-frame change {jitter:e}");
        assert!(
            jitter < 1e-4 * SPEED.length(),
            "{pattern:?}: frame-to-frame change {jitter}"
        );
    }
}

/// The control: sampling the same target once per frame (its displacement over the frame, as
/// if it moved every frame) sees it stand still in one frame and jump two fixed steps in the
/// next. Under uneven frames the camera then wanders around the steady lag by far more than
/// the tolerance above, so the test above can tell.
#[test]
fn sampling_a_fixed_update_target_per_frame_would_wobble() {
    for pattern in &PATTERNS[1..] {
        let (offsets, lag) = camera_offsets(pattern, TargetMotion::PerFrame);
        let expected = -SPEED * lag;
        let wobble = offsets
            .iter()
            .map(|offset| offset.distance(expected))
            .fold(0.0_f32, f32::max);
        println!("{pattern:?}, per-frame sampling: off the steady lag by up to {wobble:e}");
        assert!(
            wobble > 2e-3 * SPEED.length(),
            "{pattern:?}: expected a visible wobble, got {wobble}"
        );
    }
}

/// A target moved in `Update` is read after gameplay moved it: the camera follows it in the
/// same frame, and settles at the steady lag behind it.
#[test]
fn follows_a_target_moved_every_frame_without_a_frame_of_lag() {
    let mut app = app(60);
    app.add_systems(Update, move_player);
    let player = app.world_mut().spawn((Player, Transform::default())).id();
    let spring = Spring::from_natural_frequency(6.0, 1.0).unwrap();
    let camera = app
        .world_mut()
        .spawn((
            Transform::from_translation(OFFSET),
            TranslationSpring::new(spring, OFFSET),
            SpringFollow::new(player, OFFSET),
        ))
        .id();
    for _ in 0..240 {
        app.update();
    }
    let target = app.world().get::<Transform>(player).unwrap().translation;
    let position = app.world().get::<Transform>(camera).unwrap().translation;
    let lag = spring.damping() / spring.stiffness();
    assert!((position - target - OFFSET).distance(-SPEED * lag) < 1e-3);
}

/// A target two levels down a hierarchy whose root moves in `Update` (a weapon on a hand on a
/// player): it is followed at the same steady lag `c·v/k` as a root target, at every frame-time
/// pattern, not a frame (`v·dt`) behind it.
#[test]
fn follows_a_child_of_a_moving_root_without_a_frame_of_lag() {
    const LOCAL: Vec3 = Vec3::new(1.5, 0.5, 0.0);
    for pattern in PATTERNS {
        let mut app = app(60);
        app.add_systems(Update, move_player);
        // Root moved by gameplay, a rotated and scaled middle level, the followed leaf.
        let root = app.world_mut().spawn((Player, Transform::default())).id();
        let middle = Transform::from_xyz(0.0, 1.0, 0.0)
            .with_rotation(Quat::from_rotation_y(0.5))
            .with_scale(Vec3::splat(2.0));
        let middle = app.world_mut().spawn((middle, ChildOf(root))).id();
        let leaf = app
            .world_mut()
            .spawn((Transform::from_translation(LOCAL), ChildOf(middle)))
            .id();
        let spring = Spring::from_natural_frequency(6.0, 1.0).unwrap();
        let camera = app
            .world_mut()
            .spawn((
                Transform::from_translation(OFFSET),
                TranslationSpring::new(spring, OFFSET),
                SpringFollow::new(leaf, OFFSET),
            ))
            .id();
        let lag = spring.damping() / spring.stiffness();
        let mut worst: f32 = 0.0;
        run_pattern(&mut app, pattern, 5.0, |app, t| {
            if t > 3.5 {
                // Where the leaf is now: its ancestors' transforms as gameplay left them.
                let world = app.world();
                let place = |entity| *world.get::<Transform>(entity).unwrap();
                let target = place(root)
                    .mul_transform(place(middle))
                    .transform_point(LOCAL);
                let position = place(camera).translation;
                worst = worst.max((position - target - OFFSET).distance(-SPEED * lag));
            }
        });
        assert!(worst < 1e-3, "{pattern:?}: off the steady lag by {worst}");
    }
}

/// A target carried 1e4 units in one frame (a respawn), told with `TargetWarped` or caught by
/// the follower's teleport distance: the follower moves with it and stays at the steady lag,
/// instead of chasing it across the world.
#[test]
fn a_teleported_target_carries_the_follower() {
    const JUMP: Vec3 = Vec3::new(1e4, 0.0, -5e3);
    fn respawn(
        time: Res<Time>,
        mut players: Query<(Entity, &mut Transform), With<Player>>,
        mut commands: Commands,
    ) {
        let now = time.elapsed_secs();
        if now >= 3.0 && now - time.delta_secs() < 3.0 {
            for (player, mut transform) in &mut players {
                transform.translation += JUMP;
                commands.trigger(TargetWarped {
                    entity: player,
                    delta: JUMP,
                });
            }
        }
    }
    for told in [true, false] {
        let mut app = app(60);
        app.add_systems(Update, (move_player, respawn).chain());
        let player = app.world_mut().spawn((Player, Transform::default())).id();
        let spring = Spring::from_natural_frequency(6.0, 1.0).unwrap();
        let follow = if told {
            SpringFollow::new(player, OFFSET)
        } else {
            // Without the event the respawn still reaches the follower; only its distance tells.
            SpringFollow::new(player, OFFSET).with_teleport_distance(1000.0)
        };
        let camera = app
            .world_mut()
            .spawn((
                Transform::from_translation(OFFSET),
                TranslationSpring::new(spring, OFFSET),
                follow,
            ))
            .id();
        let lag = spring.damping() / spring.stiffness();
        let mut worst: f32 = 0.0;
        run_pattern(&mut app, PATTERNS[3], 5.0, |app, t| {
            if t > 2.0 {
                let target = app.world().get::<Transform>(player).unwrap().translation;
                let position = app.world().get::<Transform>(camera).unwrap().translation;
                worst = worst.max((position - target - OFFSET).distance(-SPEED * lag));
            }
        });
        // f32 at 1e4 resolves 1e-3.
        assert!(worst < 1e-2, "told {told}: off the steady lag by {worst}");
    }
}

/// Looking at the target: the rotation spring turns the follower toward it.
#[test]
fn looks_at_the_target() {
    let mut app = app(60);
    let player = app
        .world_mut()
        .spawn(Transform::from_xyz(3.0, 0.0, 0.0))
        .id();
    let camera = app
        .world_mut()
        .spawn((
            Transform::from_xyz(0.0, 5.0, 10.0),
            TranslationSpring::new(Spring::smooth(), Vec3::new(0.0, 5.0, 10.0)),
            RotationSpring::new(Spring::smooth(), Quat::IDENTITY),
            SpringFollow::new(player, Vec3::new(0.0, 5.0, 10.0)).looking_at(Vec3::ZERO),
        ))
        .id();
    for _ in 0..300 {
        app.update();
    }
    let transform = *app.world().get::<Transform>(camera).unwrap();
    let to_target = (Vec3::new(3.0, 0.0, 0.0) - transform.translation).normalize();
    assert!(
        transform.forward().dot(to_target) > 0.9999,
        "{:?}",
        transform.forward()
    );
}
