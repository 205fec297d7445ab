//! The step of every chain: root to leaf, each bone's tip springs toward where its parent's
//! pose puts it at rest, and the joint turns toward the tip.

use bevy::ecs::system::SystemParam;
use bevy::log::warn_once;
use bevy::prelude::*;
use sprung::{Spring, SpringState};

use super::collider::PlacedCollider;
use super::pose::Pose;
use super::{CachedTransition, ChainBone, ChainCollider, ChainJoint, Reshaped, SpringChain};
use crate::clock::SpringTime;

/// Passes over a chain's colliders per bone: a capsule's nearest point moves as the end turns.
const COLLIDER_PASSES: usize = 3;

/// A tip rests within this fraction of its bone's length of where gravity holds it (a
/// ten-thousandth of a radian), moving slower than that many lengths per second times its
/// natural frequency.
const REST: f32 = 1e-4;

/// What a chain carries between frames.
#[derive(Debug, Clone, Default)]
pub(super) struct ChainState {
    /// Put every tip at rest at the next step.
    pub reset: bool,
    /// Nothing moves: nothing is stepped or written until something does.
    pub resting: bool,
    /// Whether it steps this frame (and then its joints' rotations are written).
    this_frame: ThisFrame,
    /// A joint was not found (despawned, or its `Transform` removed): find them again.
    lost: bool,
    joints: Vec<Joint>,
    /// The time since the last step of the grid.
    behind: f32,
    /// Each joint's `Transform` as others left it this frame, read once (scratch, kept for its
    /// allocation).
    locals: Vec<Pose>,
    /// Each joint's world pose and local rotation after the last pass (scratch).
    poses: Vec<(Pose, Quat)>,
    /// The world pose of the chain's parent, and the first joint's position, last frame.
    last_parent: Option<Transform>,
    last_root: Option<Vec3>,
}

impl ChainState {
    /// Each joint's bone as of the last step (joints without a bone, or not stepped yet, have
    /// none).
    pub(super) fn bones(&self) -> impl Iterator<Item = ChainBone> + '_ {
        self.joints.iter().filter_map(|joint| {
            let rest_tip = joint.rest_tip?;
            Some(ChainBone {
                joint: joint.entity,
                rest_tip: rest_tip.into(),
                tip: (rest_tip + joint.offset).into(),
            })
        })
    }
}

/// Whether a chain steps this frame.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
enum ThisFrame {
    #[default]
    Still,
    Steps,
}

/// One joint of a chain.
#[derive(Debug, Clone)]
struct Joint {
    entity: Entity,
    /// The joint it hangs from (`None`: the chain's own entity, which hangs from the chain's
    /// parent).
    parent: Option<usize>,
    /// Where its bone ends: at its one child joint, at the chain's `end`, or nowhere.
    bone: Bone,
    spring: Spring<f32>,
    /// How far a unit acceleration holds the tip off its rest place, `m/k` (none without
    /// stiffness).
    compliance: f32,
    /// Its spring's natural frequency (at least 1/s, for the rest test).
    omega: f32,
    gravity_scale: f32,
    /// Its local rotation as others gave it, and the one the chain last wrote.
    rest: Quat,
    written: Option<Quat>,
    /// The tip's offset from its rest place and its velocity, in world units (`Vec3A`: the
    /// step's arithmetic is done four lanes at a time).
    offset: Vec3A,
    velocity: Vec3A,
    /// Where the tip rested last frame, in the world.
    rest_tip: Option<Vec3A>,
    step: Option<CachedTransition>,
}

impl Joint {
    /// Where the spring holds the tip under a constant `acceleration`: `m·a/k` off its rest
    /// place (none without stiffness).
    fn hangs(&self, acceleration: Vec3A) -> Vec3A {
        acceleration * self.compliance
    }
}

