//! Layout transitions (FLIP) with `bevy_ui`'s layout running: continuous across reflows, exact
//! arrival, velocity kept through a second reflow, nodes that do not move never written.

use bevy::app::{HierarchyPropagatePlugin, PropagateSet};
use bevy::camera::{ComputedCameraValues, RenderTargetInfo, Viewport};
use bevy::prelude::*;
use bevy::ui::update::propagate_ui_target_cameras;
use bevy::ui::{
    ComputedUiRenderTargetInfo, ComputedUiTargetCamera, UiGlobalTransform, UiScale, UiSystems,
    ui_layout_system,
};
use bevy_sprung::clock::{DefaultSpringClock, SpringClock};
use bevy_sprung::prelude::*;
use bevy_sprung::ui::{LayoutOffset, MomentumScroll, PopLayout, ScrollSettled};
use bevy_sprung::ui::{LayoutScale, LayoutTranslation};

use crate::harness::{app, asleep, run};

pub(crate) const WIDTH: u32 = 800;
pub(crate) const HEIGHT: u32 = 600;

/// A headless app at `fps` with `bevy_ui`'s layout, as `UiPlugin` schedules it, on an 800×600
/// target.
pub(crate) fn ui_app(fps: u32) -> App {
    let mut app = app(fps);
    app.add_plugins((
        HierarchyPropagatePlugin::<ComputedUiTargetCamera>::new(PostUpdate),
        HierarchyPropagatePlugin::<ComputedUiRenderTargetInfo>::new(PostUpdate),
    ))
    .init_resource::<UiScale>()
    .init_resource::<bevy::ui::ui_surface::UiSurface>()
    .init_resource::<bevy::text::FontCx>()
    .configure_sets(
        PostUpdate,
        (
            UiSystems::Prepare.after(bevy::app::AnimationSystems),
            UiSystems::Propagate,
            UiSystems::Content,
            UiSystems::Layout,
            UiSystems::PostLayout,
        )
            .chain(),
    )
    .configure_sets(
        PostUpdate,
        (
            PropagateSet::<ComputedUiTargetCamera>::default().in_set(UiSystems::Propagate),
            PropagateSet::<ComputedUiRenderTargetInfo>::default().in_set(UiSystems::Propagate),
        ),
    )
    .add_systems(
        PostUpdate,
        (
            propagate_ui_target_cameras.in_set(UiSystems::Prepare),
            ui_layout_system.in_set(UiSystems::Layout),
        ),
    );
    app.world_mut().spawn((
        Camera2d,
        Camera {
            computed: ComputedCameraValues {
                target_info: Some(RenderTargetInfo {
                    physical_size: UVec2::new(WIDTH, HEIGHT),
                    scale_factor: 1.0,
                }),
                ..default()
            },
            viewport: Some(Viewport {
                physical_size: UVec2::new(WIDTH, HEIGHT),
                ..default()
            }),
            ..default()
        },
    ));
    app
}

/// A column of `count` items 40 px high, each with a layout spring, and the column.
pub(crate) fn spawn_column(app: &mut App, count: usize, spring: Spring) -> (Entity, Vec<Entity>) {
    let column = app
        .world_mut()
        .spawn(Node {
            flex_direction: FlexDirection::Column,
            width: px(200.0),
            ..default()
        })
        .id();
    let items = (0..count)
        .map(|_| {
            app.world_mut()
                .spawn((
                    Node {
                        height: px(40.0),
                        flex_shrink: 0.0,
                        ..default()
                    },
                    LayoutSpring::new(spring),
                    ChildOf(column),
                ))
                .id()
        })
        .collect();
    (column, items)
}

/// Where the node is drawn: its centre on screen.
pub(crate) fn drawn(app: &App, entity: Entity) -> Vec2 {
    app.world()
        .get::<UiGlobalTransform>(entity)
        .unwrap()
        .translation
}

/// The centre of the `index`th 40 px item of a column at the top left.
pub(crate) fn slot(index: usize) -> Vec2 {
    Vec2::new(100.0, 20.0 + 40.0 * index as f32)
}

/// Moves the column's last item to the top.
pub(crate) fn last_to_top(app: &mut App, column: Entity) {
    let last = *app.world().get::<Children>(column).unwrap().last().unwrap();
    app.world_mut().entity_mut(column).insert_child(0, last);
}

