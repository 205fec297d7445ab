//! The per-frame cost of the plugin against what Bevy users write instead, all in one criterion
//! run so that the ratios read off one run on a shared machine.
//!
//! For N ∈ {1k, 10k, 100k} entities with a `Transform`, one frame of:
//! - `springs`: a [`TranslationSpring`] each, awake every measured frame;
//! - `springs_at_rest`: the same springs asleep (target reached);
//! - `smooth_nudge`: a hand-written system calling Bevy's [`StableInterpolate::smooth_nudge`]
//!   on `Transform::translation` toward a per-entity [`NudgeTarget`];
//! - `bevy_tweening`: a `TweenAnim` per entity, a `Tween` of `TransformPositionLens`;
//! - `handwritten_spring`: the floor for any exact spring in this layout, for reference: a
//!   hand-written system that applies one shared transition to a velocity component, with
//!   no validation, rest check, sleep or per-entity parameters.
//!
//! Group `schedule/N` runs only the schedule that holds the animation (`PostUpdate` for the
//! springs, `Update` for the others), so the fixed cost of a frame does not dilute the ratios;
//! the `Time` delta stays at the last frame's `1/60 s`. Group `frame/100000` runs whole frames
//! (`app.update()`) with `TransformPlugin`, to show what propagation adds. Group `empty` runs
//! whole frames of an app with `TransformPlugin` and no springs, with and without
//! [`SpringPlugin`].
//!
//! Every app is `MinimalPlugins` with `TimeUpdateStrategy::ManualDuration(1/60 s)`; the schedule
//! groups leave out `TransformPlugin` (propagation would add the same cost to every method).
//! The bench build has no `multi_threaded` Bevy feature: every method runs on one thread with
//! the single-threaded executor (`par_iter_mut` in the plugin runs serially), so the numbers are
//! CPU time per frame, and the same executor serves every method.

use core::f32::consts::TAU;
use core::time::Duration;

use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::ScheduleLabel;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::prelude::*;
use bevy_sprung::sprung::SpringState;
use bevy_tweening::lens::TransformPositionLens;
use bevy_tweening::{RepeatCount, RepeatStrategy, Tween, TweenAnim, TweeningPlugin};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

/// The entity counts.
const COUNTS: [usize; 3] = [1_000, 10_000, 100_000];
/// How far each entity is from its target, in world units.
const DISTANCE: f32 = 1_000.0;
/// `smooth_nudge`'s decay rate, per second (a time constant of 1.6 s). Its cost does not depend
/// on how close an entity is: the system writes every entity every frame.
const DECAY_RATE: f32 = 0.1 * TAU;

/// One frame, as the `Duration` Bevy adds each update.
fn frame_time() -> Duration {
    Duration::from_secs_f64(1.0 / 60.0)
}

/// A 1 Hz spring with damping ratio `1e-5`: from `DISTANCE` away, its amplitude halves every
/// `ln 2/(ζω)` ≈ 11 000 s of simulated time, while even a long bench run steps a few thousand
/// seconds of 60 fps frames, so it never comes to rest. Every entity shares it, as in a scene
/// built from a few presets (the transition is the same for any damping).
fn active_spring() -> Spring {
    Spring::from_natural_frequency(TAU, 1e-5).expect("valid bench spring")
}

/// Where entity `i` starts: spread over a plane, so that no two move alike.
fn start(i: usize) -> Vec3 {
    let i = i as f32;
    Vec3::new(i % 317.0, (i / 317.0).floor(), 0.0)
}

/// Where entity `i` is sent: `DISTANCE` away from its start, in a direction of its own.
fn target(i: usize) -> Vec3 {
    let angle = i as f32 * 0.618_034 * TAU;
    start(i) + DISTANCE * Vec3::new(angle.cos(), angle.sin(), 0.5).normalize()
}

/// The target of the hand-written `smooth_nudge` system.
#[derive(Component, Clone, Copy)]
struct NudgeTarget(Vec3);

/// What Bevy users write by hand to follow a target: exponential smoothing, frame-rate
/// independent, no velocity.
fn nudge(time: Res<Time>, mut query: Query<(&mut Transform, &NudgeTarget)>) {
    let dt = time.delta_secs();
    for (mut transform, target) in &mut query {
        transform
            .translation
            .smooth_nudge(&target.0, DECAY_RATE, dt);
    }
}

/// The velocity of the hand-written spring.
#[derive(Component, Clone, Copy)]
struct HandVelocity(Vec3);

/// The target of the hand-written spring.
#[derive(Component, Clone, Copy)]
struct HandTarget(Vec3);

