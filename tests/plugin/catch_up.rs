//! Hidden springs skip frames and catch up exactly: the result equals stepping every frame.

use bevy::camera::visibility::ViewVisibility;
use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringMotion;
use bevy_sprung::visibility::CatchUpWhenHidden;

use crate::harness::{app, run, translation};

fn spawn_pair(app: &mut App, spring: Spring, to: Vec3) -> (Entity, Entity) {
    let every_frame = app
        .world_mut()
        .spawn((Transform::default(), TranslationSpring::new(spring, to)))
        .id();
    let hidden = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(spring, to),
            CatchUpWhenHidden,
            ViewVisibility::HIDDEN,
        ))
        .id();
    (every_frame, hidden)
}

fn set_visible(app: &mut App, entity: Entity, visible: bool) {
    *app.world_mut().get_mut::<ViewVisibility>(entity).unwrap() = if visible {
        ViewVisibility::VISIBLE
    } else {
        ViewVisibility::HIDDEN
    };
}

#[test]
fn a_hidden_spring_catches_up_to_the_every_frame_state_when_seen() {
    let spring = Spring::from_natural_frequency(7.0, 0.3).unwrap();
    let mut app = app(60);
    let (every_frame, hidden) = spawn_pair(&mut app, spring, Vec3::new(50.0, 20.0, 0.0));
    run(&mut app, 25);
    // Hidden: not stepped, not written.
    assert_eq!(translation(&app, hidden), Vec3::ZERO);
    assert!(translation(&app, every_frame).length() > 10.0);
    set_visible(&mut app, hidden, true);
    app.update();
    let a = translation(&app, every_frame);
    let b = translation(&app, hidden);
    assert!(a.distance(b) < 1e-4 * a.length(), "{a} vs {b}");
    let va = app
        .world()
        .get::<SpringMotion<Translation>>(every_frame)
        .unwrap()
        .velocity();
    let vb = app
        .world()
        .get::<SpringMotion<Translation>>(hidden)
        .unwrap()
        .velocity();
    assert!(
        va.distance(vb) < 1e-3 * va.length().max(1.0),
        "{va} vs {vb}"
    );
}

/// A retarget while hidden first catches up under the old target, then steps toward the new
/// one: the same as a spring that was stepped every frame and retargeted at that frame.
#[test]
fn a_retarget_while_hidden_catches_up_under_the_old_target_first() {
    let spring = Spring::from_natural_frequency(5.0, 0.5).unwrap();
    let mut app = app(60);
    let (every_frame, hidden) = spawn_pair(&mut app, spring, Vec3::new(30.0, 0.0, 0.0));
    run(&mut app, 14);
    for entity in [every_frame, hidden] {
        app.world_mut()
            .get_mut::<TranslationSpring>(entity)
            .unwrap()
            .set_target(Vec3::new(-10.0, 40.0, 0.0));
    }
    app.update();
    let a = translation(&app, every_frame);
    let b = translation(&app, hidden);
    assert!(a.distance(b) < 1e-4 * a.length(), "{a} vs {b}");
    // Still hidden: it defers again until the next change or until it is seen.
    run(&mut app, 20);
    set_visible(&mut app, hidden, true);
    app.update();
    let a = translation(&app, every_frame);
    let b = translation(&app, hidden);
    assert!(a.distance(b) < 1e-4 * a.length(), "{a} vs {b}");
}

/// Springs without the opt-in ignore visibility.
#[test]
fn without_the_opt_in_hidden_springs_keep_stepping() {
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::X),
            ViewVisibility::HIDDEN,
        ))
        .id();
    run(&mut app, 5);
    assert!(translation(&app, entity).x > 0.0);
}
