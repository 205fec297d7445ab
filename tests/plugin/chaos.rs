//! Structural chaos: seeded random worlds in which entities are spawned, cloned and despawned
//! (also by observers of the plugin's own events), spring components are inserted, replaced and
//! removed, the components they move are removed and come back, hierarchies change, entities are
//! disabled and hidden, clocks pause and hitch, followed leaders teleport (told or not), list
//! rows pop out of layout as they leave, drags start and end, and NaN, infinite and huge
//! values arrive through the setters, through reflection and through the properties themselves.
//!
//! After every frame: every value the plugin writes is finite, every event went to a live
//! entity, and every sleep came with exactly one settle event (and every settle event with a
//! sleep). Afterwards, with the chaos stopped, every spring comes to rest on its target.
//!
//! Every feature adds its components and operations here (see [`Operation`]).

use core::f32::consts::PI;
use std::time::Duration;

use bevy::camera::visibility::ViewVisibility;
use bevy::camera::{OrthographicProjection, Projection};
use bevy::ecs::entity_disabling::Disabled;
use bevy::ecs::query::Allow;
use bevy::ecs::world::DeferredWorld;
use bevy::math::VectorSpace;
use bevy::platform::collections::HashSet;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::camera::{
    BlendLens, BlendRotation, BlendTranslation, CameraGoal, ConfinerVolume, RigHorizontal,
    RigHorizontalSpring, RigLookAhead, RigOrbit, RigVertical, RigZoom,
};
use bevy_sprung::camera::{
    CameraBlend, CameraTargets, Confiner, DeadZone, GroupFraming, LookAhead, OrbitRig,
    ScreenPosition, VirtualCamera,
};
use bevy_sprung::chain::ChainCollider;
use bevy_sprung::choreography::{
    AllSpringsSettled, SequenceCompleted, SequenceInterrupted, SpringGroup, SpringGroupSettled,
};
use bevy_sprung::clock::{DefaultSpringClock, SpringClock};
use bevy_sprung::inertia::DragBounds;
use bevy_sprung::interaction::{DragReleased, InteractionTargets, SpringDrag};
use bevy_sprung::layers::SpringLayerPlugin;
use bevy_sprung::layers::{LayerSpring, SpringLayers};
use bevy_sprung::prelude::*;
use bevy_sprung::presence::StaggerChildren;
use bevy_sprung::property::{SpringProperty, ValueOf, VelocityOf};
use bevy_sprung::reduced_motion::KeepMotion;
use bevy_sprung::spring::{SkipFrames, SpringAsleep, SpringMotion};
use bevy_sprung::tracking::TargetWarped;
use bevy_sprung::transform::Scale;
use bevy_sprung::ui::PopLayout;
use bevy_sprung::ui::{NodeSize, UiTransformRotation, UiTransformTranslation};
use bevy_sprung::visibility::CatchUpWhenHidden;

use crate::bad_input::write_by_reflection;
use crate::harness::{Random, app_with};
use crate::interaction::{drag, drag_end, drag_start, enter, leave, press, release};

/// What an entity of the chaos is: which operations apply to it.
#[derive(Component, Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// A `Transform` with translation, rotation and scale springs, followers, sequences,
    /// groups, shakes, squash and catch-up.
    Body,
    /// A UI node: colour, size, rotation and translation springs, and drags.
    Node,
    /// What followers follow: a `Transform` that walks.
    Leader,
    /// What the others are parented to; may spring its translation.
    Parent,
}

/// A leader's velocity, units per second.
#[derive(Component, Clone, Copy)]
struct Walk(Vec3);

/// What ordinary observer code inserts on the entity of an event: it panics for a despawned one.
#[derive(Component)]
struct Touched;

