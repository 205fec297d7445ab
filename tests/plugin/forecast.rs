//! `SpringForecast`: the path it predicts is the path the spring then takes, at every frame
//! rate and preset, in pixels; its settle time is within a frame of the spring's arrival.

use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::{SpringAsleep, SpringForecast, SpringMotion};

use crate::harness::app;

/// The frame rates users run at.
const RATES: [u32; 5] = [30, 60, 144, 240, 360];

/// Where the springs start and head for: pixels, far from the origin.
const FROM: Vec3 = Vec3::new(1800.0, -950.0, 0.0);
const TO: Vec3 = Vec3::new(2400.0, -600.0, 0.0);

/// The forecast of `entity`'s translation spring as it is now.
fn forecast(app: &App, entity: Entity) -> SpringForecast<Translation> {
    let world = app.world();
    let spring = world.get::<TranslationSpring>(entity).unwrap();
    let motion = world.get::<SpringMotion<Translation>>(entity).unwrap();
    spring.forecast(motion)
}

fn translation(app: &App, entity: Entity) -> Vec3 {
    app.world().get::<Transform>(entity).unwrap().translation
}

/// The length of a frame as the springs see it.
fn frame_seconds(app: &App) -> f32 {
    app.world().resource::<Time<Virtual>>().delta_secs()
}

/// How far apart a prediction and a frame's value may be: rounding at the scene's magnitude
/// (a few hundred units in the last place of 2400, 0.03 px).
fn rounding() -> f32 {
    256.0 * f32::EPSILON * TO.abs().max_element()
}

/// A spring in flight: started from rest at `FROM`, stepped `frames` frames, then retargeted
/// and kicked (both still to apply, as a forecast taken in a game's `Update` sees them).
fn in_flight(fps: u32, spring: Spring, frames: u32) -> (App, Entity) {
    let mut app = app(fps);
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_translation(FROM),
            TranslationSpring::new(spring, FROM + Vec3::new(-300.0, 200.0, 0.0)),
        ))
        .id();
    // The first update has dt = 0.
    for _ in 0..=frames {
        app.update();
    }
    let mut spring = app
        .world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap();
    spring.set_target(TO);
    spring.add_impulse(Vec3::new(500.0, -250.0, 0.0));
    (app, entity)
}

#[test]
fn the_predicted_path_is_the_path_the_spring_takes() {
    for fps in RATES {
        for (name, spring) in Spring::presets() {
            let (mut app, entity) = in_flight(fps, spring, 5);
            let dt = frame_seconds(&app);
            let ahead = forecast(&app, entity);
            // As many frames as the spring takes to settle, up to 4 s.
            let frames = 4 * fps as usize;
            let sampled: Vec<Vec3> = ahead.samples(dt, frames).collect();
            for (i, &sample) in sampled.iter().enumerate() {
                app.update();
                let shown = translation(&app, entity);
                let exact = ahead.value_at(dt * (i + 1) as f32);
                assert!(
                    shown.distance(sample) <= rounding() && shown.distance(exact) <= rounding(),
                    "{name} at {fps} fps, frame {}: the spring shows {shown}, the forecast's \
                     samples {sample} and its closed form {exact}",
                    i + 1
                );
            }
        }
    }
}

#[test]
fn the_predicted_velocity_is_the_velocity_the_spring_has() {
    for fps in [30, 240] {
        let (mut app, entity) = in_flight(fps, Spring::bouncy(), 3);
        let dt = frame_seconds(&app);
        let ahead = forecast(&app, entity);
        for frame in 1..=fps {
            app.update();
            let velocity = app
                .world()
                .get::<SpringMotion<Translation>>(entity)
                .unwrap()
                .velocity();
            let predicted = ahead.velocity_at(dt * frame as f32);
            // Speeds of up to 2048 px/s, to a few units in their last place.
            assert!(
                velocity.distance(predicted) <= 16.0 * f32::EPSILON * 2048.0,
                "{fps} fps, frame {frame}: velocity {velocity}, predicted {predicted}"
            );
        }
    }
}

