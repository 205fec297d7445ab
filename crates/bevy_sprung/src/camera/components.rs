//! The rig and its parts: components on the camera entity.

use alloc::vec::Vec;

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;

use super::framing::CameraFraming;
use sprung::Spring;

use crate::follow::{FixedSamples, TargetMotion};
use crate::space::Linear;
use crate::spring::{PropertySpring, SpringTargetMut};

/// A camera rig: the camera springs after a goal — the point it frames, made of
/// [`CameraTargets`] (or a point you compute) and the optional parts [`LookAhead`],
/// [`DeadZone`], [`ScreenPosition`], [`Confiner`], [`GroupFraming`] and [`OrbitRig`], each a
/// component on the camera entity. Works on 2D (orthographic) and 3D cameras.
///
/// Each frame, in [`SpringUpdate`](crate::spring::SpringUpdate) after gameplay moved the
/// targets, the rig computes the goal ([`CameraGoal`]), shapes it with its parts in
/// [`CameraRigSystems`](super::CameraRigSystems) order, and retargets its springs with the
/// goal's velocity, so every motion is the exact moving-target step: a target moving at a
/// constant velocity is followed at the analytic steady lag `c·v/k`, the same at every frame
/// rate and with no jitter from uneven frames, and a goal you compute yourself gets the same.
/// Horizontal (x and z) and vertical (y) motion have their own springs (a platformer follows
/// jumps more slowly, or not at all while [`hold_vertical`](Self::hold_vertical) is set), and
/// the zoom springs too.
///
/// The rig owns the camera's `Transform` translation (and, when it aims, its rotation) and,
/// for an orthographic camera, its projection's `scale`: it writes them after its springs
/// stepped, and only when they change, so a camera whose goal stands still (a target inside
/// its [`DeadZone`]) is not written and its springs sleep. [`Shake`](crate::juice::Shake) adds
/// on top. Do not also put a `TranslationSpring` or a [`SpringFollow`](crate::follow::SpringFollow)
/// on it.
///
/// On its first frame the camera starts on its goal (no fly-in from the origin).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::camera::{CameraTargets, Confiner, DeadZone, LookAhead, ScreenPosition};
///
/// fn spawn(mut commands: Commands) {
///     let player = commands.spawn(Transform::from_xyz(300.0, 80.0, 0.0)).id();
///     commands.spawn((
///         Camera2d,
///         CameraRig::new(Spring::smooth()).with_vertical(Spring::slow()),
///         CameraTargets::single(player),
///         // The player stays in the lower third, in a dead zone a fifth of the view wide.
///         ScreenPosition(Vec2::new(0.0, -1.0 / 6.0)),
///         DeadZone::view(Vec2::new(0.2, 0.1)),
///         LookAhead::new(0.4),
///         // The level: the view never shows outside it.
///         Confiner::new(Rect::new(0.0, 0.0, 4000.0, 1200.0)).with_slowing_distance(64.0),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, PartialEq)]
#[component(on_remove = stop_rig)]
#[require(
    Transform,
    CameraGoal,
    CameraFraming,
    RigMotion,
    RigTracking,
    RigHorizontalSpring = PropertySpring::new(Spring::smooth(), Vec2::ZERO),
    RigVerticalSpring = PropertySpring::new(Spring::smooth(), 0.0),
    RigZoomSpring = PropertySpring::new(Spring::smooth(), 1.0)
)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct CameraRig {
    /// The spring of the horizontal motion (along x and z).
    pub horizontal: Spring,
    /// The spring of the vertical motion (along y).
    pub vertical: Spring,
    /// The spring of the zoom.
    pub zoom_spring: Spring,
    /// Where the camera is relative to the point it frames, in world units: `(0, 0, z)` for a
    /// 2D camera (its depth), behind and above for a 3D one. For a perspective camera it scales
    /// with the zoom. An [`OrbitRig`] replaces it.
    pub offset: Vec3,
    /// The zoom to spring to, when no [`GroupFraming`] sets it: an orthographic camera's
    /// projection `scale` (1: one world unit per pixel with Bevy's default 2D projection), a
    /// perspective camera's distance factor (1: at [`offset`](Self::offset) or the orbit's
    /// distance). Kept at least `1e-4`.
    pub zoom: f32,
    /// While set, the camera's vertical motion holds where it is (a platformer's camera
    /// ignoring a jump until the player lands); when cleared it springs on, following the goal
    /// with its velocity.
    pub hold_vertical: bool,
    /// Turn the camera to look at the point it frames (3D).
    pub look_at_goal: bool,
    /// A frame in which the goal moves further than this (world units) is a teleport of its
    /// targets (a respawn, a level change): the camera moves with it, keeping its framing and
    /// velocity, instead of reading the jump as motion (which would fling a
    /// [`LookAhead`] far past the target). Infinite (never) by default;
    /// [`TargetWarped`](crate::tracking::TargetWarped) on a target says so explicitly.
    pub teleport_distance: f32,
}

