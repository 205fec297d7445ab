//! UI and colour properties: lengths in their units, rotations, and colours that stay in range.

use bevy::color::Oklaba;
use bevy::prelude::*;
use bevy_sprung::color::{SpriteColorSpring, TextColorSpring};
use bevy_sprung::prelude::*;
use bevy_sprung::ui::UiTransformRotationSpring;
use bevy_sprung::ui::{NodeLeftSpring, NodeTopSpring, NodeWidthSpring, UiTransformRotation};

use crate::harness::{app, asleep, run};

#[test]
fn ui_transform_and_node_geometry_spring_in_their_units() {
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Node {
                width: Val::Px(100.0),
                height: Val::Vh(40.0),
                left: Val::Percent(10.0),
                ..default()
            },
            UiTransform {
                translation: Val2::new(Val::Vw(0.0), Val::Auto),
                ..default()
            },
            NodeSizeSpring::new(Spring::snappy(), Val2::new(px(200.0), vh(60.0))),
            NodeLeftSpring::new(Spring::snappy(), percent(30.0)),
            UiTransformTranslationSpring::new(Spring::bouncy(), Val2::new(vw(5.0), px(-8.0))),
            UiTransformScaleSpring::new(Spring::bouncy(), Vec2::splat(1.1)),
            UiTransformRotationSpring::new(Spring::smooth(), Rot2::degrees(15.0)),
        ))
        .id();
    run(&mut app, 5);
    let node = app.world().get::<Node>(entity).unwrap().clone();
    let (Val::Px(width), Val::Vh(height), Val::Percent(left)) =
        (node.width, node.height, node.left)
    else {
        panic!("a unit changed mid-flight: {node:?}")
    };
    assert!(width > 100.0 && width < 200.0, "width {width}");
    assert!(height > 40.0 && height < 60.0, "height {height}");
    assert!(left > 10.0 && left < 30.0, "left {left}");
    run(&mut app, 300);
    let node = app.world().get::<Node>(entity).unwrap().clone();
    assert_eq!(
        (node.width, node.height, node.left),
        (Val::Px(200.0), Val::Vh(60.0), Val::Percent(30.0))
    );
    let transform = *app.world().get::<UiTransform>(entity).unwrap();
    // `Auto` has no number to keep: it is read as 0 and becomes pixels.
    assert_eq!(
        transform.translation,
        Val2::new(Val::Vw(5.0), Val::Px(-8.0))
    );
    assert_eq!(transform.scale, Vec2::splat(1.1));
    assert_eq!(transform.rotation, Rot2::degrees(15.0));
    assert!(asleep::<UiTransformRotation>(&app, entity));
}

/// A bouncy collapse to zero size lands on 0 without a negative width on the way (what layout
/// would clamp, visibly, for a frame), while a position overshoots freely.
#[test]
fn node_sizes_do_not_pass_through_zero() {
    let bouncy = Spring::from_natural_frequency(20.0, 0.1).unwrap();
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Node {
                width: Val::Percent(50.0),
                top: Val::Px(40.0),
                ..default()
            },
            NodeWidthSpring::new(bouncy, percent(0.0)),
            NodeTopSpring::new(bouncy, px(0.0)),
        ))
        .id();
    let mut overshot = false;
    for _ in 0..240 {
        app.update();
        let node = app.world().get::<Node>(entity).unwrap();
        let Val::Percent(width) = node.width else {
            panic!("width changed unit: {:?}", node.width)
        };
        assert!(width >= 0.0, "width went negative: {width}");
        overshot |= matches!(node.top, Val::Px(top) if top < -1.0);
    }
    assert!(overshot, "the position spring should overshoot past 0");
    let node = app.world().get::<Node>(entity).unwrap();
    assert_eq!((node.width, node.top), (Val::Percent(0.0), Val::Px(0.0)));
}

#[test]
fn ui_rotation_takes_the_short_way() {
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            UiTransform::from_rotation(Rot2::degrees(170.0)),
            UiTransformRotationSpring::new(Spring::smooth(), Rot2::degrees(-170.0)),
        ))
        .id();
    for _ in 0..120 {
        app.update();
        let angle = app
            .world()
            .get::<UiTransform>(entity)
            .unwrap()
            .rotation
            .as_degrees();
        assert!(angle.abs() >= 169.99, "went the long way: {angle}°");
    }
}

