//! The mechanism's plugins: the schedule the springs step in, and the systems that step one
//! property.

use core::any::TypeId;
use core::marker::PhantomData;

use bevy::app::AnimationSystems;
use bevy::ecs::component::ComponentId;
use bevy::ecs::entity_disabling::DefaultQueryFilters;
use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::{ScheduleLabel, SingleThreadedExecutor, SystemSet};
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;
use bevy::transform::TransformSystems;

use super::component::{PropertySpring, SpringAsleep, SpringMotion};
use super::first_use::{FirstUse, install_ready_systems};
use super::first_use::{
    add_property_systems, add_systems_on_first_use, any_spring, property_added,
};
use super::misconfigured::warn_missing;
use super::schedule::{PropertySystems, SpringPhase, SpringSystems, SpringUpdate};
use super::systems::{step_springs, wake_springs};
use crate::clock::SpringClockPlugin;
use crate::property::SpringProperty;

/// Puts [`SpringSystems`] into the schedule the springs step in (part of
/// [`SpringPlugins`](crate::SpringPlugins)): in `PostUpdate`, inside [`AnimationSystems`] and
/// before transform propagation; in any other schedule, as a plain set. The set holds the
/// system that runs [`SpringUpdate`].
#[derive(Debug, Clone)]
pub struct SpringSchedulePlugin {
    /// The schedule: `PostUpdate` by default, `FixedUpdate` for determinism with a
    /// fixed-timestep simulation.
    pub schedule: Interned<dyn ScheduleLabel>,
}

impl Default for SpringSchedulePlugin {
    fn default() -> Self {
        Self {
            schedule: PostUpdate.intern(),
        }
    }
}

impl Plugin for SpringSchedulePlugin {
    fn build(&self, app: &mut App) {
        if let Some(existing) = app.world().get_resource::<SpringSchedule>() {
            if existing.label != self.schedule {
                warn!(
                    "bevy_sprung: springs already step in {:?}; add SpringPlugins before any \
                     spring property plugin to step them in {:?}",
                    existing.label, self.schedule
                );
            }
            return;
        }
        app.insert_resource(SpringSchedule {
            label: self.schedule,
            last_property: None,
            registered: Vec::new(),
            returns_observed: Vec::new(),
        });
        // Every system in it runs after the one before (properties in order, each property's
        // systems chained): the single-threaded executor runs them without handing each to a
        // task.
        app.init_schedule(SpringUpdate)
            .edit_schedule(SpringUpdate, |schedule| {
                schedule.set_executor(SingleThreadedExecutor::new());
            });
        // The runner joins with the first spring: an app with no springs runs none of this
        // crate's systems.
        add_systems_on_first_use(app, &[any_spring()], self.schedule, |schedule| {
            schedule.add_systems(run_spring_update.in_set(SpringSystems));
        });
        if self.schedule == PostUpdate.intern() {
            app.configure_sets(
                PostUpdate,
                SpringSystems
                    .in_set(AnimationSystems)
                    .before(TransformSystems::Propagate),
            );
        } else {
            app.configure_sets(self.schedule, SpringSystems);
        }
    }

    /// Adding it again (a property plugin adds it with its defaults) keeps the first.
    fn is_unique(&self) -> bool {
        false
    }
}

/// Where the springs step, and the properties added in order: build-time bookkeeping of the
/// plugins, not a setting.
#[derive(Resource)]
pub(crate) struct SpringSchedule {
    /// The schedule the springs step in.
    pub(crate) label: Interned<dyn ScheduleLabel>,
    /// The set of the last property added, which the next one runs after.
    last_property: Option<Interned<dyn SystemSet>>,
    /// The properties already added (adding one twice is harmless).
    registered: Vec<TypeId>,
    /// The components (and their properties) whose removal [`touch_on_return`] observes.
    returns_observed: Vec<(TypeId, ComponentId)>,
}

/// Runs [`SpringUpdate`], first adding the systems of properties whose first spring was added
/// while it ran.
fn run_spring_update(world: &mut World) {
    if world.resource::<FirstUse>().has_ready() {
        install_ready_systems(world);
    }
    world.run_schedule(SpringUpdate);
}

/// The schedule the springs step in. An app without [`SpringPlugins`](crate::SpringPlugins) gets
/// what springs need to step (the schedule and the clock, with their defaults): every plugin
/// that adds springing systems starts with this.
pub(crate) fn spring_schedule(app: &mut App) -> Interned<dyn ScheduleLabel> {
    if !app.world().contains_resource::<SpringSchedule>() {
        app.add_plugins((
            SpringSchedulePlugin::default(),
            SpringClockPlugin::default(),
        ));
    }
    app.world().resource::<SpringSchedule>().label
}

/// Whether property `P` has been added (by a [`SpringPropertyStepPlugin<P>`]).
pub(crate) fn is_registered<P: SpringProperty>(world: &World) -> bool {
    world
        .get_resource::<SpringSchedule>()
        .is_some_and(|bookkeeping| bookkeeping.registered.contains(&TypeId::of::<P>()))
}

