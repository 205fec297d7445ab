//! Pointer interaction through synthetic `bevy_picking` events: states and their targets,
//! velocity kept across state changes, drag, release velocity, fling and snap, rubber-band
//! bounds, and world-space drags through a camera.

use bevy::camera::NormalizedRenderTarget;
use bevy::camera::{ComputedCameraValues, RenderTargetInfo};
use bevy::input_focus::InputFocus;
use bevy::picking::backend::HitData;
use bevy::picking::events::{Drag, DragEnd, DragStart, Enter, Leave, Pointer, Press, Release};
use bevy::picking::pointer::{Location, PointerButton, PointerId};
use bevy::prelude::*;
use bevy::ui::InteractionDisabled;
use bevy_sprung::interaction::{
    DragBounds, InteractionState, InteractionTargets, Snap, SpringDrag,
};
use bevy_sprung::prelude::*;
use bevy_sprung::transform::Scale;
use bevy_sprung::ui::{UiTransformTranslation, UiTransformTranslationSpring};
use sprung::SpringState;

use crate::harness::{app, motion, run};

fn location(position: Vec2) -> Location {
    Location {
        target: NormalizedRenderTarget::None {
            width: 800,
            height: 600,
        },
        position,
    }
}

fn hit(camera: Entity) -> HitData {
    HitData::new(camera, 0.0, None, None)
}

/// Triggers pointer event `event` on `entity` with the mouse at `position`.
fn pointer<E: core::fmt::Debug + Clone + Reflect>(
    world: &mut World,
    entity: Entity,
    position: Vec2,
    event: E,
) {
    world.trigger(Pointer::new(
        PointerId::Mouse,
        location(position),
        event,
        entity,
    ));
}

pub(crate) fn enter(world: &mut World, entity: Entity) {
    pointer(
        world,
        entity,
        Vec2::ZERO,
        Enter {
            hit: hit(Entity::PLACEHOLDER),
            is_in_bounds: true,
        },
    );
}

pub(crate) fn press(world: &mut World, entity: Entity) {
    pointer(
        world,
        entity,
        Vec2::ZERO,
        Press {
            button: PointerButton::Primary,
            hit: hit(Entity::PLACEHOLDER),
            count: 1,
        },
    );
}

pub(crate) fn release(world: &mut World, entity: Entity) {
    pointer(
        world,
        entity,
        Vec2::ZERO,
        Release {
            button: PointerButton::Primary,
            hit: hit(Entity::PLACEHOLDER),
        },
    );
}

pub(crate) fn leave(world: &mut World, entity: Entity) {
    pointer(
        world,
        entity,
        Vec2::ZERO,
        Leave {
            hit: hit(Entity::PLACEHOLDER),
            was_in_bounds: true,
        },
    );
}

pub(crate) fn drag_start(world: &mut World, entity: Entity, position: Vec2, camera: Entity) {
    pointer(
        world,
        entity,
        position,
        DragStart {
            button: PointerButton::Primary,
            hit: hit(camera),
        },
    );
}

pub(crate) fn drag(world: &mut World, entity: Entity, position: Vec2) {
    pointer(
        world,
        entity,
        position,
        Drag {
            button: PointerButton::Primary,
            distance: Vec2::ZERO,
            delta: Vec2::ZERO,
        },
    );
}

pub(crate) fn drag_end(world: &mut World, entity: Entity, position: Vec2) {
    pointer(
        world,
        entity,
        position,
        DragEnd {
            button: PointerButton::Primary,
            distance: Vec2::ZERO,
        },
    );
    // The release's commands (its event) land now, before the next frame steps the spring.
    world.flush();
}

fn state(app: &App, entity: Entity) -> InteractionState {
    *app.world().get::<InteractionState>(entity).unwrap()
}

fn scale_target(app: &App, entity: Entity) -> Vec3 {
    app.world().get::<ScaleSpring>(entity).unwrap().target()
}

const IDLE: Vec3 = Vec3::ONE;
const HOVERED: Vec3 = Vec3::splat(1.1);
const PRESSED: Vec3 = Vec3::splat(0.9);
const DISABLED: Vec3 = Vec3::splat(0.8);

