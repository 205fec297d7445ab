//! Animation transitions by inertialization: `bevy_animation` clip changes that never pop, at
//! the cost of one clip.
//!
//! A cross-fade ([`AnimationTransitions`])
//! evaluates the old and the new clip for the whole fade and blends them. Inertialization (as
//! Unreal's Inertialization node and Unity's inertialized transitions do, and as Daniel
//! Holden's "Spring-It-On" derives it) switches to the new clip at once and records, per joint,
//! the offset between the pose that was being shown and the new clip's pose, with the offset's
//! velocity; the offset then decays to zero on an exact critically damped spring. Only the new
//! clip is evaluated, a transition interrupted by another starts from what is shown with its
//! velocity, and once the offset has decayed the pose is the new clip's exactly.
//!
//! Put an [`Inertialization`] on the entity with the `AnimationPlayer` and play clips with
//! [`Inertialization::play`], as with `AnimationTransitions::play`.

mod joint;
mod pose;
mod systems;

use core::time::Duration;

use bevy::animation::graph::AnimationNodeIndex;
use bevy::animation::{ActiveAnimation, AnimationPlayer, animate_targets};
use bevy::app::AnimationSystems;
use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;
use sprung::Spring;

use crate::spring::{add_systems_on_first_use, first_use};
use joint::{BlendFrame, Decay};

/// `ω·T` of the blend spring: a critically damped offset released at rest is
/// `(1 + ωt)·e^{−ωt}` of its size at time `t`, which is 1 % at `ωt = 6.6383…`.
const ONE_PERCENT_AT: f32 = 6.638_352;

/// `ω·t` after a switch at which every offset is done: an offset `x₀` moving at `v₀` stays,
/// with its velocity over `ω`, within `(1 + 2ωt)·e^{−ωt}·(|x₀| + |v₀|/ω)` (per axis), and
/// that bound reaches 1e-4 of the start here. The joints then show their clip exactly; the
/// last jump is below a tenth of a millimetre for a metre, far below what shows.
const DONE_AT: f32 = 12.465_803;

/// Switches an `AnimationPlayer`'s clips by inertialization: the new clip plays at once, and
/// each joint's offset from the pose that was shown (translation, rotation on the short arc,
/// scale, and their velocities) decays to zero on an exact critically damped spring.
///
/// Use it as [`AnimationTransitions`] is
/// used: put it on the entity with the `AnimationPlayer` (it requires one) and the
/// `AnimationGraphHandle`, and start clips with [`play`](Self::play) rather than on the player.
///
/// - **One clip evaluated**: the old clip stops at the switch. While the offsets decay, a
///   joint costs its offset read off the closed-form decay (two multiply-adds per number) and a
///   quaternion exponential a frame; once they are done, two pose copies.
/// - **No pop, whatever the timing**: the frame of a switch shows the old motion carried on
///   for that frame, and the offset's velocity keeps the joint's velocity. A switch during
///   another starts from what is shown, with its velocity; any number of switches in one frame
///   make one.
/// - **Exact, at any frame rate**: the offset follows the closed-form critically damped decay,
///   so the pose a second after a switch is the same at 30 and at 240 fps (to the velocities
///   the frames before the switch show).
/// - **Joints in one clip only**: a joint the new clip does not animate keeps the pose the old
///   clip last gave it (as without inertialization), reached smoothly; a joint only the new clip
///   animates moves from where it stood.
/// - **The graph still blends**: the offset is taken on the pose the whole animation graph
///   produced, so weights, masks and additive nodes keep working.
///   [`inertialize`](Self::inertialize) blends any change of pose made by other means (a
///   weight set at once, a seek, another graph).
/// - **Its clock**: the game clock the animation plays on (`Time<Virtual>`); paused, nothing
///   moves.
///
/// A joint's state lives on the joint (the entities with `AnimatedBy` this player): joints that
/// spawn later (a scene under the player) or move to it are picked up, and despawned ones are
/// simply gone. Removing the component shows the clip's pose at once.
///
/// # Example
/// ```
/// use std::time::Duration;
/// use bevy::animation::graph::{AnimationGraph, AnimationGraphHandle, AnimationNodeIndex};
/// use bevy::animation::{AnimationClip, AnimationPlayer, AnimationPlugin};
/// use bevy::prelude::*;
/// use bevy_sprung::inertialization::Inertialization;
/// use bevy_sprung::prelude::*;
///
/// #[derive(Resource)]
/// struct Moves {
///     walk: AnimationNodeIndex,
/// }
///
/// // Switch to the walk in 0.3 s, from wherever the character's joints are.
/// fn walk(moves: Res<Moves>, mut players: Query<(&mut AnimationPlayer, &mut Inertialization)>) {
///     for (mut player, mut inertialization) in &mut players {
///         inertialization
///             .play(&mut player, moves.walk, Duration::from_millis(300))
///             .repeat();
///     }
/// }
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, AssetPlugin::default(), AnimationPlugin))
///     .add_plugins(SpringPlugins::default());
/// let clip = app.world_mut().resource_mut::<Assets<AnimationClip>>().add(AnimationClip::default());
/// let (graph, node) = AnimationGraph::from_clip(clip);
/// let graph = app.world_mut().resource_mut::<Assets<AnimationGraph>>().add(graph);
/// app.insert_resource(Moves { walk: node })
///     .add_systems(Update, walk);
/// app.world_mut().spawn((AnimationGraphHandle(graph), Inertialization::default()));
/// app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone)]
#[component(on_add = inertialization_added)]
#[require(AnimationPlayer)]
#[reflect(Component, Debug, Clone, Default)]
pub struct Inertialization {
    /// The animation [`play`](Self::play) last started.
    main: Option<AnimationNodeIndex>,
    /// The spring the last transition's offsets decay on (`None`: it was instant).
    spring: Option<Spring<f32>>,
    /// How many transitions have started.
    transitions: u32,
    /// The time since the last switch on the animation's clock, in seconds.
    since: f32,
    /// Where this frame stands on the decay, for the joints.
    #[reflect(ignore)]
    frame: BlendFrame,
}

