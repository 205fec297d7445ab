//! The world changes under a spring: entities despawned (also inside the plugin's own event
//! observers), spring components replaced, removed and inserted again, follow targets that
//! vanish, group members that leave, springs removed mid-drag, and values at the edge of `f32`.
//! Each test protects one defined behaviour (see the README's "How stable").

use bevy::prelude::*;
use bevy_sprung::choreography::{
    AllSpringsSettled, SequenceCompleted, SpringGroup, SpringGroupSettled,
};
use bevy_sprung::interaction::SpringDrag;
use bevy_sprung::prelude::*;
use bevy_sprung::property::{SpringProperty, ValueOf};
use bevy_sprung::transform::Scale;
use bevy_sprung::ui::UiTransformRotationSpring;
use bevy_sprung::ui::{NodeSize, UiTransformRotation, UiTransformTranslationSpring};
use bevy_sprung::visibility::CatchUpWhenHidden;

use crate::harness::{app, asleep, assert_stepped_from, run, spawn_translation, translation};
use crate::interaction::{drag, drag_end, drag_start, ui_position};

/// Marks an entity whose settle event an observer saw.
#[derive(Component)]
struct Arrived;

/// The other entity of a pair: an observer despawns it when this one's event arrives.
#[derive(Component)]
struct Partner(Entity);

