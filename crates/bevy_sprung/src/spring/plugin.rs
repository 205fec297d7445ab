//! The system set, the schedule the springs step in, and the plugin that adds one property.

use core::any::TypeId;
use core::marker::PhantomData;

use bevy::app::AnimationSystems;
use bevy::ecs::component::ComponentId;
use bevy::ecs::entity_disabling::DefaultQueryFilters;
use bevy::ecs::intern::Interned;
use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::schedule::{ScheduleLabel, Schedules, SingleThreadedExecutor, SystemSet};
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;
use bevy::transform::TransformSystems;

use super::component::{PropertySpring, SpringAsleep, SpringMotion};
use super::systems::{step_springs, wake_springs};
use crate::choreography::{SpringGroup, SpringSequence, drive_sequences, note_awake};
use crate::clock::SpringClockPlugin;
use crate::property::SpringProperty;

/// Where the springs step, in the schedule they step in: the one system that runs
/// [`SpringUpdate`]. In `PostUpdate` (the default schedule) the set runs in
/// [`AnimationSystems`] and before [`TransformSystems::Propagate`], so `GlobalTransform` (and
/// `bevy_ui`'s layout, which runs after `AnimationSystems`) see this frame's sprung values.
/// Order your systems against it: write targets before it, read sprung values after it.
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct SpringSystems;

/// The schedule of the spring systems, run from [`SpringSystems`] once per run of the schedule
/// the springs step in (`PostUpdate`, or the one
/// [`SpringPlugin::in_schedule`](crate::SpringPlugin::in_schedule) names).
///
/// What a scene does not spring costs nothing: the systems of a property join this schedule
/// when the first spring on that property is added, and the system that runs the schedule joins
/// with the first spring on any property. An app with the plugin and no springs runs none of
/// its systems (nor those of choreography, juice or interaction before their first component). Order systems of your own between properties here, against [`PropertySystems`].
///
/// The runner is an exclusive system, as Bevy's fixed-timestep loop is: no other system of the
/// outer schedule runs beside it while the springs step (they step on the compute pool's
/// threads themselves). The schedule runs on Bevy's single-threaded executor: its systems run
/// one after another in any case (properties in order, each property's systems chained), and
/// handing each to a task cost more than the systems of a scene at rest (a frame of 100 000
/// sleeping springs took 40 µs on the multi-threaded executor, 12 µs on this one). Systems of
/// your own added here run on the calling thread too; `par_iter` still uses the compute pool.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::spring::{PropertySystems, SpringUpdate};
/// use bevy_sprung::transform::{Rotation, Translation};
///
/// // Runs after the translation springs moved and before the rotation springs step.
/// fn aim(mut aimed: Query<(&Transform, &mut RotationSpring)>) {
///     for (transform, mut rotation) in &mut aimed {
///         let heading = Quat::from_rotation_z(transform.translation.y.atan2(transform.translation.x));
///         rotation.set_target_if_neq(heading);
///     }
/// }
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugin::default())).add_systems(
///     SpringUpdate,
///     aim.after(PropertySystems::<Translation>::default())
///         .before(PropertySystems::<Rotation>::default()),
/// );
/// app.world_mut().spawn((
///     Transform::default(),
///     TranslationSpring::new(Spring::snappy(), Vec3::new(100.0, 50.0, 0.0)),
///     RotationSpring::new(Spring::snappy(), Quat::IDENTITY),
/// ));
/// app.update();
/// ```
#[derive(ScheduleLabel, Debug, Clone, PartialEq, Eq, Hash)]
pub struct SpringUpdate;

/// The systems of property `P`: in [`SpringUpdate`], after the set of the property registered
/// before it, so that properties of one component (translation, rotation and scale of a
/// `Transform`) never run in an ambiguous order. Order against it, in [`SpringUpdate`], to run
/// between two properties (a follower retargets its translation spring before
/// `PropertySystems<Translation>`).
#[derive(SystemSet)]
pub struct PropertySystems<P: SpringProperty>(PhantomData<fn() -> P>);

impl<P: SpringProperty> Default for PropertySystems<P> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P: SpringProperty> Clone for PropertySystems<P> {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl<P: SpringProperty> core::fmt::Debug for PropertySystems<P> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "PropertySystems<{}>", P::short_type_path())
    }
}

impl<P: SpringProperty> PartialEq for PropertySystems<P> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<P: SpringProperty> Eq for PropertySystems<P> {}

impl<P: SpringProperty> core::hash::Hash for PropertySystems<P> {
    fn hash<H: core::hash::Hasher>(&self, _: &mut H) {}
}

/// Where the springs step, the order their properties were added in, and the systems that wait
/// for their first use: build-time bookkeeping of the plugins, not a setting.
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
    /// Systems that wait for the first component of any of their types.
    waiting: Vec<(Vec<TypeId>, Interned<dyn ScheduleLabel>, AddSystems)>,
    /// Systems whose component has been added, to add to their schedule: at once, or, if that
    /// schedule is running then, from [`install_ready_systems`] run before its next run.
    ready: Vec<(Interned<dyn ScheduleLabel>, AddSystems)>,
    /// The component types that have been added (a spring's: `PropertySpring<P>`).
    in_use: Vec<TypeId>,
    /// The schedule [`install_ready_systems`] was put in as a system, if it was needed.
    installer: Option<Interned<dyn ScheduleLabel>>,
}

