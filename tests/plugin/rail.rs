//! Camera rails: the analytic lag along a straight stretch, loops that wrap, places ahead and
//! driven, warps, blends, and the world changing under a rail, at 30 to 360 fps, uneven frames
//! and a 1 s hitch.

use std::f32::consts::{PI, TAU};

use bevy::math::cubic_splines::{CubicCardinalSpline, CubicCurve, CubicGenerator};
use bevy::prelude::*;

use bevy_sprung::camera::{
    BlendTrack, CameraBlend, CameraGoal, CameraRail, CameraTargets, RailAim, RailFollow,
    RailMotion, RigMotion, RigRail, VirtualCamera,
};
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringAsleep;

use crate::camera::{RATES, camera_app, move_player, patterns, tell_of_a_respawn, translation};
use crate::harness::run_pattern;

/// Where the straight rail runs: along x, 200 up and 500 back.
const RAIL_HEIGHT: f32 = 200.0;
const RAIL_DEPTH: f32 = 500.0;

/// A straight rail along x from `from` to `to` (thousands), through evenly spaced points:
/// Catmull-Rom runs along it at a constant speed, so distance along it is exact.
fn straight_rail(from: i32, to: i32, depth: f32) -> CubicCurve<Vec3> {
    let points = (from / 1000..=to / 1000)
        .map(|i| Vec3::new(i as f32 * 1000.0, RAIL_HEIGHT, depth))
        .collect::<Vec<_>>();
    CubicCardinalSpline::new_catmull_rom(points)
        .to_curve()
        .unwrap()
}

/// A closed ring of `radius` round the y axis, 100 up, through twelve points.
fn ring(radius: f32) -> CubicCurve<Vec3> {
    let points = (0..12).map(|i| {
        let angle = i as f32 * TAU / 12.0;
        Vec3::new(angle.cos() * radius, 100.0, angle.sin() * radius)
    });
    CubicCardinalSpline::new_catmull_rom(points)
        .to_curve_cyclic()
        .unwrap()
}

/// The patterns of [`patterns`], and one with a 1 s hitch every half second (Bevy steps a
/// quarter second of it).
fn patterns_and_hitch() -> Vec<Vec<f64>> {
    let mut all = patterns();
    let mut hitch = vec![1.0 / 60.0; 30];
    hitch.push(1.0);
    all.push(hitch);
    all
}

/// A 3D camera on `rail`, following the player.
fn rail_camera(app: &mut App, player: Entity, spring: Spring, rail: CameraRail) -> Entity {
    app.world_mut()
        .spawn((
            Camera3d::default(),
            CameraRig::new(Spring::from_natural_frequency(8.0, 1.0).unwrap()),
            CameraTargets::single(player),
            rail.with_spring(spring),
        ))
        .id()
}

/// The angle of `point` round the y axis.
fn angle_of(point: Vec3) -> f32 {
    point.z.atan2(point.x)
}

/// `angle` wrapped into `[-π, π)`.
fn wrapped(angle: f32) -> f32 {
    (angle + PI).rem_euclid(TAU) - PI
}

#[test]
fn a_target_moving_along_a_straight_stretch_is_followed_at_the_analytic_lag() {
    const SPEED: f32 = 240.0;
    let spring = Spring::from_natural_frequency(4.0, 1.0).unwrap();
    let lag = SPEED * spring.damping() / spring.stiffness();
    for pattern in patterns_and_hitch() {
        let (mut app, player) =
            camera_app(60, (800, 600), |t| Vec3::new(-1500.0 + SPEED * t, 0.0, 0.0));
        let rail = CameraRail::new(straight_rail(-5000, 5000, RAIL_DEPTH));
        let camera = rail_camera(&mut app, player, spring, rail);
        let (mut worst, mut worst_aim): (f32, f32) = (0.0, 0.0);
        run_pattern(&mut app, &pattern, 6.0, |app, elapsed| {
            let at = translation(app, camera);
            let player = translation(app, player);
            let expected = Vec3::new(player.x - lag, RAIL_HEIGHT, RAIL_DEPTH);
            if elapsed > 4.0 {
                worst = worst.max(at.distance(expected));
            }
            // Always on the rail, looking at the point the rig frames.
            assert!((at.y - RAIL_HEIGHT).abs() < 1e-3 && (at.z - RAIL_DEPTH).abs() < 1e-3);
            let focus = app.world().get::<RigMotion>(camera).unwrap().centre();
            let forward = app.world().get::<Transform>(camera).unwrap().forward();
            worst_aim = worst_aim.max(forward.angle_between(focus - at));
        });
        // Rounding at positions of a thousand units: a few thousandths.
        assert!(
            worst < 5e-3,
            "{pattern:?}: off the steady lag {lag} by {worst}"
        );
        assert!(worst_aim < 1e-3, "{pattern:?}: aims {worst_aim} rad off");
    }
}

