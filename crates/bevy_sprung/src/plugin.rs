//! The plugins and the system set.

use core::marker::PhantomData;

use bevy::app::AnimationSystems;
use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::{ScheduleLabel, SystemSet};
use bevy::prelude::*;
use bevy::transform::TransformSystems;

use crate::component::{PropertySpring, SpringAsleep, SpringClock};
use crate::follow::{
    SpringFollow, TargetMotion, aim_followers, follow_targets, sample_fixed_targets,
};
use crate::property::{Rotation, Scale, SignedScale, SpringProperty, Translation};
use crate::spin::{Spin, SpinAngle, apply_spin};
use crate::systems::{step_springs, wake_springs};

/// All of the plugin's systems. In `PostUpdate` (the default schedule) the set runs in
/// [`AnimationSystems`] and before [`TransformSystems::Propagate`], so `GlobalTransform` (and
/// `bevy_ui`'s layout, which runs after `AnimationSystems`) see this frame's sprung values. Order
/// your systems against it: write targets before it, read sprung values after it.
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct SpringSystems;

/// The systems of one property, ordered after the previously registered property's so that
/// properties on the same component (translation, rotation, scale of a `Transform`) never run
/// in an ambiguous order.
#[derive(SystemSet)]
pub(crate) struct PropertySystems<P: SpringProperty>(PhantomData<fn() -> P>);

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

/// Settings the systems read, inserted by [`SpringPlugin`].
#[derive(Resource, Debug, Clone)]
pub struct SpringSettings {
    /// The clock for springs that do not choose one ([`PropertySpring::with_clock`]).
    pub default_clock: SpringClock,
    schedule: Interned<dyn ScheduleLabel>,
    /// The set of the last registered property, which the next one runs after.
    last_property: Option<Interned<dyn SystemSet>>,
    /// Properties whose systems are already added (adding one twice is harmless).
    registered: Vec<core::any::TypeId>,
}

/// Springs `Transform`s (translation, rotation, scale) toward their targets every frame, and
/// hosts any other [`SpringProperty`] added with [`SpringPropertyPlugin`].
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// App::new()
///     .add_plugins((MinimalPlugins, SpringPlugin::default()))
///     .add_systems(Startup, |mut commands: Commands| {
///         commands.spawn((
///             Transform::default(),
///             TranslationSpring::new(Spring::bouncy(), Vec3::new(0.0, 200.0, 0.0)),
///         ));
///     })
///     .update();
///
/// // Deterministic: step in FixedUpdate; or keep UI springing while the game is paused.
/// let fixed = SpringPlugin::default().in_schedule(FixedUpdate);
/// let ui = SpringPlugin::default().with_clock(SpringClock::Real);
/// # let _ = (fixed, ui);
/// ```
#[derive(Debug, Clone)]
pub struct SpringPlugin {
    /// The schedule the springs step in: `PostUpdate` by default, `FixedUpdate` for
    /// determinism with a fixed-timestep simulation.
    pub schedule: Interned<dyn ScheduleLabel>,
    /// The clock for springs that do not choose one: [`SpringClock::Game`] by default.
    pub clock: SpringClock,
}

impl Default for SpringPlugin {
    fn default() -> Self {
        Self {
            schedule: PostUpdate.intern(),
            clock: SpringClock::Game,
        }
    }
}

impl SpringPlugin {
    /// The same plugin stepping springs in `schedule`.
    #[must_use]
    pub fn in_schedule(mut self, schedule: impl ScheduleLabel) -> Self {
        self.schedule = schedule.intern();
        self
    }

    /// The same plugin with `clock` as the default clock.
    #[must_use]
    pub fn with_clock(mut self, clock: SpringClock) -> Self {
        self.clock = clock;
        self
    }
}