/// How many events of each kind the observers saw, and for which entities.
#[derive(Resource, Default)]
struct Seen(Vec<(&'static str, Entity)>);

impl Seen {
    fn count(&self, kind: &str) -> usize {
        self.0.iter().filter(|(seen, _)| *seen == kind).count()
    }
}

/// Two entities that settle in the same frame, each the other's partner; `spawn` adds to each
/// what makes it report (a spring, a sequence, a group).
fn pair(app: &mut App, spawn: impl Fn(&mut EntityWorldMut)) -> (Entity, Entity) {
    let a = spawn_translation(app, Spring::snappy(), Vec3::ZERO, Vec3::X * 10.0);
    let b = spawn_translation(app, Spring::snappy(), Vec3::ZERO, Vec3::X * 10.0);
    for (this, other) in [(a, b), (b, a)] {
        let mut entity = app.world_mut().entity_mut(this);
        entity.insert(Partner(other));
        spawn(&mut entity);
    }
    (a, b)
}

/// Ordinary observer code for event `E`: mark the entity (which panics for a despawned one) and
/// despawn its partner.
fn mark_and_despawn_partner<E: EntityEvent>(app: &mut App, kind: &'static str) {
    app.init_resource::<Seen>()
        .add_observer(
            move |event: On<E>, mut commands: Commands, mut seen: ResMut<Seen>| {
                seen.0.push((kind, event.event_target()));
                commands.entity(event.event_target()).insert(Arrived);
            },
        )
        .add_observer(
            |event: On<E>, partners: Query<&Partner>, mut commands: Commands| {
                if let Ok(partner) = partners.get(event.event_target()) {
                    commands.entity(partner.0).despawn();
                }
            },
        );
}

/// The partner despawned by the first event's observer hears nothing: one event, for the live
/// entity, and no panic in the observer that marks it.
fn assert_one_event_for_the_survivor(app: &mut App, (a, b): (Entity, Entity), kind: &str) {
    run(app, 180);
    let alive: Vec<Entity> = [a, b]
        .into_iter()
        .filter(|&entity| app.world().get_entity(entity).is_ok())
        .collect();
    assert_eq!(alive.len(), 1, "{kind}: one of the pair is despawned");
    let seen = app.world().resource::<Seen>();
    assert_eq!(seen.count(kind), 1, "{kind}: {:?}", seen.0);
    assert_eq!(seen.0[0].1, alive[0]);
    assert!(app.world().get::<Arrived>(alive[0]).is_some());
}

#[test]
fn settle_events_are_not_delivered_for_entities_despawned_before_them() {
    let mut app = app(60);
    mark_and_despawn_partner::<SpringSettled<Translation>>(&mut app, "settled");
    let pair = pair(&mut app, |_| {});
    assert_one_event_for_the_survivor(&mut app, pair, "settled");
}

#[test]
fn sequence_completions_are_not_delivered_for_entities_despawned_before_them() {
    let mut app = app(60);
    mark_and_despawn_partner::<SequenceCompleted<Translation>>(&mut app, "completed");
    let pair = pair(&mut app, |entity| {
        entity.insert(SpringSequence::<Translation>::new().then(Vec3::Y * 5.0));
    });
    assert_one_event_for_the_survivor(&mut app, pair, "completed");
}

#[test]
fn group_settles_are_not_delivered_for_entities_despawned_before_them() {
    let mut app = app(60);
    mark_and_despawn_partner::<AllSpringsSettled>(&mut app, "all settled");
    let pair = pair(&mut app, |entity| {
        entity.insert(SpringGroup::this_entity());
    });
    assert_one_event_for_the_survivor(&mut app, pair, "all settled");
}

/// A spring that sleeps and is then replaced (or removed and inserted again) moves to its new
/// target: the new spring starts from wherever the property is, awake.
fn replaced_spring_moves<P: SpringProperty>(
    spawn: impl Fn(&mut App) -> Entity,
    replacement: PropertySpring<P>,
    value: impl Fn(&App, Entity) -> ValueOf<P>,
) where
    ValueOf<P>: PartialEq + core::fmt::Debug,
{
    for remove_first in [false, true] {
        let mut app = app(60);
        let entity = spawn(&mut app);
        run(&mut app, 300);
        assert!(asleep::<P>(&app, entity), "the first spring settled");
        let mut world_entity = app.world_mut().entity_mut(entity);
        if remove_first {
            world_entity.remove::<PropertySpring<P>>();
        }
        world_entity.insert(replacement);
        run(&mut app, 300);
        assert_eq!(
            value(&app, entity),
            replacement.target(),
            "removed first: {remove_first}"
        );
        assert!(asleep::<P>(&app, entity));
    }
}

#[test]
fn a_sleeping_spring_replaced_or_inserted_again_moves_to_its_new_target() {
    replaced_spring_moves::<Translation>(
        |app| spawn_translation(app, Spring::snappy(), Vec3::ZERO, Vec3::X * 10.0),
        TranslationSpring::new(Spring::snappy(), Vec3::new(0.0, 50.0, 0.0)),
        translation,
    );
    replaced_spring_moves::<Scale>(
        |app| {
            app.world_mut()
                .spawn((
                    Transform::default(),
                    ScaleSpring::new(Spring::bouncy(), Vec3::splat(2.0)),
                ))
                .id()
        },
        ScaleSpring::new(Spring::snappy(), Vec3::splat(0.5)),
        |app, entity| app.world().get::<Transform>(entity).unwrap().scale,
    );
    let white = Color::WHITE;
    let red = Color::srgb(1.0, 0.0, 0.0);
    replaced_spring_moves::<BackgroundColor>(
        |app| {
            app.world_mut()
                .spawn((
                    Node::default(),
                    BackgroundColor(Color::BLACK),
                    BackgroundColorSpring::new(Spring::snappy(), white),
                ))
                .id()
        },
        BackgroundColorSpring::new(Spring::snappy(), red),
        |app, entity| app.world().get::<BackgroundColor>(entity).unwrap().0,
    );
    replaced_spring_moves::<NodeSize>(
        |app| {
            app.world_mut()
                .spawn((
                    Node::default(),
                    NodeSizeSpring::new(Spring::snappy(), Val2::px(100.0, 40.0)),
                ))
                .id()
        },
        NodeSizeSpring::new(Spring::snappy(), Val2::px(300.0, 80.0)),
        |app, entity| {
            let node = app.world().get::<Node>(entity).unwrap();
            Val2::new(node.width, node.height)
        },
    );
}

#[derive(Component)]
struct Leader(Vec3);

/// The leader walks at its velocity, every frame.
fn walk(time: Res<Time>, mut leaders: Query<(&Leader, &mut Transform)>) {
    for (leader, mut transform) in &mut leaders {
        transform.translation += leader.0 * time.delta_secs();
    }
}

/// How the followed leader goes away.
#[derive(Clone, Copy, Debug)]
enum Vanish {
    Despawn,
    RemoveTransform,
    DespawnParent,
    Unfollow,
}

/// A follower of a walking leader comes to rest (asleep, exactly on its last goal, no target
/// velocity left) once the leader is gone, however it went and however it moved.
#[test]
fn a_follower_comes_to_rest_when_its_target_vanishes() {
    const WALK: Vec3 = Vec3::new(60.0, 0.0, 20.0);
    const OFFSET: Vec3 = Vec3::new(0.0, 5.0, 10.0);
    for fixed in [false, true] {
        for stop_first in [false, true] {
            for vanish in [
                Vanish::Despawn,
                Vanish::RemoveTransform,
                Vanish::DespawnParent,
                Vanish::Unfollow,
            ] {
                let case = format!("fixed {fixed}, stopped first {stop_first}, {vanish:?}");
                let mut app = app(60);
                app.insert_resource(Time::<Fixed>::from_hz(64.0));
                if fixed {
                    app.add_systems(FixedUpdate, walk);
                } else {
                    app.add_systems(Update, walk);
                }
                let parent = app.world_mut().spawn(Transform::default()).id();
                let leader = app
                    .world_mut()
                    .spawn((Transform::default(), Leader(WALK), ChildOf(parent)))
                    .id();
                let mut follow = SpringFollow::new(leader, OFFSET);
                if fixed {
                    follow = follow.moving_in_fixed_update();
                }
                let camera = app
                    .world_mut()
                    .spawn((
                        Transform::from_translation(OFFSET),
                        TranslationSpring::new(Spring::smooth(), OFFSET),
                        follow,
                    ))
                    .id();
                run(&mut app, 120);
                if stop_first {
                    app.world_mut().get_mut::<Leader>(leader).unwrap().0 = Vec3::ZERO;
                    run(&mut app, 30);
                }
                match vanish {
                    Vanish::Despawn => {
                        app.world_mut().despawn(leader);
                    }
                    Vanish::RemoveTransform => {
                        app.world_mut().entity_mut(leader).remove::<Transform>();
                    }
                    Vanish::DespawnParent => {
                        app.world_mut().despawn(parent);
                    }
                    Vanish::Unfollow => {
                        let mut camera = app.world_mut().entity_mut(camera);
                        camera.remove::<SpringFollow>();
                        camera
                            .get_mut::<TranslationSpring>()
                            .unwrap()
                            .set_target(Vec3::new(-40.0, 30.0, 0.0));
                    }
                }
                run(&mut app, 20 * 60);
                let spring = *app.world().get::<TranslationSpring>(camera).unwrap();
                assert_eq!(spring.target_velocity(), Vec3::ZERO, "{case}");
                assert!(asleep::<Translation>(&app, camera), "{case}");
                assert_eq!(translation(&app, camera), spring.target(), "{case}");
                assert!(spring.target().is_finite(), "{case}");
            }
        }
    }
}

#[derive(Resource, Default)]
struct GroupReports(usize);

/// A group whose slow member vanishes (despawned between frames, inside another member's
/// observer, or its spring removed) reports once its remaining springs have settled.
#[test]
fn a_group_reports_when_its_moving_member_vanishes() {
    for how in [
        "despawn",
        "despawn in an observer",
        "remove the spring",
        "leave the group",
    ] {
        let mut app = app(60);
        app.init_resource::<GroupReports>().add_observer(
            |_: On<SpringGroupSettled>, mut reports: ResMut<GroupReports>| reports.0 += 1,
        );
        let fast = spawn_translation(&mut app, Spring::snappy(), Vec3::ZERO, Vec3::X);
        let slow = spawn_translation(&mut app, Spring::molasses(), Vec3::ZERO, Vec3::X * 1e4);
        for member in [fast, slow] {
            app.world_mut()
                .entity_mut(member)
                .insert(SpringGroup::named("menu"));
        }
        if how == "despawn in an observer" {
            app.world_mut().entity_mut(fast).observe(
                move |_: On<SpringSettled<Translation>>, mut commands: Commands| {
                    commands.entity(slow).despawn();
                },
            );
        }
        run(&mut app, 120);
        assert!(asleep::<Translation>(&app, fast), "{how}");
        if how != "despawn in an observer" {
            assert_eq!(app.world().resource::<GroupReports>().0, 0, "{how}");
        }
        match how {
            "despawn" => {
                app.world_mut().despawn(slow);
            }
            "remove the spring" => {
                app.world_mut()
                    .entity_mut(slow)
                    .remove::<TranslationSpring>();
            }
            "leave the group" => {
                app.world_mut().entity_mut(slow).remove::<SpringGroup>();
            }
            _ => {}
        }
        run(&mut app, 60);
        assert_eq!(app.world().resource::<GroupReports>().0, 1, "{how}");
    }
}

/// A group whose members are all despawned while moving reports once: none of its springs is
/// moving any more.
#[test]
fn a_group_whose_members_all_vanish_reports_once() {
    let mut app = app(60);
    app.init_resource::<GroupReports>().add_observer(
        |_: On<SpringGroupSettled>, mut reports: ResMut<GroupReports>| reports.0 += 1,
    );
    let members: Vec<Entity> = (0..3)
        .map(|i| {
            let member = spawn_translation(&mut app, Spring::molasses(), Vec3::ZERO, Vec3::X * 1e3);
            app.world_mut()
                .entity_mut(member)
                .insert(SpringGroup::named(if i < 2 { "a" } else { "b" }));
            member
        })
        .collect();
    run(&mut app, 10);
    for member in &members[..2] {
        app.world_mut().despawn(*member);
    }
    run(&mut app, 10);
    assert_eq!(
        app.world().resource::<GroupReports>().0,
        1,
        "group a vanished"
    );
    app.world_mut().despawn(members[2]);
    run(&mut app, 10);
    assert_eq!(
        app.world().resource::<GroupReports>().0,
        2,
        "group b vanished"
    );
}

/// A drag whose spring (or value) is removed mid-drag ends on release: the entity is no longer
/// dragged, and the next drag grabs it afresh.
#[test]
fn a_drag_ends_on_release_after_its_spring_was_removed() {
    for remove_value in [false, true] {
        let mut app = app(60);
        let card = app
            .world_mut()
            .spawn((
                Node::default(),
                UiTransform::default(),
                UiTransformTranslationSpring::new(Spring::smooth(), Val2::px(0.0, 0.0)),
                SpringDrag::new(),
            ))
            .id();
        run(&mut app, 2);
        drag_start(
            app.world_mut(),
            card,
            Vec2::new(100.0, 100.0),
            Entity::PLACEHOLDER,
        );
        drag(app.world_mut(), card, Vec2::new(120.0, 100.0));
        run(&mut app, 1);
        assert_eq!(ui_position(&app, card), Vec2::new(20.0, 0.0));
        if remove_value {
            app.world_mut().entity_mut(card).remove::<UiTransform>();
        } else {
            app.world_mut()
                .entity_mut(card)
                .remove::<UiTransformTranslationSpring>();
        }
        run(&mut app, 1);
        drag_end(app.world_mut(), card, Vec2::new(120.0, 100.0));
        run(&mut app, 1);
        if remove_value {
            app.world_mut()
                .entity_mut(card)
                .insert(UiTransform::from_translation(Val2::px(20.0, 0.0)));
        } else {
            app.world_mut()
                .entity_mut(card)
                .insert(UiTransformTranslationSpring::new(
                    Spring::smooth(),
                    Val2::px(20.0, 0.0),
                ));
        }
        run(&mut app, 2);
        assert!(
            !app.world().get::<SpringDrag>(card).unwrap().is_dragged(),
            "remove value: {remove_value}"
        );
        // A new 10 px drag moves the card 10 px.
        drag_start(
            app.world_mut(),
            card,
            Vec2::new(400.0, 300.0),
            Entity::PLACEHOLDER,
        );
        drag(app.world_mut(), card, Vec2::new(410.0, 300.0));
        run(&mut app, 1);
        assert_eq!(
            ui_position(&app, card),
            Vec2::new(30.0, 0.0),
            "remove value: {remove_value}"
        );
    }
}

/// A huge but finite angular velocity, however it is given, never writes a NaN rotation (nor,
/// through a shake on the same entity, a NaN translation), and the spring still arrives.
#[test]
fn a_huge_angular_velocity_never_writes_nan_and_still_arrives() {
    let target = Quat::from_rotation_z(1.0);
    for how in ["impulse", "set velocity", "with velocity", "with a shake"] {
        for speed in [1e20_f32, 1e25, 1e30, f32::MAX] {
            let mut app = app(60);
            let velocity = Vec3::new(speed, 0.0, 0.0);
            let mut spring = RotationSpring::new(Spring::snappy(), target);
            if how == "with velocity" {
                spring = spring.with_velocity(velocity);
            }
            let entity = app.world_mut().spawn((Transform::default(), spring)).id();
            if how == "with a shake" {
                let mut shake = Shake::new(3)
                    .with_max_translation(Vec3::splat(5.0))
                    .with_max_rotation(Vec3::splat(0.1));
                shake.add_trauma(1.0);
                app.world_mut().entity_mut(entity).insert(shake);
            }
            run(&mut app, 2);
            let mut spring = app.world_mut().get_mut::<RotationSpring>(entity).unwrap();
            match how {
                "set velocity" => spring.set_velocity(velocity),
                "with velocity" => {}
                _ => spring.add_impulse(velocity),
            }
            for frame in 0..30 * 60 {
                app.update();
                let transform = app.world().get::<Transform>(entity).unwrap();
                assert!(
                    transform.rotation.is_finite() && transform.translation.is_finite(),
                    "{how}, {speed:e}, frame {frame}: {transform:?}"
                );
            }
            let rotation = app.world().get::<Transform>(entity).unwrap().rotation;
            assert!(asleep::<Rotation>(&app, entity), "{how}, {speed:e}");
            assert!(rotation.angle_between(target) < 1e-3, "{how}, {speed:e}");
        }
    }
}

/// A UI rotation spring toward a rotation that is not one (zero, or with an infinite part)
/// holds still, also beside a moving spring with the same parameters (whose transition it would
/// share).
#[test]
fn a_ui_rotation_spring_toward_an_invalid_rotation_holds_still() {
    for bad in [
        Rot2 { cos: 0.0, sin: 0.0 },
        Rot2 {
            cos: 0.0,
            sin: f32::INFINITY,
        },
        Rot2 {
            cos: 1e30,
            sin: 1e30,
        },
        Rot2 {
            cos: f32::NAN,
            sin: 0.0,
        },
    ] {
        let mut app = app(60);
        let start = Rot2::radians(0.5);
        let spawn = |app: &mut App, target: Rot2| {
            app.world_mut()
                .spawn((
                    Node::default(),
                    UiTransform {
                        rotation: start,
                        ..default()
                    },
                    UiTransformRotationSpring::new(Spring::molasses(), target),
                ))
                .id()
        };
        let moving = spawn(&mut app, Rot2::radians(-1.0));
        run(&mut app, 10);
        let still = spawn(&mut app, bad);
        run(&mut app, 600);
        let rotation = |entity| app.world().get::<UiTransform>(entity).unwrap().rotation;
        assert_eq!(rotation(still), start, "{bad:?}");
        assert!(
            (rotation(moving).as_radians() + 1.0).abs() < 1e-3,
            "{bad:?}: {:?}",
            rotation(moving)
        );
        assert!(asleep::<UiTransformRotation>(&app, moving));
    }
}

#[derive(Resource)]
struct Retarget(Entity, Vec3);

fn retarget(target: Res<Retarget>, mut springs: Query<&mut TranslationSpring>) {
    if let Ok(mut spring) = springs.get_mut(target.0) {
        spring.set_target_if_neq(target.1);
    }
}

/// A spring spawned toward a non-finite target holds still; retargeted to a finite one, it moves
/// there from where it is, by the exact step: no NaN on the first frame, no jump to the target.
#[test]
fn a_spring_spawned_toward_a_non_finite_target_later_moves_by_the_exact_step() {
    let mut app = app(60);
    let entity = spawn_translation(
        &mut app,
        Spring::snappy(),
        Vec3::ZERO,
        Vec3::new(1.0, f32::INFINITY, 0.0),
    );
    let goal = Vec3::new(1.0, 2.0, 0.0);
    app.insert_resource(Retarget(entity, goal))
        .add_systems(Update, retarget);
    // The first update has dt = 0: retargeted, not yet moved.
    app.update();
    assert_eq!(translation(&app, entity), Vec3::ZERO);
    app.update();
    assert_stepped_from(
        &app,
        entity,
        Spring::snappy(),
        (Vec3::ZERO, Vec3::ZERO),
        goal,
    );
    run(&mut app, 300);
    assert_eq!(translation(&app, entity), goal);

    // Paused: nothing moves, and no NaN is written.
    let mut app = crate::harness::app(60);
    app.world_mut().resource_mut::<Time<Virtual>>().pause();
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            ScaleSpring::new(Spring::snappy(), Vec3::new(1.0, f32::INFINITY, 1.0)),
        ))
        .id();
    run(&mut app, 3);
    app.world_mut()
        .get_mut::<ScaleSpring>(entity)
        .unwrap()
        .set_target(Vec3::splat(2.0));
    run(&mut app, 3);
    assert_eq!(
        app.world().get::<Transform>(entity).unwrap().scale,
        Vec3::ONE
    );
    app.world_mut().resource_mut::<Time<Virtual>>().unpause();
    run(&mut app, 300);
    assert_eq!(
        app.world().get::<Transform>(entity).unwrap().scale,
        Vec3::splat(2.0)
    );
}