#[test]
fn a_looped_rail_wraps_without_a_jump_the_same_at_every_frame_rate() {
    const RATE: f32 = 1.5;
    const RADIUS: f32 = 500.0;
    let spring = Spring::from_natural_frequency(4.0, 1.0).unwrap();
    let mut lags = Vec::new();
    for pattern in patterns_and_hitch() {
        // Round and round inside the ring, three and a half laps in ten seconds.
        let (mut app, player) = camera_app(60, (800, 600), |t| {
            let angle = RATE * t + 0.2;
            Vec3::new(angle.cos(), 0.0, angle.sin()) * 300.0
        });
        let rail = CameraRail::new(ring(RADIUS)).looped();
        let camera = rail_camera(&mut app, player, spring, rail);
        let mut last = None;
        let (mut last_time, mut worst_step, mut off_ring): (f64, f32, f32) = (0.0, 0.0, 0.0);
        let mut lag = 0.0;
        run_pattern(&mut app, &pattern, 10.0, |app, elapsed| {
            let at = translation(app, camera);
            off_ring = off_ring.max((at.xz().length() / RADIUS - 1.0).abs());
            let angle = angle_of(at);
            if let Some(last) = last {
                // Never faster than the target goes round (a critically damped camera does not
                // overshoot its speed): a wrap would jump a whole lap.
                #[expect(clippy::cast_possible_truncation, reason = "a frame's time")]
                let dt = (elapsed - last_time) as f32;
                let step = wrapped(angle - last).abs();
                worst_step = worst_step.max(step / (RATE * dt));
            }
            last = Some(angle);
            last_time = elapsed;
            lag = wrapped(angle_of(translation(app, player)) - angle);
        });
        assert!(off_ring < 3e-3, "{pattern:?}: {off_ring} off the ring");
        assert!(
            worst_step < 1.05,
            "{pattern:?}: a frame moved {worst_step} times the target's turn"
        );
        lags.push(lag);
    }
    // The steady lag along the rail: c·v/k of the arc, 0.75 rad of a true circle.
    let expected = RATE * spring.damping() / spring.stiffness();
    for (&lag, pattern) in lags.iter().zip(patterns_and_hitch()) {
        assert!((lag / expected - 1.0).abs() < 5e-3, "lag {lag}, {lags:?}");
        // On a bend the place nearest the target does not move at an exactly constant rate,
        // and each step takes it to: over a hitch's quarter second that is 2e-3 rad.
        let tolerance = if pattern.contains(&1.0) { 2e-3 } else { 2e-4 };
        assert!((lag - lags[0]).abs() < tolerance, "{pattern:?}: {lags:?}");
    }
}