/// A very bouncy colour spring overshoots, but its channels and alpha never leave their range;
/// the motion is an even blend in Oklab and lands exactly on the target.
#[test]
fn colours_stay_in_range_and_land_exactly() {
    let bouncy = Spring::from_natural_frequency(25.0, 0.05).unwrap();
    let mut app = app(60);
    let target = Color::srgba(1.0, 0.0, 0.0, 1.0);
    let entity = app
        .world_mut()
        .spawn((
            BackgroundColor(Color::srgba(0.0, 0.0, 1.0, 0.2)),
            BackgroundColorSpring::new(bouncy, target),
            Sprite::default(),
            SpriteColorSpring::new(bouncy, Color::srgba(0.0, 1.0, 0.0, 0.0)),
            TextColor(Color::WHITE),
            TextColorSpring::new(bouncy, Color::BLACK),
        ))
        .id();
    for _ in 0..600 {
        app.update();
        let world = app.world();
        for color in [
            world.get::<BackgroundColor>(entity).unwrap().0,
            world.get::<Sprite>(entity).unwrap().color,
            world.get::<TextColor>(entity).unwrap().0,
        ] {
            let linear = LinearRgba::from(color);
            for channel in [linear.red, linear.green, linear.blue, linear.alpha] {
                assert!((0.0..=1.0).contains(&channel), "{color:?} out of range");
            }
        }
    }
    let world = app.world();
    assert_eq!(world.get::<BackgroundColor>(entity).unwrap().0, target);
    assert_eq!(world.get::<TextColor>(entity).unwrap().0, Color::BLACK);
}

/// Halfway through a critically damped blend from black to white the colour is a perceptual
/// mid-grey (Oklab lightness ≈ 0.5), not sRGB's mid value.
#[test]
fn colours_blend_in_oklab() {
    let spring = Spring::from_natural_frequency(8.0, 1.0).unwrap();
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            BackgroundColor(Color::BLACK),
            BackgroundColorSpring::new(spring, Color::WHITE),
        ))
        .id();
    let mut lightness = Vec::new();
    for _ in 0..60 {
        app.update();
        let color = app.world().get::<BackgroundColor>(entity).unwrap().0;
        lightness.push(Oklaba::from(color).lightness);
    }
    // Lightness follows the exact critically damped response 1 − f0(t), to f32 rounding.
    let dt = 1.0 / 60.0_f32;
    for (frame, &l) in lightness.iter().enumerate().skip(1) {
        let t = dt * frame as f32;
        let [[f0, _], _] = spring.transition(t).matrix();
        assert!(
            (l - (1.0 - f0)).abs() < 2e-3,
            "frame {frame}: L = {l} vs {}",
            1.0 - f0
        );
    }
}

/// A UI length of `number` in one of the units a size is given in.
fn size_length(random: &mut crate::harness::Random, number: f32) -> Val {
    match random.below(6) {
        0 => Val::Percent(number / 4.0),
        1 => Val::Vw(number / 8.0),
        2 => Val::Auto,
        _ => Val::Px(number),
    }
}

fn size(random: &mut crate::harness::Random) -> Val2 {
    let mut number = || 300.0 * random.unit();
    let (width, height) = (number(), number());
    Val2::new(size_length(random, width), size_length(random, height))
}

/// The number of a length (0 for `Auto`).
fn length_number(value: Val) -> f32 {
    match value {
        Val::Px(n) | Val::Percent(n) | Val::Vw(n) | Val::Vh(n) | Val::VMin(n) | Val::VMax(n) => n,
        Val::Auto => 0.0,
    }
}