/// The hook of a [`CameraRig`] removed: its springs stay (they were required) but nothing
/// retargets them any more, so their goals stop moving and they come to rest where they aim.
fn stop_rig(mut world: DeferredWorld, context: HookContext) {
    if let Some(mut spring) = world.get_mut::<RigHorizontalSpring>(context.entity) {
        spring.set_target_velocity_if_neq(Vec2::ZERO);
    }
    if let Some(mut spring) = world.get_mut::<RigVerticalSpring>(context.entity) {
        spring.set_target_velocity_if_neq(0.0);
    }
    if let Some(mut spring) = world.get_mut::<RigZoomSpring>(context.entity) {
        spring.set_target_velocity_if_neq(0.0);
    }
}

impl Default for CameraRig {
    fn default() -> Self {
        Self::new(Spring::smooth())
    }
}

impl CameraRig {
    /// A rig whose motion and zoom all use `spring`, at no offset, zoom 1, not aiming.
    #[must_use]
    pub fn new(spring: Spring) -> Self {
        Self {
            horizontal: spring,
            vertical: spring,
            zoom_spring: spring,
            offset: Vec3::ZERO,
            zoom: 1.0,
            hold_vertical: false,
            look_at_goal: false,
            teleport_distance: f32::INFINITY,
        }
    }

    /// The same rig with `spring` for its vertical motion.
    #[must_use]
    pub fn with_vertical(mut self, spring: Spring) -> Self {
        self.vertical = spring;
        self
    }

    /// The same rig with `spring` for its zoom.
    #[must_use]
    pub fn with_zoom_spring(mut self, spring: Spring) -> Self {
        self.zoom_spring = spring;
        self
    }

    /// The same rig at `offset` from the point it frames (see [`offset`](Self::offset)).
    #[must_use]
    pub fn with_offset(mut self, offset: Vec3) -> Self {
        self.offset = offset;
        self
    }

    /// The same rig at zoom `zoom` (see [`zoom`](Self::zoom)).
    #[must_use]
    pub fn with_zoom(mut self, zoom: f32) -> Self {
        self.zoom = zoom;
        self
    }

    /// The same rig turning the camera toward the point it frames.
    #[must_use]
    pub fn looking_at_goal(mut self) -> Self {
        self.look_at_goal = true;
        self
    }

    /// The same rig, treating a move of its goal further than `distance` in one frame as a
    /// teleport (see [`teleport_distance`](Self::teleport_distance)).
    #[must_use]
    pub fn with_teleport_distance(mut self, distance: f32) -> Self {
        self.teleport_distance = distance;
        self
    }
}

/// What a [`CameraRig`] aims for this frame: the point to frame and how much around it must be
/// seen. [`CameraTargets`] write it in [`CameraRigSystems::Targets`](super::CameraRigSystems);
/// change it or write your own in [`CameraRigSystems::Goal`](super::CameraRigSystems) — a goal
/// you compute is followed with the exact moving-target step like any other (its velocity is
/// taken from its successive positions and the frame's time step). A non-finite goal is
/// ignored (the previous one is kept).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::camera::CameraGoal;
/// use bevy_sprung::camera::CameraRigSystems;
/// use bevy_sprung::spring::SpringUpdate;
///
/// #[derive(Component)]
/// struct Player;
///
/// // Frame a point between the player and the cursor (here: fixed), a third of the way.
/// fn aim_between(players: Query<&Transform, With<Player>>, mut goals: Query<&mut CameraGoal>) {
///     let cursor = Vec3::new(500.0, 0.0, 0.0);
///     for player in &players {
///         for mut goal in &mut goals {
///             goal.point = player.translation.lerp(cursor, 1.0 / 3.0);
///         }
///     }
/// }
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugins::default()))
///     .add_systems(SpringUpdate, aim_between.in_set(CameraRigSystems::Goal));
/// app.world_mut().spawn((Player, Transform::default()));
/// app.world_mut().spawn(CameraRig::new(Spring::smooth()));
/// app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Debug, Clone, PartialEq, Default)]
pub struct CameraGoal {
    /// The world point the camera frames.
    pub point: Vec3,
    /// How far around [`point`](Self::point) must be seen, in world units along the camera's
    /// right and up axes (the targets' extent with their radii); what [`GroupFraming`] zooms
    /// to fit.
    pub spread: Vec2,
}

/// One entity a [`CameraRig`] frames.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Debug, Clone, PartialEq)]
pub struct CameraTarget {
    /// The entity (its `Transform`, placed by its ancestors' `Transform`s as they are this frame).
    pub entity: Entity,
    /// Its share of the framed point: the point is the weighted centre of the targets. A
    /// weight that is not positive and finite leaves the target out.
    pub weight: f32,
    /// How much around it must be seen, in world units (for [`GroupFraming`]).
    pub radius: f32,
}

