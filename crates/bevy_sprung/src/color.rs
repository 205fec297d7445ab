//! Colours, sprung in Oklab with their channels kept in range.

use core::marker::PhantomData;

use bevy::color::{LinearRgba, Oklaba};
use bevy::ecs::component::Mutable;
use bevy::math::Vec4;
use bevy::prelude::*;
use bevy::reflect::TypePath;
use sprung::RestThreshold;

use crate::component::PropertySpring;
use crate::property::SpringProperty;

/// A `Color` field of a component, for [`Oklab`] to spring.
pub trait ColorField: TypePath + Send + Sync + 'static {
    /// The component holding the colour.
    type Component: Component<Mutability = Mutable>;

    /// Reads the colour.
    #[must_use]
    fn get(component: &Self::Component) -> Color;

    /// Writes the colour.
    fn set(component: &mut Self::Component, color: Color);
}

/// Springs the colour field `F` in Oklab (lightness, a, b) plus alpha.
///
/// Oklab is perceptually even, so a spring moves through colours that look like an even blend
/// (no muddy midpoints from mixing in sRGB) and an overshoot reads as "a little brighter", not as
/// a hue jump. Every step keeps alpha in `[0, 1]` and the linear RGB channels in
/// `[0, max(1, target's channel)]` (HDR targets stay reachable). Values are written as
/// `Color::LinearRgba`; at rest the target is written exactly as given.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// fn hover(mut buttons: Query<(&Interaction, &mut BackgroundColorSpring), Changed<Interaction>>) {
///     for (interaction, mut color) in &mut buttons {
///         let target = match interaction {
///             Interaction::Hovered => Color::srgb(0.3, 0.5, 0.9),
///             _ => Color::srgb(0.15, 0.15, 0.2),
///         };
///         let _ = color.set_target(target);
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugin::default())).add_systems(Update, hover);
/// # app.update();
/// ```
#[derive(TypePath)]
pub struct Oklab<F: ColorField>(PhantomData<fn() -> F>);

/// `(L, a, b, alpha)` of a colour.
#[inline]
fn oklab(color: Color) -> Vec4 {
    let c = Oklaba::from(color);
    Vec4::new(c.lightness, c.a, c.b, c.alpha)
}

impl<F: ColorField> SpringProperty for Oklab<F> {
    type Component = F::Component;
    type Value = Color;
    type Linear = Vec4;

    /// A thousandth of the lightness range, and a hundredth per second.
    fn default_rest() -> RestThreshold<f32> {
        RestThreshold::new(1e-3, 1e-2)
    }

    #[inline]
    fn get(component: &Self::Component) -> Color {
        F::get(component)
    }

    #[inline]
    fn set(component: &mut Self::Component, value: Color) {
        F::set(component, value);
    }

    #[inline]
    fn is_finite(value: Color) -> bool {
        Vec4::from(LinearRgba::from(value).to_f32_array()).is_finite()
    }

    #[inline]
    fn offset(value: Color, target: Color) -> Vec4 {
        oklab(value) - oklab(target)
    }

    #[inline]
    fn at_offset(target: Color, offset: Vec4) -> Color {
        let c = oklab(target) + offset;
        Color::Oklaba(Oklaba::new(c.x, c.y, c.z, c.w))
    }

    #[inline]
    fn constrain(_before: Color, after: Color, velocity: Vec4, target: Color) -> (Color, Vec4) {
        let limit = LinearRgba::from(target);
        let value = LinearRgba::from(after);
        let clamped = LinearRgba::new(
            value.red.clamp(0.0, limit.red.max(1.0)),
            value.green.clamp(0.0, limit.green.max(1.0)),
            value.blue.clamp(0.0, limit.blue.max(1.0)),
            value.alpha.clamp(0.0, 1.0),
        );
        (Color::LinearRgba(clamped), velocity)
    }
}

macro_rules! color_field {
    ($(#[$doc:meta])* $field:ident, $component:ty, $alias:ident, |$c:ident| $get:expr, |$m:ident, $color:ident| $set:expr) => {
        $(#[$doc])*
        #[derive(TypePath, Debug, Clone, Copy)]
        pub struct $field;

        impl ColorField for $field {
            type Component = $component;

            #[inline]
            fn get($c: &$component) -> Color {
                $get
            }

            #[inline]
            fn set($m: &mut $component, $color: Color) {
                $set;
            }
        }

        #[doc = concat!("A spring on the colour of [`", stringify!($component), "`], in Oklab.")]
        pub type $alias = PropertySpring<Oklab<$field>>;
    };
}

#[cfg(feature = "sprite")]
color_field!(
    /// `Sprite::color`.
    SpriteTint,
    Sprite,
    SpriteColorSpring,
    |sprite| sprite.color,
    |sprite, color| sprite.color = color
);

#[cfg(feature = "ui")]
color_field!(
    /// `BackgroundColor`.
    Background,
    BackgroundColor,
    BackgroundColorSpring,
    |background| background.0,
    |background, color| background.0 = color
);

#[cfg(feature = "ui")]
color_field!(
    /// `BorderColor`, all four sides together (read from the top side, written to all).
    Border,
    BorderColor,
    BorderColorSpring,
    |border| border.top,
    |border, color| *border = BorderColor::all(color)
);

#[cfg(feature = "ui")]
color_field!(
    /// `TextColor`.
    Text,
    TextColor,
    TextColorSpring,
    |text| text.0,
    |text, color| text.0 = color
);

#[cfg(feature = "ui")]
color_field!(
    /// `ImageNode::color` (the image's tint).
    ImageTint,
    ImageNode,
    ImageColorSpring,
    |image| image.color,
    |image, color| image.color = color
);
