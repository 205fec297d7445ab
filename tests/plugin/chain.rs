//! Spring chains: exact, frame-rate independent, lengths kept, at rest free, teleports and
//! colliders.

use bevy::prelude::*;
use bevy_sprung::chain::{ChainCollider, SpringChain};
use bevy_sprung::prelude::*;

use crate::harness::{app, load_tail, run};

/// A body, and hanging from it a chain of `segments` bones of `length` along −x (the joints
/// listed from the chain's first joint down, the last one a bare tip).
fn spawn_chain(
    app: &mut App,
    chain: SpringChain,
    segments: usize,
    length: f32,
) -> (Entity, Vec<Entity>) {
    let world = app.world_mut();
    let body = world.spawn(Transform::default()).id();
    let mut joints = vec![world.spawn((Transform::default(), chain)).id()];
    world.entity_mut(body).add_child(joints[0]);
    for _ in 0..segments {
        let joint = world.spawn(Transform::from_xyz(-length, 0.0, 0.0)).id();
        world.entity_mut(*joints.last().unwrap()).add_child(joint);
        joints.push(joint);
    }
    (body, joints)
}

/// The angle between two rotations, precise for small ones (`Quat::angle_between` goes
/// through `acos`, which in `f32` cannot tell angles below ~5e-4 rad).
fn angle(a: Quat, b: Quat) -> f32 {
    2.0 * (a.inverse() * b).xyz().length().asin()
}

fn rotations(app: &App, joints: &[Entity]) -> Vec<Quat> {
    joints
        .iter()
        .map(|&joint| app.world().get::<Transform>(joint).unwrap().rotation)
        .collect()
}

fn positions(app: &App, joints: &[Entity]) -> Vec<Vec3> {
    joints
        .iter()
        .map(|&joint| {
            app.world()
                .get::<GlobalTransform>(joint)
                .unwrap()
                .translation()
        })
        .collect()
}

/// The body's path: a throw to the right that stops, then a turn, with its corners at times
/// every frame rate tested has a frame at (multiples of 1/6 s), sampled at each frame's end.
#[expect(
    clippy::cast_possible_truncation,
    reason = "a path in f64 time, placed in f32 like any Transform"
)]
fn body_at(t: f64) -> (Vec3, Quat) {
    let x = 2400.0 * t.min(1.0 / 6.0);
    let angle = (t.clamp(0.5, 5.0 / 6.0) - 0.5) * 1.5;
    (
        Vec3::new(x as f32, 0.0, 0.0),
        Quat::from_rotation_z(angle as f32),
    )
}

/// The pose after 1 s of the same body motion agrees across 30, 60, 144, 240 and 360 fps within
/// 1e-4 rad at every joint, 2D and 3D, with gravity.
#[test]
fn the_pose_is_the_same_at_any_frame_rate() {
    for planar in [true, false] {
        let pose = |fps: u32| {
            let mut app = app(fps);
            let mut chain =
                SpringChain::new(Spring::wobbly()).with_gravity(Vec3::new(0.0, -300.0, 0.0));
            if planar {
                chain = chain.planar();
            }
            let (body, joints) = spawn_chain(&mut app, chain, 4, 30.0);
            app.update();
            for frame in 1..=fps {
                let (at, turn) = body_at(f64::from(frame) / f64::from(fps));
                let mut transform = app.world_mut().get_mut::<Transform>(body).unwrap();
                transform.translation = at;
                transform.rotation = turn;
                app.update();
            }
            rotations(&app, &joints)
        };
        let reference = pose(240);
        let swing = angle(reference[0], Quat::IDENTITY);
        assert!(swing > 0.05, "the chain swings: {swing}");
        for fps in [30, 60, 144, 360] {
            for (joint, (a, b)) in pose(fps).iter().zip(&reference).enumerate() {
                let difference = angle(*a, *b);
                assert!(
                    difference < 1e-4,
                    "planar {planar}, {fps} fps, joint {joint}: {difference} rad"
                );
            }
        }
    }
}