#[test]
fn the_settle_time_is_within_a_frame_of_the_arrival() {
    for fps in RATES {
        for (name, spring) in Spring::presets() {
            let (mut app, entity) = in_flight(fps, spring, 2);
            let dt = f64::from(frame_seconds(&app));
            let settle = f64::from(forecast(&app, entity).settle_time().unwrap());
            // The first frame whose state is within the rest tolerances (the spring's own
            // test on its own state, carried digits and all: a forecast from a state is at
            // rest when the state is), and the frame the spring sleeps.
            let mut within = None;
            let mut asleep = None;
            for frame in 1..=(60 * fps) {
                app.update();
                let now = dt * f64::from(frame);
                if within.is_none() && forecast(&app, entity).is_at_rest() {
                    within = Some(now);
                }
                let world = app.world();
                if world.get::<SpringAsleep<Translation>>(entity).is_some() {
                    asleep = Some(now);
                    break;
                }
            }
            let within = within.unwrap_or_else(|| panic!("{name} at {fps} fps never settled"));
            let asleep = asleep.unwrap();
            // The state comes within its tolerances at the first frame at or after the
            // predicted time, and the spring sleeps at that frame or the next.
            let slack = 1e-3 * dt;
            assert!(
                within >= settle - slack && within < settle + dt + slack,
                "{name} at {fps} fps: predicted {settle:.4} s, within rest at {within:.4} s \
                 (frames of {dt:.4} s)"
            );
            assert!(
                asleep <= within + dt + slack,
                "{name} at {fps} fps: within rest at {within:.4} s, asleep at {asleep:.4} s"
            );
        }
    }
}

#[test]
fn a_resting_spring_forecasts_its_target_and_no_time() {
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_translation(TO),
            TranslationSpring::new(Spring::snappy(), TO),
        ))
        .id();
    app.update();
    let ahead = forecast(&app, entity);
    assert!(ahead.is_at_rest());
    assert_eq!(ahead.settle_time(), Some(0.0));
    assert_eq!(ahead.value_at(1.0), TO);
    assert_eq!(ahead.velocity_at(1.0), Vec3::ZERO);
    assert!(ahead.samples(1.0 / 60.0, 10).all(|value| value == TO));
    // Times that are not times give the state now; steps that are not steps give nothing.
    assert_eq!(ahead.value_at(f32::NAN), TO);
    assert_eq!(ahead.value_at(-1.0), TO);
    assert_eq!(ahead.samples(f32::NAN, 10).count(), 0);
    assert_eq!(ahead.samples(0.0, 10).count(), 0);
}

#[test]
fn a_spring_that_never_settles_has_no_settle_time() {
    let mut app = app(60);
    let undamped = Spring::new(1.0, 100.0, 0.0).unwrap();
    let entity = app
        .world_mut()
        .spawn((Transform::default(), TranslationSpring::new(undamped, TO)))
        .id();
    app.update();
    assert_eq!(forecast(&app, entity).settle_time(), None);
    // A moving target: followed, never reached.
    let mut spring = app
        .world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap();
    spring.set_spring(Spring::snappy());
    spring.set_target_velocity(Vec3::X * 100.0);
    let ahead = forecast(&app, entity);
    assert_eq!(ahead.settle_time(), None);
    // It goes on with the target: after a long time, the steady lag c·r/k behind it.
    let later = ahead.value_at(30.0);
    let moved = TO + Vec3::X * 3000.0;
    let snappy: Spring = Spring::snappy();
    let lag = snappy.damping() * 100.0 / snappy.stiffness();
    assert!(
        (moved.x - later.x - lag).abs() < 1e-2 && (later.y - moved.y).abs() < 1e-2,
        "{later} against {moved} less a lag of {lag}"
    );
}