/// The chaos' state: its generator, the entities it made, and what the observers saw.
#[derive(Resource)]
struct Chaos {
    random: Random,
    /// Every entity the chaos made, in order (some despawned since).
    entities: Vec<Entity>,
    /// Springs that reported settling and have not woken since: (entity, property).
    asleep: HashSet<(Entity, &'static str)>,
    /// Properties into which the chaos wrote a non-finite value, not finite again since.
    poisoned: HashSet<(Entity, &'static str)>,
    /// Entities cloned this frame (a clone of a sleeping spring sleeps without an event).
    cloned: Vec<Entity>,
    /// Springs whose sleep marker was inserted this frame.
    fell_asleep: Vec<(Entity, &'static str)>,
    /// Settle events this frame.
    reported: Vec<(Entity, &'static str)>,
    /// What went wrong, with the frame.
    violations: Vec<String>,
    /// Events seen in all, by kind.
    events: Vec<&'static str>,
    /// What the chaos did, frame by frame, to tell a failure's story.
    log: Vec<String>,
    frame: u32,
}

impl Chaos {
    fn violation(&mut self, what: String) {
        let frame = self.frame;
        self.violations.push(format!("frame {frame}: {what}"));
    }

    /// Notes what the chaos did to `entity`.
    fn note(&mut self, entity: Entity, what: impl core::fmt::Display) {
        let frame = self.frame;
        self.log.push(format!("frame {frame}: {entity}: {what}"));
    }

    /// The first violations, and what the chaos did to the entity of the first one.
    fn report(&self) -> String {
        let first = self.violations.first().map_or("", String::as_str);
        let entity = first
            .split_whitespace()
            .map(|word| word.trim_end_matches(':'))
            .find(|word| word.contains('v') && word.starts_with(|c: char| c.is_ascii_digit()))
            .unwrap_or_default();
        format!(
            "{:#?}\n{}",
            &self.violations[..self.violations.len().min(10)],
            self.story(entity)
        )
    }

    /// What the chaos did to the entity written `entity` (as `Entity` displays).
    fn story(&self, entity: &str) -> String {
        let lines: Vec<&String> = self
            .log
            .iter()
            .filter(|line| line.contains(&format!(" {entity}:")))
            .collect();
        format!("what happened to {entity}:\n{lines:#?}")
    }
}

/// Notes what the chaos did to `entity`.
fn note(world: &mut World, entity: Entity, what: impl core::fmt::Display) {
    world.resource_mut::<Chaos>().note(entity, what);
}

/// A property the chaos springs: ordinary values, values at the edge of `f32` and beyond it,
/// and velocities.
trait Chaotic: SpringProperty {
    const NAME: &'static str;
    /// The kind of entity that has the property.
    const KIND: Kind;
    /// An ordinary target.
    fn value(random: &mut Random) -> ValueOf<Self>;
    /// A target at the edge: huge, degenerate, NaN or infinite.
    fn extreme(random: &mut Random) -> ValueOf<Self>;
    /// A velocity, now and then huge or non-finite.
    fn velocity(random: &mut Random) -> VelocityOf<Self>;
    /// The component to insert where it was removed.
    fn component() -> Self::Component;
    /// Whether every number of a value is finite.
    fn is_finite(value: ValueOf<Self>) -> bool;
    /// What an entity shows when its spring rests on `target`: the target, with the layers
    /// the chaos puts on the property.
    fn shown_at_rest(entity: EntityRef, target: ValueOf<Self>) -> ValueOf<Self> {
        let _ = entity;
        target
    }
}

/// An ordinary coordinate: mostly hundreds of units, sometimes a big world's or a unit's.
fn scalar(random: &mut Random) -> f32 {
    match random.below(10) {
        0 => random.symmetric(1e6),
        1 => random.symmetric(1.0),
        _ => random.symmetric(500.0),
    }
}

/// A number at or past the edge of `f32`.
fn extreme_scalar(random: &mut Random) -> f32 {
    random.pick(&[
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MAX,
        -f32::MAX,
        3e38,
        1e30,
        -1e25,
        1e20,
        1e-40,
        0.0,
    ])
}

/// A coordinate that is now and then extreme.
fn maybe_extreme(random: &mut Random) -> f32 {
    if random.chance(0.2) {
        extreme_scalar(random)
    } else {
        scalar(random)
    }
}

fn vec3(mut component: impl FnMut() -> f32) -> Vec3 {
    Vec3::new(component(), component(), component())
}

/// A velocity component: usually tens to thousands of units a second, now and then extreme.
fn speed(random: &mut Random) -> f32 {
    if random.chance(0.1) {
        extreme_scalar(random)
    } else {
        10.0 * scalar(random)
    }
}

impl Chaotic for Translation {
    const NAME: &'static str = "translation";
    const KIND: Kind = Kind::Body;
    fn shown_at_rest(entity: EntityRef, target: Vec3) -> Vec3 {
        entity
            .get::<SpringLayers<Translation>>()
            .map_or(target, |layers| layers.apply(target))
    }
    fn value(random: &mut Random) -> Vec3 {
        vec3(|| scalar(random))
    }
    fn extreme(random: &mut Random) -> Vec3 {
        vec3(|| maybe_extreme(random))
    }
    fn velocity(random: &mut Random) -> Vec3 {
        vec3(|| speed(random))
    }
    fn component() -> Transform {
        Transform::default()
    }
    fn is_finite(value: Vec3) -> bool {
        value.is_finite()
    }
}

impl Chaotic for Rotation {
    const NAME: &'static str = "rotation";
    const KIND: Kind = Kind::Body;
    fn value(random: &mut Random) -> Quat {
        let (x, y, z) = (
            random.symmetric(PI),
            random.symmetric(PI),
            random.symmetric(PI),
        );
        Quat::from_euler(EulerRot::XYZ, x, y, z)
    }
    fn extreme(random: &mut Random) -> Quat {
        Quat::from_xyzw(
            maybe_extreme(random),
            maybe_extreme(random),
            maybe_extreme(random),
            maybe_extreme(random),
        )
    }
    fn velocity(random: &mut Random) -> Vec3 {
        vec3(|| speed(random) / 100.0)
    }
    fn component() -> Transform {
        Transform::default()
    }
    fn is_finite(value: Quat) -> bool {
        value.is_finite()
    }
}

impl Chaotic for Scale {
    fn shown_at_rest(entity: EntityRef, target: Vec3) -> Vec3 {
        entity
            .get::<SpringLayers<Scale>>()
            .map_or(target, |layers| layers.apply(target))
    }
    const NAME: &'static str = "scale";
    const KIND: Kind = Kind::Body;
    fn value(random: &mut Random) -> Vec3 {
        vec3(|| 0.05 + 3.0 * random.unit())
    }
    fn extreme(random: &mut Random) -> Vec3 {
        vec3(|| maybe_extreme(random))
    }
    fn velocity(random: &mut Random) -> Vec3 {
        vec3(|| speed(random) / 100.0)
    }
    fn component() -> Transform {
        Transform::default()
    }
    fn is_finite(value: Vec3) -> bool {
        value.is_finite()
    }
}

impl Chaotic for BackgroundColor {
    const NAME: &'static str = "background";
    const KIND: Kind = Kind::Node;
    fn value(random: &mut Random) -> Color {
        Color::srgba(random.unit(), random.unit(), random.unit(), random.unit())
    }
    fn extreme(random: &mut Random) -> Color {
        if random.chance(0.5) {
            Color::linear_rgba(
                maybe_extreme(random),
                maybe_extreme(random),
                maybe_extreme(random),
                maybe_extreme(random),
            )
        } else {
            Color::srgb(maybe_extreme(random), random.unit(), random.unit())
        }
    }
    fn velocity(random: &mut Random) -> Vec4 {
        Vec4::new(speed(random), speed(random), speed(random), speed(random)) / 100.0
    }
    fn component() -> BackgroundColor {
        BackgroundColor(Color::BLACK)
    }
    fn is_finite(value: Color) -> bool {
        Vec4::from_array(value.to_linear().to_f32_array()).is_finite()
    }
}

/// Whether a UI length's number is finite.
fn finite_length(value: Val) -> bool {
    match value {
        Val::Px(x) | Val::Percent(x) | Val::Vw(x) | Val::Vh(x) | Val::VMin(x) | Val::VMax(x) => {
            x.is_finite()
        }
        Val::Auto => true,
    }
}

/// A UI length: pixels mostly, percent or auto sometimes.
fn length(random: &mut Random, value: f32) -> Val {
    match random.below(8) {
        0 => Val::Percent(value / 5.0),
        1 => Val::Auto,
        _ => Val::Px(value),
    }
}

impl Chaotic for NodeSize {
    const NAME: &'static str = "size";
    const KIND: Kind = Kind::Node;
    fn value(random: &mut Random) -> Val2 {
        let (width, height) = (400.0 * random.unit(), 400.0 * random.unit());
        Val2::new(length(random, width), length(random, height))
    }
    fn extreme(random: &mut Random) -> Val2 {
        let (width, height) = (maybe_extreme(random), maybe_extreme(random));
        Val2::new(length(random, width), length(random, height))
    }
    fn velocity(random: &mut Random) -> Vec2 {
        Vec2::new(speed(random), speed(random))
    }
    fn component() -> Node {
        Node::default()
    }
    fn is_finite(value: Val2) -> bool {
        finite_length(value.x) && finite_length(value.y)
    }
}

impl Chaotic for UiTransformRotation {
    const NAME: &'static str = "ui rotation";
    const KIND: Kind = Kind::Node;
    fn value(random: &mut Random) -> Rot2 {
        Rot2::radians(random.symmetric(4.0 * PI))
    }
    fn extreme(random: &mut Random) -> Rot2 {
        Rot2 {
            cos: maybe_extreme(random),
            sin: maybe_extreme(random),
        }
    }
    fn velocity(random: &mut Random) -> f32 {
        speed(random) / 100.0
    }
    fn component() -> UiTransform {
        UiTransform::default()
    }
    fn is_finite(value: Rot2) -> bool {
        value.is_finite()
    }
}

impl Chaotic for UiTransformTranslation {
    const NAME: &'static str = "ui translation";
    const KIND: Kind = Kind::Node;
    fn value(random: &mut Random) -> Val2 {
        let (x, y) = (scalar(random), scalar(random));
        Val2::new(length(random, x), length(random, y))
    }
    fn extreme(random: &mut Random) -> Val2 {
        let (x, y) = (maybe_extreme(random), maybe_extreme(random));
        Val2::new(length(random, x), length(random, y))
    }
    fn velocity(random: &mut Random) -> Vec2 {
        Vec2::new(speed(random), speed(random))
    }
    fn component() -> UiTransform {
        UiTransform::default()
    }
    fn is_finite(value: Val2) -> bool {
        finite_length(value.x) && finite_length(value.y)
    }
}

/// A spring: a preset, or a random one from an ordinary range.
fn spring(random: &mut Random) -> Spring {
    if random.chance(0.7) {
        random.pick(&Spring::presets()).1
    } else {
        let frequency = 4.0 + 36.0 * random.unit();
        let ratio = 0.1 + 1.9 * random.unit();
        Spring::from_natural_frequency(frequency, ratio).unwrap()
    }
}

/// A live entity of the chaos (of `kind`, if given), if one is found in a few draws.
fn live(world: &mut World, kind: Option<Kind>) -> Option<Entity> {
    for _ in 0..8 {
        let entity = {
            let mut chaos = world.resource_mut::<Chaos>();
            if chaos.entities.is_empty() {
                return None;
            }
            let count = chaos.entities.len();
            let index = chaos.random.below(count);
            chaos.entities[index]
        };
        let Ok(found) = world.get_entity(entity) else {
            continue;
        };
        if kind.is_none_or(|kind| found.get::<Kind>() == Some(&kind)) {
            return Some(entity);
        }
    }
    None
}

/// Runs `draw` with the chaos' generator.
fn draw<T>(world: &mut World, draw: impl FnOnce(&mut Random) -> T) -> T {
    draw(&mut world.resource_mut::<Chaos>().random)
}

/// One of the operations on property `P` of a live entity of its kind.
#[expect(
    clippy::too_many_lines,
    reason = "one arm per operation: the list of what the chaos does to a spring"
)]
fn spring_operation<P: Chaotic>(world: &mut World)
where
    ValueOf<P>: core::fmt::Debug,
{
    let Some(entity) = live(world, Some(P::KIND)) else {
        return;
    };
    let (operation, target, extreme, velocity, parameters) = draw(world, |random| {
        (
            random.below(14),
            P::value(random),
            P::extreme(random),
            P::velocity(random),
            spring(random),
        )
    });
    note(
        world,
        entity,
        format_args!(
            "{} operation {operation}: {target:?}, {extreme:?}, {velocity:?}, {parameters:?}",
            P::NAME
        ),
    );
    let mut entity_mut = world.entity_mut(entity);
    let has_spring = entity_mut.contains::<PropertySpring<P>>();
    match operation {
        // Insert, or replace, the spring; now and then with a velocity and on the real clock.
        0 | 1 => {
            let mut new = PropertySpring::<P>::new(parameters, target);
            if operation == 1 {
                new = new.with_velocity(velocity).with_clock(SpringClock::Real);
            }
            entity_mut.insert(new);
        }
        2 => {
            entity_mut.remove::<PropertySpring<P>>();
        }
        // Retarget: ordinary, extreme (refused where not finite), only if it differs.
        3..=5 if has_spring => {
            let mut spring = entity_mut.get_mut::<PropertySpring<P>>().unwrap();
            match operation {
                3 => spring.set_target(target),
                4 => spring.set_target(extreme),
                _ => {
                    spring.set_target_if_neq(target);
                }
            }
        }
        6 | 7 if has_spring => {
            let mut spring = entity_mut.get_mut::<PropertySpring<P>>().unwrap();
            if operation == 6 {
                spring.add_impulse(velocity);
            } else {
                spring.set_velocity(velocity);
            }
        }
        8 if has_spring => {
            let mut spring = entity_mut.get_mut::<PropertySpring<P>>().unwrap();
            spring.set_target_velocity(velocity);
        }
        9 if has_spring => {
            let mut spring = entity_mut.get_mut::<PropertySpring<P>>().unwrap();
            spring.set_spring(parameters);
            let clock = spring.clock();
            spring.set_clock(if clock.is_some() {
                None
            } else {
                Some(SpringClock::Real)
            });
        }
        // Something else writes the property: an extreme value, or the sleep marker is
        // removed by hand.
        10 => {
            if let Some(mut component) = entity_mut.get_mut::<P::Component>() {
                P::set(&mut component, extreme);
                if !P::is_finite(P::get(&component)) {
                    world
                        .resource_mut::<Chaos>()
                        .poisoned
                        .insert((entity, P::NAME));
                }
            }
        }
        11 => {
            entity_mut.remove::<SpringAsleep<P>>();
        }
        // The component the spring moves goes away, or comes back.
        12 => {
            if entity_mut.contains::<P::Component>() {
                entity_mut.remove::<P::Component>();
            } else {
                entity_mut.insert(P::component());
            }
        }
        // Reflection writes what the setters refuse.
        13 if has_spring => {
            let velocity: bevy_sprung::property::OffsetOf<P> = velocity.into();
            match draw(world, |random| random.below(3)) {
                0 => write_by_reflection::<PropertySpring<P>>(
                    world,
                    entity,
                    &["spring", "mass"],
                    &-1.0_f32,
                ),
                1 => write_by_reflection::<PropertySpring<P>>(world, entity, &["target"], &extreme),
                _ => {
                    write_by_reflection::<SpringMotion<P>>(world, entity, &["velocity"], &velocity);
                }
            }
        }
        _ => {}
    }
}

/// Spawns an entity of `kind`, now and then as a parent's child.
fn spawn(world: &mut World, kind: Kind) -> Entity {
    let parent = if kind == Kind::Parent {
        None
    } else {
        live(world, Some(Kind::Parent)).filter(|_| draw(world, |random| random.chance(0.3)))
    };
    let (position, spring) = draw(world, |random| (Translation::value(random), spring(random)));
    let mut entity = match kind {
        Kind::Body => world.spawn((kind, Transform::from_translation(position))),
        Kind::Node => world.spawn((
            kind,
            Node::default(),
            UiTransform::default(),
            BackgroundColor(Color::BLACK),
        )),
        Kind::Leader => world.spawn((
            kind,
            Transform::from_translation(position),
            Walk(position / 10.0),
        )),
        Kind::Parent => world.spawn((
            kind,
            Transform::from_translation(position),
            TranslationSpring::new(spring, Vec3::ZERO),
        )),
    };
    if let Some(parent) = parent {
        entity.insert(ChildOf(parent));
    }
    let id = entity.id();
    world.resource_mut::<Chaos>().entities.push(id);
    note(
        world,
        id,
        format_args!("spawned, a {kind:?}, parent {parent:?}"),
    );
    id
}

/// The operations on entities and on the features built on springs, each a small function of
/// the world: a new feature adds its own here.
const OPERATIONS: &[(&str, fn(&mut World))] = &[
    ("spawn", spawn_any),
    ("despawn", despawn),
    ("clone", clone),
    ("disable or enable", toggle_disabled),
    ("reparent", reparent),
    ("follow", follow),
    ("sequence", sequence),
    ("group", group),
    ("shake", shake),
    ("squash", squash),
    ("catch up", catch_up),
    ("skip frames", skip_frames),
    ("drag component", drag_component),
    ("drag start", |world| pointer_drag(world, 0)),
    ("drag move", |world| pointer_drag(world, 1)),
    ("drag end", |world| pointer_drag(world, 2)),
    ("interaction targets", interaction_targets),
    ("pointer", pointer_state),
    ("reduced motion", reduced_motion),
    ("default clock", default_clock),
    ("game clock", game_clock),
    ("camera rig", camera_rig),
    ("camera shots", camera_shots),
    ("window", resize_window),
    ("presence", presence),
    ("implicit", implicit),
    ("layer", layer),
    ("chain", chain),
    ("inertia", inertia),
    ("teleport", teleport),
    ("list exit", list_exit),
];

/// A live entity to operate on (of `kind`, if given), with the operation noted in its story.
fn target_of(world: &mut World, kind: Option<Kind>, operation: &str) -> Option<Entity> {
    let entity = live(world, kind)?;
    note(world, entity, operation);
    Some(entity)
}

fn spawn_any(world: &mut World) {
    let kind = draw(world, |random| {
        random.pick(&[
            Kind::Body,
            Kind::Body,
            Kind::Node,
            Kind::Leader,
            Kind::Parent,
        ])
    });
    spawn(world, kind);
}

fn despawn(world: &mut World) {
    if let Some(entity) = target_of(world, None, "despawn") {
        world.despawn(entity);
    }
}

/// A copy of an entity (not a parent: its children would be shared): its values, springs and
/// sleep markers.
fn clone(world: &mut World) {
    let Some(original) = live(world, None) else {
        return;
    };
    if world.get::<Kind>(original) == Some(&Kind::Parent) {
        return;
    }
    let copy = world.entity_mut(original).clone_and_spawn();
    note(world, copy, format_args!("a clone of {original}"));
    let mut chaos = world.resource_mut::<Chaos>();
    chaos.entities.push(copy);
    chaos.cloned.push(copy);
    let poisoned: Vec<_> = chaos
        .poisoned
        .iter()
        .filter(|(entity, _)| *entity == original)
        .map(|&(_, name)| (copy, name))
        .collect();
    chaos.poisoned.extend(poisoned);
}

fn toggle_disabled(world: &mut World) {
    if let Some(entity) = target_of(world, None, "disable or enable") {
        let mut entity = world.entity_mut(entity);
        if entity.contains::<Disabled>() {
            entity.remove::<Disabled>();
        } else {
            entity.insert(Disabled);
        }
    }
}

/// Parented to a parent, or made a root.
fn reparent(world: &mut World) {
    let Some(child) = target_of(world, None, "reparent") else {
        return;
    };
    if world.get::<Kind>(child) == Some(&Kind::Parent) {
        return;
    }
    let parent = live(world, Some(Kind::Parent));
    match parent {
        Some(parent) if draw(world, |random| random.chance(0.6)) => {
            world.entity_mut(child).insert(ChildOf(parent));
        }
        _ => {
            world.entity_mut(child).remove::<ChildOf>();
        }
    }
}

/// Follow a leader (live, or despawned), in `Update` or `FixedUpdate`, looking at it or not;
/// or stop following.
fn follow(world: &mut World) {
    let Some(follower) = target_of(world, Some(Kind::Body), "follow") else {
        return;
    };
    let leader = live(world, Some(Kind::Leader)).unwrap_or(Entity::PLACEHOLDER);
    let (offset, fixed, look, teleports) = draw(world, |random| {
        (
            Translation::value(random) / 100.0,
            random.chance(0.5),
            random.chance(0.5),
            random.chance(0.5),
        )
    });
    let mut follower = world.entity_mut(follower);
    if follower.contains::<SpringFollow>() && !fixed {
        follower.remove::<SpringFollow>();
        return;
    }
    let mut follow = SpringFollow::new(leader, offset);
    if fixed {
        follow = follow.moving_in_fixed_update();
    }
    if look {
        follow = follow.looking_at(Vec3::ZERO);
    }
    if teleports {
        follow = follow.with_teleport_distance(1000.0);
    }
    follower.insert(follow);
}

/// A leader (which followers and rigs may frame) is carried far in one frame — a respawn —
/// told with `TargetWarped` or not (a follower or rig with a teleport distance catches it).
fn teleport(world: &mut World) {
    let Some(leader) = target_of(world, Some(Kind::Leader), "teleport") else {
        return;
    };
    let (jump, told) = draw(world, |random| {
        (Translation::value(random) * 50.0, random.chance(0.5))
    });
    if let Some(mut transform) = world.get_mut::<Transform>(leader) {
        transform.translation += jump;
    }
    if told {
        world.trigger(TargetWarped {
            entity: leader,
            delta: jump,
        });
    }
}

/// A UI node in a list: given a presence that pops out of layout as it leaves, sent out,
/// called back, or stripped of it.
fn list_exit(world: &mut World) {
    let Some(entity) = target_of(world, Some(Kind::Node), "list exit") else {
        return;
    };
    let (choice, to) = draw(world, |random| {
        (random.below(4), UiTransformTranslation::value(random))
    });
    match choice {
        0 => {
            world.entity_mut(entity).insert((
                Presence::default(),
                PopLayout,
                UiTransformTranslationSpring::new(Spring::snappy(), Val2::ZERO),
                ExitTo::<UiTransformTranslation>(to),
            ));
        }
        1 => {
            world.commands().entity(entity).despawn_after_exit();
        }
        2 => {
            world.commands().entity(entity).cancel_exit();
        }
        _ => {
            world
                .entity_mut(entity)
                .remove::<(PopLayout, ExitTo<UiTransformTranslation>)>();
        }
    }
    world.flush();
}

/// A camera rig on a new entity framing live (or despawned) leaders and bodies, orthographic
/// or perspective, with a random set of parts; or a part of a live rig added, changed or
/// removed. Rigs have no `Kind`: the entity operations (despawn, clone, disable, reparent) reach
/// them, the property operations do not.
fn camera_rig(world: &mut World) {
    let rigs: Vec<Entity> = world
        .query_filtered::<Entity, With<CameraRig>>()
        .iter(world)
        .collect();
    if rigs.is_empty() || draw(world, |random| random.chance(0.3)) {
        let targets: Vec<CameraTarget> = (0..draw(world, |random| 1 + random.below(3)))
            .map(|_| {
                let entity = live(world, Some(Kind::Leader))
                    .or_else(|| live(world, Some(Kind::Body)))
                    .unwrap_or(Entity::PLACEHOLDER);
                let (weight, radius) =
                    draw(world, |random| (maybe_extreme(random), scalar(random)));
                CameraTarget::new(entity)
                    .with_weight(weight)
                    .with_radius(radius)
            })
            .collect();
        let (perspective, fixed, spring) = draw(world, |random| {
            (random.chance(0.4), random.chance(0.3), spring(random))
        });
        let projection = if perspective {
            Projection::Perspective(default())
        } else {
            Projection::Orthographic(OrthographicProjection::default_2d())
        };
        let targets = CameraTargets::new(targets);
        let targets = if fixed {
            targets.moving_in_fixed_update()
        } else {
            targets
        };
        let rig = world
            .spawn((
                projection,
                CameraRig::new(spring).with_offset(Vec3::new(0.0, 2.0, 10.0)),
                targets,
            ))
            .id();
        world.resource_mut::<Chaos>().entities.push(rig);
        note(world, rig, "spawned, a camera rig");
        for _ in 0..draw(world, |random| random.below(4)) {
            camera_part(world, rig);
        }
        return;
    }
    let rig = draw(world, |random| random.pick(&rigs));
    camera_part(world, rig);
}

/// One part of `rig` added, changed or removed, or its goal or zoom written (now and then not
/// finite).
fn camera_part(world: &mut World, rig: Entity) {
    let (part, add, a, b, spring) = draw(world, |random| {
        (
            random.below(11),
            random.chance(0.7),
            maybe_extreme(random),
            scalar(random),
            spring(random),
        )
    });
    note(
        world,
        rig,
        format_args!("camera part {part}, add {add}, {a}, {b}"),
    );
    let mut entity = world.entity_mut(rig);
    match (part, add) {
        (0, true) => drop(entity.insert(LookAhead::new(b.abs() / 100.0).with_spring(spring))),
        (1, true) => drop(entity.insert(DeadZone::view(Vec2::new(b.abs() / 1000.0, 0.1)))),
        (2, true) => drop(entity.insert(ScreenPosition(Vec2::new(0.0, a / 1000.0)))),
        (3, true) => drop(
            entity.insert(
                Confiner::new(Rect::new(-b.abs(), -b.abs(), b.abs() + 1.0, b.abs() + 1.0))
                    .with_slowing_distance(a.abs()),
            ),
        ),
        (4, true) => drop(entity.insert(GroupFraming::new(a / 100.0))),
        (5, true) => drop(
            entity.insert(
                OrbitRig::new(b.abs() + 1.0)
                    .with_angles(a, b)
                    .with_spring(spring),
            ),
        ),
        (6, true) => drop(
            entity.insert(
                ConfinerVolume::new(Vec3::splat(-b.abs()), Vec3::splat(b.abs()))
                    .with_slowing_distance(1.0),
            ),
        ),
        (7, _) => {
            if let Some(mut rig) = entity.get_mut::<CameraRig>() {
                rig.hold_vertical = add;
                rig.zoom = a;
            }
        }
        (8, _) => {
            if let Some(mut goal) = entity.get_mut::<CameraGoal>() {
                goal.point = Vec3::new(a, b, a);
            }
        }
        (9, _) => {
            if let Some(mut orbit) = entity.get_mut::<OrbitRig>() {
                orbit.rotate(Vec2::new(a, b));
                orbit.zoom_by(b);
            }
        }
        (10, _) => drop(entity.remove::<CameraTargets>()),
        (0, false) => drop(entity.remove::<LookAhead>()),
        (1, false) => drop(entity.remove::<DeadZone>()),
        (2, false) => drop(entity.remove::<ScreenPosition>()),
        (3, false) => drop(entity.remove::<Confiner>()),
        (4, false) => drop(entity.remove::<GroupFraming>()),
        (5, false) => drop(entity.remove::<OrbitRig>()),
        _ => drop(entity.remove::<ConfinerVolume>()),
    }
}

/// A live rig made a shot of some priority (or no longer one), and a rendering camera that
/// blends between shots spawned if there is none.
fn camera_shots(world: &mut World) {
    let rigs: Vec<Entity> = world
        .query_filtered::<Entity, With<CameraRig>>()
        .iter(world)
        .collect();
    if rigs.is_empty() {
        return;
    }
    let (rig, priority, shot) = draw(world, |random| {
        (random.pick(&rigs), random.below(5), random.chance(0.8))
    });
    note(world, rig, format_args!("shot {shot}, priority {priority}"));
    if shot {
        #[expect(
            clippy::cast_possible_wrap,
            clippy::cast_possible_truncation,
            reason = "below 5"
        )]
        world
            .entity_mut(rig)
            .insert(VirtualCamera::new(priority as i32));
    } else {
        world.entity_mut(rig).remove::<VirtualCamera>();
    }
    if world
        .query_filtered::<(), With<CameraBlend>>()
        .iter(world)
        .next()
        .is_none()
    {
        let spring = draw(world, spring);
        let camera = world
            .spawn((Projection::Perspective(default()), CameraBlend::new(spring)))
            .id();
        world.resource_mut::<Chaos>().entities.push(camera);
        note(world, camera, "spawned, a blending camera");
    }
}