impl CameraTarget {
    /// `entity`, with weight 1 and radius 0.
    #[must_use]
    pub fn new(entity: Entity) -> Self {
        Self {
            entity,
            weight: 1.0,
            radius: 0.0,
        }
    }

    /// The same target with weight `weight`.
    #[must_use]
    pub fn with_weight(mut self, weight: f32) -> Self {
        self.weight = weight;
        self
    }

    /// The same target with radius `radius`.
    #[must_use]
    pub fn with_radius(mut self, radius: f32) -> Self {
        self.radius = radius;
        self
    }
}

/// The entities a [`CameraRig`] frames: its goal is their weighted centre, and their spread
/// (with their radii) is what [`GroupFraming`] keeps in view. Targets that are gone (despawned,
/// or without a `Transform`) are left out; with none left, the camera comes to rest on its
/// last goal.
///
/// Targets that move in `FixedUpdate` (fixed-timestep gameplay or physics) are sampled after
/// each fixed step and followed between steps along their fixed-step velocity
/// ([`moving_in_fixed_update`](Self::moving_in_fixed_update), as
/// [`SpringFollow`](crate::follow::SpringFollow) does): frames and fixed steps that do not line
/// up then give a steady lag with no jitter.
#[derive(Component, Reflect, Debug, Clone, PartialEq, Default)]
#[component(on_add = crate::spring::first_use::<CameraTargets>)]
#[reflect(Component, Debug, Clone, PartialEq, Default)]
pub struct CameraTargets {
    /// The targets.
    pub targets: Vec<CameraTarget>,
    /// How they move.
    pub motion: TargetMotion,
    /// Each target's last fixed-step positions (`TargetMotion::FixedTimestep`).
    #[reflect(ignore)]
    pub(crate) fixed: Vec<FixedSamples>,
}

impl CameraTargets {
    /// Frame `entity` alone.
    #[must_use]
    pub fn single(entity: Entity) -> Self {
        Self::new([entity])
    }

    /// Frame these targets (entities or [`CameraTarget`]s).
    #[must_use]
    pub fn new(targets: impl IntoIterator<Item = impl Into<CameraTarget>>) -> Self {
        Self {
            targets: targets.into_iter().map(Into::into).collect(),
            motion: TargetMotion::PerFrame,
            fixed: Vec::new(),
        }
    }

    /// The targets move in `FixedUpdate`: see [`TargetMotion::FixedTimestep`].
    #[must_use]
    pub fn moving_in_fixed_update(mut self) -> Self {
        self.motion = TargetMotion::FixedTimestep;
        self
    }
}

impl From<Entity> for CameraTarget {
    fn from(entity: Entity) -> Self {
        Self::new(entity)
    }
}

/// Frames ahead of where the goal is heading: an offset of the goal's velocity times
/// [`time`](Self::time), smoothed by its own spring so that turning round swings the view
/// over instead of snapping it. For a goal at constant velocity the offset rests at exactly
/// `velocity · time`.
///
/// **What is seen on screen** is less than `v·T`: the camera follows the look-ahead point with
/// the rig's steady lag `c·v/k`, and a [`DeadZone`] lets the point run half the zone ahead
/// before the camera moves, so the screen centre leads the target by `v·T − c·v/k − zone/2`
/// (with `v = 600`, `T = 0.4`, `c/k = 0.25 s` and a zone 160 px wide: 240 − 150 − 80 = 10 px).
/// For a wanted on-screen lead `L`, set `time = L/v + c/k + zone/(2v)`; a stiffer horizontal
/// spring (smaller `c/k`) or a narrower zone leaves more of `v·T` on screen.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[require(RigLookAheadSpring = PropertySpring::new(Spring::smooth(), Vec3::ZERO))]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct LookAhead {
    /// How far ahead, in seconds of the goal's motion.
    pub time: f32,
    /// The spring the offset moves with.
    pub spring: Spring,
    /// Look ahead vertically too (off by default: a platformer should not look down when the
    /// player falls).
    pub vertical: bool,
}

impl LookAhead {
    /// `time` seconds ahead, horizontally, with a smooth spring.
    #[must_use]
    pub fn new(time: f32) -> Self {
        Self {
            time,
            spring: Spring::smooth(),
            vertical: false,
        }
    }

    /// The same look-ahead with `spring`.
    #[must_use]
    pub fn with_spring(mut self, spring: Spring) -> Self {
        self.spring = spring;
        self
    }

    /// The same look-ahead along every axis.
    #[must_use]
    pub fn with_vertical(mut self) -> Self {
        self.vertical = true;
        self
    }
}

