//! The per-frame cost of a camera rig with every part on, against `SpringFollow` alone, in one
//! criterion run: `cargo bench -p bevy_sprung --features camera --bench camera`.
//!
//! Each scene has `CAMERAS` players, each moving every frame along a circle, and (but for the
//! baseline) a camera per player. The measured time is a whole frame (`app.update()`); the
//! cost per camera is the difference from the baseline (the same players, no cameras) divided
//! by the cameras, printed with its ratio to `SpringFollow`'s after the run. Scenes:
//!
//! - `none`: the players alone (the baseline);
//! - `follow`: `SpringFollow` + `TranslationSpring` + `RotationSpring` (looking at the player);
//! - `rig_2d`: an orthographic `CameraRig` with two targets (the player and its neighbour),
//!   look-ahead, dead zone, screen position, confiner and group framing;
//! - `rig_orbit`: a perspective `CameraRig` with an `OrbitRig` turned every frame, look-ahead
//!   and group framing;
//! - `rig_rail`: a perspective `CameraRig` on a looped `CameraRail` round the player's circle
//!   (twelve Catmull-Rom segments), springing to the place nearest the player and looking at
//!   it.
//!
//! A counting allocator reports the allocations per frame of each scene beyond the baseline's
//! (the rig must make none).

use core::sync::atomic::{AtomicUsize, Ordering};
use std::alloc::{GlobalAlloc, Layout, System};
use std::time::{Duration, Instant};

use bevy::camera::{OrthographicProjection, Projection};
use bevy::math::cubic_splines::{CubicCardinalSpline, CyclicCubicGenerator};
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy::window::{PrimaryWindow, WindowResolution};
use bevy_sprung::camera::{
    CameraRail, CameraTargets, Confiner, DeadZone, GroupFraming, LookAhead, OrbitRig,
    ScreenPosition,
};
use bevy_sprung::prelude::*;
use criterion::{Criterion, criterion_group, criterion_main};

/// Counts allocations, to check that a frame of rigs allocates nothing.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

#[expect(
    unsafe_code,
    reason = "counting allocations takes a `GlobalAlloc`, which forwards to the system's"
)]
// SAFETY: every call is forwarded to the system allocator unchanged.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: the caller's contract is the system allocator's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: the caller's contract is the system allocator's.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: the caller's contract is the system allocator's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Cameras (and players) per scene.
const CAMERAS: usize = 1000;

#[derive(Component)]
struct Player(f32);

/// Gameplay: every player runs round its circle.
fn run(time: Res<Time>, mut players: Query<(&Player, &mut Transform)>) {
    let t = time.elapsed_secs();
    for (player, mut transform) in &mut players {
        let angle = t * 0.8 + player.0;
        transform.translation =
            Vec3::new(400.0 * angle.cos(), 250.0 * angle.sin(), 0.0) + Vec3::X * player.0 * 500.0;
    }
}

/// Turns every orbit a little each frame, as mouse input would.
fn turn(mut orbits: Query<&mut OrbitRig>) {
    for mut orbit in &mut orbits {
        orbit.rotate(Vec2::new(0.01, 0.0));
    }
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Scene {
    None,
    Follow,
    Rig2d,
    RigOrbit,
    RigRail,
}

impl Scene {
    const ALL: [Self; 5] = [
        Self::None,
        Self::Follow,
        Self::Rig2d,
        Self::RigOrbit,
        Self::RigRail,
    ];

    fn name(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::Follow => "follow",
            Self::Rig2d => "rig_2d",
            Self::RigOrbit => "rig_orbit",
            Self::RigRail => "rig_rail",
        }
    }
}