/// Every bone keeps its length to 1e-6 relative through a violent 3D motion.
#[test]
fn bone_lengths_are_kept() {
    let mut app = app(60);
    let chain = SpringChain::new(Spring::bouncy()).with_gravity(Vec3::new(0.0, -9.81, 0.0));
    let (body, joints) = spawn_chain(&mut app, chain, 6, 0.25);
    for frame in 0..600 {
        let t = frame as f32 / 60.0;
        let mut transform = app.world_mut().get_mut::<Transform>(body).unwrap();
        transform.translation = Vec3::new((7.0 * t).sin() * 3.0, (5.0 * t).cos(), (3.0 * t).sin());
        transform.rotation = Quat::from_euler(EulerRot::XYZ, t, 2.0 * t, 0.5 * t);
        app.update();
        let at = positions(&app, &joints);
        for pair in at.windows(2) {
            let length = pair[0].distance(pair[1]);
            assert!(
                (length / 0.25 - 1.0).abs() < 1e-6,
                "frame {frame}: {length}"
            );
        }
    }
}

/// A chain whose body does not move comes to rest, hanging under gravity, and is then never
/// written; moving the body wakes it.
#[test]
fn a_still_chain_rests_and_is_never_written() {
    let mut app = app(60);
    let chain = SpringChain::new(Spring::bouncy()).with_gravity(Vec3::new(0.0, -500.0, 0.0));
    let (body, joints) = spawn_chain(&mut app, chain, 5, 20.0);
    run(&mut app, 600);
    assert!(
        app.world()
            .get::<SpringChain>(joints[0])
            .unwrap()
            .is_resting()
    );
    let hanging = rotations(&app, &joints);
    assert!(angle(hanging[0], Quat::IDENTITY) > 0.1, "gravity bends it");
    let ticks: Vec<_> = joints
        .iter()
        .map(|&joint| {
            app.world()
                .entity(joint)
                .get_ref::<Transform>()
                .unwrap()
                .last_changed()
        })
        .collect();
    run(&mut app, 120);
    for (&joint, tick) in joints.iter().zip(&ticks) {
        let now = app
            .world()
            .entity(joint)
            .get_ref::<Transform>()
            .unwrap()
            .last_changed();
        assert_eq!(now, *tick, "written at rest");
    }
    app.world_mut()
        .get_mut::<Transform>(body)
        .unwrap()
        .translation
        .x += 50.0;
    app.update();
    assert!(
        !app.world()
            .get::<SpringChain>(joints[0])
            .unwrap()
            .is_resting()
    );
}

/// A teleport further than the chain's teleport distance carries the tips along: the frame
/// after, the pose is what it would have been without the jump.
#[test]
fn a_teleport_gives_no_swing() {
    let mut app = app(60);
    let chain = || SpringChain::new(Spring::wobbly()).with_teleport_distance(100.0);
    let (jumper, jumping) = spawn_chain(&mut app, chain(), 4, 20.0);
    let (stayer, staying) = spawn_chain(&mut app, chain(), 4, 20.0);
    // Both sway the same way first.
    for frame in 0..30 {
        let x = 3.0 * frame as f32;
        for body in [jumper, stayer] {
            app.world_mut()
                .get_mut::<Transform>(body)
                .unwrap()
                .translation
                .x = x;
        }
        app.update();
    }
    app.world_mut()
        .get_mut::<Transform>(jumper)
        .unwrap()
        .translation += Vec3::new(5000.0, -2000.0, 0.0);
    for _ in 0..30 {
        app.update();
        for (a, b) in rotations(&app, &jumping)
            .iter()
            .zip(rotations(&app, &staying))
        {
            assert!(angle(*a, b) < 1e-5, "swung: {}", angle(*a, b));
        }
    }
    // A reset stops the sway.
    app.world_mut()
        .get_mut::<SpringChain>(jumping[0])
        .unwrap()
        .reset();
    app.update();
    for rotation in rotations(&app, &jumping) {
        assert!(angle(rotation, Quat::IDENTITY) < 1e-6);
    }
}

