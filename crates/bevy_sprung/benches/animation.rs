//! The per-frame cost of clip transitions by inertialization against Bevy's own cross-fade, in
//! one criterion run: `cargo bench -p bevy_sprung --features animation --bench animation`.
//!
//! A scene like Bevy's `many_foxes`: `CHARACTERS` characters of `JOINTS` joints each, every
//! joint's translation and rotation animated by three clips (idle, walk, gesture) sampled at
//! 30 keys a second. Each character switches to its next clip once a second, the characters'
//! switches spread over the second, with a blend of `BLEND`. The measured time is a whole frame
//! (`app.update()`) at 60 fps. Scenes:
//!
//! - `one_clip`: every character plays one clip and never switches (what one clip costs);
//! - `crossfade`: `AnimationTransitions::play`, Bevy's cross-fade: both clips evaluated and
//!   blended for the fade;
//! - `inertialization`: `Inertialization::play`: the new clip alone, and the offsets decaying.
//!
//! After the run it prints each scene's median frame and the ratio of inertialization's to the
//! cross-fade's, measured in the same run. `-- count` (needs `valgrind`) counts instead the
//! instructions of one second of each scene under callgrind, on one thread: deterministic, so
//! the ratio holds on a noisy machine.

use std::time::{Duration, Instant};

use bevy::animation::graph::{AnimationGraph, AnimationGraphHandle, AnimationNodeIndex};
use bevy::animation::transition::AnimationTransitions;
use bevy::animation::{
    AnimatedBy, AnimationClip, AnimationPlayer, AnimationPlugin, AnimationTargetId, animated_field,
    prelude::{AnimatableCurve, AnimatableKeyframeCurve},
};
use bevy::asset::AssetPlugin;
use bevy::ecs::schedule::{Schedules, SingleThreadedExecutor};
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::inertialization::Inertialization;
use bevy_sprung::prelude::*;
use callgrind::callgrind;
use criterion::{Criterion, criterion_group};

#[path = "support/callgrind.rs"]
mod callgrind;
#[path = "support/task_pools.rs"]
mod task_pools;

/// Characters per scene.
const CHARACTERS: usize = 100;
/// Joints per character (a fox has 24 bones with joints).
const JOINTS: usize = 24;
/// The blend (cross-fade duration, inertialization blend time).
const BLEND: Duration = Duration::from_millis(400);
/// Frames per second of the scene: each character switches once every `FPS` frames.
const FPS: u32 = 60;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scene {
    OneClip,
    Crossfade,
    Inertialization,
}

impl Scene {
    const ALL: [Scene; 3] = [Scene::OneClip, Scene::Crossfade, Scene::Inertialization];

    fn name(self) -> &'static str {
        match self {
            Scene::OneClip => "one_clip",
            Scene::Crossfade => "crossfade",
            Scene::Inertialization => "inertialization",
        }
    }
}

/// The three clips' nodes, and which character plays which.
#[derive(Resource)]
struct Moves {
    scene: Scene,
    nodes: Vec<AnimationNodeIndex>,
    frame: usize,
}

/// A character's clip index.
#[derive(Component)]
struct Character {
    index: usize,
    playing: usize,
}

/// A clip over `ids`: each joint's translation and rotation swing with the clip's own
/// frequency and phase, sampled at 30 keys a second for two seconds.
fn clip(ids: &[AnimationTargetId], kind: usize) -> AnimationClip {
    let mut clip = AnimationClip::default();
    let frequency = [0.5, 1.0, 2.0][kind];
    for (joint, &id) in ids.iter().enumerate() {
        let phase = joint as f32 * 0.3 + kind as f32;
        let times = (0..=60).map(|k| k as f32 / 30.0);
        let swing = |t: f32| (core::f32::consts::TAU * frequency * t + phase).sin();
        clip.add_curve_to_target(
            id,
            AnimatableCurve::new(
                animated_field!(Transform::translation),
                AnimatableKeyframeCurve::new(
                    times
                        .clone()
                        .map(|t| (t, Vec3::new(0.1 * swing(t), 1.0, 0.05 * swing(t + 0.2)))),
                )
                .unwrap(),
            ),
        );
        clip.add_curve_to_target(
            id,
            AnimatableCurve::new(
                animated_field!(Transform::rotation),
                AnimatableKeyframeCurve::new(times.map(|t| {
                    (
                        t,
                        Quat::from_euler(EulerRot::XYZ, 0.4 * swing(t), 0.2, 0.3 * swing(t + 0.5)),
                    )
                }))
                .unwrap(),
            ),
        );
    }
    clip
}

