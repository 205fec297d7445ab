//! What secondary motion costs: `cargo bench -p bevy_sprung --bench secondary`.
//!
//! Criterion, whole frames of headless apps at 60 fps, each against its alternative measured
//! in the same run:
//!
//! 1. `chain_10k`: 1000 chains of 10 joints (10 000 joints) hanging from bodies that move
//!    every frame, so every joint swings.
//!    - `none`: the hierarchy and the moving bodies, no secondary motion (the base);
//!    - `verlet`: a hand-written Verlet chain, Dynamic Bone's method (inertia from the
//!      previous position, damping, a pull toward the rest shape, gravity, lengths restored,
//!      rotations written back), one step a frame, kept where Dynamic Bone keeps it: in a
//!      component on the chain's root bone, as a `SpringChain` is. Its rest shape is fixed:
//!      it reads no bone's `Transform` but the root's, so nothing can animate the bones;
//!    - `dynamic_bone`: the same, doing all of Dynamic Bone's work of a frame: it reads each
//!      bone's `Transform` for its rest place and length (so that an animation plays under
//!      it, as it does under a `SpringChain`) and keeps Dynamic Bone's stiffness limit. The
//!      chain's budget is set against this one: it does the same job;
//!    - `spring_chain`: a `SpringChain` on each chain (one exact step a frame at 60 fps).
//! 2. `layers_20k`: 20 000 translation springs in flight, retargeted every 30 frames.
//!    - `separate`: on 20 000 entities, one spring each;
//!    - `layered`: on 10 000 entities, a base spring and a layer each.
//!
//! `… --bench secondary -- count` (needs `valgrind`) counts the instructions of the chain
//! scenes' frames under callgrind instead, every schedule on one thread: repeatable figures
//! on a shared machine. `… -- one SCENE` runs one scene's counted frames (what it runs under
//! callgrind).

#[path = "support/callgrind.rs"]
mod callgrind;
#[path = "support/task_pools.rs"]
mod task_pools;

use bevy::ecs::schedule::{Schedules, SingleThreadedExecutor};
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy::transform::TransformSystems;
use bevy_sprung::chain::SpringChain;
use bevy_sprung::layers::{LayerSpring, SpringLayerPlugin};
use bevy_sprung::prelude::*;
use callgrind::callgrind;
use criterion::{Criterion, criterion_group};

const CHAINS: usize = 1000;
const JOINTS: usize = 10;
const BONE: f32 = 10.0;
const GRAVITY: Vec3 = Vec3::new(0.0, -300.0, 0.0);

/// A moving body.
#[derive(Component)]
struct Body(f32);

/// The secondary motion a scene has.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Secondary {
    None,
    Verlet,
    DynamicBone,
    SpringChain,
}

impl Secondary {
    const ALL: [Self; 4] = [
        Self::None,
        Self::Verlet,
        Self::DynamicBone,
        Self::SpringChain,
    ];

    fn name(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::Verlet => "verlet",
            Self::DynamicBone => "dynamic_bone",
            Self::SpringChain => "spring_chain",
        }
    }
}

/// `MinimalPlugins` at 60 fps (with the compute threads `SPRUNG_BENCH_COMPUTE_THREADS` asks
/// for, as callgrind runs it).
fn headless() -> App {
    let mut app = App::new();
    app.add_plugins((
        task_pools::minimal_plugins(),
        TransformPlugin,
        SpringPlugins::default(),
    ))
    .insert_resource(TimeUpdateStrategy::ManualDuration(
        std::time::Duration::from_secs_f64(1.0 / 60.0),
    ));
    app
}

/// Moves every body on its own circle.
fn move_bodies(time: Res<Time>, mut bodies: Query<(&Body, &mut Transform)>) {
    let t = time.elapsed_secs();
    for (body, mut transform) in &mut bodies {
        let phase = t * 3.0 + body.0;
        transform.translation = Vec3::new(phase.cos(), phase.sin(), 0.0) * 40.0;
    }
}

fn chain_app(secondary: Secondary) -> App {
    let mut app = headless();
    app.add_systems(Update, move_bodies);
    let world = app.world_mut();
    for index in 0..CHAINS {
        let body = world.spawn((Transform::default(), Body(index as f32))).id();
        let mut joints = vec![world.spawn(Transform::default()).id()];
        world.entity_mut(body).add_child(joints[0]);
        for _ in 1..JOINTS {
            let joint = world.spawn(Transform::from_xyz(-BONE, 0.0, 0.0)).id();
            world.entity_mut(*joints.last().unwrap()).add_child(joint);
            joints.push(joint);
        }
        match secondary {
            Secondary::SpringChain => {
                world
                    .entity_mut(joints[0])
                    .insert(SpringChain::new(Spring::bouncy()).with_gravity(GRAVITY));
            }
            Secondary::Verlet => {
                world
                    .entity_mut(joints[0])
                    .insert(VerletChain::new(joints, RestShape::Fixed));
            }
            Secondary::DynamicBone => {
                world
                    .entity_mut(joints[0])
                    .insert(VerletChain::new(joints, RestShape::Posed));
            }
            Secondary::None => {}
        }
    }
    if matches!(secondary, Secondary::Verlet | Secondary::DynamicBone) {
        app.add_systems(PostUpdate, step_verlet.before(TransformSystems::Propagate));
    }
    app
}

