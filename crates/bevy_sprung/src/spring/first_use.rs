//! What a scene does not use costs nothing: systems that wait for the first component of their
//! kind (a spring on a property, a group, a shake) and join their schedule only then. Component
//! hooks tell this bookkeeping; plugins put their systems in it.

use core::any::TypeId;

use bevy::ecs::intern::Interned;
use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::schedule::{ScheduleLabel, Schedules};
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;

use super::schedule::{SpringSystems, SpringUpdate};

/// The systems that wait for their first component, and the component types that have come:
/// build-time bookkeeping of the plugins, not a setting.
#[derive(Resource, Default)]
pub(crate) struct FirstUse {
    /// Systems that wait for the first component of any of their types.
    waiting: Vec<(Vec<TypeId>, Interned<dyn ScheduleLabel>, AddSystems)>,
    /// Systems whose component has been added, to add to their schedule: at once, or, if that
    /// schedule is running then, from [`install_ready_systems`] run before its next run.
    ready: Vec<(Interned<dyn ScheduleLabel>, AddSystems)>,
    /// The component types that have been added (a spring's: `PropertySpring<P>`).
    in_use: Vec<TypeId>,
    /// The schedule [`install_ready_systems`] was put in as a system, if it was needed.
    installer: Option<Interned<dyn ScheduleLabel>>,
    /// The spring component types whose property was added (`PropertySpring<P>` of each
    /// registered `P`).
    properties: Vec<TypeId>,
    /// Those not added that a spring was told about (once each).
    told: Vec<TypeId>,
}

impl FirstUse {
    /// Whether systems wait to be added to a schedule that was running when they became ready.
    pub(super) fn has_ready(&self) -> bool {
        !self.ready.is_empty()
    }

    /// Component type `used` has been added: the systems waiting for it are ready. Whether any
    /// are.
    fn use_type(&mut self, used: TypeId) -> bool {
        if self.in_use.contains(&used) {
            return false;
        }
        self.in_use.push(used);
        let (now, later): (Vec<_>, _) = core::mem::take(&mut self.waiting)
            .into_iter()
            .partition(|(types, _, _)| types.contains(&used));
        self.waiting = later;
        self.ready.extend(
            now.iter()
                .map(|&(_, schedule, systems)| (schedule, systems)),
        );
        !now.is_empty()
    }
}

/// Adds systems to a schedule.
pub(crate) type AddSystems = fn(&mut Schedule);

/// What stands for "a spring on any property" among the component types systems wait for: the
/// trigger of the runner of [`SpringUpdate`].
pub(crate) fn any_spring() -> TypeId {
    TypeId::of::<SpringSystems>()
}

/// The hook of a component whose first addition brings in systems (see
/// [`add_systems_on_first_use`]): one lookup in a short list for each one added.
pub(crate) fn first_use<C: Component>(mut world: DeferredWorld, _: HookContext) {
    component_used(&mut world, TypeId::of::<C>());
}

/// Component type `used` was added: if that brings systems in, they are added when the world
/// next applies its commands (at once when spawned outside a schedule).
fn component_used(world: &mut DeferredWorld, used: TypeId) {
    let in_use = world
        .get_resource::<FirstUse>()
        .is_none_or(|bookkeeping| bookkeeping.in_use.contains(&used));
    if !in_use
        && let Some(mut bookkeeping) = world.get_resource_mut::<FirstUse>()
        && bookkeeping.use_type(used)
    {
        world.commands().queue(install_ready_systems);
    }
}

