//! The life of an entity with [`Presence`]: its entrance, its exit, and the turns between them.

use core::fmt;

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::system::EntityCommands;
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;

use crate::choreography::{AllSpringsSettled, SpringGroup, report_when_settled};
use bevy::math::NormedVectorSpace;
use sprung::{RestThreshold, Spring};

use crate::property::{SpringProperty, ValueOf};
use crate::space::SpringSpace;
use crate::spring::{PropertySpring, SpringTargetMut, trigger_if_alive};

/// Makes an entity's arrival and departure spring: it enters from its [`EnterFrom<P>`] values,
/// and [`despawn_after_exit`](PresenceCommands::despawn_after_exit) springs it to its
/// [`ExitTo<P>`] values and despawns it (with its descendants) once they have settled.
///
/// An exit is done where it stops showing: while it leaves, each spring rests within 1/256 of
/// the distance it travels (one step of an 8-bit channel for a full fade, under half a pixel
/// of a 100 px slide), with the speed of equal energy, or within its own tolerances if those
/// are coarser; a cancelled exit gets its own tolerances back. So the despawn does not wait
/// for the invisible last thousandth of a unit.
///
/// [`Entered`] is triggered when the entrance has settled, [`Exited`] just before the entity
/// is despawned (it is still there for the observer). The settling is what
/// [`SpringGroup`] reports: the entity gets a `SpringGroup` for its own springs if it has none.
///
/// What the world may do meanwhile is defined: an exit requested twice is one exit; an exit
/// cancelled ([`cancel_exit`](PresenceCommands::cancel_exit)) turns every spring back to the
/// target it had, keeping its velocity, and the next settle is an [`Entered`]; an entity
/// despawned another way mid-exit (directly, or with its parent) just goes, with no event; an
/// exit that has nothing to move (no [`ExitTo`], or every spring already at its exit value)
/// completes in the frame it was asked in, and an entrance with nothing to move is reported in
/// the frame the entity was spawned in.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// #[derive(Component)]
/// struct Coin;
///
/// fn spawn_coin(mut commands: Commands) {
///     commands.spawn((
///         Coin,
///         Transform::default(),
///         Presence::default(),
///         // Rises 40 units and grows from 80 % as it appears; sinks and shrinks as it leaves.
///         TranslationSpring::new(Spring::snappy(), Vec3::ZERO),
///         EnterFrom::<Translation>(Vec3::new(0.0, -40.0, 0.0)),
///         ExitTo::<Translation>(Vec3::new(0.0, -40.0, 0.0)),
///         ScaleSpring::new(Spring::bouncy(), Vec3::ONE),
///         EnterFrom::<Scale>(Vec3::splat(0.8)),
///         ExitTo::<Scale>(Vec3::splat(0.0)),
///     ));
/// }
///
/// fn collect(coins: Query<Entity, With<Coin>>, mut commands: Commands) {
///     for coin in &coins {
///         // Leaves, then is despawned; asking again while it leaves changes nothing.
///         commands.entity(coin).despawn_after_exit();
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default()))
/// #     .add_systems(Startup, spawn_coin)
/// #     .add_systems(Update, collect);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Default, Clone, Copy, PartialEq, Eq)]
#[require(SpringGroup)]
#[reflect(Component, Debug, Default, Clone, PartialEq)]
#[component(on_add = Self::on_add)]
pub struct Presence {
    phase: PresencePhase,
}

impl Presence {
    /// The hook: the entrance is reported when the entity's springs have settled, also if none
    /// of them moves.
    fn on_add(mut world: DeferredWorld, context: HookContext) {
        world
            .commands()
            .queue(move |world: &mut World| report_when_settled(world, context.entity));
    }

    /// Where the entity is in its life.
    #[inline]
    #[must_use]
    pub fn phase(&self) -> PresencePhase {
        self.phase
    }

    /// Whether it is on its way out (an exit requested and not cancelled).
    #[inline]
    #[must_use]
    pub fn is_exiting(&self) -> bool {
        self.phase == PresencePhase::Exiting
    }
}

/// Where an entity with [`Presence`] is in its life.
#[derive(Reflect, Debug, Default, Clone, Copy, PartialEq, Eq, Hash)]
#[reflect(Debug, Default, Clone, PartialEq)]
pub enum PresencePhase {
    /// Spawned (or turned back from an exit), its springs not yet settled.
    #[default]
    Entering,
    /// Entered: its springs settled since it was spawned or turned back.
    Present,
    /// On its way out: it is despawned when its springs have settled.
    Exiting,
}

