//! Events the springs trigger.

use core::marker::PhantomData;

use bevy::prelude::*;

use crate::property::SpringProperty;

/// Implements what an entity event about one property's spring has: `new(entity)`, `Clone`,
/// `Copy` and a `Debug` that names the property. The event is a struct of an `entity: Entity`
/// and a `property: PhantomData<fn() -> P>`.
macro_rules! property_event {
    ($name:ident) => {
        impl<P: $crate::property::SpringProperty> $name<P> {
            /// The event for `entity`.
            #[must_use]
            pub fn new(entity: ::bevy::prelude::Entity) -> Self {
                Self {
                    entity,
                    property: ::core::marker::PhantomData,
                }
            }
        }

        impl<P: $crate::property::SpringProperty> Clone for $name<P> {
            fn clone(&self) -> Self {
                *self
            }
        }

        impl<P: $crate::property::SpringProperty> Copy for $name<P> {}

        impl<P: $crate::property::SpringProperty> ::core::fmt::Debug for $name<P> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                f.debug_struct(stringify!($name))
                    .field("property", &P::short_type_path())
                    .field("entity", &self.entity)
                    .finish()
            }
        }
    };
}

pub(crate) use property_event;

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
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(EntityEvent)]
pub struct SpringSettled<P: SpringProperty> {
    /// The entity whose spring settled.
    pub entity: Entity,
    property: PhantomData<fn() -> P>,
}

/// Triggered when the sleeping spring on property `P` of `entity` wakes: its target changed,
/// it was kicked, or something else wrote its property. The moment a motion starts (a sound, a
/// group that tracks what moves); it may settle again within the same frame.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::spring::SpringWoke;
///
/// fn spawn(mut commands: Commands) {
///     commands
///         .spawn((Transform::default(), TranslationSpring::new(Spring::snappy(), Vec3::X)))
///         .observe(|woke: On<SpringWoke<Translation>>| info!("{} moves again", woke.entity));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(EntityEvent)]
pub struct SpringWoke<P: SpringProperty> {
    /// The entity whose spring woke.
    pub entity: Entity,
    property: PhantomData<fn() -> P>,
}

property_event!(SpringSettled);
property_event!(SpringWoke);

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