/// A chain falling onto a sphere drapes over it: no joint is ever inside it by more than a
/// ten-thousandth of a bone length (rounding), and it comes to rest on it.
#[test]
fn a_collider_is_never_penetrated() {
    for fps in [30, 60, 240] {
        let mut app = app(fps);
        let ball = app
            .world_mut()
            .spawn((
                Transform::from_xyz(-50.0, -40.0, 0.0),
                ChainCollider::sphere(30.0),
            ))
            .id();
        let chain = SpringChain::new(Spring::bouncy())
            .with_gravity(Vec3::new(0.0, -900.0, 0.0))
            .with_colliders([ball]);
        let (_, joints) = spawn_chain(&mut app, chain, 6, 15.0);
        let centre = Vec3::new(-50.0, -40.0, 0.0);
        let mut touched = false;
        for _ in 0..(4 * fps) {
            app.update();
            for (joint, at) in positions(&app, &joints).iter().enumerate() {
                let depth = 30.0 - at.distance(centre);
                assert!(
                    depth < 15.0 * 1e-4,
                    "{fps} fps, joint {joint}: {depth} inside"
                );
                touched |= depth > -0.5;
            }
        }
        assert!(touched, "{fps} fps: the chain lies on the ball");
        run(&mut app, 20 * fps);
        assert!(
            app.world()
                .get::<SpringChain>(joints[0])
                .unwrap()
                .is_resting(),
            "{fps} fps"
        );
    }
}

/// A rotation written every frame by something else (an animation) is the rest pose the
/// chain adds to: still, the chain shows it exactly.
#[test]
fn the_chain_adds_to_an_animated_pose() {
    let mut app = app(60);
    let (_, joints) = spawn_chain(&mut app, SpringChain::new(Spring::snappy()), 3, 20.0);
    let animated = joints[1];
    app.add_systems(
        Update,
        move |time: Res<Time>, mut transforms: Query<&mut Transform>| {
            let t = time.elapsed_secs().min(1.0);
            transforms.get_mut(animated).unwrap().rotation = Quat::from_rotation_z(t);
        },
    );
    run(&mut app, 180);
    let shown = app.world().get::<Transform>(animated).unwrap().rotation;
    assert!(angle(shown, Quat::from_rotation_z(1.0)) < 1e-3, "{shown}");
}

/// A glTF skin (`assets/models/tail.gltf`: three bones along −x skinned to a strip, and a clip
/// that turns the middle bone 1 rad in 1 s), loaded by `bevy_gltf` and played by
/// `bevy_animation`, with a chain on its first bone: the skin's joints sway on top of the clip
/// (0.03 rad or more behind its sample half-way through the turn, bones kept to 1e-5) and
/// settle on its last pose.
#[test]
fn a_gltf_skin_played_by_bevy_animation_sways() {
    use bevy::animation::AnimationPlayer;
    use bevy::animation::graph::{AnimationGraph, AnimationGraphHandle};
    use bevy::mesh::skinning::SkinnedMesh;

    let mut app = app(60);
    let (clip, bones) = load_tail(&mut app);
    let joints = bones.map(|(entity, _)| entity);
    let skinned: Vec<Entity> = app
        .world_mut()
        .query::<&SkinnedMesh>()
        .single(app.world())
        .unwrap()
        .joints
        .clone();
    assert_eq!(skinned, joints, "the chain's joints are the skin's");
    let player = app
        .world_mut()
        .query_filtered::<Entity, With<AnimationPlayer>>()
        .single(app.world())
        .unwrap();
    let (graph, node) = AnimationGraph::from_clip(clip);
    let graph = app
        .world_mut()
        .resource_mut::<Assets<AnimationGraph>>()
        .add(graph);
    let world = app.world_mut();
    world.entity_mut(player).insert(AnimationGraphHandle(graph));
    world.get_mut::<AnimationPlayer>(player).unwrap().play(node);
    world
        .entity_mut(joints[0])
        .insert(SpringChain::new(Spring::bouncy()));
    let turned = Quat::from_rotation_z(1.0);
    let length = |app: &App| {
        let [joint, tip] = [joints[1], joints[2]].map(|joint| positions(app, &[joint])[0]);
        joint.distance(tip)
    };

    run(&mut app, 30);
    let played = app
        .world()
        .get::<AnimationPlayer>(player)
        .and_then(|player| player.animation(node))
        .unwrap()
        .seek_time();
    let sampled = Quat::IDENTITY.slerp(turned, played);
    let lag = angle(rotations(&app, &joints[1..2])[0], sampled);
    assert!(lag > 0.03, "the skin follows the clip rigidly: {lag} rad");
    assert!((length(&app) - 20.0).abs() < 20.0 * 1e-5);

    run(&mut app, 240);
    let settled = angle(rotations(&app, &joints[1..2])[0], turned);
    assert!(settled < 1e-3, "{settled} rad from the clip's last pose");
}