/// The least an exact spring can do per entity: one transition for all, computed once per
/// frame, applied to position and velocity.
fn hand_spring(
    time: Res<Time>,
    mut query: Query<(&mut Transform, &mut HandVelocity, &HandTarget)>,
) {
    let transition = active_spring().transition(time.delta_secs());
    for (mut transform, mut velocity, target) in &mut query {
        let next = transition.step(
            SpringState::new(transform.translation, velocity.0),
            target.0,
        );
        transform.translation = next.position;
        velocity.0 = next.velocity;
    }
}

/// How the entities are animated.
#[derive(Clone, Copy, Debug)]
enum Method {
    /// Awake [`TranslationSpring`]s.
    Springs,
    /// [`TranslationSpring`]s asleep on their targets.
    SpringsAtRest,
    /// The hand-written [`nudge`] system.
    SmoothNudge,
    /// `bevy_tweening`.
    Tweening,
    /// The hand-written [`hand_spring`] system.
    HandwrittenSpring,
}

impl Method {
    const ALL: [Self; 5] = [
        Self::Springs,
        Self::SpringsAtRest,
        Self::SmoothNudge,
        Self::Tweening,
        Self::HandwrittenSpring,
    ];

    fn name(self) -> &'static str {
        match self {
            Self::Springs => "springs",
            Self::SpringsAtRest => "springs_at_rest",
            Self::SmoothNudge => "smooth_nudge",
            Self::Tweening => "bevy_tweening",
            Self::HandwrittenSpring => "handwritten_spring",
        }
    }

    /// The schedule that holds the method's systems.
    fn schedule(self) -> Interned<dyn ScheduleLabel> {
        match self {
            Self::Springs | Self::SpringsAtRest => PostUpdate.intern(),
            Self::SmoothNudge | Self::Tweening | Self::HandwrittenSpring => Update.intern(),
        }
    }

    /// An app with `count` entities animated by this method, run for a few frames so that the
    /// `Time` delta is `1/60 s` (the first frame has `dt = 0`) and resting springs are asleep.
    fn app(self, count: usize, propagate: bool) -> App {
        let mut app = minimal_app();
        if propagate {
            app.add_plugins(TransformPlugin);
        }
        let world = match self {
            Self::Springs | Self::SpringsAtRest => {
                app.add_plugins(SpringPlugin::default());
                app.world_mut()
            }
            Self::SmoothNudge => {
                app.add_systems(Update, nudge);
                app.world_mut()
            }
            Self::Tweening => {
                app.add_plugins(TweeningPlugin);
                app.world_mut()
            }
            Self::HandwrittenSpring => {
                app.add_systems(Update, hand_spring);
                app.world_mut()
            }
        };
        match self {
            Self::Springs => {
                let spring = active_spring();
                world.spawn_batch((0..count).map(move |i| {
                    (
                        Transform::from_translation(start(i)),
                        TranslationSpring::new(spring, target(i)),
                    )
                }));
            }
            Self::SpringsAtRest => {
                let spring = active_spring();
                world.spawn_batch((0..count).map(move |i| {
                    (
                        Transform::from_translation(target(i)),
                        TranslationSpring::new(spring, target(i)),
                    )
                }));
            }
            Self::SmoothNudge => {
                world.spawn_batch((0..count).map(|i| {
                    (
                        Transform::from_translation(start(i)),
                        NudgeTarget(target(i)),
                    )
                }));
            }
            Self::Tweening => {
                // A 1 s ease-in-out there and back, forever: active every frame.
                world.spawn_batch((0..count).map(|i| {
                    let tween = Tween::new(
                        EaseFunction::QuadraticInOut,
                        Duration::from_secs(1),
                        TransformPositionLens {
                            start: start(i),
                            end: target(i),
                        },
                    )
                    .with_repeat(RepeatCount::Infinite, RepeatStrategy::MirroredRepeat);
                    (Transform::from_translation(start(i)), TweenAnim::new(tween))
                }));
            }
            Self::HandwrittenSpring => {
                world.spawn_batch((0..count).map(|i| {
                    (
                        Transform::from_translation(start(i)),
                        HandVelocity(Vec3::ZERO),
                        HandTarget(target(i)),
                    )
                }));
            }
        }
        app.finish();
        app.cleanup();
        for _ in 0..3 {
            app.update();
        }
        self.check(&mut app, count, App::update);
        app
    }

    /// Checks that the next run of `run` writes every entity's `Transform` (and, for springs
    /// and tweens, moves it); at rest, that it writes none and every spring sleeps. Sleep is
    /// absorbing here (nothing retargets), so springs that are all awake after a measurement
    /// were awake in every measured frame.
    fn check(self, app: &mut App, count: usize, run: impl FnOnce(&mut App)) {
        let before = translations(app.world_mut());
        // Every system of `run` gets a change tick after `since`.
        let since = app.world_mut().increment_change_tick();
        run(app);
        let after = translations(app.world_mut());
        let moved = before.iter().zip(&after).filter(|(b, a)| b != a).count();
        let world = app.world_mut();
        let now = world.read_change_tick();
        let written = world
            .query::<Ref<Transform>>()
            .iter(world)
            .filter(|transform| transform.last_changed().is_newer_than(since, now))
            .count();
        let asleep = world
            .query_filtered::<(), With<SpringAsleep<Translation>>>()
            .iter(world)
            .count();
        match self {
            Self::SpringsAtRest => {
                assert_eq!(asleep, count, "{self:?}: every spring should sleep");
                assert_eq!(written, 0, "{self:?}: no transform should be written");
            }
            Self::Springs | Self::SmoothNudge | Self::Tweening | Self::HandwrittenSpring => {
                assert_eq!(asleep, 0, "{self:?}: no spring should sleep");
                assert_eq!(
                    written, count,
                    "{self:?}: every transform should be written"
                );
            }
        }
        match self {
            Self::Springs | Self::Tweening | Self::HandwrittenSpring => {
                assert_eq!(moved, count, "{self:?}: every entity should move");
            }
            // `smooth_nudge` converges (in `f32`, exactly) but keeps writing every frame, at
            // the same cost.
            Self::SmoothNudge | Self::SpringsAtRest => {}
        }
        if let Self::Tweening = self {
            let anims = world.query::<&TweenAnim>().iter(world).count();
            assert_eq!(anims, count, "every tween should still play");
        }
    }
}