/// The unit of a [`DeadZone`]'s size.
#[derive(Reflect, Debug, Clone, Copy, PartialEq, Eq, Default)]
#[reflect(Debug, Clone, PartialEq, Default)]
pub enum ZoneUnit {
    /// Fractions of the view's width and height (at the current zoom).
    #[default]
    View,
    /// World units.
    World,
}

/// A region around the framed point within which the goal may move without moving the camera:
/// the camera's goal moves only as far as needed to keep the point inside (and a spring pulls
/// the camera after it: the soft zone). While the point moves inside it, the camera is at rest,
/// asleep, and its `Transform` is not written.
///
/// The size is the whole width and height (horizontal along x and z, vertical along y). The
/// zone is centred on its anchor (where the [`ScreenPosition`] puts the framed point) unless
/// [`offset`](Self::offset) moves it: its four sides are then set on their own
/// ([`view_sides`](Self::view_sides), [`world_sides`](Self::world_sides)), as a platformer that
/// lets the player walk further right than left before the camera moves.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::camera::{DeadZone, ZoneSides};
///
/// // The player walks three eighths of the view to the right, an eighth to the left, before
/// // the camera follows; up and down a sixteenth.
/// let sides = ZoneSides { left: 0.125, right: 0.375, down: 0.0625, up: 0.0625 };
/// let zone = DeadZone::view_sides(sides);
/// assert_eq!(zone.size, Vec2::new(0.5, 0.125));
/// assert_eq!(zone.sides(), sides);
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct DeadZone {
    /// Width and height of the zone.
    pub size: Vec2,
    /// How far the zone's centre is from its anchor, in the same unit (positive: right and
    /// up). Zero for a zone centred on the point it holds.
    pub offset: Vec2,
    /// What `size` and `offset` are measured in.
    pub unit: ZoneUnit,
}

/// How far a [`DeadZone`] reaches from its anchor toward each side, in its unit: the framed
/// point moves that far left (−x), right (+x), down (−y) or up (+y) before the camera
/// follows.
#[derive(Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Debug, Clone, PartialEq, Default)]
pub struct ZoneSides {
    /// Toward −x.
    pub left: f32,
    /// Toward +x.
    pub right: f32,
    /// Toward −y.
    pub down: f32,
    /// Toward +y.
    pub up: f32,
}

impl DeadZone {
    /// A zone `size` in fractions of the view (`0.2`: a fifth of its width).
    #[must_use]
    pub fn view(size: Vec2) -> Self {
        Self {
            size,
            offset: Vec2::ZERO,
            unit: ZoneUnit::View,
        }
    }

    /// A zone `size` in world units.
    #[must_use]
    pub fn world(size: Vec2) -> Self {
        Self {
            size,
            offset: Vec2::ZERO,
            unit: ZoneUnit::World,
        }
    }

    /// A zone whose sides are `sides` fractions of the view's width (left, right) and height
    /// (down, up) from its anchor.
    #[must_use]
    pub fn view_sides(sides: ZoneSides) -> Self {
        Self::from_sides(sides, ZoneUnit::View)
    }

    /// A zone whose sides are `sides` world units from its anchor.
    #[must_use]
    pub fn world_sides(sides: ZoneSides) -> Self {
        Self::from_sides(sides, ZoneUnit::World)
    }

    fn from_sides(sides: ZoneSides, unit: ZoneUnit) -> Self {
        Self {
            size: Vec2::new(sides.left + sides.right, sides.down + sides.up),
            offset: 0.5 * Vec2::new(sides.right - sides.left, sides.up - sides.down),
            unit,
        }
    }

    /// How far the zone reaches from its anchor toward each side, in its unit (the sides it
    /// was made from, to rounding).
    #[must_use]
    pub fn sides(&self) -> ZoneSides {
        let half = 0.5 * self.size;
        ZoneSides {
            left: half.x - self.offset.x,
            right: half.x + self.offset.x,
            down: half.y - self.offset.y,
            up: half.y + self.offset.y,
        }
    }

    /// The zone's centre from its anchor in world units (x and y; a 3D zone is centred along
    /// z), for a view of `half_view` half extents. Non-finite offsets count as 0.
    #[must_use]
    pub fn offset_in(&self, half_view: Vec2) -> Vec2 {
        let offset = match self.unit {
            ZoneUnit::View => self.offset * 2.0 * half_view,
            ZoneUnit::World => self.offset,
        };
        if offset.is_finite() {
            offset
        } else {
            Vec2::ZERO
        }
    }

    /// The zone's half width and half height in world units, for a view of `half_view` half
    /// extents. Negative or non-finite sizes count as 0.
    #[must_use]
    pub fn half_size(&self, half_view: Vec2) -> Vec2 {
        let size = match self.unit {
            ZoneUnit::View => self.size * half_view,
            ZoneUnit::World => self.size * 0.5,
        };
        if size.is_finite() {
            size.max(Vec2::ZERO)
        } else {
            Vec2::ZERO
        }
    }
}

