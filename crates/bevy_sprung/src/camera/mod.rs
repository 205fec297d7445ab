//! Camera rigs: a camera that follows a goal made of parts — targets, look-ahead, dead zone,
//! screen position, level bounds, group framing, orbit — every motion on the exact step
//! (feature `camera`).
//!
//! A [`CameraRig`] on a camera entity springs after its [`CameraGoal`]; the parts are further
//! components on the same entity, and a goal of your own joins in
//! [`CameraRigSystems::Goal`]. See the [camera guide](crate::guides::camera) for each
//! Cinemachine, smooth-bevy-cameras and `bevy_dolly` concept and the code that does it here.

mod blend;
mod components;
mod framing;
#[cfg(feature = "camera_occlusion")]
mod occlusion;
mod rail;
mod systems;
mod view;
mod zones;

use core::any::TypeId;

use bevy::prelude::*;

pub use blend::{
    BlendLens, BlendLensSpring, BlendOffset, BlendRotation, BlendRotationSpring, BlendTrack,
    BlendTranslation, BlendTranslationSpring, CameraBlend, VirtualCamera,
};
pub use components::{
    CameraGoal, CameraRig, CameraTarget, CameraTargets, Confiner, ConfinerVolume, DeadZone,
    GroupFraming, HardLimit, LookAhead, OrbitRig, RigHorizontal, RigHorizontalSpring, RigLookAhead,
    RigLookAheadSpring, RigMotion, RigOrbit, RigOrbitSpring, RigVertical, RigVerticalSpring,
    RigZoom, RigZoomSpring, ScreenPosition, ZoneSides, ZoneUnit,
};
#[cfg(feature = "camera_occlusion")]
pub use components::{RigClearance, RigClearanceSpring};
pub use framing::CameraFraming;
#[cfg(feature = "camera_occlusion")]
pub use occlusion::CameraOcclusion;
#[cfg(feature = "debug")]
pub(crate) use rail::RailState;
pub use rail::{CameraRail, RailAim, RailFollow, RailMotion, RigRail, RigRailSpring};
pub use systems::CameraRigSystems;
pub use zones::{
    ConfinerEdgeLeft, ConfinerEdgeReached, DeadZoneEntered, DeadZoneExited, HardLimitLeft,
    HardLimitReached,
};

use crate::property_plugin::SpringPropertyPlugin;
use crate::spring::{
    PropertySpring, PropertySystems, SpringPhase, SpringSystems, add_property_systems,
    add_systems_on_first_use, spring_schedule, warn_lacking,
};

/// [`CameraRig`] and its parts (part of [`SpringPlugins`](crate::SpringPlugins) with feature
/// `camera`). The rig's systems join the spring schedule with the first rig: goals and the
/// springs they retarget before the rig's springs step, the camera placed after.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringCameraPlugin;

impl Plugin for SpringCameraPlugin {
    fn build(&self, app: &mut App) {
        // In this order: the look-ahead, zoom and orbit step before the centre is framed.
        app.add_plugins((
            SpringPropertyPlugin::<RigLookAhead>::default(),
            SpringPropertyPlugin::<RigZoom>::default(),
            SpringPropertyPlugin::<RigOrbit>::default(),
        ));
        // The clearance steps before the camera is placed, from the last frame's pull.
        #[cfg(feature = "camera_occlusion")]
        app.add_plugins(occlusion::SpringCameraOcclusionPlugin);
        // The place along a rail steps before the camera is put on it.
        app.add_plugins(rail::SpringCameraRailPlugin);
        app.add_plugins((
            SpringPropertyPlugin::<RigHorizontal>::default(),
            SpringPropertyPlugin::<RigVertical>::default(),
        ))
        .register_type::<CameraRig>()
        .register_type::<CameraGoal>()
        .register_type::<CameraTargets>()
        .register_type::<LookAhead>()
        .register_type::<DeadZone>()
        .register_type::<ZoneSides>()
        .register_type::<HardLimit>()
        .register_type::<ScreenPosition>()
        .register_type::<Confiner>()
        .register_type::<ConfinerVolume>()
        .register_type::<GroupFraming>()
        .register_type::<OrbitRig>()
        .register_type::<RigMotion>()
        .register_type::<CameraFraming>()
        .add_observer(systems::note_warps);
        // Targets that move in `FixedUpdate` are sampled after each fixed step.
        add_systems_on_first_use(
            app,
            &[TypeId::of::<CameraTargets>()],
            FixedPostUpdate,
            |schedule| {
                schedule.add_systems(
                    systems::sample_fixed_targets.run_if(any_with_component::<CameraTargets>),
                );
            },
        );
        // A rig on an entity that is neither a camera nor a shot moves a Transform nobody
        // looks through: told once, where the spawning commands have been applied.
        let outer = spring_schedule(app);
        // Every rig requires its horizontal spring, whose first use brings these in.
        let rigs = [TypeId::of::<PropertySpring<RigHorizontal>>()];
        add_systems_on_first_use(app, &rigs, outer, |schedule| {
            schedule.add_systems(
                warn_lacking::<CameraRig, (Without<Camera>, Without<VirtualCamera>)>(
                    "Camera or VirtualCamera",
                    "the rig places this entity's Transform, but nothing renders through it; \
                     put the CameraRig on a camera (Camera2d, Camera3d) or on a VirtualCamera \
                     shot",
                )
                .before(SpringSystems)
                .run_if(any_with_component::<CameraRig>),
            );
        });
        // Blends come after the shots (rigs) are placed.
        app.add_plugins(blend::SpringCameraBlendPlugin);
        let springs = [TypeId::of::<PropertySpring<RigHorizontal>>()];
        add_property_systems(app, &springs, |schedule| {
            // The rig's properties run in the order the plugin added them: look-ahead, zoom,
            // orbit, horizontal, vertical.
            schedule
                .configure_sets(
                    (
                        CameraRigSystems::Targets,
                        CameraRigSystems::Goal,
                        CameraRigSystems::Track,
                    )
                        .chain()
                        .before(PropertySystems::<RigLookAhead>::default()),
                )
                .configure_sets(
                    CameraRigSystems::Frame
                        .after(PropertySystems::<RigOrbit>::default())
                        .in_set(PropertySystems::<RigHorizontal>::phase(SpringPhase::Input)),
                )
                .configure_sets(
                    CameraRigSystems::Compose
                        .in_set(PropertySystems::<RigVertical>::phase(SpringPhase::Observe)),
                )
                .add_systems(
                    (
                        systems::sample_targets.in_set(CameraRigSystems::Targets),
                        systems::track_goals.in_set(CameraRigSystems::Track),
                        systems::frame_goals.in_set(CameraRigSystems::Frame),
                        (
                            systems::compose_cameras,
                            systems::zoom_projections,
                            zones::announce_zones,
                        )
                            .chain()
                            .in_set(CameraRigSystems::Compose),
                    )
                        .run_if(any_with_component::<CameraRig>),
                );
        });
    }
}