/// How many child joints a joint has, while the chain is found.
#[derive(Clone, Copy)]
enum ChildJoints {
    None,
    One(usize),
    Several,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Bone {
    None,
    Child(usize),
    End,
}

/// What the chain step reads besides the chains.
#[derive(SystemParam)]
pub(super) struct ChainWorld<'w, 's> {
    time: SpringTime<'w>,
    transforms: Query<'w, 's, &'static mut Transform>,
    parents: Query<'w, 's, &'static ChildOf>,
    children: Query<'w, 's, &'static Children>,
    reshaped: Query<'w, 's, Entity, Changed<Children>>,
    colliders: Query<'w, 's, &'static ChainCollider>,
    joints: Query<'w, 's, &'static ChainJoint>,
}

impl ChainWorld<'_, '_> {
    /// The world pose of `entity` from the `Transform`s as they are now (not last frame's
    /// `GlobalTransform`): its ancestors may have moved this frame.
    fn pose_of(&self, entity: Entity) -> Transform {
        let mut pose = self
            .transforms
            .get(entity)
            .map_or(Transform::IDENTITY, |transform| *transform);
        let mut current = entity;
        while let Ok(child_of) = self.parents.get(current) {
            current = child_of.parent();
            if let Ok(transform) = self.transforms.get(current) {
                pose = transform.mul_transform(pose);
            }
        }
        pose
    }

