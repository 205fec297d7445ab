//! The designer attached to a running game: which springs it can tune, the one it tunes, and
//! saving what was tuned where the game loads it from.

use core::any::TypeId;
use std::path::PathBuf;

use bevy::asset::AssetPath;
use bevy::prelude::*;
use sprung::Spring;

use super::model::SpringDesign;
use crate::asset::{SpringPreset, UsePropertyPreset, UseSpringPreset};
use crate::property::SpringProperty;
use crate::spring::PropertySpring;

/// One spring of the game: an entity and the property it springs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpringRef {
    /// The entity.
    pub entity: Entity,
    /// The property, as [`TypeId`].
    pub property: TypeId,
    /// The property's name.
    pub property_name: &'static str,
}

/// The spring of the game the designer is tuning: every edit is applied to it at once, and
/// [`SaveSpringDesign`] writes to the file it loads its preset from, if it has one. `None`:
/// the designer only previews.
///
/// Pick one with [`TuneSpring`] (the panel's arrows cycle through every spring of the
/// properties the designer tunes).
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TunedSpring(pub Option<SpringRef>);

/// Asks the designer to tune `entity`'s spring on property `P` (or stop tuning, with
/// [`TuneSpring::none`]): its spring becomes the design, and the design's reference (B) the
/// spring as it was, to compare against.
#[derive(Event, Clone, Copy, Debug, PartialEq, Eq)]
pub struct TuneSpring(pub Option<SpringRef>);

impl TuneSpring {
    /// Tune `entity`'s spring on property `P`.
    #[must_use]
    pub fn of<P: SpringProperty>(entity: Entity) -> Self {
        Self(Some(SpringRef {
            entity,
            property: TypeId::of::<P>(),
            property_name: P::short_type_path(),
        }))
    }

    /// Stop tuning a spring of the game.
    #[must_use]
    pub fn none() -> Self {
        Self(None)
    }
}

/// Asks the designer to save the design: to the preset file of the spring it tunes if that
/// has one (which the game then reloads), else to [`SpringDesign::path`] in the asset folder.
/// The outcome is in [`DesignerStatus`].
#[derive(Event, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SaveSpringDesign;

/// What the designer last did or refused, for its status line.
#[derive(Resource, Clone, Debug, Default, PartialEq, Eq)]
pub struct DesignerStatus(pub String);

/// How the designer reaches the springs of one property.
#[derive(Clone, Copy)]
pub(super) struct TunableProperty {
    id: TypeId,
    name: &'static str,
    springs: fn(&mut World) -> Vec<Entity>,
    read: fn(&World, Entity) -> Option<Spring<f32>>,
    write: fn(&mut World, Entity, Spring<f32>),
    preset: fn(&World, Entity) -> Option<AssetPath<'static>>,
}

impl TunableProperty {
    pub(super) fn of<P: SpringProperty>() -> Self {
        Self {
            id: TypeId::of::<P>(),
            name: P::short_type_path(),
            springs: |world| {
                let mut query = world.query_filtered::<Entity, With<PropertySpring<P>>>();
                let mut entities: Vec<Entity> = query.iter(world).collect();
                entities.sort_unstable();
                entities
            },
            read: |world, entity| world.get::<PropertySpring<P>>(entity).map(|s| *s.spring()),
            write: |world, entity, spring| {
                if let Some(mut config) = world.get_mut::<PropertySpring<P>>(entity)
                    && *config.spring() != spring
                {
                    config.set_spring(spring);
                }
            },
            preset: |world, entity| {
                let own = world
                    .get::<UsePropertyPreset<P>>(entity)
                    .map(|preset| &preset.handle);
                let shared = world.get::<UseSpringPreset>(entity).map(|preset| &preset.0);
                own.or(shared)
                    .and_then(Handle::path)
                    .map(AssetPath::clone_owned)
            },
        }
    }
}

/// The properties the designer tunes, and where it saves.
#[derive(Resource, Clone)]
pub(super) struct Tunables {
    pub(super) properties: Vec<TunableProperty>,
    pub(super) assets_folder: PathBuf,
}

