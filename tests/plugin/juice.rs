//! Juice: punch, shake (deterministic, frame-rate independent, on top of a follower) and squash
//! & stretch (volume kept).

use bevy::prelude::*;
use bevy_sprung::prelude::*;

use crate::harness::{app, run};

/// A punch swings the spring out by the distance asked for, for every preset, and it returns.
#[test]
fn punch_swings_out_by_the_displacement() {
    for spring in [
        Spring::gentle(),
        Spring::wobbly(),
        Spring::stiff(),
        Spring::slow(),
        Spring::smooth(),
        Spring::snappy(),
        Spring::bouncy(),
    ] {
        let mut app = app(1000);
        let entity = app
            .world_mut()
            .spawn((Transform::default(), ScaleSpring::new(spring, Vec3::ONE)))
            .id();
        run(&mut app, 2);
        app.world_mut()
            .get_mut::<ScaleSpring>(entity)
            .unwrap()
            .punch(Vec3::new(0.3, -0.2, 0.0));
        let mut peak = Vec3::ONE;
        for _ in 0..5000 {
            app.update();
            let scale = app.world().get::<Transform>(entity).unwrap().scale;
            if (scale.x - 1.0).abs() > (peak.x - 1.0).abs() {
                peak = scale;
            }
        }
        // Sampled at 1 ms: the peak is met to the sampling's resolution.
        assert!((peak.x - 1.3).abs() < 2e-3, "{spring:?}: {peak}");
        assert!((peak.y - 0.8).abs() < 2e-3, "{spring:?}: {peak}");
        assert_eq!(peak.z, 1.0);
        assert_eq!(
            app.world().get::<Transform>(entity).unwrap().scale,
            Vec3::ONE
        );
    }
}

const MAX: Vec3 = Vec3::new(12.0, 8.0, 0.0);

/// Records the shake's offset at `samples` times (seconds), stepping at `fps`.
fn shake_path(fps: u32, seed: u64, samples: &[f64]) -> Vec<(Vec3, Quat)> {
    let mut app = app(fps);
    let base = Vec3::new(1000.0, -500.0, 3.0);
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_translation(base),
            Shake::new(seed)
                .with_max_translation(MAX)
                .with_max_rotation(Vec3::new(0.0, 0.0, 0.05))
                .with_decay(0.8),
        ))
        .id();
    run(&mut app, 1); // dt = 0
    app.world_mut()
        .get_mut::<Shake>(entity)
        .unwrap()
        .add_trauma(1.0);
    let mut path = Vec::new();
    let mut frames = 0u32;
    for &t in samples {
        while f64::from(frames) / f64::from(fps) < t - 1e-9 {
            app.update();
            frames += 1;
        }
        let transform = app.world().get::<Transform>(entity).unwrap();
        path.push((transform.translation - base, transform.rotation));
    }
    // Calm again: back exactly where it was.
    run(&mut app, 2 * fps);
    let transform = app.world().get::<Transform>(entity).unwrap();
    assert_eq!(transform.translation, base);
    assert_eq!(transform.rotation, Quat::IDENTITY);
    path
}

/// The same seed gives the same shake at 30, 60, 144 and 240 fps (to rounding), within its
/// amplitude; another seed gives another shake.
#[test]
fn shake_is_deterministic_and_frame_rate_independent() {
    // Times on every frame rate's grid.
    let samples: Vec<f64> = (1..=7).map(|k| f64::from(k) / 6.0).collect();
    let reference = shake_path(240, 7, &samples);
    #[expect(clippy::cast_possible_truncation, reason = "a gain in f32")]
    let gain = |t: f64| (1.0 - 0.8 * t).max(0.0).powi(2) as f32;
    let mut largest = 0.0f32;
    for (&(offset, _), &t) in reference.iter().zip(&samples) {
        assert!(
            offset.x.abs() <= MAX.x * gain(t) * 1.0001,
            "{offset} at {t}"
        );
        assert!(
            offset.y.abs() <= MAX.y * gain(t) * 1.0001,
            "{offset} at {t}"
        );
        largest = largest.max(offset.x.abs());
    }
    assert!(largest > 0.2 * MAX.x, "it shakes: {largest}");
    for fps in [30, 60, 144] {
        for ((offset, tilt), (expected, expected_tilt)) in
            shake_path(fps, 7, &samples).into_iter().zip(&reference)
        {
            assert!(
                offset.distance(*expected) < 1e-3,
                "{fps} fps: {offset} vs {expected}"
            );
            let (tilt, expected_tilt) = (tilt.to_scaled_axis(), expected_tilt.to_scaled_axis());
            assert!(
                tilt.distance(expected_tilt) < 2e-5,
                "{fps} fps: {tilt} vs {expected_tilt}"
            );
        }
    }
    let other = shake_path(240, 8, &samples);
    assert!(
        other
            .iter()
            .zip(&reference)
            .any(|(a, b)| a.0.distance(b.0) > 1.0),
        "another seed, another shake"
    );
}

