//! Exact damped springs for Bevy.
//!
//! Spring components move a property of their entity — a `Transform`'s translation, rotation or
//! scale, a UI node's size or colour, or any field you name with
//! [`spring_property!`] — toward a target every frame, with the exact closed-form step of
//! [`sprung`]: the same motion at any frame rate and after a hitch, momentum kept when
//! retargeted, arrival at any magnitude, and no NaN ever written.
//!
//! - **One mechanism**: [`PropertySpring<P>`](spring::PropertySpring) springs any
//!   [`SpringProperty`](property::SpringProperty); the built-in
//!   [`TranslationSpring`](transform::TranslationSpring),
//!   [`RotationSpring`](transform::RotationSpring), [`ScaleSpring`](transform::ScaleSpring),
//!   the UI and colour springs are aliases, declared with the same one-line macro you use for a
//!   field of your own. How a value springs — as a vector, never through zero, the short way
//!   round, in Oklab, in its UI unit — is its [`SpringSpace`](space::SpringSpace).
//! - **Simulate only what the scene calls for**: each property is a separate component, so only
//!   what a scene springs is stepped; a spring at rest snaps onto its target, triggers
//!   [`SpringSettled`](spring::SpringSettled) once and sleeps (not iterated, no writes,
//!   `Changed<Transform>` stays quiet) until its target changes; with the `visibility` feature,
//!   springs nobody sees skip frames and [catch up](visibility::CatchUpWhenHidden) exactly.
//! - **Tween replacement and camera smoothing**: UI geometry and colours (feature `ui`),
//!   [`SpringFollow`](follow::SpringFollow) for cameras, [`Spin`](spin::Spin) for whole turns.
//! - **Interaction and juice**: springs that answer the pointer (`interaction`, feature
//!   `picking`: hover/press/drag targets, drag and fling to snap points), and
//!   [`juice`]: punches, camera shake, squash & stretch.
//!
//! # Example
//! ```
//! use bevy::prelude::*;
//! use bevy_sprung::prelude::*;
//!
//! let mut app = App::new();
//! app.add_plugins((MinimalPlugins, SpringPlugins::default()));
//! let entity = app
//!     .world_mut()
//!     .spawn((Transform::default(), TranslationSpring::new(Spring::snappy(), Vec3::X * 100.0)))
//!     .id();
//! for _ in 0..90 {
//!     app.update();
//! }
//! ```
//!
//! # Layout
//! Each domain is a module with its own plugin, components and systems, and [`SpringPlugins`]
//! adds them all. No two files import each other in a circle. From the bottom up:
//! - [`space`] (how values spring), [`clock`] (the one source of time,
//!   [`SpringClockPlugin`](clock::SpringClockPlugin)), [`property`] (what a property is);
//! - [`spring`], the mechanism every property shares
//!   ([`SpringSchedulePlugin`](spring::SpringSchedulePlugin),
//!   [`SpringPropertyStepPlugin`](spring::SpringPropertyStepPlugin), the sets and phases
//!   ([`PropertySystems`](spring::PropertySystems), [`SpringPhase`](spring::SpringPhase)) and
//!   the events ([`SpringSettled`](spring::SpringSettled), [`SpringWoke`](spring::SpringWoke)));
//! - the properties, which define markers and aliases only: [`transform`], [`spin`], `color`,
//!   `ui`;
//! - small shared types below the features that use them: [`throw`] (release velocity, bounds,
//!   snap points) and [`tracking`] (where a target is this frame, teleports);
//! - the features, which join the mechanism's sets or observe its events and which it never
//!   imports: [`choreography`], [`presence`] (built on choreography), [`follow`], `camera`
//!   (built on follow), [`juice`] (built on [`layers`]), [`chain`], [`inertia`],
//!   [`reduced_motion`], `interaction` (built on inertia), `inertialization`, `asset` and
//!   `visibility` (behind their features);
//! - on top, [`SpringPropertyPlugin`], which adds one property with the mechanism and every
//!   feature's part of it, the plugins of the built-in properties ([`SpringTransformPlugin`],
//!   `SpringColorPlugin`, `SpringUiPlugin`), and [`SpringPlugins`].
//!
//! Add the domain plugins alone to spring only what you need. The
//! [architecture guide](guides::architecture) follows one frame through these layers and shows
//! where a new property or feature plugs in.
//!
//! # Features
//! - `visibility`: [`CatchUpWhenHidden`](visibility::CatchUpWhenHidden), which needs
//!   `ViewVisibility` (`bevy/bevy_camera`).
//! - `color`: [`OklabColor`](space::OklabColor) for any `Color` field.
//! - `sprite`: `Sprite` colour (`color` + `bevy/bevy_sprite`).
//! - `ui`: `UiTransform`, `Node` geometry, `BackgroundColor`, `BorderColor`, `TextColor` and
//!   `ImageNode` colour (`color` + `bevy/bevy_ui`).
//! - `picking`: `interaction`: `InteractionState`, `InteractionTargets`, `SpringDrag`
//!   (`bevy/bevy_picking`; the app adds a picking backend).
//! - `animation`: [`Inertialization`](inertialization::Inertialization), clip changes in
//!   `bevy_animation` that never pop (`bevy/bevy_animation`).
//! - `serde`: `Serialize`/`Deserialize` for [`Spring`](sprung::Spring), `RestThreshold`,
//!   [`SpringClock`](clock::SpringClock) and the spring components' configuration.
#![cfg_attr(docsrs, feature(doc_cfg))]

extern crate alloc;

// First: `spring_property!` is in scope, by name, in every module declared after this one.
#[macro_use]
pub mod property;

