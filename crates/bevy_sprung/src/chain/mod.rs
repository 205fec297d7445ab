//! Spring chains: secondary motion on `Transform` hierarchies — tails, ears, antennae, hair,
//! ropes, dangling signs — in the manner of Dynamic Bone and VRM's spring bones, with exact
//! springs.
//!
//! Put a [`SpringChain`] on the first joint of a hierarchy. Every joint below it (and the
//! first one) with one child joint is a bone: its tip (the child's position) follows, through
//! an exact spring, where the parent's current pose puts it at rest; the joint turns to point
//! the bone at the sprung tip. So a parent that accelerates leaves the tail behind, gravity and
//! wind bend it (the core's exact constant-acceleration step), and bone lengths are kept by
//! construction: only rotations are written. The pose a joint is given by others (an
//! animation, your code) is its rest pose, and the chain adds to it.

mod collider;
mod pose;
mod systems;

pub use collider::ChainCollider;

use bevy::app::AnimationSystems;
use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;
use bevy::transform::TransformSystems;
use sprung::{Spring, Transition};

use crate::spring::{add_systems_on_first_use, first_use};

/// Makes the hierarchy below its entity swing: each joint with one child joint springs toward
/// the pose it is given, pulled by its parent's motion, gravity and wind.
///
/// Two things to know up front:
/// - **The last joint turns only with an end bone.** A joint turns to point its bone at the
///   sprung tip, and a bone runs to the joint's child: a joint without a child joint (the last
///   one) has no bone and does not turn, unless [`with_end`](Self::with_end) gives it one (the
///   offset of its tip in its own axes, e.g. the length of the last bone). A chain on an entity
///   with no child joints and no end is told once.
/// - **Choosing the spring.** A chain follows at the spring's natural frequency and sways by
///   its damping ratio: start from [`Spring::smooth`] or [`Spring::gentle`] (ζ ≥ 0.7) for hair
///   and tails; a bouncy spring (ζ ≈ 0.3) whips: after a hard stop of the parent a joint can
///   swing past 180° and the chain folds over. There are no angle limits: keep the swing within
///   bounds with damping (or a stiffer spring toward the root, [`ChainGradient`]), and keep
///   bodies out with [`ChainCollider`]s.
///
/// - **Exact, and the same at any frame rate**: the chain steps on a fixed grid of times
///   ([`rate`](Self::rate) steps a second), each tip by the exact step of its spring toward a
///   rest place moving linearly over the step (a first-order hold) plus the exact response to
///   the constant `gravity + wind`; the parent's pose at a step inside a frame is interpolated.
///   The rest of a frame is shown by an exact step from the last one, not kept. So the same
///   motion of the parent gives the same pose at 30 and at 240 fps, and no frame shows a pose
///   late.
/// - **Bone lengths kept**: only joint rotations are written; translations and scales stay as
///   given, so every bone keeps its length to rounding.
/// - **On top of animation**: a joint rotation written by anything else (`bevy_animation`,
///   gameplay) is its new rest pose, so the chain adds to a played clip. A glTF skin's joints
///   are a hierarchy like any other: once its scene has spawned, put the chain on the first
///   joint that should swing (find it by its `Name`).
/// - **At rest, free**: when every tip has settled where gravity holds it and the chain's
///   parent does not move, nothing is stepped or written until it moves again.
/// - **Cost**: each moving joint costs about what a hand-written Verlet joint (Dynamic Bone's
///   method) does; chains step in parallel on Bevy's compute pool, and only the joints'
///   rotations that changed are written.
/// - **Teleports**: a root that moves further than
///   [`teleport_distance`](Self::teleport_distance) in one frame carries the tips with it (no
///   swing from the jump); [`reset`](Self::reset) puts every tip at rest.
/// - **2D**: [`planar`](Self::planar) chains turn their joints about z only (sprite
///   hierarchies).
///
/// The stiffness and damping of [`spring`](Self::spring) are per unit mass of a tip (its
/// natural frequency sets how fast the tail follows); [`gradient`](Self::gradient) scales them
/// and the gravity from the first joint to the last. A joint with a [`ChainJoint`] uses its own
/// spring and gravity scale.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::chain::SpringChain;
/// use bevy_sprung::prelude::*;
///
/// fn spawn_tail(mut commands: Commands) {
///     // Three segments of 20 px hanging from a body, in 2D.
///     commands.spawn(Transform::default()).with_children(|body| {
///         body.spawn((
///             Transform::from_xyz(-30.0, 0.0, 0.0),
///             SpringChain::new(Spring::bouncy())
///                 .with_gravity(Vec3::new(0.0, -400.0, 0.0))
///                 .planar(),
///         ))
///         .with_children(|joint| {
///             joint.spawn(Transform::from_xyz(-20.0, 0.0, 0.0)).with_children(|joint| {
///                 joint.spawn(Transform::from_xyz(-20.0, 0.0, 0.0)).with_children(|joint| {
///                     joint.spawn(Transform::from_xyz(-20.0, 0.0, 0.0));
///                 });
///             });
///         });
///     });
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, TransformPlugin, SpringPlugins::default())).add_systems(Startup, spawn_tail);
/// # app.update();
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone)]
#[component(on_add = chain_added)]
#[require(Transform)]
#[reflect(Component, Debug, Clone)]
pub struct SpringChain {
    /// The spring each tip follows its rest place with (per unit mass). Its natural frequency
    /// is how fast the chain follows; its damping ratio how much it sways.
    pub spring: Spring<f32>,
    /// A constant acceleration on every tip, in world units per second² (`Vec3::NEG_Y * 9.81`
    /// for metres): a chain hangs by `gravity / ω²` below its rest pose.
    pub gravity: Vec3,
    /// A constant acceleration from wind, added to `gravity` (set it every frame for gusts).
    pub wind: Vec3,
    /// Scales of stiffness, damping and gravity from the first joint to the last.
    pub gradient: ChainGradient,
    /// A bone past each last joint, in its local axes (Dynamic Bone's end offset): without it
    /// the last joints do not turn.
    pub end: Option<Vec3>,
    /// The colliders the chain's bones stay out of (entities with a [`ChainCollider`]).
    pub colliders: Vec<Entity>,
    /// A frame in which the first joint moves further than this (world units) is a teleport:
    /// the tips move with it. Infinite (never) by default.
    pub teleport_distance: f32,
    /// Turn joints about the world z axis only (2D).
    pub planar: bool,
    /// The steps per second of the chain's own clock (60 by default, as Dynamic Bone's): the
    /// tips step on a fixed grid of times, and the end of each frame is shown by a step from
    /// the last one, not kept. So the same motion gives the same pose at any frame rate.
    pub rate: f32,
    #[reflect(ignore)]
    state: systems::ChainState,
}