/// An outer limit that keeps the goal's point (the target, without look-ahead) on screen when
/// it outruns the follow spring (a dash, a fall): a rectangle `size` wide and high, centred on
/// the view, that the point never leaves.
///
/// Cinemachine clamps at its hard limits, a jump in the camera's velocity. Here the camera is
/// carried along instead: over the [`slowing`](Self::slowing) band inside the limit, the
/// point's offset from the view is eased by a smooth map whose slope falls from 1 to 0 (the
/// confiner's map), so the camera's velocity changes continuously and its acceleration stays
/// bounded: by twice the target's acceleration, plus the follow spring's own, plus
/// `v²/(2·slowing)` for the point's speed `v` relative to the spring. A `slowing` of 0 is
/// Cinemachine's clamp. Horizontal along x, vertical along y, as a [`DeadZone`]; a
/// [`Confiner`] still has the last word.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::camera::{CameraTargets, HardLimit};
/// use bevy_sprung::prelude::*;
///
/// fn camera_following(player: Entity) -> impl Bundle {
///     (
///         Camera2d,
///         CameraRig::new(Spring::smooth()),
///         CameraTargets::single(player),
///         // The player never gets closer to the window's edge than a twentieth of it.
///         HardLimit::view(Vec2::splat(0.9)),
///     )
/// }
/// # let _ = camera_following(Entity::PLACEHOLDER);
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct HardLimit {
    /// Width and height of the rectangle the point stays in.
    pub size: Vec2,
    /// How far inside the limit the camera starts to be carried, in the same unit (of the
    /// view's width, for [`ZoneUnit::View`]).
    pub slowing: f32,
    /// What `size` and `slowing` are measured in.
    pub unit: ZoneUnit,
}

impl HardLimit {
    /// A limit `size` in fractions of the view, eased in over a tenth of the view.
    #[must_use]
    pub fn view(size: Vec2) -> Self {
        Self {
            size,
            slowing: 0.1,
            unit: ZoneUnit::View,
        }
    }

    /// A limit `size` in world units, eased in over a tenth of its smaller side.
    #[must_use]
    pub fn world(size: Vec2) -> Self {
        Self {
            size,
            slowing: 0.1 * size.min_element(),
            unit: ZoneUnit::World,
        }
    }

    /// The same limit, eased in over `slowing` (its unit); 0 clamps.
    #[must_use]
    pub fn with_slowing(mut self, slowing: f32) -> Self {
        self.slowing = slowing;
        self
    }

    /// The limit's half extents and its slowing band in world units, for a view of
    /// `half_view` half extents. Negative or non-finite values count as 0.
    #[must_use]
    pub fn in_world(&self, half_view: Vec2) -> (Vec2, f32) {
        let (half, slowing) = match self.unit {
            ZoneUnit::View => (self.size * half_view, self.slowing * 2.0 * half_view.x),
            ZoneUnit::World => (self.size * 0.5, self.slowing),
        };
        let half = if half.is_finite() {
            half.max(Vec2::ZERO)
        } else {
            Vec2::ZERO
        };
        let slowing = if slowing.is_finite() {
            slowing.max(0.0)
        } else {
            0.0
        };
        (half, slowing)
    }
}

/// Where on screen the framed point sits, from the view's centre in fractions of its width and
/// height (x right, y up): `(0, -1/6)` puts it on the lower third. Without it, in the centre.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Debug, Clone, PartialEq, Default)]
pub struct ScreenPosition(pub Vec2);

/// Keeps the camera's view inside `bounds` (the level): an orthographic camera's whole view,
/// from its projection, window and zoom; a perspective camera's footprint at the framed
/// point's distance (a side view looking along −z). Within
/// [`slowing_distance`](Self::slowing_distance) of an edge the camera slows down and stops at
/// the edge as a moving spring would come to rest, never with a jump in its velocity: its
/// position is eased into the bounds by a smooth map whose slope falls from 1 to 0 over the
/// slowing distance. Right at every frame, zoom and window size, and after a hitch. A view
/// larger than the bounds is centred on them.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct Confiner {
    /// The region the view stays in, in world x and y.
    pub bounds: Rect,
    /// Over how much distance, in world units, the camera slows down before an edge (0: it
    /// stops dead).
    pub slowing_distance: f32,
}

impl Confiner {
    /// The view stays in `bounds`, slowing over 0 units (add one with
    /// [`with_slowing_distance`](Self::with_slowing_distance)).
    #[must_use]
    pub fn new(bounds: Rect) -> Self {
        Self {
            bounds,
            slowing_distance: 0.0,
        }
    }