/// The last item moves to the top: every item is drawn continuously from its old slot to its
/// new one, each frame moving by no more than the spring's own step, and ends exactly there.
#[test]
fn a_reorder_springs_every_item_to_its_new_place() {
    for fps in [30, 60, 144, 240] {
        let mut app = ui_app(fps);
        let spring = Spring::smooth();
        let (column, items) = spawn_column(&mut app, 5, spring);
        run(&mut app, 3);
        for (index, &item) in items.iter().enumerate() {
            assert_eq!(drawn(&app, item), slot(index), "{fps} fps");
        }
        last_to_top(&mut app, column);
        let before: Vec<Vec2> = items.iter().map(|&item| drawn(&app, item)).collect();
        app.update();
        // The frame of the reorder: drawn where they were.
        for (index, &item) in items.iter().enumerate() {
            assert_eq!(drawn(&app, item), before[index], "{fps} fps: jumped");
        }
        // Then along the exact motion of the spring from the old slot: one dimension, from
        // rest, so every frame is the exact state at its time (to the rest tolerance, 0.05 px,
        // once it has arrived).
        let dt = 1.0 / f64::from(fps);
        for frame in 1..=2 * fps {
            app.update();
            let time = dt * f64::from(frame);
            for (index, &item) in items.iter().enumerate() {
                let to = (index + 1) % items.len();
                let from = slot(index).y;
                let exact = sprung::Spring::<f64>::from(spring)
                    .transition(time)
                    .step(
                        sprung::SpringState::new(f64::from(from - slot(to).y), 0.0),
                        0.0,
                    )
                    .position
                    + f64::from(slot(to).y);
                let y = f64::from(drawn(&app, item).y);
                assert!(
                    (y - exact).abs() < 0.05,
                    "{fps} fps, item {index}, frame {frame}: {y} vs {exact}"
                );
                assert_eq!(drawn(&app, item).x, 100.0);
            }
        }
        run(&mut app, fps);
        for (index, &item) in items.iter().enumerate() {
            let to = (index + 1) % items.len();
            assert_eq!(drawn(&app, item), slot(to), "{fps} fps");
            assert_eq!(
                *app.world().get::<LayoutOffset>(item).unwrap(),
                LayoutOffset::ZERO
            );
            assert!(asleep::<LayoutTranslation>(&app, item));
        }
    }
}

/// A second reorder mid-flight keeps the velocity: the item moving to the top is sent back
/// before it arrives, and its drawn path is the exact spring motion of one offset, rebased by
/// the layout move with its velocity kept — not a restart from rest.
#[test]
fn a_second_reorder_mid_flight_keeps_velocity() {
    for fps in [30, 60, 144, 240] {
        let mut app = ui_app(fps);
        let spring = Spring::snappy();
        let (column, items) = spawn_column(&mut app, 5, spring);
        run(&mut app, 3);
        let item = items[4];
        let transition = sprung::Spring::<f64>::from(spring).transition(1.0 / f64::from(fps));
        // Drawn at slot 4 while laid out at slot 0: an offset of 160 px, at rest.
        let mut state = sprung::SpringState::new(f64::from(slot(4).y - slot(0).y), 0.0);
        last_to_top(&mut app, column);
        app.update();
        let mut laid_out = slot(0).y;
        let back_at = fps / 5;
        for frame in 1..=fps {
            if frame == back_at {
                app.world_mut().entity_mut(column).insert_child(4, item);
            }
            app.update();
            state = transition.step(state, 0.0);
            if frame == back_at {
                // Layout moved it 160 px down: the offset takes that up, the velocity stays.
                state.position -= f64::from(slot(4).y - slot(0).y);
                laid_out = slot(4).y;
                assert!(state.velocity < -100.0, "{fps} fps: {state:?}");
            }
            let expected = f64::from(laid_out) + state.position;
            let y = f64::from(drawn(&app, item).y);
            assert!(
                (y - expected).abs() < 0.05,
                "{fps} fps, frame {frame}: {y} vs {expected}"
            );
        }
        run(&mut app, fps);
        assert_eq!(drawn(&app, item), slot(4));
    }
}

