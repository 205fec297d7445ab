//! A camera on a rail: Cinemachine's spline dolly. The camera lives on a curve and springs
//! along it, in distance along the curve, to the point nearest its target, a point ahead of
//! that, or a place the game drives.

mod track;

use core::any::TypeId;

use bevy::log::warn_once;
use bevy::math::cubic_splines::CubicCurve;
use bevy::prelude::*;
use bevy::window::{PrimaryWindow, Window};
use sprung::Spring;

use super::components::{CameraGoal, CameraRig, RigMotion, RigTracking};
use super::systems::{CameraRigSystems, Posed, compose_cameras, track_goals};
use crate::clock::SpringTime;
use crate::property_plugin::SpringPropertyPlugin;
use crate::space::Linear;
use crate::spring::{PropertySpring, SpringTargetMut, add_property_systems};

pub(crate) use track::RailTrack;

/// Puts a [`CameraRig`]'s camera on a rail, Cinemachine's spline dolly: the camera lives on
/// [`curve`](Self::curve) (any `bevy_math` cubic curve: Bézier, Catmull-Rom, B-spline, Hermite)
/// and springs along it to the place [`follow`](Self::follow) picks, turning to look at the
/// point the rig frames. The spring moves in distance along the curve, so the camera keeps to
/// the rail round every bend, and with the rail's velocity given to the step, a target moving
/// at a constant speed along a straight stretch is followed at the analytic lag `c·v/k` at
/// every frame rate. A [`looped`](Self::looped) rail wraps without a jump and the camera takes
/// the shorter way round.
///
/// The rig's parts shape what the camera looks at, as they do without a rail: its dead zone,
/// screen position, look-ahead, hard limit and confiner move the framed point, and the camera
/// turns toward it from the rail. The rig's [`offset`](CameraRig::offset) sets only the
/// distance at which a perspective view's [`DeadZone::view`](super::DeadZone::view) and the
/// like are measured. The rail replaces the rig's arm: it does not combine with an
/// [`OrbitRig`](super::OrbitRig) or a [`CameraOcclusion`](super::CameraOcclusion).
///
/// - A target warped ([`TargetWarped`](crate::tracking::TargetWarped), or beyond the rig's
///   [`teleport_distance`](CameraRig::teleport_distance)) carries the camera to the place on
///   the rail nearest its new position, keeping its lag and velocity: a warp, not a fling.
/// - A curve replaced mid-follow puts the camera at the place on the new rail nearest where it
///   stood, with its velocity along the rail, and it springs on from there.
/// - With the rail removed, the rig places the camera again by its offset from the point it
///   frames (at once: blend between two shots, [`CameraBlend`](super::CameraBlend), for a
///   smooth change).
///
/// # Example
/// ```
/// use bevy::math::cubic_splines::{CubicCardinalSpline, CubicGenerator};
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::camera::{CameraRail, CameraTargets};
///
/// fn spawn(mut commands: Commands) {
///     let player = commands.spawn(Transform::default()).id();
///     // A dolly track along one side of the arena, two metres up.
///     let track = CubicCardinalSpline::new_catmull_rom([
///         Vec3::new(-20.0, 2.0, 8.0),
///         Vec3::new(-8.0, 3.0, 12.0),
///         Vec3::new(8.0, 3.0, 12.0),
///         Vec3::new(20.0, 2.0, 8.0),
///     ])
///     .to_curve()
///     .unwrap();
///     commands.spawn((
///         Camera3d::default(),
///         CameraRig::new(Spring::smooth()),
///         CameraTargets::single(player),
///         CameraRail::new(track).with_spring(Spring::smooth()),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, PartialEq)]
#[require(
    CameraRig,
    RailMotion,
    RailState,
    RigRailSpring = PropertySpring::new(Spring::smooth(), 0.0)
)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct CameraRail {
    /// The rail, in world space.
    pub curve: CubicCurve<Vec3>,
    /// Whether the rail's end joins its start (build the curve with `to_curve_cyclic`). A
    /// looped rail that is not closed warns once.
    pub looped: bool,
    /// Which place on the rail the camera springs to.
    pub follow: RailFollow,
    /// The spring along the rail.
    pub spring: Spring,
    /// Which way the camera looks from the rail.
    pub aim: RailAim,
    /// The camera's roll about its view direction along the rail, in radians: a curve sampled
    /// at the same fraction of its segments as the rail's place is of the rail's (one segment
    /// of roll per segment of rail reads the roll at each of the rail's points).
    pub roll: Option<CubicCurve<f32>>,
}