impl Default for Inertialization {
    fn default() -> Self {
        Self {
            main: None,
            spring: None,
            transitions: 0,
            since: 0.0,
            frame: BlendFrame::IDLE,
        }
    }
}

impl Inertialization {
    /// Plays `animation` on `player` from its start, at once, and stops the animation the last
    /// `play` started (others the player plays are left alone); the change of pose blends away
    /// over `blend_time` (see [`inertialize`](Self::inertialize)). `Duration::ZERO` switches
    /// without a blend. Returns the new animation, to set its repeat, speed or weight.
    ///
    /// # Example
    /// ```
    /// use std::time::Duration;
    /// use bevy::animation::AnimationPlayer;
    /// use bevy::animation::graph::AnimationNodeIndex;
    /// use bevy_sprung::inertialization::Inertialization;
    ///
    /// let (mut player, mut inertialization) = (AnimationPlayer::default(), Inertialization::default());
    /// let (idle, wave) = (AnimationNodeIndex::new(1), AnimationNodeIndex::new(2));
    /// inertialization.play(&mut player, idle, Duration::ZERO).repeat();
    /// inertialization.play(&mut player, wave, Duration::from_millis(250));
    /// assert!(player.is_playing_animation(wave) && !player.is_playing_animation(idle));
    /// assert_eq!(inertialization.main_animation(), Some(wave));
    /// ```
    pub fn play<'p>(
        &mut self,
        player: &'p mut AnimationPlayer,
        animation: AnimationNodeIndex,
        blend_time: Duration,
    ) -> &'p mut ActiveAnimation {
        if let Some(previous) = self.main.replace(animation)
            && previous != animation
        {
            player.stop(previous);
        }
        self.inertialize(blend_time);
        player.start(animation)
    }

    /// Blends away whatever changes the pose this frame, by any means (this frame's clips, a
    /// graph weight set at once, a seek), over `blend_time`: each joint shows its old motion
    /// carried on for this frame, and the offset from the new pose decays on
    /// [`blend_spring(blend_time)`](Self::blend_spring). A call during a blend starts a new one
    /// from what is shown; several in one frame make one, with the last `blend_time`.
    pub fn inertialize(&mut self, blend_time: Duration) {
        self.spring = Self::blend_spring(blend_time);
        self.transitions = self.transitions.wrapping_add(1);
    }

    /// The animation [`play`](Self::play) last started.
    #[must_use]
    pub fn main_animation(&self) -> Option<AnimationNodeIndex> {
        self.main
    }

    /// The critically damped spring a blend of `blend_time` decays on: an offset released at
    /// rest is down to 1 % of its size after `blend_time`; every offset is done (below 1e-4
    /// of where it started, moving included) `1.88 × blend_time` after the switch. `None` for
    /// `Duration::ZERO` (an instant switch) or a time so short that the spring's rates
    /// overflow.
    ///
    /// # Example
    /// ```
    /// use std::time::Duration;
    /// use bevy_sprung::inertialization::Inertialization;
    ///
    /// let spring = Inertialization::blend_spring(Duration::from_millis(400)).unwrap();
    /// let settle = spring.settle_time(1.0, 0.01).unwrap();
    /// assert!((settle - 0.4).abs() < 1e-5);
    /// assert!(Inertialization::blend_spring(Duration::ZERO).is_none());
    /// ```
    #[must_use]
    pub fn blend_spring(blend_time: Duration) -> Option<Spring<f32>> {
        let omega = ONE_PERCENT_AT / blend_time.as_secs_f32();
        Spring::from_natural_frequency(omega, 1.0)
            .ok()
            .filter(|_| omega.is_finite())
    }

    /// How many transitions have started (what joints compare with the count they saw).
    pub(crate) fn transitions(&self) -> u32 {
        self.transitions
    }

    /// What the joints need this frame.
    pub(crate) fn frame(&self) -> &BlendFrame {
        &self.frame
    }

    /// Advances the time since the last switch by this frame's `dt` (the switch is at the start
    /// of the frame whose joints first see it) and finds where the offsets stand.
    fn prepare(&mut self, dt: f32) {
        if self.frame.transitions != self.transitions {
            self.since = 0.0;
        }
        self.since += dt;
        let decay = self.spring.and_then(|spring| {
            (spring.natural_frequency() * self.since < DONE_AT).then(|| {
                // The exact transition over the whole time since the switch: sprung's
                // coefficients keep full accuracy for a tiny time and decay without overflow
                // for a long one, and reading them afresh each frame accumulates no rounding.
                let [[from_offset, from_rate], _] = spring.transition(self.since).matrix();
                Decay {
                    from_offset,
                    from_rate,
                }
            })
        });
        self.frame = BlendFrame {
            transitions: self.transitions,
            decay,
            dt,
        };
    }
}

