//! A long run through the real systems: random frame times (hitches of half a second, frames of
//! no time), retargets, impulses and wakes over springs of several properties. Every value stays
//! finite, every sleep comes with one settle event, and after the last retarget every spring
//! settles on its target. (The spring step alone runs a million frames in the crate's own
//! tests.)

use std::time::Duration;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::prelude::*;
use bevy_sprung::spin::{Spin, SpinAngleSpring};
use bevy_sprung::spring::SpringAsleep;
use bevy_sprung::ui::{NodeLeft, NodeLeftSpring};

use crate::harness::{Random, app};

/// The settle events of this frame: entity and property (0 translation, 1 node, 2 spin).
#[derive(Resource, Default)]
struct Events(Vec<(Entity, usize)>);

fn count(settled: On<SpringSettled<Translation>>, mut events: ResMut<Events>) {
    events.0.push((settled.entity, 0));
}

fn count_node(settled: On<SpringSettled<NodeLeft>>, mut events: ResMut<Events>) {
    events.0.push((settled.entity, 1));
}

fn count_spin(
    settled: On<SpringSettled<bevy_sprung::spin::SpinAngle>>,
    mut events: ResMut<Events>,
) {
    events.0.push((settled.entity, 2));
}

/// Whether each sprung entity sleeps.
fn sleeping(app: &mut App) -> (usize, usize) {
    let world = app.world_mut();
    let asleep = world
        .query_filtered::<(), With<SpringAsleep<Translation>>>()
        .iter(world)
        .count()
        + world
            .query_filtered::<(), With<SpringAsleep<NodeLeft>>>()
            .iter(world)
            .count()
        + world
            .query_filtered::<(), With<SpringAsleep<bevy_sprung::spin::SpinAngle>>>()
            .iter(world)
            .count();
    (asleep, 3 * 16)
}

/// Sixteen entities, each with a translation, a UI length and a spin spring of one preset, and
/// a scale from pixels of a small UI to a large 2D world.
fn spawn_entities(app: &mut App) -> Vec<(Entity, f32)> {
    (0..16)
        .map(|i| {
            let presets = Spring::presets();
            let spring = presets[i % presets.len()].1;
            let scale = 10f32.powi(i32::try_from(i % 6).unwrap());
            let entity = app
                .world_mut()
                .spawn((
                    Transform::default(),
                    TranslationSpring::new(spring, Vec3::ZERO),
                    Node::default(),
                    NodeLeftSpring::new(spring, px(0.0)),
                    Spin::z(0.0),
                    SpinAngleSpring::new(spring, 0.0),
                ))
                .id();
            (entity, scale)
        })
        .collect()
}

/// One frame's random time step and events: a retarget one time in 200 per entity, a kick one
/// time in 330.
fn random_frame(app: &mut App, random: &mut Random, entities: &[(Entity, f32)]) {
    let seconds = match random.unit() {
        x if x < 0.01 => 0.0,
        x if x < 0.02 => 0.5 * random.unit(),
        x => 1.0 / (30.0 + 330.0 * x),
    };
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(
        seconds,
    )));
    for &(entity, scale) in entities {
        let event = random.unit();
        let mut world = app.world_mut().entity_mut(entity);
        if event < 0.005 {
            let target = Vec3::new(random.symmetric(scale), random.symmetric(scale), 0.0);
            world
                .get_mut::<TranslationSpring>()
                .unwrap()
                .set_target(target);
            world
                .get_mut::<NodeLeftSpring>()
                .unwrap()
                .set_target(px(random.symmetric(scale)));
            world
                .get_mut::<SpinAngleSpring>()
                .unwrap()
                .set_target(random.symmetric(100.0));
        } else if event < 0.008 {
            let kick = Vec3::new(random.symmetric(10.0 * scale), 0.0, 0.0);
            world
                .get_mut::<TranslationSpring>()
                .unwrap()
                .add_impulse(kick);
            world
                .get_mut::<NodeLeftSpring>()
                .unwrap()
                .add_impulse(random.symmetric(10.0 * scale));
        }
    }
}

/// Checks one entity after a frame: finite values, and one settle event exactly when a spring
/// fell asleep. Returns how many of its springs fell asleep.
fn check_entity(world: &World, frame: u32, entity: Entity, was_asleep: &mut [bool; 3]) -> u32 {
    let events = &world.resource::<Events>().0;
    let transform = world.get::<Transform>(entity).unwrap();
    let Val::Px(left) = world.get::<Node>(entity).unwrap().left else {
        panic!("frame {frame}: left changed unit");
    };
    let angle = world.get::<Spin>(entity).unwrap().angle;
    assert!(
        transform.is_finite() && left.is_finite() && angle.is_finite(),
        "frame {frame}: {transform:?} {left} {angle}"
    );
    let now = [
        world.get::<SpringAsleep<Translation>>(entity).is_some(),
        world.get::<SpringAsleep<NodeLeft>>(entity).is_some(),
        world
            .get::<SpringAsleep<bevy_sprung::spin::SpinAngle>>(entity)
            .is_some(),
    ];
    let mut sleeps = 0;
    for (property, (was, is)) in was_asleep.iter_mut().zip(now).enumerate() {
        let fired = events
            .iter()
            .filter(|&&event| event == (entity, property))
            .count();
        // Falling asleep fires exactly one event; an event means it sleeps now (a spring woken
        // and settled again within one frame sleeps before and after).
        assert!(fired <= 1, "frame {frame}: {fired} settle events at once");
        assert!(fired == 0 || is, "frame {frame}: settled but awake");
        if is && !*was {
            assert_eq!(fired, 1, "frame {frame}: fell asleep without an event");
            sleeps += 1;
        }
        *was = is;
    }
    sleeps
}

#[test]
fn twelve_thousand_frames_of_hitches_retargets_and_impulses() {
    const FRAMES: u32 = 12_000;
    let mut random = Random(0x50AC);
    let mut app = app(60);
    app.init_resource::<Events>()
        .add_observer(count)
        .add_observer(count_node)
        .add_observer(count_spin);
    let entities = spawn_entities(&mut app);
    let mut sleeps = 0_u32;
    let mut was_asleep = vec![[false; 3]; entities.len()];
    for frame in 0..FRAMES {
        random_frame(&mut app, &mut random, &entities);
        app.world_mut().resource_mut::<Events>().0.clear();
        app.update();
        for (&(entity, _), was) in entities.iter().zip(&mut was_asleep) {
            sleeps += check_entity(app.world(), frame, entity, was);
        }
    }
    assert!(
        sleeps > 100,
        "only {sleeps} sleeps: the run does not exercise settling"
    );
    // No more events: everything settles on its target within half a minute of 60 fps.
    app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
        1.0 / 60.0,
    )));
    for _ in 0..1800 {
        app.update();
    }
    let (asleep, total) = sleeping(&mut app);
    assert_eq!(
        asleep, total,
        "springs still moving after the last retarget"
    );
    for &(entity, _) in &entities {
        let world = app.world();
        assert_eq!(
            world.get::<Transform>(entity).unwrap().translation,
            world.get::<TranslationSpring>(entity).unwrap().target()
        );
        assert_eq!(
            world.get::<Node>(entity).unwrap().left,
            world.get::<NodeLeftSpring>(entity).unwrap().target()
        );
    }
}
