//! The spring designer (feature `designer`): tune a spring by seeing it, then keep it.
//!
//! [`SpringDesignerPlugin`] opens a panel, on Bevy's own editor widgets (`bevy_feathers`),
//! beside a running game or on its own (`cargo run --example designer`):
//!
//! - **the plot** of the spring's step response, x(t) above and v(t) below, from the exact
//!   transition, with the readouts beside it: regime, overshoot, the settle time to a
//!   tolerance you set, period and half-life ([`Readouts`]);
//! - **every parametrisation** the crate speaks, kept in sync as any one field is edited:
//!   physical (m, k, c), natural frequency and damping ratio, half-life, SwiftUI's response
//!   and damping fraction, duration and bounce, Unity's smooth time, react-spring's tension
//!   and friction ([`Parametrisation`]); and the presets to start from;
//! - **A/B**: keep the spring as B, edit A, and both are plotted and previewed together;
//! - **a preview** on three things — a sprite moving to its target, a button's scale, a
//!   camera following a target — at 30, 60, 144 or 240 fps and a time scale: the steps of
//!   each rate lie on the same curve (the plot marks them);
//! - **save** to a `*.spring.ron` (the `asset` feature's [`SpringPreset`](crate::asset::SpringPreset)
//!   format) and **copy as code** (`Spring::from_duration_and_bounce(0.5, 0.2)`);
//! - **attached to the game**: the arrows pick any spring of the game (on the properties the
//!   plugin tunes, [`SpringDesignerPlugin::tuning`]); edits apply to it live, and saving
//!   writes the preset file it loads from, which every spring using it then reloads.
//!
//! Without the panel (an app without Bevy's UI), the same life is reachable from code:
//! [`SpringDesign`], [`TuneSpring`], [`SaveSpringDesign`].

mod attach;
mod model;
mod panel;
mod plot;
mod preview;

use bevy::asset::io::file::FileAssetReader;
use bevy::feathers::FeathersCorePlugin;
use bevy::feathers::dark_theme::create_dark_theme;
use bevy::feathers::theme::UiTheme;
use bevy::input_focus::tab_navigation::TabNavigationPlugin;
use bevy::prelude::*;

pub use attach::{DesignerStatus, SaveSpringDesign, SpringRef, TuneSpring, TunedSpring};
pub use model::{Parametrisation, PreviewSettings, Readouts, SpringDesign, step_response};

use crate::property::SpringProperty;
use crate::transform::{Rotation, Scale, Translation};
use crate::ui::{UiTransformScale, UiTransformTranslation};

/// Adds the spring designer (see the [module](self)): its panel, and tuning the springs of
/// the running game.
///
/// Add it after `DefaultPlugins` and [`SpringPlugins`](crate::SpringPlugins). It adds the parts
/// of Bevy's `FeathersPlugins` the app does not have yet (with the dark theme), so an app that
/// already uses Bevy's widgets keeps its own. An app without Bevy's UI gets no panel and is
/// told so once; [`SpringDesign`] and the events still work.
///
/// # Example
/// ```no_run
/// use bevy::prelude::*;
/// use bevy_sprung::designer::SpringDesignerPlugin;
/// use bevy_sprung::prelude::*;
///
/// App::new()
///     .add_plugins((
///         DefaultPlugins,
///         SpringPlugins::default(),
///         // F2 shows and hides it; saving writes assets/springs/jump.spring.ron.
///         SpringDesignerPlugin::default()
///             .toggled_by(KeyCode::F2)
///             .saving_to("springs/jump.spring.ron"),
///     ))
///     .run();
/// ```
pub struct SpringDesignerPlugin {
    tunables: Vec<attach::TunableProperty>,
    path: String,
    toggle: Option<KeyCode>,
}