    /// The same confiner slowing over `distance` world units.
    #[must_use]
    pub fn with_slowing_distance(mut self, distance: f32) -> Self {
        self.slowing_distance = distance;
        self
    }
}

/// Keeps the camera's position inside a box (a room, a corridor; Cinemachine's Confiner 3D),
/// with the same slowing: within [`slowing_distance`](Self::slowing_distance) of a wall the
/// camera slows down and stops at it, never with a jump in its velocity. Applied last, after an
/// orbit or an occluder placed the camera; an orbiting camera pushed off its sphere by a wall
/// keeps its orientation. For the view of a 2D or side-on camera, use [`Confiner`].
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct ConfinerVolume {
    /// The box's least corner.
    pub min: Vec3,
    /// The box's greatest corner.
    pub max: Vec3,
    /// Over how much distance, in world units, the camera slows down before a wall.
    pub slowing_distance: f32,
}

impl ConfinerVolume {
    /// The camera stays between `min` and `max`, slowing over 0 units.
    #[must_use]
    pub fn new(min: Vec3, max: Vec3) -> Self {
        Self {
            min,
            max,
            slowing_distance: 0.0,
        }
    }

    /// The same volume slowing over `distance` world units.
    #[must_use]
    pub fn with_slowing_distance(mut self, distance: f32) -> Self {
        self.slowing_distance = distance;
        self
    }
}

/// Zooms so that every target of [`CameraTargets`] (with its radius) stays in view, with
/// `margin` of the view free on each side: the zoom springs to fit them
/// ([`CameraRig::zoom_spring`]) within `min_zoom..=max_zoom`. The framed point is their
/// weighted centre.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct GroupFraming {
    /// The fraction of the view's width and height kept free on each side (0.1: the targets
    /// fill at most the middle 80 %). Kept within `0..=0.45`.
    pub margin: f32,
    /// The least zoom (closest in).
    pub min_zoom: f32,
    /// The greatest zoom (furthest out).
    pub max_zoom: f32,
}

impl GroupFraming {
    /// Fit the targets with `margin` free on each side, at zoom 0.1 to 10.
    #[must_use]
    pub fn new(margin: f32) -> Self {
        Self {
            margin,
            min_zoom: 0.1,
            max_zoom: 10.0,
        }
    }

    /// The same framing within `min..=max` zoom.
    #[must_use]
    pub fn with_zoom_range(mut self, min: f32, max: f32) -> Self {
        self.min_zoom = min;
        self.max_zoom = max;
        self
    }

    /// The zoom that fits `spread` (half extents around the framed point) into a view whose
    /// half extents are `half_view` at zoom 1. `None` if the view is unknown.
    #[must_use]
    pub fn zoom_to_fit(&self, spread: Vec2, half_view: Vec2) -> Option<f32> {
        if !(half_view.x > 0.0 && half_view.y > 0.0) {
            return None;
        }
        let free = 1.0 - 2.0 * self.margin.clamp(0.0, 0.45);
        let needed = (spread / (half_view * free)).max_element();
        let (low, high) = (
            self.min_zoom.max(1e-4),
            self.max_zoom.max(self.min_zoom.max(1e-4)),
        );
        needed.is_finite().then(|| needed.clamp(low, high))
    }
}

/// Orbits the framed point: the camera sits at [`distance`](Self::distance) from it, turned by
/// [`yaw`](Self::yaw) about the vertical and tilted down by [`pitch`](Self::pitch), looking at
/// it. Yaw, pitch and distance spring in these polar coordinates (one spring,
/// [`spring`](Self::spring)), so orbiting never changes the distance, and zooming is a spring
/// on the distance.
///
/// Yaw 0 (and pitch 0) puts the camera on the pivot's `+Z` side looking along `−Z` (Bevy's
/// forward); a positive yaw turns it about `+Y` toward `+X`, a positive pitch raises it.
///
/// Drive it from input by changing its targets — [`rotate`](Self::rotate) by mouse motion or a
/// stick, [`zoom_by`](Self::zoom_by) by the wheel — or by setting the fields. Pitch and
/// distance are kept within their limits.
///
/// # Example
/// ```
/// use bevy::input::mouse::AccumulatedMouseMotion;
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::camera::OrbitRig;
///
/// fn orbit_with_mouse(motion: Res<AccumulatedMouseMotion>, mut orbits: Query<&mut OrbitRig>) {
///     for mut orbit in &mut orbits {
///         orbit.rotate(-motion.delta * 0.005);
///     }
/// }
/// # let _ = bevy::ecs::system::IntoSystem::into_system(orbit_with_mouse);
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[require(RigOrbitSpring = PropertySpring::new(Spring::smooth(), Vec3::new(0.0, 0.0, 1.0)))]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct OrbitRig {
    /// The turn about the vertical axis, in radians (unwrapped: whole turns spring through).
    pub yaw: f32,
    /// The tilt down toward the point, in radians.
    pub pitch: f32,
    /// The distance from the point.
    pub distance: f32,
    /// The least and greatest pitch.
    pub pitch_limits: Vec2,
    /// The least and greatest distance.
    pub distance_limits: Vec2,
    /// The spring of yaw, pitch and distance.
    pub spring: Spring,
}

