//! [`SpringPlugins`]: every domain's plugin, configured in one place.

use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::ScheduleLabel;
use bevy::prelude::*;

use bevy::app::PluginGroupBuilder;

use crate::chain::SpringChainPlugin;
use crate::choreography::SpringChoreographyPlugin;
use crate::clock::{SpringClock, SpringClockPlugin};
use crate::follow::SpringFollowPlugin;
use crate::inertia::SpringInertiaPlugin;
use crate::juice::SpringJuicePlugin;
use crate::presence::SpringPresencePlugin;
use crate::property_plugin::SpringTransformPlugin;
use crate::reduced_motion::SpringReducedMotionPlugin;
use crate::spin::SpringSpinPlugin;
use crate::spring::SpringSchedulePlugin;

/// Everything, as a plugin group (like Bevy's `DefaultPlugins`): springs for `Transform`s, whole
/// turns ([`Spin`](crate::spin::Spin)), followers, choreography, presence, juice, chains, inertia,
/// and with their cargo features colours, UI geometry and layout, pointer interaction, assets,
/// cameras and catch-up for hidden springs. Each domain is one plugin of the group, named
/// `Spring<Domain>Plugin`; a domain's systems join the frame only once its first component
/// appears, so what a scene does not use costs nothing a frame, and
/// `SpringPlugins::default().build().disable::<…>()` leaves a domain out altogether. Add
/// [`SpringPropertyPlugin`](crate::SpringPropertyPlugin) for a field of your own.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::chain::SpringChainPlugin;
/// use bevy_sprung::juice::SpringJuicePlugin;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::clock::SpringClock;
///
/// App::new()
///     .add_plugins((MinimalPlugins, SpringPlugins::default()))
///     .add_systems(Startup, |mut commands: Commands| {
///         commands.spawn((
///             Transform::default(),
///             TranslationSpring::new(Spring::bouncy(), Vec3::new(0.0, 200.0, 0.0)),
///         ));
///     })
///     .update();
///
/// // Deterministic: step in FixedUpdate; or keep UI springing while the game is paused.
/// let fixed = SpringPlugins::default().in_schedule(FixedUpdate);
/// let ui = SpringPlugins::default().with_clock(SpringClock::Real);
/// // Without chains or juice.
/// let lean = SpringPlugins::default()
///     .build()
///     .disable::<SpringChainPlugin>()
///     .disable::<SpringJuicePlugin>();
/// # let _ = (fixed, ui, lean);
/// ```
///
/// # Using every core
/// Springs step in parallel: Bevy's compute task pool's threads and the thread that runs the
/// springs' schedule (the main thread, which starts at once while the others wake; the pool's
/// threads have nothing else to run then) each claim a part of a table's springs at a time,
/// the parts shrinking as the springs run out, so that the threads finish together. Bevy gives
/// the compute pool the cores left after one thread each for I/O and async tasks: on a
/// machine with two cores one thread, so the springs step on both cores with
/// Bevy's defaults. On more cores, ask for a compute thread per core (the I/O and async threads
/// mostly sleep) to step them on all of them. On two cores this helps frames where many
/// `Transform`s move, as Bevy's transform propagation runs on the compute pool alone: whole
/// frames where most `Transform`s move gain from it (with the setting in the next section; the
/// performance log has the figures).
/// ```
/// use bevy::app::{TaskPoolOptions, TaskPoolPlugin, TaskPoolThreadAssignmentPolicy};
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// let cores = std::thread::available_parallelism().map_or(1, |cores| cores.get());
/// let task_pools = TaskPoolPlugin {
///     task_pool_options: TaskPoolOptions {
///         compute: TaskPoolThreadAssignmentPolicy {
///             min_threads: cores,
///             ..TaskPoolOptions::default().compute
///         },
///         ..default()
///     },
/// };
/// App::new()
///     // `DefaultPlugins.set(task_pools)` in a game.
///     .add_plugins((MinimalPlugins.set(task_pools), SpringPlugins::default()))
///     .update();
/// ```
/// Each spring steps independently (the same result on any number of threads), so moving
/// springs step faster with each core until memory bandwidth, not arithmetic, bounds the step
/// (a spring and its `Transform` are read and written every frame).
///
/// # Scenes where most `Transform`s move
/// Bevy's transform propagation first marks which hierarchies changed, so that a scene that
/// mostly stands still propagates little ([`StaticTransformOptimizations`], on by default).
/// When most `Transform`s move every frame, as in a field of a million springs, that marking
/// is all cost, and it can outweigh the springs themselves. Turn it off for such a scene and the
/// whole frame costs what the springs and the propagation need (the performance log compares it
/// with a hand-written Euler spring's frame):
/// ```
/// use bevy::prelude::*;
/// use bevy::transform::StaticTransformOptimizations;
/// use bevy_sprung::prelude::*;
///
/// App::new()
///     .add_plugins((MinimalPlugins, TransformPlugin, SpringPlugins::default()))
///     .insert_resource(StaticTransformOptimizations::Disabled)
///     .update();
/// ```
/// Keep the default when most of the scene is still: springs that have settled do not touch
/// their `Transform`, so a still scene with a few springs moving gains from the marking.
///
/// [`StaticTransformOptimizations`]: bevy::transform::StaticTransformOptimizations
#[derive(Debug, Clone)]
pub struct SpringPlugins {
    /// The schedule the springs step in: `PostUpdate` by default, `FixedUpdate` for
    /// determinism with a fixed-timestep simulation.
    pub schedule: Interned<dyn ScheduleLabel>,
    /// The clock of springs that do not choose one: [`SpringClock::Game`] by default (see
    /// [`DefaultSpringClock`](crate::clock::DefaultSpringClock)).
    pub clock: SpringClock,
}

