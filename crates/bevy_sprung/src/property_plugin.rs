//! [`SpringPropertyPlugin`]: one property, with the mechanism that steps it and what every
//! feature built on springs needs of it.

use core::marker::PhantomData;

use bevy::prelude::*;

use crate::property::SpringProperty;
use crate::spring::{SpringPropertyStepPlugin, is_registered};

/// Adds everything for one [`SpringProperty`]: springing a field of your own component takes a
/// [`spring_property!`](crate::spring_property) and this plugin. It adds the mechanism that
/// steps the property's springs ([`SpringPropertyStepPlugin<P>`]) and what the features built on
/// springs need of the property: [`SpringSequence<P>`](crate::choreography::SpringSequence),
/// groups, and with their cargo features `InteractionTargets<P>` and spring presets. Their
/// systems join [`SpringUpdate`](crate::spring::SpringUpdate), in
/// [`PropertySystems<P>`](crate::spring::PropertySystems), when their first component is added
/// (until then the property costs nothing a frame).
///
/// In an app without [`SpringPlugins`](crate::SpringPlugins) it adds what springs need to step,
/// with the defaults; add `SpringPlugins` first to configure them. Adding a property twice (say,
/// once by a library and once by the app) is harmless.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::space::Linear;
///
/// #[derive(Component, Default)]
/// struct Health {
///     shown: f32,
/// }
///
/// spring_property!(
///     /// The health bar's shown value.
///     ShownHealth: Health::shown as Linear<f32>
/// );
///
/// let mut app = App::new();
/// app.add_plugins((
///     MinimalPlugins,
///     SpringPlugins::default(),
///     SpringPropertyPlugin::<ShownHealth>::default(),
/// ));
/// app.world_mut()
///     .spawn((Health::default(), PropertySpring::<ShownHealth>::new(Spring::smooth(), 100.0)));
/// app.update();
/// ```
pub struct SpringPropertyPlugin<P: SpringProperty>(PhantomData<fn() -> P>);

impl<P: SpringProperty> Default for SpringPropertyPlugin<P> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P: SpringProperty> Plugin for SpringPropertyPlugin<P> {
    fn build(&self, app: &mut App) {
        if is_registered::<P>(app.world()) {
            return;
        }
        app.add_plugins(SpringPropertyStepPlugin::<P>::default());
        crate::choreography::add_property::<P>(app);
        crate::presence::add_property::<P>(app);
        crate::implicit::add_property::<P>(app);
        #[cfg(feature = "picking")]
        crate::interaction::add_property::<P>(app);
        #[cfg(feature = "asset")]
        crate::asset::add_property::<P>(app);
    }

    fn is_unique(&self) -> bool {
        false
    }
}

impl<P: SpringProperty> core::fmt::Debug for SpringPropertyPlugin<P> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "SpringPropertyPlugin<{}>", P::short_type_path())
    }
}

/// Adds built-in property `P`: [`SpringPropertyPlugin<P>`], and with feature `asset` its
/// sequences from files.
#[cfg(feature = "asset")]
fn add_built_in<P>(app: &mut App)
where
    P: SpringProperty,
    crate::property::ValueOf<P>: serde::de::DeserializeOwned,
{
    app.add_plugins((
        SpringPropertyPlugin::<P>::default(),
        crate::asset::SpringSequenceAssetPlugin::<P>::default(),
    ));
}

/// Adds built-in property `P`: [`SpringPropertyPlugin<P>`].
#[cfg(not(feature = "asset"))]
fn add_built_in<P: SpringProperty>(app: &mut App) {
    app.add_plugins(SpringPropertyPlugin::<P>::default());
}

/// Springs `Transform`s: [`TranslationSpring`](crate::transform::TranslationSpring),
/// [`RotationSpring`](crate::transform::RotationSpring),
/// [`ScaleSpring`](crate::transform::ScaleSpring) and
/// [`SignedScaleSpring`](crate::transform::SignedScaleSpring), and whole turns
/// ([`SpinAngleSpring`](crate::spin::SpinAngleSpring)) (part of
/// [`SpringPlugins`](crate::SpringPlugins)).
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringTransformPlugin;

impl Plugin for SpringTransformPlugin {
    fn build(&self, app: &mut App) {
        use crate::transform::{Rotation, Scale, SignedScale, Translation};
        add_built_in::<Translation>(app);
        add_built_in::<Rotation>(app);
        add_built_in::<Scale>(app);
        add_built_in::<SignedScale>(app);
        add_built_in::<crate::spin::SpinAngle>(app);
    }
}

/// Springs the colours of sprites (feature `sprite`) and UI nodes (feature `ui`) in Oklab
/// (part of [`SpringPlugins`](crate::SpringPlugins)). A `Color` field of your own springs with
/// [`spring_property!`](crate::spring_property)`(… as OklabColor)`.
#[cfg(feature = "color")]
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringColorPlugin;

#[cfg(feature = "color")]
impl Plugin for SpringColorPlugin {
    #[cfg_attr(
        not(any(feature = "sprite", feature = "ui")),
        expect(
            unused_variables,
            reason = "with `color` alone there is no colour component to register"
        )
    )]
    fn build(&self, app: &mut App) {
        #[cfg(feature = "sprite")]
        add_built_in::<crate::color::SpriteColor>(app);
        #[cfg(feature = "ui")]
        {
            use crate::color::ImageNodeColor;
            add_built_in::<BackgroundColor>(app);
            add_built_in::<BorderColor>(app);
            add_built_in::<TextColor>(app);
            add_built_in::<ImageNodeColor>(app);
        }
    }
}

/// Springs UI geometry: `UiTransform` translation, scale and rotation and `Node` sizes and
/// offsets, with layout transitions and momentum scrolling
/// ([`SpringUiLayoutPlugin`](crate::ui::SpringUiLayoutPlugin)) (part of
/// [`SpringPlugins`](crate::SpringPlugins) with feature `ui`; UI colours are in
/// [`SpringColorPlugin`]).
#[cfg(feature = "ui")]
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringUiPlugin;

#[cfg(feature = "ui")]
impl Plugin for SpringUiPlugin {
    fn build(&self, app: &mut App) {
        use crate::ui::{
            LayoutScale, LayoutTranslation, NodeBottom, NodeHeight, NodeLeft, NodePosition,
            NodeRight, NodeSize, NodeTop, NodeWidth, ScrollOffset, SpringUiLayoutPlugin,
            UiTransformRotation, UiTransformScale, UiTransformTranslation,
        };
        add_built_in::<UiTransformTranslation>(app);
        add_built_in::<UiTransformScale>(app);
        add_built_in::<UiTransformRotation>(app);
        add_built_in::<NodeSize>(app);
        add_built_in::<NodePosition>(app);
        add_built_in::<NodeWidth>(app);
        add_built_in::<NodeHeight>(app);
        add_built_in::<NodeLeft>(app);
        add_built_in::<NodeTop>(app);
        add_built_in::<NodeRight>(app);
        add_built_in::<NodeBottom>(app);
        // Layout offsets and scroll positions: no sequences from files.
        app.add_plugins((
            SpringPropertyPlugin::<LayoutTranslation>::default(),
            SpringPropertyPlugin::<LayoutScale>::default(),
            SpringPropertyPlugin::<ScrollOffset>::default(),
            SpringUiLayoutPlugin,
        ));
    }
}