/// A node whose layout does not change is never written, nor are its springs woken, while its
/// siblings move.
#[test]
fn a_node_whose_layout_does_not_change_is_never_written() {
    let mut app = ui_app(60);
    let (column, items) = spawn_column(&mut app, 3, Spring::snappy());
    run(&mut app, 5);
    let first = items[0];
    let ticks = |app: &App| {
        let entity = app.world().entity(first);
        (
            entity
                .get_change_ticks::<UiGlobalTransform>()
                .unwrap()
                .changed,
            entity.get_change_ticks::<LayoutOffset>().unwrap().changed,
        )
    };
    let still = ticks(&app);
    // The second and third trade places; the first stays.
    app.world_mut()
        .get_mut::<Children>(column)
        .unwrap()
        .swap(1, 2);
    for _ in 0..120 {
        app.update();
        assert_eq!(ticks(&app), still);
        assert!(asleep::<LayoutTranslation>(&app, first));
    }
    assert_eq!(drawn(&app, items[1]), slot(2));
}

/// A size change is drawn as a scale of the node's box that springs to 1; the children keep
/// their size (their transform is not scaled) and their place from the drawn box's top-left
/// corner, where layout places them from.
#[test]
fn a_size_change_springs_without_distorting_children() {
    let mut app = ui_app(60);
    let panel = app
        .world_mut()
        .spawn((
            Node {
                width: px(100.0),
                height: px(100.0),
                ..default()
            },
            LayoutSpring::new(Spring::smooth()),
        ))
        .id();
    let child = app
        .world_mut()
        .spawn((
            Node {
                width: px(20.0),
                height: px(20.0),
                ..default()
            },
            ChildOf(panel),
        ))
        .id();
    run(&mut app, 3);
    let child_before = app
        .world()
        .get::<UiGlobalTransform>(child)
        .unwrap()
        .translation;
    app.world_mut().get_mut::<Node>(panel).unwrap().width = px(300.0);
    app.update();
    let global = |app: &App, entity| *app.world().get::<UiGlobalTransform>(entity).unwrap();
    // The child's place in the panel did not change: it is drawn where it was.
    assert!(global(&app, child).translation.distance(child_before) < 1e-3);
    // Drawn at its old size and place: 100 px wide, centred at x = 50.
    let drawn_panel = global(&app, panel);
    assert!((drawn_panel.matrix2.x_axis.x * 300.0 - 100.0).abs() < 1e-3);
    assert!((drawn_panel.translation.x - 50.0).abs() < 1e-3);
    let mut last_width = 100.0;
    for _ in 0..180 {
        app.update();
        let panel_now = global(&app, panel);
        let width = panel_now.matrix2.x_axis.x * 300.0;
        assert!(width >= last_width - 1e-3 && width <= 300.0 + 1e-3);
        last_width = width;
        // The child: never scaled, laid out 10 px from the drawn box's left edge, where its
        // place in the panel is laid out from (so it stays put while the panel grows right).
        let child_now = global(&app, child);
        assert_eq!(child_now.matrix2, Mat2::IDENTITY);
        let expected = panel_now.translation.x - width / 2.0 + 10.0;
        assert!(
            (child_now.translation.x - expected).abs() < 1e-2,
            "child at {} instead of {expected}",
            child_now.translation.x
        );
    }
    assert_eq!(global(&app, panel).matrix2, Mat2::IDENTITY);
    assert!(asleep::<LayoutScale>(&app, panel));
}

