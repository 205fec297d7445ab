//! Which clock a spring runs on, and stepping in `FixedUpdate`.

use bevy::prelude::*;
use bevy_sprung::prelude::*;

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
    let mut app = app_with(60, SpringPlugin::default().with_clock(SpringClock::Real));
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
    let mut app = app_with(60, SpringPlugin::default().in_schedule(FixedUpdate));
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