    /// The pose of the chain's parent (the identity for a chain at the top of its hierarchy).
    fn parent_pose(&self, chain: Entity) -> Transform {
        self.parents
            .get(chain)
            .map_or(Transform::IDENTITY, |child_of| {
                self.pose_of(child_of.parent())
            })
    }
}

/// `PostUpdate`: steps every chain that moves, chains in parallel, and writes their joints.
pub(super) fn step_chains(
    mut chains: Query<(Entity, &mut SpringChain)>,
    mut world: ChainWorld,
    hierarchy: Option<ResMut<Reshaped>>,
) {
    // Chains advance on the default spring clock.
    let dt = world.time.delta(None);
    if !(dt >= 0.0 && dt.is_finite()) {
        return;
    }
    // Which chains step: change ticks are read here. Whose children changed is looked up only
    // when the hierarchy did (a scan of every entity with children).
    let hierarchy_changed = hierarchy.is_none_or(|mut hierarchy| core::mem::take(&mut hierarchy.0));
    let reshaped: Vec<Entity> = if hierarchy_changed {
        world.reshaped.iter().collect()
    } else {
        Vec::new()
    };
    for (entity, mut chain) in &mut chains {
        let configured = chain.is_changed();
        let chain = chain.bypass_change_detection();
        if configured || needs_rebuild(entity, &chain.state, &reshaped) {
            rebuild(entity, chain, &world);
        }
        let mut still = || {
            chain.state.last_parent == Some(world.parent_pose(entity))
                && !chain.state.reset
                && !configured
                && !chain.state.joints.iter().any(|joint| {
                    world
                        .transforms
                        .get_mut(joint.entity)
                        .is_ok_and(|transform| transform.is_changed())
                })
        };
        chain.state.this_frame = if chain.state.resting && still() {
            ThisFrame::Still
        } else {
            ThisFrame::Steps
        };
    }
    // Each chain's step reads the world and changes only the chain.
    let reader = &world;
    chains.par_iter_mut().for_each(|(entity, mut chain)| {
        let chain = chain.bypass_change_detection();
        if chain.state.this_frame == ThisFrame::Steps {
            step_chain(chain, reader.parent_pose(entity), dt, reader);
        }
    });
    for (_, mut chain) in &mut chains {
        let state = &mut chain.bypass_change_detection().state;
        if state.this_frame == ThisFrame::Steps {
            write_rotations(state, &mut world.transforms);
        }
    }
}

/// Writes each joint's rotation from the chain's last pass where it differs from the one its
/// `Transform` has (which the pass left in `written`).
fn write_rotations(state: &mut ChainState, transforms: &mut Query<&mut Transform>) {
    for (joint, &(_, rotation)) in state.joints.iter_mut().zip(&state.poses) {
        if joint.written != Some(rotation) {
            if let Ok(mut transform) = transforms.get_mut(joint.entity) {
                transform.rotation = rotation;
            }
            joint.written = Some(rotation);
        }
    }
}

/// Whether the chain's joints changed: one despawned (its `Transform` was not found when the
/// chain last read it), or children added or removed (`reshaped`: the entities whose children
/// changed this frame, usually none).
fn needs_rebuild(entity: Entity, state: &ChainState, reshaped: &[Entity]) -> bool {
    state.joints.is_empty()
        || state.lost
        || (!reshaped.is_empty()
            && (reshaped.contains(&entity)
                || state
                    .joints
                    .iter()
                    .any(|joint| reshaped.contains(&joint.entity))))
}

/// Finds the chain's joints (its entity and every descendant with a `Transform`, parents
/// first) and their springs, keeping the motion of joints it had.
fn rebuild(entity: Entity, chain: &mut SpringChain, world: &ChainWorld) {
    let old = core::mem::take(&mut chain.state.joints);
    let mut found: Vec<(Entity, Option<usize>, u32)> = vec![(entity, None, 0)];
    let mut next = 0;
    while next < found.len() {
        let (joint, _, depth) = found[next];
        if let Ok(children) = world.children.get(joint) {
            for &child in children {
                if world.transforms.contains(child) {
                    found.push((child, Some(next), depth + 1));
                }
            }
        }
        next += 1;
    }
    let deepest = found
        .iter()
        .map(|&(_, _, depth)| depth)
        .max()
        .unwrap_or(0)
        .max(1);
    // Each joint's child joints, in one pass (a joint with one turns toward it).
    let mut children = vec![ChildJoints::None; found.len()];
    for (index, &(_, parent, _)) in found.iter().enumerate() {
        if let Some(parent) = parent {
            children[parent] = match children[parent] {
                ChildJoints::None => ChildJoints::One(index),
                _ => ChildJoints::Several,
            };
        }
    }
    let lerp = |[root, tip]: [f32; 2], depth: f32| root + (tip - root) * depth;
    chain.state.joints = found
        .iter()
        .enumerate()
        .map(|(index, &(joint, parent, depth))| {
            let bone = match children[index] {
                ChildJoints::One(child) => Bone::Child(child),
                ChildJoints::None if chain.end.is_some() => Bone::End,
                _ => Bone::None,
            };
            let depth = depth as f32 / deepest as f32;
            let (spring, gravity_scale) = if let Ok(own) = world.joints.get(joint) {
                (own.spring, own.gravity_scale)
            } else {
                let gradient = chain.gradient;
                let spring = &chain.spring;
                let scaled = Spring::new(
                    spring.mass(),
                    spring.stiffness() * lerp(gradient.stiffness, depth),
                    spring.damping() * lerp(gradient.damping, depth),
                );
                (
                    scaled.unwrap_or(chain.spring),
                    lerp(gradient.gravity, depth),
                )
            };
            let kept = old.iter().find(|kept| kept.entity == joint);
            Joint {
                entity: joint,
                parent,
                bone,
                spring,
                compliance: if spring.stiffness() > 0.0 {
                    spring.mass() / spring.stiffness()
                } else {
                    0.0
                },
                omega: spring.natural_frequency().max(1.0),
                gravity_scale,
                rest: kept.map_or(Quat::IDENTITY, |kept| kept.rest),
                written: kept.and_then(|kept| kept.written),
                offset: kept.map_or(Vec3A::ZERO, |kept| kept.offset),
                velocity: kept.map_or(Vec3A::ZERO, |kept| kept.velocity),
                rest_tip: kept.and_then(|kept| kept.rest_tip),
                step: None,
            }
        })
        .collect();
    chain.state.resting = false;
    chain.state.lost = false;
}

/// Time within this of a step of the grid is on it (frame times are whole nanoseconds).
const ON_GRID: f32 = 1e-6;

/// One frame of one chain: the whole steps of its grid that the frame passed, root to leaf,
/// each toward the parent's pose at that step (interpolated over the frame), then the rest of
/// the frame as a step that is shown and not kept.
fn step_chain(chain: &mut SpringChain, parent: Transform, dt: f32, world: &ChainWorld) {
    let colliders: Vec<PlacedCollider> = chain
        .colliders
        .iter()
        .filter_map(|&collider| {
            let shape = world.colliders.get(collider).ok()?;
            PlacedCollider::new(*shape, &GlobalTransform::from(world.pose_of(collider)))
        })
        .collect();
    // Every joint's `Transform` as the frame left it, read once.
    let state = &mut chain.state;
    state.locals.clear();
    let mut lost = false;
    state.locals.extend(state.joints.iter().map(|joint| {
        Pose::from(world.transforms.get(joint.entity).map_or_else(
            |_| {
                lost = true;
                Transform::IDENTITY
            },
            |transform| *transform,
        ))
    }));
    state.lost = lost;
    let root = state
        .locals
        .first()
        .map(|local| parent.transform_point(local.translation.into()));
    let teleported = match (root, chain.state.last_root) {
        (Some(now), Some(before)) => now.distance(before) > chain.teleport_distance,
        _ => false,
    };
    let before = match chain.state.last_parent {
        Some(before) if !teleported => before,
        _ => parent,
    };
    chain.state.last_parent = Some(parent);
    chain.state.last_root = root;
    if teleported || core::mem::take(&mut chain.state.reset) {
        // The tips move with their rest places: nothing swings from the jump.
        let reset = !teleported;
        for joint in &mut chain.state.joints {
            joint.rest_tip = None;
            if reset {
                joint.offset =
                    joint.hangs(Vec3A::from(chain.gravity + chain.wind) * joint.gravity_scale);
                joint.velocity = Vec3A::ZERO;
            }
        }
    }
    let grid = if chain.rate > 0.0 && chain.rate.is_finite() {
        chain.rate.recip()
    } else {
        dt
    };
    let pass = Pass {
        end: chain.end.map(Vec3A::from),
        planar: chain.planar,
        colliders: &colliders,
        acceleration: (chain.gravity + chain.wind).into(),
        grid,
    };
    let state = &mut chain.state;
    state.behind += dt;
    let mut resting = state.resting;
    while state.behind >= grid - ON_GRID {
        // What of the frame is left after this step of the grid (none, on the grid), and so
        // how far into the frame the step ends.
        let after = (state.behind - grid).max(0.0);
        let after = if after < ON_GRID { 0.0 } else { after };
        let into = ((dt - after) / dt).clamp(0.0, 1.0);
        resting = pass.run(state, blend(before, parent, into), grid, true);
        state.behind = after;
    }
    if state.behind > 0.0 {
        resting = false;
        pass.run(state, parent, state.behind, false);
    } else if dt == 0.0 {
        // A frame without time (an app's first): where the tips rest now, for the next step to
        // move from.
        pass.run(state, parent, 0.0, true);
    }
    state.resting = resting;
    if resting {
        state.behind = 0.0;
    }
}

/// The pose a fraction `t` of the way from `a` to `b`.
fn blend(a: Transform, b: Transform, t: f32) -> Transform {
    if t >= 1.0 || a == b {
        return b;
    }
    Transform {
        translation: a.translation.lerp(b.translation, t),
        rotation: a.rotation.slerp(b.rotation, t),
        scale: a.scale.lerp(b.scale, t),
    }
}

/// What every joint's step in a pass shares.
struct Pass<'a> {
    end: Option<Vec3A>,
    planar: bool,
    colliders: &'a [PlacedCollider],
    acceleration: Vec3A,
    grid: f32,
}

