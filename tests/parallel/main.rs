//! The springs step on a compute pool of two threads, as `SpringPlugins`'s docs set it up: the
//! table's springs stepped in parallel chunks (more than 2048 rows), and the transition table
//! prepared in parallel chunks (more than 4096 distinct springs). A test binary of its own:
//! Bevy's task pools are made once per process, and the other tests use the default pools.

use core::time::Duration;

use bevy::app::{TaskPoolOptions, TaskPoolPlugin, TaskPoolThreadAssignmentPolicy};
use bevy::prelude::*;
use bevy::tasks::ComputeTaskPool;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::prelude::*;
#[path = "../plugin/harness.rs"]
#[expect(
    dead_code,
    reason = "the plugin tests' helpers; this binary uses only the exact reference"
)]
mod harness;

/// Distinct springs, one per entity: more than the table prepares in one chunk.
const SPRINGS: usize = 6000;

/// How far every entity travels.
const DISTANCE: f32 = 100.0;

/// How far from its exact position a spring may be after the run: rounding (the error seen is
/// about `1.2e-5`), and less than half the closest two springs' positions differ by.
const TOLERANCE: f64 = 1e-4;

/// Every spring of a scene stepped on two compute threads with a time step that changes every
/// frame is where its exact solution is, to rounding: no entity reads another's state or
/// another's transition. Neighbouring springs' positions differ by far more than the tolerance,
/// so a mixed-up transition would show.
#[test]
fn springs_step_exactly_on_two_compute_threads() {
    let mut task_pool_options = TaskPoolOptions::default();
    task_pool_options.compute = TaskPoolThreadAssignmentPolicy {
        min_threads: 2,
        max_threads: 2,
        ..task_pool_options.compute
    };
    let mut app = App::new();
    app.add_plugins((
        MinimalPlugins.set(TaskPoolPlugin { task_pool_options }),
        TransformPlugin,
        SpringPlugins::default(),
    ));
    assert_eq!(ComputeTaskPool::get().thread_num(), 2);
    // Half-lives from 1 to 10 s: nothing settles in the two seconds run.
    let springs: Vec<Spring> = (0..SPRINGS)
        .map(|i| Spring::from_half_life(1.0 + 9.0 * i as f32 / SPRINGS as f32).unwrap())
        .collect();
    let entities: Vec<Entity> = springs
        .iter()
        .map(|spring| {
            app.world_mut()
                .spawn((
                    Transform::default(),
                    TranslationSpring::new(*spring, Vec3::X * DISTANCE),
                ))
                .id()
        })
        .collect();
    // The first update has no time step; then 120 frames around 60 fps, each different.
    app.update();
    for frame in 0..120_u32 {
        let jitter = 1.0 + 0.02 * (f64::from(frame) * 2.4).sin();
        app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            jitter / 60.0,
        )));
        app.update();
    }
    let elapsed = app.world().resource::<Time<Virtual>>().elapsed_secs_f64();
    assert!(elapsed > 1.9, "{elapsed}");
    let expected: Vec<f64> = springs
        .iter()
        .map(|spring| harness::exact(spring, 0.0, DISTANCE, elapsed).position)
        .collect();
    let mut worst = 0.0_f64;
    for (entity, expected) in entities.iter().zip(&expected) {
        let x = f64::from(app.world().get::<Transform>(*entity).unwrap().translation.x);
        worst = worst.max((x - expected).abs());
    }
    let closest = expected
        .windows(2)
        .map(|pair| (pair[1] - pair[0]).abs())
        .fold(f64::INFINITY, f64::min);
    println!("worst error {worst:e}; the closest neighbouring springs differ by {closest:e}");
    assert!(worst < TOLERANCE, "worst error {worst}");
    assert!(closest > 2.0 * TOLERANCE, "{closest}");
}