/// Dynamic Bone's particle of a joint: where it is, where it was, its rest offset from its
/// parent joint in the parent's axes.
struct Particle {
    entity: Entity,
    position: Vec3,
    previous: Vec3,
    rest: Vec3,
}

/// Where a Verlet chain's rest shape comes from.
#[derive(Clone, Copy, PartialEq, Eq)]
enum RestShape {
    /// The offsets it was built with: nothing poses the bones (no bone's `Transform` is read).
    Fixed,
    /// Each bone's `Transform` as the frame left it, read every frame, and Dynamic Bone's
    /// stiffness limit: what Dynamic Bone does each frame (`UpdateParticles2`), so that an
    /// animation plays under it, as a `SpringChain` reads every joint's pose.
    Posed,
}

/// Dynamic Bone's component on a chain's root bone: the chain's particles, root first.
#[derive(Component)]
struct VerletChain {
    particles: Vec<Particle>,
    shape: RestShape,
}

impl VerletChain {
    fn new(joints: Vec<Entity>, shape: RestShape) -> Self {
        let particles = joints
            .into_iter()
            .enumerate()
            .map(|(index, entity)| {
                let at = Vec3::new(-BONE * index as f32, 0.0, 0.0);
                Particle {
                    entity,
                    position: at,
                    previous: at,
                    rest: if index == 0 {
                        Vec3::ZERO
                    } else {
                        Vec3::new(-BONE, 0.0, 0.0)
                    },
                }
            })
            .collect();
        Self { particles, shape }
    }
}

/// Dynamic Bone's step, one a frame: Verlet inertia with damping and gravity, a pull toward
/// the rest shape under the parent's orientation (of a posed chain: where each bone's
/// `Transform` puts it, no farther than the stiffness limit), the bone length restored, and
/// each joint turned to point at its child.
fn step_verlet(
    time: Res<Time>,
    mut chains: Query<(&mut VerletChain, &ChildOf)>,
    mut transforms: Query<&mut Transform>,
) {
    const DAMPING: f32 = 0.1;
    const ELASTICITY: f32 = 0.1;
    const STIFFNESS: f32 = 0.1;
    let dt = time.delta_secs();
    for (mut chain, body) in &mut chains {
        let Ok(body) = transforms.get(body.parent()).copied() else {
            continue;
        };
        let root = chain.particles[0].entity;
        let root_local = transforms.get(root).map_or(Transform::IDENTITY, |t| *t);
        let mut rotation = body.rotation * root_local.rotation;
        let first = body.transform_point(root_local.translation);
        chain.particles[0].position = first;
        chain.particles[0].previous = first;
        let mut rotations = Vec::with_capacity(chain.particles.len());
        let shape = chain.shape;
        for index in 1..chain.particles.len() {
            let parent = chain.particles[index - 1].position;
            let particle = &mut chain.particles[index];
            let offset = match shape {
                RestShape::Fixed => particle.rest,
                RestShape::Posed => transforms
                    .get(particle.entity)
                    .map_or(particle.rest, |local| local.translation),
            };
            let velocity = particle.position - particle.previous;
            particle.previous = particle.position;
            particle.position += velocity * (1.0 - DAMPING) + GRAVITY * dt * dt;
            let rest = parent + rotation * offset;
            particle.position += (rest - particle.position) * ELASTICITY;
            let length = offset.length();
            if shape == RestShape::Posed {
                // No farther from the rest place than a share of the bone's length.
                let away = rest - particle.position;
                let distance = away.length();
                let limit = length * (1.0 - STIFFNESS) * 2.0;
                if distance > limit {
                    particle.position += away * ((distance - limit) / distance);
                }
            }
            let direction = (particle.position - parent).normalize_or_zero();
            particle.position = parent + direction * length;
            let swing = Quat::from_rotation_arc((rotation * offset).normalize_or_zero(), direction);
            rotations.push(swing);
            rotation = swing * rotation;
        }
        let mut parent_rotation = body.rotation;
        for (index, swing) in rotations.into_iter().enumerate() {
            let Ok(mut transform) = transforms.get_mut(chain.particles[index].entity) else {
                continue;
            };
            let world = parent_rotation * transform.rotation;
            let turned = swing * world;
            transform.rotation = (parent_rotation.inverse() * turned).normalize();
            parent_rotation = turned;
        }
    }
}