/// A sleeping spring whose property something else moves (a teleport, a value set by hand, a
/// NaN) wakes and springs back to its target: sleeping saves work and changes nothing a spring
/// does. Its own value written back does not wake it, nor does a write to another field of the
/// same component.
#[test]
fn a_sleeping_spring_whose_property_is_moved_springs_back() {
    for moved in [Vec3::new(40.0, -3.0, 2.0), Vec3::NAN] {
        let mut app = app(60);
        let target = Vec3::new(10.0, 0.0, 0.0);
        let entity = spawn_translation(&mut app, Spring::snappy(), Vec3::ZERO, target);
        run(&mut app, 120);
        assert!(asleep::<Translation>(&app, entity));
        let mut transform = app.world_mut().get_mut::<Transform>(entity).unwrap();
        transform.translation = target;
        transform.scale = Vec3::splat(2.0);
        run(&mut app, 2);
        assert!(
            asleep::<Translation>(&app, entity),
            "not moved: still asleep"
        );
        app.world_mut()
            .get_mut::<Transform>(entity)
            .unwrap()
            .translation = moved;
        app.update();
        if moved.is_finite() {
            assert!(!asleep::<Translation>(&app, entity), "{moved}: woken");
            assert_stepped_from(&app, entity, Spring::snappy(), (moved, Vec3::ZERO), target);
        } else {
            // Restored from the spring's own state (at rest: the target), at once.
            assert_eq!(translation(&app, entity), target);
        }
        run(&mut app, 120);
        assert!(asleep::<Translation>(&app, entity));
        assert_eq!(translation(&app, entity), target);
    }
}

