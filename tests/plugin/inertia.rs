//! Inertia: a fling coasts exactly `v₀/d` and stops; bounds, snap points, bad input.

use bevy::prelude::*;
use bevy_sprung::inertia::{DragBounds, Inertia, Snap};
use bevy_sprung::prelude::*;

use crate::harness::{app, run};

fn translation(app: &App, entity: Entity) -> Vec3 {
    app.world().get::<Transform>(entity).unwrap().translation
}

fn fling(app: &mut App, entity: Entity, velocity: Vec3) {
    app.world_mut()
        .get_mut::<Inertia>(entity)
        .unwrap()
        .fling(velocity);
}

/// Every frame on the closed form `x₀ + v₀·(1 − e^(−d·t))/d`, and at rest exactly on
/// `x₀ + v₀/d`, at 30 to 240 fps, at pixel and at large-world magnitudes.
#[test]
fn a_fling_travels_v0_over_d() {
    for fps in [30, 60, 144, 240, 360] {
        for from in [Vec3::new(10.0, -20.0, 0.0), Vec3::new(1.0e5, -2.0e5, 30.0)] {
            let mut app = app(fps);
            let puck = app
                .world_mut()
                .spawn((Transform::from_translation(from), Inertia::new(3.0)))
                .id();
            app.update();
            let velocity = Vec3::new(900.0, -450.0, 0.0);
            fling(&mut app, puck, velocity);
            let spacing = from.abs().max_element() * f32::EPSILON;
            let mut t = 0.0_f64;
            for _ in 0..(3 * fps) {
                app.update();
                t += 1.0 / f64::from(fps);
                let travelled = (1.0 - (-3.0 * t).exp()) / 3.0;
                let expected = from.as_dvec3() + velocity.as_dvec3() * travelled;
                let error = (translation(&app, puck).as_dvec3() - expected)
                    .abs()
                    .max_element();
                assert!(
                    error < 0.01 + 4.0 * f64::from(spacing),
                    "{fps} fps from {from}: {error} at {t}"
                );
            }
            run(&mut app, 20 * fps);
            assert_eq!(
                translation(&app, puck),
                from + velocity / 3.0,
                "{fps} fps: rests exactly v0/d away"
            );
        }
    }
}

/// A throw toward an edge stops on it and is never past it; one released past an edge (as a
/// rubber-banded drag leaves it) going further out never goes further, and comes back inside.
#[test]
fn bounds_are_never_passed() {
    let bounds = DragBounds {
        min: Vec3::new(-100.0, -100.0, 0.0),
        max: Vec3::new(100.0, 100.0, 0.0),
        give: 40.0,
    };
    for fps in [30, 60, 240] {
        let mut app = app(fps);
        let puck = app
            .world_mut()
            .spawn((Transform::default(), Inertia::new(2.0).bounded(bounds)))
            .id();
        app.update();
        fling(&mut app, puck, Vec3::new(4000.0, 500.0, 0.0));
        for _ in 0..(10 * fps) {
            app.update();
            let at = translation(&app, puck);
            assert!(at.x <= 100.0 && at.y <= 100.0, "{fps} fps: {at}");
        }
        let at = translation(&app, puck);
        assert_eq!(
            at.x, 100.0,
            "{fps} fps: stopped on the edge it reached first"
        );
        assert!(
            (at.y - 12.5).abs() < 1e-3,
            "{fps} fps: along its line: {at}"
        );

        // Let go 30 past the right edge (inside its 40 of give), still moving out.
        app.world_mut()
            .get_mut::<Transform>(puck)
            .unwrap()
            .translation
            .x = 130.0;
        app.world_mut()
            .get_mut::<TranslationSpring>(puck)
            .unwrap()
            .set_target(Vec3::new(130.0, 12.5, 0.0));
        run(&mut app, 2);
        fling(&mut app, puck, Vec3::new(3000.0, 0.0, 0.0));
        for _ in 0..(5 * fps) {
            app.update();
            let at = translation(&app, puck);
            assert!(at.x <= 130.0 + 1e-3, "{fps} fps: went further out: {at}");
        }
        assert!(translation(&app, puck).x <= 100.0, "{fps} fps: back inside");
    }
}

/// With snap points the throw springs to the one nearest where it would have stopped.
#[test]
fn a_throw_snaps_to_the_nearest_point() {
    let mut app = app(60);
    let points = vec![
        Vec3::ZERO,
        Vec3::new(200.0, 0.0, 0.0),
        Vec3::new(400.0, 0.0, 0.0),
    ];
    let card = app
        .world_mut()
        .spawn((
            Transform::default(),
            Inertia::new(4.0).snapping(Snap::Points(points)),
        ))
        .id();
    app.update();
    // Would stop at 1100 / 4 = 275: nearest is 200.
    fling(&mut app, card, Vec3::new(1100.0, 0.0, 0.0));
    run(&mut app, 600);
    assert_eq!(translation(&app, card), Vec3::new(200.0, 0.0, 0.0));
}

/// A NaN fling is refused; a nonsense deceleration is taken as the default; an existing
/// translation spring is used, not replaced.
#[test]
fn bad_input_is_refused() {
    let mut app = app(60);
    let puck = app
        .world_mut()
        .spawn((
            Transform::from_xyz(5.0, 0.0, 0.0),
            TranslationSpring::new(Spring::snappy(), Vec3::new(5.0, 0.0, 0.0)),
            Inertia::new(f32::NAN),
        ))
        .id();
    app.update();
    fling(&mut app, puck, Vec3::new(f32::NAN, 0.0, 0.0));
    run(&mut app, 60);
    assert_eq!(translation(&app, puck), Vec3::new(5.0, 0.0, 0.0));
    fling(&mut app, puck, Vec3::new(100.0, 0.0, 0.0));
    run(&mut app, 1200);
    let expected = 5.0 + 100.0 / Inertia::DEFAULT_DECELERATION;
    assert_eq!(translation(&app, puck), Vec3::new(expected, 0.0, 0.0));
}

/// A thrown spring gets its own parameters back when the throw ends, and one retargeted
/// mid-coast (a follower, a sequence) gets them back at once and arrives: a coast has no
/// stiffness and would never get there.
#[test]
fn the_spring_is_given_back_after_a_throw() {
    let mut app = app(60);
    let puck = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::bouncy(), Vec3::ZERO),
            Inertia::new(2.0),
        ))
        .id();
    app.update();
    fling(&mut app, puck, Vec3::new(200.0, 0.0, 0.0));
    run(&mut app, 20);
    assert_ne!(
        *app.world().get::<TranslationSpring>(puck).unwrap().spring(),
        Spring::bouncy()
    );
    run(&mut app, 1200);
    assert_eq!(
        *app.world().get::<TranslationSpring>(puck).unwrap().spring(),
        Spring::bouncy()
    );

    fling(&mut app, puck, Vec3::new(-500.0, 0.0, 0.0));
    run(&mut app, 10);
    app.world_mut()
        .get_mut::<TranslationSpring>(puck)
        .unwrap()
        .set_target(Vec3::new(0.0, 300.0, 0.0));
    run(&mut app, 600);
    assert_eq!(translation(&app, puck), Vec3::new(0.0, 300.0, 0.0));
    assert_eq!(
        *app.world().get::<TranslationSpring>(puck).unwrap().spring(),
        Spring::bouncy()
    );
}