/// Layout springs nested: a column with a layout spring (moves only, or moves and size) holds
/// three rows with their own; the middle row goes. No row jumps in that frame (the first row's
/// place did not change, the last one's is sprung from where it was), every frame after moves
/// each row by no more than its spring can, and they end on their new places — with the column
/// at the top left or centred in the window, and turned and scaled by its `UiTransform`.
#[test]
fn nested_layout_springs_keep_rows_in_place_when_a_sibling_goes() {
    let springs = [
        LayoutSpring::position_only(Spring::snappy()),
        LayoutSpring::new(Spring::snappy()),
    ];
    for column_spring in springs {
        for centred in [false, true] {
            for transform in [
                UiTransform::default(),
                UiTransform {
                    scale: Vec2::splat(1.5),
                    rotation: Rot2::degrees(10.0),
                    ..default()
                },
            ] {
                let mut app = ui_app(60);
                let window = app
                    .world_mut()
                    .spawn(Node {
                        width: percent(100.0),
                        height: percent(100.0),
                        justify_content: if centred {
                            JustifyContent::Center
                        } else {
                            JustifyContent::Start
                        },
                        align_items: if centred {
                            AlignItems::Center
                        } else {
                            AlignItems::Start
                        },
                        ..default()
                    })
                    .id();
                let column = app
                    .world_mut()
                    .spawn((
                        Node {
                            flex_direction: FlexDirection::Column,
                            width: px(200.0),
                            ..default()
                        },
                        column_spring,
                        transform,
                        ChildOf(window),
                    ))
                    .id();
                let rows: Vec<Entity> = (0..3)
                    .map(|_| {
                        app.world_mut()
                            .spawn((
                                Node {
                                    height: px(40.0),
                                    flex_shrink: 0.0,
                                    ..default()
                                },
                                LayoutSpring::new(Spring::snappy()),
                                ChildOf(column),
                            ))
                            .id()
                    })
                    .collect();
                run(&mut app, 5);
                let case = format!("{column_spring:?}, centred {centred}, {transform:?}");
                let before = [drawn(&app, rows[0]), drawn(&app, rows[2])];
                app.world_mut().entity_mut(rows[1]).despawn();
                app.update();
                for (row, was) in [rows[0], rows[2]].into_iter().zip(before) {
                    let now = drawn(&app, row);
                    assert!(
                        now.distance(was) < 1e-2,
                        "{case}: {row} jumped {was} → {now}"
                    );
                }
                let mut last = [drawn(&app, rows[0]), drawn(&app, rows[2])];
                for frame in 0..120 {
                    app.update();
                    let now = [drawn(&app, rows[0]), drawn(&app, rows[2])];
                    for (a, b) in last.iter().zip(now) {
                        // A snappy spring carries a 40 px (60 px turned and scaled) offset at
                        // most ~6 px in a frame.
                        assert!(a.distance(b) < 8.0, "{case}, frame {frame}: {a} → {b}");
                    }
                    last = now;
                }
                let column_offset = *app.world().get::<LayoutOffset>(column).unwrap();
                assert_eq!(column_offset, LayoutOffset::ZERO, "{case}");
                // Laid out one row apart: 40 px along the column's turned and scaled axis.
                let apart = last[1].distance(last[0]);
                let expected = if transform == UiTransform::default() {
                    40.0
                } else {
                    60.0
                };
                assert!((apart - expected).abs() < 0.1, "{case}: {apart}");
            }
        }
    }
}

/// `PopLayout` (Motion's `popLayout`): the row that leaves is taken out of the flow the
/// moment its exit starts, drawn where it stood while it shrinks away, and the row below
/// springs up into the gap at once (not after the exit settled); cancelled, the leaving row
/// goes back into the flow as it was and the row below springs back down.
#[test]
fn a_row_that_pops_out_of_layout_lets_the_next_row_close_the_gap_at_once() {
    use bevy_sprung::ui::UiTransformScale;
    for cancel in [false, true] {
        let mut app = ui_app(60);
        let (_, items) = spawn_column(&mut app, 3, Spring::snappy());
        let leaving = items[1];
        app.world_mut().entity_mut(leaving).insert((
            PopLayout,
            UiTransformScaleSpring::new(Spring::smooth(), Vec2::ONE),
            ExitTo::<UiTransformScale>(Vec2::ZERO),
        ));
        run(&mut app, 30);
        let node_before = app.world().get::<Node>(leaving).unwrap().clone();
        assert_eq!(drawn(&app, items[2]), slot(2));
        app.world_mut()
            .commands()
            .entity(leaving)
            .despawn_after_exit();
        app.update();
        // The frame the exit starts: nothing jumps, and the row below is already laid out in
        // the gap (drawn where it was by its offset, which springs it up).
        assert!(drawn(&app, leaving).distance(slot(1)) < 1e-3);
        assert!(drawn(&app, items[2]).distance(slot(2)) < 1e-3);
        let offset = app
            .world()
            .get::<LayoutOffset>(items[2])
            .unwrap()
            .translation;
        assert!((offset.y - 40.0).abs() < 1e-3, "{offset}");
        // It moves up while the leaving row shrinks where it stood.
        run(&mut app, 10);
        assert!(drawn(&app, items[2]).y < slot(2).y - 5.0);
        assert!(drawn(&app, leaving).distance(slot(1)) < 1e-3);
        if cancel {
            app.world_mut().commands().entity(leaving).cancel_exit();
            run(&mut app, 120);
            assert_eq!(*app.world().get::<Node>(leaving).unwrap(), node_before);
            assert!(drawn(&app, leaving).distance(slot(1)) < 1e-3);
            assert!(drawn(&app, items[2]).distance(slot(2)) < 0.05);
        } else {
            run(&mut app, 120);
            assert!(app.world().get_entity(leaving).is_err(), "never despawned");
            assert!(drawn(&app, items[2]).distance(slot(1)) < 0.05);
        }
    }
}