/// The value property `P` starts from when the entity is spawned (or this component is
/// inserted): its spring carries it from there to its target. The entrance of an entity with
/// [`Presence`].
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// fn spawn_card(mut commands: Commands) {
///     // Grows from nothing to full size with a bounce.
///     commands.spawn((
///         Transform::default(),
///         Presence::default(),
///         ScaleSpring::new(Spring::bouncy(), Vec3::ONE),
///         EnterFrom::<Scale>(Vec3::ZERO),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn_card);
/// # app.update();
/// ```
#[derive(Component, Reflect)]
#[component(on_insert = Self::on_insert)]
#[require(HeldTarget<P>)]
#[reflect(Component, Debug, Clone)]
pub struct EnterFrom<P: SpringProperty>(pub ValueOf<P>);

impl<P: SpringProperty> EnterFrom<P> {
    /// The hook: the property takes the starting value (its spring, which follows what else
    /// writes its property, springs from there). A value that is not finite is refused.
    fn on_insert(mut world: DeferredWorld, context: HookContext) {
        let Some(&Self(value)) = world.get::<Self>(context.entity) else {
            return;
        };
        if !P::Space::is_valid(value) {
            warn_once!("bevy_sprung: refused a non-finite entering value {value:?}");
            return;
        }
        if let Some(mut component) = world.get_mut::<P::Component>(context.entity) {
            P::set(&mut component, value);
        }
    }
}

/// The value property `P`'s spring heads for when the entity leaves
/// ([`despawn_after_exit`](PresenceCommands::despawn_after_exit)); the target it had is kept and
/// restored if the exit is cancelled. See [`Presence`].
#[derive(Component, Reflect)]
#[require(HeldTarget<P>)]
#[reflect(Component, Debug, Clone)]
pub struct ExitTo<P: SpringProperty>(pub ValueOf<P>);

/// The target property `P`'s spring had when an exit began (restored if it is cancelled), or
/// while its entrance waits (restored when it goes); and during an exit, the spring's own rest
/// tolerances (restored if it is cancelled).
#[derive(Component)]
pub(super) struct HeldTarget<P: SpringProperty> {
    target: Option<ValueOf<P>>,
    rest: Option<RestThreshold<f32>>,
}

impl<P: SpringProperty> Default for HeldTarget<P> {
    fn default() -> Self {
        Self {
            target: None,
            rest: None,
        }
    }
}

/// The share of an exit's travel within which it counts as done: one step of an 8-bit
/// channel for a full fade, under half a pixel of a 100 px slide.
const EXIT_REST_SHARE: f32 = 1.0 / 256.0;

/// The rest tolerances of a spring leaving over a distance `travel`: a share of the travel
/// ([`EXIT_REST_SHARE`]) and the speed of equal energy, never finer than its own `rest`. An
/// exit ends where it stops showing, not on the last thousandth of a unit.
fn exit_rest(spring: &Spring<f32>, rest: RestThreshold<f32>, travel: f32) -> RestThreshold<f32> {
    if !travel.is_finite() {
        return rest;
    }
    let visible = RestThreshold::for_spring(spring, travel * EXIT_REST_SHARE);
    RestThreshold::new(
        visible.offset.max(rest.offset),
        visible.speed.max(rest.speed),
    )
}

impl<P: SpringProperty> Clone for EnterFrom<P> {
    fn clone(&self) -> Self {
        Self(self.0)
    }
}

impl<P: SpringProperty> fmt::Debug for EnterFrom<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "EnterFrom<{}>({:?})", P::short_type_path(), self.0)
    }
}

impl<P: SpringProperty> Clone for ExitTo<P> {
    fn clone(&self) -> Self {
        Self(self.0)
    }
}

impl<P: SpringProperty> fmt::Debug for ExitTo<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "ExitTo<{}>({:?})", P::short_type_path(), self.0)
    }
}

/// Triggered on an entity with [`Presence`] when its entrance has settled (after it was
/// spawned, or turned back from an exit).
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct Entered {
    /// The entity that entered.
    pub entity: Entity,
}

/// Triggered on an entity with [`Presence`] when its exit has settled, just before it is
/// despawned: observers still find it and its components.
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct Exited {
    /// The entity that is leaving.
    pub entity: Entity,
}

/// A turn in an entity's life: each property's observer turns its spring.
#[derive(EntityEvent, Debug, Clone, Copy)]
pub(super) struct Turn {
    pub(super) entity: Entity,
    pub(super) to: TurnTo,
}

/// Where a [`Turn`] takes the springs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum TurnTo {
    /// Toward each [`ExitTo`] value, holding the target each had.
    Exit,
    /// Back to the targets held by an exit.
    Back,
    /// Waiting: each entering spring ([`EnterFrom`]) holds where its property is, keeping its
    /// target for [`Go`](Self::Go).
    Wait,
    /// Entering after a wait: to the targets held by [`Wait`](Self::Wait).
    Go,
}

/// Marks an entity whose entrance waits (a staggered child): its entering springs hold still
/// until the wait is over.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub(super) struct Waiting;