impl OrbitRig {
    /// An orbit at `distance`, looking along −z, tilted down by 0.3 rad, with pitch within
    /// ±1.5 rad and distance within `distance/10..=distance·10`.
    #[must_use]
    pub fn new(distance: f32) -> Self {
        Self {
            yaw: 0.0,
            pitch: 0.3,
            distance,
            pitch_limits: Vec2::new(-1.5, 1.5),
            distance_limits: Vec2::new(distance * 0.1, distance * 10.0),
            spring: Spring::smooth(),
        }
    }

    /// Turn by `delta.x` radians of yaw and `delta.y` of pitch (pitch kept in its limits).
    pub fn rotate(&mut self, delta: Vec2) {
        if delta.is_finite() {
            self.yaw += delta.x;
            self.pitch = (self.pitch + delta.y).clamp(
                self.pitch_limits.x,
                self.pitch_limits.y.max(self.pitch_limits.x),
            );
        }
    }

    /// Multiply the distance by `factor` (kept in its limits).
    pub fn zoom_by(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.distance = (self.distance * factor).clamp(
                self.distance_limits.x,
                self.distance_limits.y.max(self.distance_limits.x),
            );
        }
    }

    /// The same orbit with its yaw and pitch.
    #[must_use]
    pub fn with_angles(mut self, yaw: f32, pitch: f32) -> Self {
        self.yaw = yaw;
        self.pitch = pitch;
        self
    }

    /// The same orbit with its pitch and distance limits.
    #[must_use]
    pub fn with_limits(mut self, pitch: Vec2, distance: Vec2) -> Self {
        self.pitch_limits = pitch;
        self.distance_limits = distance;
        self
    }

    /// The same orbit with `spring`.
    #[must_use]
    pub fn with_spring(mut self, spring: Spring) -> Self {
        self.spring = spring;
        self
    }

    /// Where the orbit aims: `(yaw, pitch, distance)` with pitch and distance in their limits
    /// (a non-finite value keeps `previous`'s).
    #[must_use]
    pub(crate) fn aim(&self, previous: Vec3) -> Vec3 {
        let pitch_high = self.pitch_limits.y.max(self.pitch_limits.x);
        let distance_low = self.distance_limits.x.max(1e-4);
        let distance_high = self.distance_limits.y.max(distance_low);
        let aim = Vec3::new(
            self.yaw,
            self.pitch.clamp(self.pitch_limits.x, pitch_high),
            self.distance.clamp(distance_low, distance_high),
        );
        if aim.is_finite() { aim } else { previous }
    }
}

/// The rotation of an orbit at `yaw` and `pitch`: the camera looks along its −z at the point.
#[inline]
#[must_use]
pub(crate) fn orbit_rotation(yaw: f32, pitch: f32) -> Quat {
    Quat::from_euler(EulerRot::YXZ, yaw, -pitch, 0.0)
}

/// The sprung values of a [`CameraRig`]: the centre of its view (before it is eased into a
/// [`Confiner`]), its look-ahead offset, zoom and orbit. The rig's springs move it; read it
/// to see where a rig is heading.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, Clone, PartialEq, Default)]
pub struct RigMotion {
    horizontal: Vec2,
    vertical: f32,
    look_ahead: Vec3,
    zoom: f32,
    orbit: Vec3,
    clearance: f32,
}

impl Default for RigMotion {
    fn default() -> Self {
        Self {
            horizontal: Vec2::ZERO,
            vertical: 0.0,
            look_ahead: Vec3::ZERO,
            zoom: 1.0,
            orbit: Vec3::new(0.0, 0.0, 1.0),
            clearance: 1.0,
        }
    }
}

impl RigMotion {
    /// The centre of the view the springs hold, before a [`Confiner`] eases it.
    #[must_use]
    pub fn centre(&self) -> Vec3 {
        Vec3::new(self.horizontal.x, self.vertical, self.horizontal.y)
    }

    /// Places the centre (a first frame's snap).
    pub(crate) fn set_centre(&mut self, centre: Vec3) {
        self.horizontal = Vec2::new(centre.x, centre.z);
        self.vertical = centre.y;
    }

    /// The look-ahead offset.
    #[must_use]
    pub fn look_ahead(&self) -> Vec3 {
        self.look_ahead
    }

