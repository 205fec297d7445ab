//! Springs that skip frames and catch up exactly.

use bevy::prelude::*;

/// While `SkipFrames(true)`, the springs of this entity skip frames: each keeps the time that
/// passes and writes nothing, and is advanced over all of it in one step when it is `false`
/// again, or when its target changes (under the old target first). Each step is the exact
/// solution, so the result equals stepping every frame, to rounding.
///
/// For springs nobody needs to see move every frame: a hidden menu, a prop out of view
/// ([`CatchUpWhenHidden`](crate::visibility::CatchUpWhenHidden) keeps it equal to "not seen"
/// with the `visibility` feature), a panel behind another.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::spring::SkipFrames;
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugins::default()));
/// let panel = app
///     .world_mut()
///     .spawn((
///         Transform::default(),
///         TranslationSpring::new(Spring::smooth(), Vec3::X * 300.0),
///         SkipFrames(true),
///     ))
///     .id();
/// app.update();
/// // Shown again: it is where the spring would have taken it by now.
/// app.world_mut().entity_mut(panel).insert(SkipFrames(false));
/// app.update();
/// ```
#[derive(Component, Reflect, Debug, Default, Clone, Copy, PartialEq, Eq)]
#[reflect(Component, Default, Debug, Clone, PartialEq)]
pub struct SkipFrames(pub bool);