impl SpringSchedule {
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
fn any_spring() -> TypeId {
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
        .get_resource::<SpringSchedule>()
        .is_none_or(|bookkeeping| bookkeeping.in_use.contains(&used));
    if !in_use
        && let Some(mut bookkeeping) = world.get_resource_mut::<SpringSchedule>()
        && bookkeeping.use_type(used)
    {
        world.commands().queue(install_ready_systems);
    }
}

/// The hook of a spring component (of type `spring`) being added: the first one brings in its
/// property's systems (and the first on any property the runner of [`SpringUpdate`]).
pub(crate) fn spring_added(world: &mut DeferredWorld, spring: TypeId) {
    component_used(world, spring);
    component_used(world, any_spring());
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
    spring_schedule(app);
    let present = already_added(app.world(), types);
    let mut bookkeeping = app.world_mut().resource_mut::<SpringSchedule>();
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
            .resource_mut::<SpringSchedule>()
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
fn install_ready_systems(world: &mut World) {
    let Some(mut bookkeeping) = world.get_resource_mut::<SpringSchedule>() else {
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
    let mut bookkeeping = world.resource_mut::<SpringSchedule>();
    bookkeeping.ready = later;
    if bookkeeping.installer.is_none() {
        bookkeeping.installer = Some(installer);
        world.resource_mut::<Schedules>().add_systems(
            installer,
            install_ready_systems
                .run_if(|bookkeeping: Res<SpringSchedule>| !bookkeeping.ready.is_empty()),
        );
    }
}

/// Runs [`SpringUpdate`], first adding the systems of properties whose first spring was added
/// while it ran.
fn run_spring_update(world: &mut World) {
    if !world.resource::<SpringSchedule>().ready.is_empty() {
        install_ready_systems(world);
    }
    world.run_schedule(SpringUpdate);
}

/// Puts [`SpringSystems`] into the schedule the springs step in (part of
/// [`SpringPlugin`](crate::SpringPlugin)): in `PostUpdate`, inside [`AnimationSystems`] and
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
                    "bevy_sprung: springs already step in {:?}; add SpringPlugin before any \
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
            waiting: Vec::new(),
            ready: Vec::new(),
            in_use: Vec::new(),
            installer: None,
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

/// The schedule the springs step in. An app without [`SpringPlugin`](crate::SpringPlugin) gets
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

/// Adds the systems for one [`SpringProperty`]: springing a field of your own component takes
/// a [`spring_property!`](crate::spring_property) and this plugin. The systems join
/// [`SpringUpdate`], in [`PropertySystems<P>`](PropertySystems), when the first spring on the
/// property is added (until then the property costs nothing a frame). In an app without
/// [`SpringPlugin`](crate::SpringPlugin) it adds what springs need to step, with the defaults;
/// add `SpringPlugin` first to configure them. Adding a property twice (say, once by a library
/// and once by the app) is harmless.
pub struct SpringPropertyPlugin<P: SpringProperty>(PhantomData<fn() -> P>);

impl<P: SpringProperty> Default for SpringPropertyPlugin<P> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P: SpringProperty> Plugin for SpringPropertyPlugin<P> {
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
            .register_type::<SpringAsleep<P>>()
            .register_type::<SpringSequence<P>>();
        #[cfg(feature = "picking")]
        app.register_type::<crate::interaction::InteractionTargets<P>>();
        add_property_systems(
            app,
            &[TypeId::of::<PropertySpring<P>>()],
            add_systems_of::<P>,
        );
        // A sequence drives the property's springs, before they step; with its first sequence.
        add_systems_on_first_use(
            app,
            &[TypeId::of::<SpringSequence<P>>()],
            SpringUpdate,
            |schedule| {
                schedule.add_systems(
                    drive_sequences::<P, PropertySpring<P>, SpringAsleep<P>>
                        .before(wake_springs::<P>)
                        .in_set(PropertySystems::<P>::default())
                        .run_if(any_with_component::<SpringSequence<P>>),
                );
            },
        );
        if let Some(previous) = previous {
            app.configure_sets(
                SpringUpdate,
                PropertySystems::<P>::default().after(previous),
            );
        }
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

/// The systems of property `P`, added with its first spring.
fn add_systems_of<P: SpringProperty>(schedule: &mut Schedule) {
    schedule.add_systems(
        (
            (wake_springs::<P>, step_springs::<P>)
                .chain()
                .run_if(any_with_component::<PropertySpring<P>>),
            note_awake::<PropertySpring<P>, SpringAsleep<P>>
                .run_if(any_with_component::<SpringGroup>),
        )
            .chain()
            .in_set(PropertySystems::<P>::default()),
    );
    // Pointer states retarget every property's springs, before sequences drive them.
    #[cfg(feature = "picking")]
    schedule.add_systems(
        crate::interaction::retarget_on_interaction::<P, PropertySpring<P>>
            .before(drive_sequences::<P, PropertySpring<P>, SpringAsleep<P>>)
            .before(wake_springs::<P>)
            .in_set(PropertySystems::<P>::default())
            .run_if(any_with_component::<crate::interaction::InteractionTargets<P>>),
    );
    // Presets from files reach every property's springs, before pointer states, sequences or
    // the step use them.
    #[cfg(feature = "asset")]
    {
        let presets = crate::asset::apply_presets::<P, PropertySpring<P>>
            .before(drive_sequences::<P, PropertySpring<P>, SpringAsleep<P>>)
            .before(wake_springs::<P>);
        #[cfg(feature = "picking")]
        let presets =
            presets.before(crate::interaction::retarget_on_interaction::<P, PropertySpring<P>>);
        schedule.add_systems(
            presets.in_set(PropertySystems::<P>::default()).run_if(
                resource_exists::<Assets<crate::asset::SpringPreset>>
                    .and_then(any_with_component::<crate::asset::UseSpringPreset>),
            ),
        );
    }
}

impl<P: SpringProperty> core::fmt::Debug for SpringPropertyPlugin<P> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "SpringPropertyPlugin<{}>", P::short_type_path())
    }
}