    /// The zoom, at least `1e-4`.
    #[must_use]
    pub fn zoom(&self) -> f32 {
        if self.zoom.is_finite() {
            self.zoom.max(1e-4)
        } else {
            1.0
        }
    }

    /// Sets the zoom (a first frame's snap).
    pub(crate) fn set_zoom(&mut self, zoom: f32) {
        self.zoom = zoom;
    }

    /// Yaw, pitch and distance of the orbit.
    #[must_use]
    pub fn orbit(&self) -> Vec3 {
        self.orbit
    }

    /// Sets the orbit (a first frame's snap).
    pub(crate) fn set_orbit(&mut self, orbit: Vec3) {
        self.orbit = orbit;
    }

    /// How much of its arm the camera has clear of occluders, from 0 to 1 (1 without
    /// occlusion).
    #[must_use]
    pub fn clearance(&self) -> f32 {
        if self.clearance.is_finite() {
            self.clearance.clamp(0.0, 1.0)
        } else {
            1.0
        }
    }

    /// Pulls the camera in to `clearance` of its arm (an occluder between it and the point).
    #[cfg(feature = "camera_occlusion")]
    pub(crate) fn set_clearance(&mut self, clearance: f32) {
        self.clearance = clearance;
    }
}

spring_property!(
    /// A rig's horizontal motion (x and z of the centre of its view).
    pub RigHorizontal: RigMotion::horizontal as Linear<Vec2>
);
spring_property!(
    /// A rig's vertical motion (y of the centre of its view).
    pub RigVertical: RigMotion::vertical as Linear<f32>
);
spring_property!(
    /// A rig's look-ahead offset.
    pub RigLookAhead: RigMotion::look_ahead as Linear<Vec3>
);
spring_property!(
    /// A rig's zoom.
    pub RigZoom: RigMotion::zoom as Linear<f32>
);
spring_property!(
    /// A rig's orbit: yaw, pitch and distance.
    pub RigOrbit: RigMotion::orbit as Linear<Vec3>
);

#[cfg(feature = "camera_occlusion")]
spring_property!(
    /// How much of its arm a rig's camera has clear of occluders (see
    /// [`CameraOcclusion`](super::CameraOcclusion)).
    pub RigClearance: RigMotion::clearance as Linear<f32>
);

/// The spring of a rig's clearance: how the camera moves back out once an occluder is gone.
#[cfg(feature = "camera_occlusion")]
pub type RigClearanceSpring = PropertySpring<RigClearance>;

/// The spring of a rig's horizontal motion.
pub type RigHorizontalSpring = PropertySpring<RigHorizontal>;
/// The spring of a rig's vertical motion.
pub type RigVerticalSpring = PropertySpring<RigVertical>;
/// The spring of a rig's look-ahead.
pub type RigLookAheadSpring = PropertySpring<RigLookAhead>;
/// The spring of a rig's zoom.
pub type RigZoomSpring = PropertySpring<RigZoom>;
/// The spring of a rig's orbit.
pub type RigOrbitSpring = PropertySpring<RigOrbit>;

/// What a rig remembers between frames.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Default)]
pub(crate) struct RigTracking {
    /// The goal's point last frame, for its velocity.
    pub(crate) last_point: Option<Vec3>,
    /// The goal's velocity this frame.
    pub(crate) point_velocity: Vec3,
    /// Where the dead zone holds the goal.
    pub(crate) held: Option<Vec3>,
    /// The centre the rig aimed for last frame (before a held vertical), for its velocity.
    pub(crate) last_centre: Option<Vec3>,
    /// The zoom the rig aimed for last frame, for its rate.
    pub(crate) last_zoom: Option<f32>,
    /// Explicit warps of the goal ([`TargetWarped`](crate::tracking::TargetWarped) on its
    /// targets, by their shares) not yet applied.
    pub(crate) warp: Vec3,
    /// The goal was carried this frame: the centre keeps last frame's velocity.
    pub(crate) warped: bool,
    /// Where the rig stood against its zones last frame, for their events.
    pub(crate) contact: Option<ZoneContact>,
}

/// Where a rig stands against its zones: whether its framed point pushes its dead zone, and
/// whether its camera is at its confiner's edge.
#[derive(Reflect, Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct ZoneContact {
    pub(crate) pushes_dead_zone: bool,
    pub(crate) at_hard_limit: bool,
    pub(crate) at_confiner_edge: bool,
}

impl RigTracking {
    /// The goal was carried by `shift` without travelling: what the rig remembers of where it
    /// was moves with it, so that framing is kept and no velocity is read from the jump.
    pub(crate) fn carry(&mut self, shift: Vec3) {
        for place in [&mut self.last_point, &mut self.held, &mut self.last_centre]
            .into_iter()
            .flatten()
        {
            *place += shift;
        }
        self.warped = true;
    }
}