/// Which place on a [`CameraRail`] the camera springs to.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Debug, Clone, PartialEq)]
pub enum RailFollow {
    /// The place nearest the rig's goal (its targets).
    Nearest,
    /// This far (world units) along the rail past the place nearest the goal: negative to
    /// trail behind it.
    Ahead(f32),
    /// The game drives the camera: a position from 0 (the rail's start) to 1 (its end), the
    /// fraction of the rail's length; on a looped rail any value, wrapped.
    Driven(f32),
}

/// Which way a camera on a [`CameraRail`] looks.
#[derive(Reflect, Debug, Clone, Copy, PartialEq, Eq, Default)]
#[reflect(Debug, Clone, PartialEq, Default)]
pub enum RailAim {
    /// At the point the rig frames (Cinemachine's rotation composer).
    #[default]
    AtFocus,
    /// Along the rail, the way it runs (a ride).
    Along,
    /// The camera's rotation is left as it is (a 2D camera on a rail in its plane). Nothing
    /// turns to the point the rig frames, so the rig's dead zone, screen position and hard
    /// limit shape nothing the camera shows.
    Unchanged,
}

impl CameraRail {
    /// A camera on the open rail `curve`, at the place nearest its target, springing along it
    /// smoothly and looking at the point the rig frames.
    #[must_use]
    pub fn new(curve: CubicCurve<Vec3>) -> Self {
        Self {
            curve,
            looped: false,
            follow: RailFollow::Nearest,
            spring: Spring::smooth(),
            aim: RailAim::AtFocus,
            roll: None,
        }
    }

    /// The same rail, looped: its end joins its start.
    #[must_use]
    pub fn looped(mut self) -> Self {
        self.looped = true;
        self
    }

    /// The same rail, following `follow`.
    #[must_use]
    pub fn following(mut self, follow: RailFollow) -> Self {
        self.follow = follow;
        self
    }

    /// The same rail, springing along it with `spring`.
    #[must_use]
    pub fn with_spring(mut self, spring: Spring) -> Self {
        self.spring = spring;
        self
    }

    /// The same rail, the camera looking `aim`.
    #[must_use]
    pub fn aiming(mut self, aim: RailAim) -> Self {
        self.aim = aim;
        self
    }

    /// The same rail, the camera rolled by `roll` along it (see [`roll`](Self::roll)).
    #[must_use]
    pub fn with_roll(mut self, roll: CubicCurve<f32>) -> Self {
        self.roll = Some(roll);
        self
    }

    /// Drives the camera to `position` (0 to 1, see [`RailFollow::Driven`]).
    pub fn drive(&mut self, position: f32) {
        self.follow = RailFollow::Driven(position);
    }
}

/// Where a [`CameraRail`]'s camera is along it: its spring moves it.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Debug, Clone, PartialEq, Default)]
pub struct RailMotion {
    distance: f32,
}

impl RailMotion {
    /// How far along the rail the camera is, in world units (past an open rail's ends while
    /// an under-damped spring overshoots them; the camera stands on the end).
    #[must_use]
    pub fn distance(&self) -> f32 {
        self.distance
    }
}

crate::spring_property!(
    /// A rail camera's place along its rail.
    pub RigRail: RailMotion::distance as Linear<f32>
);