impl Default for SpringPlugins {
    fn default() -> Self {
        Self {
            schedule: PostUpdate.intern(),
            clock: SpringClock::Game,
        }
    }
}

impl SpringPlugins {
    /// The same plugins stepping springs in `schedule`.
    #[must_use]
    pub fn in_schedule(mut self, schedule: impl ScheduleLabel) -> Self {
        self.schedule = schedule.intern();
        self
    }

    /// The same plugins with `clock` as the default clock.
    #[must_use]
    pub fn with_clock(mut self, clock: SpringClock) -> Self {
        self.clock = clock;
        self
    }
}

impl PluginGroup for SpringPlugins {
    fn build(self) -> PluginGroupBuilder {
        let group = PluginGroupBuilder::start::<Self>()
            .add(SpringClockPlugin {
                default: self.clock,
            })
            .add(SpringSchedulePlugin {
                schedule: self.schedule,
            })
            .add(SpringTransformPlugin)
            .add(SpringSpinPlugin)
            .add(SpringFollowPlugin)
            .add(SpringReducedMotionPlugin)
            .add(SpringChoreographyPlugin)
            .add(SpringJuicePlugin)
            .add(SpringPresencePlugin)
            .add(SpringChainPlugin)
            .add(SpringInertiaPlugin);
        #[cfg(feature = "color")]
        let group = group.add(crate::property_plugin::SpringColorPlugin);
        #[cfg(feature = "ui")]
        let group = group.add(crate::property_plugin::SpringUiPlugin);
        #[cfg(feature = "visibility")]
        let group = group.add(crate::visibility::SpringCatchUpPlugin);
        #[cfg(feature = "asset")]
        let group = group.add(crate::asset::SpringAssetPlugin);
        #[cfg(feature = "picking")]
        let group = group.add(crate::interaction::SpringInteractionPlugin);
        #[cfg(feature = "camera")]
        let group = group.add(crate::camera::SpringCameraPlugin);
        #[cfg(feature = "animation")]
        let group = group.add(crate::inertialization::SpringInertializationPlugin);
        group
    }
}
