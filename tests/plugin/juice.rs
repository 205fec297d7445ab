//! Juice: punch, shake (deterministic, frame-rate independent, on top of a follower) and squash
//! & stretch (volume kept).

use core::time::Duration;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::juice::Conserve;
use bevy_sprung::prelude::*;
use bevy_sprung::tracking::TargetWarped;

use crate::harness::{app, frame, run};

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

/// A squashed body without a translation spring, walking at 300 units/s in the world as the
/// child of a parent that also moves, carried far in one frame (a respawn): told with
/// `TargetWarped`, or caught by the teleport distance, the jump does not read as speed and the
/// stretch stays within what the steady walk already showed. Untold and uncaught, the jump is a
/// frame at the stretch limit and the body widens, by more than twice the bound: what every case
/// did before the fix.
/// At 30 to 360 fps, in a world 1e5 units from its origin, and with the jump in a 1 s hitch.
#[test]
fn a_teleport_does_not_stretch_a_squashed_body() {
    let at_origin = [30, 60, 144, 360].map(|fps| Walk {
        fps,
        origin: 0.0,
        hitch: false,
    });
    let others = [
        // A big world: f32 positions are 1/128 apart here.
        Walk {
            fps: 60,
            origin: 1e5,
            hitch: false,
        },
        Walk {
            fps: 60,
            origin: 0.0,
            hitch: true,
        },
    ];
    for walk in at_origin.into_iter().chain(others) {
        for (told, distance) in [
            (true, f32::INFINITY),
            (false, 1000.0),
            (false, f32::INFINITY),
        ] {
            let case = format!("{walk:?}, told {told}, distance {distance}");
            let (steady, widest) = walk.jump_by_1e5(told, distance);
            // 300 units/s in the world: 1.3× along x, reached and held.
            assert!((steady - 1.3).abs() < 1e-3, "{case}: {steady}");
            if told || distance.is_finite() {
                assert!(widest - steady < 1e-3, "{case}: stretched to {widest}");
            } else {
                // The control: the bound above tells the cases apart (at 360 fps the deformation
                // has the least time to answer the one-frame spike).
                assert!(
                    widest - steady > 2e-3,
                    "{case}: the untold jump reads as speed: {widest}"
                );
            }
        }
    }
}

/// A squashed body walking with its parent, for [`a_teleport_does_not_stretch_a_squashed_body`].
#[derive(Debug)]
struct Walk {
    fps: u32,
    origin: f32,
    /// The jump's frame lasts a second.
    hitch: bool,
}

#[derive(Component)]
struct Mover;

#[derive(Resource, Default)]
struct Jump {
    now: bool,
    told: bool,
    delta: Vec3,
}

impl Walk {
    /// The widest x scale over the steady walk's last second, and over the second after a jump
    /// of 1e5, told with `TargetWarped` or not, with a teleport distance.
    fn jump_by_1e5(&self, told: bool, distance: f32) -> (f32, f32) {
        let mut app = app(self.fps);
        app.init_resource::<Jump>().add_systems(Update, walk);
        let parent = app
            .world_mut()
            .spawn((Transform::from_xyz(self.origin, 0.0, 0.0), Mover))
            .id();
        let body = app
            .world_mut()
            .spawn((
                Transform::default(),
                Mover,
                SquashStretch::new(0.001, 1.5).with_teleport_distance(distance),
                ChildOf(parent),
            ))
            .id();
        let scale = |app: &App| app.world().get::<Transform>(body).unwrap().scale.x;
        run(&mut app, 2 * self.fps);
        let mut steady = scale(&app);
        for _ in 0..self.fps {
            app.update();
            steady = steady.max(scale(&app));
        }
        *app.world_mut().resource_mut::<Jump>() = Jump {
            now: true,
            told,
            delta: Vec3::new(1e5, 0.0, 0.0),
        };
        let mut widest = steady;
        for i in 0..self.fps {
            let length = if self.hitch && i == 0 {
                Duration::from_secs(1)
            } else {
                frame(self.fps)
            };
            app.insert_resource(TimeUpdateStrategy::ManualDuration(length));
            app.update();
            widest = widest.max(scale(&app));
        }
        (steady, widest)
    }
}

/// Moves every [`Mover`] at 150 units/s and makes the pending [`Jump`].
fn walk(
    time: Res<Time>,
    mut movers: Query<(Entity, &mut Transform, Has<SquashStretch>), With<Mover>>,
    mut jump: ResMut<Jump>,
    mut commands: Commands,
) {
    for (entity, mut transform, squashed) in &mut movers {
        transform.translation.x += 150.0 * time.delta_secs();
        if squashed && core::mem::take(&mut jump.now) {
            transform.translation += jump.delta;
            if jump.told {
                commands.trigger(TargetWarped {
                    entity,
                    delta: jump.delta,
                });
            }
        }
    }
}

/// A squashed body handed from its translation spring back to its own position, with the
/// spring removed at rest or mid-flight: the estimate picks up where the spring left the body,
/// so neither the distance the spring carried it nor a teleport told while the spring moved it
/// reads as speed, and the frozen motion of the removed spring is not read at all: the body,
/// now still, relaxes to its own shape.
#[test]
fn a_squash_hands_over_from_a_removed_spring_without_a_jump() {
    for fps in [30, 60, 144, 360] {
        for in_flight in [false, true] {
            let mut app = app(fps);
            let body = app
                .world_mut()
                .spawn((Transform::default(), SquashStretch::new(0.001, 1.5)))
                .id();
            let shape = |app: &App| {
                let scale = app.world().get::<Transform>(body).unwrap().scale;
                (scale - Vec3::ONE).abs().max_element()
            };
            // Still and spring-less: the estimate knows the body at the origin.
            run(&mut app, fps / 2);
            app.world_mut()
                .entity_mut(body)
                .insert(TranslationSpring::new(
                    Spring::snappy(),
                    Vec3::new(500.0, 0.0, 0.0),
                ));
            run(&mut app, fps / 10);
            app.world_mut().trigger(TargetWarped {
                entity: body,
                delta: Vec3::new(-2e4, 0.0, 0.0),
            });
            if in_flight {
                app.update();
                assert!(shape(&app) > 1e-2, "{fps} fps: not stretched in flight");
            } else {
                run(&mut app, 3 * fps);
                assert!(shape(&app) < 1e-4, "{fps} fps: at rest {}", shape(&app));
            }
            app.world_mut()
                .entity_mut(body)
                .remove::<TranslationSpring>();
            let mut widest = 0.0_f32;
            for _ in 0..fps {
                app.update();
                widest = widest.max(shape(&app));
            }
            if !in_flight {
                assert!(
                    widest < 1e-4,
                    "{fps} fps: the hand-over stretched it by {widest}"
                );
            }
            run(&mut app, 2 * fps);
            assert!(
                shape(&app) < 1e-4,
                "{fps} fps, in flight {in_flight}: {}",
                shape(&app)
            );
        }
    }
}