impl Pass<'_> {
    /// Steps every joint by `dt` under the chain's parent at `parent`, root to leaf: kept
    /// (`keep`) or only shown. Leaves each joint's world pose and local rotation in
    /// `state.poses`, and returns whether every tip rests.
    fn run(&self, state: &mut ChainState, parent: Transform, dt: f32, keep: bool) -> bool {
        let parent = Pose::from(parent);
        let mut resting = true;
        state.poses.clear();
        for index in 0..state.joints.len() {
            let joint = &state.joints[index];
            let local = state.locals[index];
            let above = match joint.parent {
                Some(up) => state.poses[up].0,
                None => parent,
            };
            let tip = match joint.bone {
                Bone::Child(child) => Some(state.locals[child].translation),
                Bone::End => self.end,
                Bone::None => None,
            };
            let joint = &mut state.joints[index];
            if joint.written != Some(local.rotation) {
                // Written by something else (an animation, gameplay), or new: its rest pose.
                joint.rest = local.rotation;
                joint.written = Some(local.rotation);
            }
            let rest_pose = above.then(Pose {
                rotation: joint.rest,
                ..local
            });
            let (rotation, pose) = match tip {
                Some(tip) => {
                    let swing = Swing {
                        rest_pose,
                        tip,
                        acceleration: self.acceleration * joint.gravity_scale,
                        colliders: self.colliders,
                        planar: self.planar,
                        dt,
                        cache: dt.to_bits() == self.grid.to_bits(),
                    };
                    let (world_rotation, rests) = swing.step(joint, keep);
                    resting &= rests;
                    // The joint's rotation under its parent's: normalised once here, where it is
                    // written (a parent's rotation not of unit length only scales the product).
                    let rotation = (above.rotation.inverse() * world_rotation).normalize();
                    // Only the rotation differs from the rest pose: the joint stays in place.
                    let pose = Pose {
                        rotation: world_rotation,
                        ..rest_pose
                    };
                    (rotation, pose)
                }
                None => (joint.rest, rest_pose),
            };
            state.poses.push((pose, rotation));
        }
        resting
    }
}

