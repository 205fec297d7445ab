//! The task pools the benches run with, for the benches that choose them.

use bevy::app::{PluginGroupBuilder, TaskPoolOptions, TaskPoolThreadAssignmentPolicy};
use bevy::prelude::*;

/// `MinimalPlugins`, with as many compute threads as `SPRUNG_BENCH_COMPUTE_THREADS` says (the
/// task-pool setting `SpringPlugins`'s docs give), or Bevy's default pools. The pools are made
/// once per process: a run measures one setting.
#[must_use]
pub(crate) fn minimal_plugins() -> PluginGroupBuilder {
    let threads = std::env::var("SPRUNG_BENCH_COMPUTE_THREADS")
        .ok()
        .and_then(|threads| threads.parse::<usize>().ok());
    let mut task_pool_options = TaskPoolOptions::default();
    if let Some(threads) = threads {
        task_pool_options.compute = TaskPoolThreadAssignmentPolicy {
            min_threads: threads,
            max_threads: threads,
            ..task_pool_options.compute
        };
    }
    MinimalPlugins.set(TaskPoolPlugin { task_pool_options })
}
