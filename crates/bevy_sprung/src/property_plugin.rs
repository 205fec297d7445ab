//! [`SpringPropertyPlugin`]: one property, with the mechanism that steps it and what every
//! feature built on springs needs of it.

use core::marker::PhantomData;

use bevy::prelude::*;

use crate::property::SpringProperty;
use crate::spring::{PropertyStepPlugin, is_registered};

/// Adds everything for one [`SpringProperty`]: springing a field of your own component takes a
/// [`spring_property!`](crate::spring_property) and this plugin. It adds the mechanism that
/// steps the property's springs ([`PropertyStepPlugin<P>`]) and what the features built on
/// springs need of the property: [`SpringSequence<P>`](crate::choreography::SpringSequence),
/// groups, and with their cargo features `InteractionTargets<P>` and spring presets. Their
/// systems join [`SpringUpdate`](crate::spring::SpringUpdate), in
/// [`PropertySystems<P>`](crate::spring::PropertySystems), when their first component is added
/// (until then the property costs nothing a frame).
///
/// In an app without [`SpringPlugin`](crate::SpringPlugin) it adds what springs need to step,
/// with the defaults; add `SpringPlugin` first to configure them. Adding a property twice (say,
/// once by a library and once by the app) is harmless.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
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
///     SpringPlugin::default(),
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
        app.add_plugins(PropertyStepPlugin::<P>::default());
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
