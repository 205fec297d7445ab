//! The scenes the benchmarks measure, shared by the criterion suite (`plugin.rs`) and the
//! instruction counter (`instructions.rs`): N entities animated by one method, in an app whose
//! time step the bench sets before every frame.
//!
//! Every method moves the same entities the same way: from a start spread over a plane toward a
//! target 1000 units away, with springs whose half-life is long enough (hundreds of seconds)
//! that nothing comes to rest while measured — every frame measures moving springs, and the
//! checks after each measurement assert it.

#![allow(
    dead_code,
    reason = "each bench binary uses a different part of the shared scenarios"
)]

#[path = "../support/task_pools.rs"]
mod task_pools;

pub(crate) use task_pools::minimal_plugins;

use core::f32::consts::TAU;
use core::time::Duration;

use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::ScheduleLabel;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringAsleep;
use bevy_sprung::sprung::SpringState;
use bevy_tweening::lens::TransformPositionLens;
use bevy_tweening::{RepeatCount, RepeatStrategy, Tween, TweenAnim, TweeningPlugin};

pub(crate) mod lanes;

/// How far each entity is from its target, in world units.
pub(crate) const DISTANCE: f32 = 1_000.0;

/// The half-life of the springs that every method shares: long, so they keep moving.
pub(crate) const HALF_LIFE: f32 = 400.0;

/// `smooth_nudge`'s decay rate, per second.
const DECAY_RATE: f32 = 0.1 * TAU;

/// One frame at 60 fps.
pub(crate) const FRAME: f32 = 1.0 / 60.0;

/// The `dt` of frame `k` when it varies: 60 fps with a jitter of up to ±2.5 % that never
/// repeats a value in a bench run (as Bevy's virtual time does from frame to frame).
#[must_use]
pub(crate) fn varying_dt(k: u64) -> f32 {
    #[expect(clippy::cast_precision_loss, reason = "a phase")]
    let phase = k as f32 * 0.618_034;
    FRAME * (1.0 + 0.025 * (phase * TAU).sin())
}

/// Where entity `i` starts: spread over a plane, so that no two move alike.
#[must_use]
pub(crate) fn start(i: usize) -> Vec3 {
    #[expect(clippy::cast_precision_loss, reason = "entity indices are small")]
    let i = i as f32;
    Vec3::new(i % 317.0, (i / 317.0).floor(), 0.0)
}

/// Where entity `i` is sent: `DISTANCE` away from its start, in a direction of its own.
#[must_use]
pub(crate) fn target(i: usize) -> Vec3 {
    #[expect(clippy::cast_precision_loss, reason = "entity indices are small")]
    let angle = i as f32 * 0.618_034 * TAU;
    start(i) + DISTANCE * Vec3::new(angle.cos(), angle.sin(), 0.5).normalize()
}

/// The half-life of entity `i` for `springs` distinct springs, `0` meaning one per entity;
/// shuffled over the entities (a scene's springs are not sorted by kind).
#[must_use]
pub(crate) fn half_life(i: usize, springs: usize) -> f32 {
    let index = if springs == 0 {
        i
    } else {
        // A multiplicative hash: neighbouring entities get unrelated springs.
        (i.wrapping_mul(0x9E37_79B9) >> 7) % springs
    };
    #[expect(clippy::cast_precision_loss, reason = "small indices")]
    let spread = index as f32 * 1e-3;
    HALF_LIFE * (1.0 + spread)
}

/// Ours, from a half-life (the time to cover half the distance from rest): critically damped.
#[must_use]
pub(crate) fn sprung_spring(half_life: f32) -> Spring {
    Spring::from_half_life(half_life).expect("valid bench spring")
}

/// spring_damper's `halflife` for the same motion: its damping is `4 ln 2/(h + 1e-5)` and
/// `ω = damping/2`, ours `ω = 1.678…/half_life`.
#[must_use]
pub(crate) fn spring_damper_halflife(half_life: f32) -> f32 {
    let omega = sprung_spring(half_life).natural_frequency();
    2.0 * core::f32::consts::LN_2 / omega - 1e-5
}

