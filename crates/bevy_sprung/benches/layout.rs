//! What layout transitions cost: `cargo bench -p bevy_sprung --features ui --bench layout`.
//!
//! 1. **Reflowing**, criterion, whole frames with `bevy_ui`'s layout: `NODES` nodes in a
//!    wrapping grid whose `Children` order is reversed every `REFLOW_EVERY` frames, so that
//!    every node is always in flight.
//!    - `none`: no spring (the layout's own cost, the base);
//!    - `layout_spring`: each node has a `LayoutSpring` (it springs from where it was drawn);
//!    - `translation_spring`: each node has a `UiTransformTranslationSpring` retargeted at each
//!      reversal instead (the same springs in flight, the same relayouts), the cost a layout
//!      spring is held against.
//! 2. **Standing still**, instructions under callgrind (`-- count`, needs `valgrind`): the same
//!    grid laid out and never changed, with and without a `LayoutSpring` on every node; the
//!    difference per node per frame is what a layout spring costs when its layout does not
//!    change.

#[path = "support/callgrind.rs"]
mod callgrind;

use bevy::app::{HierarchyPropagatePlugin, PropagateSet};
use bevy::camera::{ComputedCameraValues, RenderTargetInfo, Viewport};
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy::ui::update::propagate_ui_target_cameras;
use bevy::ui::{ComputedUiRenderTargetInfo, ComputedUiTargetCamera, UiScale, UiSystems};
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringAsleep;
use bevy_sprung::ui::LayoutTranslation;
use callgrind::callgrind;
use criterion::{Criterion, criterion_group};

/// Nodes per scene.
const NODES: usize = 10_000;
/// Frames between reversals of the grid's order.
const REFLOW_EVERY: u32 = 30;

/// What each node of the grid carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scene {
    LayoutSpring,
    TranslationSpring,
    /// No spring at all (the base of the still scenes).
    Plain,
}

/// The grid's root, and the frame count.
#[derive(Resource)]
struct Grid {
    root: Entity,
    frame: u32,
    reflowing: bool,
}

/// A headless app with `bevy_ui`'s layout (as `UiPlugin` schedules it) and a grid of `NODES`
/// nodes 20 px square in a 2000 px wide wrapping row.
fn app(scene: Scene, reflowing: bool) -> App {
    let mut app = App::new();
    app.add_plugins((
        MinimalPlugins,
        SpringPlugins::default(),
        HierarchyPropagatePlugin::<ComputedUiTargetCamera>::new(PostUpdate),
        HierarchyPropagatePlugin::<ComputedUiRenderTargetInfo>::new(PostUpdate),
    ))
    .insert_resource(TimeUpdateStrategy::ManualDuration(
        std::time::Duration::from_secs_f64(1.0 / 60.0),
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
            bevy::ui::ui_layout_system.in_set(UiSystems::Layout),
        ),
    )
    .add_systems(Update, reflow);
    let size = UVec2::new(2000, 2000);
    app.world_mut().spawn((
        Camera2d,
        Camera {
            computed: ComputedCameraValues {
                target_info: Some(RenderTargetInfo {
                    physical_size: size,
                    scale_factor: 1.0,
                }),
                ..default()
            },
            viewport: Some(Viewport {
                physical_size: size,
                ..default()
            }),
            ..default()
        },
    ));
    let root = app
        .world_mut()
        .spawn(Node {
            width: px(2000.0),
            flex_wrap: FlexWrap::Wrap,
            ..default()
        })
        .id();
    for _ in 0..NODES {
        let node = Node {
            width: px(20.0),
            height: px(20.0),
            ..default()
        };
        let mut entity = app.world_mut().spawn((node, ChildOf(root)));
        match scene {
            Scene::LayoutSpring => {
                entity.insert(LayoutSpring::new(Spring::smooth()));
            }
            Scene::TranslationSpring => {
                entity.insert(UiTransformTranslationSpring::new(
                    Spring::smooth(),
                    Val2::ZERO,
                ));
            }
            Scene::Plain => {}
        }
    }
    app.insert_resource(Grid {
        root,
        frame: 0,
        reflowing,
    });
    app.finish();
    app.cleanup();
    for _ in 0..5 {
        app.update();
    }
    app
}

/// Every `REFLOW_EVERY` frames the grid's order reverses, and translation springs are sent
/// 40 px away or back.
fn reflow(
    mut grid: ResMut<Grid>,
    mut children: Query<&mut Children>,
    mut springs: Query<&mut UiTransformTranslationSpring>,
) {
    grid.frame += 1;
    if !grid.reflowing || !grid.frame.is_multiple_of(REFLOW_EVERY) {
        return;
    }
    let Ok(mut order) = children.get_mut(grid.root) else {
        return;
    };
    order.sort_by_key(|entity| core::cmp::Reverse(entity.index()));
    let away = grid.frame / REFLOW_EVERY % 2 == 1;
    let offset = if away { 40.0 } else { 0.0 };
    for mut spring in &mut springs {
        spring.set_target(Val2::px(offset, offset));
    }
}

fn reflowing(c: &mut Criterion) {
    let mut group = c.benchmark_group("reflow_10k");
    for (name, scene) in [
        ("none", Scene::Plain),
        ("translation_spring", Scene::TranslationSpring),
        ("layout_spring", Scene::LayoutSpring),
    ] {
        let mut app = app(scene, true);
        // Past the first reversal, most springs are in flight.
        for _ in 0..REFLOW_EVERY + 5 {
            app.update();
        }
        let world = app.world_mut();
        let awake = match scene {
            Scene::LayoutSpring => world
                .query_filtered::<(), (With<LayoutSpring>, Without<SpringAsleep<LayoutTranslation>>)>()
                .iter(world)
                .count(),
            _ => world
                .query_filtered::<(), (
                    With<UiTransformTranslationSpring>,
                    Without<SpringAsleep<UiTransformTranslation>>,
                )>()
                .iter(world)
                .count(),
        };
        assert!(
            scene == Scene::Plain || awake > NODES / 2,
            "{name}: only {awake} springs in flight"
        );
        group.bench_function(name, |b| b.iter(|| app.update()));
    }
    group.finish();
}

criterion_group!(benches, reflowing);

/// The frames callgrind counts.
#[inline(never)]
fn measured(app: &mut App, frames: u32) {
    for _ in 0..frames {
        app.update();
    }
}

/// Frames counted per still scene.
const COUNTED_FRAMES: u32 = 10;

/// Instructions of the still grid's frames under callgrind, with or without layout springs.
fn count(scene: Scene) -> u64 {
    callgrind("*layout::measured", None, &["one", &format!("{scene:?}")])
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("one") => {
            let scene = match args[1].as_str() {
                "LayoutSpring" => Scene::LayoutSpring,
                _ => Scene::Plain,
            };
            let mut app = app(scene, false);
            measured(&mut app, COUNTED_FRAMES);
        }
        Some("count") => {
            let plain = count(Scene::Plain);
            let sprung = count(Scene::LayoutSpring);
            let per_node = |total: u64| total as f64 / f64::from(COUNTED_FRAMES) / NODES as f64;
            println!(
                "still grid of {NODES} nodes, instructions per node per frame: no component {:.2}, \
                 LayoutSpring {:.2}, difference {:.2}",
                per_node(plain),
                per_node(sprung),
                per_node(sprung) - per_node(plain)
            );
        }
        _ => {
            benches();
            Criterion::default().configure_from_args().final_summary();
        }
    }
}