/// One bone's step: what its joint hangs from, where its tip is in its local axes, and what
/// acts on it.
struct Swing<'a> {
    /// The joint's pose with its rest rotation, under its parent's pose this pass.
    rest_pose: Pose,
    tip: Vec3A,
    acceleration: Vec3A,
    colliders: &'a [PlacedCollider],
    planar: bool,
    dt: f32,
    /// Keep this step's transition for the next (a step of the grid).
    cache: bool,
}

impl Swing<'_> {
    /// Steps `joint`'s tip (kept if `keep`, otherwise only shown) and returns the joint's new
    /// rotation in the world, and whether the tip rests.
    fn step(&self, joint: &mut Joint, keep: bool) -> (Quat, bool) {
        let rest_pose = self.rest_pose;
        let origin = rest_pose.translation;
        let rest_tip = rest_pose.point(self.tip);
        let length = rest_tip.distance(origin);
        let hangs = joint.hangs(self.acceleration);
        let moved = joint
            .rest_tip
            .map_or(Vec3A::ZERO, |before| rest_tip - before);
        let (mut offset, mut velocity) = self.advance(joint, moved);
        let touches = self.collide(&mut offset, &mut velocity, origin, rest_tip, length);
        let rest = rest_test(&RestTest {
            moved,
            offset,
            velocity,
            hangs,
            kept: joint.offset,
            touches,
            tolerance: REST * length,
            omega: joint.omega,
            dt: self.dt,
        });
        let swing = arc(
            rest_tip - origin,
            length,
            rest_tip + offset - origin,
            self.planar,
        );
        if keep {
            joint.rest_tip = Some(rest_tip);
            (joint.offset, joint.velocity) = match rest {
                Rest::Hanging => (hangs, Vec3A::ZERO),
                Rest::Held => (offset, Vec3A::ZERO),
                Rest::Moving => (offset, velocity),
            };
        }
        (swing * rest_pose.rotation, rest != Rest::Moving)
    }

    /// The exact step of the tip's offset from its rest place, which moved by `moved` over the
    /// step (at a constant rate: a first-order hold), under the constant acceleration.
    fn advance(&self, joint: &mut Joint, moved: Vec3A) -> (Vec3A, Vec3A) {
        let dt = self.dt;
        if dt == 0.0 {
            return (joint.offset, joint.velocity);
        }
        let step = match joint.step {
            Some(cached) if cached.dt.to_bits() == dt.to_bits() => cached.transition,
            _ => {
                let transition = joint.spring.transition(dt);
                if self.cache {
                    joint.step = Some(CachedTransition { dt, transition });
                }
                transition
            }
        };
        // Relative to the rest place at the end of the step, the tip starts `moved` behind it.
        let start = SpringState::new(joint.offset - moved, joint.velocity);
        let stepped = step.step_toward_moving(start, Vec3A::ZERO, moved / dt);
        // The response to the constant acceleration adds to it (the equation is linear).
        let [[_, f1], _] = step.matrix();
        let offset = stepped.position + self.acceleration * step.acceleration_gain();
        let velocity = stepped.velocity + self.acceleration * f1;
        if offset.is_finite() && velocity.is_finite() {
            (offset, velocity)
        } else {
            warn_once!("bevy_sprung: a SpringChain tip's motion was not finite; put at rest");
            (joint.hangs(self.acceleration), Vec3A::ZERO)
        }
    }

    /// Keeps the bone's end out of the colliders: an end inside one turns about the joint, in
    /// the plane of the bone and the collider, to where the bone's length meets the surface;
    /// the tip follows, and loses its velocity into the collider. Whether it touched one.
    fn collide(
        &self,
        offset: &mut Vec3A,
        velocity: &mut Vec3A,
        origin: Vec3A,
        rest_tip: Vec3A,
        length: f32,
    ) -> bool {
        if self.colliders.is_empty() || length == 0.0 {
            return false;
        }
        let tip = rest_tip + *offset;
        let Some(mut direction) = (tip - origin).try_normalize() else {
            return false;
        };
        let mut turned = false;
        // A capsule's nearest point moves as the end turns: a few passes settle it.
        for _ in 0..COLLIDER_PASSES {
            for collider in self.colliders {
                let end = origin + direction * length;
                let mut centre = Vec3A::from(collider.nearest(end.into()));
                if self.planar {
                    centre.z = origin.z;
                }
                let Some(out) = turn_out(origin, direction, length, centre, collider.radius) else {
                    continue;
                };
                direction = out;
                turned = true;
                let normal = (origin + direction * length - centre).normalize_or_zero();
                let into = velocity.dot(normal);
                if into < 0.0 {
                    *velocity -= normal * into;
                }
            }
        }
        if turned {
            // Held at the bone's length: motion along the bone would move nothing and never
            // settle.
            *offset = origin + direction * length - rest_tip;
            *velocity -= direction * velocity.dot(direction);
        }
        turned
    }
}

