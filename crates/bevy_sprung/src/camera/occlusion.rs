//! Occlusion: the camera pulls in front of scene geometry between it and the point it frames,
//! and springs back out when the way is clear (feature `camera_occlusion`).

use bevy::picking::mesh_picking::ray_cast::{MeshRayCast, MeshRayCastSettings, RayCastVisibility};
use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use sprung::Spring;

use core::any::TypeId;

use super::components::{CameraTargets, RigClearance, RigClearanceSpring, RigMotion};
use super::systems::Posed;
use crate::property_plugin::SpringPropertyPlugin;
use crate::spring::{PropertySpring, SpringTargetMut, add_systems_on_first_use};

/// Keeps a [`CameraRig`](super::CameraRig)'s view of the point it frames clear: when a mesh is
/// between them (Bevy's `MeshRayCast`, along the rig's arm from the point to the camera), the
/// camera is pulled in front of it in the same frame, [`margin`](Self::margin) short of the
/// hit; when the way is clear again it springs back out with [`spring`](Self::spring). The
/// rig's targets and their descendants never occlude. Meshes are tested as Bevy's picking
/// sees them (`Aabb`s computed by Bevy's visibility systems; hidden meshes ignored).
///
/// The ray is cast in `PostUpdate` after transform propagation and Bevy's bounds, so a blocker
/// moved or spawned this frame is seen this frame; a pulled-in camera's `Transform` and
/// `GlobalTransform` are both written then (its children follow the next frame, and a
/// [`CameraBlend`](super::CameraBlend) showing the rig as a shot sees the pull the next frame).
///
/// Needs feature `camera_occlusion` (`bevy/mesh_picking`); a game without it pays nothing.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::camera::{CameraOcclusion, CameraTargets, OrbitRig};
///
/// fn spawn(mut commands: Commands) {
///     let player = commands.spawn(Transform::default()).id();
///     commands.spawn((
///         CameraRig::new(Spring::smooth()),
///         CameraTargets::single(player),
///         OrbitRig::new(8.0),
///         CameraOcclusion::new(0.3),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, AssetPlugin::default(), SpringPlugins::default())).init_asset::<Mesh>().add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[component(on_add = crate::spring::first_use::<CameraOcclusion>)]
#[require(RigClearanceSpring = PropertySpring::new(Spring::smooth(), 1.0))]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct CameraOcclusion {
    /// How far in front of an occluder the camera stops, in world units.
    pub margin: f32,
    /// The spring the camera moves back out with.
    pub spring: Spring,
}

impl CameraOcclusion {
    /// Stop `margin` in front of occluders; spring back out smoothly.
    #[must_use]
    pub fn new(margin: f32) -> Self {
        Self {
            margin,
            spring: Spring::smooth(),
        }
    }

    /// The same occlusion springing back out with `spring`.
    #[must_use]
    pub fn with_spring(mut self, spring: Spring) -> Self {
        self.spring = spring;
        self
    }
}

/// Whether the app has meshes to cast rays against (`Assets<Mesh>`, which Bevy's mesh plugin
/// adds); warns once if a rig wants occlusion without them.
pub(super) fn meshes_exist(meshes: Option<Res<Assets<Mesh>>>, mut warned: Local<bool>) -> bool {
    if meshes.is_none() && !*warned {
        *warned = true;
        warn!(
            "bevy_sprung: a CameraOcclusion needs meshes to cast rays against, but the app has \
             no Assets<Mesh>: add Bevy's mesh plugin (DefaultPlugins has it)"
        );
    }
    meshes.is_some()
}

/// What an occluded rig is read and written through.
type Occluded<'a> = (
    Entity,
    Posed,
    &'a CameraOcclusion,
    &'a mut RigMotion,
    &'a mut RigClearanceSpring,
    Option<&'a CameraTargets>,
    &'a mut Transform,
);