/// Brings in the systems with the first [`Inertialization`], and tells once that nothing will
/// blend when no plugin was added.
fn inertialization_added(mut world: DeferredWorld, context: HookContext) {
    first_use::<Inertialization>(world.reborrow(), context);
    if !world.contains_resource::<InertializationAdded>() {
        let entity = context.entity;
        world.commands().queue(move |world: &mut World| {
            if !world.contains_resource::<InertializationAdded>() {
                world.insert_resource(InertializationAdded);
                warn!(
                    "bevy_sprung: {entity} has an Inertialization but no \
                     SpringInertializationPlugin was added: its clips switch without blending. \
                     Add SpringPlugins (with the `animation` feature) or \
                     SpringInertializationPlugin."
                );
            }
        });
    }
}

/// Present once the plugin is added (or once its absence has been told).
#[derive(Resource)]
struct InertializationAdded;

/// Where inertialization adds its offsets: in `AnimationSystems`, right after Bevy's
/// `animate_targets`, so that spring chains and anything ordered after `AnimationSystems` see
/// the blended pose. Order a system after it to read the pose that will be shown.
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct InertializationSystems;

/// [`Inertialization`] (part of [`SpringPlugins`](crate::SpringPlugins) with the `animation`
/// feature): its systems join the frame with the first `Inertialization`.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringInertializationPlugin;

impl Plugin for SpringInertializationPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<Inertialization>()
            .insert_resource(InertializationAdded)
            .configure_sets(
                PostUpdate,
                InertializationSystems
                    .in_set(AnimationSystems)
                    .after(animate_targets),
            )
            .add_observer(systems::track_animated_joint)
            .add_observer(systems::track_player_joints);
        add_systems_on_first_use(
            app,
            &[core::any::TypeId::of::<Inertialization>()],
            PostUpdate,
            |schedule| {
                schedule.add_systems(
                    (
                        systems::prepare_frames.before(AnimationSystems),
                        systems::blend_joints.in_set(InertializationSystems),
                    )
                        .run_if(any_with_component::<Inertialization>),
                );
            },
        );
    }
}