fn spawn_button(app: &mut App) -> Entity {
    app.world_mut()
        .spawn((
            Transform::default(),
            ScaleSpring::new(Spring::bouncy(), IDLE),
            InteractionTargets::<Scale>::new(IDLE)
                .hovered(HOVERED)
                .pressed(PRESSED)
                .disabled(DISABLED),
        ))
        .id()
}

/// Every state retargets the spring, with the fallbacks: dragged takes pressed's target.
#[test]
fn states_map_to_targets() {
    let mut app = app(60);
    let button = spawn_button(&mut app);
    run(&mut app, 2);
    assert_eq!(state(&app, button), InteractionState::Idle);
    enter(app.world_mut(), button);
    run(&mut app, 1);
    assert_eq!(state(&app, button), InteractionState::Hovered);
    assert_eq!(scale_target(&app, button), HOVERED);
    press(app.world_mut(), button);
    run(&mut app, 1);
    assert_eq!(state(&app, button), InteractionState::Pressed);
    assert_eq!(scale_target(&app, button), PRESSED);
    drag_start(app.world_mut(), button, Vec2::ZERO, Entity::PLACEHOLDER);
    run(&mut app, 1);
    assert_eq!(state(&app, button), InteractionState::Dragged);
    assert_eq!(scale_target(&app, button), PRESSED);
    drag_end(app.world_mut(), button, Vec2::ZERO);
    run(&mut app, 1);
    assert_eq!(state(&app, button), InteractionState::Hovered);
    assert_eq!(scale_target(&app, button), HOVERED);
    press(app.world_mut(), button);
    release(app.world_mut(), button);
    pointer(
        app.world_mut(),
        button,
        Vec2::ZERO,
        Leave {
            hit: hit(Entity::PLACEHOLDER),
            was_in_bounds: true,
        },
    );
    run(&mut app, 1);
    assert_eq!(state(&app, button), InteractionState::Idle);
    assert_eq!(scale_target(&app, button), IDLE);

    // Focus shows when no pointer is on it; disabled wins over everything.
    app.insert_resource(InputFocus::from_entity(button));
    run(&mut app, 1);
    assert_eq!(state(&app, button), InteractionState::Focused);
    assert_eq!(
        scale_target(&app, button),
        HOVERED,
        "focused falls back to hovered"
    );
    app.world_mut()
        .entity_mut(button)
        .insert(InteractionDisabled);
    enter(app.world_mut(), button);
    run(&mut app, 1);
    assert_eq!(state(&app, button), InteractionState::Disabled);
    assert_eq!(scale_target(&app, button), DISABLED);
    app.world_mut()
        .entity_mut(button)
        .remove::<InteractionDisabled>();
    run(&mut app, 1);
    assert_eq!(state(&app, button), InteractionState::Hovered);
}

/// A pointer event on a child counts for the parent only through Bevy's own propagation; an
/// entity without `InteractionState` is never touched.
#[test]
fn events_reach_only_entities_that_opted_in() {
    let mut app = app(60);
    let plain = app.world_mut().spawn(Transform::default()).id();
    run(&mut app, 1);
    enter(app.world_mut(), plain);
    press(app.world_mut(), plain);
    run(&mut app, 1);
    assert!(app.world().get::<InteractionState>(plain).is_none());
}

/// Released mid-press, the button turns from "pressed" back to "hovered" with the velocity it
/// had: the next frame is the exact step from its state toward the new target.
#[test]
fn state_changes_keep_the_velocity() {
    let mut app = app(60);
    let button = spawn_button(&mut app);
    run(&mut app, 2);
    enter(app.world_mut(), button);
    run(&mut app, 20);
    press(app.world_mut(), button);
    run(&mut app, 4);
    let spring = *app.world().get::<ScaleSpring>(button).unwrap();
    let (x, v) = (
        app.world().get::<Transform>(button).unwrap().scale.x,
        motion::<Scale>(&app, button).velocity().x,
    );
    assert!(v.abs() > 0.1, "still moving: {v}");
    release(app.world_mut(), button);
    run(&mut app, 1);
    let after = app.world().get::<Transform>(button).unwrap().scale.x;
    let exact = sprung::Spring::<f64>::from(*spring.spring())
        .transition(1.0 / 60.0)
        .step(
            SpringState::new(f64::from(x), f64::from(v)),
            f64::from(HOVERED.x),
        );
    assert!(
        (f64::from(after) - exact.position).abs() < 1e-5,
        "{after} vs {}",
        exact.position
    );
}