fn chains(c: &mut Criterion) {
    let mut group = c.benchmark_group("chain_10k");
    for secondary in Secondary::ALL {
        let mut app = chain_app(secondary);
        for _ in 0..30 {
            app.update();
        }
        group.bench_function(secondary.name(), |b| b.iter(|| app.update()));
    }
    group.finish();
}

#[derive(TypePath)]
struct Lift;

/// The springs' targets, flipped every 30 frames.
#[derive(Resource, Default)]
struct Frame(u32);

fn retarget(
    mut frame: ResMut<Frame>,
    mut bases: Query<&mut TranslationSpring>,
    mut lifts: Query<&mut LayerSpring<Translation, Lift>>,
) {
    frame.0 += 1;
    if !frame.0.is_multiple_of(30) {
        return;
    }
    let sign = if frame.0.is_multiple_of(60) {
        1.0
    } else {
        -1.0
    };
    for mut spring in &mut bases {
        spring.set_target(Vec3::new(100.0 * sign, 0.0, 0.0));
    }
    for mut layer in &mut lifts {
        layer.set_target(Vec3::new(0.0, 20.0 * sign, 0.0));
    }
}

fn layers_app(layered: bool) -> App {
    let mut app = headless();
    app.add_plugins(SpringLayerPlugin::<Translation, Lift>::default())
        .init_resource::<Frame>()
        .add_systems(Update, retarget);
    let world = app.world_mut();
    if layered {
        world.spawn_batch((0..10_000).map(|_| {
            (
                Transform::default(),
                TranslationSpring::new(Spring::smooth(), Vec3::ZERO),
                LayerSpring::<Translation, Lift>::new(Spring::bouncy(), Vec3::ZERO),
            )
        }));
    } else {
        world.spawn_batch((0..20_000).map(|index| {
            let spring = if index % 2 == 0 {
                Spring::smooth()
            } else {
                Spring::bouncy()
            };
            (
                Transform::default(),
                TranslationSpring::new(spring, Vec3::ZERO),
            )
        }));
    }
    app
}

fn layers(c: &mut Criterion) {
    let mut group = c.benchmark_group("layers_20k");
    for (name, layered) in [("separate", false), ("layered", true)] {
        let mut app = layers_app(layered);
        for _ in 0..30 {
            app.update();
        }
        group.bench_function(name, |b| b.iter(|| app.update()));
    }
    group.finish();
}

criterion_group!(benches, chains, layers);

/// Frames counted per chain scene, after as many to warm up (which are not counted: the first
/// finds every chain's joints).
const COUNTED_FRAMES: u32 = 10;

/// The frames callgrind counts.
#[inline(never)]
fn measured(app: &mut App, frames: u32) {
    for _ in 0..frames {
        app.update();
    }
}

/// One chain scene's counted frames, every schedule on this thread (callgrind counts only the
/// thread `measured` runs on; transform propagation's parallel work, the same in every scene,
/// runs on the one compute thread: with none it never finishes).
fn one(secondary: Secondary) {
    let mut app = chain_app(secondary);
    for (_, schedule) in app.world_mut().resource_mut::<Schedules>().iter_mut() {
        schedule.set_executor(SingleThreadedExecutor::new());
    }
    for _ in 0..COUNTED_FRAMES {
        app.update();
    }
    measured(&mut app, COUNTED_FRAMES);
}

/// Instructions per joint per frame of each chain scene, and the chain's share against the
/// Dynamic Bone chain's and the fixed-shape Verlet chain's (each less the scene without
/// secondary motion).
fn count() {
    let per_joint = |secondary: Secondary| {
        let total = callgrind("*secondary::measured", Some(1), &["one", secondary.name()]);
        total as f64 / f64::from(COUNTED_FRAMES) / (CHAINS * JOINTS) as f64
    };
    let [none, verlet, dynamic_bone, chain] = Secondary::ALL.map(per_joint);
    println!(
        "chain_10k, instructions per joint per frame: none {none:.0}, verlet {verlet:.0}, \
         dynamic_bone {dynamic_bone:.0}, spring_chain {chain:.0}; own share spring_chain / \
         dynamic_bone = {:.2}, spring_chain / verlet = {:.2}",
        (chain - none) / (dynamic_bone - none),
        (chain - none) / (verlet - none)
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("one") => {
            let name = args.get(1).map_or("", String::as_str);
            let secondary = Secondary::ALL
                .into_iter()
                .find(|secondary| secondary.name() == name)
                .unwrap_or_else(|| panic!("no chain scene {name}"));
            one(secondary);
        }
        Some("count") => count(),
        _ => {
            benches();
            Criterion::default().configure_from_args().final_summary();
        }
    }
}