/// The app of `scene`, run for a second so that every system has joined its schedule.
fn app(scene: Scene) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin, SpringPlugins::default()))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            1.0 / 60.0,
        )))
        .add_systems(Update, (run, turn));
    app.world_mut().spawn((
        Window {
            resolution: WindowResolution::new(1280, 720).with_scale_factor_override(1.0),
            ..default()
        },
        PrimaryWindow,
    ));
    #[expect(clippy::cast_precision_loss, reason = "a few players")]
    let players: Vec<Entity> = (0..CAMERAS)
        .map(|i| {
            app.world_mut()
                .spawn((Player(i as f32 * 0.01), Transform::default()))
                .id()
        })
        .collect();
    for (i, &player) in players.iter().enumerate() {
        let neighbour = players[(i + 1) % CAMERAS];
        let targets = CameraTargets::new([
            CameraTarget::new(player).with_radius(40.0),
            CameraTarget::new(neighbour),
        ]);
        match scene {
            Scene::None => {}
            Scene::Follow => {
                let offset = Vec3::new(0.0, 4.0, 10.0);
                app.world_mut().spawn((
                    Transform::from_translation(offset),
                    TranslationSpring::new(Spring::smooth(), offset),
                    RotationSpring::new(Spring::smooth(), Quat::IDENTITY),
                    SpringFollow::new(player, offset).looking_at(Vec3::ZERO),
                ));
            }
            Scene::Rig2d => {
                app.world_mut().spawn((
                    Projection::Orthographic(OrthographicProjection::default_2d()),
                    CameraRig::new(Spring::smooth()).with_vertical(Spring::gentle()),
                    targets,
                    LookAhead::new(0.4),
                    DeadZone::view(Vec2::new(0.05, 0.05)),
                    ScreenPosition(Vec2::new(0.0, -1.0 / 6.0)),
                    Confiner::new(Rect::new(-2000.0, -1000.0, 2000.0, 1000.0))
                        .with_slowing_distance(100.0),
                    GroupFraming::new(0.1),
                ));
            }
            Scene::RigOrbit => {
                app.world_mut().spawn((
                    Projection::Perspective(default()),
                    CameraRig::new(Spring::smooth()),
                    targets,
                    OrbitRig::new(600.0),
                    LookAhead::new(0.3),
                    GroupFraming::new(0.1),
                ));
            }
            Scene::RigRail => {
                // A ring round the player's circle, 300 up.
                #[expect(clippy::cast_precision_loss, reason = "a few players")]
                let centre = Vec3::X * (i as f32 * 0.01) * 500.0;
                let ring = (0..12).map(|k| {
                    #[expect(clippy::cast_precision_loss, reason = "twelve points")]
                    let angle = k as f32 * core::f32::consts::TAU / 12.0;
                    centre + Vec3::new(600.0 * angle.cos(), 450.0 * angle.sin(), 300.0)
                });
                let rail = CubicCardinalSpline::new_catmull_rom(ring)
                    .to_curve_cyclic()
                    .expect("twelve points make a loop");
                app.world_mut().spawn((
                    Projection::Perspective(default()),
                    CameraRig::new(Spring::smooth()),
                    CameraTargets::single(player),
                    CameraRail::new(rail).looped(),
                ));
            }
        }
    }
    for _ in 0..60 {
        app.update();
    }
    app
}

fn cameras(c: &mut Criterion) {
    let mut group = c.benchmark_group("camera");
    let mut means = Vec::new();
    for scene in Scene::ALL {
        let mut app = app(scene);
        group.bench_function(scene.name(), |b| b.iter(|| app.update()));
        // Criterion's estimate is not exposed to the bench: measure the mean here too, in the
        // same run, for the per-camera difference.
        let start = Instant::now();
        let before = ALLOCATIONS.load(Ordering::Relaxed);
        for _ in 0..2000 {
            app.update();
        }
        let allocations = ALLOCATIONS.load(Ordering::Relaxed) - before;
        means.push((
            scene,
            start.elapsed().as_secs_f64() / 2000.0,
            allocations as f64 / 2000.0,
        ));
    }
    group.finish();
    let (_, baseline, baseline_allocations) = means[0];
    let follow = means[1].1 - baseline;
    println!(
        "\nper camera per frame, beyond {CAMERAS} players alone ({:.1} µs a frame):",
        baseline * 1e6
    );
    for &(scene, mean, allocations) in &means[1..] {
        #[expect(clippy::cast_precision_loss, reason = "a few cameras")]
        let per_camera = (mean - baseline) / CAMERAS as f64;
        println!(
            "  {:<10} {:>6.2} µs  ({:.2}× SpringFollow)  allocations per frame beyond the baseline: {:+.2}",
            scene.name(),
            per_camera * 1e6,
            (mean - baseline) / follow,
            allocations - baseline_allocations,
        );
    }
}

criterion_group!(benches, cameras);
criterion_main!(benches);
