//! Colours of sprites and UI nodes, sprung in Oklab ([`OklabColor`]).
//!
//! A component that is one colour is its own property: `PropertySpring<BackgroundColor>`,
//! `SpringSettled<TextColor>`, `SpringSequence<BorderColor>` name Bevy's components directly. A
//! colour that is a field of a larger component has a marker named after both: `SpriteColor`
//! (`Sprite::color`), `ImageNodeColor` (`ImageNode::color`).

#[cfg(doc)]
use crate::space::OklabColor;

#[cfg(feature = "sprite")]
mod sprite {
    use bevy::prelude::*;

    use crate::space::OklabColor;
    use crate::spring::PropertySpring;

    spring_property!(
        /// `Sprite::color`, in Oklab.
        pub SpriteColor: Sprite::color as OklabColor
    );

    /// A spring on the colour of a `Sprite`, in Oklab.
    pub type SpriteColorSpring = PropertySpring<SpriteColor>;
}

#[cfg(feature = "sprite")]
pub use sprite::{SpriteColor, SpriteColorSpring};

#[cfg(feature = "ui")]
mod ui {
    use bevy::prelude::*;

    use crate::property::SpringProperty;
    use crate::space::OklabColor;
    use crate::spring::PropertySpring;

    /// `BackgroundColor` is its own property, sprung in Oklab.
    impl SpringProperty for BackgroundColor {
        type Component = Self;
        type Space = OklabColor;

        #[inline]
        fn get(background: &Self) -> Color {
            background.0
        }

        #[inline]
        fn set(background: &mut Self, color: Color) {
            background.0 = color;
        }
    }

    /// `BorderColor` is its own property, all four sides together (read from the top side,
    /// written to all), sprung in Oklab.
    impl SpringProperty for BorderColor {
        type Component = Self;
        type Space = OklabColor;

        #[inline]
        fn get(border: &Self) -> Color {
            border.top
        }

        #[inline]
        fn set(border: &mut Self, color: Color) {
            *border = Self::all(color);
        }
    }

    /// `TextColor` is its own property, sprung in Oklab.
    impl SpringProperty for TextColor {
        type Component = Self;
        type Space = OklabColor;

        #[inline]
        fn get(text: &Self) -> Color {
            text.0
        }

        #[inline]
        fn set(text: &mut Self, color: Color) {
            text.0 = color;
        }
    }

    spring_property!(
        /// `ImageNode::color` (the image's tint), in Oklab.
        pub ImageNodeColor: ImageNode::color as OklabColor
    );

    /// A spring on a node's `BackgroundColor`, in Oklab.
    pub type BackgroundColorSpring = PropertySpring<BackgroundColor>;
    /// A spring on a node's `BorderColor` (all sides), in Oklab.
    pub type BorderColorSpring = PropertySpring<BorderColor>;
    /// A spring on a text's `TextColor`, in Oklab.
    pub type TextColorSpring = PropertySpring<TextColor>;
    /// A spring on an `ImageNode`'s tint, in Oklab.
    pub type ImageNodeColorSpring = PropertySpring<ImageNodeColor>;
}

#[cfg(feature = "ui")]
pub use ui::{
    BackgroundColorSpring, BorderColorSpring, ImageNodeColor, ImageNodeColorSpring, TextColorSpring,
};