/// The window resized (the rigs' views change under them).
fn resize_window(world: &mut World) {
    let (width, height) = draw(world, |random| {
        (1.0 + 2000.0 * random.unit(), 1.0 + 2000.0 * random.unit())
    });
    for mut window in world.query::<&mut Window>().iter_mut(world) {
        window.resolution.set(width, height);
    }
}

/// Presence: made present (entering from a value, leaving toward one, maybe extreme), asked to
/// leave (also again, also by a parent that staggers its children), or turned back.
fn presence(world: &mut World) {
    let Some(entity) = target_of(world, Some(Kind::Body), "presence") else {
        return;
    };
    let (choice, from, to, interval) = draw(world, |random| {
        (
            random.below(6),
            Translation::value(random),
            Translation::extreme(random),
            random.unit() * 0.2,
        )
    });
    match choice {
        0 => {
            world.entity_mut(entity).insert((
                Presence::default(),
                EnterFrom::<Translation>(from),
                ExitTo::<Translation>(to),
            ));
        }
        1 | 2 => {
            world.commands().entity(entity).despawn_after_exit();
        }
        3 => {
            world.commands().entity(entity).cancel_exit();
        }
        4 => {
            world
                .entity_mut(entity)
                .insert(StaggerChildren::new(interval));
        }
        _ => {
            world
                .entity_mut(entity)
                .remove::<(Presence, ExitTo<Translation>, StaggerChildren)>();
        }
    }
    world.flush();
}

