//! Where springs step: the set in the outer schedule, the schedule of the spring systems, and
//! the sets of each property and its phases, which features join.

use core::fmt;
use core::hash::{Hash, Hasher};
use core::marker::PhantomData;

use bevy::ecs::schedule::{ScheduleLabel, SystemSet};

use crate::property::SpringProperty;

/// Where the springs step, in the schedule they step in: the one system that runs
/// [`SpringUpdate`]. In `PostUpdate` (the default schedule) the set runs in
/// [`AnimationSystems`](bevy::app::AnimationSystems) and before
/// [`TransformSystems::Propagate`](bevy::transform::TransformSystems::Propagate), so
/// `GlobalTransform` (and `bevy_ui`'s layout, which runs after `AnimationSystems`) see this
/// frame's sprung values.
/// Order your systems against it: write targets before it, read sprung values after it.
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct SpringSystems;

/// The schedule of the spring systems, run from [`SpringSystems`] once per run of the schedule
/// the springs step in (`PostUpdate`, or the one
/// [`SpringPlugins::in_schedule`](crate::SpringPlugins::in_schedule) names).
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
/// handing each to a task cost more than the systems of a scene at rest (several times what a
/// frame of sleeping springs costs on this one). Systems of
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
/// app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(
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
///
/// Inside it a property's frame runs in [`SpringPhase`]s, in their order: join one with
/// [`PropertySystems::phase`] (a system that retargets springs from input runs in
/// [`SpringPhase::Input`], before they step).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::spring::{PropertySystems, SpringPhase, SpringUpdate};
/// use bevy_sprung::transform::Scale;
///
/// #[derive(Resource)]
/// struct Growing(bool);
///
/// // Grows every scale spring's target while growing, before the springs step.
/// fn grow(growing: Res<Growing>, mut springs: Query<&mut ScaleSpring>) {
///     if growing.0 {
///         for mut spring in &mut springs {
///             let target = spring.target() * 1.01;
///             spring.set_target(target);
///         }
///     }
/// }
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugins::default()))
///     .insert_resource(Growing(true))
///     .add_systems(SpringUpdate, grow.in_set(PropertySystems::<Scale>::phase(SpringPhase::Input)));
/// app.update();
/// ```
#[derive(SystemSet)]
pub struct PropertySystems<P: SpringProperty> {
    /// One phase of the property's frame, or all of them.
    phase: Option<SpringPhase>,
    property: PhantomData<fn() -> P>,
}

/// The phases of a property's frame inside its [`PropertySystems`], in this order. The plugin's
/// own systems run in [`Step`](Self::Step); features built on springs join the others.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SpringPhase {
    /// Spring parameters and tolerances are set (presets loaded from assets).
    Configure,
    /// Targets follow input (pointer states, drags).
    Input,
    /// Targets follow time and settling (sequences), after input, which may interrupt them.
    Choreograph,
    /// Sleeping springs that have something to do wake, awake ones step, and those that come
    /// to rest go to sleep (triggering [`SpringSettled`](super::SpringSettled)).
    Step,
    /// The frame's motion is seen (which springs still move).
    Observe,
}

impl SpringPhase {
    /// Every phase, in order.
    pub const ALL: [Self; 5] = [
        Self::Configure,
        Self::Input,
        Self::Choreograph,
        Self::Step,
        Self::Observe,
    ];
}

impl<P: SpringProperty> PropertySystems<P> {
    /// The set of one phase of property `P`'s frame.
    #[must_use]
    pub fn phase(phase: SpringPhase) -> Self {
        Self {
            phase: Some(phase),
            property: PhantomData,
        }
    }
}

impl<P: SpringProperty> Default for PropertySystems<P> {
    /// The set of every system of property `P`.
    fn default() -> Self {
        Self {
            phase: None,
            property: PhantomData,
        }
    }
}

impl<P: SpringProperty> Clone for PropertySystems<P> {
    fn clone(&self) -> Self {
        Self {
            phase: self.phase,
            property: PhantomData,
        }
    }
}

impl<P: SpringProperty> fmt::Debug for PropertySystems<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.phase {
            Some(phase) => write!(f, "PropertySystems<{}>::{phase:?}", P::short_type_path()),
            None => write!(f, "PropertySystems<{}>", P::short_type_path()),
        }
    }
}

impl<P: SpringProperty> PartialEq for PropertySystems<P> {
    fn eq(&self, other: &Self) -> bool {
        self.phase == other.phase
    }
}

impl<P: SpringProperty> Eq for PropertySystems<P> {}

impl<P: SpringProperty> Hash for PropertySystems<P> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.phase.hash(state);
    }
}
