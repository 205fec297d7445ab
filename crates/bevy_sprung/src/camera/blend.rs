//! Blends between virtual cameras: the rendering camera shows the live shot with the highest
//! priority, and a change of shot is a spring from where the camera is, velocity kept.

use core::any::TypeId;

use bevy::camera::Projection;
use bevy::ecs::entity::EntityHashMap;
use bevy::prelude::*;
use sprung::Spring;

use crate::clock::SpringTime;
use crate::property_plugin::SpringPropertyPlugin;
use crate::space::{Linear, ShortestArc};
use crate::spring::{PropertySpring, PropertySystems, SpringPhase, add_property_systems};

/// Makes a [`CameraRig`](super::CameraRig) (or any entity with a `Transform`) one shot among
/// several: it places itself as usual but renders nothing (give it no `Camera`), and the
/// rendering camera's [`CameraBlend`] shows the live shot with the highest
/// [`priority`](Self::priority). Give it a `Projection` to set the lens the camera blends to
/// (an orthographic scale or a field of view).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::camera::{CameraBlend, CameraTargets, VirtualCamera};
///
/// fn spawn(mut commands: Commands) {
///     let player = commands.spawn(Transform::default()).id();
///     // Two shots of the player: a wide one, and a close one that takes over when raised.
///     commands.spawn((
///         CameraRig::new(Spring::smooth()).with_offset(Vec3::new(0.0, 6.0, 14.0)).looking_at_goal(),
///         CameraTargets::single(player),
///         VirtualCamera::new(0),
///     ));
///     commands.spawn((
///         CameraRig::new(Spring::snappy()).with_offset(Vec3::new(1.0, 2.0, 4.0)).looking_at_goal(),
///         CameraTargets::single(player),
///         VirtualCamera::new(-1),
///     ));
///     commands.spawn((Camera3d::default(), CameraBlend::new(Spring::smooth())));
/// }
///
/// fn close_up(mut shots: Query<&mut VirtualCamera>) {
///     for mut shot in &mut shots {
///         shot.priority = -shot.priority;
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Eq)]
#[require(Transform)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct VirtualCamera {
    /// Which shot shows: the live one with the highest priority (on a tie, the one showing
    /// stays; else the oldest entity).
    pub priority: i32,
}

impl VirtualCamera {
    /// A shot with `priority`.
    #[must_use]
    pub fn new(priority: i32) -> Self {
        Self { priority }
    }
}

/// On the rendering camera: show the [`VirtualCamera`] with the highest priority. The camera
/// takes the shot's `Transform` (and lens: orthographic scale or field of view, when both have
/// a projection of the same kind) every frame; when another shot takes over, it springs from
/// where it was to the new shot with [`spring`](Self::spring) — position, rotation and lens —
/// so a cut becomes a smooth move, and once the blend has settled it is exactly on the shot
/// again. The camera's velocity, angular velocity and lens rate are kept across the change.
/// The first shot is a cut. [`BlendTrack::shot`] says which
/// shot shows.
///
/// The blend is an offset from the new shot that springs to zero, so a moving shot is followed
/// exactly during the blend too (no lag behind it). Put [`Shake`](crate::juice::Shake) on the
/// rendering camera to shake every shot.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[require(
    Transform,
    BlendOffset,
    BlendTrack,
    BlendTranslationSpring = PropertySpring::new(Spring::smooth(), Vec3::ZERO),
    BlendRotationSpring = PropertySpring::new(Spring::smooth(), Quat::IDENTITY),
    BlendLensSpring = PropertySpring::new(Spring::smooth(), 0.0)
)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct CameraBlend {
    /// The spring of a change of shot.
    pub spring: Spring,
}

impl CameraBlend {
    /// Blend between shots with `spring`.
    #[must_use]
    pub fn new(spring: Spring) -> Self {
        Self { spring }
    }
}

/// How far the rendering camera is from the shot it blends to: the offsets that spring to
/// zero.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, Clone, PartialEq, Default)]
pub struct BlendOffset {
    translation: Vec3,
    rotation: Quat,
    lens: f32,
}

impl Default for BlendOffset {
    fn default() -> Self {
        Self {
            translation: Vec3::ZERO,
            rotation: Quat::IDENTITY,
            lens: 0.0,
        }
    }
}

spring_property!(
    /// The translation of a [`CameraBlend`]'s camera from its shot.
    pub BlendTranslation: BlendOffset::translation as Linear<Vec3>
);
spring_property!(
    /// The rotation of a [`CameraBlend`]'s camera from its shot.
    pub BlendRotation: BlendOffset::rotation as ShortestArc
);
spring_property!(
    /// The lens (orthographic scale or field of view) of a [`CameraBlend`]'s camera from its
    /// shot's.
    pub BlendLens: BlendOffset::lens as Linear<f32>
);

/// The spring of a blend's translation.
pub type BlendTranslationSpring = PropertySpring<BlendTranslation>;
/// The spring of a blend's rotation.
pub type BlendRotationSpring = PropertySpring<BlendRotation>;
/// The spring of a blend's lens.
pub type BlendLensSpring = PropertySpring<BlendLens>;