/// Joints despawned or added mid-swing, even the chain's own entity: no panic, what is left
/// keeps swinging and rests, and a joint added is found and swings.
#[test]
fn the_hierarchy_changes_under_a_chain() {
    let mut app = app(60);
    let chain = SpringChain::new(Spring::bouncy()).with_gravity(Vec3::new(0.0, -300.0, 0.0));
    let (body, joints) = spawn_chain(&mut app, chain, 5, 20.0);
    run(&mut app, 10);
    app.world_mut().entity_mut(joints[4]).despawn();
    run(&mut app, 10);
    let new = app
        .world_mut()
        .spawn(Transform::from_xyz(-20.0, 0.0, 0.0))
        .id();
    app.world_mut().entity_mut(joints[3]).add_child(new);
    app.world_mut()
        .get_mut::<Transform>(body)
        .unwrap()
        .translation
        .x = 100.0;
    run(&mut app, 600);
    assert!(
        app.world()
            .get::<SpringChain>(joints[0])
            .unwrap()
            .is_resting()
    );
    for rotation in rotations(&app, &joints[..4]) {
        assert!(rotation.is_finite());
    }
    // The joint given a new child has a bone again: gravity bends it off its rest rotation.
    let droop = angle(rotations(&app, &joints[3..4])[0], Quat::IDENTITY);
    assert!(droop > 1e-2, "the new joint's bone does not swing: {droop}");
    app.world_mut().entity_mut(joints[0]).despawn();
    run(&mut app, 5);
}

/// A 1 s hitch while the chain sways is the same 60 steps of its grid: the pose after it is
/// the pose of the same second at 60 fps (within 1e-4 rad), and nothing is left non-finite.
#[test]
fn a_hitch_is_the_same_second() {
    let run_with = |hitch: bool| {
        let mut app = app(60);
        // Bevy clamps a frame of virtual time to 0.25 s by default: let the hitch through.
        app.world_mut()
            .resource_mut::<Time<Virtual>>()
            .set_max_delta(std::time::Duration::from_secs(2));
        let chain = SpringChain::new(Spring::wobbly()).with_gravity(Vec3::new(0.0, -300.0, 0.0));
        let (body, joints) = spawn_chain(&mut app, chain, 4, 30.0);
        app.update();
        // A jerk sideways starts the sway.
        app.world_mut()
            .get_mut::<Transform>(body)
            .unwrap()
            .translation
            .y = 40.0;
        app.update();
        if hitch {
            app.insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(
                std::time::Duration::from_secs(1),
            ));
            app.update();
        } else {
            run(&mut app, 60);
        }
        rotations(&app, &joints)
    };
    let (hitched, smooth) = (run_with(true), run_with(false));
    for (joint, (a, b)) in hitched.iter().zip(&smooth).enumerate() {
        assert!(a.is_finite(), "joint {joint}");
        assert!(angle(*a, *b) < 1e-4, "joint {joint}: {} rad", angle(*a, *b));
    }
}
