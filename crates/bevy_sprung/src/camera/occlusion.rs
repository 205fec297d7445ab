//! Occlusion: the camera pulls in front of scene geometry between it and the point it frames,
//! and springs back out when the way is clear (feature `camera_occlusion`).

use bevy::picking::mesh_picking::ray_cast::{MeshRayCast, MeshRayCastSettings, RayCastVisibility};
use bevy::prelude::*;
use bevy::window::PrimaryWindow;
use sprung::Spring;

use super::components::{CameraTargets, RigClearanceSpring, RigMotion};
use super::systems::Posed;
use crate::spring::{PropertySpring, SpringTargetMut};

/// Keeps a [`CameraRig`](super::CameraRig)'s view of the point it frames clear: when a mesh is
/// between them (Bevy's `MeshRayCast`, along the rig's arm from the point to the camera), the
/// camera is pulled in front of it in the same frame, [`margin`](Self::margin) short of the
/// hit; when the way is clear again it springs back out with [`spring`](Self::spring). The
/// rig's targets and their descendants never occlude. Meshes are tested as Bevy's picking
/// sees them (`Aabb`s computed by Bevy's visibility systems; hidden meshes ignored).
///
/// Needs feature `camera_occlusion` (`bevy/mesh_picking`); a game without it pays nothing.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
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
/// # app.add_plugins((MinimalPlugins, AssetPlugin::default(), SpringPlugin::default())).init_asset::<Mesh>().add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
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

/// Before the camera is placed: cast each occluded rig's arm, pull the camera in to the
/// nearest hit, and aim its clearance spring at what is clear (all of the arm once nothing is
/// hit).
pub(super) fn occlude(
    mut rigs: Query<(
        Entity,
        Posed,
        &CameraOcclusion,
        &mut RigMotion,
        &mut RigClearanceSpring,
        Option<&CameraTargets>,
    )>,
    window: Query<&Window, With<PrimaryWindow>>,
    parents: Query<&ChildOf>,
    mut ray_cast: MeshRayCast,
) {
    let window = window.single().ok();
    for (camera, posed, occlusion, mut motion, mut spring, targets) in &mut rigs {
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
                    .any(|ancestor| targets.0.iter().any(|target| target.entity == ancestor))
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
        }
        spring.set_target_if_neq(clear);
    }
}