impl Tunables {
    fn property(&self, id: TypeId) -> Option<&TunableProperty> {
        self.properties.iter().find(|p| p.id == id)
    }

    /// Every spring the designer can tune, property by property, entity by entity.
    pub(super) fn springs(&self, world: &mut World) -> Vec<SpringRef> {
        let mut all = Vec::new();
        for property in &self.properties {
            all.extend(
                (property.springs)(world)
                    .into_iter()
                    .map(|entity| SpringRef {
                        entity,
                        property: property.id,
                        property_name: property.name,
                    }),
            );
        }
        all
    }
}

/// Hears [`TuneSpring`]; the pick needs the whole world (an observer cannot have it).
pub(super) fn on_tune(event: On<TuneSpring>, mut commands: Commands) {
    commands.run_system_cached_with(tune, event.0);
}

/// Hears [`SaveSpringDesign`].
pub(super) fn on_save(_: On<SaveSpringDesign>, mut commands: Commands) {
    commands.run_system_cached(save);
}

/// Picks the spring to tune: the design takes its spring, and keeps the one it replaces as
/// the reference.
fn tune(In(target): In<Option<SpringRef>>, world: &mut World) {
    let Some(tunables) = world.get_resource::<Tunables>().cloned() else {
        return;
    };
    let picked = target.and_then(|target| {
        let property = tunables.property(target.property)?;
        Some((target, (property.read)(world, target.entity)?))
    });
    world.resource_mut::<TunedSpring>().0 = picked.map(|(target, _)| target);
    if let Some((_, spring)) = picked {
        let mut design = world.resource_mut::<SpringDesign>();
        design.set_spring(spring);
        design.keep_as_reference();
    }
    world.resource_mut::<DesignerStatus>().0.clear();
}

/// Keeps the design and the tuned spring one: an edit of the design goes to the spring, live;
/// a change of the spring from elsewhere (its preset file reloaded, the game's code) comes
/// back to the design.
pub(super) fn sync(world: &mut World) {
    let Some(target) = world.resource::<TunedSpring>().0 else {
        return;
    };
    let Some(property) = world
        .resource::<Tunables>()
        .property(target.property)
        .copied()
    else {
        return;
    };
    let Some(current) = (property.read)(world, target.entity) else {
        world.resource_mut::<TunedSpring>().0 = None;
        world.resource_mut::<DesignerStatus>().0 =
            format!("{} has no spring any more; previewing only", target.entity);
        return;
    };
    let design = world.resource_ref::<SpringDesign>();
    let (edited, spring) = (design.is_changed(), design.spring());
    if spring == current {
        return;
    }
    if edited {
        (property.write)(world, target.entity, spring);
    } else {
        world.resource_mut::<SpringDesign>().set_spring(current);
    }
}

/// Writes the design's `*.spring.ron`, and reloads it so every spring that uses it takes it.
fn save(world: &mut World) {
    let tunables = world.resource::<Tunables>().clone();
    let design = world.resource::<SpringDesign>().clone();
    let preset = world.resource::<TunedSpring>().0.and_then(|target| {
        let property = tunables.property(target.property)?;
        world.get_entity(target.entity).ok()?;
        (property.preset)(world, target.entity)
    });
    let path = preset.unwrap_or_else(|| AssetPath::from(design.path.clone()));
    let file = tunables.assets_folder.join(path.path());
    let written = file
        .parent()
        .map_or(Ok(()), std::fs::create_dir_all)
        .and_then(|()| std::fs::write(&file, design.to_ron()));
    let status = match written {
        Ok(()) => {
            if let Some(server) = world.get_resource::<AssetServer>() {
                // What Bevy's file watcher would do, at once and without it: every
                // `UseSpringPreset` of this file takes the new spring.
                if server.get_handle::<SpringPreset>(&path).is_some() {
                    server.reload(path.clone());
                }
            }
            format!("Saved {}", file.display())
        }
        Err(error) => format!("Could not save {}: {error}", file.display()),
    };
    world.resource_mut::<DesignerStatus>().0 = status;
}