/// Each character switches to its next clip once a second, the switches spread over the second.
fn switch(
    mut moves: ResMut<Moves>,
    mut characters: Query<(
        &mut Character,
        &mut AnimationPlayer,
        Option<&mut AnimationTransitions>,
        Option<&mut Inertialization>,
    )>,
) {
    moves.frame += 1;
    if moves.scene == Scene::OneClip {
        return;
    }
    let frame = moves.frame;
    for (mut character, mut player, transitions, inertialization) in &mut characters {
        if !(frame + character.index * 37).is_multiple_of(FPS as usize) {
            continue;
        }
        character.playing = (character.playing + 1) % moves.nodes.len();
        let node = moves.nodes[character.playing];
        if let Some(mut transitions) = transitions {
            transitions.play(&mut player, node, BLEND).repeat();
        } else if let Some(mut inertialization) = inertialization {
            inertialization.play(&mut player, node, BLEND).repeat();
        }
    }
}

fn app(scene: Scene) -> App {
    let mut app = App::new();
    app.add_plugins((
        task_pools::minimal_plugins(),
        TransformPlugin,
        AssetPlugin::default(),
        AnimationPlugin,
        SpringPlugins::default(),
    ))
    .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
        1.0 / f64::from(FPS),
    )))
    .add_systems(Update, switch);
    let ids: Vec<AnimationTargetId> = (0..JOINTS)
        .map(|joint| AnimationTargetId::from_name(&Name::new(format!("joint{joint}"))))
        .collect();
    let clips: Vec<Handle<AnimationClip>> = (0..3)
        .map(|kind| {
            app.world_mut()
                .resource_mut::<Assets<AnimationClip>>()
                .add(clip(&ids, kind))
        })
        .collect();
    let (graph, nodes) = AnimationGraph::from_clips(clips);
    let graph = app
        .world_mut()
        .resource_mut::<Assets<AnimationGraph>>()
        .add(graph);
    let world = app.world_mut();
    for index in 0..CHARACTERS {
        let mut player = AnimationPlayer::default();
        let mut transitions = AnimationTransitions::new();
        let mut inertialization = Inertialization::default();
        match scene {
            Scene::OneClip => {
                player.start(nodes[0]).repeat();
            }
            Scene::Crossfade => {
                transitions
                    .play(&mut player, nodes[0], Duration::ZERO)
                    .repeat();
            }
            Scene::Inertialization => {
                inertialization
                    .play(&mut player, nodes[0], Duration::ZERO)
                    .repeat();
            }
        }
        let character = world
            .spawn((
                Character { index, playing: 0 },
                player,
                AnimationGraphHandle(graph.clone()),
                Transform::from_xyz(index as f32 * 2.0, 0.0, 0.0),
            ))
            .id();
        match scene {
            Scene::Crossfade => {
                world.entity_mut(character).insert(transitions);
            }
            Scene::Inertialization => {
                world.entity_mut(character).insert(inertialization);
            }
            Scene::OneClip => {}
        }
        // A spine of half the joints, and two limbs of a quarter each from its middle.
        let mut parents = vec![character];
        for (joint, &id) in ids.iter().enumerate() {
            let parent = match joint {
                0 => character,
                j if j == JOINTS / 2 || j == 3 * JOINTS / 4 => parents[JOINTS / 4 + 1],
                j => parents[j],
            };
            let entity = world
                .spawn((
                    Transform::default(),
                    id,
                    AnimatedBy(character),
                    ChildOf(parent),
                ))
                .id();
            parents.push(entity);
        }
    }
    app.insert_resource(Moves {
        scene,
        nodes,
        frame: 0,
    });
    // Past the first switches, so every scene is in its steady cycle.
    for _ in 0..2 * FPS {
        app.update();
    }
    app
}