/// Whether a scene's whole frames propagate transforms, and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Propagation {
    /// No `TransformPlugin`: the animation alone.
    Off,
    /// `TransformPlugin` with Bevy's defaults: the static-scene optimisation marks the tree of
    /// every changed `Transform` dirty, entity by entity, before propagating.
    StaticScene,
    /// `TransformPlugin` with `StaticTransformOptimizations::Disabled`: what a scene whose
    /// `Transform`s mostly move every frame sets (the marking then costs more than it saves).
    MovingScene,
}

/// What animates the entities.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Method {
    /// [`TranslationSpring`]s.
    Springs {
        /// Distinct springs, 0 for one per entity.
        springs: usize,
    },
    /// [`TranslationSpring`]s asleep on their targets.
    SpringsAtRest,
    /// [`UiTransformScaleSpring`]s: a UI property.
    UiScaleSprings,
    /// [`UiTransformTranslationSpring`]s: a UI property in `Val` lengths (pixels), a hover lift or a
    /// slide-in.
    UiTranslationSprings,
    /// spring_damper 0.1.1's `TranslationSpring`, with `springs` distinct half-lives.
    SpringDamper {
        /// Distinct half-lives, 0 for one per entity.
        springs: usize,
    },
    /// A hand-written semi-implicit Euler spring on the translation.
    Euler,
    /// A hand-written semi-implicit Euler spring on `UiTransform::scale`.
    EulerUiScale,
    /// A hand-written exact spring: one shared transition, no checks.
    BareExact,
    /// A model of the plugin's usual step, four springs at a time (see `lanes.rs`).
    LanesModel,
    /// A hand-written `smooth_nudge` system.
    SmoothNudge,
    /// bevy_tweening 0.16.
    Tweening,
    /// No animation: a system that moves every translation by a constant step. The floor of a
    /// frame that changes every `Transform` (change ticks, and propagation when it runs).
    Touch,
    /// Nothing to animate: the plugin, and entities with a `Transform` alone. What a whole
    /// frame of Bevy's costs that no animation can save (the base of sleeping springs' cost).
    Idle,
}

impl Method {
    /// A short name for reports.
    #[must_use]
    pub(crate) fn name(self) -> String {
        match self {
            Self::Springs { springs: 1 } => "sprung_shared".into(),
            Self::Springs { springs: 0 } => "sprung_per_entity".into(),
            Self::Springs { springs } => format!("sprung_{springs}_springs"),
            Self::SpringsAtRest => "sprung_at_rest".into(),
            Self::UiScaleSprings => "sprung_ui_scale".into(),
            Self::UiTranslationSprings => "sprung_ui_translation".into(),
            Self::SpringDamper { springs: 1 } => "spring_damper_shared".into(),
            Self::SpringDamper { springs: 0 } => "spring_damper_per_entity".into(),
            Self::SpringDamper { springs } => format!("spring_damper_{springs}_springs"),
            Self::Euler => "euler".into(),
            Self::EulerUiScale => "euler_ui_scale".into(),
            Self::BareExact => "bare_exact".into(),
            Self::LanesModel => "lanes_model".into(),
            Self::SmoothNudge => "smooth_nudge".into(),
            Self::Tweening => "bevy_tweening".into(),
            Self::Touch => "touch".into(),
            Self::Idle => "idle".into(),
        }
    }

    /// The schedule that holds the method's systems.
    #[must_use]
    pub(crate) fn schedule(self) -> Interned<dyn ScheduleLabel> {
        match self {
            Self::Springs { .. }
            | Self::SpringsAtRest
            | Self::UiScaleSprings
            | Self::UiTranslationSprings
            | Self::SpringDamper { .. }
            | Self::Idle => PostUpdate.intern(),
            Self::Euler
            | Self::EulerUiScale
            | Self::BareExact
            | Self::LanesModel
            | Self::SmoothNudge
            | Self::Tweening
            | Self::Touch => Update.intern(),
        }
    }