/// Scrolling is not a layout change: the items move with the scroll at once, their springs
/// asleep.
#[test]
fn scrolling_moves_items_at_once() {
    let mut app = ui_app(60);
    let (column, items) = spawn_column(&mut app, 10, Spring::snappy());
    {
        let mut node = app.world_mut().get_mut::<Node>(column).unwrap();
        node.height = px(120.0);
        node.overflow = Overflow::scroll_y();
    }
    run(&mut app, 3);
    for scrolled in [10.0, 35.0, 80.0] {
        app.world_mut()
            .entity_mut(column)
            .insert(ScrollPosition(Vec2::new(0.0, scrolled)));
        app.update();
        for (index, &item) in items.iter().enumerate() {
            assert_eq!(drawn(&app, item), slot(index) - Vec2::Y * scrolled);
            assert!(asleep::<LayoutTranslation>(&app, item));
        }
    }
}

/// A window resize reflows a row of percentage-wide items: they spring to their new places and
/// sizes from where they were drawn.
#[test]
fn a_window_resize_springs_to_the_new_layout() {
    let mut app = ui_app(60);
    let row = app
        .world_mut()
        .spawn(Node {
            width: percent(100.0),
            ..default()
        })
        .id();
    let items: Vec<Entity> = (0..4)
        .map(|_| {
            app.world_mut()
                .spawn((
                    Node {
                        width: percent(25.0),
                        height: px(50.0),
                        ..default()
                    },
                    LayoutSpring::new(Spring::smooth()),
                    ChildOf(row),
                ))
                .id()
        })
        .collect();
    run(&mut app, 3);
    let before: Vec<Vec2> = items.iter().map(|&item| drawn(&app, item)).collect();
    assert_eq!(before[3], Vec2::new(700.0, 25.0));
    let mut cameras = app.world_mut().query::<&mut Camera>();
    for mut camera in cameras.iter_mut(app.world_mut()) {
        let size = UVec2::new(400, HEIGHT);
        camera.computed.target_info.as_mut().unwrap().physical_size = size;
        camera.viewport.as_mut().unwrap().physical_size = size;
    }
    app.update();
    for (index, &item) in items.iter().enumerate() {
        assert_eq!(drawn(&app, item), before[index], "item {index} jumped");
    }
    run(&mut app, 120);
    for (index, &item) in items.iter().enumerate() {
        assert_eq!(
            drawn(&app, item),
            Vec2::new(50.0 + 100.0 * index as f32, 25.0)
        );
        let global = app.world().get::<UiGlobalTransform>(item).unwrap();
        assert_eq!(global.matrix2, Mat2::IDENTITY);
    }
}

/// A scroll area 200 px high over 100 rows of 40 px (it scrolls to 3800), with `scroll`.
pub(crate) fn spawn_scroll_area(app: &mut App, scroll: MomentumScroll) -> (Entity, Entity) {
    let area = app
        .world_mut()
        .spawn((
            Node {
                width: px(200.0),
                height: px(200.0),
                flex_direction: FlexDirection::Column,
                overflow: Overflow::scroll_y(),
                ..default()
            },
            scroll,
        ))
        .id();
    let rows: Vec<Entity> = (0..100)
        .map(|_| {
            app.world_mut()
                .spawn((
                    Node {
                        height: px(40.0),
                        flex_shrink: 0.0,
                        ..default()
                    },
                    ChildOf(area),
                ))
                .id()
        })
        .collect();
    (area, rows[0])
}