/// A shake on a `Transform` whose rotation something else made huge and not a unit quaternion
/// is not applied, rather than writing a NaN translation.
#[test]
fn a_shake_never_writes_nan_over_a_rotation_that_is_not_a_unit_quaternion() {
    let mut app = app(60);
    let mut shake = Shake::new(7).with_max_translation(Vec3::splat(5.0));
    shake.add_trauma(1.0);
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_rotation(Quat::from_xyzw(236.5, -32.8, 421.0, -3.4e38)),
            shake,
        ))
        .id();
    for _ in 0..30 {
        app.update();
        assert!(translation(&app, entity).is_finite());
    }
}

/// Springs that may skip frames while hidden take reduced motion as every spring does: a hidden
/// one snaps under `Snap` rather than freezing until it is seen.
#[test]
fn hidden_springs_follow_reduced_motion() {
    let mut app = app(60);
    app.insert_resource(ReducedMotion::Snap);
    let target = Vec3::new(4.0, 5.0, 6.0);
    let entity = spawn_translation(&mut app, Spring::molasses(), Vec3::ZERO, target);
    app.world_mut().entity_mut(entity).insert((
        CatchUpWhenHidden,
        bevy::camera::visibility::ViewVisibility::HIDDEN,
    ));
    run(&mut app, 3);
    assert_eq!(translation(&app, entity), target);
    assert!(asleep::<Translation>(&app, entity));
}