#[test]
fn a_place_ahead_or_driven_is_where_the_camera_rests() {
    for fps in RATES {
        let (mut app, player) = camera_app(fps, (800, 600), |_| Vec3::new(300.0, 0.0, 0.0));
        let straight = straight_rail(-5000, 5000, RAIL_DEPTH);
        let ahead = CameraRail::new(straight.clone()).following(RailFollow::Ahead(150.0));
        let ahead = rail_camera(&mut app, player, Spring::smooth(), ahead);
        let behind = CameraRail::new(straight.clone()).following(RailFollow::Ahead(-150.0));
        let behind = rail_camera(&mut app, player, Spring::smooth(), behind);
        let driven = CameraRail::new(straight).following(RailFollow::Driven(0.25));
        let driven = rail_camera(&mut app, player, Spring::smooth(), driven);
        let looped = CameraRail::new(ring(500.0))
            .looped()
            .following(RailFollow::Driven(1.25))
            .aiming(RailAim::Along);
        let looped = rail_camera(&mut app, player, Spring::smooth(), looped);
        for _ in 0..fps * 4 {
            app.update();
        }
        let x = |app: &App, camera| translation(app, camera).x;
        assert!(
            (x(&app, ahead) - 450.0).abs() < 1e-2,
            "{fps} fps: {}",
            x(&app, ahead)
        );
        assert!(
            (x(&app, behind) - 150.0).abs() < 1e-2,
            "{fps} fps: {}",
            x(&app, behind)
        );
        // A quarter of the way from -5000 to 5000.
        assert!(
            (x(&app, driven) + 2500.0).abs() < 1e-2,
            "{fps} fps: {}",
            x(&app, driven)
        );
        // 1.25 round a loop is a quarter round, where the ring heads back toward -x.
        let quarter = translation(&app, looped);
        assert!(
            quarter.x.abs() < 5.0 && (quarter.z - 500.0).abs() < 5.0,
            "{quarter}"
        );
        let forward = app.world().get::<Transform>(looped).unwrap().forward();
        assert!(forward.dot(Vec3::NEG_X) > 0.999, "{forward:?}");

        // Driven elsewhere mid-run: the camera springs along the rail, never off it.
        app.world_mut()
            .get_mut::<CameraRail>(driven)
            .unwrap()
            .drive(0.75);
        for _ in 0..fps * 4 {
            app.update();
            let at = translation(&app, driven);
            assert!((at.y - RAIL_HEIGHT).abs() < 1e-3 && (at.z - RAIL_DEPTH).abs() < 1e-3);
        }
        assert!(
            (x(&app, driven) - 2500.0).abs() < 1e-2,
            "{fps} fps: {}",
            x(&app, driven)
        );
        assert!(
            app.world().get::<SpringAsleep<RigRail>>(driven).is_some(),
            "{fps} fps: still moving"
        );
    }
}

/// A roll curve along the rail turns the camera about its view by the roll read at its place:
/// rising from 0 at the start to 0.6 rad at the end of a straight rail.
#[test]
fn a_roll_curve_turns_the_camera_about_its_view() {
    for fps in RATES {
        let (mut app, player) = camera_app(fps, (800, 600), |_| Vec3::new(-2000.0, 0.0, 0.0));
        // One roll segment per rail segment: the roll at each of the rail's points.
        let points = (-5..=5).map(|i| 0.06 * (i + 5) as f32).collect::<Vec<_>>();
        let roll = CubicCardinalSpline::new_catmull_rom(points)
            .to_curve()
            .unwrap();
        let rail = CameraRail::new(straight_rail(-5000, 5000, RAIL_DEPTH))
            .aiming(RailAim::Along)
            .with_roll(roll);
        let camera = rail_camera(&mut app, player, Spring::smooth(), rail);
        for _ in 0..fps * 3 {
            app.update();
        }
        // At x = -2000, three tenths of the way: 0.18 rad, about the way it looks (+x).
        let transform = *app.world().get::<Transform>(camera).unwrap();
        assert!((transform.translation.x + 2000.0).abs() < 1e-2);
        assert!(transform.forward().dot(Vec3::X) > 0.9999);
        let unrolled = Transform::default().looking_to(Vec3::X, Vec3::Y);
        let roll = (unrolled.rotation.inverse() * transform.rotation).to_scaled_axis();
        assert!(
            (roll - Vec3::new(0.0, 0.0, 0.18)).length() < 1e-4,
            "{fps} fps: rolled {roll}"
        );
    }
}

