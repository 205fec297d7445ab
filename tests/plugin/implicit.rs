//! Implicit transitions: values written directly spring to the written value, exactly as an
//! explicit retarget would; writing the target again does nothing; bad writes are refused.

use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::ui::{NodeWidth, NodeWidthSpring};

use crate::harness::{app, asleep, motion, run};

fn width(app: &App, entity: Entity) -> f32 {
    match app.world().get::<Node>(entity).unwrap().width {
        Val::Px(width) => width,
        other => panic!("width {other:?}"),
    }
}

/// A width written directly springs there: every frame strictly between the old and the
/// written value (a critically damped spring), then exactly the written value; and the motion
/// is, bit for bit, that of a spring retargeted by hand at the same frame.
#[test]
fn a_write_springs_to_the_written_value_as_a_retarget_would() {
    for fps in [30, 60, 144, 240] {
        let mut app = app(fps);
        let node = |width| Node {
            width: px(width),
            ..default()
        };
        let implicit = app
            .world_mut()
            .spawn((
                node(100.0),
                ImplicitSpring::<NodeWidth>::new(Spring::smooth()),
            ))
            .id();
        let explicit = app
            .world_mut()
            .spawn((
                node(100.0),
                NodeWidthSpring::new(Spring::smooth(), px(100.0)),
            ))
            .id();
        run(&mut app, 5);
        assert_eq!(width(&app, implicit), 100.0);
        assert!(asleep::<NodeWidth>(&app, implicit));
        // The game writes the width; the other spring is retargeted.
        app.world_mut().get_mut::<Node>(implicit).unwrap().width = px(300.0);
        app.world_mut()
            .get_mut::<NodeWidthSpring>(explicit)
            .unwrap()
            .set_target(px(300.0));
        let mut last = 100.0;
        for frame in 0..3 * fps {
            app.update();
            let now = width(&app, implicit);
            assert_eq!(now, width(&app, explicit), "{fps} fps, frame {frame}");
            assert_eq!(
                motion::<NodeWidth>(&app, implicit).velocity(),
                motion::<NodeWidth>(&app, explicit).velocity()
            );
            if now < 300.0 {
                assert!(now > last, "{fps} fps, frame {frame}: {now} after {last}");
            }
            assert!(now <= 300.0);
            last = now;
        }
        assert_eq!(width(&app, implicit), 300.0);
        assert!(asleep::<NodeWidth>(&app, implicit));
    }
}

/// Writing the value it is heading for, every frame, changes nothing of the motion; writing it
/// at rest leaves the spring asleep.
#[test]
fn writing_the_same_value_again_does_nothing() {
    let mut app = app(60);
    let spawn = |app: &mut App| {
        app.world_mut()
            .spawn((
                Transform::default(),
                ImplicitSpring::<Translation>::new(Spring::bouncy()),
            ))
            .id()
    };
    let rewritten = spawn(&mut app);
    let written_once = spawn(&mut app);
    run(&mut app, 2);
    let goal = Vec3::new(500.0, -20.0, 0.0);
    for entity in [rewritten, written_once] {
        app.world_mut()
            .get_mut::<Transform>(entity)
            .unwrap()
            .translation = goal;
    }
    for frame in 0..240 {
        app.world_mut()
            .get_mut::<Transform>(rewritten)
            .unwrap()
            .translation = goal;
        app.update();
        let [a, b] = [rewritten, written_once]
            .map(|entity| app.world().get::<Transform>(entity).unwrap().translation);
        assert_eq!(a, b, "frame {frame}");
    }
    assert_eq!(
        app.world().get::<Transform>(rewritten).unwrap().translation,
        goal
    );
    assert!(asleep::<Translation>(&app, rewritten));
    app.world_mut()
        .get_mut::<Transform>(rewritten)
        .unwrap()
        .translation = goal;
    run(&mut app, 3);
    assert!(asleep::<Translation>(&app, rewritten));
}

/// A colour written directly fades in Oklab and lands on the written colour; a NaN written is
/// refused: the shown colour is put back and the target kept.
#[test]
fn colours_fade_and_bad_writes_are_refused() {
    let mut app = app(60);
    let from = Color::srgb(0.1, 0.2, 0.8);
    let to = Color::srgb(0.9, 0.6, 0.1);
    let panel = app
        .world_mut()
        .spawn((
            BackgroundColor(from),
            ImplicitSpring::<BackgroundColor>::new(Spring::smooth()),
        ))
        .id();
    run(&mut app, 2);
    app.world_mut().get_mut::<BackgroundColor>(panel).unwrap().0 = to;
    run(&mut app, 10);
    let mid = app.world().get::<BackgroundColor>(panel).unwrap().0;
    assert!(mid != from && mid != to, "{mid:?}");
    app.world_mut().get_mut::<BackgroundColor>(panel).unwrap().0 = Color::srgb(f32::NAN, 0.0, 0.0);
    app.update();
    let after = app.world().get::<BackgroundColor>(panel).unwrap().0;
    assert!(!after.to_srgba().red.is_nan(), "NaN shown");
    run(&mut app, 240);
    assert_eq!(app.world().get::<BackgroundColor>(panel).unwrap().0, to);
}

/// An implicit spring added to an entity that already springs the property uses that spring:
/// its target and parameters are kept.
#[test]
fn an_existing_spring_is_kept() {
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::bouncy(), Vec3::X * 50.0),
            ImplicitSpring::<Translation>::new(Spring::smooth()),
        ))
        .id();
    run(&mut app, 2);
    let spring = *app.world().get::<TranslationSpring>(entity).unwrap();
    assert_eq!(spring.target(), Vec3::X * 50.0);
    assert_eq!(*spring.spring(), Spring::bouncy());
}
