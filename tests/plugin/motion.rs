//! Springs reach their targets exactly as the closed form says, at any frame rate.

use bevy::prelude::*;
use bevy_sprung::prelude::*;
use sprung::SpringState;

use crate::harness::{app, asleep, elapsed, exact, motion, run, spawn_translation, translation};

#[test]
fn reaches_and_settles_exactly_on_its_target() {
    let mut app = app(60);
    let target = Vec3::new(100.0, -40.0, 3.0);
    let entity = spawn_translation(&mut app, Spring::snappy(), Vec3::ZERO, target);
    run(&mut app, 20);
    assert!(
        !asleep::<Translation>(&app, entity),
        "still moving after 1/3 s"
    );
    let halfway = translation(&app, entity);
    assert!(halfway.distance(target) < target.length() / 2.0 && halfway != target);
    run(&mut app, 180);
    assert!(asleep::<Translation>(&app, entity));
    // Snapped: exactly the target, exactly at rest.
    assert_eq!(translation(&app, entity), target);
    assert_eq!(motion::<Translation>(&app, entity).velocity(), Vec3::ZERO);
}

#[test]
fn follows_the_exact_solution() {
    let spring = Spring::from_natural_frequency(9.0, 0.35).unwrap();
    let mut app = app(60);
    let entity = spawn_translation(&mut app, spring, Vec3::X * 10.0, Vec3::ZERO);
    for _ in 0..45 {
        app.update();
        let expected = exact(&spring, 10.0, 0.0, elapsed(&app));
        let x = translation(&app, entity).x;
        assert!(
            (f64::from(x) - expected.position).abs() < 2e-5,
            "{x} vs {}",
            expected.position
        );
    }
}

/// 1 s at 30, 60 and 144 fps lands on the same state, the exact one, to f32 rounding.
#[test]
fn same_motion_at_30_60_and_144_fps() {
    let spring = Spring::from_natural_frequency(12.0, 0.2).unwrap();
    let mut finals = Vec::new();
    for fps in [30, 60, 144] {
        let mut app = app(fps);
        let entity = spawn_translation(&mut app, spring, Vec3::ZERO, Vec3::new(100.0, 50.0, 0.0));
        // The first update has dt = 0; then `fps` frames make one second.
        run(&mut app, fps + 1);
        let seconds = elapsed(&app);
        let state = motion::<Translation>(&app, entity);
        let x = translation(&app, entity);
        let expected = exact(&spring, 0.0, 100.0, seconds);
        assert!((seconds - 1.0).abs() < 1e-6, "{fps} fps: {seconds} s");
        assert!(
            (f64::from(x.x) - expected.position).abs() < 2e-3,
            "{fps} fps: {} vs {}",
            x.x,
            expected.position
        );
        assert!(
            (f64::from(state.velocity().x) - expected.velocity).abs() < 2e-2,
            "{fps} fps"
        );
        finals.push((x, state.velocity()));
    }
    for (x, v) in &finals[1..] {
        assert!(
            x.distance(finals[0].0) < 3e-3 && v.distance(finals[0].1) < 3e-2,
            "{finals:?}"
        );
    }
}

/// A retarget keeps the velocity: the frame after it moves as the exact step from the same
/// position and velocity toward the new target, and the velocity only changes by what the
/// spring force does in one frame.
#[test]
fn retargeting_mid_flight_keeps_the_velocity() {
    let spring = Spring::from_natural_frequency(10.0, 0.6).unwrap();
    let mut app = app(60);
    let entity = spawn_translation(&mut app, spring, Vec3::ZERO, Vec3::new(100.0, 0.0, 0.0));
    run(&mut app, 8);
    let before = motion::<Translation>(&app, entity).velocity();
    let position = translation(&app, entity);
    assert!(before.x > 100.0, "should be moving fast: {before}");
    let new_target = Vec3::new(0.0, 80.0, 0.0);
    app.world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap()
        .set_target(new_target);
    app.update();
    let after = motion::<Translation>(&app, entity).velocity();
    let dt = 1.0 / 60.0;
    let step = spring
        .transition(dt)
        .step(SpringState::new(position, before), new_target);
    assert!(translation(&app, entity).distance(step.position) < 1e-4);
    assert!(after.distance(step.velocity) < 1e-3);
    // Continuity: |Δv| ≤ dt·(k·|offset| + c·|v|)/m, and it still moves along +x.
    let bound = dt
        * (spring.stiffness() * (position - new_target).length()
            + spring.damping() * before.length());
    assert!(after.distance(before) <= bound, "{before} → {after}");
    assert!(after.x > 0.5 * before.x);
}

