//! Events the springs trigger.

use core::fmt;
use core::marker::PhantomData;

use bevy::prelude::*;

use crate::property::SpringProperty;

/// Triggered once when the spring on property `P` of `entity` comes to rest and goes to sleep:
/// the replacement for a tween's completion event.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// fn spawn(mut commands: Commands) {
///     commands
///         .spawn((Transform::default(), TranslationSpring::new(Spring::snappy(), Vec3::X)))
///         .observe(|settled: On<SpringSettled<Translation>>| {
///             info!("{} arrived", settled.entity);
///         });
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugin::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(EntityEvent)]
pub struct SpringSettled<P: SpringProperty> {
    /// The entity whose spring settled.
    pub entity: Entity,
    property: PhantomData<fn() -> P>,
}

impl<P: SpringProperty> SpringSettled<P> {
    /// The event for `entity`.
    #[must_use]
    pub fn new(entity: Entity) -> Self {
        Self {
            entity,
            property: PhantomData,
        }
    }
}

impl<P: SpringProperty> Clone for SpringSettled<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for SpringSettled<P> {}

/// Triggered when the sleeping spring on property `P` of `entity` wakes: its target changed,
/// it was kicked, or something else wrote its property. The moment a motion starts (a sound, a
/// group that tracks what moves); it may settle again within the same frame.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// fn spawn(mut commands: Commands) {
///     commands
///         .spawn((Transform::default(), TranslationSpring::new(Spring::snappy(), Vec3::X)))
///         .observe(|woke: On<SpringWoke<Translation>>| info!("{} moves again", woke.entity));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugin::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(EntityEvent)]
pub struct SpringWoke<P: SpringProperty> {
    /// The entity whose spring woke.
    pub entity: Entity,
    property: PhantomData<fn() -> P>,
}

impl<P: SpringProperty> SpringWoke<P> {
    /// The event for `entity`.
    #[must_use]
    pub fn new(entity: Entity) -> Self {
        Self {
            entity,
            property: PhantomData,
        }
    }
}

impl<P: SpringProperty> Clone for SpringWoke<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for SpringWoke<P> {}

impl<P: SpringProperty> fmt::Debug for SpringWoke<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SpringWoke")
            .field("property", &P::short_type_path())
            .field("entity", &self.entity)
            .finish()
    }
}

/// Triggers `event` when the commands are applied, if its entity is still alive then: an
/// observer of an earlier event (this frame's settle of another spring, say) may have despawned
/// it meanwhile, and an event for a despawned entity makes ordinary observer code
/// (`commands.entity(event.entity)…`) panic. Every entity event of this crate is triggered this
/// way.
pub(crate) fn trigger_if_alive<E>(commands: &mut Commands, event: E)
where
    E: EntityEvent<Trigger<'static>: Default>,
{
    commands.queue(move |world: &mut World| {
        if world.get_entity(event.event_target()).is_ok() {
            world.trigger(event);
        }
    });
}

impl<P: SpringProperty> fmt::Debug for SpringSettled<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SpringSettled")
            .field("property", &P::short_type_path())
            .field("entity", &self.entity)
            .finish()
    }
}