/// Every entity's translation, in query order (the same order before and after a frame).
fn translations(world: &mut World) -> Vec<Vec3> {
    world
        .query::<&Transform>()
        .iter(world)
        .map(|transform| transform.translation)
        .collect()
}

/// `MinimalPlugins` advancing a fixed `1/60 s` per update.
fn minimal_app() -> App {
    let mut app = App::new();
    app.add_plugins(MinimalPlugins)
        .insert_resource(TimeUpdateStrategy::ManualDuration(frame_time()));
    app
}

/// One run of each method's schedule, for each count.
fn schedules(c: &mut Criterion) {
    for count in COUNTS {
        let mut group = c.benchmark_group(format!("schedule/{count}"));
        group.throughput(Throughput::Elements(count as u64));
        if count >= 100_000 {
            group.sample_size(20);
        }
        for method in Method::ALL {
            // Built on first use: criterion calls the routine once per sample, and not at all
            // for benchmarks its filter leaves out.
            let mut app = None;
            let schedule = method.schedule();
            group.bench_function(BenchmarkId::from_parameter(method.name()), |b| {
                let app = app.get_or_insert_with(|| method.app(count, false));
                b.iter(|| app.world_mut().run_schedule(schedule));
            });
            if let Some(mut app) = app {
                method.check(&mut app, count, |app| {
                    app.world_mut().run_schedule(schedule);
                });
            }
        }
        group.finish();
    }
}

/// Whole frames at 100k entities, with transform propagation.
fn frames(c: &mut Criterion) {
    let count = 100_000;
    let mut group = c.benchmark_group(format!("frame/{count}"));
    group.throughput(Throughput::Elements(count as u64));
    group.sample_size(20);
    for method in Method::ALL {
        let mut app = None;
        group.bench_function(BenchmarkId::from_parameter(method.name()), |b| {
            let app = app.get_or_insert_with(|| method.app(count, true));
            b.iter(|| app.update());
        });
        if let Some(mut app) = app {
            method.check(&mut app, count, App::update);
        }
    }
    group.finish();
}

/// Whole frames of an app with no springs, with and without the plugin.
fn empty(c: &mut Criterion) {
    let mut group = c.benchmark_group("empty");
    for (name, plugin) in [("no_plugin", false), ("spring_plugin", true)] {
        // With `TransformPlugin` in both, as in any app with something to spring: `PostUpdate`
        // then exists without the plugin too, and the difference is the plugin's own cost.
        let mut app = minimal_app();
        app.add_plugins(TransformPlugin);
        if plugin {
            app.add_plugins(SpringPlugin::default());
        }
        app.finish();
        app.cleanup();
        app.update();
        group.bench_function(name, |b| b.iter(|| app.update()));
    }
    group.finish();
}

criterion_group!(benches, schedules, frames, empty);
criterion_main!(benches);
