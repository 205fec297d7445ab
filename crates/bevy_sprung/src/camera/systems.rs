//! The rig's frame: targets to goal, goal to spring targets, springs to the camera.

use bevy::camera::{Camera, Projection};
use bevy::ecs::query::QueryData;
use bevy::log::warn_once;
use bevy::prelude::*;
use bevy::window::{PrimaryWindow, Window};

use super::components::{
    CameraGoal, CameraRig, CameraTargets, Confiner, ConfinerVolume, DeadZone, GroupFraming,
    HardLimit, LookAhead, OrbitRig, RigHorizontalSpring, RigLookAheadSpring, RigMotion,
    RigOrbitSpring, RigTracking, RigVerticalSpring, RigZoomSpring, ScreenPosition, orbit_rotation,
};
use super::framing::CameraFraming;
use super::view::{centre_range, ease_into, goal_range, view_area, viewport_size};
use crate::clock::SpringTime;
use crate::follow::{FixedSamples, TargetMotion, fixed_sample};
use crate::spring::SpringTargetMut;
use crate::tracking::{TargetWarped, WorldPositions, take_warp};

/// The stages of a rig's frame in [`SpringUpdate`](crate::spring::SpringUpdate), in this
/// order. Put a system of your own that computes or changes a [`CameraGoal`] in
/// [`Goal`](Self::Goal).
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CameraRigSystems {
    /// [`CameraTargets`] set the goal.
    Targets,
    /// Your systems change the goal (or set it, for a rig without targets).
    Goal,
    /// The goal's velocity is taken, and the look-ahead, zoom and orbit springs retargeted
    /// (they step next).
    Track,
    /// The dead zone, screen position and confiner shape the centre the camera springs to.
    Frame,
    /// The camera's `Transform` and projection are written from the springs.
    Compose,
}

/// After each fixed step: where the targets of rigs whose targets move in `FixedUpdate` are.
pub(super) fn sample_fixed_targets(mut rigs: Query<&mut CameraTargets>, positions: WorldPositions) {
    for mut targets in &mut rigs {
        if targets.motion != TargetMotion::FixedTimestep {
            continue;
        }
        let targets = &mut *targets;
        // Resized only when targets are added or removed.
        targets
            .fixed
            .resize(targets.targets.len(), FixedSamples::default());
        for (target, samples) in targets.targets.iter().zip(&mut targets.fixed) {
            samples.record(positions.of(target.entity));
        }
    }
}

/// Where each rig's targets are: their weighted centre and spread become its goal. Targets
/// that move in `FixedUpdate` are where their fixed steps put them now (see
/// [`TargetMotion::FixedTimestep`]).
pub(super) fn sample_targets(
    mut rigs: Query<(Entity, &CameraTargets, Option<&Transform>, &mut CameraGoal)>,
    positions: WorldPositions,
    time: SpringTime,
) {
    for (rig, targets, transform, mut goal) in &mut rigs {
        let found = || {
            targets
                .targets
                .iter()
                .enumerate()
                .filter_map(|(i, target)| {
                    let usable =
                        target.entity != rig && target.weight.is_finite() && target.weight > 0.0;
                    let position = usable.then(|| positions.of(target.entity))??;
                    let position = match (targets.motion, targets.fixed.get(i)) {
                        (TargetMotion::FixedTimestep, Some(&samples)) => {
                            fixed_sample(samples, time.fixed_step())
                                .map_or(position, |(now, _)| now)
                        }
                        _ => position,
                    };
                    position.is_finite().then_some((position, target))
                })
        };
        let (sum, weight) = found().fold((Vec3::ZERO, 0.0), |(sum, weight), (position, target)| {
            (sum + position * target.weight, weight + target.weight)
        });
        if weight <= 0.0 || !weight.is_finite() {
            continue;
        }
        let point = sum / weight;
        if !point.is_finite() {
            continue;
        }
        // The spread along the camera's own right and up axes, radii included.
        let to_view = transform.map_or(Quat::IDENTITY, |transform| transform.rotation.inverse());
        let spread = found().fold(Vec2::ZERO, |spread, (position, target)| {
            let local = to_view * (position - point);
            spread.max(local.truncate().abs() + Vec2::splat(target.radius.max(0.0)))
        });
        let spread = if spread.is_finite() {
            spread
        } else {
            goal.spread
        };
        if goal.point != point || goal.spread != spread {
            *goal = CameraGoal { point, spread };
        }
    }
}