/// What the observer saw of the last release.
#[derive(Resource, Default)]
struct Released(Vec<bevy_sprung::interaction::DragReleased>);

fn ui_card(app: &mut App, drag: SpringDrag) -> Entity {
    app.init_resource::<Released>().add_observer(
        |event: On<bevy_sprung::interaction::DragReleased>, mut seen: ResMut<Released>| {
            seen.0.push(*event);
        },
    );
    app.world_mut()
        .spawn((
            Node::default(),
            UiTransform::default(),
            UiTransformTranslationSpring::new(Spring::smooth(), Val2::px(0.0, 0.0)),
            drag,
        ))
        .id()
}

pub(crate) fn ui_position(app: &App, entity: Entity) -> Vec2 {
    let translation = app.world().get::<UiTransform>(entity).unwrap().translation;
    match (translation.x, translation.y) {
        (Val::Px(x), Val::Px(y)) => Vec2::new(x, y),
        other => panic!("not pixels: {other:?}"),
    }
}

/// Drags `entity` from `from` by `step` per frame for `frames` frames and lets go one step on.
fn throw(app: &mut App, entity: Entity, from: Vec2, step: Vec2, frames: u32) {
    drag_start(app.world_mut(), entity, from, Entity::PLACEHOLDER);
    drag(app.world_mut(), entity, from);
    run(app, 1);
    for i in 1..=frames {
        drag(app.world_mut(), entity, from + step * i as f32);
        run(app, 1);
    }
    drag_end(app.world_mut(), entity, from + step * (frames + 1) as f32);
}

/// Glued to the pointer while dragged (the spring does not pull it back), flung on release with
/// the pointer's velocity toward the slot nearest where the throw would rest, and at rest there.
#[test]
fn fling_snaps_to_the_slot_nearest_the_throw() {
    let slots = vec![Vec3::new(300.0, 0.0, 0.0), Vec3::new(600.0, 0.0, 0.0)];
    for (speed, slot) in [(600.0, 0), (1500.0, 1)] {
        let mut app = app(60);
        let card = ui_card(
            &mut app,
            SpringDrag::new()
                .snapping(Snap::Points(slots.clone()))
                .with_throw(0.3),
        );
        run(&mut app, 2);
        let step = Vec2::new(speed / 60.0, 0.0);
        drag_start(
            app.world_mut(),
            card,
            Vec2::new(100.0, 100.0),
            Entity::PLACEHOLDER,
        );
        drag(app.world_mut(), card, Vec2::new(100.0, 100.0));
        run(&mut app, 1);
        for i in 1..=12 {
            drag(
                app.world_mut(),
                card,
                Vec2::new(100.0, 100.0) + step * i as f32,
            );
            run(&mut app, 1);
            // Exactly where the pointer put it, frame after frame.
            assert_eq!(ui_position(&app, card), step * i as f32);
        }
        assert_eq!(state(&app, card), InteractionState::Dragged);
        run(&mut app, 3);
        assert_eq!(
            ui_position(&app, card),
            step * 12.0,
            "the spring does not pull"
        );
        // Moving again, then let go while moving.
        for i in 13..=20 {
            drag(
                app.world_mut(),
                card,
                Vec2::new(100.0, 100.0) + step * i as f32,
            );
            run(&mut app, 1);
        }
        drag_end(app.world_mut(), card, Vec2::new(100.0, 100.0) + step * 21.0);
        let released = app.world().resource::<Released>().0[0];
        assert!(
            (released.velocity.x - speed).abs() < 0.01 * speed && released.velocity.y.abs() < 1.0,
            "{released:?}"
        );
        assert_eq!(released.snapped, Some(slot), "{released:?}");
        assert_eq!(released.target, slots[slot]);
        let spring = *app
            .world()
            .get::<UiTransformTranslationSpring>(card)
            .unwrap();
        assert_eq!(spring.target(), Val2::px(slots[slot].x, slots[slot].y));
        // The next frame is the exact step from the release, with the pointer's velocity.
        let start = ui_position(&app, card);
        run(&mut app, 1);
        let transition = sprung::Spring::<f64>::from(*spring.spring()).transition(1.0 / 60.0);
        let velocity = motion::<UiTransformTranslation>(&app, card).velocity();
        for axis in 0..2 {
            let exact = transition.step(
                SpringState::new(f64::from(start[axis]), f64::from(released.velocity[axis])),
                f64::from(slots[slot][axis]),
            );
            assert!(
                (f64::from(velocity[axis]) - exact.velocity).abs() < 1e-4 * f64::from(speed),
                "axis {axis}: {velocity} vs {exact:?}"
            );
        }
        run(&mut app, 300);
        assert_eq!(ui_position(&app, card), slots[slot].truncate());
    }
}