/// A shake's tilt, added to a rotation that was not one (zero), is not "taken off" a rotation
/// written since: no NaN, what was written is kept.
#[test]
fn a_shake_never_takes_a_nan_off_a_written_rotation() {
    let mut app = app(60);
    let mut shake = Shake::new(7).with_max_rotation(Vec3::splat(0.1));
    shake.add_trauma(1.0);
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_rotation(Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)),
            shake,
        ))
        .id();
    run(&mut app, 3);
    let written = Quat::from_rotation_y(0.5);
    app.world_mut()
        .get_mut::<Transform>(entity)
        .unwrap()
        .rotation = written;
    for _ in 0..10 {
        app.update();
        let rotation = app.world().get::<Transform>(entity).unwrap().rotation;
        assert!(rotation.is_finite(), "{rotation}");
    }
}

/// A spring toward a target at the edge of `f32` (a `Node` width of `3.4e38` px) that
/// overshoots past it meets the edge as a wall: the value stays finite and arrives.
#[test]
fn a_target_at_the_edge_of_f32_is_reached_without_leaving_it() {
    let mut app = app(60);
    let target = Val2::px(f32::MAX, 10.0);
    let entity = app
        .world_mut()
        .spawn((
            Node::default(),
            NodeSizeSpring::new(Spring::wobbly(), target).with_velocity(Vec2::new(f32::MAX, 0.0)),
        ))
        .id();
    for _ in 0..600 {
        app.update();
        let node = app.world().get::<Node>(entity).unwrap();
        let (Val::Px(width) | Val::Percent(width)) = node.width else {
            continue;
        };
        assert!(width.is_finite(), "{:?}", node.width);
    }
    let node = app.world().get::<Node>(entity).unwrap();
    assert_eq!(Val2::new(node.width, node.height), target);
}

/// A follower told to follow itself (a misconfiguration) rests where it is told to be instead of
/// running away from itself, with one warning.
#[test]
fn a_follower_of_itself_rests() {
    let mut app = app(60);
    let follower = spawn_translation(&mut app, Spring::smooth(), Vec3::ZERO, Vec3::X);
    app.world_mut()
        .entity_mut(follower)
        .insert(SpringFollow::new(follower, Vec3::new(0.0, 5.0, 0.0)));
    run(&mut app, 600);
    assert!(asleep::<Translation>(&app, follower));
    assert_eq!(translation(&app, follower), Vec3::X);
}