/// Writes to a translation made to spring (`ImplicitSpring`), or no longer.
fn implicit(world: &mut World) {
    let Some(entity) = target_of(world, Some(Kind::Body), "implicit") else {
        return;
    };
    let (add, spring, written) = draw(world, |random| {
        (
            random.chance(0.6),
            spring(random),
            Translation::value(random),
        )
    });
    let mut entity = world.entity_mut(entity);
    if add {
        entity.insert(ImplicitSpring::<Translation>::new(spring));
        if let Some(mut transform) = entity.get_mut::<Transform>() {
            transform.translation = written;
        }
    } else {
        entity.remove::<ImplicitSpring<Translation>>();
    }
}

/// A layer of the translation: added with a target (now and then extreme), punched, or
/// removed mid-flight.
fn layer(world: &mut World) {
    let Some(entity) = target_of(world, Some(Kind::Body), "layer") else {
        return;
    };
    let (what, spring, target, kick) = draw(world, |random| {
        (
            random.below(3),
            spring(random),
            Translation::extreme(random),
            Translation::velocity(random),
        )
    });
    let mut entity = world.entity_mut(entity);
    match (
        what,
        entity.get_mut::<LayerSpring<Translation, ChaosLayer>>(),
    ) {
        (0, _) => {
            entity.insert(LayerSpring::<Translation, ChaosLayer>::new(spring, target));
        }
        (1, Some(mut layer)) => layer.punch(kick),
        _ => {
            entity.remove::<LayerSpring<Translation, ChaosLayer>>();
        }
    }
}

