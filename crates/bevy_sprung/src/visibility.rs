//! Springs nobody sees: skip frames, then catch up exactly in one step.

use bevy::prelude::*;

/// Opt-in for springs that nobody sees: while the entity's `ViewVisibility` is false its
/// springs skip frames, and are advanced exactly, in one step over the accumulated time, when
/// it is seen again or their target changes (under the old target first). Because every step
/// is the exact solution, the result equals stepping every frame (to rounding).
///
/// `ViewVisibility` reflects the previous frame. Use this where being seen does not depend on
/// the spring's own motion (hidden menus, far-away props, things behind the camera that the
/// camera turns toward): a spring whose motion would carry it into view while it is culled
/// waits to be seen or retargeted.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// fn spawn(mut commands: Commands) {
///     // A prop that bobs where the camera may not be looking.
///     commands.spawn((
///         Transform::default(),
///         TranslationSpring::new(Spring::wobbly(), Vec3::Y),
///         CatchUpWhenHidden,
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugin::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Default, Clone, Copy)]
#[reflect(Component, Default, Debug, Clone)]
pub struct CatchUpWhenHidden;

/// Registers [`CatchUpWhenHidden`] (part of [`SpringPlugin`](crate::SpringPlugin) with feature
/// `visibility`); the spring systems read it.
#[derive(Debug, Default, Clone, Copy)]
pub struct CatchUpPlugin;

impl Plugin for CatchUpPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<CatchUpWhenHidden>();
    }
}
