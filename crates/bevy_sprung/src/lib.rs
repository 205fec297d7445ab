//! Exact damped springs for Bevy.
//!
//! Spring components move a property of their entity — a `Transform`'s translation, rotation or
//! scale, or any field you describe with a [`SpringProperty`] — toward a target every frame,
//! with the exact closed-form step of [`sprung`]: the same motion at any frame rate and after a
//! hitch, momentum kept when retargeted, and no NaN ever written.
//!
//! - **Simulate only what the scene calls for**: each property is a separate component, so only
//!   what a scene springs is stepped; a spring at rest snaps onto its target, triggers
//!   [`SpringSettled`] once and sleeps (not iterated, no writes, `Changed<Transform>` stays
//!   quiet) until its target changes; with the `visibility` feature, springs nobody sees can
//!   skip frames and [catch up](CatchUpWhenHidden) exactly in one step.
//! - **One mechanism**: [`PropertySpring<P>`] over a [`SpringProperty`]; the built-in
//!   [`TranslationSpring`], [`RotationSpring`], [`ScaleSpring`] are aliases, and a field of your
//!   own component takes a [`LinearProperty`] impl and a [`SpringPropertyPlugin`].
//!
//! # Example
//! ```
//! use bevy::prelude::*;
//! use bevy_sprung::prelude::*;
//!
//! let mut app = App::new();
//! app.add_plugins((MinimalPlugins, SpringPlugin::default()));
//! let entity = app
//!     .world_mut()
//!     .spawn((Transform::default(), TranslationSpring::new(Spring::snappy(), Vec3::X * 100.0)))
//!     .id();
//! app.update();
//! ```
//!
//! - **Tween replacement**: with the `ui` feature, `UiTransform` (translation, scale,
//!   rotation), `Node` sizes and offsets, and the UI colours spring too; colours move in Oklab
//!   and stay in range. [`SpringFollow`] makes a camera follow and look at an entity.
//!
//! # Features
//! - `visibility`: [`CatchUpWhenHidden`], which needs `ViewVisibility` (`bevy/bevy_camera`).
//! - `color`: [`Oklab`] springs for any `Color` field you describe with a [`ColorField`].
//! - `sprite`: `Sprite` colour (`color` + `bevy/bevy_sprite`).
//! - `ui`: `UiTransform`, `Node` geometry, `BackgroundColor`, `BorderColor`, `TextColor` and
//!   `ImageNode` colour (`color` + `bevy/bevy_ui`).

#[cfg(feature = "color")]
mod color;
mod component;
mod event;
mod follow;
mod plugin;
mod property;
mod spin;
mod systems;
#[cfg(feature = "ui")]
mod ui;

#[cfg(feature = "ui")]
pub use color::{
    Background, BackgroundColorSpring, Border, BorderColorSpring, ImageColorSpring, ImageTint,
    Text, TextColorSpring,
};
#[cfg(feature = "color")]
pub use color::{ColorField, Oklab};
#[cfg(feature = "sprite")]
pub use color::{SpriteColorSpring, SpriteTint};
#[cfg(feature = "visibility")]
pub use component::CatchUpWhenHidden;
pub use component::{
    PropertySpring, RotationSpring, ScaleSpring, SignedScaleSpring, SpringAsleep, SpringClock,
    SpringInputError, TranslationSpring,
};
pub use event::SpringSettled;
pub use follow::{SpringFollow, TargetMotion};
pub use plugin::{SpringPlugin, SpringPropertyPlugin, SpringSettings, SpringSystems};
pub use property::{
    LinearProperty, Reflectable, Rotation, Scale, SignedScale, SpringProperty, SpringVector,
    Translation, rotation_vector,
};
pub use spin::{Spin, SpinAngle, SpinSpring};
pub use sprung;
#[cfg(feature = "ui")]
pub use ui::{
    NodeBottom, NodeBottomSpring, NodeHeight, NodeHeightSpring, NodeLeft, NodeLeftSpring,
    NodePosition, NodePositionSpring, NodeRight, NodeRightSpring, NodeSize, NodeSizeSpring,
    NodeTop, NodeTopSpring, NodeWidth, NodeWidthSpring, UiRotationSpring, UiScaleSpring,
    UiTransformRotation, UiTransformScale, UiTransformTranslation, UiTranslationSpring,
};

/// The types most apps need: `use bevy_sprung::prelude::*;`.
pub mod prelude {
    #[cfg(feature = "visibility")]
    pub use crate::CatchUpWhenHidden;
    #[cfg(feature = "sprite")]
    pub use crate::SpriteColorSpring;
    #[cfg(feature = "ui")]
    pub use crate::{
        BackgroundColorSpring, BorderColorSpring, ImageColorSpring, NodePositionSpring,
        NodeSizeSpring, TextColorSpring, UiRotationSpring, UiScaleSpring, UiTranslationSpring,
    };
    pub use crate::{
        LinearProperty, PropertySpring, Rotation, RotationSpring, Scale, ScaleSpring, SignedScale,
        SignedScaleSpring, Spin, SpinSpring, SpringAsleep, SpringClock, SpringPlugin,
        SpringProperty, SpringPropertyPlugin, SpringSettled, SpringSystems, Translation,
        TranslationSpring,
    };
    pub use crate::{SpringFollow, TargetMotion};
    pub use sprung::{RestThreshold, Spring};
}