fn transitions(c: &mut Criterion) {
    let mut group = c.benchmark_group("animation");
    let mut apps: Vec<(Scene, App)> = Scene::ALL
        .iter()
        .map(|&scene| (scene, app(scene)))
        .collect();
    for (scene, app) in &mut apps {
        group.bench_function(scene.name(), |b| b.iter(|| app.update()));
    }
    group.finish();
    // Criterion's estimates are not exposed to the bench: measure the scenes here too, in the
    // same run, interleaved (a second of each in turn, eleven times) so that the machine's
    // slow spells fall on all of them, and take each one's median second.
    let mut seconds: Vec<Vec<f64>> = vec![Vec::new(); apps.len()];
    for _ in 0..11 {
        for (k, (_, app)) in apps.iter_mut().enumerate() {
            let start = Instant::now();
            for _ in 0..FPS {
                app.update();
            }
            seconds[k].push(start.elapsed().as_secs_f64() / f64::from(FPS));
        }
    }
    let medians: Vec<f64> = seconds
        .iter_mut()
        .map(|frames| {
            frames.sort_by(f64::total_cmp);
            frames[frames.len() / 2]
        })
        .collect();
    println!(
        "\n{CHARACTERS} characters of {JOINTS} joints, switching once a second with a {} ms blend \
         (median of 11 interleaved seconds):",
        BLEND.as_millis()
    );
    for (&(scene, _), median) in apps.iter().zip(&medians) {
        println!("  {:<16} {:>8.1} µs a frame", scene.name(), median * 1e6);
    }
    let (one, fade, inertial) = (medians[0], medians[1], medians[2]);
    println!(
        "  inertialization / crossfade: {:.2}×  (beyond one clip: {:.2}×)",
        inertial / fade,
        (inertial - one) / (fade - one)
    );
}

criterion_group!(benches, transitions);

/// The frames callgrind counts: one second, in which every character switches once.
#[inline(never)]
fn measured(app: &mut App) {
    for _ in 0..FPS {
        app.update();
    }
}

/// Instructions of one second of `scene` under callgrind: every schedule on the counted thread,
/// and one compute thread, so that animation's parallel iteration runs there too (transform
/// propagation's parallel part, the same in every scene, runs on the compute thread).
fn count(scene: Scene) -> u64 {
    callgrind("*animation::measured", Some(1), &["one", scene.name()])
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("one") => {
            let scene = Scene::ALL
                .into_iter()
                .find(|scene| scene.name() == args[1])
                .expect("a scene name");
            let mut app = app(scene);
            for (_, schedule) in app.world_mut().resource_mut::<Schedules>().iter_mut() {
                schedule.set_executor(SingleThreadedExecutor::new());
            }
            measured(&mut app);
        }
        Some("count") => {
            let counts = Scene::ALL.map(count);
            let per_joint =
                |total: u64| total as f64 / f64::from(FPS) / (CHARACTERS * JOINTS) as f64;
            println!(
                "{CHARACTERS} characters of {JOINTS} joints, one second, instructions per joint per \
                 frame (whole frame):"
            );
            for (scene, &total) in Scene::ALL.iter().zip(&counts) {
                println!("  {:<16} {:>8.0}", scene.name(), per_joint(total));
            }
            let [one, fade, inertial] = counts.map(|total| total as f64);
            println!(
                "  inertialization / crossfade: {:.3}×  (beyond one clip: {:.2}×)",
                inertial / fade,
                (inertial - one) / (fade - one)
            );
        }
        _ => {
            benches();
            Criterion::default().configure_from_args().final_summary();
        }
    }
}