/// A rail camera with no goal yet (not finite: its target not found) starts at the target's
/// place once there is one, with no fly-in from the rail's start.
#[test]
fn a_rail_camera_starts_where_its_first_goal_is() {
    let (mut app, player) = camera_app(60, (800, 600), |_| Vec3::new(2000.0, 0.0, 0.0));
    let rail = CameraRail::new(straight_rail(-5000, 5000, RAIL_DEPTH));
    let camera = app
        .world_mut()
        .spawn((
            Camera3d::default(),
            CameraRig::new(Spring::smooth()),
            CameraTargets::single(Entity::PLACEHOLDER),
            CameraGoal {
                point: Vec3::NAN,
                spread: Vec2::ZERO,
            },
            rail,
        ))
        .id();
    for _ in 0..10 {
        app.update();
    }
    // The target given now: the camera is on its place in the same frame.
    app.world_mut()
        .entity_mut(camera)
        .insert(CameraTargets::single(player));
    app.update();
    let at = translation(&app, camera);
    assert!((at.x - 2000.0).abs() < 1e-2, "{at}");
}

const JUMP: Vec3 = Vec3::new(3000.0, 0.0, 0.0);

fn running_with_a_respawn(t: f32) -> Vec3 {
    let carried = if t >= 4.5 { JUMP } else { Vec3::ZERO };
    Vec3::new(-1500.0 + 240.0 * t, 0.0, 0.0) + carried
}

/// A target carried along the rail in one frame, told or caught by the rig's teleport
/// distance: the camera is carried too, at the same lag behind it, instead of flying down the
/// rail.
#[test]
fn a_warped_target_carries_the_camera_along_the_rail() {
    let spring = Spring::from_natural_frequency(4.0, 1.0).unwrap();
    let lag = 240.0 * spring.damping() / spring.stiffness();
    for told in [true, false] {
        for pattern in patterns_and_hitch() {
            let (mut app, player) = camera_app(60, (800, 600), running_with_a_respawn);
            if told {
                app.add_systems(Update, tell_of_a_respawn(JUMP).after(move_player));
            }
            let rail = CameraRail::new(straight_rail(-5000, 9000, RAIL_DEPTH));
            let camera = rail_camera(&mut app, player, spring, rail);
            if !told {
                app.world_mut()
                    .get_mut::<CameraRig>(camera)
                    .unwrap()
                    .teleport_distance = 1000.0;
            }
            let mut worst: f32 = 0.0;
            run_pattern(&mut app, &pattern, 7.0, |app, elapsed| {
                if elapsed > 4.0 {
                    let behind = translation(app, player).x - translation(app, camera).x;
                    worst = worst.max((behind - lag).abs());
                }
            });
            assert!(
                worst < 5e-3,
                "told {told}, {pattern:?}: off the steady lag {lag} by {worst}"
            );
        }
    }
}

#[test]
fn a_blend_to_a_rail_shot_ends_on_the_rail() {
    let (mut app, player) = camera_app(60, (800, 600), |t| Vec3::new(100.0 * t, 0.0, 0.0));
    let rail = CameraRail::new(straight_rail(-5000, 5000, RAIL_DEPTH));
    let shot = app
        .world_mut()
        .spawn((
            CameraRig::new(Spring::smooth()),
            CameraTargets::single(player),
            rail,
            VirtualCamera::new(1),
        ))
        .id();
    let wide = app
        .world_mut()
        .spawn((
            Transform::from_xyz(0.0, 900.0, 900.0),
            VirtualCamera::new(0),
        ))
        .id();
    let camera = app
        .world_mut()
        .spawn((Camera3d::default(), CameraBlend::new(Spring::smooth())))
        .id();
    let blend: Spring = Spring::smooth();
    let dt = 1.0 / 60.0;
    let (mut last, mut last_velocity) = (Vec3::NAN, Vec3::ZERO);
    for frame in 0..600 {
        // To the wide shot and back to the rail mid-blend.
        match frame {
            200 => {
                app.world_mut()
                    .get_mut::<VirtualCamera>(wide)
                    .unwrap()
                    .priority = 2;
            }
            230 => {
                app.world_mut()
                    .get_mut::<VirtualCamera>(wide)
                    .unwrap()
                    .priority = 0;
            }
            _ => {}
        }
        app.update();
        let now = translation(&app, camera);
        let showing = if (200..230).contains(&frame) {
            wide
        } else {
            shot
        };
        if last.is_finite() {
            // No jump in velocity: it changes by at most what the blend's spring pulls, from
            // the shot it heads for (the rail shot moving at 100 units a second).
            let velocity = (now - last) / dt;
            let remaining = translation(&app, showing) - now;
            let pull = (blend.stiffness() * remaining.length()
                + blend.damping() * (last_velocity.length() + 100.0))
                / blend.mass();
            assert!(
                (velocity - last_velocity).length() <= pull * dt * 1.5 + 1.0,
                "frame {frame}: a jump in velocity"
            );
            last_velocity = velocity;
        }
        last = now;
    }
    assert_eq!(
        app.world().get::<BlendTrack>(camera).unwrap().shot(),
        Some(shot)
    );
    let shown = app.world().get::<Transform>(camera).unwrap();
    let on_rail = app.world().get::<Transform>(shot).unwrap();
    assert!(shown.translation.distance(on_rail.translation) < 1e-2);
    assert!(shown.rotation.angle_between(on_rail.rotation) < 1e-3);
}