/// Whether a tip rests after its step, and how.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Rest {
    Moving,
    /// Free, where gravity holds it, slow.
    Hanging,
    /// Held by a collider where it stopped (the spring still pulls it into the collider, and
    /// along its bone, which moves nothing).
    Held,
}

/// What the rest test of one tip reads.
struct RestTest {
    /// How far its rest place moved over the step.
    moved: Vec3A,
    /// Its offset from its rest place and its velocity after the step.
    offset: Vec3A,
    velocity: Vec3A,
    /// Where gravity holds it, and where it was before the step.
    hangs: Vec3A,
    kept: Vec3A,
    /// Whether a collider turned it.
    touches: bool,
    /// How near is near enough (a fraction of the bone's length), and the spring's natural
    /// frequency, which turns it into a speed.
    tolerance: f32,
    omega: f32,
    dt: f32,
}

/// Whether a tip rests: its rest place did not move (or by rounding only: its parent re-posed
/// from the same state), and it hangs or is held, to within the tolerance.
fn rest_test(test: &RestTest) -> Rest {
    let within = |v: Vec3A, distance: f32| v.length_squared() <= distance * distance;
    let tolerance = test.tolerance;
    if !within(test.moved, 0.1 * tolerance) {
        Rest::Moving
    } else if within(test.offset - test.hangs, tolerance)
        && within(test.velocity, tolerance * test.omega)
    {
        Rest::Hanging
    } else if test.touches && within(test.offset - test.kept, tolerance * test.omega * test.dt) {
        Rest::Held
    } else {
        Rest::Moving
    }
}