pub(crate) fn scroll_position(app: &App, area: Entity) -> f32 {
    app.world().get::<ScrollPosition>(area).unwrap().y
}

pub(crate) fn steer(app: &mut App, area: Entity, input: impl FnOnce(&mut MomentumScroll)) {
    input(&mut app.world_mut().get_mut::<MomentumScroll>(area).unwrap());
}

/// Counts `ScrollSettled` per area.
#[derive(Resource, Default)]
struct Settled(Vec<Entity>);

/// A fling coasts as the closed form `x0 + v·(1 − e^(−d·t))/d`, at every frame rate, and rests
/// exactly at `x0 + v/d`, reported once.
#[test]
fn a_fling_decays_exactly() {
    for fps in [30, 60, 144, 240] {
        let mut app = ui_app(fps);
        app.init_resource::<Settled>().add_observer(
            |settled: On<ScrollSettled>, mut all: ResMut<Settled>| {
                all.0.push(settled.entity);
            },
        );
        let deceleration = 2.0;
        let (area, _) = spawn_scroll_area(
            &mut app,
            MomentumScroll::default().with_deceleration(deceleration),
        );
        run(&mut app, 3);
        steer(&mut app, area, |scroll| scroll.drag_by(Vec2::Y * 1000.0));
        app.update();
        assert_eq!(scroll_position(&app, area), 1000.0);
        let velocity = 800.0;
        steer(&mut app, area, |scroll| scroll.fling(Vec2::Y * velocity));
        app.world_mut().resource_mut::<Settled>().0.clear();
        for frame in 1..=5 * fps {
            app.update();
            let t = f64::from(frame) / f64::from(fps);
            let exact = 1000.0
                + f64::from(velocity) * (1.0 - (-f64::from(deceleration) * t).exp())
                    / f64::from(deceleration);
            let shown = f64::from(scroll_position(&app, area));
            assert!(
                (shown - exact).abs() < 0.06,
                "{fps} fps, frame {frame}: {shown} vs {exact}"
            );
        }
        run(&mut app, 5 * fps);
        assert_eq!(scroll_position(&app, area), 1400.0);
        assert_eq!(app.world().resource::<Settled>().0, [area]);
    }
}

/// A fling in a pause menu's list coasts while the game is paused on the real clock; on the
/// game clock the list holds where it was let go.
#[test]
fn a_fling_coasts_on_the_spring_clock() {
    for clock in [SpringClock::Real, SpringClock::Game] {
        let mut app = ui_app(60);
        app.insert_resource(DefaultSpringClock(clock));
        app.world_mut().resource_mut::<Time<Virtual>>().pause();
        let (area, _) = spawn_scroll_area(&mut app, MomentumScroll::default());
        run(&mut app, 3);
        steer(&mut app, area, |scroll| scroll.drag_by(Vec2::Y * 1000.0));
        app.update();
        steer(&mut app, area, |scroll| scroll.fling(Vec2::Y * 800.0));
        run(&mut app, 60);
        let shown = scroll_position(&app, area);
        match clock {
            SpringClock::Real => assert!(shown > 1100.0, "no coast on the real clock: {shown}"),
            SpringClock::Game => assert_eq!(shown, 1000.0, "coasted while the game was paused"),
        }
    }
}