/// The spring of a rail camera's place along its rail.
pub type RigRailSpring = PropertySpring<RigRail>;

/// What a rail camera remembers between frames: its rail's distance table (rebuilt when the
/// curve changes), and where its goal was on it.
#[derive(Component, Debug, Clone, Default)]
pub(crate) struct RailState {
    track: Option<RailTrack>,
    /// The curve's parameter at the place nearest the goal last frame: the nearest-point
    /// search starts there.
    nearest: Option<f32>,
    /// The place the camera sprang to last frame, for its velocity.
    last_goal: Option<f32>,
    /// The camera has been put on the rail (at its first place to go: no fly-in).
    placed: bool,
}

#[cfg(feature = "debug")]
impl RailState {
    /// The rail's distance table, once the camera has followed it.
    pub(crate) fn track(&self) -> Option<&RailTrack> {
        self.track.as_ref()
    }

    /// How far along the rail the place the camera springs to is.
    pub(crate) fn goal(&self) -> Option<f32> {
        self.last_goal
    }
}

/// The place on `track` that `rail` follows for `goal`, searched for from `nearest` (the
/// curve's parameter at last frame's nearest place, updated), or along the whole rail when `fresh` (the target was
/// warped or the rail replaced).
fn goal_on(
    track: &RailTrack,
    rail: &CameraRail,
    goal: Vec3,
    nearest: &mut Option<f32>,
    fresh: bool,
) -> Option<f32> {
    let mut find_nearest = || {
        let found = track.nearest(goal, if fresh { None } else { *nearest });
        *nearest = Some(found.parameter);
        found.distance
    };
    let place = match rail.follow {
        RailFollow::Nearest if goal.is_finite() => find_nearest(),
        RailFollow::Ahead(ahead) if goal.is_finite() && ahead.is_finite() => find_nearest() + ahead,
        RailFollow::Driven(position) if position.is_finite() => position * track.length(),
        _ => return None,
    };
    Some(track.on_rail(place))
}

/// What a rail camera is read and written through while it follows.
type Railed<'a> = (
    Ref<'a, CameraRail>,
    &'a CameraGoal,
    &'a RigTracking,
    &'a Transform,
    &'a mut RailState,
    &'a mut RailMotion,
    &'a mut RigRailSpring,
);

/// After the goal is tracked: each rail's place to spring to, with its velocity along the
/// rail (the distance table rebuilt first if the curve changed).
pub(super) fn follow_rails(time: SpringTime, mut rails: Query<Railed>) {
    let steps = time.steps();
    for (rail, goal, tracking, camera, mut state, mut motion, mut spring) in &mut rails {
        // Compared only when the rail was changed (its place followed, perhaps, not its curve).
        let replaced = match state.track.as_ref() {
            Some(track) => rail.is_changed() && !track.is_of(&rail.curve, rail.looped),
            None => true,
        };
        if replaced {
            let track = RailTrack::new(&rail.curve, rail.looped);
            if track.looped() && track.gap() > 1e-3 {
                warn_once!(
                    "bevy_sprung: a looped CameraRail's curve does not end where it starts: the \
                     camera jumps across the gap; build it with to_curve_cyclic"
                );
            }
            if state.placed {
                // On the new rail where it stood, going on at its speed along the rail.
                motion.distance = track.nearest(camera.translation, None).distance;
            }
            state.track = Some(track);
            state.nearest = None;
            state.last_goal = None;
        }
        if spring.spring() != &rail.spring {
            spring.set_spring(rail.spring);
        }
        let warped = tracking.warped;
        let RailState {
            track: Some(track),
            nearest,
            last_goal,
            placed,
        } = &mut *state
        else {
            continue;
        };
        let Some(place) = goal_on(track, &rail, goal.point, nearest, replaced || warped) else {
            // Nowhere to go: the camera comes to rest where it aims.
            spring.set_target_velocity_if_neq(0.0);
            continue;
        };
        let dt = steps.dt(spring.clock());
        let velocity = match *last_goal {
            // Carried with the target: the camera keeps its lag and its velocity. The place
            // went on at its last rate, and the rest of its move is the jump.
            Some(last) if warped => {
                let rate = spring.target_velocity();
                motion.distance += track.toward(last, place) - rate * dt;
                rate
            }
            Some(last) if dt > 0.0 => track.toward(last, place) / dt,
            _ => 0.0,
        };
        let velocity = if velocity.is_finite() { velocity } else { 0.0 };
        *last_goal = Some(place);
        if !*placed {
            motion.distance = place;
            *placed = true;
        }
        // The camera's place stays on the rail's range, and the place it springs to is the
        // one the shorter way from it, so a loop wraps without a jump.
        let here = track.on_rail(motion.distance);
        if track.looped() && here.to_bits() != motion.distance.to_bits() {
            motion.distance = here;
        }
        spring.set_target_if_neq(here + track.toward(here, place));
        spring.set_target_velocity_if_neq(velocity);
    }
}

