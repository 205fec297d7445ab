//! Presence: entering from a start value, exits that despawn once settled, exits cancelled
//! mid-flight, and the world changing under an exit.

use bevy::prelude::*;
use bevy_sprung::prelude::*;

use crate::harness::{app, asleep, motion, run, translation};

/// The events each entity received, in order.
#[derive(Resource, Default)]
struct Heard(Vec<(Entity, &'static str)>);

fn listen(app: &mut App) {
    app.init_resource::<Heard>()
        .add_observer(|entered: On<Entered>, mut heard: ResMut<Heard>| {
            heard.0.push((entered.entity, "entered"));
        })
        .add_observer(
            |exited: On<Exited>, mut heard: ResMut<Heard>, presences: Query<&Presence>| {
                // Still there, with its components, when told.
                assert!(presences.get(exited.entity).is_ok());
                heard.0.push((exited.entity, "exited"));
            },
        );
}

fn heard(app: &App, entity: Entity) -> Vec<&'static str> {
    app.world()
        .resource::<Heard>()
        .0
        .iter()
        .filter(|(heard, _)| *heard == entity)
        .map(|&(_, what)| what)
        .collect()
}

const EXIT: Vec3 = Vec3::new(0.0, -300.0, 0.0);

/// A card that rises from below to the origin and leaves downward, with a child.
fn spawn_card(app: &mut App) -> (Entity, Entity) {
    let card = app
        .world_mut()
        .spawn((
            Transform::default(),
            Presence::default(),
            TranslationSpring::new(Spring::smooth(), Vec3::ZERO),
            EnterFrom::<Translation>(Vec3::new(0.0, -200.0, 0.0)),
            ExitTo::<Translation>(EXIT),
            ScaleSpring::new(Spring::bouncy(), Vec3::ONE),
            EnterFrom::<Scale>(Vec3::splat(0.5)),
            ExitTo::<Scale>(Vec3::splat(0.5)),
        ))
        .id();
    let child = app
        .world_mut()
        .spawn((Transform::default(), ChildOf(card)))
        .id();
    (card, child)
}

fn exit(app: &mut App, entity: Entity) {
    app.world_mut()
        .commands()
        .entity(entity)
        .despawn_after_exit();
    app.world_mut().flush();
}

fn cancel(app: &mut App, entity: Entity) {
    app.world_mut().commands().entity(entity).cancel_exit();
    app.world_mut().flush();
}

#[test]
fn enters_from_its_start_and_leaves_once_its_exit_settled() {
    for fps in [30, 60, 144, 240] {
        let mut app = app(fps);
        listen(&mut app);
        let (card, child) = spawn_card(&mut app);
        run(&mut app, 2);
        let rising = translation(&app, card).y;
        assert!(
            rising > -200.0 && rising < 0.0,
            "{fps} fps: entering at {rising}"
        );
        assert!(heard(&app, card).is_empty());
        run(&mut app, 3 * fps);
        assert_eq!(heard(&app, card), ["entered"], "{fps} fps");
        assert_eq!(
            app.world().get::<Presence>(card).unwrap().phase(),
            PresencePhase::Present
        );

        exit(&mut app, card);
        // Until its exit has settled the card is there, moving toward its exit values.
        let mut frames = 0;
        while app.world().get_entity(card).is_ok() {
            assert!(
                app.world().get::<Presence>(card).unwrap().is_exiting(),
                "{fps} fps"
            );
            let y = translation(&app, card).y;
            assert!((EXIT.y..=0.0).contains(&y), "{fps} fps: leaving at {y}");
            app.update();
            frames += 1;
            assert!(frames < 10 * fps, "{fps} fps: never left");
        }
        // It went once its springs had settled, not at once: a smooth spring takes a while.
        assert!(frames > fps / 4, "{fps} fps: left after {frames} frames");
        assert!(app.world().get_entity(child).is_err(), "the child stays");
        assert_eq!(heard(&app, card), ["entered", "exited"], "{fps} fps");
    }
}

/// Turned back mid-exit, the card moves exactly as a spring retargeted by hand at the same
/// frames: position and velocity carry over, bit for bit.
#[test]
fn a_cancelled_exit_keeps_position_and_velocity() {
    for fps in [30, 60, 144, 240] {
        let mut app = app(fps);
        listen(&mut app);
        let (card, _) = spawn_card(&mut app);
        let twin = app
            .world_mut()
            .spawn((
                Transform::from_xyz(0.0, -200.0, 0.0),
                TranslationSpring::new(Spring::smooth(), Vec3::ZERO),
            ))
            .id();
        let alike = |app: &App| {
            assert_eq!(translation(app, card), translation(app, twin), "{fps} fps");
            assert_eq!(
                motion::<Translation>(app, card).velocity(),
                motion::<Translation>(app, twin).velocity(),
                "{fps} fps"
            );
        };
        // Exit while still entering (a toast dismissed as it slides in), then turn back.
        run(&mut app, fps / 10);
        exit(&mut app, card);
        app.world_mut()
            .get_mut::<TranslationSpring>(twin)
            .unwrap()
            .set_target(EXIT);
        for _ in 0..fps / 5 {
            app.update();
            alike(&app);
        }
        let leaving = motion::<Translation>(&app, card).velocity().y;
        assert!(leaving < 0.0, "{fps} fps: not leaving ({leaving})");
        cancel(&mut app, card);
        app.world_mut()
            .get_mut::<TranslationSpring>(twin)
            .unwrap()
            .set_target(Vec3::ZERO);
        for _ in 0..3 * fps {
            app.update();
            alike(&app);
        }
        assert!(app.world().get_entity(card).is_ok(), "{fps} fps: despawned");
        assert_eq!(translation(&app, card), Vec3::ZERO);
        assert!(asleep::<Translation>(&app, card));
        // One entrance, reported once the turned-back motion settled; no exit.
        assert_eq!(heard(&app, card), ["entered"], "{fps} fps");
        assert_eq!(
            *app.world().get::<Transform>(card).unwrap(),
            Transform::default()
        );
    }
}

#[test]
fn an_exit_asked_twice_is_one_exit() {
    let mut app = app(60);
    listen(&mut app);
    let (card, _) = spawn_card(&mut app);
    run(&mut app, 120);
    exit(&mut app, card);
    run(&mut app, 10);
    exit(&mut app, card);
    exit(&mut app, card);
    run(&mut app, 300);
    assert!(app.world().get_entity(card).is_err());
    assert_eq!(heard(&app, card), ["entered", "exited"]);
}

/// With nothing to move, the exit completes in the frame it was asked in; without a `Presence`
/// the entity just goes.
#[test]
fn an_exit_with_nothing_to_move_despawns_at_once() {
    let mut app = app(60);
    listen(&mut app);
    let still = app
        .world_mut()
        .spawn((
            Transform::default(),
            Presence::default(),
            TranslationSpring::new(Spring::smooth(), Vec3::ZERO),
        ))
        .id();
    let plain = app.world_mut().spawn(Transform::default()).id();
    run(&mut app, 30);
    // Nothing moved, and still it entered.
    assert_eq!(heard(&app, still), ["entered"]);
    exit(&mut app, still);
    exit(&mut app, plain);
    assert!(app.world().get_entity(plain).is_err());
    app.update();
    assert!(app.world().get_entity(still).is_err());
    assert!(app.world().get_entity(plain).is_err());
    assert_eq!(heard(&app, still), ["entered", "exited"]);
    run(&mut app, 10);
}

/// The world changing under an exit: despawned directly, with its parent, from inside the
/// `Exited` observer, or turned back there. No panic, no event for a dead entity.
#[test]
fn the_world_changing_under_an_exit() {
    let mut app = app(60);
    listen(&mut app);
    let (direct, _) = spawn_card(&mut app);
    let parent = app.world_mut().spawn(Transform::default()).id();
    let (orphan, _) = spawn_card(&mut app);
    app.world_mut().entity_mut(orphan).insert(ChildOf(parent));
    let (despawns_itself, _) = spawn_card(&mut app);
    let (turns_back, _) = spawn_card(&mut app);
    app.add_observer(move |exited: On<Exited>, mut commands: Commands| {
        if exited.entity == despawns_itself {
            commands.entity(exited.entity).despawn();
        }
        if exited.entity == turns_back {
            commands.entity(exited.entity).cancel_exit();
        }
    });
    run(&mut app, 120);
    for entity in [direct, orphan, despawns_itself, turns_back] {
        exit(&mut app, entity);
    }
    run(&mut app, 5);
    app.world_mut().entity_mut(direct).despawn();
    app.world_mut().entity_mut(parent).despawn();
    run(&mut app, 300);
    for gone in [direct, orphan] {
        assert!(app.world().get_entity(gone).is_err());
        assert_eq!(heard(&app, gone), ["entered"], "an event for a dead entity");
    }
    assert!(app.world().get_entity(despawns_itself).is_err());
    assert_eq!(heard(&app, despawns_itself), ["entered", "exited"]);
    // Turned back in its `Exited` observer: it stays, and springs back in.
    assert!(app.world().get_entity(turns_back).is_ok());
    assert_eq!(translation(&app, turns_back), Vec3::ZERO);
    assert_eq!(heard(&app, turns_back), ["entered", "exited", "entered"]);
}

/// A non-finite start is refused: the property keeps its value.
#[test]
fn a_non_finite_start_is_refused() {
    let mut app = app(60);
    let card = app
        .world_mut()
        .spawn((
            Transform::from_xyz(5.0, 0.0, 0.0),
            TranslationSpring::new(Spring::smooth(), Vec3::ZERO),
            EnterFrom::<Translation>(Vec3::NAN),
        ))
        .id();
    run(&mut app, 120);
    assert_eq!(translation(&app, card), Vec3::ZERO);
}