/// Which shot a [`CameraBlend`] shows, and how its camera moved last frame.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Debug, Clone, PartialEq, Default)]
pub struct BlendTrack {
    shot: Option<Entity>,
    /// Where the camera was last frame, and how fast it moved.
    #[reflect(ignore)]
    motion: Option<(Pose, PoseRate)>,
}

impl BlendTrack {
    /// The shot the camera shows (or blends to), if any.
    #[must_use]
    pub fn shot(&self) -> Option<Entity> {
        self.shot
    }
}

/// Where each shot was last frame, and how fast it moved, for a change of shot.
#[derive(Resource, Default)]
pub(super) struct ShotMotion(EntityHashMap<(Pose, PoseRate)>);

/// What a blend moves: a camera's translation, rotation and lens.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Pose {
    translation: Vec3,
    rotation: Quat,
    lens: Option<f32>,
}

/// How fast a [`Pose`] changes: velocity, world angular velocity and the lens's rate.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
struct PoseRate {
    translation: Vec3,
    rotation: Vec3,
    lens: f32,
}

impl Pose {
    fn of(transform: &Transform, projection: Option<&Projection>) -> Self {
        Self {
            translation: transform.translation,
            rotation: transform.rotation,
            lens: projection.and_then(lens),
        }
    }

    /// The rate from `last` to this pose over `dt` (the last rate if `dt` is 0, nothing where
    /// it would not be finite).
    fn rate_since(self, last: Option<(Self, PoseRate)>, dt: f32) -> PoseRate {
        let Some((last, last_rate)) = last else {
            return PoseRate::default();
        };
        if dt <= 0.0 {
            return last_rate;
        }
        // The turn since last frame, the short way, as a world angular velocity.
        let turn = self.rotation * last.rotation.inverse();
        let turn = if turn.w < 0.0 { -turn } else { turn };
        let rate = PoseRate {
            translation: (self.translation - last.translation) / dt,
            rotation: turn.to_scaled_axis() / dt,
            lens: self
                .lens
                .zip(last.lens)
                .map_or(0.0, |(now, last)| (now - last) / dt),
        };
        let finite =
            rate.translation.is_finite() && rate.rotation.is_finite() && rate.lens.is_finite();
        if finite { rate } else { PoseRate::default() }
    }
}

/// The lens of a projection: an orthographic scale or a field of view.
fn lens(projection: &Projection) -> Option<f32> {
    match projection {
        Projection::Orthographic(orthographic) => Some(orthographic.scale),
        Projection::Perspective(perspective) => Some(perspective.fov),
        Projection::Custom(_) => None,
    }
}

/// Sets the lens of `projection` (of the same kind as `shot`'s).
fn set_lens(projection: &mut Projection, value: f32) {
    match projection {
        Projection::Orthographic(orthographic) => orthographic.scale = value,
        Projection::Perspective(perspective) => perspective.fov = value,
        Projection::Custom(_) => {}
    }
}

/// Whether two projections are of the same kind (their lenses blend).
fn same_kind(a: &Projection, b: &Projection) -> bool {
    matches!(
        (a, b),
        (Projection::Orthographic(_), Projection::Orthographic(_))
            | (Projection::Perspective(_), Projection::Perspective(_))
    )
}

/// Each shot's motion this frame, from where it was last frame.
pub(super) fn track_shots(
    time: SpringTime,
    shots: Query<(Entity, &Transform, Option<&Projection>), With<VirtualCamera>>,
    mut motion: ResMut<ShotMotion>,
) {
    let dt = time.steps().dt(None);
    motion.0.retain(|shot, _| shots.contains(*shot));
    for (shot, transform, projection) in &shots {
        let now = Pose::of(transform, projection);
        let rate = now.rate_since(motion.0.get(&shot).copied(), dt);
        motion.0.insert(shot, (now, rate));
    }
}

/// The best shot: the highest priority; on a tie the one showing, else the oldest entity.
fn best_shot(
    shots: &Query<(Entity, &VirtualCamera, &Transform, Option<&Projection>), Without<CameraBlend>>,
    showing: Option<Entity>,
) -> Option<Entity> {
    shots
        .iter()
        .max_by(|(a, shot_a, ..), (b, shot_b, ..)| {
            shot_a
                .priority
                .cmp(&shot_b.priority)
                .then_with(|| (Some(*a) == showing).cmp(&(Some(*b) == showing)))
                .then_with(|| b.cmp(a))
        })
        .map(|(entity, ..)| entity)
}

/// The parts of a blending camera changed at a change of shot.
type Blending<'a> = (
    &'a mut BlendTrack,
    &'a Transform,
    Option<&'a Projection>,
    &'a mut BlendOffset,
    &'a mut BlendTranslationSpring,
    &'a mut BlendRotationSpring,
    &'a mut BlendLensSpring,
    &'a CameraBlend,
);

