//! Misconfigurations a new user meets, each told once with its fix: a spring on an entity
//! without the component it moves, a spring whose property was never added, a feature's
//! component without the spring it drives.

use core::fmt::Display;

use bevy::ecs::query::QueryFilter;
use bevy::prelude::*;
use bevy::utils::prelude::ShortName;

/// A system that warns once about the entities that got a `C` (since it last ran) but have no
/// `R`, naming the first such entity, both components and `fix`. Run where the entity's
/// commands have been applied (a later schedule than the one that spawned it), so that a
/// component inserted in a second command is not missed.
pub(crate) fn warn_missing<C: Component, R: Component>(
    fix: &'static str,
) -> impl FnMut(Query<Entity, (Added<C>, Without<R>)>, Local<bool>) {
    warn_lacking::<C, Without<R>>(ShortName::of::<R>(), fix)
}

/// A system that warns once about the entities that got a `C` (since it last ran) and match
/// `F` (what they lack, as filters: `(Without<A>, Without<B>)` for "neither A nor B"), naming
/// the first such entity, `C`, `missing` and `fix`. Run as [`warn_missing`] is.
pub(crate) fn warn_lacking<C: Component, F: QueryFilter + 'static>(
    missing: impl Display + Send + Sync + 'static,
    fix: &'static str,
) -> impl FnMut(Query<Entity, (Added<C>, F)>, Local<bool>) {
    move |lacking, mut warned| {
        if *warned {
            return;
        }
        if let Some(entity) = lacking.iter().next() {
            *warned = true;
            warn!(
                "bevy_sprung: {entity} has a {} but no {missing}: {fix}",
                ShortName::of::<C>(),
            );
        }
    }
}
