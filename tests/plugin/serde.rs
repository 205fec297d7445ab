//! Spring components in RON: their configuration round-trips, a spring read from a file works
//! in an app, and invalid files are clear errors.

use bevy::prelude::*;
use bevy_sprung::clock::SpringClock;
use bevy_sprung::juice::Conserve;
use bevy_sprung::prelude::*;

use crate::harness::{app, asleep, assert_move_alike, run, translation};

fn round_trip<T>(value: &T) -> T
where
    T: serde::Serialize + for<'de> serde::Deserialize<'de>,
{
    let text = ron::to_string(value).unwrap();
    ron::from_str(&text).unwrap_or_else(|error| panic!("{text}: {error}"))
}

/// Two springs started from the same place (on the default clock: the real clock of an app under
/// test does not advance) move alike, frame after frame.
fn assert_same_motion(a: TranslationSpring, b: TranslationSpring) {
    let mut app = app(60);
    let [a, b] = [a, b].map(|spring| {
        app.world_mut()
            .spawn((
                Transform::from_xyz(3.0, 4.0, 5.0),
                spring.with_clock(SpringClock::Game),
            ))
            .id()
    });
    assert_move_alike(&mut app, (a, b), 10);
    assert_ne!(translation(&app, a), Vec3::new(3.0, 4.0, 5.0), "it moved");
}

#[test]
fn configurations_round_trip() {
    let translation = TranslationSpring::new(Spring::bouncy(), Vec3::new(1.0, -2.5, 1e5))
        .with_velocity(Vec3::X * 3.0)
        .with_rest(RestThreshold::new(0.5, 5.0))
        .with_clock(SpringClock::Real);
    let back = round_trip(&translation);
    assert_eq!(back.spring(), translation.spring());
    assert_eq!(back.target(), translation.target());
    assert_eq!(back.rest(), translation.rest());
    assert_eq!(back.clock(), Some(SpringClock::Real));
    // The starting velocity too: both move alike from the same place.
    assert_same_motion(translation, back);

    let slide =
        UiTransformTranslationSpring::new(Spring::smooth(), Val2::new(percent(30.0), px(-8.0)));
    assert_eq!(round_trip(&slide).target(), slide.target());
    let fade = BackgroundColorSpring::new(Spring::snappy(), Color::srgba(0.2, 0.4, 0.9, 0.5));
    assert_eq!(round_trip(&fade).target(), fade.target());
    let turn = RotationSpring::new(Spring::wobbly(), Quat::from_rotation_y(1.0));
    assert_eq!(round_trip(&turn).target(), turn.target());
}

/// Interaction and juice components round-trip their configuration.
#[test]
fn interaction_and_juice_round_trip() {
    use bevy_sprung::interaction::{DragBounds, DragFollow, InteractionTargets, Snap, SpringDrag};
    let targets = InteractionTargets::<Scale>::new(Vec3::ONE)
        .hovered(Vec3::splat(1.1))
        .pressed(Vec3::splat(0.9));
    let back = round_trip(&targets);
    assert_eq!(
        (back.idle, back.hovered, back.pressed),
        (targets.idle, targets.hovered, targets.pressed)
    );
    assert_eq!(back.dragged, None);

    let drag = SpringDrag::new()
        .following(DragFollow::Spring(Spring::stiff()))
        .snapping(Snap::Points(vec![Vec3::X, Vec3::Y]))
        .within(50.0)
        .bounded(DragBounds {
            min: Vec3::ZERO,
            max: Vec3::splat(10.0),
            give: 3.0,
        })
        .with_threshold(4.0);
    let back = round_trip(&drag);
    assert_eq!(back.follow, drag.follow);
    assert_eq!(back.snap, drag.snap);
    assert_eq!(back.bounds, drag.bounds);
    assert_eq!((back.snap_radius, back.threshold), (Some(50.0), 4.0));

    let mut shake = Shake::new(9).with_max_translation(Vec3::new(4.0, 4.0, 0.0));
    shake.add_trauma(0.5);
    let back = round_trip(&shake);
    assert_eq!(
        (back.seed, back.trauma, back.max_translation),
        (9, 0.5, shake.max_translation)
    );
    let squash = SquashStretch::new(0.01, 1.3).conserving(Conserve::Area);
    let back = round_trip(&squash);
    assert_eq!((back.max_stretch, back.conserve), (1.3, Conserve::Area));
}

/// A file need only name the spring (any parametrisation) and the target.
#[test]
fn a_spring_read_from_a_file_springs() {
    let spring: TranslationSpring =
        ron::from_str("(spring: (duration: 0.4, bounce: 0.2), target: (10.0, 20.0, 0.0))").unwrap();
    assert_eq!(spring.rest(), RestThreshold::DEFAULT);
    // It starts at rest, as one made in code.
    assert_same_motion(
        TranslationSpring::new(*spring.spring(), spring.target()),
        spring,
    );
    let mut app = app(60);
    let entity = app.world_mut().spawn((Transform::default(), spring)).id();
    run(&mut app, 180);
    assert!(asleep::<Translation>(&app, entity));
    assert_eq!(translation(&app, entity), Vec3::new(10.0, 20.0, 0.0));
}

#[test]
fn invalid_files_are_clear_errors() {
    let cases = [
        (
            "(spring: (stiffness: -1.0, damping: 1.0), target: (0.0, 0.0, 0.0))",
            "stiffness must not be negative",
        ),
        (
            "(spring: (preset: snappy), target: (NaN, 0.0, 0.0))",
            "target",
        ),
        (
            "(spring: (preset: snappy), target: (0.0, 0.0, 0.0), velocity: (inf, 0.0, 0.0))",
            "velocity",
        ),
        (
            "(spring: (preset: snappy), target: (0.0, 0.0, 0.0), rest: (offset: -1.0, speed: 1.0))",
            "rest offset",
        ),
        (
            "(spring: (preset: snappy), targt: (0.0, 0.0, 0.0))",
            "targt",
        ),
        ("(target: (0.0, 0.0, 0.0))", "spring"),
    ];
    for (text, needle) in cases {
        let error = ron::from_str::<TranslationSpring>(text)
            .expect_err(text)
            .to_string();
        assert!(error.contains(needle), "{text}: {error}");
    }
}