#[test]
fn impulses_add_velocity_and_wake_the_spring() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ZERO, Vec3::ZERO);
    run(&mut app, 3);
    assert!(asleep::<Translation>(&app, entity));
    app.world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap()
        .add_impulse(Vec3::new(0.0, 300.0, 0.0));
    app.update();
    assert!(!asleep::<Translation>(&app, entity));
    assert!(translation(&app, entity).y > 0.0);
    run(&mut app, 600);
    assert!(asleep::<Translation>(&app, entity));
    assert_eq!(translation(&app, entity), Vec3::ZERO);
}

/// A follower given its target's velocity trails it by the steady lag `c·r/k` and never
/// sleeps while the target moves.
#[test]
fn follows_a_moving_target_at_the_steady_lag() {
    let spring = Spring::from_natural_frequency(8.0, 1.0).unwrap();
    let speed = Vec3::new(30.0, 0.0, 0.0);
    let mut app = app(60);
    let entity = spawn_translation(&mut app, spring, Vec3::ZERO, Vec3::ZERO);
    app.world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap()
        .set_target_velocity(speed);
    let lag = spring.damping() * speed.x / spring.stiffness();
    let mut target = Vec3::ZERO;
    for frame in 0..240 {
        target += speed / 60.0;
        app.world_mut()
            .get_mut::<TranslationSpring>(entity)
            .unwrap()
            .set_target(target);
        app.update();
        if frame > 120 {
            let trailing = target.x - translation(&app, entity).x;
            assert!(
                (trailing - lag).abs() < 1e-3,
                "frame {frame}: lag {trailing} vs {lag}"
            );
        }
    }
    assert!(!asleep::<Translation>(&app, entity));
}

/// Thousands of springs, stepped in parallel batches with cached transitions, each move
/// exactly as one spring alone would.
#[test]
fn many_springs_match_one_spring_each() {
    let mut app = app(60);
    let springs: Vec<_> = (0..3000)
        .map(|i| {
            let f = i as f32;
            let spring = Spring::from_natural_frequency(2.0 + (f % 7.0), 0.1 * (f % 13.0)).unwrap();
            let target = Vec3::new(f, -f, 0.5 * f);
            (
                spawn_translation(&mut app, spring, Vec3::ZERO, target),
                spring,
                target,
            )
        })
        .collect();
    run(&mut app, 31);
    let seconds = elapsed(&app);
    for (entity, spring, target) in springs {
        let expected = exact(&spring, 0.0, target.x, seconds).position;
        let x = f64::from(translation(&app, entity).x);
        assert!(
            (x - expected).abs() <= 1e-5 * (1.0 + expected.abs()),
            "{x} vs {expected}"
        );
    }
}