/// What a rig reads of its camera to know its view.
#[derive(QueryData)]
pub(super) struct View {
    camera: Option<&'static Camera>,
    projection: Option<&'static Projection>,
}

/// The area `view` covers relative to the camera at `zoom` (see [`view_area`]), `distance`
/// being the camera's distance from the framed point at zoom 1 (perspective).
fn camera_view_area(view: &ViewItem, window: Option<&Window>, zoom: f32, distance: f32) -> Rect {
    view_area(
        view.projection,
        viewport_size(view.camera, window),
        zoom,
        distance * zoom,
    )
}

/// Whether `projection` is a perspective one (a zoom is a distance factor).
fn is_perspective(projection: Option<&Projection>) -> bool {
    matches!(projection, Some(Projection::Perspective(_)))
}

/// The camera's distance from the point it frames at zoom 1.
fn base_distance(rig: &CameraRig, orbit: Option<&OrbitRig>, motion: &RigMotion) -> f32 {
    match orbit {
        Some(_) => motion.orbit().z,
        None => rig.offset.length(),
    }
}

/// The parts of a rig read while its goal is tracked.
#[derive(QueryData)]
#[query_data(mutable)]
pub(super) struct Tracked {
    rig: &'static CameraRig,
    goal: &'static CameraGoal,
    motion: &'static mut RigMotion,
    tracking: &'static mut RigTracking,
    zoom: &'static mut RigZoomSpring,
    framing: Option<&'static GroupFraming>,
    look_ahead: Option<&'static LookAhead>,
    look_ahead_spring: Option<&'static mut RigLookAheadSpring>,
    orbit: Option<(&'static OrbitRig, &'static mut RigOrbitSpring)>,
    view: View,
}