    /// An app with `count` entities animated by this method (with transform propagation as
    /// `propagation` says), run for a few frames so that the springs at rest sleep.
    pub(crate) fn app(self, count: usize, propagation: Propagation) -> App {
        let mut app = App::new();
        app.add_plugins(minimal_plugins())
            .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(
                FRAME,
            )));
        if propagation != Propagation::Off {
            app.add_plugins(TransformPlugin);
        }
        if propagation == Propagation::MovingScene {
            app.insert_resource(bevy::transform::StaticTransformOptimizations::Disabled);
        }
        match self {
            Self::Springs { .. }
            | Self::SpringsAtRest
            | Self::UiScaleSprings
            | Self::UiTranslationSprings
            | Self::Idle => {
                app.add_plugins(SpringPlugins::default());
            }
            Self::SpringDamper { .. } => {
                app.add_plugins(spring_damper::bevy_layer::SpringPlugin);
            }
            Self::Euler => {
                app.add_systems(Update, euler);
            }
            Self::EulerUiScale => {
                app.add_systems(Update, euler_ui_scale);
            }
            Self::BareExact => {
                app.add_systems(Update, bare_exact);
            }
            Self::LanesModel => {
                app.add_systems(Update, lanes::lanes_model);
            }
            Self::SmoothNudge => {
                app.add_systems(Update, nudge);
            }
            Self::Tweening => {
                app.add_plugins(TweeningPlugin);
            }
            Self::Touch => {
                app.add_systems(Update, touch);
            }
        }
        self.spawn(app.world_mut(), count);
        app.finish();
        app.cleanup();
        for _ in 0..3 {
            app.update();
        }
        app
    }

    fn spawn(self, world: &mut World, count: usize) {
        match self {
            Self::Springs { springs } => {
                world.spawn_batch((0..count).map(move |i| {
                    let spring = sprung_spring(half_life(i, springs));
                    (
                        Transform::from_translation(start(i)),
                        TranslationSpring::new(spring, target(i)),
                    )
                }));
            }
            Self::SpringsAtRest => {
                world.spawn_batch((0..count).map(|i| {
                    (
                        Transform::from_translation(target(i)),
                        TranslationSpring::new(sprung_spring(HALF_LIFE), target(i)),
                    )
                }));
            }
            Self::UiScaleSprings => {
                world.spawn_batch((0..count).map(|i| {
                    (
                        UiTransform::default(),
                        UiTransformScaleSpring::new(sprung_spring(HALF_LIFE), target(i).truncate()),
                    )
                }));
            }
            Self::UiTranslationSprings => {
                world.spawn_batch((0..count).map(|i| {
                    let target = target(i);
                    (
                        UiTransform::default(),
                        UiTransformTranslationSpring::new(
                            sprung_spring(HALF_LIFE),
                            Val2::px(target.x, target.y),
                        ),
                    )
                }));
            }
            Self::SpringDamper { springs } => {
                world.spawn_batch((0..count).map(move |i| {
                    (
                        Transform::from_translation(start(i)),
                        spring_damper::bevy_layer::TranslationSpring {
                            goal: target(i),
                            velocity: Vec3::ZERO,
                            halflife: spring_damper_halflife(half_life(i, springs)),
                        },
                    )
                }));
            }
            Self::Euler | Self::BareExact => {
                world.spawn_batch((0..count).map(|i| {
                    (
                        Transform::from_translation(start(i)),
                        HandVelocity(Vec3::ZERO),
                        HandTarget(target(i)),
                    )
                }));
            }
            Self::EulerUiScale => {
                world.spawn_batch((0..count).map(|i| {
                    (
                        UiTransform::default(),
                        HandVelocity2(Vec2::ZERO),
                        HandTarget2(target(i).truncate()),
                    )
                }));
            }
            Self::LanesModel => lanes::spawn(world, count),
            Self::SmoothNudge => {
                world.spawn_batch(
                    (0..count)
                        .map(|i| (Transform::from_translation(start(i)), HandTarget(target(i)))),
                );
            }
            Self::Touch | Self::Idle => {
                world.spawn_batch((0..count).map(|i| Transform::from_translation(start(i))));
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
        }
    }

    /// Sets the time step of the next frame: every clock the methods read (`Time`, the
    /// `Time<Virtual>` spring_damper reads, and `Time<Real>`) advances by `dt`.
    pub(crate) fn set_dt(world: &mut World, dt: f32) {
        let delta = Duration::from_secs_f32(dt);
        world.resource_mut::<Time>().advance_by(delta);
        world.resource_mut::<Time<Virtual>>().advance_by(delta);
        world.resource_mut::<Time<Real>>().advance_by(delta);
    }

    /// Checks that the last frame moved every entity (or, at rest, wrote none and every spring
    /// sleeps): the measured frames measured what they claim.
    pub(crate) fn check(
        self,
        world: &mut World,
        count: usize,
        since: bevy::ecs::change_detection::Tick,
    ) {
        let now = world.read_change_tick();
        let written = match self {
            Self::UiScaleSprings | Self::UiTranslationSprings | Self::EulerUiScale => world
                .query::<Ref<UiTransform>>()
                .iter(world)
                .filter(|t| t.last_changed().is_newer_than(since, now))
                .count(),
            _ => world
                .query::<Ref<Transform>>()
                .iter(world)
                .filter(|t| t.last_changed().is_newer_than(since, now))
                .count(),
        };
        let asleep = world
            .query_filtered::<(), With<SpringAsleep<Translation>>>()
            .iter(world)
            .count()
            + world
                .query_filtered::<(), With<SpringAsleep<bevy_sprung::ui::UiTransformScale>>>()
                .iter(world)
                .count()
            + world
                .query_filtered::<(), With<SpringAsleep<bevy_sprung::ui::UiTransformTranslation>>>()
                .iter(world)
                .count();
        if self == Self::SpringsAtRest {
            assert_eq!(asleep, count, "{self:?}: every spring should sleep");
            assert_eq!(written, 0, "{self:?}: nothing should be written");
        } else if self == Self::Idle {
            assert_eq!(written, 0, "{self:?}: nothing should be written");
        } else {
            assert_eq!(asleep, 0, "{self:?}: no spring should sleep");
            assert_eq!(written, count, "{self:?}: every entity should be written");
        }
    }
}

