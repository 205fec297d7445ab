//! One event when a group of springs has settled.

use alloc::borrow::Cow;

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::platform::collections::HashSet;
use bevy::prelude::*;

use crate::property::SpringProperty;
use crate::spring::{PropertySpring, SpringAsleep, SpringWoke, trigger_if_alive};

/// Makes this entity's springs report together: when every spring on the entity (any property)
/// has settled, [`AllSpringsSettled`] is triggered on it, once; and when every spring of every
/// entity in a named group has settled, the global [`SpringGroupSettled`] is triggered, once.
/// Each time springs of the entity (or group) start moving again, the next settle reports
/// again. The per-spring [`SpringSettled`](crate::spring::SpringSettled) events fire as always.
///
/// Only entities with a `SpringGroup` are tracked: springs without one pay nothing.
///
/// Members that go away count as settled: when a member with a spring in motion is despawned,
/// loses its `SpringGroup` or its springs, the group reports once its other members' springs
/// have settled (at once if none is moving), and no event is triggered for the member itself.
/// A group whose members all went away reports once. No event is delivered to a despawned
/// entity.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::choreography::{SpringGroup, SpringGroupSettled};
///
/// fn open_menu(mut commands: Commands) {
///     for index in 0..4 {
///         commands.spawn((
///             Transform::default(),
///             TranslationSpring::new(Spring::snappy(), Vec3::new(0.0, index as f32 * 50.0, 0.0)),
///             ScaleSpring::new(Spring::bouncy(), Vec3::splat(1.2)),
///             SpringGroup::named("menu"),
///         ));
///     }
///     commands.add_observer(|settled: On<SpringGroupSettled>| {
///         info!("every spring of group {} has settled", settled.group);
///     });
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, open_menu);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Default, Clone, PartialEq, Eq, Hash)]
#[component(on_add = crate::spring::first_use::<SpringGroup>, on_remove = leave_group)]
#[reflect(Component, Debug, Default, PartialEq, Clone)]
pub struct SpringGroup {
    /// The group's name (`None`: the entity alone).
    pub name: Option<Cow<'static, str>>,
}

impl SpringGroup {
    /// The entity's own springs, reported together by [`AllSpringsSettled`].
    #[must_use]
    pub const fn this_entity() -> Self {
        Self { name: None }
    }

    /// A member of the group `name`, reported by [`SpringGroupSettled`] (and the entity's own
    /// springs by [`AllSpringsSettled`]).
    #[must_use]
    pub fn named(name: impl Into<Cow<'static, str>>) -> Self {
        Self {
            name: Some(name.into()),
        }
    }
}

/// Triggered on an entity with a [`SpringGroup`] when all its springs have settled.
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct AllSpringsSettled {
    /// The entity whose springs all settled.
    pub entity: Entity,
}

/// Triggered (globally) when every spring of every entity in a named [`SpringGroup`] has
/// settled.
#[derive(Event, Debug, Clone, PartialEq, Eq)]
pub struct SpringGroupSettled {
    /// The group.
    pub group: Cow<'static, str>,
}

/// Which grouped entities are moving.
#[derive(Resource, Default, Debug)]
pub(super) struct SettleTracker {
    /// Entities with a spring that moved since they last reported.
    in_motion: HashSet<Entity>,
    /// Entities with an awake spring after this frame's steps.
    awake: HashSet<Entity>,
    /// Groups a member in motion left (despawned, or its `SpringGroup` removed): they report
    /// if no other member is moving.
    left: Vec<Cow<'static, str>>,
}

impl SettleTracker {
    /// Whether [`announce_settled`] has anything to look at.
    fn has_news(&self) -> bool {
        !(self.in_motion.is_empty() && self.left.is_empty())
    }
}

/// The hook of a [`SpringGroup`] removed (also when its entity is despawned): a member in
/// motion leaves its group, which then reports if none of its other members is moving.
fn leave_group(mut world: DeferredWorld, context: HookContext) {
    let name = world
        .get::<SpringGroup>(context.entity)
        .and_then(|group| group.name.clone());
    let Some(mut tracker) = world.get_resource_mut::<SettleTracker>() else {
        return;
    };
    tracker.awake.remove(&context.entity);
    if tracker.in_motion.remove(&context.entity)
        && let Some(name) = name
        && !tracker.left.contains(&name)
    {
        tracker.left.push(name);
    }
}

/// Makes the grouped `entity` report [`AllSpringsSettled`] once none of its springs moves (this
/// frame, if none does): for features that start something on an entity and wait for its
/// springs, whether or not any of them moves.
pub(crate) fn report_when_settled(world: &mut World, entity: Entity) {
    if let Some(mut tracker) = world.get_resource_mut::<SettleTracker>() {
        tracker.in_motion.insert(entity);
    }
}

/// Whether any grouped entity is in motion or left its group in motion: the run condition of
/// [`announce_settled`].
pub(super) fn has_news(tracker: Option<Res<SettleTracker>>) -> bool {
    tracker.is_some_and(|tracker| tracker.has_news())
}

/// A spring on property `P` woke: a grouped entity is in motion, even if it settles again
/// within the frame.
pub(super) fn note_woken<P: SpringProperty>(
    woken: On<SpringWoke<P>>,
    grouped: Query<(), With<SpringGroup>>,
    mut tracker: ResMut<SettleTracker>,
) {
    if grouped.contains(woken.entity) {
        tracker.in_motion.insert(woken.entity);
    }
}

/// After property `C`'s springs stepped: notes the grouped entities whose spring on it is
/// awake (`A`: the property's sleep marker).
pub(super) fn note_awake<P: SpringProperty>(
    mut tracker: ResMut<SettleTracker>,
    awake: Query<
        Entity,
        (
            With<SpringGroup>,
            With<PropertySpring<P>>,
            Without<SpringAsleep<P>>,
        ),
    >,
) {
    for entity in &awake {
        tracker.awake.insert(entity);
        tracker.in_motion.insert(entity);
    }
}

/// After every property stepped: reports the grouped entities (and groups) whose springs were
/// moving and have all settled.
pub(super) fn announce_settled(
    mut tracker: ResMut<SettleTracker>,
    groups: Query<&SpringGroup>,
    mut commands: Commands,
) {
    let SettleTracker {
        in_motion,
        awake,
        left,
    } = &mut *tracker;
    let mut settled_groups: Vec<Cow<'static, str>> = core::mem::take(left);
    in_motion.retain(|&entity| {
        if awake.contains(&entity) {
            return true;
        }
        // Not grouped any more (its group heard of it in `leave_group`).
        let Ok(group) = groups.get(entity) else {
            return false;
        };
        trigger_if_alive(&mut commands, AllSpringsSettled { entity });
        if let Some(name) = &group.name
            && !settled_groups.contains(name)
        {
            settled_groups.push(name.clone());
        }
        false
    });
    for group in settled_groups {
        let still_moving = in_motion.iter().any(|&entity| {
            groups
                .get(entity)
                .is_ok_and(|member| member.name.as_ref() == Some(&group))
        });
        if !still_moving {
            commands.trigger(SpringGroupSettled { group });
        }
    }
    awake.clear();
}