/// What a rail camera is placed through.
type Placed<'a> = (
    Posed,
    &'a RigMotion,
    &'a CameraRail,
    &'a RailState,
    &'a RailMotion,
    &'a mut Transform,
);

/// After the rig placed its camera: cameras on rails are moved onto their rails, turned to
/// look at the point their rig frames (or along the rail), and rolled.
pub(super) fn place_on_rails(
    mut rails: Query<Placed>,
    window: Query<&Window, With<PrimaryWindow>>,
) {
    let window = window.single().ok();
    for (posed, motion, rail, state, rail_motion, mut transform) in &mut rails {
        let Some(track) = state.track.as_ref() else {
            continue;
        };
        let position = track.position_at(rail_motion.distance);
        if !position.is_finite() {
            continue;
        }
        let looking = match rail.aim {
            RailAim::AtFocus => Some(posed.pose(motion, window).focus - position),
            RailAim::Along => Some(track.direction_at(rail_motion.distance)),
            RailAim::Unchanged => None,
        };
        let mut placed = *transform;
        placed.translation = position;
        if let Some(direction) = looking.and_then(|looking| Dir3::new(looking).ok()) {
            placed.look_to(direction, Vec3::Y);
            if let Some(roll) = rolled(rail, track, rail_motion.distance) {
                placed.rotate_local_z(roll);
            }
        }
        if placed.is_finite() && *transform != placed {
            *transform = placed;
        }
    }
}

/// The roll of `rail` at `distance` along it, if it has one.
fn rolled(rail: &CameraRail, track: &RailTrack, distance: f32) -> Option<f32> {
    let roll = rail.roll.as_ref()?;
    let segments = track.curve().segments().len() as f32;
    let fraction = track.parameter_at(distance) / segments;
    let angle = roll.position(fraction * roll.segments().len() as f32);
    angle.is_finite().then_some(angle)
}

/// [`CameraRail`] (part of [`SpringCameraPlugin`](super::SpringCameraPlugin)): the spring
/// along the rail, its place set after the goal is tracked, and the camera put on the rail
/// after the rig placed it.
#[derive(Debug, Default, Clone, Copy)]
pub(super) struct SpringCameraRailPlugin;

impl Plugin for SpringCameraRailPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugins(SpringPropertyPlugin::<RigRail>::default())
            .register_type::<CameraRail>()
            .register_type::<RailMotion>();
        let springs = [TypeId::of::<RigRailSpring>()];
        add_property_systems(app, &springs, |schedule| {
            schedule.add_systems((
                follow_rails
                    .in_set(CameraRigSystems::Track)
                    .after(track_goals)
                    .run_if(any_with_component::<CameraRail>),
                place_on_rails
                    .in_set(CameraRigSystems::Compose)
                    .after(compose_cameras)
                    .run_if(any_with_component::<CameraRail>),
            ));
        });
    }
}