/// The velocity of the hand-written springs.
#[derive(Component, Clone, Copy)]
pub(crate) struct HandVelocity(Vec3);

/// The target of the hand-written methods.
#[derive(Component, Clone, Copy)]
pub(crate) struct HandTarget(Vec3);

/// The velocity of the hand-written UI spring.
#[derive(Component, Clone, Copy)]
pub(crate) struct HandVelocity2(Vec2);

/// The target of the hand-written UI spring.
#[derive(Component, Clone, Copy)]
pub(crate) struct HandTarget2(Vec2);

/// `(k, c)` of the shared spring, for the Euler systems.
fn euler_parameters() -> (f32, f32) {
    let spring = sprung_spring(HALF_LIFE);
    (spring.stiffness(), spring.damping())
}

/// Moves every translation a little: no state but the `Transform`.
fn touch(mut query: Query<&mut Transform>) {
    for mut transform in &mut query {
        transform.translation.x += 1e-3;
    }
}

/// What a game writes by hand: a semi-implicit Euler spring, unit mass, shared parameters.
fn euler(time: Res<Time>, mut query: Query<(&mut Transform, &mut HandVelocity, &HandTarget)>) {
    let dt = time.delta_secs();
    let (k, c) = euler_parameters();
    for (mut transform, mut velocity, target) in &mut query {
        let v = velocity.0 + (k * (target.0 - transform.translation) - c * velocity.0) * dt;
        velocity.0 = v;
        transform.translation += v * dt;
    }
}

/// The same on a UI node's scale.
fn euler_ui_scale(
    time: Res<Time>,
    mut query: Query<(&mut UiTransform, &mut HandVelocity2, &HandTarget2)>,
) {
    let dt = time.delta_secs();
    let (k, c) = euler_parameters();
    for (mut transform, mut velocity, target) in &mut query {
        let v = velocity.0 + (k * (target.0 - transform.scale) - c * velocity.0) * dt;
        velocity.0 = v;
        transform.scale += v * dt;
    }
}

/// The least an exact spring can do per entity: one transition for all, computed once per
/// frame, applied to position and velocity.
fn bare_exact(time: Res<Time>, mut query: Query<(&mut Transform, &mut HandVelocity, &HandTarget)>) {
    let transition = sprung_spring(HALF_LIFE).transition(time.delta_secs());
    for (mut transform, mut velocity, target) in &mut query {
        let next = transition.step(
            SpringState::new(transform.translation, velocity.0),
            target.0,
        );
        transform.translation = next.position;
        velocity.0 = next.velocity;
    }
}

/// Exponential smoothing, frame-rate independent, no velocity.
fn nudge(time: Res<Time>, mut query: Query<(&mut Transform, &HandTarget)>) {
    let dt = time.delta_secs();
    for (mut transform, target) in &mut query {
        transform
            .translation
            .smooth_nudge(&target.0, DECAY_RATE, dt);
    }
}
