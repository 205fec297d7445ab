//! The per-frame cost of the plugin against what Bevy users write instead, in one criterion run
//! so that the ratios read off one run on a shared machine. See `scenarios/mod.rs` for the
//! scenes; every measured frame moves every entity (checked after each measurement).
//!
//! Groups (100 000 entities unless named):
//! - `euler`: one frame of the animation's schedule, `dt` fixed at 1/60 s — translation springs
//!   sharing one spring against a hand-written semi-implicit Euler system and a hand-written
//!   exact spring (one shared transition, no checks: the floor for any exact spring), and a
//!   spring per entity (a fixed step, as in `FixedUpdate`, reuses every transition);
//! - `ui`: the same for a UI property, `UiTransform::scale`;
//! - `varying_dt`: `dt` different every frame (as Bevy's virtual time is) — one shared spring,
//!   8 springs in random entity order, a spring per entity — against spring_damper 0.1.1's
//!   critically damped springs of the same half-lives;
//! - `rest`: the same springs asleep, and an app with no springs against one without the
//!   plugin (whole frames);
//! - `tweens`: `smooth_nudge` and bevy_tweening 0.16, for reference;
//! - `frame_1m`: whole frames of a million translation springs with transform propagation,
//!   on the multi-threaded executor, against the Euler system and a system that only moves
//!   every translation (the floor any animation of a million `Transform`s pays in Bevy): set up
//!   for a scene whose `Transform`s mostly move (`StaticTransformOptimizations::Disabled`), and
//!   the springs once more with Bevy's default, the static-scene optimisation.

#[path = "scenarios/mod.rs"]
mod scenarios;

use bevy::prelude::*;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use scenarios::{FRAME, Method, Propagation, varying_dt};

/// Entities per scene (`SPRUNG_BENCH_COUNT` overrides it, for looking at cache effects).
fn count() -> usize {
    std::env::var("SPRUNG_BENCH_COUNT")
        .ok()
        .and_then(|count| count.parse().ok())
        .unwrap_or(100_000)
}

/// Measures one frame of each method's schedule in `group`, with a fixed or a varying `dt`.
fn schedule_group(c: &mut Criterion, group: &str, methods: &[Method], vary: bool) {
    let mut group = c.benchmark_group(group);
    group.throughput(Throughput::Elements(count() as u64));
    group.sample_size(30);
    for &method in methods {
        // Built on first use: criterion calls the routine once per sample, and not at all for
        // benchmarks its filter leaves out.
        let mut app = None;
        let schedule = method.schedule();
        let mut frame = 0_u64;
        group.bench_function(BenchmarkId::from_parameter(method.name()), |b| {
            let app = app.get_or_insert_with(|| method.app(count(), Propagation::Off));
            b.iter(|| {
                let world = app.world_mut();
                frame += 1;
                Method::set_dt(world, if vary { varying_dt(frame) } else { FRAME });
                world.run_schedule(schedule);
            });
        });
        if let Some(mut app) = app {
            let world = app.world_mut();
            let since = world.increment_change_tick();
            Method::set_dt(world, FRAME);
            world.run_schedule(schedule);
            method.check(world, count(), since);
        }
    }
    group.finish();
}

fn euler(c: &mut Criterion) {
    schedule_group(
        c,
        "euler",
        &[
            Method::Euler,
            Method::BareExact,
            Method::LanesModel,
            Method::Springs { springs: 1 },
            Method::Springs { springs: 0 },
        ],
        false,
    );
}

fn ui(c: &mut Criterion) {
    schedule_group(
        c,
        "ui",
        &[
            Method::EulerUiScale,
            Method::UiScaleSprings,
            Method::UiTranslationSprings,
        ],
        false,
    );
}

fn varying(c: &mut Criterion) {
    schedule_group(
        c,
        "varying_dt",
        &[
            Method::Springs { springs: 1 },
            Method::Springs { springs: 8 },
            Method::Springs { springs: 0 },
            Method::SpringDamper { springs: 1 },
            Method::SpringDamper { springs: 8 },
            Method::SpringDamper { springs: 0 },
        ],
        true,
    );
}

fn rest(c: &mut Criterion) {
    schedule_group(
        c,
        "rest",
        &[Method::SpringsAtRest, Method::Springs { springs: 1 }],
        false,
    );
    let mut group = c.benchmark_group("empty");
    for (name, plugin) in [("no_plugin", false), ("spring_plugin", true)] {
        // With `TransformPlugin` in both, as in any app with something to spring: `PostUpdate`
        // then exists without the plugin too, and the difference is the plugin's own cost.
        let mut app = App::new();
        app.add_plugins((scenarios::minimal_plugins(), TransformPlugin));
        if plugin {
            app.add_plugins(bevy_sprung::SpringPlugins::default());
        }
        app.finish();
        app.cleanup();
        app.update();
        group.bench_function(name, |b| b.iter(|| app.update()));
    }
    group.finish();
}

fn tweens(c: &mut Criterion) {
    schedule_group(
        c,
        "tweens",
        &[
            Method::SmoothNudge,
            Method::Tweening,
            Method::Springs { springs: 1 },
        ],
        false,
    );
}

/// Whole frames (`app.update()`, with transform propagation) of a million springs.
fn frame_1m(c: &mut Criterion) {
    let count = 1_000_000;
    let mut group = c.benchmark_group("frame_1m");
    group.throughput(Throughput::Elements(count as u64));
    group.sample_size(10);
    let moving = Propagation::MovingScene;
    for (method, propagation) in [
        (Method::Springs { springs: 1 }, moving),
        (Method::Euler, moving),
        (Method::Touch, moving),
        (Method::Springs { springs: 1 }, Propagation::StaticScene),
    ] {
        let mut app = None;
        let name = match propagation {
            Propagation::StaticScene => format!("{}_static_scene", method.name()),
            _ => method.name(),
        };
        group.bench_function(BenchmarkId::from_parameter(name), |b| {
            let app = app.get_or_insert_with(|| method.app(count, propagation));
            b.iter(|| app.update());
        });
        if let Some(mut app) = app {
            let since = app.world_mut().increment_change_tick();
            app.update();
            method.check(app.world_mut(), count, since);
        }
    }
    group.finish();
}

criterion_group!(benches, euler, ui, varying, rest, tweens, frame_1m);
criterion_main!(benches);
