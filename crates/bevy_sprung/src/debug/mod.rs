//! The debug overlay: gizmos that show what springs are doing while the game runs (feature
//! `debug`). Add [`SpringDebugPlugin`] to see, per entity:
//!
//! - **springs** ([`SpringGizmos`]): each `Transform` translation spring's target, velocity,
//!   the path it will take to rest and the seconds left until it settles, and the springs
//!   asleep; each rotation spring's pointer (the local x axis) now and at its target with the
//!   path of its tip, and each scale spring's box now and at its target. The paths and the
//!   times are exact, from the closed-form future of the spring
//!   ([`SpringForecast`](crate::spring::SpringForecast)), not sampled guesses: the path drawn
//!   is the path the spring then takes, at any frame rate;
//! - **camera rigs** ([`CameraRigGizmos`], feature `camera`): the guides of each
//!   [`CameraRig`](crate::camera::CameraRig), drawn in the world where they act, as
//!   Cinemachine draws its guides over the game view: the dead zone around the held point,
//!   the framed point and the goal (with the look-ahead between them), the view the camera is
//!   heading for, the confiner's bounds with the band where the camera slows, the group's
//!   targets with their radii and the extent the group framing fits, the orbit sphere, and
//!   the occlusion ray; and every shot ([`VirtualCamera`](crate::camera::VirtualCamera)) as a
//!   frame with its priority, the one showing in gold, with the path a blending camera will
//!   take to it;
//! - **chains** ([`ChainGizmos`]): each [`SpringChain`](crate::chain::SpringChain)'s joints
//!   and bones, the rest pose they spring around, and its colliders;
//! - **throws** ([`ThrowGizmos`]): each [`Inertia`](crate::inertia::Inertia)'s and drag's
//!   bounds with the give of their rubber band, the points, lines or grid they snap to, and
//!   where a moving throw will come to rest;
//! - **UI nodes** ([`UiSpringGizmos`], feature `ui`), in their own space, over the view of the
//!   camera their UI is on: `UiTransform` translation springs' targets and paths, layout
//!   springs' boxes where they are drawn and where layout puts them, scroll areas' bounds,
//!   rubber band and rest, and UI drags' bounds and snap points.
//!
//! Each group is a Bevy [`GizmoConfigGroup`] of its own, drawn over the scene: turn one on or
//! off, change its options or its line width, through [`GizmoConfigStore`] (or all at once, with a key:
//! [`SpringDebugPlugin::toggled_by`]). A group that is off costs nothing: its system does not
//! run. Without the plugin nothing of it is built into the app.
//!
//! The gizmos are drawn in the world (`Transform` space): in 2D in pixels, in 3D in world
//! units; [`SpringGizmos::size`] (and the other groups' `size`) sets the size of markers and
//! labels. Rendering them needs Bevy's gizmo renderer (`bevy_gizmos_render`, part of the
//! `2d`/`3d` feature sets).

#[cfg(feature = "camera")]
mod camera;
mod chains;
#[cfg(feature = "ui")]
mod nodes;
#[cfg(feature = "camera")]
mod shots;
mod springs;
mod throws;
mod turns;
#[cfg(feature = "ui")]
mod ui_space;

use bevy::gizmos::config::{GizmoConfigGroup, GizmoConfigStore};
use bevy::gizmos::{AppGizmoBuilder, GizmoPlugin};
use bevy::prelude::*;
use bevy::transform::TransformSystems;

#[cfg(feature = "camera")]
pub use camera::CameraRigGizmos;
pub use chains::ChainGizmos;
#[cfg(feature = "ui")]
pub use nodes::UiSpringGizmos;
pub use springs::SpringGizmos;
pub use throws::ThrowGizmos;

/// Shows what springs, camera rigs and chains are doing, as gizmos (see the [module](self)).
///
/// It draws with Bevy's gizmos: add it after `DefaultPlugins` (which has `GizmoPlugin`);
/// without a `GizmoPlugin` it says so once and draws nothing.
///
/// # Example
/// ```no_run
/// use bevy::prelude::*;
/// use bevy_sprung::debug::SpringDebugPlugin;
/// use bevy_sprung::prelude::*;
///
/// App::new()
///     .add_plugins((
///         DefaultPlugins,
///         SpringPlugins::default(),
///         // Hidden until D is pressed.
///         SpringDebugPlugin::hidden().toggled_by(KeyCode::KeyD),
///     ))
///     .run();
/// ```
#[derive(Debug, Clone, Copy)]
pub struct SpringDebugPlugin {
    /// Whether the groups start shown.
    pub shown: bool,
    /// A key that shows or hides every group at once.
    pub toggle: Option<KeyCode>,
}

impl Default for SpringDebugPlugin {
    /// Every group shown, no key.
    fn default() -> Self {
        Self {
            shown: true,
            toggle: None,
        }
    }
}

