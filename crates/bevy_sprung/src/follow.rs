//! Followers: a camera (or anything) that springs after another entity and looks at it.

use core::any::TypeId;

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::log::warn_once;
use bevy::prelude::*;

use crate::clock::{FixedStep, SpringTime};
use crate::spring::{PropertySystems, SpringTargetMut, SpringUpdate, add_systems_on_first_use};
use crate::tracking::{TargetWarped, WorldPositions, take_warp};
use crate::transform::{Rotation, RotationSpring, Translation, TranslationSpring};

/// How the followed entity moves, which decides how its motion is sampled.
#[derive(Reflect, Debug, Default, Clone, Copy, PartialEq, Eq)]
pub enum TargetMotion {
    /// It moves in `Update` (or anywhere once per frame): its velocity is its displacement over
    /// the frame.
    #[default]
    PerFrame,
    /// It moves in `FixedUpdate` (fixed-timestep gameplay or physics): it is sampled after each
    /// fixed step, and between steps followed along its last fixed-step velocity by the
    /// overstep, so uneven frames over a 64 Hz simulation give a smooth, exact steady lag
    /// instead of a target that stands still one frame and jumps two steps the next.
    FixedTimestep,
}

/// The last two fixed-step positions of a followed entity.
#[derive(Reflect, Debug, Default, Clone, Copy, PartialEq)]
pub(crate) struct FixedSamples {
    previous: Option<Vec3>,
    latest: Option<Vec3>,
}

impl FixedSamples {
    /// Records where the target is after a fixed step; a target gone forgets its samples, so
    /// that it is not followed along a stale velocity.
    pub(crate) fn record(&mut self, position: Option<Vec3>) {
        match position {
            Some(position) => {
                let latest = self.latest.replace(position);
                self.previous = latest;
            }
            None => *self = Self::default(),
        }
    }

    /// The target was carried by `shift` without travelling (a warp) and is at `now`: the
    /// samples taken before the jump (nearer to it from where it came) move with it, so the
    /// next velocity taken from them is its motion, not the jump.
    pub(crate) fn carry_before(&mut self, shift: Vec3, now: Vec3) {
        for sample in [&mut self.previous, &mut self.latest].into_iter().flatten() {
            if (*sample + shift).distance_squared(now) < sample.distance_squared(now) {
                *sample += shift;
            }
        }
    }

    /// The target was carried by `shift` since its last sample: every sample moves with it.
    #[cfg(feature = "camera")]
    pub(crate) fn carry(&mut self, shift: Vec3) {
        for sample in [&mut self.previous, &mut self.latest].into_iter().flatten() {
            *sample += shift;
        }
    }
}

/// Makes this entity follow `target` with its [`TranslationSpring`], at `offset` from it, and
/// optionally look at it with its [`RotationSpring`]: camera smoothing.
///
/// Every frame, after gameplay moved the target (in `Update` or `FixedUpdate`), the follower's
/// spring is retargeted to the target's position plus `offset`, and given the target's velocity
/// so the step follows a moving target exactly (the steady lag `c·v/k` is reproduced at any
/// frame rate, with no jitter from uneven frames). The follower reads the target's `Transform`
/// in the same frame (no one-frame lag), at any depth of its hierarchy: a target under a moving
/// parent is placed by its ancestors' `Transform`s as they are this frame. The follower itself
/// should be a root entity (its springs move its local `Transform`).
///
/// When the target goes away (despawned, with its parent or alone, or its `Transform` removed)
/// the follower comes to rest on its last goal, and sleeps; it follows again if the target comes
/// back. Removing the `SpringFollow` does the same: the spring keeps its target (or the one you
/// set) and no longer follows a moving one.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// fn spawn(mut commands: Commands) {
///     let player = commands.spawn(Transform::default()).id();
///     // A camera (add `Camera3d` with Bevy's 3D features) that follows the player.
///     commands.spawn((
///         Transform::from_xyz(0.0, 4.0, 8.0),
///         TranslationSpring::new(Spring::smooth(), Vec3::new(0.0, 4.0, 8.0)),
///         RotationSpring::new(Spring::smooth(), Quat::IDENTITY),
///         SpringFollow::new(player, Vec3::new(0.0, 4.0, 8.0))
///             .looking_at(Vec3::Y)
///             .moving_in_fixed_update(),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone)]
#[component(on_add = crate::spring::first_use::<SpringFollow>, on_remove = stop_following)]
#[reflect(Component)]
pub struct SpringFollow {
    /// The entity to follow.
    pub target: Entity,
    /// Where to be, relative to the target, in world space.
    pub offset: Vec3,
    /// If set, turn the [`RotationSpring`] to look at the target plus this offset.
    pub look_at: Option<Vec3>,
    /// The up direction when looking at the target.
    pub up: Dir3,
    /// How the target moves.
    pub motion: TargetMotion,
    /// A frame in which the target moves further than this (world units) is a teleport: the
    /// follower moves with it, keeping its offset and velocity. Infinite (never) by default;
    /// [`TargetWarped`] says so explicitly.
    pub teleport_distance: f32,
    /// Explicit warps of the target not yet applied.
    warp: Vec3,
    /// Where the target was last frame (`PerFrame`).
    last_frame_position: Option<Vec3>,
    /// The target's last fixed-step positions (`FixedTimestep`).
    fixed: FixedSamples,
    /// Where the target is (continuously) this frame: what the look-at aims at.
    current: Option<Vec3>,
}