/// A camera that follows a moving target and shakes ends exactly where its twin without a shake
/// does: the follow never sees the shake.
#[test]
fn shake_adds_on_top_of_a_follower() {
    let mut app = app(60);
    let target = app.world_mut().spawn(Transform::default()).id();
    let camera = |shake: bool| {
        let mut camera = (
            Transform::from_xyz(0.0, 2.0, 10.0),
            TranslationSpring::new(Spring::smooth(), Vec3::new(0.0, 2.0, 10.0)),
            SpringFollow::new(target, Vec3::new(0.0, 2.0, 10.0)),
        );
        camera.0.translation.x = 0.0;
        (
            camera,
            shake.then(|| Shake::new(1).with_max_translation(Vec3::splat(0.5))),
        )
    };
    let (plain, _) = camera(false);
    let plain = app.world_mut().spawn(plain).id();
    let (shaken, shake) = camera(true);
    let shaken = app.world_mut().spawn((shaken, shake.unwrap())).id();
    run(&mut app, 1);
    app.world_mut()
        .get_mut::<Shake>(shaken)
        .unwrap()
        .add_trauma(1.0);
    let mut differed = false;
    for frame in 0..150 {
        app.world_mut()
            .get_mut::<Transform>(target)
            .unwrap()
            .translation
            .x = 0.05 * frame as f32;
        app.update();
        let a = app.world().get::<Transform>(plain).unwrap().translation;
        let b = app.world().get::<Transform>(shaken).unwrap().translation;
        differed |= a.distance(b) > 0.01;
    }
    assert!(differed, "it shook");
    assert_eq!(
        app.world().get::<Transform>(plain).unwrap().translation,
        app.world().get::<Transform>(shaken).unwrap().translation
    );
}

/// Stretched along the motion, volume (area) kept every frame, squashed by an impact to the
/// factor asked for, and back to the base scale at rest.
#[test]
fn squash_and_stretch_keep_volume() {
    for conserve in [Conserve::Volume, Conserve::Area] {
        let mut app = app(240);
        let entity = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::snappy(), Vec3::new(0.0, 400.0, 0.0)),
                SquashStretch::new(0.002, 1.5).conserving(conserve),
            ))
            .id();
        let mut longest = 1.0f32;
        for _ in 0..720 {
            app.update();
            let scale = app.world().get::<Transform>(entity).unwrap().scale;
            let kept = match conserve {
                Conserve::Volume => scale.x * scale.y * scale.z,
                Conserve::Area => {
                    assert_eq!(scale.z, 1.0);
                    scale.x * scale.y
                }
            };
            assert!((kept - 1.0).abs() < 1e-5, "{conserve:?}: {scale}");
            assert!(scale.y <= 1.5 * 1.2, "limited: {scale}");
            longest = longest.max(scale.y);
        }
        assert!(longest > 1.1, "{conserve:?}: stretched along y: {longest}");
        assert_eq!(
            app.world().get::<Transform>(entity).unwrap().scale,
            Vec3::ONE
        );

        // A landing: squashed to 0.7 along y at the peak.
        app.world_mut()
            .get_mut::<SquashStretch>(entity)
            .unwrap()
            .impact(Vec3::Y, 0.7);
        let mut flattest = 1.0f32;
        for _ in 0..720 {
            app.update();
            flattest = flattest.min(app.world().get::<Transform>(entity).unwrap().scale.y);
        }
        assert!((flattest - 0.7).abs() < 2e-3, "{conserve:?}: {flattest}");
        assert_eq!(
            app.world().get::<Transform>(entity).unwrap().scale,
            Vec3::ONE
        );
    }
}

/// A body moved by gameplay (no translation spring) at a steady 300 units/s along x, child of
/// a parent that also moves, carried 1e5 units in one frame (a respawn): told with
/// `TargetWarped`, or caught by the teleport distance, the jump does not read as speed and the
/// stretch stays where the steady motion holds it. Untold and uncaught, the jump is a frame at
/// the stretch limit and the body visibly widens: what every case did before the fix.
#[test]
fn a_teleport_does_not_stretch_a_squashed_body() {
    #[derive(Component)]
    struct Mover;
    #[derive(Resource, Default)]
    struct Jump(bool, bool);
    fn walk(
        time: Res<Time>,
        mut movers: Query<(Entity, &mut Transform, Has<SquashStretch>), With<Mover>>,
        mut jump: ResMut<Jump>,
        mut commands: Commands,
    ) {
        for (entity, mut transform, squashed) in &mut movers {
            transform.translation.x += 150.0 * time.delta_secs();
            if squashed && core::mem::take(&mut jump.0) {
                let delta = Vec3::new(1e5, 0.0, 0.0);
                transform.translation += delta;
                if jump.1 {
                    commands.trigger(TargetWarped { entity, delta });
                }
            }
        }
    }
    for fps in [30, 60, 144] {
        for (told, distance) in [
            (true, f32::INFINITY),
            (false, 1000.0),
            (false, f32::INFINITY),
        ] {
            let mut app = app(fps);
            app.init_resource::<Jump>().add_systems(Update, walk);
            let parent = app.world_mut().spawn((Transform::default(), Mover)).id();
            let body = app
                .world_mut()
                .spawn((
                    Transform::default(),
                    Mover,
                    SquashStretch::new(0.001, 1.5).with_teleport_distance(distance),
                    ChildOf(parent),
                ))
                .id();
            run(&mut app, 2 * fps);
            let steady = app.world().get::<Transform>(body).unwrap().scale.x;
            // 300 units/s in the world: 1.3× along x, reached and held.
            assert!((steady - 1.3).abs() < 1e-3, "{fps} fps: {steady}");
            app.world_mut().resource_mut::<Jump>().0 = true;
            app.world_mut().resource_mut::<Jump>().1 = told;
            let mut widest = steady;
            for _ in 0..fps {
                app.update();
                widest = widest.max(app.world().get::<Transform>(body).unwrap().scale.x);
            }
            if told || distance.is_finite() {
                assert!(
                    widest - steady < 1e-3,
                    "{fps} fps, told {told}, distance {distance}: stretched to {widest}"
                );
            } else {
                assert!(
                    widest - steady > 5e-3,
                    "{fps} fps: the untold jump reads as speed: {widest}"
                );
            }
        }
    }
}