/// A hard fling toward the end: the content is never drawn past the end by as much as the
/// give, springs back, and rests exactly at the end.
#[test]
fn a_fling_past_the_end_stays_within_the_rubber_band() {
    for fps in [30, 60, 240] {
        let mut app = ui_app(fps);
        let give = 120.0;
        let (area, first_row) = spawn_scroll_area(&mut app, MomentumScroll::default());
        run(&mut app, 3);
        steer(&mut app, area, |scroll| scroll.drag_by(Vec2::Y * 3000.0));
        app.update();
        steer(&mut app, area, |scroll| scroll.fling(Vec2::Y * 20000.0));
        let mut furthest: f32 = 0.0;
        for _ in 0..4 * fps {
            app.update();
            let scrolled = scroll_position(&app, area);
            assert!((0.0..=3800.0).contains(&scrolled));
            // Past the end by what the first row is drawn above where the scroll puts it
            // (layout scrolls by whole pixels).
            let past = (20.0 - scrolled.floor()) - drawn(&app, first_row).y;
            assert!(
                past >= -1e-3 && past < give,
                "{fps} fps: {past} past the end"
            );
            furthest = furthest.max(past);
        }
        assert!(furthest > 10.0, "{fps} fps: never pulled past the end");
        assert_eq!(scroll_position(&app, area), 3800.0);
        assert_eq!(drawn(&app, first_row).y, 20.0 - 3800.0);
    }
}

/// Dragged past the start, the content follows less and less; let go, it springs back.
#[test]
fn a_drag_past_the_start_rubber_bands_and_springs_back() {
    let mut app = ui_app(60);
    let (area, first_row) = spawn_scroll_area(&mut app, MomentumScroll::default());
    run(&mut app, 3);
    let mut last = 0.0;
    for _ in 0..30 {
        steer(&mut app, area, |scroll| scroll.drag_by(Vec2::Y * -20.0));
        app.update();
        let pulled = drawn(&app, first_row).y - 20.0;
        assert!(pulled > last && pulled < 120.0, "{pulled} after {last}");
        assert!(pulled - last <= 20.0 * 0.55 + 1e-3);
        last = pulled;
    }
    // Held still: it stays pulled.
    run(&mut app, 10);
    assert_eq!(drawn(&app, first_row).y - 20.0, last);
    steer(&mut app, area, |scroll| scroll.fling(Vec2::ZERO));
    run(&mut app, 180);
    assert_eq!(drawn(&app, first_row).y, 20.0);
    assert_eq!(scroll_position(&app, area), 0.0);
}

/// With snap points a fling rests on the one nearest its rest point; wheel steps glide there
/// and add up.
#[test]
fn snapping_and_wheel_steps() {
    let mut app = ui_app(60);
    let (area, _) = spawn_scroll_area(
        &mut app,
        MomentumScroll::default().snap_every(Vec2::new(0.0, 40.0)),
    );
    run(&mut app, 3);
    steer(&mut app, area, |scroll| scroll.fling(Vec2::Y * 555.0));
    run(&mut app, 240);
    // Rest point 277.5: the nearest row boundary is 280.
    assert_eq!(scroll_position(&app, area), 280.0);
    steer(&mut app, area, |scroll| scroll.scroll_by(Vec2::Y * 80.0));
    app.update();
    steer(&mut app, area, |scroll| scroll.scroll_by(Vec2::Y * 40.0));
    let mut last = scroll_position(&app, area);
    for _ in 0..120 {
        app.update();
        let now = scroll_position(&app, area);
        assert!(now >= last && now <= 400.0);
        last = now;
    }
    assert_eq!(last, 400.0);
}

/// A row hidden with `Display::None` and shown again appears at its place at once (no flight
/// from where a hidden node is laid out), while its siblings spring around it.
#[test]
fn a_hidden_node_shown_again_appears_in_place() {
    let mut app = ui_app(60);
    let (_, items) = spawn_column(&mut app, 4, Spring::smooth());
    run(&mut app, 3);
    let hidden = items[1];
    app.world_mut().get_mut::<Node>(hidden).unwrap().display = Display::None;
    run(&mut app, 5);
    // The next row springs up into the gap.
    assert!(drawn(&app, items[2]).y < slot(2).y && drawn(&app, items[2]).y > slot(1).y);
    run(&mut app, 120);
    assert_eq!(drawn(&app, items[2]), slot(1));
    app.world_mut().get_mut::<Node>(hidden).unwrap().display = Display::Flex;
    app.update();
    assert_eq!(drawn(&app, hidden), slot(1));
    assert_eq!(
        *app.world().get::<LayoutOffset>(hidden).unwrap(),
        LayoutOffset::ZERO
    );
    // Its sibling springs back down from where it was drawn.
    assert_eq!(drawn(&app, items[2]), slot(1));
    run(&mut app, 120);
    assert_eq!(drawn(&app, items[2]), slot(2));
}