/// A throw that comes to rest far from every slot goes home; one that stops before letting go
/// snaps from where it was dropped.
#[test]
fn far_throws_go_home_and_stopped_drags_do_not_fling() {
    let mut app = app(60);
    let card = ui_card(
        &mut app,
        SpringDrag::new()
            .snapping(Snap::Points(vec![Vec3::new(300.0, 0.0, 0.0)]))
            .within(100.0),
    );
    run(&mut app, 2);
    throw(&mut app, card, Vec2::ZERO, Vec2::new(0.0, 20.0), 10);
    let released = app.world().resource::<Released>().0[0];
    assert_eq!(released.snapped, None);
    assert_eq!(
        released.target,
        Vec3::ZERO,
        "home: the target before the drag"
    );
    run(&mut app, 300);
    assert_eq!(ui_position(&app, card), Vec2::ZERO);

    // Dragged to the slot, held still for 0.2 s, released: no fling, snapped.
    drag_start(app.world_mut(), card, Vec2::ZERO, Entity::PLACEHOLDER);
    for i in 1..=10 {
        drag(app.world_mut(), card, Vec2::new(29.0 * i as f32, 0.0));
        run(&mut app, 1);
    }
    run(&mut app, 12);
    drag_end(app.world_mut(), card, Vec2::new(290.0, 0.0));
    let released = app.world().resource::<Released>().0[1];
    assert_eq!(released.velocity, Vec3::ZERO);
    assert_eq!(released.snapped, Some(0));
}

/// Past the bounds the card follows less and less, never beyond `give`; released, it springs
/// back inside.
#[test]
fn rubber_band_bounds() {
    let bounds = DragBounds {
        min: Vec3::ZERO,
        max: Vec3::new(100.0, 0.0, 0.0),
        give: 50.0,
    };
    let mut app = app(60);
    let card = ui_card(
        &mut app,
        SpringDrag::new()
            .snapping(Snap::Free)
            .bounded(bounds)
            .with_throw(0.0),
    );
    run(&mut app, 2);
    drag_start(app.world_mut(), card, Vec2::ZERO, Entity::PLACEHOLDER);
    let mut last = 0.0;
    for i in 1..=40 {
        drag(app.world_mut(), card, Vec2::new(10.0 * i as f32, 0.0));
        run(&mut app, 1);
        let x = ui_position(&app, card).x;
        assert!(x >= last, "monotonic");
        if i > 10 {
            assert!(x > 100.0 && x < 150.0, "{x}");
            // Less than the pointer's 10 px per frame, and less each frame.
            assert!(x - last < 0.56 * 10.0, "{i}: {}", x - last);
        }
        last = x;
    }
    drag_end(app.world_mut(), card, Vec2::new(400.0, 0.0));
    run(&mut app, 300);
    assert_eq!(ui_position(&app, card), Vec2::new(100.0, 0.0));
}