/// After transforms and bounds are current: cast each occluded rig's arm, pull the camera in
/// to the nearest hit, and aim its clearance spring at what is clear (all of the arm once
/// nothing is hit).
pub(super) fn occlude(
    mut rigs: Query<Occluded>,
    window: Query<&Window, With<PrimaryWindow>>,
    parents: Query<&ChildOf>,
    mut ray_cast: MeshRayCast,
) {
    let window = window.single().ok();
    for (camera, posed, occlusion, mut motion, mut spring, targets, mut transform) in &mut rigs {
        if spring.spring() != &occlusion.spring {
            spring.set_spring(occlusion.spring);
        }
        let pose = posed.pose(&motion, window);
        let length = pose.arm.length();
        let (Ok(direction), true) = (Dir3::new(pose.arm), length.is_finite()) else {
            continue;
        };
        // Targets and everything under them (the player's own mesh) do not occlude.
        let is_target = |entity: Entity| {
            targets.is_some_and(|targets| {
                core::iter::once(entity)
                    .chain(parents.iter_ancestors(entity))
                    .any(|ancestor| {
                        targets
                            .targets
                            .iter()
                            .any(|target| target.entity == ancestor)
                    })
            })
        };
        let filter = |entity: Entity| entity != camera && !is_target(entity);
        let settings = MeshRayCastSettings::default()
            .with_visibility(RayCastVisibility::Visible)
            .with_filter(&filter);
        let hit = ray_cast
            .cast_ray(Ray3d::new(pose.focus, direction), &settings)
            .first()
            .map(|(_, hit)| hit.distance)
            .filter(|&distance| distance < length);
        let clear = match hit {
            Some(distance) => ((distance - occlusion.margin.max(0.0)) / length).clamp(0.0, 1.0),
            None => 1.0,
        };
        if clear < motion.clearance() {
            // In front of the occluder this frame, from rest: the spring moves it out from here.
            motion.set_clearance(clear);
            spring.set_velocity(0.0);
            let translation = posed.place(&pose, clear);
            if translation.is_finite() && transform.translation != translation {
                transform.translation = translation;
            }
        }
        spring.set_target_if_neq(clear);
    }
}

/// After [`occlude`]: the `GlobalTransform` of a camera pulled in this frame, so that it renders
/// from where it was pulled to (propagation ran before the ray could be cast).
pub(super) fn place_pulled_cameras(
    mut cameras: Query<
        (&Transform, &mut GlobalTransform, Option<&ChildOf>),
        (With<CameraOcclusion>, Changed<Transform>),
    >,
    parents: Query<&GlobalTransform, Without<CameraOcclusion>>,
) {
    for (transform, mut global, parent) in &mut cameras {
        let placed = match parent.and_then(|parent| parents.get(parent.parent()).ok()) {
            Some(parent) => parent.mul_transform(*transform),
            None => GlobalTransform::from(*transform),
        };
        global.set_if_neq(placed);
    }
}

/// [`CameraOcclusion`] (part of [`SpringCameraPlugin`](super::SpringCameraPlugin) with feature
/// `camera_occlusion`): the clearance spring, and the ray cast after transform propagation.
#[derive(Debug, Default, Clone, Copy)]
pub(super) struct SpringCameraOcclusionPlugin;

impl Plugin for SpringCameraOcclusionPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins(SpringPropertyPlugin::<RigClearance>::default())
            .register_type::<CameraOcclusion>();
        // Occlusion sees this frame's transforms and bounds: after propagation, before the
        // cameras' frusta are computed; with the first occluded rig.
        add_systems_on_first_use(
            app,
            &[TypeId::of::<CameraOcclusion>()],
            PostUpdate,
            |schedule| {
                use bevy::camera::visibility::VisibilitySystems;
                use bevy::transform::TransformSystems;
                schedule.add_systems(
                    (occlude, place_pulled_cameras)
                        .chain()
                        .after(TransformSystems::Propagate)
                        .after(VisibilitySystems::CalculateBounds)
                        .after(VisibilitySystems::VisibilityPropagate)
                        .before(VisibilitySystems::UpdateFrusta)
                        .run_if(any_with_component::<CameraOcclusion>)
                        .run_if(meshes_exist),
                );
            },
        );
    }
}
