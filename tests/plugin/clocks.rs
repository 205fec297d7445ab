//! Which clock a spring runs on, and stepping in `FixedUpdate`.

use bevy::prelude::*;
use bevy_sprung::clock::SpringClock;
use bevy_sprung::prelude::*;
use bevy_sprung::presence::StaggerChildren;

use crate::harness::{app, app_with, exact, run, spawn_translation, translation};

#[test]
fn paused_game_time_freezes_game_springs_but_not_real_time_springs() {
    let mut app = app(60);
    let game = spawn_translation(&mut app, Spring::gentle(), Vec3::ZERO, Vec3::X * 100.0);
    let ui = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::gentle(), Vec3::X * 100.0).with_clock(SpringClock::Real),
        ))
        .id();
    run(&mut app, 10);
    // Both have moved the same way so far.
    assert_eq!(translation(&app, game), translation(&app, ui));
    app.world_mut().resource_mut::<Time<Virtual>>().pause();
    let frozen = translation(&app, game);
    let before = translation(&app, ui);
    run(&mut app, 10);
    assert_eq!(
        translation(&app, game),
        frozen,
        "game spring moved while paused"
    );
    assert!(
        translation(&app, ui).x > before.x,
        "real-time spring stopped"
    );
    app.world_mut().resource_mut::<Time<Virtual>>().unpause();
    run(&mut app, 2);
    assert!(
        translation(&app, game).x > frozen.x,
        "game spring did not resume"
    );
}

#[test]
fn the_plugin_default_clock_can_be_real_time() {
    let mut app = app_with(60, SpringPlugins::default().with_clock(SpringClock::Real));
    let entity = spawn_translation(&mut app, Spring::gentle(), Vec3::ZERO, Vec3::X * 100.0);
    run(&mut app, 2);
    app.world_mut().resource_mut::<Time<Virtual>>().pause();
    let before = translation(&app, entity);
    run(&mut app, 5);
    assert!(translation(&app, entity).x > before.x);
}

/// Stepped in `FixedUpdate`, a spring advances by whole fixed steps: its state is the exact
/// solution at the fixed clock's elapsed time, whatever the frame times were.
#[test]
fn fixed_update_steps_follow_the_fixed_clock() {
    let spring = Spring::from_natural_frequency(6.0, 0.4).unwrap();
    let mut app = app_with(60, SpringPlugins::default().in_schedule(FixedUpdate));
    let entity = spawn_translation(&mut app, spring, Vec3::ZERO, Vec3::X * 10.0);
    let mut steps_seen = 0_u128;
    for _ in 0..90 {
        app.update();
        let fixed = app.world().resource::<Time<Fixed>>();
        let elapsed = fixed.elapsed_secs_f64();
        steps_seen = fixed.elapsed().as_nanos() / fixed.timestep().as_nanos();
        let expected = exact(&spring, 0.0, 10.0, elapsed).position;
        let x = f64::from(translation(&app, entity).x);
        assert!(
            (x - expected).abs() < 1e-4,
            "{x} vs {expected} at {elapsed}"
        );
    }
    // 90 frames of 1/60 s hold 1.48 s of 64 Hz steps.
    assert!((94..=96).contains(&steps_seen), "{steps_seen} fixed steps");
}

/// An app whose game clock is paused from the start, every spring on `clock` by default.
fn paused_app(clock: SpringClock) -> App {
    let mut app = app_with(60, SpringPlugins::default().with_clock(clock));
    app.world_mut().resource_mut::<Time<Virtual>>().pause();
    app
}

/// A pause menu: five staggered children of a panel, on the real clock, all enter while the
/// game is paused; on the game clock none of them moves.
#[test]
fn a_stagger_counts_on_the_spring_clock() {
    for clock in [SpringClock::Real, SpringClock::Game] {
        let mut app = paused_app(clock);
        let panel = app
            .world_mut()
            .spawn((Transform::default(), StaggerChildren::new(0.1)))
            .id();
        let items: Vec<Entity> = (0..5)
            .map(|index| {
                app.world_mut()
                    .spawn((
                        Transform::from_xyz(0.0, index as f32 * 40.0, 0.0),
                        Presence::default(),
                        ScaleSpring::new(Spring::snappy(), Vec3::ONE),
                        EnterFrom::<bevy_sprung::transform::Scale>(Vec3::splat(0.01)),
                        ChildOf(panel),
                    ))
                    .id()
            })
            .collect();
        run(&mut app, 120);
        for &item in &items {
            let scale = app.world().get::<Transform>(item).unwrap().scale.x;
            match clock {
                SpringClock::Real => assert!((scale - 1.0).abs() < 1e-3, "{item}: {scale}"),
                SpringClock::Game => assert_eq!(scale, 0.01, "{item} moved while paused"),
            }
        }
    }
}