/// The layer the chaos springs.
#[derive(TypePath)]
struct ChaosLayer;

/// A spring chain on an entity (whatever hangs below it is its joints), with gravity, a
/// collider and now and then a reset; or removed.
fn chain(world: &mut World) {
    let Some(entity) = target_of(world, None, "chain") else {
        return;
    };
    let (what, spring, gravity, collider) = draw(world, |random| {
        (
            random.below(4),
            spring(random),
            Translation::extreme(random),
            [0.0, 40.0, 80.0][random.below(3)],
        )
    });
    let collider = world.spawn(ChainCollider::sphere(collider)).id();
    let mut entity = world.entity_mut(entity);
    match (what, entity.get_mut::<SpringChain>()) {
        (0 | 1, _) => {
            entity.insert(
                SpringChain::new(spring)
                    .with_gravity(gravity)
                    .with_colliders([collider])
                    .with_teleport_distance(500.0),
            );
        }
        (2, Some(mut chain)) => chain.reset(),
        _ => {
            entity.remove::<SpringChain>();
        }
    }
}

/// A fling with `Inertia` (bounded now and then; the velocity now and then extreme).
fn inertia(world: &mut World) {
    let Some(entity) = target_of(world, Some(Kind::Body), "inertia") else {
        return;
    };
    let (bounded, deceleration, velocity) = draw(world, |random| {
        (
            random.chance(0.5),
            random.unit() * 5.0,
            Translation::extreme(random),
        )
    });
    let mut inertia = Inertia::new(deceleration);
    if bounded {
        inertia = inertia.bounded(DragBounds {
            min: Vec3::splat(-200.0),
            max: Vec3::splat(200.0),
            give: 50.0,
        });
    }
    let mut entity = world.entity_mut(entity);
    if !entity.contains::<Inertia>() {
        entity.insert(inertia);
    }
    if let Some(mut inertia) = entity.get_mut::<Inertia>() {
        inertia.fling(velocity);
    }
}

/// A few targets, on settle and timed, delayed (one of them extreme); or removed.
fn sequence(world: &mut World) {
    let Some(entity) = target_of(world, Some(Kind::Body), "sequence") else {
        return;
    };
    let (steps, delay, seconds) = draw(world, |random| {
        (
            [
                Translation::value(random),
                Translation::value(random),
                Translation::extreme(random),
            ],
            random.unit(),
            random.unit(),
        )
    });
    let within = draw(world, |random| random.chance(0.5));
    let mut entity = world.entity_mut(entity);
    if entity.contains::<SpringSequence<Translation>>() {
        entity.remove::<SpringSequence<Translation>>();
    } else if within {
        entity.insert(
            SpringSequence::<Translation>::new()
                .hold(delay)
                .then_within(0.5, steps[0])
                .hold(seconds)
                .then(steps[2]),
        );
    } else {
        entity.insert(
            SpringSequence::<Translation>::new()
                .then(steps[0])
                .then_after(seconds, steps[1])
                .then(steps[2])
                .delayed(delay),
        );
    }
}