/// A world-space drag: the pointer is projected through the camera that picked the entity onto
/// the plane through the entity, and the entity follows it in world units.
#[test]
fn world_space_drag_through_a_camera() {
    let mut app = app(60);
    // An orthographic camera 800 × 600 px, one unit per pixel, at z = 100 looking down −z.
    let camera = app
        .world_mut()
        .spawn((
            Camera {
                computed: ComputedCameraValues {
                    clip_from_view: Mat4::orthographic_rh(
                        -400.0, 400.0, -300.0, 300.0, 0.0, 1000.0,
                    ),
                    target_info: Some(RenderTargetInfo {
                        physical_size: UVec2::new(800, 600),
                        scale_factor: 1.0,
                    }),
                    ..default()
                },
                ..default()
            },
            Transform::from_xyz(0.0, 0.0, 100.0),
        ))
        .id();
    let card = app
        .world_mut()
        .spawn((
            Transform::from_xyz(10.0, 20.0, 5.0),
            TranslationSpring::new(Spring::smooth(), Vec3::new(10.0, 20.0, 5.0)),
            SpringDrag::new().snapping(Snap::Free).with_throw(0.0),
        ))
        .id();
    run(&mut app, 2);
    // Grabbed 5 px right of its centre (screen (415, 280) is world (15, 20)).
    drag_start(app.world_mut(), card, Vec2::new(415.0, 280.0), camera);
    drag(app.world_mut(), card, Vec2::new(415.0, 280.0));
    run(&mut app, 1);
    for i in 1..=10 {
        // Right and up on screen: +x, −y in pixels is +x, +y in the world.
        drag(
            app.world_mut(),
            card,
            Vec2::new(415.0 + 4.0 * i as f32, 280.0 - 2.0 * i as f32),
        );
        run(&mut app, 1);
        let translation = app.world().get::<Transform>(card).unwrap().translation;
        let expected = Vec3::new(10.0 + 4.0 * i as f32, 20.0 + 2.0 * i as f32, 5.0);
        assert!(
            translation.distance(expected) < 1e-3,
            "{translation} vs {expected}"
        );
    }
    // Snapped to a point at another depth, it keeps its own (a 2D card keeps its draw order).
    app.world_mut().get_mut::<SpringDrag>(card).unwrap().snap =
        Snap::Points(vec![Vec3::new(100.0, 100.0, -40.0)]);
    drag_end(app.world_mut(), card, Vec2::new(455.0, 260.0));
    let target = app.world().get::<TranslationSpring>(card).unwrap().target();
    assert_eq!(target, Vec3::new(100.0, 100.0, 5.0));
}

/// With a threshold, a press with a few pixels of jitter stays a click: never dragged, nothing
/// flung, the spring untouched. Past the threshold the drag takes the entity where it is (no
/// jump) and follows the pointer from there.
#[test]
fn drag_threshold_keeps_clicks_clicks() {
    let mut app = app(60);
    let card = ui_card(
        &mut app,
        SpringDrag::new()
            .snapping(Snap::Free)
            .with_throw(0.0)
            .with_threshold(6.0),
    );
    run(&mut app, 2);
    let moved = |distance: Vec2| Drag {
        button: PointerButton::Primary,
        distance,
        delta: Vec2::ZERO,
    };
    drag_start(
        app.world_mut(),
        card,
        Vec2::new(50.0, 50.0),
        Entity::PLACEHOLDER,
    );
    pointer(
        app.world_mut(),
        card,
        Vec2::new(52.0, 51.0),
        moved(Vec2::new(2.0, 1.0)),
    );
    run(&mut app, 1);
    assert_ne!(state(&app, card), InteractionState::Dragged);
    assert_eq!(ui_position(&app, card), Vec2::ZERO);
    drag_end(app.world_mut(), card, Vec2::new(52.0, 51.0));
    run(&mut app, 1);
    assert!(app.world().resource::<Released>().0.is_empty(), "a click");

    drag_start(
        app.world_mut(),
        card,
        Vec2::new(50.0, 50.0),
        Entity::PLACEHOLDER,
    );
    pointer(
        app.world_mut(),
        card,
        Vec2::new(54.0, 50.0),
        moved(Vec2::new(4.0, 0.0)),
    );
    run(&mut app, 1);
    assert_eq!(ui_position(&app, card), Vec2::ZERO);
    pointer(
        app.world_mut(),
        card,
        Vec2::new(58.0, 50.0),
        moved(Vec2::new(8.0, 0.0)),
    );
    run(&mut app, 1);
    assert_eq!(state(&app, card), InteractionState::Dragged);
    assert_eq!(
        ui_position(&app, card),
        Vec2::ZERO,
        "taken where it is: no jump"
    );
    pointer(
        app.world_mut(),
        card,
        Vec2::new(78.0, 50.0),
        moved(Vec2::new(28.0, 0.0)),
    );
    run(&mut app, 1);
    assert_eq!(ui_position(&app, card), Vec2::new(20.0, 0.0));
    drag_end(app.world_mut(), card, Vec2::new(78.0, 50.0));
    assert_eq!(app.world().resource::<Released>().0.len(), 1);
}