/// After the goal is known: its velocity, and the targets of the look-ahead, zoom and orbit
/// springs (which step next).
pub(super) fn track_goals(
    time: SpringTime,
    mut rigs: Query<Tracked>,
    window: Query<&Window, With<PrimaryWindow>>,
) {
    let steps = time.steps();
    let window = window.single().ok();
    for mut rig in &mut rigs {
        let first_frame = rig.tracking.last_point.is_none();
        let point = rig.goal.point;
        if !point.is_finite() {
            warn_once!(
                "bevy_sprung: a CameraGoal's point is not finite; the rig keeps its last goal"
            );
            // Kept, so no longer moving: the zoom stops following its last rate.
            rig.zoom.set_target_velocity_if_neq(0.0);
            continue;
        }
        let dt = steps.dt(rig.zoom.clock());
        let tracking = &mut *rig.tracking;
        let shift = take_warp(
            &mut tracking.warp,
            rig.rig.teleport_distance,
            (tracking.last_point, point),
            tracking.point_velocity * dt,
        );
        if shift != Vec3::ZERO && shift.is_finite() {
            // The goal was carried: so is the camera, keeping its framing and velocity (the
            // jump is not motion).
            tracking.carry(shift);
            let centre = rig.motion.centre() + shift;
            rig.motion.set_centre(centre);
        }
        let velocity = match rig.tracking.last_point {
            Some(last) if dt > 0.0 => (point - last) / dt,
            _ => Vec3::ZERO,
        };
        rig.tracking.point_velocity = if velocity.is_finite() {
            velocity
        } else {
            Vec3::ZERO
        };
        rig.tracking.last_point = Some(point);

        let distance = base_distance(
            rig.rig,
            rig.orbit.as_ref().map(|(orbit, _)| *orbit),
            &rig.motion,
        );
        // Without a look-ahead (or once it is removed) the offset springs back to nothing.
        if let Some(spring) = rig.look_ahead_spring.as_mut() {
            let ahead = rig.look_ahead.map_or(Vec3::ZERO, |look_ahead| {
                if spring.spring() != &look_ahead.spring {
                    spring.set_spring(look_ahead.spring);
                }
                let ahead = rig.tracking.point_velocity * look_ahead.time;
                if look_ahead.vertical {
                    ahead
                } else {
                    ahead.with_y(0.0)
                }
            });
            spring.set_target_if_neq(ahead);
        }

        if let Some((orbit, spring)) = rig.orbit.as_mut() {
            if spring.spring() != &orbit.spring {
                spring.set_spring(orbit.spring);
            }
            let aim = orbit.aim(spring.target());
            spring.set_target_if_neq(aim);
            if first_frame {
                rig.motion.set_orbit(aim);
            }
        }

        if rig.zoom.spring() != &rig.rig.zoom_spring {
            let spring = rig.rig.zoom_spring;
            rig.zoom.set_spring(spring);
        }
        let fitted = rig.framing.and_then(|framing| {
            let half_view = camera_view_area(&rig.view, window, 1.0, distance).half_size();
            framing.zoom_to_fit(rig.goal.spread, half_view)
        });
        let zoom = fitted.unwrap_or(rig.rig.zoom);
        if zoom.is_finite() {
            let zoom = zoom.max(1e-4);
            // A zoom that follows moving targets moves with them: its rate, like the centre's,
            // makes the step exact (and keeps the spring from settling and waking every frame
            // as its goal creeps).
            let rate = match rig.tracking.last_zoom {
                Some(last) if dt > 0.0 => (zoom - last) / dt,
                _ => 0.0,
            };
            rig.tracking.last_zoom = Some(zoom);
            rig.zoom.set_target_if_neq(zoom);
            rig.zoom
                .set_target_velocity_if_neq(if rate.is_finite() { rate } else { 0.0 });
            if first_frame {
                rig.motion.set_zoom(zoom);
            }
        } else {
            rig.zoom.set_target_velocity_if_neq(0.0);
        }
    }
}

/// The parts of a rig read while its centre is aimed.
#[derive(QueryData)]
#[query_data(mutable)]
pub(super) struct Framed {
    rig: &'static CameraRig,
    goal: &'static CameraGoal,
    transform: Option<&'static Transform>,
    motion: &'static mut RigMotion,
    tracking: &'static mut RigTracking,
    framing: &'static mut CameraFraming,
    horizontal: &'static mut RigHorizontalSpring,
    vertical: &'static mut RigVerticalSpring,
    dead_zone: Option<&'static DeadZone>,
    screen: Option<&'static ScreenPosition>,
    confiner: Option<&'static Confiner>,
    orbit: Option<&'static OrbitRig>,
    view: View,
}

impl FramedItem<'_, '_> {
    /// A frame with no goal to frame (not finite): the goal holds where it was, so the springs
    /// stop following its last velocity and come to rest.
    fn hold_goal(&mut self) {
        self.horizontal.set_target_velocity_if_neq(Vec2::ZERO);
        self.vertical.set_target_velocity_if_neq(0.0);
    }
}