/// Named (three names), the entity alone, or none.
fn group(world: &mut World) {
    let Some(entity) = target_of(world, None, "group") else {
        return;
    };
    let name = draw(world, |random| random.below(4));
    let mut entity = world.entity_mut(entity);
    match name {
        0 => {
            entity.remove::<SpringGroup>();
        }
        1 => {
            entity.insert(SpringGroup::this_entity());
        }
        _ => {
            entity.insert(SpringGroup::named(["a", "b", "c"][name - 1]));
        }
    }
}

fn shake(world: &mut World) {
    let Some(entity) = target_of(world, Some(Kind::Body), "shake") else {
        return;
    };
    let trauma = draw(world, |random| maybe_extreme(random).abs().min(2.0));
    let mut entity = world.entity_mut(entity);
    if let Some(mut shake) = entity.get_mut::<Shake>() {
        shake.add_trauma(trauma);
        if trauma < 0.1 {
            entity.remove::<Shake>();
        }
    } else {
        entity.insert(
            Shake::new(7)
                .with_max_translation(Vec3::splat(5.0))
                .with_max_rotation(Vec3::splat(0.1)),
        );
    }
}

/// Squash & stretch, on entities without a scale spring (its docs say not both).
fn squash(world: &mut World) {
    let Some(entity) = target_of(world, Some(Kind::Body), "squash") else {
        return;
    };
    let mut entity = world.entity_mut(entity);
    if entity.contains::<SquashStretch>() {
        entity.remove::<SquashStretch>();
    } else if !entity.contains::<ScaleSpring>() {
        entity.insert(SquashStretch::new(0.002, 1.5));
    }
}

/// Hidden springs skip frames; seen again, they catch up.
fn catch_up(world: &mut World) {
    let Some(entity) = target_of(world, None, "catch up") else {
        return;
    };
    let seen = draw(world, |random| random.chance(0.5));
    let mut entity = world.entity_mut(entity);
    if entity.contains::<CatchUpWhenHidden>() && seen {
        entity.remove::<CatchUpWhenHidden>();
    } else {
        let visibility = if seen {
            ViewVisibility::VISIBLE
        } else {
            ViewVisibility::HIDDEN
        };
        entity.insert((CatchUpWhenHidden, visibility));
    }
}

/// Springs skip frames for the app's own reasons, or step every frame again.
fn skip_frames(world: &mut World) {
    let Some(entity) = target_of(world, None, "skip frames") else {
        return;
    };
    let skip = draw(world, |random| random.below(3));
    let mut entity = world.entity_mut(entity);
    match skip {
        0 => {
            entity.remove::<SkipFrames>();
        }
        _ => {
            entity.insert(SkipFrames(skip == 1));
        }
    }
}

fn drag_component(world: &mut World) {
    let Some(node) = target_of(world, Some(Kind::Node), "drag component") else {
        return;
    };
    let mut node = world.entity_mut(node);
    if node.contains::<SpringDrag>() {
        node.remove::<SpringDrag>();
    } else {
        node.insert(SpringDrag::new());
    }
}

/// A drag starts (0), moves (1) or ends (2) on a node, at a random place.
fn pointer_drag(world: &mut World, phase: u8) {
    let Some(node) = target_of(world, Some(Kind::Node), "pointer drag") else {
        return;
    };
    let position = draw(world, |random| {
        Vec2::new(random.symmetric(800.0), random.symmetric(600.0))
    });
    match phase {
        0 => drag_start(world, node, position, Entity::PLACEHOLDER),
        1 => drag(world, node, position),
        _ => drag_end(world, node, position),
    }
}

/// Pointer states retarget a node's colour (one of its targets extreme).
fn interaction_targets(world: &mut World) {
    let Some(node) = target_of(world, Some(Kind::Node), "interaction targets") else {
        return;
    };
    let targets = draw(world, |random| {
        InteractionTargets::<BackgroundColor>::new(BackgroundColor::value(random))
            .hovered(BackgroundColor::value(random))
            .pressed(BackgroundColor::extreme(random))
    });
    let mut node = world.entity_mut(node);
    if node.contains::<InteractionTargets<BackgroundColor>>() {
        node.remove::<InteractionTargets<BackgroundColor>>();
    } else {
        node.insert(targets);
    }
}

fn pointer_state(world: &mut World) {
    let Some(node) = target_of(world, Some(Kind::Node), "pointer") else {
        return;
    };
    match draw(world, |random| random.below(4)) {
        0 => enter(world, node),
        1 => leave(world, node),
        2 => press(world, node),
        _ => release(world, node),
    }
}

/// The app's reduced-motion preference changes, and a spring opts out or in.
fn reduced_motion(world: &mut World) {
    let (preference, keep) = draw(world, |random| {
        (
            random.pick(&[
                ReducedMotion::Full,
                ReducedMotion::Snap,
                ReducedMotion::NoOvershoot,
                ReducedMotion::Scaled(2.0),
                ReducedMotion::Scaled(f32::NAN),
            ]),
            random.chance(0.5),
        )
    });
    world.insert_resource(preference);
    if let Some(entity) = target_of(world, None, "keep motion") {
        let mut entity = world.entity_mut(entity);
        if keep {
            entity.insert(KeepMotion);
        } else {
            entity.remove::<KeepMotion>();
        }
    }
}

fn default_clock(world: &mut World) {
    let clock = draw(world, |random| {
        random.pick(&[SpringClock::Game, SpringClock::Real])
    });
    world.insert_resource(DefaultSpringClock(clock));
}

/// The game pauses, resumes, runs slower or at its speed.
fn game_clock(world: &mut World) {
    let change = draw(world, |random| random.below(4));
    let mut time = world.resource_mut::<Time<Virtual>>();
    match change {
        0 => time.pause(),
        1 => time.unpause(),
        2 => time.set_relative_speed(0.25),
        _ => time.set_relative_speed(1.0),
    }
}

/// The leaders walk, every frame.
fn walk(time: Res<Time>, mut leaders: Query<(&Walk, &mut Transform)>) {
    for (walk, mut transform) in &mut leaders {
        transform.translation += walk.0 * time.delta_secs();
    }
}

/// The observers of a spring property's events: a settle goes to a live entity whose spring
/// sleeps and has not reported since it last woke; ordinary observer code then touches the
/// entity, and now and then despawns another one, removes a spring, or despawns itself.
fn observe<P: Chaotic>(app: &mut App) {
    app.add_observer(|event: On<SpringSettled<P>>, mut world: DeferredWorld| {
        let entity = event.entity;
        let alive = world.get_entity(entity).is_ok();
        let sleeps = world.get::<SpringAsleep<P>>(entity).is_some();
        let mut chaos = world.resource_mut::<Chaos>();
        chaos.events.push(P::NAME);
        if !alive {
            chaos.violation(format!("{} settled for despawned {entity}", P::NAME));
            return;
        }
        if !sleeps {
            chaos.violation(format!("{} settled but awake: {entity}", P::NAME));
        }
        if !chaos.asleep.insert((entity, P::NAME)) {
            chaos.violation(format!(
                "{} settled twice without waking: {entity}",
                P::NAME
            ));
        }
        chaos.reported.push((entity, P::NAME));
        let reaction = chaos.random.below(12);
        let count = chaos.entities.len();
        let other = chaos.random.below(count);
        let other = chaos.entities[other];
        let mut commands = world.commands();
        // `try_`: an earlier observer's reaction in the same flush may have queued this entity's
        // despawn (its event was triggered while it was alive, which is what is asserted).
        commands.entity(entity).try_insert(Touched);
        match reaction {
            0 => {
                commands.entity(other).try_despawn();
            }
            1 => {
                commands.entity(entity).despawn();
            }
            2 => {
                commands.entity(other).try_remove::<PropertySpring<P>>();
            }
            3 => {
                commands.entity(other).try_remove::<P::Component>();
            }
            _ => {}
        }
    });
    app.add_observer(
        |event: On<Insert, SpringAsleep<P>>, mut chaos: ResMut<Chaos>| {
            chaos.fell_asleep.push((event.entity, P::NAME));
        },
    );
    app.add_observer(
        |event: On<Remove, SpringAsleep<P>>, mut chaos: ResMut<Chaos>| {
            chaos.asleep.remove(&(event.entity, P::NAME));
        },
    );
}