impl SpringDebugPlugin {
    /// Every group hidden until it is turned on (through [`GizmoConfigStore`] or the
    /// [`toggled_by`](Self::toggled_by) key).
    #[must_use]
    pub fn hidden() -> Self {
        Self {
            shown: false,
            toggle: None,
        }
    }

    /// `key` shows or hides every group at once (a group turned on or off by itself is set
    /// like the others at the next press).
    #[must_use]
    pub fn toggled_by(mut self, key: KeyCode) -> Self {
        self.toggle = Some(key);
        self
    }
}

/// Where the overlay draws: in `PostUpdate`, after transform propagation (so it draws this
/// frame's poses, the springs' and chains' included).
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct SpringDebugSystems;

impl Plugin for SpringDebugPlugin {
    fn build(&self, app: &mut App) {
        if !app.is_plugin_added::<GizmoPlugin>() {
            warn!(
                "bevy_sprung: SpringDebugPlugin draws with Bevy's gizmos, and the app has no \
                 GizmoPlugin yet: add SpringDebugPlugin after DefaultPlugins (or after \
                 GizmoPlugin); nothing is drawn"
            );
            return;
        }
        app.configure_sets(
            PostUpdate,
            SpringDebugSystems.after(TransformSystems::Propagate),
        );
        add_group::<SpringGizmos>(app, self.shown);
        add_group::<ChainGizmos>(app, self.shown);
        add_group::<ThrowGizmos>(app, self.shown);
        app.add_systems(
            PostUpdate,
            (
                (
                    springs::draw_springs,
                    turns::draw_rotations,
                    turns::draw_scales,
                )
                    .run_if(is_shown::<SpringGizmos>),
                chains::draw_chains.run_if(is_shown::<ChainGizmos>),
                throws::draw_inertia.run_if(is_shown::<ThrowGizmos>),
                #[cfg(feature = "picking")]
                throws::draw_drags.run_if(is_shown::<ThrowGizmos>),
            )
                .in_set(SpringDebugSystems),
        );
        #[cfg(feature = "camera")]
        {
            add_group::<CameraRigGizmos>(app, self.shown);
            app.add_systems(
                PostUpdate,
                (camera::draw_rigs, shots::draw_shots)
                    .run_if(is_shown::<CameraRigGizmos>)
                    .in_set(SpringDebugSystems),
            );
        }
        #[cfg(feature = "ui")]
        {
            // After the layout springs and rubber bands have drawn their nodes.
            add_group::<UiSpringGizmos>(app, self.shown);
            app.add_systems(
                PostUpdate,
                (
                    nodes::draw_translations,
                    nodes::draw_layouts,
                    nodes::draw_scrolls,
                    #[cfg(feature = "picking")]
                    nodes::draw_drags,
                )
                    .run_if(is_shown::<UiSpringGizmos>)
                    .after(bevy::ui::UiSystems::PostLayout)
                    .in_set(SpringDebugSystems),
            );
        }
        if let Some(key) = self.toggle {
            app.add_systems(
                PreUpdate,
                (move |keys: Option<Res<ButtonInput<KeyCode>>>,
                       mut store: ResMut<GizmoConfigStore>| {
                    if keys.is_some_and(|keys| keys.just_pressed(key)) {
                        toggle_all(&mut store);
                    }
                })
                .after(bevy::input::InputSystems),
            );
        }
    }
}

/// Registers group `G`, shown or not, drawn over the scene (as guides are: a path or a zone
/// behind a mesh is still seen).
fn add_group<G: GizmoConfigGroup>(app: &mut App, shown: bool) {
    app.init_gizmo_group::<G>();
    let mut store = app.world_mut().resource_mut::<GizmoConfigStore>();
    let (config, _) = store.config_mut::<G>();
    config.enabled = shown;
    config.depth_bias = -1.0;
}

/// Whether group `G` is shown: a group that is off does not run its system.
fn is_shown<G: GizmoConfigGroup>(store: Res<GizmoConfigStore>) -> bool {
    store.config::<G>().0.enabled
}

/// Shows every group if any is hidden, otherwise hides them all.
fn toggle_all(store: &mut GizmoConfigStore) {
    let hidden = !store.config::<SpringGizmos>().0.enabled
        || !store.config::<ChainGizmos>().0.enabled
        || !store.config::<ThrowGizmos>().0.enabled;
    #[cfg(feature = "camera")]
    let hidden = hidden || !store.config::<CameraRigGizmos>().0.enabled;
    #[cfg(feature = "ui")]
    let hidden = hidden || !store.config::<UiSpringGizmos>().0.enabled;
    store.config_mut::<SpringGizmos>().0.enabled = hidden;
    store.config_mut::<ChainGizmos>().0.enabled = hidden;
    store.config_mut::<ThrowGizmos>().0.enabled = hidden;
    #[cfg(feature = "camera")]
    {
        store.config_mut::<CameraRigGizmos>().0.enabled = hidden;
    }
    #[cfg(feature = "ui")]
    {
        store.config_mut::<UiSpringGizmos>().0.enabled = hidden;
    }
}