/// After the look-ahead, zoom and orbit stepped: the centre the camera springs to (the goal
/// plus look-ahead, held by the dead zone, moved by the screen position, kept near the
/// confiner), with its velocity, for the horizontal and vertical springs.
pub(super) fn frame_goals(
    time: SpringTime,
    mut rigs: Query<Framed>,
    window: Query<&Window, With<PrimaryWindow>>,
) {
    let steps = time.steps();
    let window = window.single().ok();
    for mut rig in &mut rigs {
        let zoom = rig.motion.zoom();
        let distance = base_distance(rig.rig, rig.orbit, &rig.motion);
        let area = camera_view_area(&rig.view, window, zoom, distance);
        let half_view = area.half_size();
        let point = rig.goal.point + rig.motion.look_ahead();
        if !point.is_finite() {
            rig.hold_goal();
            continue;
        }

        // The dead zone holds the goal until the point leaves the zone around it: the goal is
        // dragged along by the zone's edge (a backlash, the same for any frame rate).
        // Without a zone its half extents are zero, and the point itself is held.
        // A zone off its anchor holds the anchor as far from the point as the zone's centre
        // is from the anchor.
        let (half, offset) = rig.dead_zone.map_or((Vec3::ZERO, Vec3::ZERO), |zone| {
            let half = zone.half_size(half_view);
            let offset = zone.offset_in(half_view);
            (Vec3::new(half.x, half.y, half.x), offset.extend(0.0))
        });
        let anchor = point - offset;
        let held = rig
            .tracking
            .held
            .unwrap_or(point)
            .clamp(anchor - half, anchor + half);
        rig.tracking.held = Some(held);

        let shift = rig.screen.map_or(Vec3::ZERO, |screen| {
            let rotation = match rig.orbit {
                Some(_) => orbit_rotation(rig.motion.orbit().x, rig.motion.orbit().y),
                None => rig
                    .transform
                    .map_or(Quat::IDENTITY, |transform| transform.rotation),
            };
            rotation * (screen.0 * 2.0 * half_view).extend(0.0)
        });
        let mut centre = held - shift;
        if let Some(confiner) = rig.confiner {
            // Beyond this the eased camera stands on the edge: a goal further out would only
            // make it wait there before coming back.
            let range = centre_range(confiner.bounds, area);
            let (low, high) = goal_range(range.min.x, range.max.x, confiner.slowing_distance);
            centre.x = centre.x.clamp(low, high);
            let (low, high) = goal_range(range.min.y, range.max.y, confiner.slowing_distance);
            centre.y = centre.y.clamp(low, high);
        }
        if !centre.is_finite() {
            rig.hold_goal();
            continue;
        }
        *rig.framing = CameraFraming {
            goal: rig.goal.point,
            point,
            held,
            dead_zone: half,
            dead_zone_offset: offset,
            half_view,
            centre,
        };

        let dt = steps.dt(rig.horizontal.clock());
        let carried = core::mem::take(&mut rig.tracking.warped);
        let velocity = match rig.tracking.last_centre {
            // Carried this frame: the centre goes on at the velocity it had.
            Some(_) if carried => Vec3::new(
                rig.horizontal.target_velocity().x,
                rig.vertical.target_velocity(),
                rig.horizontal.target_velocity().y,
            ),
            Some(last) if dt > 0.0 => (centre - last) / dt,
            _ => Vec3::ZERO,
        };
        let velocity = if velocity.is_finite() {
            velocity
        } else {
            Vec3::ZERO
        };
        let first_frame = rig.tracking.last_centre.is_none();
        rig.tracking.last_centre = Some(centre);
        if first_frame {
            rig.motion.set_centre(centre);
        }

        if rig.horizontal.spring() != &rig.rig.horizontal {
            let spring = rig.rig.horizontal;
            rig.horizontal.set_spring(spring);
        }
        rig.horizontal
            .set_target_if_neq(Vec2::new(centre.x, centre.z));
        rig.horizontal
            .set_target_velocity_if_neq(Vec2::new(velocity.x, velocity.z));

        if rig.vertical.spring() != &rig.rig.vertical {
            let spring = rig.rig.vertical;
            rig.vertical.set_spring(spring);
        }
        if rig.rig.hold_vertical && !first_frame {
            // Held where it is: the spring comes to rest on its current height.
            let here = rig.motion.centre().y;
            rig.vertical.set_target_if_neq(here);
            rig.vertical.set_target_velocity_if_neq(0.0);
        } else {
            rig.vertical.set_target_if_neq(centre.y);
            rig.vertical.set_target_velocity_if_neq(velocity.y);
        }
    }
}

/// Where a rig puts its camera this frame, before an occluder pulls it in: the point it
/// frames (eased into its confiner), the arm from that point to the camera, and the rotation
/// it turns the camera to (when it aims).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct RigPose {
    pub(super) focus: Vec3,
    pub(super) arm: Vec3,
    pub(super) rotation: Option<Quat>,
}

