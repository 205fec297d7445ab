//! Springs nobody sees: skip frames, then catch up exactly in one step.

use core::any::TypeId;

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;

use crate::spring::{
    SkipFrames, SpringSystems, add_systems_on_first_use, first_use, spring_schedule,
};

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
/// use bevy_sprung::visibility::CatchUpWhenHidden;
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
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Default, Clone, Copy)]
#[reflect(Component, Default, Debug, Clone)]
#[require(SkipFrames)]
#[component(on_add = first_use::<Self>, on_remove = stop_skipping)]
pub struct CatchUpWhenHidden;

/// The hook of a [`CatchUpWhenHidden`] removed: its springs step every frame again (the
/// [`SkipFrames`] it required goes too, and with it any time put aside is caught up).
fn stop_skipping(mut world: DeferredWorld, context: HookContext) {
    world
        .commands()
        .entity(context.entity)
        .try_remove::<SkipFrames>();
}

/// Before the springs step: springs of entities nobody saw last frame skip frames.
/// (`ViewVisibility` tells what the last frame drew: it lags a frame.)
fn skip_unseen_frames(
    mut springs: Query<(&ViewVisibility, &mut SkipFrames), With<CatchUpWhenHidden>>,
) {
    for (visibility, mut skip) in &mut springs {
        skip.set_if_neq(SkipFrames(!visibility.get()));
    }
}

/// [`CatchUpWhenHidden`] (part of [`SpringPlugins`](crate::SpringPlugins) with feature
/// `visibility`): keeps its entity's [`SkipFrames`] equal to "not seen" before the springs
/// step, from the first `CatchUpWhenHidden`.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringCatchUpPlugin;

impl Plugin for SpringCatchUpPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<CatchUpWhenHidden>();
        let schedule = spring_schedule(app);
        let catching_up = [TypeId::of::<CatchUpWhenHidden>()];
        add_systems_on_first_use(app, &catching_up, schedule, |schedule| {
            schedule.add_systems(
                skip_unseen_frames
                    .before(SpringSystems)
                    .run_if(any_with_component::<CatchUpWhenHidden>),
            );
        });
    }
}