/// An observer of entity event `E`: it goes to a live entity, which ordinary code then touches.
fn observe_entity_event<E: EntityEvent>(app: &mut App, name: &'static str) {
    app.add_observer(move |event: On<E>, mut world: DeferredWorld| {
        let entity = event.event_target();
        let alive = world.get_entity(entity).is_ok();
        let mut chaos = world.resource_mut::<Chaos>();
        chaos.events.push(name);
        if alive {
            world.commands().entity(entity).try_insert(Touched);
        } else {
            chaos.violation(format!("{name} for despawned {entity}"));
        }
    });
}

/// The springs' properties, each with its operations and observers.
macro_rules! for_each_property {
    ($action:ident ( $($argument:expr),* )) => {
        $action::<Translation>($($argument),*);
        $action::<Rotation>($($argument),*);
        $action::<Scale>($($argument),*);
        $action::<BackgroundColor>($($argument),*);
        $action::<NodeSize>($($argument),*);
        $action::<UiTransformRotation>($($argument),*);
        $action::<UiTransformTranslation>($($argument),*);
    };
}

/// A headless app with the chaos' observers and a world of a few entities of each kind.
fn chaos_app(seed: u64, plugin: SpringPlugins) -> App {
    let mut app = app_with(60, plugin);
    app.insert_resource(Chaos {
        random: Random(seed),
        entities: Vec::new(),
        asleep: HashSet::default(),
        poisoned: HashSet::default(),
        cloned: Vec::new(),
        fell_asleep: Vec::new(),
        reported: Vec::new(),
        violations: Vec::new(),
        events: Vec::new(),
        log: Vec::new(),
        frame: 0,
    })
    .insert_resource(Time::<Fixed>::from_hz(50.0))
    .add_plugins(SpringLayerPlugin::<Translation, ChaosLayer>::default())
    .add_systems(FixedUpdate, walk);
    for_each_property!(observe(&mut app));
    observe_entity_event::<AllSpringsSettled>(&mut app, "all settled");
    observe_entity_event::<SequenceCompleted<Translation>>(&mut app, "completed");
    observe_entity_event::<SequenceInterrupted<Translation>>(&mut app, "interrupted");
    observe_entity_event::<DragReleased>(&mut app, "released");
    app.add_observer(|_: On<SpringGroupSettled>, mut chaos: ResMut<Chaos>| {
        chaos.events.push("group settled");
    });
    let world = app.world_mut();
    crate::harness::primary_window(world, 800, 600);
    for kind in [Kind::Parent, Kind::Leader, Kind::Leader] {
        spawn(world, kind);
    }
    for _ in 0..6 {
        spawn(world, Kind::Body);
        spawn(world, Kind::Node);
    }
    for _ in 0..40 {
        for_each_property!(spring_operation(world));
    }
    app
}

/// A frame's time: mostly 60 fps, also 30, 144 and 360, frames of no time, and hitches.
fn frame_time(random: &mut Random) -> Duration {
    let seconds = match random.below(24) {
        0 => 0.0,
        1 => 0.5,
        2 => 2.0,
        3 | 4 => 1.0 / 360.0,
        5 | 6 => 1.0 / 144.0,
        7 | 8 => 1.0 / 30.0,
        _ => 1.0 / 60.0,
    };
    Duration::from_secs_f64(seconds)
}

/// One frame of chaos: a few operations, then the update.
fn chaotic_frame(app: &mut App) {
    let world = app.world_mut();
    let (operations, dt) = draw(world, |random| (random.below(5), frame_time(random)));
    for _ in 0..operations {
        if draw(world, |random| random.chance(0.55)) {
            match draw(world, |random| random.below(7)) {
                0 => spring_operation::<Translation>(world),
                1 => spring_operation::<Rotation>(world),
                2 => spring_operation::<Scale>(world),
                3 => spring_operation::<BackgroundColor>(world),
                4 => spring_operation::<NodeSize>(world),
                5 => spring_operation::<UiTransformRotation>(world),
                _ => spring_operation::<UiTransformTranslation>(world),
            }
        } else {
            let (_, operation) = draw(world, |random| random.pick(OPERATIONS));
            operation(world);
        }
    }
    app.insert_resource(TimeUpdateStrategy::ManualDuration(dt));
    app.update();
}

/// After a frame: every value written is finite, and every sleep came with one settle event
/// and every settle event with a sleep.
fn check_frame(world: &mut World) {
    for_each_property!(check_values(world));
    check_cameras(world);
    let mut chaos = world.resource_mut::<Chaos>();
    let fell_asleep = core::mem::take(&mut chaos.fell_asleep);
    let reported = core::mem::take(&mut chaos.reported);
    let cloned = core::mem::take(&mut chaos.cloned);
    for sleep in &fell_asleep {
        let alive = world.get_entity(sleep.0).is_ok();
        if alive && !cloned.contains(&sleep.0) && !reported.contains(sleep) {
            let mut chaos = world.resource_mut::<Chaos>();
            chaos.violation(format!(
                "{} fell asleep without an event: {}",
                sleep.1, sleep.0
            ));
        }
    }
    let mut chaos = world.resource_mut::<Chaos>();
    for report in &reported {
        if !fell_asleep.contains(report) {
            chaos.violation(format!(
                "{} settled without falling asleep: {}",
                report.1, report.0
            ));
        }
    }
    chaos.frame += 1;
}

/// Every camera a rig or a blend places is finite, and so is its lens.
fn check_cameras(world: &mut World) {
    let mut cameras = world.query_filtered::<(Entity, &Transform, Option<&Projection>), Or<(With<CameraRig>, With<CameraBlend>)>>();
    let broken: Vec<Entity> = cameras
        .iter(world)
        .filter(|(_, transform, projection)| {
            let lens = match projection {
                Some(Projection::Orthographic(orthographic)) => orthographic.scale,
                Some(Projection::Perspective(perspective)) => perspective.fov,
                _ => 1.0,
            };
            !(transform.translation.is_finite()
                && transform.rotation.is_finite()
                && lens.is_finite())
        })
        .map(|(entity, ..)| entity)
        .collect();
    let mut chaos = world.resource_mut::<Chaos>();
    for entity in broken {
        chaos.violation(format!(
            "camera {entity} placed at a non-finite pose or lens"
        ));
    }
}