/// How the chain's stiffness, damping and gravity change from its first joint to its last:
/// each is scaled by a factor interpolated linearly by depth, `root` at the first joint and
/// `tip` at the deepest one (a tail that is stiff at the base and loose at the end).
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Debug, PartialEq, Clone, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ChainGradient {
    /// Stiffness factors `[root, tip]`.
    pub stiffness: [f32; 2],
    /// Damping factors `[root, tip]`.
    pub damping: [f32; 2],
    /// Gravity (and wind) factors `[root, tip]`.
    pub gravity: [f32; 2],
}

impl Default for ChainGradient {
    fn default() -> Self {
        Self {
            stiffness: [1.0; 2],
            damping: [1.0; 2],
            gravity: [1.0; 2],
        }
    }
}

/// A joint of a [`SpringChain`] with a spring and a gravity scale of its own, in place of the
/// chain's and its gradient's.
#[derive(Component, Reflect, Debug, Clone, Copy)]
#[reflect(Component, Debug, Clone)]
pub struct ChainJoint {
    /// The spring of this joint's tip.
    pub spring: Spring<f32>,
    /// The scale of the chain's gravity and wind on this joint's tip.
    pub gravity_scale: f32,
}

impl SpringChain {
    /// A chain whose tips follow with `spring`, without gravity or wind.
    #[must_use]
    pub fn new(spring: Spring<f32>) -> Self {
        Self {
            spring,
            gravity: Vec3::ZERO,
            wind: Vec3::ZERO,
            gradient: ChainGradient::default(),
            end: None,
            colliders: Vec::new(),
            teleport_distance: f32::INFINITY,
            planar: false,
            rate: 60.0,
            state: systems::ChainState::default(),
        }
    }

    /// The same, with `gravity`.
    #[must_use]
    pub fn with_gravity(mut self, gravity: Vec3) -> Self {
        self.gravity = gravity;
        self
    }

