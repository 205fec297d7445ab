//! Presence: entering from a start value, exits that despawn once settled, exits cancelled
//! mid-flight, and the world changing under an exit.

use core::time::Duration;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::prelude::*;
use bevy_sprung::presence::{
    Entered, Exited, PresencePhase, StaggerChildren, StaggerOrder, StaggerWhen,
};

use crate::harness::{app, asleep, frame, motion, run, translation};

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

/// An exit ends where it stops showing, not on the last thousandth of a unit: the card goes
/// within 0.2 s of coming within 1/100 of its travel on every spring (a smooth spring takes
/// another 0.6 s from there to a thousandth of a unit), and never before that. At 30 to 360
/// fps, in a world 1e5 units from its origin, and with a 1 s hitch mid-exit.
#[test]
fn an_exit_ends_at_a_visible_rest() {
    let at_origin = [30, 60, 144, 240, 360].map(|fps| (fps, Vec3::ZERO, false));
    let cases = at_origin.into_iter().chain([
        (60, Vec3::new(1e5, -1e5, 0.0), false),
        (60, Vec3::ZERO, true),
    ]);
    for (fps, origin, hitch) in cases {
        let case = format!("{fps} fps, origin {origin}, hitch {hitch}");
        let mut app = app(fps);
        let card = app
            .world_mut()
            .spawn((
                Transform::from_translation(origin),
                Presence::default(),
                TranslationSpring::new(Spring::smooth(), origin),
                EnterFrom::<Translation>(origin + Vec3::new(0.0, -200.0, 0.0)),
                ExitTo::<Translation>(origin + EXIT),
                ScaleSpring::new(Spring::bouncy(), Vec3::ONE),
                EnterFrom::<Scale>(Vec3::splat(0.5)),
                ExitTo::<Scale>(Vec3::splat(0.5)),
            ))
            .id();
        run(&mut app, 3 * fps);
        let scale_travel = (Vec3::ONE - Vec3::splat(0.5)).length();
        exit(&mut app, card);
        let mut near_since = None;
        let mut elapsed = 0.0;
        let mut frames = 0;
        while app.world().get_entity(card).is_ok() {
            let transform = *app.world().get::<Transform>(card).unwrap();
            let near = transform.translation.distance(origin + EXIT) <= EXIT.length() / 100.0
                && (transform.scale - Vec3::splat(0.5)).length() <= scale_travel / 100.0;
            if near {
                near_since.get_or_insert(elapsed);
            }
            let length = if hitch && frames == fps / 10 {
                Duration::from_secs(1)
            } else {
                frame(fps)
            };
            app.insert_resource(TimeUpdateStrategy::ManualDuration(length));
            app.update();
            frames += 1;
            elapsed += app.world().resource::<Time>().delta_secs_f64();
            if app.world().get_entity(card).is_err() {
                assert!(near, "{case}: left {transform:?} short of its exit");
            }
            assert!(frames < 10 * fps, "{case}: never left");
        }
        let lingered = elapsed - near_since.unwrap();
        assert!(
            lingered <= 0.2 + 1e-9,
            "{case}: went {lingered} s after it stopped showing"
        );
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

/// A parent whose `count` children, each entering from scale 0, are staggered by `stagger`.
fn spawn_staggered(app: &mut App, stagger: StaggerChildren, count: usize) -> (Entity, Vec<Entity>) {
    let parent = app
        .world_mut()
        .spawn((
            Transform::default(),
            stagger,
            Presence::default(),
            TranslationSpring::new(Spring::smooth(), Vec3::ZERO),
            EnterFrom::<Translation>(Vec3::Y * -100.0),
        ))
        .id();
    let children = (0..count)
        .map(|index| spawn_child(app, parent, index))
        .collect();
    (parent, children)
}

fn spawn_child(app: &mut App, parent: Entity, index: usize) -> Entity {
    app.world_mut()
        .spawn((
            Transform::from_xyz(index as f32 * 10.0, 0.0, 0.0),
            Presence::default(),
            ScaleSpring::new(Spring::smooth(), Vec3::ONE),
            EnterFrom::<Scale>(Vec3::splat(1e-3)),
            ChildOf(parent),
        ))
        .id()
}

fn scale(app: &App, entity: Entity) -> f32 {
    app.world().get::<Transform>(entity).unwrap().scale.x
}

fn elapsed(app: &App) -> f64 {
    app.world().resource::<Time<Virtual>>().elapsed_secs_f64()
}

/// The game time at which each entity first moved from where it entered from, running `frames`.
fn start_times(app: &mut App, entities: &[Entity], frames: u32) -> Vec<Option<f64>> {
    let mut started = vec![None; entities.len()];
    for _ in 0..frames {
        app.update();
        for (index, &entity) in entities.iter().enumerate() {
            if started[index].is_none() && scale(app, entity) != 1e-3 {
                started[index] = Some(elapsed(app));
            }
        }
    }
    started
}

/// Children start `interval` apart in each order: each holds its entering value exactly until
/// its turn, at every frame rate (a turn falls in the frame that reaches it).
#[test]
fn children_enter_one_after_another_in_each_order() {
    let interval = 0.1;
    let orders: [(StaggerOrder, [f64; 5]); 4] = [
        (StaggerOrder::First, [0.0, 1.0, 2.0, 3.0, 4.0]),
        (StaggerOrder::Last, [4.0, 3.0, 2.0, 1.0, 0.0]),
        (StaggerOrder::Centre, [2.0, 1.0, 0.0, 1.0, 2.0]),
        // Children at x = 0, 10, ..., 40: nearest to x = 31 first.
        (
            StaggerOrder::From(Vec3::X * 31.0),
            [4.0, 3.0, 2.0, 0.0, 1.0],
        ),
    ];
    for fps in [30, 60, 144, 240] {
        for (order, ranks) in orders {
            let mut app = app(fps);
            let (_, children) =
                spawn_staggered(&mut app, StaggerChildren::new(interval).from(order), 5);
            // The first update has dt = 0: the clock starts after it.
            app.update();
            let origin = elapsed(&app);
            let started = start_times(&mut app, &children, fps);
            let frame = 1.0 / f64::from(fps);
            for (index, rank) in ranks.iter().enumerate() {
                let due = rank * f64::from(interval);
                let at = started[index].expect("never started") - origin;
                assert!(
                    at >= due - 1e-6 && at < due + frame + 1e-6,
                    "{fps} fps, {order:?}: child {index} started at {at}, due at {due}"
                );
            }
        }
    }
}

/// `BeforeChildren`: no child moves until the parent has entered. `AfterChildren`: the parent
/// holds still until every child has entered.
#[test]
fn a_parent_enters_before_or_after_its_children() {
    let mut app = app(60);
    listen(&mut app);
    let (parent, children) = spawn_staggered(
        &mut app,
        StaggerChildren::new(0.05).when(StaggerWhen::BeforeChildren),
        3,
    );
    for _ in 0..240 {
        app.update();
        let parent_entered = heard(&app, parent) == ["entered"];
        if !parent_entered {
            for &child in &children {
                assert_eq!(scale(&app, child), 1e-3, "a child moved first");
            }
        }
    }
    for &child in &children {
        assert_eq!(heard(&app, child), ["entered"]);
    }

    let mut app = crate::harness::app(60);
    listen(&mut app);
    let (parent, children) = spawn_staggered(
        &mut app,
        StaggerChildren::new(0.05).when(StaggerWhen::AfterChildren),
        3,
    );
    for _ in 0..300 {
        app.update();
        let all_entered = children
            .iter()
            .all(|&child| heard(&app, child) == ["entered"]);
        if !all_entered {
            assert_eq!(
                translation(&app, parent).y,
                -100.0,
                "the parent moved first"
            );
        }
    }
    assert_eq!(translation(&app, parent).y, 0.0);
    assert_eq!(heard(&app, parent), ["entered"]);
}

/// A child added while others wait starts after the last of them; a child asked to leave
/// while it waits leaves at once from where it is, and is despawned.
#[test]
fn later_children_join_and_waiting_children_can_leave() {
    let mut app = app(60);
    listen(&mut app);
    let (parent, children) = spawn_staggered(&mut app, StaggerChildren::new(0.2), 3);
    app.update();
    let origin = elapsed(&app);
    run(&mut app, 3);
    let late = spawn_child(&mut app, parent, 3);
    // The third child waits for its turn at 0.4 s: it leaves instead.
    exit(&mut app, children[2]);
    let mut all = children.clone();
    all.push(late);
    let started = start_times(&mut app, &all, 120);
    let late_start = started[3].unwrap() - origin;
    assert!(
        late_start >= 0.6 - 1e-6,
        "the late child started at {late_start}"
    );
    // The leaving child never grew: it shrinks from where it was, which is where it is.
    assert!(app.world().get_entity(children[2]).is_err());
    assert_eq!(heard(&app, children[2]), ["exited"]);
}