/// In a scene of 3000 springs (several chunks, and blocks of rows whose change ticks the step
/// tests together), springs retargeted at the edges of blocks and chunks turn toward their new
/// targets the very next frame, as the exact step from their state says, and the springs
/// around them, untouched, go on toward their old ones.
#[test]
fn retargets_anywhere_in_a_large_scene_apply_the_next_frame() {
    let spring = Spring::from_natural_frequency(6.0, 0.7).unwrap();
    let mut app = app(60);
    let springs: Vec<_> = (0..3000)
        .map(|i| {
            let target = Vec3::new(i as f32, 100.0, -50.0);
            spawn_translation(&mut app, spring, Vec3::ZERO, target)
        })
        .collect();
    run(&mut app, 10);
    let retargeted = [0, 1, 255, 256, 257, 511, 1000, 2047, 2048, 2999];
    let before: Vec<_> = springs
        .iter()
        .map(|&entity| {
            let velocity = motion::<Translation>(&app, entity).velocity();
            (translation(&app, entity), velocity)
        })
        .collect();
    let new_target = |i: usize| Vec3::new(-(i as f32), -40.0, 30.0);
    for &i in &retargeted {
        app.world_mut()
            .get_mut::<TranslationSpring>(springs[i])
            .unwrap()
            .set_target(new_target(i));
    }
    app.update();
    let transition = spring.transition(1.0 / 60.0);
    for (i, (&entity, &(position, velocity))) in springs.iter().zip(&before).enumerate() {
        let target = if retargeted.contains(&i) {
            new_target(i)
        } else {
            Vec3::new(i as f32, 100.0, -50.0)
        };
        let step = transition.step(SpringState::new(position, velocity), target);
        let moved = translation(&app, entity);
        assert!(
            moved.distance(step.position) <= 1e-4 * (1.0 + step.position.length()),
            "spring {i}: {moved} vs {}",
            step.position
        );
    }
}

/// Every preset toward targets from 1e3 to 1e6 away, in `f32`, at 144 and 360 fps, in a scene
/// large enough (3000 springs, more than a chunk of 2048) that it steps in chunks split over the
/// compute pool's thread and the calling one: every spring arrives, asleep exactly on its target,
/// within 40 seconds.
#[test]
fn thousands_of_springs_toward_large_targets_at_high_frame_rates_all_arrive() {
    for fps in [144, 360] {
        let mut app = app(fps);
        assert!(bevy::tasks::ComputeTaskPool::get().thread_num() >= 1);
        let springs: Vec<(Entity, Vec3)> = (0..3000_u16)
            .map(|i| {
                let magnitude = 10f32.powi(3 + i32::from(i % 4));
                let angle = f32::from(i) * 0.618_034 * core::f32::consts::TAU;
                let target = magnitude * Vec3::new(angle.cos(), angle.sin(), 0.3);
                let presets = Spring::presets();
                let spring = presets[usize::from(i) % presets.len()].1;
                (
                    spawn_translation(&mut app, spring, Vec3::ZERO, target),
                    target,
                )
            })
            .collect();
        let mut frames = 0;
        while frames < 40 * fps
            && !springs
                .iter()
                .all(|(entity, _)| asleep::<Translation>(&app, *entity))
        {
            run(&mut app, fps);
            frames += fps;
        }
        println!("{fps} fps: every spring asleep after {frames} frames");
        for (entity, target) in springs {
            assert!(
                asleep::<Translation>(&app, entity),
                "{fps} fps: {target} not asleep"
            );
            assert_eq!(translation(&app, entity), target, "{fps} fps");
        }
    }
}

/// A slow spring far from its target moves by less than its offset's last digit each frame
/// (here from 1e5 away with a half-life of 400 s at 240 fps): added to the offset, each step
/// would round away and the spring would not start. It follows the exact motion from the first
/// frame.
#[test]
fn a_slow_spring_far_from_its_target_follows_the_exact_motion() {
    let spring = Spring::from_half_life(400.0).unwrap();
    let mut app = app(240);
    let target = Vec3::new(1e5, -300.0, 7.0);
    let entity = spawn_translation(&mut app, spring, Vec3::ZERO, target);
    app.update();
    for frame in 1..=480 {
        app.update();
        let seconds = elapsed(&app);
        let x = translation(&app, entity);
        for axis in 0..3 {
            let exact = exact(&spring, 0.0, target[axis], seconds).position;
            // To a few units in the last place of the value itself, far finer than the
            // target's (the value is 1e5 times smaller than its target at first).
            #[expect(clippy::cast_possible_truncation, reason = "the exact value in f32")]
            let spacing = f64::from((exact as f32).abs().next_up() - (exact as f32).abs());
            assert!(
                (f64::from(x[axis]) - exact).abs() <= 4.0 * spacing + 1e-9 * exact.abs(),
                "frame {frame} axis {axis}: {} vs {exact}",
                x[axis]
            );
        }
    }
    assert!(
        translation(&app, entity).x > 0.0,
        "the spring never started"
    );
}