/// Exits on `EntityCommands`: `commands.entity(toast).despawn_after_exit()`.
pub trait PresenceCommands {
    /// Springs the entity to its [`ExitTo`] values and despawns it, with its descendants,
    /// once its springs have settled ([`Exited`] is triggered first). Asked again while it
    /// leaves, nothing changes. An entity without [`Presence`] is despawned at once, and one
    /// already gone is ignored.
    fn despawn_after_exit(&mut self) -> &mut Self;

    /// Turns a leaving entity back: its springs retarget to the targets they had before the
    /// exit, keeping their velocities, and it is no longer despawned. [`Entered`] follows when
    /// they settle. Does nothing to an entity that is not leaving.
    fn cancel_exit(&mut self) -> &mut Self;
}

impl PresenceCommands for EntityCommands<'_> {
    fn despawn_after_exit(&mut self) -> &mut Self {
        self.queue_silenced(|entity: EntityWorldMut| turn(entity, true))
    }

    fn cancel_exit(&mut self) -> &mut Self {
        self.queue_silenced(|entity: EntityWorldMut| turn(entity, false))
    }
}

/// Starts an exit (`exiting`) or cancels one: every property's spring turns (in the observers
/// of [`Turn`]), and the entity reports when they have settled.
fn turn(mut entity: EntityWorldMut, exiting: bool) {
    let id = entity.id();
    let Some(mut presence) = entity.get_mut::<Presence>() else {
        if exiting {
            entity.despawn();
        }
        return;
    };
    if presence.is_exiting() == exiting {
        return;
    }
    presence.phase = if exiting {
        PresencePhase::Exiting
    } else {
        PresencePhase::Entering
    };
    // An entrance still waiting goes first, so that the exit starts from the springs' own
    // targets.
    let waited = entity.take::<Waiting>().is_some();
    entity.world_scope(|world| {
        if waited {
            world.trigger(Turn {
                entity: id,
                to: TurnTo::Go,
            });
        }
        let to = if exiting { TurnTo::Exit } else { TurnTo::Back };
        world.trigger(Turn { entity: id, to });
        report_when_settled(world, id);
    });
}

/// Property `P`'s part of a turn: its spring heads for the exit value or holds where it is
/// (keeping the target it had), or back to that target.
pub(super) fn turn_property<P: SpringProperty>(
    turn: On<Turn>,
    mut springs: Query<(
        &mut PropertySpring<P>,
        &P::Component,
        &mut HeldTarget<P>,
        Option<&ExitTo<P>>,
        Has<EnterFrom<P>>,
    )>,
    springless_exits: Query<(), (With<ExitTo<P>>, Without<PropertySpring<P>>)>,
    mut warned: Local<bool>,
) {
    let Ok((mut spring, component, mut held, exit, entering)) = springs.get_mut(turn.entity) else {
        if turn.to == TurnTo::Exit && springless_exits.contains(turn.entity) && !*warned {
            *warned = true;
            warn!(
                "bevy_sprung: {} has an ExitTo<{path}> but no PropertySpring<{path}>: its exit \
                 has nothing to move, so it is despawned at once; add the spring that moves \
                 {path} (the ExitTo value is where it heads)",
                turn.entity,
                path = P::short_type_path(),
            );
        }
        return;
    };
    let target = match (turn.to, exit) {
        (TurnTo::Exit, Some(exit)) => {
            held.target = Some(spring.target());
            let travel = P::Space::offset(P::get(component), exit.0).norm();
            let rest = spring.rest();
            held.rest = Some(rest);
            let rest = exit_rest(spring.spring(), rest, travel);
            spring.set_rest(rest);
            exit.0
        }
        (TurnTo::Wait, _) if entering => {
            held.target = Some(spring.target());
            P::get(component)
        }
        (TurnTo::Back | TurnTo::Go, _) => {
            if let Some(rest) = held.rest.take() {
                spring.set_rest(rest);
            }
            match held.target.take() {
                Some(held) => held,
                None => return,
            }
        }
        _ => return,
    };
    spring.set_target_if_neq(target);
}

/// Every spring of an entity with [`Presence`] settled: it has entered, or it has left and is
/// despawned.
pub(super) fn settled(
    settled: On<AllSpringsSettled>,
    mut presences: Query<&mut Presence, Without<Waiting>>,
    mut commands: Commands,
) {
    let entity = settled.entity;
    // An entrance that waits has not entered: it reports once it went and settled.
    let Ok(mut presence) = presences.get_mut(entity) else {
        return;
    };
    match presence.phase {
        PresencePhase::Entering => {
            presence.phase = PresencePhase::Present;
            trigger_if_alive(&mut commands, Entered { entity });
        }
        PresencePhase::Present => {}
        PresencePhase::Exiting => {
            trigger_if_alive(&mut commands, Exited { entity });
            commands.queue(move |world: &mut World| {
                // An observer of `Exited` may have despawned it, or cancelled the exit.
                if world
                    .get::<Presence>(entity)
                    .is_some_and(Presence::is_exiting)
                {
                    world.despawn(entity);
                }
            });
        }
    }
}