/// One operation of the `NodeSize` chaos below, on one of `nodes`.
fn size_operation(app: &mut App, nodes: &[Entity], random: &mut crate::harness::Random) {
    let node = random.pick(nodes);
    let spring = random.pick(&[
        Spring::bouncy(),
        Spring::wobbly(),
        Spring::snappy(),
        Spring::from_natural_frequency(30.0, 0.05).unwrap(),
    ]);
    let target = size(random);
    let kick = Vec2::new(random.symmetric(5e3), random.symmetric(5e3));
    let operation = random.below(14);
    let mut entity = app.world_mut().entity_mut(node);
    let has_spring = entity.contains::<NodeSizeSpring>();
    match operation {
        0 => {
            entity.insert(NodeSizeSpring::new(spring, target).with_velocity(kick));
        }
        1 => {
            entity.remove::<NodeSizeSpring>();
        }
        2 | 3 if has_spring => {
            entity
                .get_mut::<NodeSizeSpring>()
                .unwrap()
                .set_target(target);
        }
        4 if has_spring => {
            entity
                .get_mut::<NodeSizeSpring>()
                .unwrap()
                .add_impulse(kick);
        }
        5 if has_spring => {
            entity
                .get_mut::<NodeSizeSpring>()
                .unwrap()
                .set_velocity(kick);
        }
        6 if has_spring => {
            let rate = kick * 0.05;
            entity
                .get_mut::<NodeSizeSpring>()
                .unwrap()
                .set_target_velocity(rate);
        }
        7 => {
            if entity.contains::<SpringSequence<NodeSize>>() {
                entity.remove::<SpringSequence<NodeSize>>();
            } else {
                let steps = [size(random), size(random), size(random)];
                entity.insert(
                    SpringSequence::<NodeSize>::new()
                        .then(steps[0])
                        .then_after(random.unit() * 0.3, steps[1])
                        .then_within(2.0, steps[2])
                        .with_spring(spring),
                );
            }
        }
        8 => {
            let written = size(random);
            if let Some(mut node) = entity.get_mut::<Node>() {
                (node.width, node.height) = (written.x, written.y);
            }
        }
        11 => {
            let skipping = entity
                .get::<bevy_sprung::spring::SkipFrames>()
                .is_some_and(|skip| skip.0);
            entity.insert(bevy_sprung::spring::SkipFrames(!skipping));
        }
        12 => {
            if entity.contains::<Node>() {
                entity.remove::<Node>();
            } else {
                entity.insert(Node::default());
            }
        }
        13 => {
            let steps = [size(random), size(random)];
            entity.insert(
                SpringSequence::<NodeSize>::new()
                    .then(steps[0])
                    .then(steps[1])
                    .ping_pong(),
            );
        }
        9 | 10 => clock_operation(app, operation, random),
        _ => {}
    }
}

/// A clock operation of the `NodeSize` chaos: the game pauses or resumes, or the frame time
/// changes (a rate from 30 to 240 fps, or a hitch).
fn clock_operation(app: &mut App, operation: usize, random: &mut crate::harness::Random) {
    use crate::harness::frame;
    use bevy::time::TimeUpdateStrategy;
    use std::time::Duration;
    if operation == 9 {
        let paused = random.chance(0.5);
        let mut time = app.world_mut().resource_mut::<Time<Virtual>>();
        if paused {
            time.pause();
        } else {
            time.unpause();
        }
    } else {
        let hitch = random.chance(0.3);
        let step = if hitch {
            Duration::from_secs_f32(random.unit() * 0.25)
        } else {
            frame(random.pick(&[30, 60, 144, 240]))
        };
        app.insert_resource(TimeUpdateStrategy::ManualDuration(step));
    }
}

/// `NodeSize` never passes through zero, on any path: springs inserted (with a velocity),
/// replaced and removed, targets in mixed units, sequences started and stopped over them,
/// kicks and velocities of any size, moving targets, values written by hand, pauses and
/// hitches. Every target is at least zero; no width or height drawn is ever below it.
#[test]
fn a_node_size_never_passes_through_zero_on_any_path() {
    use crate::harness::Random;
    for seed in 0..8_u64 {
        let mut random = Random(seed);
        let mut app = app(60);
        let nodes: Vec<Entity> = (0..24)
            .map(|_| app.world_mut().spawn(Node::default()).id())
            .collect();
        for frame_index in 0..1500 {
            for _ in 0..4 {
                size_operation(&mut app, &nodes, &mut random);
            }
            app.update();
            for &node in &nodes {
                let Some(drawn) = app.world().get::<Node>(node) else {
                    continue;
                };
                for (axis, length) in [("width", drawn.width), ("height", drawn.height)] {
                    let number = length_number(length);
                    assert!(
                        number >= 0.0 && number.is_finite(),
                        "seed {seed}, frame {frame_index}: {node} {axis} = {length:?}"
                    );
                }
            }
        }
    }
}