#[test]
fn the_world_changing_under_a_rail_never_panics_nor_writes_nan() {
    let spring = Spring::from_natural_frequency(4.0, 1.0).unwrap();
    let lag = 240.0 * spring.damping() / spring.stiffness();
    let (mut app, player) =
        camera_app(60, (800, 600), |t| Vec3::new(-1500.0 + 240.0 * t, 0.0, 0.0));
    let rail = CameraRail::new(straight_rail(-5000, 5000, RAIL_DEPTH));
    let camera = rail_camera(&mut app, player, spring, rail);
    let doomed = rail_camera(
        &mut app,
        player,
        spring,
        CameraRail::new(ring(500.0)).looped(),
    );
    // A rail of one point, and a looped rail that is not closed (it warns).
    let point = CubicCardinalSpline::new_catmull_rom([Vec3::ONE; 4])
        .to_curve()
        .unwrap();
    let stuck = rail_camera(&mut app, player, spring, CameraRail::new(point));
    let open = straight_rail(-1000, 1000, 0.0);
    let gapped = rail_camera(&mut app, player, spring, CameraRail::new(open).looped());
    let finite = |app: &App| {
        [camera, stuck, gapped]
            .iter()
            .filter_map(|&entity| app.world().get::<Transform>(entity))
            .all(Transform::is_finite)
    };
    for frame in 0..900 {
        match frame {
            // A rail camera despawned mid-follow.
            60 => app.world_mut().entity_mut(doomed).despawn(),
            // The curve replaced: a rail 300 further back.
            120 => {
                app.world_mut().get_mut::<CameraRail>(camera).unwrap().curve =
                    straight_rail(-5000, 5000, RAIL_DEPTH + 300.0);
            }
            // A goal of NaN written by hand: the camera keeps to where it was going.
            400 => app.world_mut().get_mut::<CameraGoal>(camera).unwrap().point = Vec3::NAN,
            _ => {}
        }
        app.update();
        assert!(finite(&app), "frame {frame}");
        let at = translation(&app, camera);
        match frame {
            120..400 => assert!((at.z - RAIL_DEPTH - 300.0).abs() < 1e-3, "{frame}: {at}"),
            60..120 => assert!((at.z - RAIL_DEPTH).abs() < 1e-3, "{frame}: {at}"),
            _ => {}
        }
        if frame == 399 {
            // Back at the steady lag on the new rail.
            let behind = translation(&app, player).x - at.x;
            assert!((behind - lag).abs() < 5e-3, "{behind}");
        }
    }
    assert_eq!(translation(&app, stuck), Vec3::ONE);
    // The rail taken off: the rig places the camera on its own again.
    app.world_mut().entity_mut(camera).remove::<CameraRail>();
    app.update();
    let motion = *app.world().get::<RigMotion>(camera).unwrap();
    assert_eq!(translation(&app, camera), motion.centre());
    // Every target gone: the rail's spring comes to rest.
    let rail = CameraRail::new(straight_rail(-5000, 5000, RAIL_DEPTH));
    app.world_mut().entity_mut(camera).insert(rail);
    app.world_mut().entity_mut(player).despawn();
    for _ in 0..600 {
        app.update();
    }
    assert!(app.world().get::<SpringAsleep<RigRail>>(camera).is_some());
    assert!(
        app.world()
            .get::<RailMotion>(camera)
            .unwrap()
            .distance()
            .is_finite()
    );
    assert!(finite(&app));
}