    /// The same, with `gradient`.
    #[must_use]
    pub fn with_gradient(mut self, gradient: ChainGradient) -> Self {
        self.gradient = gradient;
        self
    }

    /// The same, with a bone `end` past each last joint.
    #[must_use]
    pub fn with_end(mut self, end: Vec3) -> Self {
        self.end = Some(end);
        self
    }

    /// The same, kept out of `colliders`.
    #[must_use]
    pub fn with_colliders(mut self, colliders: impl IntoIterator<Item = Entity>) -> Self {
        self.colliders.extend(colliders);
        self
    }

    /// The same, treating a jump of the first joint further than `distance` as a teleport.
    #[must_use]
    pub fn with_teleport_distance(mut self, distance: f32) -> Self {
        self.teleport_distance = distance;
        self
    }

    /// The same, turning about z only (a 2D chain).
    #[must_use]
    pub fn planar(mut self) -> Self {
        self.planar = true;
        self
    }

    /// Puts every tip at rest where its spring and gravity hold it, at the next step: the
    /// bounce stops.
    pub fn reset(&mut self) {
        self.state.reset = true;
    }

    /// Whether the chain is at rest (nothing stepped or written).
    #[must_use]
    pub fn is_resting(&self) -> bool {
        self.state.resting
    }

    /// The chain's bones as of its last step, root to leaf: each joint, where the pose it
    /// is given puts its bone's tip, and where the spring holds the tip (both in the world).
    /// Nothing before the chain's first step.
    pub fn bones(&self) -> impl Iterator<Item = ChainBone> + '_ {
        self.state.bones()
    }
}

/// One bone of a [`SpringChain`] as of its last step (see [`SpringChain::bones`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChainBone {
    /// The joint the bone turns.
    pub joint: Entity,
    /// Where the joint's rest pose (the pose animation or your code gives it) puts the tip.
    pub rest_tip: Vec3,
    /// Where the tip's spring holds it: the bone points from the joint to here.
    pub tip: Vec3,
}

/// The exact step of one tip: the transition of its spring for the frame's `dt`, kept while
/// `dt` stays the same.
#[derive(Debug, Clone, Copy)]
struct CachedTransition {
    dt: f32,
    transition: Transition<f32>,
}

/// Whether the hierarchy changed (a `ChildOf` inserted, discarded or removed anywhere) since the
/// chains last looked: until it does, they do not look for joints added or removed. Watched
/// from the first chain on.
#[derive(Resource)]
struct Reshaped(bool);

/// The hook of a [`SpringChain`] being added: the first brings in the chain systems and the
/// watch on the hierarchy.
fn chain_added(mut world: DeferredWorld, context: HookContext) {
    first_use::<SpringChain>(world.reborrow(), context);
    if !world.contains_resource::<Reshaped>() {
        world.commands().queue(watch_hierarchy);
    }
}

/// Sets [`Reshaped`] whenever a `ChildOf` comes or goes (a despawn, a re-parenting).
fn watch_hierarchy(world: &mut World) {
    if world.contains_resource::<Reshaped>() {
        return;
    }
    world.insert_resource(Reshaped(true));
    world.add_observer(|_: On<Insert, ChildOf>, mut reshaped: ResMut<Reshaped>| reshaped.0 = true);
    world.add_observer(|_: On<Discard, ChildOf>, mut reshaped: ResMut<Reshaped>| reshaped.0 = true);
}

/// Where chains step: in `PostUpdate`, after animation and the springs (`AnimationSystems`, so
/// a played clip is the rest pose) and before transform propagation.
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct ChainSystems;

/// [`SpringChain`]s (part of [`SpringPlugins`](crate::SpringPlugins)): their systems join with
/// the first chain.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringChainPlugin;

impl Plugin for SpringChainPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<SpringChain>()
            .register_type::<ChainJoint>()
            .register_type::<ChainCollider>()
            .configure_sets(
                PostUpdate,
                ChainSystems
                    .after(AnimationSystems)
                    .before(TransformSystems::Propagate),
            );
        add_systems_on_first_use(
            app,
            &[core::any::TypeId::of::<SpringChain>()],
            PostUpdate,
            |schedule| {
                schedule.add_systems(
                    (
                        systems::warn_jointless,
                        systems::step_chains.in_set(ChainSystems),
                    )
                        .chain()
                        .run_if(any_with_component::<SpringChain>),
                );
            },
        );
    }
}