/// The hook of a spring component (of type `spring`, on `entity`, for the property named
/// `property`) being added: the first one brings in its property's systems (and the first on
/// any property the runner of [`SpringUpdate`]). A spring on a property no plugin added is told
/// once: nothing would ever step it.
pub(crate) fn spring_added(
    world: &mut DeferredWorld,
    spring: TypeId,
    (entity, property): (Entity, &'static str),
) {
    component_used(world, spring);
    component_used(world, any_spring());
    if let Some(mut bookkeeping) = world.get_resource_mut::<FirstUse>()
        && !bookkeeping.properties.contains(&spring)
        && !bookkeeping.told.contains(&spring)
    {
        bookkeeping.told.push(spring);
        warn!(
            "bevy_sprung: {entity} has a spring on {property}, a property no plugin added: it \
             will not move. Add `SpringPropertyPlugin::<{property}>::default()` to the app"
        );
    }
}

/// The spring component `spring` (a `PropertySpring<P>`) has its property's systems.
pub(crate) fn property_added(app: &mut App, spring: TypeId) {
    let mut bookkeeping = app.world_mut().get_resource_or_init::<FirstUse>();
    if !bookkeeping.properties.contains(&spring) {
        bookkeeping.properties.push(spring);
    }
}

/// Runs `systems` on `schedule` once a component of any of `types` (component types) exists:
/// until then they are not in any schedule, and cost nothing a frame. Components added before
/// the plugin that calls this (whose hooks found no bookkeeping to tell) count: the systems
/// are added at once. Whether there were any.
pub(crate) fn add_systems_on_first_use(
    app: &mut App,
    types: &[TypeId],
    schedule: impl ScheduleLabel,
    systems: AddSystems,
) -> bool {
    let schedule = schedule.intern();
    let present = already_added(app.world(), types);
    let mut bookkeeping = app.world_mut().get_resource_or_init::<FirstUse>();
    if types.iter().any(|used| bookkeeping.in_use.contains(used)) {
        bookkeeping.ready.push((schedule, systems));
    } else {
        bookkeeping
            .waiting
            .push((types.to_vec(), schedule, systems));
        for &used in &present {
            bookkeeping.use_type(used);
        }
    }
    install_ready_systems(app.world_mut());
    !present.is_empty()
}

/// Runs `systems` on [`SpringUpdate`] once a spring component of any of `springs` (the types
/// of `PropertySpring<P>`s) exists. Springs added before the plugin bring in the runner of
/// [`SpringUpdate`] too.
pub(crate) fn add_property_systems(app: &mut App, springs: &[TypeId], systems: AddSystems) {
    if add_systems_on_first_use(app, springs, SpringUpdate, systems) {
        app.world_mut()
            .resource_mut::<FirstUse>()
            .use_type(any_spring());
        install_ready_systems(app.world_mut());
    }
}

/// Those of component `types` that some entity already has.
fn already_added(world: &World, types: &[TypeId]) -> Vec<TypeId> {
    types
        .iter()
        .copied()
        .filter(|&used| {
            world.components().get_id(used).is_some_and(|component| {
                world
                    .archetypes()
                    .iter()
                    .any(|archetype| !archetype.is_empty() && archetype.contains(component))
            })
        })
        .collect()
}

/// Adds the systems that are ready to their schedules. A schedule that is running (the first
/// component was added by one of its own systems or observers) cannot be changed until it
/// ends: its systems wait, and this function is put in `First` as a system (`Last` if `First`
/// is the one running) to add them before it runs again.
pub(super) fn install_ready_systems(world: &mut World) {
    let Some(mut bookkeeping) = world.get_resource_mut::<FirstUse>() else {
        return;
    };
    let ready = core::mem::take(&mut bookkeeping.ready);
    if ready.is_empty() {
        return;
    }
    let mut schedules = world.get_resource_or_init::<Schedules>();
    let running = schedules.get_temporarily_removed();
    let (now, later): (Vec<_>, Vec<_>) = ready
        .into_iter()
        .partition(|(schedule, _)| !running.contains(schedule));
    for (schedule, systems) in now {
        systems(schedules.entry(schedule));
    }
    if later.is_empty() {
        return;
    }
    let installer = if running.contains(&First.intern()) {
        Last.intern()
    } else {
        First.intern()
    };
    let mut bookkeeping = world.resource_mut::<FirstUse>();
    bookkeeping.ready = later;
    if bookkeeping.installer.is_none() {
        bookkeeping.installer = Some(installer);
        world.resource_mut::<Schedules>().add_systems(
            installer,
            install_ready_systems
                .run_if(|bookkeeping: Res<FirstUse>| !bookkeeping.ready.is_empty()),
        );
    }
}