impl Default for SpringDesignerPlugin {
    /// Tunes translation, rotation and scale springs of `Transform`s and `UiTransform`s,
    /// saves to `springs/designed.spring.ron`, always shown.
    fn default() -> Self {
        Self {
            tunables: Vec::new(),
            path: SpringDesign::default().path,
            toggle: None,
        }
        .tuning::<Translation>()
        .tuning::<Rotation>()
        .tuning::<Scale>()
        .tuning::<UiTransformTranslation>()
        .tuning::<UiTransformScale>()
    }
}

impl SpringDesignerPlugin {
    /// Also lets the designer tune the springs of property `P`.
    #[must_use]
    pub fn tuning<P: SpringProperty>(mut self) -> Self {
        self.tunables.push(attach::TunableProperty::of::<P>());
        self
    }

    /// Saves to `path`, relative to the asset folder, when the tuned spring has no preset
    /// file of its own.
    #[must_use]
    pub fn saving_to(mut self, path: impl Into<String>) -> Self {
        self.path = path.into();
        self
    }

    /// Shows and hides the panel when `key` is pressed.
    #[must_use]
    pub fn toggled_by(mut self, key: KeyCode) -> Self {
        self.toggle = Some(key);
        self
    }
}

/// The key that shows and hides the panel.
#[derive(Resource, Clone, Copy)]
struct ToggleKey(KeyCode);

impl Plugin for SpringDesignerPlugin {
    fn build(&self, app: &mut App) {
        let mut design = SpringDesign::default();
        design.path.clone_from(&self.path);
        // Saved where the app's asset server reads (add the designer after `AssetPlugin`).
        let folder = app
            .get_added_plugins::<AssetPlugin>()
            .first()
            .map_or_else(|| "assets".to_owned(), |assets| assets.file_path.clone());
        app.insert_resource(design)
            .init_resource::<TunedSpring>()
            .init_resource::<DesignerStatus>()
            .insert_resource(attach::Tunables {
                properties: self.tunables.clone(),
                assets_folder: FileAssetReader::get_base_path().join(folder),
            })
            .add_observer(attach::on_tune)
            .add_observer(attach::on_save)
            .add_systems(Update, attach::sync);
        if !app.is_plugin_added::<bevy::ui::UiPlugin>() {
            warn!(
                "bevy_sprung: SpringDesignerPlugin shows its panel with Bevy's UI, and the app has \
                 no UiPlugin yet: add SpringDesignerPlugin after DefaultPlugins; without it \
                 there is no panel (SpringDesign, TuneSpring and SaveSpringDesign still work)"
            );
            return;
        }
        // What `FeathersPlugins` adds, each part only if the app has none yet (adding a
        // plugin twice panics, and a game may already use Bevy's widgets or tab navigation).
        if !app.is_plugin_added::<TabNavigationPlugin>() {
            app.add_plugins(TabNavigationPlugin);
        }
        if !app.is_plugin_added::<FeathersCorePlugin>() {
            app.add_plugins(FeathersCorePlugin)
                .insert_resource(UiTheme(create_dark_theme()));
        }
        let image = app
            .world_mut()
            .resource_mut::<Assets<Image>>()
            .add(plot::image(plot::draw(&SpringDesign::default(), 1.0)));
        app.insert_resource(plot::ResponsePlot { image, span: 1.0 })
            .init_resource::<preview::PreviewClock>()
            .add_systems(Startup, panel::spawn)
            .add_systems(
                Update,
                (
                    panel::show_plot,
                    plot::redraw,
                    preview::advance,
                    preview::show,
                    panel::refresh_fields,
                    panel::refresh_texts,
                )
                    .chain()
                    .after(attach::sync),
            );
        if let Some(key) = self.toggle {
            app.insert_resource(ToggleKey(key))
                .add_systems(Update, toggle_panel);
        }
    }
}

fn toggle_panel(
    key: Res<ToggleKey>,
    keys: Res<ButtonInput<KeyCode>>,
    mut panels: Query<&mut Visibility, With<panel::DesignerPanel>>,
) {
    if keys.just_pressed(key.0) {
        for mut visibility in &mut panels {
            visibility.toggle_visible_hidden();
        }
    }
}