/// A change of shot: the offsets start where the camera is relative to the new shot, with the
/// camera's velocity relative to the shot's, and spring to zero.
pub(super) fn switch_shots(
    mut cameras: Query<Blending>,
    shots: Query<(Entity, &VirtualCamera, &Transform, Option<&Projection>), Without<CameraBlend>>,
    motion: Res<ShotMotion>,
) {
    for (
        mut track,
        transform,
        projection,
        mut offset,
        mut translation,
        mut rotation,
        mut lens_spring,
        blend,
    ) in &mut cameras
    {
        if translation.spring() != &blend.spring {
            translation.set_spring(blend.spring);
            rotation.set_spring(blend.spring);
            lens_spring.set_spring(blend.spring);
        }
        let best = best_shot(&shots, track.shot);
        if best == track.shot {
            continue;
        }
        let first = track.shot.is_none();
        track.shot = best;
        let Some((_, _, shot, shot_projection)) = best.and_then(|best| shots.get(best).ok()) else {
            continue;
        };
        if first {
            continue;
        }
        let shot_rate = best
            .and_then(|best| motion.0.get(&best))
            .map_or(PoseRate::default(), |&(_, rate)| rate);
        let camera_rate = track.motion.map_or(PoseRate::default(), |(_, rate)| rate);
        // The offsets from the new shot, and their rates: the camera's motion relative to the
        // shot's. A rotation offset `shot⁻¹·camera` turns at the difference of the two world
        // angular velocities, seen in the shot's frame.
        offset.translation = transform.translation - shot.translation;
        translation.set_velocity(camera_rate.translation - shot_rate.translation);
        offset.rotation = (shot.rotation.inverse() * transform.rotation).normalize();
        rotation
            .set_velocity(shot.rotation.inverse() * (camera_rate.rotation - shot_rate.rotation));
        let lenses = match (projection, shot_projection) {
            (Some(camera), Some(shot)) if same_kind(camera, shot) => lens(camera).zip(lens(shot)),
            _ => None,
        };
        offset.lens = lenses.map_or(0.0, |(camera, shot)| camera - shot);
        lens_spring.set_velocity(if lenses.is_some() {
            camera_rate.lens - shot_rate.lens
        } else {
            0.0
        });
    }
}

/// After the blend stepped: the camera on its shot, offset by the blend, written only where it
/// changes.
pub(super) fn compose_blends(
    time: SpringTime,
    mut cameras: Query<
        (
            &mut BlendTrack,
            &BlendOffset,
            &mut Transform,
            Option<&mut Projection>,
        ),
        With<CameraBlend>,
    >,
    shots: Query<(&Transform, Option<&Projection>), (With<VirtualCamera>, Without<CameraBlend>)>,
) {
    let dt = time.steps().dt(None);
    for (mut track, offset, mut transform, projection) in &mut cameras {
        let Some((shot, shot_projection)) = track.shot.and_then(|shot| shots.get(shot).ok()) else {
            continue;
        };
        let translation = shot.translation + offset.translation;
        let rotation = (shot.rotation * offset.rotation).normalize();
        if translation.is_finite() && transform.translation != translation {
            transform.translation = translation;
        }
        if rotation.is_finite() && transform.rotation != rotation {
            transform.rotation = rotation;
        }
        let mut projection = projection;
        if let (Some(projection), Some(shot_projection)) = (projection.as_mut(), shot_projection) {
            if !same_kind(projection, shot_projection) {
                **projection = shot_projection.clone();
            } else if let Some(value) = lens(shot_projection).map(|shot| shot + offset.lens)
                && value.is_finite()
                && lens(projection) != Some(value)
            {
                set_lens(projection, value);
            }
        }
        let now = Pose::of(&transform, projection.as_deref());
        let rate = now.rate_since(track.motion, dt);
        track.motion = Some((now, rate));
    }
}

/// [`VirtualCamera`] and [`CameraBlend`] (part of [`SpringCameraPlugin`](super::SpringCameraPlugin)):
/// the blend's springs, after the rigs' (the shots are placed first), and their systems with the
/// first blend.
#[derive(Debug, Default, Clone, Copy)]
pub(super) struct SpringCameraBlendPlugin;

impl Plugin for SpringCameraBlendPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins((
            SpringPropertyPlugin::<BlendTranslation>::default(),
            SpringPropertyPlugin::<BlendRotation>::default(),
            SpringPropertyPlugin::<BlendLens>::default(),
        ))
        .init_resource::<ShotMotion>()
        .register_type::<VirtualCamera>()
        .register_type::<CameraBlend>()
        .register_type::<BlendTrack>()
        .register_type::<BlendOffset>();
        let blends = [TypeId::of::<PropertySpring<BlendTranslation>>()];
        add_property_systems(app, &blends, |schedule| {
            schedule.add_systems(
                (
                    (track_shots, switch_shots).chain().in_set(
                        PropertySystems::<BlendTranslation>::phase(SpringPhase::Input),
                    ),
                    compose_blends
                        .in_set(PropertySystems::<BlendLens>::phase(SpringPhase::Observe)),
                )
                    .run_if(any_with_component::<CameraBlend>),
            );
        });
    }
}