impl SpringFollow {
    /// Follow `target` at `offset` from it, without turning, sampling it once per frame.
    #[must_use]
    pub fn new(target: Entity, offset: Vec3) -> Self {
        Self {
            target,
            offset,
            look_at: None,
            up: Dir3::Y,
            motion: TargetMotion::PerFrame,
            teleport_distance: f32::INFINITY,
            warp: Vec3::ZERO,
            last_frame_position: None,
            fixed: FixedSamples::default(),
            current: None,
        }
    }

    /// Also look at the target plus `point_offset` (needs a [`RotationSpring`]).
    #[must_use]
    pub fn looking_at(mut self, point_offset: Vec3) -> Self {
        self.look_at = Some(point_offset);
        self
    }

    /// The target moves in `FixedUpdate`: see [`TargetMotion::FixedTimestep`].
    #[must_use]
    pub fn moving_in_fixed_update(mut self) -> Self {
        self.motion = TargetMotion::FixedTimestep;
        self
    }

    /// The same, treating a move of the target further than `distance` in one frame as a
    /// teleport (see [`teleport_distance`](Self::teleport_distance)).
    #[must_use]
    pub fn with_teleport_distance(mut self, distance: f32) -> Self {
        self.teleport_distance = distance;
        self
    }
}

/// A [`TargetWarped`]: every follower of the warped entity takes note, to move with it when
/// it next follows.
fn note_warps(warped: On<TargetWarped>, mut followers: Query<&mut SpringFollow>) {
    if !warped.delta.is_finite() {
        return;
    }
    for mut follow in &mut followers {
        if follow.target == warped.entity {
            follow.warp += warped.delta;
        }
    }
}

/// After each fixed step: record where fixed-timestep targets are (a target gone forgets its
/// samples, so that it is not followed along a stale velocity).
fn sample_fixed_targets(mut followers: Query<&mut SpringFollow>, positions: WorldPositions) {
    for mut follow in &mut followers {
        if follow.motion != TargetMotion::FixedTimestep {
            continue;
        }
        let position = positions.of(follow.target);
        follow.fixed.record(position);
    }
}

/// Before the translation springs step: aim every follower's spring at its target, with the
/// target's velocity. A follower whose target is gone (despawned, or without a `Transform`)
/// comes to rest on its last goal: its target stops moving.
fn follow_targets(
    time: SpringTime,
    mut followers: Query<(Entity, &mut SpringFollow, &mut TranslationSpring)>,
    mut world: ParamSet<(WorldPositions, Query<&mut Transform>)>,
    mut carried: Local<Vec<(Entity, Vec3)>>,
) {
    let steps = time.steps();
    for (follower, mut follow, mut spring) in &mut followers {
        if follow.target == follower {
            warn_once!(
                "bevy_sprung: {follower} follows itself (SpringFollow::target is its own \
                 entity); it rests instead of running away from itself"
            );
        }
        let found = Some(follow.target)
            .filter(|&target| target != follower)
            .and_then(|target| world.p0().of(target));
        if let Some(position) = found {
            let follow = &mut *follow;
            let expected = spring.target_velocity() * steps.dt(spring.clock());
            let (last, teleport) = (follow.last_frame_position, follow.teleport_distance);
            let shift = take_warp(&mut follow.warp, teleport, (last, position), expected);
            if shift != Vec3::ZERO && shift.is_finite() {
                // The target was carried, not moved: so is the follower, with its velocity.
                follow.last_frame_position = last.map(|last| last + shift);
                follow.fixed.carry_before(shift, position);
                carried.push((follower, shift));
            }
        }
        let sample = match found {
            None => None,
            Some(position) => match follow.motion {
                TargetMotion::PerFrame => {
                    let dt = steps.dt(spring.clock());
                    let velocity = match follow.last_frame_position {
                        Some(last) if dt > 0.0 => (position - last) / dt,
                        _ => Vec3::ZERO,
                    };
                    Some((position, velocity))
                }
                TargetMotion::FixedTimestep => Some(
                    fixed_sample(follow.fixed, time.fixed_step()).unwrap_or((position, Vec3::ZERO)),
                ),
            },
        };
        let Some((position, velocity)) = sample else {
            follow.last_frame_position = None;
            stop_target(&mut spring);
            continue;
        };
        follow.last_frame_position = Some(position);
        follow.current = Some(position);
        let goal = position + follow.offset;
        // A non-finite target position is refused by the spring (with a warning).
        spring.set_target_if_neq(goal);
        spring.set_target_velocity_if_neq(velocity);
    }
    // Followers carried with their targets move before their springs step (which go on from
    // there, with their velocities).
    let mut transforms = world.p1();
    for (follower, shift) in carried.drain(..) {
        if let Ok(mut transform) = transforms.get_mut(follower) {
            transform.translation += shift;
        }
    }
}