impl Plugin for SpringPlugin {
    fn build(&self, app: &mut App) {
        app.insert_resource(SpringSettings {
            default_clock: self.clock,
            schedule: self.schedule,
            last_property: None,
            registered: Vec::new(),
        })
        .register_type::<SpringClock>();
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
        #[cfg(feature = "visibility")]
        app.register_type::<crate::component::CatchUpWhenHidden>();
        app.add_plugins((
            SpringPropertyPlugin::<Translation>::default(),
            SpringPropertyPlugin::<Rotation>::default(),
            SpringPropertyPlugin::<Scale>::default(),
            SpringPropertyPlugin::<SignedScale>::default(),
            SpringPropertyPlugin::<SpinAngle>::default(),
        ));
        // A spin sets the rotation right after its spring stepped, inside the spin's property
        // set: ordered with every other property that writes a `Transform`.
        let spin_set = PropertySystems::<SpinAngle>::default;
        app.register_type::<Spin>().add_systems(
            self.schedule,
            apply_spin
                .after(step_springs::<SpinAngle>)
                .in_set(spin_set())
                .run_if(any_with_component::<Spin>),
        );
        #[cfg(feature = "ui")]
        app.add_systems(
            self.schedule,
            crate::spin::apply_ui_spin
                .after(step_springs::<SpinAngle>)
                .in_set(spin_set())
                .run_if(any_with_component::<Spin>),
        );
        #[cfg(feature = "sprite")]
        app.add_plugins(SpringPropertyPlugin::<
            crate::color::Oklab<crate::color::SpriteTint>,
        >::default());
        #[cfg(feature = "ui")]
        {
            use crate::color::{Background, Border, ImageTint, Oklab, Text};
            use crate::ui::{
                NodeBottom, NodeHeight, NodeLeft, NodePosition, NodeRight, NodeSize, NodeTop,
                NodeWidth, UiTransformRotation, UiTransformScale, UiTransformTranslation,
            };
            app.add_plugins((
                SpringPropertyPlugin::<UiTransformTranslation>::default(),
                SpringPropertyPlugin::<UiTransformScale>::default(),
                SpringPropertyPlugin::<UiTransformRotation>::default(),
                SpringPropertyPlugin::<NodeSize>::default(),
                SpringPropertyPlugin::<NodePosition>::default(),
                SpringPropertyPlugin::<NodeWidth>::default(),
                SpringPropertyPlugin::<NodeHeight>::default(),
                SpringPropertyPlugin::<NodeLeft>::default(),
                SpringPropertyPlugin::<NodeTop>::default(),
                SpringPropertyPlugin::<NodeRight>::default(),
                SpringPropertyPlugin::<NodeBottom>::default(),
            ))
            .add_plugins((
                SpringPropertyPlugin::<Oklab<Background>>::default(),
                SpringPropertyPlugin::<Oklab<Border>>::default(),
                SpringPropertyPlugin::<Oklab<Text>>::default(),
                SpringPropertyPlugin::<Oklab<ImageTint>>::default(),
            ));
        }
        // Followers: sampled after each fixed step, retargeted before the translation springs
        // step, turned toward their target after those and before the rotation springs.
        app.register_type::<SpringFollow>()
            .register_type::<TargetMotion>()
            .add_systems(
                FixedPostUpdate,
                sample_fixed_targets.run_if(any_with_component::<SpringFollow>),
            )
            .add_systems(
                self.schedule,
                (
                    follow_targets.before(PropertySystems::<Translation>::default()),
                    aim_followers
                        .after(PropertySystems::<Translation>::default())
                        .before(PropertySystems::<Rotation>::default()),
                )
                    .in_set(SpringSystems)
                    .run_if(any_with_component::<SpringFollow>),
            );
    }
}

/// Adds the systems for one [`SpringProperty`]: springing a field of your own component takes
/// this plugin and a [`LinearProperty`](crate::LinearProperty) (or
/// [`SpringProperty`]) implementation. Adds [`SpringPlugin`] with its defaults if it is not
/// there yet; add `SpringPlugin` first to configure it.
pub struct SpringPropertyPlugin<P: SpringProperty>(PhantomData<fn() -> P>);

impl<P: SpringProperty> Default for SpringPropertyPlugin<P> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P: SpringProperty> Plugin for SpringPropertyPlugin<P> {
    fn build(&self, app: &mut App) {
        // `SpringPlugin` inserts the settings before it adds the built-in properties.
        if !app.world().contains_resource::<SpringSettings>() {
            app.add_plugins(SpringPlugin::default());
        }
        let Some(mut settings) = app.world_mut().get_resource_mut::<SpringSettings>() else {
            return;
        };
        let property = core::any::TypeId::of::<P>();
        if settings.registered.contains(&property) {
            return;
        }
        settings.registered.push(property);
        let schedule = settings.schedule;
        let previous = settings
            .last_property
            .replace(PropertySystems::<P>::default().intern());
        app.register_type::<PropertySpring<P>>()
            .register_type::<SpringAsleep<P>>()
            .add_systems(
                schedule,
                (wake_springs::<P>, step_springs::<P>)
                    .chain()
                    .in_set(PropertySystems::<P>::default())
                    .run_if(any_with_component::<PropertySpring<P>>),
            )
            .configure_sets(
                schedule,
                PropertySystems::<P>::default().in_set(SpringSystems),
            );
        if let Some(previous) = previous {
            app.configure_sets(schedule, PropertySystems::<P>::default().after(previous));
        }
    }

    /// Adding a property twice (say, once by a library and once by the app) is harmless: the
    /// second time does nothing.
    fn is_unique(&self) -> bool {
        false
    }
}

impl<P: SpringProperty> core::fmt::Debug for SpringPropertyPlugin<P> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "SpringPropertyPlugin<{}>", P::short_type_path())
    }
}