/// The direction nearest `direction` in which a bone of `length` from `origin` ends on the
/// surface of the ball of `radius` about `centre`, if it ends inside it now; `None` when it
/// does not, or when the joint itself is inside the ball or the bone cannot leave it.
fn turn_out(
    origin: Vec3A,
    direction: Vec3A,
    length: f32,
    centre: Vec3A,
    radius: f32,
) -> Option<Vec3A> {
    let to_centre = centre - origin;
    let distance = to_centre.length();
    // A joint inside (a joint on the surface, where the bone before it was turned, is not).
    if distance <= radius * (1.0 - 1e-4) {
        return None;
    }
    // A hair beyond the surface, so that rounding does not leave the end inside.
    let radius = radius * (1.0 + 1e-5);
    if (origin + direction * length).distance(centre) >= radius {
        return None;
    }
    let axis = to_centre / distance;
    // The angle from the axis at which the end meets the surface (law of cosines).
    let cos = (length * length + distance * distance - radius * radius) / (2.0 * length * distance);
    if !(-1.0..=1.0).contains(&cos) {
        return None;
    }
    let across = (direction - axis * direction.dot(axis))
        .try_normalize()
        .unwrap_or_else(|| axis.any_orthonormal_vector());
    Some(axis * cos + across * (1.0 - cos * cos).max(0.0).sqrt())
}

/// The shortest rotation that turns direction `from` (of length `from_length`) onto direction
/// `to` (about z only when `planar`); the identity where either is zero or not finite.
fn arc(from: Vec3A, from_length: f32, to: Vec3A, planar: bool) -> Quat {
    if planar {
        let (from, to) = (from.truncate(), to.truncate());
        if from == Vec2::ZERO || to == Vec2::ZERO {
            return Quat::IDENTITY;
        }
        return Quat::from_rotation_z(from.angle_to(to));
    }
    // The half-way form: (from × to, |from||to| + from · to) is the rotation by the angle
    // between them, scaled by 2|from||to|cos(θ/2), so one normalisation gives it without
    // normalising the directions first. Its parts have errors of a few ulp of |from||to|, so it
    // is accurate unless the directions are nearly opposite, where the axis is arbitrary and a
    // half turn about any axis across `from` is as right as any.
    let lengths = from_length * to.length();
    if !(lengths > 0.0 && lengths < f32::INFINITY) {
        return Quat::IDENTITY;
    }
    let w = lengths + from.dot(to);
    if w <= lengths * (2.0 * f32::EPSILON) {
        let across = from.normalize().any_orthonormal_vector();
        return Quat::from_xyzw(across.x, across.y, across.z, 0.0);
    }
    Quat::from_vec4(from.cross(to).extend(w)).normalize()
}

/// Warns once (per app) about a chain that got a `SpringChain` with no child joints (children
/// with a `Transform`) and no end bone: it has no bone, so nothing turns. Run where the
/// spawning commands have been applied, so children spawned with it are seen.
pub(super) fn warn_jointless(
    chains: Query<(Entity, &SpringChain, Option<&Children>), Added<SpringChain>>,
    transforms: Query<(), With<Transform>>,
    mut warned: Local<bool>,
) {
    if *warned {
        return;
    }
    let jointless = chains.iter().find(|(_, chain, children)| {
        chain.end.is_none()
            && !children.is_some_and(|children| children.iter().any(|c| transforms.contains(c)))
    });
    if let Some((entity, ..)) = jointless {
        *warned = true;
        warn!(
            "bevy_sprung: {entity} has a SpringChain but no child joints (children with a \
             Transform) and no end bone: nothing can turn; put the chain on the first bone of \
             a hierarchy, or give it an end with SpringChain::with_end"
        );
    }
}