/// Where a target that moves in `FixedUpdate` is this frame, and its velocity, from its last
/// two fixed-step samples; from one, where it stands.
pub(crate) fn fixed_sample(samples: FixedSamples, fixed: FixedStep) -> Option<(Vec3, Vec3)> {
    match samples {
        FixedSamples {
            previous: Some(previous),
            latest: Some(latest),
        } => {
            // The target moved from `previous` to `latest` over one fixed step, and `overstep`
            // seconds of that motion have passed since.
            let velocity = (latest - previous) / fixed.timestep;
            Some((latest + velocity * fixed.overstep, velocity))
        }
        FixedSamples {
            latest: Some(latest),
            ..
        } => Some((latest, Vec3::ZERO)),
        _ => None,
    }
}

/// The spring's target stops moving (its target velocity is zeroed): it comes to rest on its
/// target and sleeps. Only a moving target is touched, so a resting spring stays asleep.
fn stop_target(spring: &mut Mut<TranslationSpring>) {
    spring.set_target_velocity_if_neq(Vec3::ZERO);
}

/// The hook of a [`SpringFollow`] removed: the translation spring it moved no longer follows a
/// moving target, and comes to rest on its target (or the one set next).
fn stop_following(mut world: DeferredWorld, context: HookContext) {
    if let Some(mut spring) = world.get_mut::<TranslationSpring>(context.entity) {
        stop_target(&mut spring);
    }
}

/// After the translation springs stepped, before the rotation springs do: turn followers that
/// look at their target toward it from where they now are.
fn aim_followers(mut followers: Query<(&SpringFollow, &Transform, &mut RotationSpring)>) {
    for (follow, transform, mut spring) in &mut followers {
        let (Some(look_at), Some(target)) = (follow.look_at, follow.current) else {
            continue;
        };
        let point = target + look_at;
        if point.distance_squared(transform.translation) <= f32::EPSILON {
            continue;
        }
        spring.set_target_if_neq(transform.looking_at(point, follow.up).rotation);
    }
}

/// [`SpringFollow`]: camera smoothing (part of [`SpringPlugins`](crate::SpringPlugins)).
/// Followers are sampled after each fixed step, retargeted before the translation springs step,
/// and turned toward their target after those and before the rotation springs.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringFollowPlugin;

impl Plugin for SpringFollowPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<SpringFollow>()
            .register_type::<TargetMotion>()
            .add_observer(note_warps);
        add_systems_on_first_use(
            app,
            &[TypeId::of::<SpringFollow>()],
            FixedPostUpdate,
            |schedule| {
                schedule
                    .add_systems(sample_fixed_targets.run_if(any_with_component::<SpringFollow>));
            },
        );
        // A follower moves its translation spring, and aims its rotation spring; with the first
        // follower.
        add_systems_on_first_use(
            app,
            &[TypeId::of::<SpringFollow>()],
            SpringUpdate,
            |schedule| {
                schedule.add_systems(
                    (
                        follow_targets.before(PropertySystems::<Translation>::default()),
                        aim_followers
                            .after(PropertySystems::<Translation>::default())
                            .before(PropertySystems::<Rotation>::default()),
                    )
                        .run_if(any_with_component::<SpringFollow>),
                );
            },
        );
    }
}