/// Steps the springs of one [`SpringProperty`]: the mechanism alone. Its systems join
/// [`SpringUpdate`] in [`PropertySystems<P>`], in [`SpringPhase::Step`], when the first spring
/// on the property is added (until then the property costs nothing a frame), after the
/// property added before it. [`SpringPropertyPlugin`](crate::SpringPropertyPlugin) adds this
/// and what the features built on springs (sequences, pointer states, presets, groups) need of
/// the property: add that one for a property of your own.
pub struct SpringPropertyStepPlugin<P: SpringProperty>(PhantomData<fn() -> P>);

impl<P: SpringProperty> Default for SpringPropertyStepPlugin<P> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P: SpringProperty> Plugin for SpringPropertyStepPlugin<P> {
    fn build(&self, app: &mut App) {
        spring_schedule(app);
        let mut bookkeeping = app.world_mut().resource_mut::<SpringSchedule>();
        let property = TypeId::of::<P>();
        if bookkeeping.registered.contains(&property) {
            return;
        }
        bookkeeping.registered.push(property);
        let previous = bookkeeping
            .last_property
            .replace(PropertySystems::<P>::default().intern());
        // Here, not only in `finish`: an app updated without being run is not finished.
        observe_returns::<P>(app.world_mut());
        app.register_type::<PropertySpring<P>>()
            .register_type::<SpringMotion<P>>()
            .register_type::<SpringAsleep<P>>();
        let phase = PropertySystems::<P>::phase;
        app.configure_sets(
            SpringUpdate,
            (
                phase(SpringPhase::Configure),
                phase(SpringPhase::Input),
                phase(SpringPhase::Choreograph),
                phase(SpringPhase::Step),
                phase(SpringPhase::Observe),
            )
                .chain()
                .in_set(PropertySystems::<P>::default()),
        );
        if let Some(previous) = previous {
            app.configure_sets(
                SpringUpdate,
                PropertySystems::<P>::default().after(previous),
            );
        }
        let spring = TypeId::of::<PropertySpring<P>>();
        property_added(app, spring);
        add_property_systems(app, &[spring], add_systems_of::<P>);
    }

    /// Marks a spring changed when its entity is enabled again, also for the disabling
    /// components that plugins registered after this one was added (see
    /// [`SpringAsleep`](crate::spring::SpringAsleep), whose removal does the same).
    fn finish(&self, app: &mut App) {
        observe_returns::<P>(app.world_mut());
    }

    fn is_unique(&self) -> bool {
        false
    }
}

impl<P: SpringProperty> core::fmt::Debug for SpringPropertyStepPlugin<P> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "SpringPropertyStepPlugin<{}>", P::short_type_path())
    }
}

/// Observes the removal of the components that take a spring on `P` out of the systems' sight
/// and are not observed yet: [`touch_on_return`].
fn observe_returns<P: SpringProperty>(world: &mut World) {
    let property = TypeId::of::<P>();
    let asleep = world.register_component::<SpringAsleep<P>>();
    let disabling = world
        .get_resource::<DefaultQueryFilters>()
        .map(|filters| filters.disabling_ids().collect::<Vec<_>>())
        .unwrap_or_default();
    let mut bookkeeping = world.resource_mut::<SpringSchedule>();
    let new: Vec<ComponentId> = core::iter::once(asleep)
        .chain(disabling)
        .filter(|&id| !bookkeeping.returns_observed.contains(&(property, id)))
        .collect();
    if new.is_empty() {
        return;
    }
    bookkeeping
        .returns_observed
        .extend(new.iter().map(|&id| (property, id)));
    world.spawn((
        Observer::new(touch_on_return::<P>).with_components(new),
        Name::new(format!("bevy_sprung returns of {}", P::short_type_path())),
    ));
}

/// A spring on `P` back among those the stepping system steps, its entity enabled again (a
/// disabling component, Bevy's `Disabled` or one registered as such before the app finishes
/// its plugins, removed) or its [`SpringAsleep<P>`] removed: its configuration is marked changed.
///
/// The systems run without the springs they do not see, so "changed since the system's last
/// run", which their change ticks tell them, is "changed since the spring's last step" only
/// for springs they saw in that run. Marked, a returning spring is read afresh: a target set
/// meanwhile wakes it or is headed for, a value written meanwhile is sprung on from.
fn touch_on_return<P: SpringProperty>(returning: On<Remove>, mut world: DeferredWorld) {
    if let Some(mut spring) = world.get_mut::<PropertySpring<P>>(returning.entity) {
        spring.set_changed();
    }
}

/// The systems of property `P`, added with its first spring: a spring added without the
/// component it moves is told once; the springs wake and step.
fn add_systems_of<P: SpringProperty>(schedule: &mut Schedule) {
    let missing = warn_missing::<PropertySpring<P>, P::Component>(
        "the spring moves nothing until the entity has that component; spawn the spring with \
         it (the component's default is where the spring starts from)",
    );
    schedule.add_systems(
        (missing, wake_springs::<P>, step_springs::<P>)
            .chain()
            .run_if(any_with_component::<PropertySpring<P>>)
            .in_set(PropertySystems::<P>::phase(SpringPhase::Step)),
    );
}
