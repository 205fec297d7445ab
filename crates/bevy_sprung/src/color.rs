//! Colours of sprites and UI nodes, sprung in Oklab ([`OklabColor`]).

use bevy::prelude::*;

use crate::property_plugin::SpringPropertyPlugin;
#[cfg(doc)]
use crate::space::OklabColor;

#[cfg(feature = "sprite")]
mod sprite {
    use bevy::prelude::*;

    use crate::space::OklabColor;
    use crate::spring::PropertySpring;

    spring_property!(
        /// `Sprite::color`, in Oklab.
        pub SpriteTint: Sprite::color as OklabColor
    );

    /// A spring on the colour of a `Sprite`, in Oklab.
    pub type SpriteColorSpring = PropertySpring<SpriteTint>;
}

#[cfg(feature = "sprite")]
pub use sprite::{SpriteColorSpring, SpriteTint};

#[cfg(feature = "ui")]
mod ui {
    use bevy::prelude::*;

    use crate::space::OklabColor;
    use crate::spring::PropertySpring;

    spring_property!(
        /// `BackgroundColor`, in Oklab.
        pub BackgroundTint: BackgroundColor::0 as OklabColor
    );

    spring_property!(
        /// `BorderColor`, all four sides together (read from the top side, written to all), in
        /// Oklab.
        pub BorderTint: BorderColor {
            get: |border| border.top,
            set: |border, color| *border = BorderColor::all(color)
        } as OklabColor
    );

    spring_property!(
        /// `TextColor`, in Oklab.
        pub TextTint: TextColor::0 as OklabColor
    );

    spring_property!(
        /// `ImageNode::color` (the image's tint), in Oklab.
        pub ImageTint: ImageNode::color as OklabColor
    );

    /// A spring on a node's `BackgroundColor`, in Oklab.
    pub type BackgroundColorSpring = PropertySpring<BackgroundTint>;
    /// A spring on a node's `BorderColor` (all sides), in Oklab.
    pub type BorderColorSpring = PropertySpring<BorderTint>;
    /// A spring on a text's `TextColor`, in Oklab.
    pub type TextColorSpring = PropertySpring<TextTint>;
    /// A spring on an `ImageNode`'s tint, in Oklab.
    pub type ImageColorSpring = PropertySpring<ImageTint>;
}

#[cfg(feature = "ui")]
pub use ui::{
    BackgroundColorSpring, BackgroundTint, BorderColorSpring, BorderTint, ImageColorSpring,
    ImageTint, TextColorSpring, TextTint,
};

/// Springs the colours of sprites (feature `sprite`) and UI nodes (feature `ui`) in Oklab
/// (part of [`SpringPlugin`](crate::SpringPlugin)). A `Color` field of your own springs with
/// [`spring_property!`](crate::spring_property)`(… as OklabColor)`.
#[derive(Debug, Default, Clone, Copy)]
pub struct ColorSpringPlugin;

impl Plugin for ColorSpringPlugin {
    #[cfg_attr(
        not(feature = "sprite"),
        expect(
            unused_variables,
            reason = "with `color` alone there is no colour component to register"
        )
    )]
    fn build(&self, app: &mut App) {
        #[cfg(feature = "sprite")]
        app.add_plugins(SpringPropertyPlugin::<SpriteTint>::default());
        #[cfg(all(feature = "sprite", feature = "asset"))]
        app.add_plugins(crate::asset::SequenceAssetPlugin::<SpriteTint>::default());
        #[cfg(all(feature = "ui", feature = "asset"))]
        app.add_plugins((
            crate::asset::SequenceAssetPlugin::<BackgroundTint>::default(),
            crate::asset::SequenceAssetPlugin::<BorderTint>::default(),
            crate::asset::SequenceAssetPlugin::<TextTint>::default(),
            crate::asset::SequenceAssetPlugin::<ImageTint>::default(),
        ));
        #[cfg(feature = "ui")]
        app.add_plugins((
            SpringPropertyPlugin::<BackgroundTint>::default(),
            SpringPropertyPlugin::<BorderTint>::default(),
            SpringPropertyPlugin::<TextTint>::default(),
            SpringPropertyPlugin::<ImageTint>::default(),
        ));
    }
}