/// A shake goes on while the game is paused on the real clock, and holds on the game clock.
#[test]
fn a_shake_runs_on_the_spring_clock() {
    for clock in [SpringClock::Real, SpringClock::Game] {
        let mut app = paused_app(clock);
        let mut shake = Shake::new(7).with_max_translation(Vec3::splat(10.0));
        shake.add_trauma(1.0);
        let shaken = app.world_mut().spawn((Transform::default(), shake)).id();
        let mut seen = Vec::new();
        for _ in 0..30 {
            app.update();
            seen.push(translation(&app, shaken));
        }
        let moved = seen.windows(2).any(|pair| pair[0] != pair[1]);
        match clock {
            SpringClock::Real => assert!(moved, "the shake stood still on the real clock"),
            SpringClock::Game => assert!(!moved, "the shake moved while the game was paused"),
        }
    }
}

/// A chain sways under gravity while the game is paused on the real clock, and holds its pose
/// on the game clock.
#[test]
fn a_chain_sways_on_the_spring_clock() {
    use bevy_sprung::chain::SpringChain;
    for clock in [SpringClock::Real, SpringClock::Game] {
        let mut app = paused_app(clock);
        let chain = SpringChain::new(Spring::wobbly()).with_gravity(Vec3::new(0.0, -300.0, 0.0));
        let root = app.world_mut().spawn((Transform::default(), chain)).id();
        let joint = app
            .world_mut()
            .spawn((Transform::from_xyz(-20.0, 0.0, 0.0), ChildOf(root)))
            .id();
        app.world_mut()
            .spawn((Transform::from_xyz(-20.0, 0.0, 0.0), ChildOf(joint)));
        run(&mut app, 30);
        let turned = app.world().get::<Transform>(root).unwrap().rotation != Quat::IDENTITY;
        match clock {
            SpringClock::Real => assert!(turned, "the chain hung still on the real clock"),
            SpringClock::Game => assert!(!turned, "the chain swayed while the game was paused"),
        }
    }
}

/// A squash from an impact plays while the game is paused on the real clock, and holds on the
/// game clock.
#[test]
fn a_squash_plays_on_the_spring_clock() {
    for clock in [SpringClock::Real, SpringClock::Game] {
        let mut app = paused_app(clock);
        let squashed = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::snappy(), Vec3::ZERO),
                SquashStretch::new(0.002, 1.5),
            ))
            .id();
        run(&mut app, 2);
        app.world_mut()
            .get_mut::<SquashStretch>(squashed)
            .unwrap()
            .impact(Vec3::Y, 0.7);
        let mut flattest = 1.0f32;
        for _ in 0..60 {
            app.update();
            flattest = flattest.min(app.world().get::<Transform>(squashed).unwrap().scale.y);
        }
        match clock {
            SpringClock::Real => assert!(flattest < 0.75, "no squash on the real clock"),
            SpringClock::Game => assert_eq!(flattest, 1.0, "squashed while the game was paused"),
        }
    }
}

/// A sequence's hold counts on the spring clock: a toast shown in a pause menu leaves after its
/// hold on the real clock; on the game clock it stays where it is while the game is paused.
#[test]
fn a_sequence_hold_counts_on_the_spring_clock() {
    for clock in [SpringClock::Real, SpringClock::Game] {
        let mut app = paused_app(clock);
        let toast = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::snappy(), Vec3::ZERO),
                SpringSequence::<bevy_sprung::transform::Translation>::new()
                    .hold(0.5)
                    .then(Vec3::X * 100.0),
            ))
            .id();
        run(&mut app, 20);
        assert_eq!(
            translation(&app, toast),
            Vec3::ZERO,
            "{clock:?}: left early"
        );
        run(&mut app, 120);
        let x = translation(&app, toast).x;
        match clock {
            SpringClock::Real => assert!((x - 100.0).abs() < 1e-2, "held on the real clock: {x}"),
            SpringClock::Game => assert_eq!(x, 0.0, "left while the game was paused"),
        }
    }
}

/// A flung puck coasts while the game is paused on the real clock, and stays put on the game
/// clock.
#[test]
fn inertia_coasts_on_the_spring_clock() {
    use bevy_sprung::inertia::Inertia;
    for clock in [SpringClock::Real, SpringClock::Game] {
        let mut app = paused_app(clock);
        let puck = app
            .world_mut()
            .spawn((Transform::default(), Inertia::new(2.0)))
            .id();
        run(&mut app, 2);
        app.world_mut()
            .get_mut::<Inertia>(puck)
            .unwrap()
            .fling(Vec3::X * 300.0);
        run(&mut app, 600);
        let x = translation(&app, puck).x;
        match clock {
            SpringClock::Real => {
                assert!((x - 150.0).abs() < 1e-2, "no coast on the real clock: {x}");
            }
            SpringClock::Game => assert_eq!(x, 0.0, "coasted while the game was paused"),
        }
    }
}
