//! The sleep marker of a spring at rest.

use core::fmt;
use core::marker::PhantomData;

use bevy::prelude::*;

use crate::property::SpringProperty;

/// Present while the spring on property `P` of this entity rests; the plugin adds and removes
/// it. Resting springs are not iterated, so a scene of sleeping springs costs almost nothing;
/// one whose target changes, that is kicked, or whose property something else writes, wakes.
/// Removed (by the plugin, or by hand, as from an entity disabled meanwhile), it marks the
/// spring's configuration changed: what changed while the spring was not stepped is taken up.
#[derive(Component, Reflect)]
#[reflect(Component, Default, Debug)]
pub struct SpringAsleep<P: SpringProperty>(#[reflect(ignore)] PhantomData<fn() -> P>);

impl<P: SpringProperty> Default for SpringAsleep<P> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P: SpringProperty> Clone for SpringAsleep<P> {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl<P: SpringProperty> fmt::Debug for SpringAsleep<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "SpringAsleep<{}>", P::short_type_path())
    }
}