/// What a rig's pose is computed from.
#[derive(QueryData)]
pub(super) struct Posed {
    rig: &'static CameraRig,
    goal: &'static CameraGoal,
    limit: Option<&'static HardLimit>,
    confiner: Option<&'static Confiner>,
    volume: Option<&'static ConfinerVolume>,
    orbit: Option<&'static OrbitRig>,
    view: View,
}

impl PosedItem<'_, '_> {
    /// The pose of a rig whose springs hold `motion`.
    pub(super) fn pose(&self, motion: &RigMotion, window: Option<&Window>) -> RigPose {
        let zoom = motion.zoom();
        let area = self.view_area(motion, window);
        let mut focus = motion.centre();
        if let Some(limit) = self.limit {
            focus = self.carried_by_goal(focus, limit, area.half_size());
        }
        if let Some(confiner) = self.confiner {
            let range = centre_range(confiner.bounds, area);
            let slowing = confiner.slowing_distance;
            focus.x = ease_into(focus.x, range.min.x, range.max.x, slowing);
            focus.y = ease_into(focus.y, range.min.y, range.max.y, slowing);
        }
        let distance_factor = if is_perspective(self.view.projection) {
            zoom
        } else {
            1.0
        };
        if self.orbit.is_some() {
            let orbit = motion.orbit();
            let rotation = orbit_rotation(orbit.x, orbit.y);
            let arm = rotation * Vec3::new(0.0, 0.0, orbit.z.max(1e-4) * distance_factor);
            RigPose {
                focus,
                arm,
                rotation: Some(rotation),
            }
        } else {
            let arm = self.rig.offset * distance_factor;
            let aim = self.rig.look_at_goal && arm.length_squared() > 0.0;
            let rotation = aim.then(|| {
                Transform::from_translation(focus + arm)
                    .looking_at(focus, Vec3::Y)
                    .rotation
            });
            RigPose {
                focus,
                arm,
                rotation,
            }
        }
    }
}

impl PosedItem<'_, '_> {
    /// `focus` carried along by the goal's point so that the point stays inside `limit`: the
    /// point's offset from the view eased into the limit (the identity well inside it, a
    /// slope falling smoothly to 0 at its edge), so the camera's velocity never jumps.
    fn carried_by_goal(&self, focus: Vec3, limit: &HardLimit, half_view: Vec2) -> Vec3 {
        let point = self.goal.point;
        if !point.is_finite() {
            return focus;
        }
        let (half, slowing) = limit.in_world(half_view);
        let mut carried = focus;
        for axis in 0..2 {
            let offset = point[axis] - focus[axis];
            carried[axis] = point[axis] - ease_into(offset, -half[axis], half[axis], slowing);
        }
        carried
    }

    /// The view a rig whose springs hold `motion` sees, around its focus, at its zoom.
    pub(super) fn view_area(&self, motion: &RigMotion, window: Option<&Window>) -> Rect {
        let distance = base_distance(self.rig, self.orbit, motion);
        camera_view_area(&self.view, window, motion.zoom(), distance)
    }

    /// Whether the goal's point is at the edge of the rig's [`HardLimit`] (the camera is
    /// carried along by it), for the rig's [`view_area`](Self::view_area) `area`: within
    /// [`EDGE_TOLERANCE`] of the view's size. `false` without a limit.
    pub(super) fn at_hard_limit(&self, motion: &RigMotion, area: Rect) -> bool {
        let Some(limit) = self.limit else {
            return false;
        };
        let (half, _) = limit.in_world(area.half_size());
        let focus = self.carried_by_goal(motion.centre(), limit, area.half_size());
        let reach = (self.goal.point.truncate() - focus.truncate()).abs();
        let tolerance = EDGE_TOLERANCE * area.size().max_element();
        half != Vec2::ZERO && (half - reach).cmple(Vec2::splat(tolerance)).any()
    }