/// Every value of property `P` is finite, but where the chaos itself wrote a non-finite one that
/// no spring has stepped over since (a spring restores it when it next steps).
fn check_values<P: Chaotic>(world: &mut World)
where
    ValueOf<P>: core::fmt::Debug,
{
    let mut values = world.query_filtered::<(Entity, &P::Component), Allow<Disabled>>();
    let mut wrong = Vec::new();
    let mut restored = Vec::new();
    let chaos = world.resource::<Chaos>();
    for (entity, component) in values.iter(world) {
        let value = P::get(component);
        let poisoned = chaos.poisoned.contains(&(entity, P::NAME));
        if P::is_finite(value) {
            if poisoned {
                restored.push((entity, P::NAME));
            }
        } else if !poisoned {
            wrong.push(format!("a non-finite {} on {entity}: {value:?}", P::NAME));
        }
    }
    let mut chaos = world.resource_mut::<Chaos>();
    for entry in restored {
        chaos.poisoned.remove(&entry);
    }
    for what in wrong {
        chaos.violation(what);
    }
}

/// The chaos stops: every entity enabled and seen, the game clock running, the leaders and the
/// moving targets still, drags let go, and the components the springs move back.
fn calm(app: &mut App) {
    let world = app.world_mut();
    let mut disabled = world.query_filtered::<Entity, With<Disabled>>();
    for entity in disabled.iter(world).collect::<Vec<_>>() {
        world.entity_mut(entity).remove::<Disabled>();
    }
    world.insert_resource(ReducedMotion::Full);
    let mut time = world.resource_mut::<Time<Virtual>>();
    time.unpause();
    time.set_relative_speed(1.0);
    for mut walk in world.query::<&mut Walk>().iter_mut(world) {
        walk.0 = Vec3::ZERO;
    }
    for mut visibility in world.query::<&mut ViewVisibility>().iter_mut(world) {
        *visibility = ViewVisibility::VISIBLE;
    }
    for mut skip in world.query::<&mut SkipFrames>().iter_mut(world) {
        skip.0 = false;
    }
    let dragged: Vec<Entity> = world
        .query::<(Entity, &SpringDrag)>()
        .iter(world)
        .filter(|(_, drag)| drag.is_dragged())
        .map(|(entity, _)| entity)
        .collect();
    for node in dragged {
        drag_end(world, node, Vec2::ZERO);
    }
    for_each_property!(calm_property(world));
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
        1.0 / 60.0,
    )));
}

/// [`calm`] for the springs on `P`: their targets stop moving, their components come back.
fn calm_property<P: Chaotic>(world: &mut World) {
    let mut springs = world.query::<(Entity, &mut PropertySpring<P>, Has<P::Component>)>();
    let mut missing = Vec::new();
    for (entity, mut spring, present) in springs.iter_mut(world) {
        spring.set_target_velocity(VelocityOf::<P>::from(
            bevy_sprung::property::OffsetOf::<P>::ZERO,
        ));
        if !present {
            missing.push(entity);
        }
    }
    for entity in missing {
        world.entity_mut(entity).insert(P::component());
    }
}

/// Every spring on `P` rests on its target: asleep, the property exactly its target.
fn assert_at_rest<P: Chaotic>(world: &mut World, seed: u64) -> usize
where
    ValueOf<P>: core::fmt::Debug,
{
    let mut springs = world.query::<(
        Entity,
        &PropertySpring<P>,
        &P::Component,
        Has<SpringAsleep<P>>,
    )>();
    let mut count = 0;
    for (entity, spring, component, asleep) in springs.iter(world) {
        let world: &World = world;
        let value = P::get(component);
        let shown = P::shown_at_rest(world.entity(entity), spring.target());
        assert!(
            asleep && value == shown,
            "seed {seed:#x}: the {} spring of {entity} does not rest on its target: asleep \
             {asleep}, {value:?} vs {:?} (shown with its layers {shown:?}), {:?}\n{}",
            P::NAME,
            spring.target(),
            world.get::<SpringMotion<P>>(entity),
            world.resource::<Chaos>().story(&entity.to_string())
        );
        count += 1;
    }
    count
}

/// Whether every spring sleeps.
fn all_asleep(world: &mut World) -> bool {
    let mut awake = 0;
    macro_rules! count_awake {
        ($($property:ty),*) => {
            $(
                awake += world
                    .query_filtered::<(), (With<PropertySpring<$property>>, Without<SpringAsleep<$property>>)>()
                    .iter(world)
                    .count();
            )*
        };
    }
    count_awake!(
        Translation,
        Rotation,
        Scale,
        BackgroundColor,
        NodeSize,
        UiTransformRotation,
        UiTransformTranslation,
        RigHorizontal,
        RigVertical,
        RigZoom,
        RigLookAhead,
        RigOrbit,
        BlendTranslation,
        BlendRotation,
        BlendLens
    );
    awake == 0
}

/// Thousands of frames of chaos per seed, checked after every frame; then every spring rests on
/// its target. Springs step in `PostUpdate` for half the seeds and in `FixedUpdate` for the
/// others. `SPRUNG_CHAOS_SEEDS=n` adds `n` more seeds (for a longer search).
#[test]
fn springs_survive_a_world_that_changes_under_them() {
    let extra: u64 = std::env::var("SPRUNG_CHAOS_SEEDS")
        .ok()
        .and_then(|seeds| seeds.parse().ok())
        .unwrap_or(0);
    let seeds = [0x5EED_0001_u64, 0xC4A0_5002, 0x0DD_BA11, 0xF00D_F00D]
        .into_iter()
        .chain((1..=extra).map(|n| n.wrapping_mul(0x9E37_79B9_7F4A_7C15)));
    for (index, seed) in seeds.enumerate() {
        run_chaos(seed, index % 2 == 1);
    }
}

/// One seed's chaos (springs stepping in `FixedUpdate` if `fixed`), then the calm.
fn run_chaos(seed: u64, fixed: bool) {
    const FRAMES: u32 = 1500;
    let plugin = if fixed {
        SpringPlugins::default().in_schedule(FixedUpdate)
    } else {
        SpringPlugins::default()
    };
    let mut app = chaos_app(seed, plugin);
    for _ in 0..FRAMES {
        chaotic_frame(&mut app);
        check_frame(app.world_mut());
    }
    let chaos = app.world().resource::<Chaos>();
    assert!(
        chaos.violations.is_empty(),
        "seed {seed:#x}: {}",
        chaos.report()
    );
    let settles = chaos.asleep.len() + chaos.events.len();
    assert!(settles > 50, "seed {seed:#x}: only {settles} events");
    calm(&mut app);
    // Four minutes at most: the slowest spring from the largest offset takes about two.
    for _ in 0..240 {
        for _ in 0..60 {
            app.update();
            check_frame(app.world_mut());
        }
        if all_asleep(app.world_mut()) {
            break;
        }
    }
    let world = app.world_mut();
    let mut springs = 0;
    springs += assert_at_rest::<Translation>(world, seed);
    springs += assert_at_rest::<Rotation>(world, seed);
    springs += assert_at_rest::<Scale>(world, seed);
    springs += assert_at_rest::<BackgroundColor>(world, seed);
    springs += assert_at_rest::<NodeSize>(world, seed);
    springs += assert_at_rest::<UiTransformRotation>(world, seed);
    springs += assert_at_rest::<UiTransformTranslation>(world, seed);
    assert!(
        springs > 3,
        "seed {seed:#x}: only {springs} springs at the end"
    );
    // The cameras came to rest too.
    let mut rigs = world.query_filtered::<Entity, (
        With<RigHorizontalSpring>,
        Without<SpringAsleep<RigHorizontal>>,
    )>();
    let restless: Vec<Entity> = rigs.iter(world).collect();
    assert!(
        restless.is_empty(),
        "seed {seed:#x}: camera rigs still moving after the calm: {restless:?}\n{}",
        restless
            .first()
            .map(|entity| world.resource::<Chaos>().story(&entity.to_string()))
            .unwrap_or_default()
    );
    let chaos = world.resource::<Chaos>();
    assert!(
        chaos.violations.is_empty(),
        "seed {seed:#x}: {}",
        chaos.report()
    );
}