#[cfg(feature = "asset")]
pub mod asset;
#[cfg(feature = "camera")]
pub mod camera;
pub mod chain;
pub mod choreography;
pub mod clock;
#[cfg(feature = "color")]
pub mod color;
#[cfg(feature = "curve")]
pub mod curve;
#[cfg(feature = "debug")]
pub mod debug;
#[cfg(feature = "designer")]
pub mod designer;
pub mod follow;
pub mod implicit;
pub mod inertia;
#[cfg(feature = "animation")]
pub mod inertialization;
#[cfg(feature = "picking")]
pub mod interaction;
pub mod juice;
pub mod layers;
mod plugin;
pub mod presence;
mod property_plugin;
pub mod reduced_motion;
mod rubber_band;
pub mod space;
pub mod spin;
pub mod spring;
pub mod throw;
pub mod tracking;
pub mod transform;
#[cfg(feature = "ui")]
pub mod ui;
#[cfg(feature = "visibility")]
pub mod visibility;

pub use plugin::SpringPlugins;
#[cfg(feature = "color")]
pub use property_plugin::SpringColorPlugin;
#[cfg(feature = "ui")]
pub use property_plugin::SpringUiPlugin;
pub use property_plugin::{SpringPropertyPlugin, SpringTransformPlugin};

/// Guides: long-form documentation.
pub mod guides {
    /// How the crate is built: the layers, one frame's path from a target to a written
    /// `Transform`, and where a new property or feature plugs in.
    #[doc = include_str!("../docs/architecture.md")]
    pub mod architecture {}

    /// From bevy_tweening to bevy_sprung: every bevy_tweening 0.16 feature and the code that
    /// replaces it. (Its examples use the `ui` and `asset` features.)
    #[cfg(all(feature = "ui", feature = "asset"))]
    #[doc = include_str!("../docs/from-bevy-tweening.md")]
    pub mod from_bevy_tweening {}

    /// UI that springs, concept by concept: each Motion (framer-motion), SwiftUI and CSS
    /// transition idea — presence, layout transitions, staggered children, implicit
    /// transitions, momentum scrolling — and the code that does it. (Its examples use the `ui`
    /// feature.)
    #[cfg(feature = "ui")]
    #[doc = include_str!("../docs/ui.md")]
    pub mod ui {}

    /// Secondary motion, concept by concept: each Dynamic Bone, SwiftUI additive-animation and
    /// react-spring `decay` idea — spring chains, layers, squash and stretch, inertia — and the
    /// code that does it.
    #[doc = include_str!("../docs/motion.md")]
    pub mod motion {}

    /// Animation transitions by inertialization: clip switches in `bevy_animation` that never
    /// pop, concept by concept (Unreal's and Unity's inertialization, Holden's
    /// "Spring-It-On"), and the code that does it. (Feature `animation`.)
    #[cfg(feature = "animation")]
    #[doc = include_str!("../docs/animation.md")]
    pub mod animation {}

    /// Camera rigs, concept by concept: each Cinemachine, smooth-bevy-cameras and `bevy_dolly`
    /// idea and the code that does it with [`CameraRig`](crate::camera::CameraRig).
    #[cfg(feature = "camera")]
    #[doc = include_str!("../docs/camera.md")]
    pub mod camera {}

    /// Tuning springs with the designer: how to read its plot, what each readout means, and
    /// the workflow from "feels wrong" to a saved `*.spring.ron`. (Feature `designer`.)
    #[cfg(feature = "designer")]
    #[doc = include_str!("../docs/tuning.md")]
    pub mod tuning {}
}

// The README's examples are compiled and run as doc tests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
pub use sprung;

/// What a first app needs: `use bevy_sprung::prelude::*;`.
///
/// The plugin group, [`Spring`](sprung::Spring) and its presets, the spring components of the
/// `Transform` and the commonest UI properties with their markers, and one entry component
/// per job (follow, camera rig, presence, sequence, juice, chain, drag). Everything else is
/// reached through the module named by its job: `camera` for the rig's parts (`DeadZone`,
/// `Confiner`, `GroupFraming`, …), [`presence`] for staggering and its events, [`choreography`]
/// for groups and sequence events, `ui` for every node property, `color`, [`spring`] for
/// the sets, events and motion, [`space`] for how values spring.
pub mod prelude {
    #[cfg(feature = "asset")]
    pub use crate::asset::UseSpringPreset;
    #[cfg(feature = "camera")]
    pub use crate::camera::{CameraRig, CameraTarget};
    pub use crate::chain::SpringChain;
    pub use crate::choreography::SpringSequence;
    #[cfg(feature = "ui")]
    pub use crate::color::BackgroundColorSpring;
    pub use crate::follow::SpringFollow;
    pub use crate::implicit::ImplicitSpring;
    pub use crate::inertia::Inertia;
    #[cfg(feature = "animation")]
    pub use crate::inertialization::Inertialization;
    #[cfg(feature = "picking")]
    pub use crate::interaction::{InteractionState, InteractionTargets, SpringDrag};
    pub use crate::juice::{Shake, SquashStretch};
    pub use crate::presence::{EnterFrom, ExitTo, Presence, PresenceCommands};
    pub use crate::reduced_motion::ReducedMotion;
    pub use crate::spring::{PropertySpring, SpringSettled, SpringTargetMut};
    pub use crate::spring_property;
    pub use crate::transform::{
        Rotation, RotationSpring, Scale, ScaleSpring, Translation, TranslationSpring,
    };
    #[cfg(feature = "ui")]
    pub use crate::ui::{
        LayoutSpring, NodeSize, NodeSizeSpring, UiTransformScale, UiTransformScaleSpring,
        UiTransformTranslation, UiTransformTranslationSpring,
    };
    pub use crate::{SpringPlugins, SpringPropertyPlugin};
    pub use sprung::{RestThreshold, Spring};
}