    /// Whether the camera of a rig whose springs hold `motion` stands at its [`Confiner`]'s
    /// edge on some axis, for the rig's [`view_area`](Self::view_area) `area`: its eased view
    /// within [`EDGE_TOLERANCE`] of the view's size from the bounds. `false` without a
    /// confiner.
    pub(super) fn at_confiner_edge(&self, motion: &RigMotion, area: Rect) -> bool {
        let Some(confiner) = self.confiner else {
            return false;
        };
        let range = centre_range(confiner.bounds, area);
        let tolerance = EDGE_TOLERANCE * area.size().max_element();
        let centre = motion.centre();
        (0..2).any(|axis| {
            let (low, high) = (range.min[axis], range.max[axis]);
            let eased = ease_into(centre[axis], low, high, confiner.slowing_distance);
            eased - low <= tolerance || high - eased <= tolerance
        })
    }

    /// Where the camera of `pose` is with `clearance` of its arm clear: on the arm, eased into
    /// its [`ConfinerVolume`].
    pub(super) fn place(&self, pose: &RigPose, clearance: f32) -> Vec3 {
        let mut translation = pose.focus + pose.arm * clearance;
        if let Some(volume) = self.volume {
            for axis in 0..3 {
                translation[axis] = ease_into(
                    translation[axis],
                    volume.min[axis],
                    volume.max[axis],
                    volume.slowing_distance,
                );
            }
        }
        translation
    }
}

/// How near a confiner's bounds a camera's view is at their edge, as a fraction of the view's
/// size: well under a pixel for views a few thousand pixels wide.
const EDGE_TOLERANCE: f32 = 1e-4;

/// After the springs stepped: the camera's translation and rotation, written only where they
/// change. An occluder's pull (the clearance) shortens the arm.
pub(super) fn compose_cameras(
    mut rigs: Query<(Entity, Posed, &RigMotion, Option<&mut Transform>)>,
    window: Query<&Window, With<PrimaryWindow>>,
) {
    let window = window.single().ok();
    for (rig, posed, motion, transform) in &mut rigs {
        let Some(mut transform) = transform else {
            warn_once!(
                "bevy_sprung: {rig} has a CameraRig but no Transform (removed?): the rig has \
                 nothing to place; keep the Transform, or remove the CameraRig"
            );
            continue;
        };
        let pose = posed.pose(motion, window);
        let translation = posed.place(&pose, motion.clearance());
        if !translation.is_finite() {
            continue;
        }
        if transform.translation != translation {
            transform.translation = translation;
        }
        if let Some(rotation) = pose.rotation.filter(|rotation| rotation.is_finite())
            && transform.rotation != rotation
        {
            transform.rotation = rotation;
        }
    }
}

/// After the springs stepped: an orthographic rig camera's scale is its zoom, written only
/// when it changes.
pub(super) fn zoom_projections(mut rigs: Query<(&RigMotion, &mut Projection), With<CameraRig>>) {
    for (motion, mut projection) in &mut rigs {
        let zoom = motion.zoom();
        if let Projection::Orthographic(orthographic) = projection.bypass_change_detection()
            && orthographic.scale.to_bits() != zoom.to_bits()
            && let Projection::Orthographic(orthographic) = projection.as_mut()
        {
            orthographic.scale = zoom;
        }
    }
}

/// A [`TargetWarped`]: every rig framing the warped entity takes note of its share of the
/// jump (its weight over the weights of the rig's targets), to move with it when it next
/// tracks its goal. Targets that move in `FixedUpdate` have their samples moved too.
pub(super) fn note_warps(
    warped: On<TargetWarped>,
    mut rigs: Query<(&mut CameraTargets, &mut RigTracking)>,
) {
    if !warped.delta.is_finite() {
        return;
    }
    for (mut targets, mut tracking) in &mut rigs {
        let usable = |weight: f32| weight.is_finite() && weight > 0.0;
        let total: f32 = targets
            .targets
            .iter()
            .map(|target| target.weight)
            .filter(|&weight| usable(weight))
            .sum();
        let Some(index) = targets
            .targets
            .iter()
            .position(|target| target.entity == warped.entity && usable(target.weight))
        else {
            continue;
        };
        tracking.warp += warped.delta * (targets.targets[index].weight / total);
        if let Some(samples) = targets.fixed.get_mut(index) {
            samples.carry(warped.delta);
        }
    }
}
