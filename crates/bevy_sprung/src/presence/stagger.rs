//! Orchestration: children that enter one after another, and parents that enter before or after
//! their children — Motion's `staggerChildren`, `delayChildren` and `when`.

use alloc::vec::Vec;

use bevy::prelude::*;

use super::lifecycle::{Presence, PresencePhase, Turn, TurnTo, Waiting};
use crate::choreography::report_when_settled;
use crate::clock::SpringTime;

/// Makes the children of this entity that have a [`Presence`] enter one after another: each
/// one's entering springs ([`EnterFrom`](super::EnterFrom)) hold still until its turn, `interval`
/// seconds after the one before, in the [`order`](Self::order) given. Children that appear
/// later join the stagger after those still waiting. The parent, if it has a `Presence` too,
/// enters with them, before them or after them ([`when`](Self::when)).
///
/// Delays count on the game clock (`Time` in `PostUpdate`). A child asked to leave while it
/// waits leaves at once from where it is; [`Entered`](super::Entered) comes after its wait and
/// its entrance.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::presence::{StaggerChildren, StaggerOrder};
///
/// fn deal_cards(mut commands: Commands) {
///     commands
///         .spawn((Transform::default(), StaggerChildren::new(0.05).from(StaggerOrder::Centre)))
///         .with_children(|hand| {
///             for index in 0..5 {
///                 hand.spawn((
///                     Transform::from_xyz(index as f32 * 60.0, 0.0, 0.0),
///                     Presence::default(),
///                     ScaleSpring::new(Spring::bouncy(), Vec3::ONE),
///                     EnterFrom::<Scale>(Vec3::ZERO),
///                 ));
///             }
///         });
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, deal_cards);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[component(on_add = crate::spring::first_use::<StaggerChildren>)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct StaggerChildren {
    /// Seconds between one child's start and the next.
    pub interval: f32,
    /// Seconds before the first child starts (Motion's `delayChildren`).
    pub delay: f32,
    /// Which child starts first.
    pub order: StaggerOrder,
    /// Whether the parent enters with its children, before them or after them.
    pub when: StaggerWhen,
    /// When (on the game clock's elapsed seconds) the last child scheduled starts: later
    /// children start after it.
    #[reflect(ignore)]
    last_start: f64,
}

impl StaggerChildren {
    /// Children start `interval` seconds apart, first to last, with the parent.
    #[must_use]
    pub fn new(interval: f32) -> Self {
        Self {
            interval: interval.max(0.0),
            delay: 0.0,
            order: StaggerOrder::First,
            when: StaggerWhen::Together,
            last_start: f64::NEG_INFINITY,
        }
    }

    /// The same stagger, starting in `order`.
    #[must_use]
    pub fn from(mut self, order: StaggerOrder) -> Self {
        self.order = order;
        self
    }

    /// The same stagger, the first child starting after `seconds`.
    #[must_use]
    pub fn delayed(mut self, seconds: f32) -> Self {
        self.delay = seconds.max(0.0);
        self
    }

    /// The same stagger, the parent entering `when` (before or after its children).
    #[must_use]
    pub fn when(mut self, when: StaggerWhen) -> Self {
        self.when = when;
        self
    }

    /// The delay of the child of `rank` among `count` children arriving together, in seconds
    /// after the first: ranks count from the first child to start.
    fn delay_of(&self, rank: f32) -> f64 {
        f64::from(self.interval * rank)
    }
}

/// Which of the children of a [`StaggerChildren`] starts first.
#[derive(Reflect, Debug, Default, Clone, Copy, PartialEq)]
#[reflect(Debug, Default, Clone, PartialEq)]
pub enum StaggerOrder {
    /// In `Children` order.
    #[default]
    First,
    /// From the last child to the first.
    Last,
    /// From the middle of `Children` outward.
    Centre,
    /// Nearest first to this point, in the parent's space (each child's `Transform`
    /// translation); a child without a `Transform` (a UI node) counts as at the parent's origin.
    From(Vec3),
}

/// Whether the parent of a [`StaggerChildren`] (if it has a [`Presence`]) enters with its
/// children, before them or after them (Motion's `when`).
#[derive(Reflect, Debug, Default, Clone, Copy, PartialEq, Eq)]
#[reflect(Debug, Default, Clone, PartialEq)]
pub enum StaggerWhen {
    /// The parent and its children start together (the children staggered).
    #[default]
    Together,
    /// The children's stagger starts once the parent has entered.
    BeforeChildren,
    /// The parent starts once its children have entered.
    AfterChildren,
}

/// A staggered child's wait: seconds left, counted once `after` (the parent entering first)
/// has entered.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
pub(super) struct EntranceDelay {
    remaining: f64,
    after: Option<Entity>,
}

/// A parent whose entrance waits for its children's.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct AwaitChildren;

/// Before the springs step: children with a [`Presence`] new under a [`StaggerChildren`] wait
/// their turn, and a parent that enters after them waits for them.
pub(super) fn schedule_entrances(
    arrived: Query<(Entity, &ChildOf), Added<Presence>>,
    mut parents: Query<(&mut StaggerChildren, &Children, Option<&Presence>)>,
    positions: Query<&Transform>,
    time: SpringTime,
    mut commands: Commands,
    mut by_parent: Local<Vec<(Entity, Entity)>>,
) {
    by_parent.clear();
    by_parent.extend(
        arrived
            .iter()
            .map(|(child, child_of)| (child_of.parent(), child))
            .filter(|&(parent, _)| parents.contains(parent)),
    );
    if by_parent.is_empty() {
        return;
    }
    by_parent.sort_unstable();
    by_parent.dedup_by_key(|(parent, _)| *parent);
    // Waits count on the default spring clock, as the entrances they delay do: a staggered
    // pause menu on the real clock goes on while the game is paused.
    let now = time.elapsed(None);
    // Waits are counted down from the start of this frame, this frame included.
    let frame_start = now - f64::from(time.delta(None));
    for &(parent, _) in &*by_parent {
        let Ok((mut stagger, children, presence)) = parents.get_mut(parent) else {
            continue;
        };
        // The new children, in `Children` order.
        let new: Vec<Entity> = children
            .iter()
            .filter(|&child| arrived.contains(child))
            .collect();
        let ranks = ranks(stagger.order, &new, |child| {
            positions
                .get(child)
                .map_or(Vec3::ZERO, |transform| transform.translation)
        });
        let start =
            (now + f64::from(stagger.delay)).max(stagger.last_start + f64::from(stagger.interval));
        let parent_entering =
            presence.is_some_and(|presence| presence.phase() == PresencePhase::Entering);
        let after =
            (stagger.when == StaggerWhen::BeforeChildren && parent_entering).then_some(parent);
        let mut last = stagger.last_start;
        for (&child, &rank) in new.iter().zip(&ranks) {
            let at = start + stagger.delay_of(rank);
            last = last.max(at);
            commands.entity(child).insert((
                Waiting,
                EntranceDelay {
                    remaining: at - frame_start,
                    after,
                },
            ));
            commands.trigger(Turn {
                entity: child,
                to: TurnTo::Wait,
            });
        }
        stagger.last_start = last;
        if stagger.when == StaggerWhen::AfterChildren && parent_entering {
            commands.entity(parent).insert((Waiting, AwaitChildren));
            commands.trigger(Turn {
                entity: parent,
                to: TurnTo::Wait,
            });
        }
    }
}

/// The rank of each of `children` (arriving together) in the stagger: 0 starts first.
fn ranks(order: StaggerOrder, children: &[Entity], position: impl Fn(Entity) -> Vec3) -> Vec<f32> {
    let count = children.len();
    let last = count.saturating_sub(1) as f32;
    match order {
        StaggerOrder::First => (0..count).map(|index| index as f32).collect(),
        StaggerOrder::Last => (0..count).map(|index| last - index as f32).collect(),
        StaggerOrder::Centre => (0..count)
            .map(|index| (index as f32 - last / 2.0).abs())
            .collect(),
        StaggerOrder::From(point) => {
            let distances: Vec<f32> = children
                .iter()
                .map(|&child| position(child).distance(point))
                .collect();
            let mut nearest: Vec<usize> = (0..count).collect();
            nearest.sort_by(|&a, &b| distances[a].total_cmp(&distances[b]));
            let mut ranks = vec![0.0; count];
            for (rank, index) in nearest.into_iter().enumerate() {
                ranks[index] = rank as f32;
            }
            ranks
        }
    }
}

/// Counts the waits down; an entrance whose wait is over goes (its springs head for their
/// targets) and reports when it has settled.
pub(super) fn release_entrances(
    mut delayed: Query<(Entity, &mut EntranceDelay)>,
    awaiting: Query<(Entity, &Children), With<AwaitChildren>>,
    presences: Query<(&Presence, Has<Waiting>)>,
    time: SpringTime,
    mut commands: Commands,
) {
    let dt = f64::from(time.delta(None));
    // Gone, or without a presence, counts as entered.
    let entered = |entity: Entity| match presences.get(entity) {
        Ok((presence, waiting)) => presence.phase() != PresencePhase::Entering && !waiting,
        Err(_) => true,
    };
    for (entity, mut delay) in &mut delayed {
        if delay.after.is_some_and(|after| !entered(after)) {
            continue;
        }
        delay.remaining -= dt;
        if delay.remaining <= 0.0 {
            commands.entity(entity).remove::<(EntranceDelay, Waiting)>();
            go(&mut commands, entity);
        }
    }
    for (parent, children) in &awaiting {
        let waiting_for = children
            .iter()
            .any(|child| presences.contains(child) && !entered(child));
        if !waiting_for {
            commands.entity(parent).remove::<(AwaitChildren, Waiting)>();
            go(&mut commands, parent);
        }
    }
}

/// The entrance of `entity` goes: its springs head for their targets, and it reports once they
/// have settled.
fn go(commands: &mut Commands, entity: Entity) {
    commands.trigger(Turn {
        entity,
        to: TurnTo::Go,
    });
    commands.queue(move |world: &mut World| report_when_settled(world, entity));
}
