//! Inertialization: `bevy_animation` clip switches that never pop, decay exactly, reach the new
//! clip, and survive the world changing under them.

use std::time::Duration;

use bevy::animation::graph::{AnimationGraph, AnimationGraphHandle, AnimationNodeIndex};
use bevy::animation::{
    AnimatedBy, AnimationClip, AnimationPlayer, AnimationPlugin, AnimationTargetId, animated_field,
    prelude::{AnimatableCurve, AnimatableKeyframeCurve},
};
use bevy::asset::AssetPlugin;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::inertialization::Inertialization;
use bevy_sprung::space::rotation_vector;

use crate::harness::{app, frame, load_tail, run};

/// The joints' rest translations: a chain along y.
const BASE: [Vec3; 4] = [
    Vec3::new(0.0, 0.0, 0.0),
    Vec3::new(0.0, 1.0, 0.0),
    Vec3::new(0.0, 1.0, 0.0),
    Vec3::new(0.5, 0.5, 0.0),
];

/// The clips of the tests, by the joints they animate and how.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Move {
    /// Joints 0–2 sway along x and turn about z, linearly over 0–2 s (then back).
    Sway,
    /// Joints 0–2 reach up and turn about x, linearly over 0–2 s (then back).
    Reach,
    /// Joints 0, 1 and 3 (not 2) nod, with corners every 0.25 s.
    Nod,
}

impl Move {
    const ALL: [Move; 3] = [Move::Sway, Move::Reach, Move::Nod];

    fn animates(self, joint: usize) -> bool {
        match self {
            Move::Sway | Move::Reach => joint < 3,
            Move::Nod => joint != 2,
        }
    }

    /// The keyframes of joint `joint`: (time, translation, rotation, scale), translations
    /// `magnitude` times those below.
    fn keys(self, joint: usize, magnitude: f32) -> Vec<(f32, Vec3, Quat, Vec3)> {
        self.unit_keys(joint)
            .into_iter()
            .map(|(t, translation, rotation, scale)| (t, translation * magnitude, rotation, scale))
            .collect()
    }

    /// The keyframes of joint `joint` in a skeleton of unit size.
    fn unit_keys(self, joint: usize) -> Vec<(f32, Vec3, Quat, Vec3)> {
        let depth = joint as f32 + 1.0;
        let base = BASE[joint];
        match self {
            Move::Sway => vec![
                (0.0, base, Quat::IDENTITY, Vec3::ONE),
                (
                    2.0,
                    base + Vec3::new(1.5 * depth, 0.2, 0.0),
                    Quat::from_rotation_z(0.9),
                    Vec3::splat(1.3),
                ),
                (4.0, base, Quat::IDENTITY, Vec3::ONE),
            ],
            Move::Reach => vec![
                (
                    0.0,
                    base + Vec3::new(-0.8, 0.4, 0.3) * depth,
                    Quat::from_rotation_x(-0.6),
                    Vec3::splat(0.8),
                ),
                (
                    2.0,
                    base + Vec3::new(-0.8, 2.4, -0.7) * depth,
                    Quat::from_rotation_x(0.8),
                    Vec3::splat(1.1),
                ),
                (4.0, base, Quat::IDENTITY, Vec3::ONE),
            ],
            Move::Nod => (0..=8)
                .map(|k| {
                    let t = k as f32 * 0.25;
                    let side = if k % 2 == 0 { 1.0 } else { -1.0 };
                    (
                        t,
                        base + Vec3::new(0.3 * side, -0.5, 0.2 * side * depth),
                        Quat::from_rotation_y(0.5 * side),
                        Vec3::ONE,
                    )
                })
                .collect(),
        }
    }

    fn clip(self, ids: &[AnimationTargetId], magnitude: f32) -> AnimationClip {
        let mut clip = AnimationClip::default();
        for (joint, &id) in ids.iter().enumerate() {
            if !self.animates(joint) {
                continue;
            }
            let keys = self.keys(joint, magnitude);
            let curve = |pick: fn(&(f32, Vec3, Quat, Vec3)) -> Vec3| {
                AnimatableKeyframeCurve::new(keys.iter().map(|key| (key.0, pick(key)))).unwrap()
            };
            clip.add_curve_to_target(
                id,
                AnimatableCurve::new(animated_field!(Transform::translation), curve(|k| k.1)),
            );
            clip.add_curve_to_target(
                id,
                AnimatableCurve::new(animated_field!(Transform::scale), curve(|k| k.3)),
            );
            clip.add_curve_to_target(
                id,
                AnimatableCurve::new(
                    animated_field!(Transform::rotation),
                    AnimatableKeyframeCurve::new(keys.iter().map(|key| (key.0, key.2))).unwrap(),
                ),
            );
        }
        clip
    }
}

/// A player with four joints (0 → 1 → 2 in a chain under it, 3 under 0), the three clips in
/// one graph, and an `Inertialization` unless `inertialized` is false.
struct Rig {
    app: App,
    /// The size of the skeleton: its translations are this many times `BASE` and the clips'.
    magnitude: f32,
    player: Entity,
    joints: Vec<Entity>,
    ids: Vec<AnimationTargetId>,
    clips: Vec<Handle<AnimationClip>>,
    nodes: Vec<AnimationNodeIndex>,
}

impl Rig {
    fn new(fps: u32, inertialized: bool) -> Self {
        Self::sized(fps, inertialized, 1.0)
    }

    /// A rig whose translations are `magnitude` times the unit skeleton's (a skeleton in
    /// centimetres, a root joint far from its player).
    fn sized(fps: u32, inertialized: bool, magnitude: f32) -> Self {
        let mut app = app(fps);
        app.add_plugins((AssetPlugin::default(), AnimationPlugin));
        let ids: Vec<AnimationTargetId> = (0..4)
            .map(|joint| AnimationTargetId::from_name(&Name::new(format!("joint{joint}"))))
            .collect();
        let clips: Vec<Handle<AnimationClip>> = Move::ALL
            .iter()
            .map(|clip| {
                let clip = clip.clip(&ids, magnitude);
                app.world_mut()
                    .resource_mut::<Assets<AnimationClip>>()
                    .add(clip)
            })
            .collect();
        let (graph, nodes) = AnimationGraph::from_clips(clips.iter().cloned());
        let graph = app
            .world_mut()
            .resource_mut::<Assets<AnimationGraph>>()
            .add(graph);
        let world = app.world_mut();
        let player = world
            .spawn((AnimationPlayer::default(), AnimationGraphHandle(graph)))
            .id();
        if inertialized {
            world.entity_mut(player).insert(Inertialization::default());
        }
        let mut joints: Vec<Entity> = Vec::new();
        for (joint, &id) in ids.iter().enumerate() {
            let parent = match joint {
                0 => player,
                3 => joints[0],
                _ => joints[joint - 1],
            };
            let entity = world
                .spawn((
                    Transform::from_translation(BASE[joint] * magnitude),
                    id,
                    AnimatedBy(player),
                    ChildOf(parent),
                ))
                .id();
            joints.push(entity);
        }
        Self {
            app,
            magnitude,
            player,
            joints,
            ids,
            clips,
            nodes,
        }
    }

    fn node(&self, clip: Move) -> AnimationNodeIndex {
        self.nodes[Move::ALL.iter().position(|&m| m == clip).unwrap()]
    }

    /// Switches to `clip` (repeating) with `blend` (through the player alone without an
    /// `Inertialization`).
    fn play(&mut self, clip: Move, blend: Duration) {
        let node = self.node(clip);
        let world = self.app.world_mut();
        let mut inertialized = world.query::<(&mut AnimationPlayer, &mut Inertialization)>();
        if let Ok((mut player, mut inertialization)) = inertialized.get_mut(world, self.player) {
            inertialization.play(&mut player, node, blend).repeat();
        } else {
            let mut player = world.get_mut::<AnimationPlayer>(self.player).unwrap();
            player.stop_all();
            player.start(node).repeat();
        }
    }

    fn poses(&self) -> Vec<Transform> {
        self.joints
            .iter()
            .map(|&joint| {
                self.app
                    .world()
                    .get::<Transform>(joint)
                    .copied()
                    .unwrap_or_default()
            })
            .collect()
    }

    /// The seek time of `clip` on the player.
    fn seek(&self, clip: Move) -> f32 {
        self.app
            .world()
            .get::<AnimationPlayer>(self.player)
            .and_then(|player| player.animation(self.node(clip)))
            .map(bevy::animation::ActiveAnimation::seek_time)
            .unwrap()
    }

    /// The pose `clip` gives `joint` at `time` (its rest pose where the clip does not animate it).
    fn sample(&self, clip: Move, joint: usize, time: f32) -> Transform {
        let clips = self.app.world().resource::<Assets<AnimationClip>>();
        let clip_asset = clips
            .get(&self.clips[Move::ALL.iter().position(|&m| m == clip).unwrap()])
            .unwrap();
        let id = self.ids[joint];
        Transform {
            translation: clip_asset
                .sample_clamped(animated_field!(Transform::translation), id, time)
                .unwrap_or(BASE[joint] * self.magnitude),
            rotation: clip_asset
                .sample_clamped(animated_field!(Transform::rotation), id, time)
                .unwrap_or(Quat::IDENTITY),
            scale: clip_asset
                .sample_clamped(animated_field!(Transform::scale), id, time)
                .unwrap_or(Vec3::ONE),
        }
    }

    fn set_frame(&mut self, dt: f64) {
        self.app
            .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
                dt,
            )));
    }
}

/// The natural frequency of the blend spring of `blend`.
fn blend_omega(blend: Duration) -> f32 {
    Inertialization::blend_spring(blend)
        .unwrap()
        .natural_frequency()
}

/// The angle between two rotations (`Quat::angle_between` goes through `acos`, whose `f32`
/// rounding alone is ~7e-4 rad near zero).
fn angle(a: Quat, b: Quat) -> f32 {
    rotation_vector(a * b.inverse()).length()
}

/// How far a joint moved between two poses: translation distance, angle, scale distance.
fn motion(a: &Transform, b: &Transform) -> Vec3 {
    Vec3::new(
        a.translation.distance(b.translation),
        angle(a.rotation, b.rotation),
        a.scale.distance(b.scale),
    )
}

/// A small deterministic generator of times.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// The most a joint may move in the frame of a switch without a pop (per unit: translation,
/// radians, scale): what it moved the frame before, what the clips move in a frame (the new
/// clip's rate, unknown on that frame, adds `ω·dt` of it), and half the decay's largest
/// acceleration, `ω²·|offset| + 2ω·|offset velocity|`, times `dt²`: second order in `dt`,
/// where a pop is the whole offset.
fn switch_bound(moved_before: Vec3, clip_motion: Vec3, offset: Vec3, omega: f32, dt: f32) -> Vec3 {
    let offset_velocity_dt = moved_before + clip_motion;
    moved_before
        + clip_motion * (1.0 + omega * dt)
        + offset * (omega * omega * dt * dt / 2.0)
        + offset_velocity_dt * (omega * dt)
        + Vec3::splat(1e-4)
}

/// Plays a scripted run: `Sway` from the start, then each `(time, clip)` switch (instant if
/// `instant`, else blended over `blend`), at `fps`, for 2.5 s. At every switch it checks that no
/// joint moves further in that frame than it did the frame before, plus what the clips move in
/// a frame, plus what the blend's own acceleration adds over one frame (`½·a·dt²`, with `a` at
/// most `ω²·|offset| + 2ω·|offset velocity|`: the decay's largest acceleration, and second
/// order in `dt`, where a pop is the whole offset). Returns the largest excess over that bound
/// (negative: within it) and the poses of every frame.
fn switch_run(
    fps: u32,
    switches: &[(f32, Move)],
    blend: Duration,
    instant: bool,
) -> (f32, Vec<Vec<Transform>>) {
    let mut rig = Rig::new(fps, true);
    rig.play(Move::Sway, Duration::ZERO);
    run(&mut rig.app, 2);
    let dt = frame(fps).as_secs_f32();
    let omega = blend_omega(blend);
    let mut frames = vec![rig.poses()];
    let mut playing = Move::Sway;
    let mut pending = switches.iter().copied().peekable();
    let mut excess = f32::NEG_INFINITY;
    let mut time = 0.0;
    while time < 2.5 {
        let before = frames.last().unwrap().clone();
        let earlier = frames[frames.len().saturating_sub(2)].clone();
        let old_seek = rig.seek(playing);
        let mut switched = None;
        while let Some(&(at, clip)) = pending.peek()
            && at <= time
        {
            pending.next();
            rig.play(clip, if instant { Duration::ZERO } else { blend });
            switched = Some(clip);
        }
        rig.app.update();
        time += dt;
        let now = rig.poses();
        if let Some(next) = switched {
            for joint in 0..4 {
                let old_motion = motion(
                    &rig.sample(playing, joint, old_seek),
                    &rig.sample(playing, joint, old_seek + dt),
                );
                let new_start = rig.sample(next, joint, 0.0);
                let new_motion = motion(&new_start, &rig.sample(next, joint, rig.seek(next)));
                let clip_motion = old_motion.max(new_motion);
                let moved = motion(&before[joint], &now[joint]);
                let moved_before = motion(&earlier[joint], &before[joint]);
                let offset = motion(&before[joint], &new_start);
                let bound = switch_bound(moved_before, clip_motion, offset, omega, dt);
                excess = excess.max((moved - bound).max_element());
            }
            playing = next;
        }
        frames.push(now);
    }
    (excess, frames)
}

/// At random times, and interrupted mid-transition (0.02–0.3 s later), a switch moves no joint
/// further in its frame than the joint moved the frame before, plus what the clips move in a
/// frame and the blend's own second-order term. The same switches without a blend jump by far
/// more than that bound.
#[test]
fn a_switch_never_pops_at_random_times_or_interrupted() {
    let mut random = Lcg(7);
    for case in 0..12 {
        let first = 0.2 + 1.2 * random.next();
        let second = first + 0.02 + 0.28 * random.next();
        let clips = [Move::Reach, Move::Nod, Move::Sway];
        let next = clips[case % 2];
        let then = clips[(case / 2) % 3];
        let switches = [(first, next), (second, then)];
        let fps = [60, 144, 30, 240][case % 4];
        let blend = Duration::from_millis(200 + 100 * (case as u64 % 3));
        let (excess, frames) = switch_run(fps, &switches, blend, false);
        assert!(
            excess <= 0.0,
            "case {case} at {fps} fps, {switches:?}: a joint jumped {excess} past the bound"
        );
        assert!(
            frames.iter().flatten().all(Transform::is_finite),
            "case {case}: a non-finite pose"
        );
        if case < 4 {
            let (instant, _) = switch_run(fps, &switches, blend, true);
            assert!(
                instant > 0.05,
                "case {case}: an instant switch must break the bound ({instant})"
            );
        }
    }
}

/// The offset shown after a switch is the closed-form critically damped decay from the pose
/// shown at the switch (less the new clip's there), moving at the rate it showed (less the
/// clip's): checked every frame against the formula, in translation and rotation. The pose
/// reaches the new clip to 1e-4 (of the offset and of the position) and 1e-4 rad by the time
/// the formula's envelope says, and then shows it exactly.
#[test]
fn the_offset_decays_exactly_and_reaches_the_new_clip() {
    decays_exactly_and_reaches_the_clip(1.0);
}

/// The same in a skeleton ten thousand times larger (a skeleton in centimetres far from its
/// player, a big world's root joint): in `f32` the offset is taken between poses of about 1e4,
/// and it still decays exactly, to 1e-4 of itself, and ends on the clip bit for bit.
#[test]
fn a_large_skeleton_decays_exactly_and_reaches_the_new_clip() {
    decays_exactly_and_reaches_the_clip(1e4);
}

/// The checks of the two tests above, with translations `magnitude` times the unit rig's.
fn decays_exactly_and_reaches_the_clip(magnitude: f32) {
    let fps = 60;
    let dt = frame(fps).as_secs_f32();
    let blend = Duration::from_millis(400);
    let omega = blend_omega(blend);
    let decay =
        |x0: Vec3, v0: Vec3, tau: f32| (x0 + (v0 + x0 * omega) * tau) * (-omega * tau).exp();
    let envelope = |x0: Vec3, v0: Vec3, tau: f32| {
        (x0.length() + (v0 + x0 * omega).length() * tau) * (-omega * tau).exp()
    };
    let mut rig = Rig::sized(fps, true, magnitude);
    rig.play(Move::Sway, Duration::ZERO);
    run(&mut rig.app, 31);
    let earlier = rig.poses();
    run(&mut rig.app, 1);
    let before = rig.poses();
    rig.play(Move::Reach, blend);
    // The offset at the switch: translation and rotation, and their rates.
    let start: Vec<_> = (0..4)
        .map(|joint| {
            let (clip0, clip1) = (
                rig.sample(Move::Reach, joint, 0.0),
                rig.sample(Move::Reach, joint, dt),
            );
            let (shown0, shown_before) = (before[joint], earlier[joint]);
            let translation = (
                shown0.translation - clip0.translation,
                (shown0.translation - shown_before.translation) / dt
                    - (clip1.translation - clip0.translation) / dt,
            );
            let rotation = (
                rotation_vector(shown0.rotation * clip0.rotation.inverse()),
                rotation_vector(shown0.rotation * shown_before.rotation.inverse()) / dt
                    - rotation_vector(clip1.rotation * clip0.rotation.inverse()) / dt,
            );
            (translation, rotation)
        })
        .collect();
    let mut reached = [false; 4];
    for k in 1..=90 {
        rig.app.update();
        let tau = k as f32 * dt;
        let seek = rig.seek(Move::Reach);
        let poses = rig.poses();
        for joint in 0..4 {
            let clip = rig.sample(Move::Reach, joint, seek);
            let ((x0, v0), (r0, w0)) = start[joint];
            let size = x0.length() + v0.length() / omega;
            let offset = poses[joint].translation - clip.translation;
            let turned = rotation_vector(poses[joint].rotation * clip.rotation.inverse());
            // The frame of the switch lacks the new clip's rate (a term of order ω·dt² times it).
            let slack = if k == 1 { omega * dt * dt * 4.0 } else { 0.0 };
            assert!(
                offset.distance(decay(x0, v0, tau)) < 1e-4 * size + (slack + 1e-5) * magnitude,
                "joint {joint}, {tau} s after: offset {offset} vs {}",
                decay(x0, v0, tau)
            );
            assert!(
                turned.distance(decay(r0, w0, tau)) < 1e-4 + slack,
                "joint {joint}, {tau} s after: rotation offset {turned} vs {}",
                decay(r0, w0, tau)
            );
            if envelope(x0, v0, tau) <= 1e-4 * size && envelope(r0, w0, tau) < 1e-4 {
                assert!(
                    offset.length() <= 1e-4 * size + 1e-5 * clip.translation.length(),
                    "joint {joint}: {offset} at {tau} s"
                );
                assert!(angle(poses[joint].rotation, clip.rotation) < 1e-4);
                reached[joint] = true;
            }
        }
    }
    assert_eq!(
        reached, [true; 4],
        "the envelope fell below 1e-4 within 1.5 s (3.75 blend times)"
    );
    // Settled: the clip's pose, exactly.
    run(&mut rig.app, 60);
    let seek = rig.seek(Move::Reach);
    for (joint, pose) in rig.poses().iter().enumerate() {
        assert_eq!(*pose, rig.sample(Move::Reach, joint, seek), "joint {joint}");
    }
}

/// A second after a switch at 0.5 s, mid-blend, the pose is the same at 30, 60, 120, 144, 240
/// and 360 fps and with hitches after the switch, within 1e-4.
#[test]
fn the_pose_is_the_same_at_every_frame_rate() {
    let blend = Duration::from_millis(800);
    let pose_at_one_second = |pattern_after: &[f64], fps: u32| {
        let mut rig = Rig::new(fps, true);
        rig.play(Move::Sway, Duration::ZERO);
        // The first update has no time.
        rig.app.update();
        let dt = frame(fps).as_secs_f64();
        // Half a second (every rate here is even).
        for _ in 0..fps / 2 {
            rig.app.update();
        }
        rig.play(Move::Reach, blend);
        let mut elapsed = 0.0;
        for &step in pattern_after.iter().cycle() {
            if elapsed >= 0.5 - 1e-6 {
                break;
            }
            let step = if pattern_after.is_empty() { dt } else { step };
            rig.set_frame(step);
            rig.app.update();
            elapsed += step;
        }
        rig.poses()
    };
    let reference = pose_at_one_second(&[1.0 / 60.0], 60);
    let mut cases: Vec<(String, Vec<Transform>)> = [30, 120, 144, 240, 360]
        .iter()
        .map(|&fps| {
            let dt = frame(fps).as_secs_f64();
            (format!("{fps} fps"), pose_at_one_second(&[dt], fps))
        })
        .collect();
    cases.push((
        "hitches".into(),
        pose_at_one_second(&[0.1, 0.05, 1.0 / 60.0, 0.25 - 1.0 / 60.0, 0.1], 60),
    ));
    for (case, poses) in cases {
        for joint in 0..4 {
            let (a, b) = (poses[joint], reference[joint]);
            assert!(
                a.translation.distance(b.translation) < 1e-4
                    && angle(a.rotation, b.rotation) < 1e-4
                    && a.scale.distance(b.scale) < 1e-4,
                "{case}, joint {joint}: {a:?} vs {b:?}"
            );
        }
        // Mid-blend: the new clip is not reached yet, so the comparison says something.
        let seek = 0.5;
        let rig = Rig::new(60, false);
        let clip = rig.sample(Move::Reach, 2, seek);
        assert!(reference[2].translation.distance(clip.translation) > 1e-2);
    }
}

/// A frame of a whole second (a load, a breakpoint; Bevy clamps the game clock's frames to
/// 0.25 s unless told otherwise, so the clamp is raised here), on the frame of the switch or
/// mid-blend, lands on the pose the frames at 60 fps reach, within 1e-4, and nothing is
/// non-finite.
#[test]
fn a_one_second_hitch_lands_where_the_frames_would() {
    // A long blend, so that 1.2 s after the switch a tenth of the offset is left to compare.
    let blend = Duration::from_secs(2);
    let pose_after = |steps: &[f64]| {
        let mut rig = Rig::new(60, true);
        rig.app
            .world_mut()
            .resource_mut::<Time<Virtual>>()
            .set_max_delta(Duration::from_secs(2));
        rig.play(Move::Sway, Duration::ZERO);
        run(&mut rig.app, 31);
        rig.play(Move::Reach, blend);
        for &step in steps {
            rig.set_frame(step);
            rig.app.update();
        }
        rig.poses()
    };
    let reference = pose_after(&[1.0 / 60.0; 72]);
    let rig = Rig::new(60, false);
    let clip = rig.sample(Move::Reach, 2, 1.2);
    assert!(
        reference[2].translation.distance(clip.translation) > 1e-2,
        "still blending 1.2 s after the switch"
    );
    for (case, steps) in [
        ("a 1 s switch frame", vec![1.0, 0.2]),
        ("a 1 s frame mid-blend", vec![0.1, 1.0, 0.1]),
    ] {
        let poses = pose_after(&steps);
        for joint in 0..4 {
            let (a, b) = (poses[joint], reference[joint]);
            assert!(a.is_finite(), "{case}, joint {joint}: {a:?}");
            assert!(
                a.translation.distance(b.translation) < 1e-4
                    && angle(a.rotation, b.rotation) < 1e-4
                    && a.scale.distance(b.scale) < 1e-4,
                "{case}, joint {joint}: {a:?} vs {b:?}"
            );
        }
    }
}

/// A joint the new clip does not animate comes smoothly to rest where the old clip last put it;
/// a joint only the new clip animates moves smoothly from where it stood to the clip.
#[test]
fn joints_animated_by_one_clip_only_move_smoothly() {
    let fps = 60;
    let dt = frame(fps).as_secs_f32();
    let blend = Duration::from_millis(300);
    let switch_at = 0.6;
    let (excess, frames) = switch_run(fps, &[(switch_at, Move::Nod)], blend, false);
    assert!(excess <= 0.0, "{excess}");
    let rig = Rig::new(fps, false);
    // Joint 2 is Sway's only: it stops where Sway last put it, without overshooting by more
    // than its momentum carries it.
    let switch_frame = frames
        .iter()
        .enumerate()
        .position(|(k, _)| k as f32 * dt > switch_at)
        .unwrap();
    let before = frames[switch_frame - 1][2];
    let speed = frames[switch_frame - 1][2]
        .translation
        .distance(frames[switch_frame - 2][2].translation)
        / dt;
    let last = frames.last().unwrap()[2];
    let omega = blend_omega(blend);
    assert!(
        last.translation.distance(before.translation) < speed * (dt + 1.0 / omega) + 1e-4,
        "{} from {}",
        last.translation,
        before.translation
    );
    assert_eq!(
        frames[frames.len() - 2][2],
        last,
        "joint 2 has come to rest"
    );
    // Joint 3 stood at its rest pose under Sway, and ends on Nod's pose.
    assert_eq!(frames[switch_frame - 1][3].translation, BASE[3]);
    let nod_end = frames.last().unwrap()[3];
    let nod_seek = (2.5 - switch_at - dt) % 2.0;
    let close = (0..5).any(|k| {
        let pose = rig.sample(Move::Nod, 3, nod_seek + (k as f32 - 2.0) * dt);
        pose.translation.distance(nod_end.translation) < 1e-3
    });
    assert!(close, "joint 3 reached Nod's pose: {nod_end:?}");
}

/// Joints despawned, added, moved to another player, and the player's `Inertialization`
/// removed, mid-blend: no panic, no non-finite pose, and the joints left follow their clips.
#[test]
fn the_world_changing_mid_blend_breaks_nothing() {
    let blend = Duration::from_millis(500);
    let mut rig = Rig::new(60, true);
    rig.play(Move::Sway, Duration::ZERO);
    run(&mut rig.app, 40);
    rig.play(Move::Reach, blend);
    run(&mut rig.app, 3);
    // Joint 3 (a leaf) despawned mid-blend; a new joint with joint 3's target added.
    rig.app.world_mut().entity_mut(rig.joints[3]).despawn();
    let added = rig
        .app
        .world_mut()
        .spawn((
            Transform::from_translation(BASE[3]),
            rig.ids[3],
            AnimatedBy(rig.player),
            ChildOf(rig.joints[0]),
        ))
        .id();
    rig.joints[3] = added;
    run(&mut rig.app, 3);
    // A switch back, interrupting.
    rig.play(Move::Nod, blend);
    run(&mut rig.app, 2);
    // Joint 1 moved to a second player that is not inertialized: it shows that player's clip.
    let graph = rig
        .app
        .world()
        .get::<AnimationGraphHandle>(rig.player)
        .unwrap()
        .0
        .clone();
    let mut other = AnimationPlayer::default();
    other.start(rig.node(Move::Sway)).repeat();
    let other = rig
        .app
        .world_mut()
        .spawn((other, AnimationGraphHandle(graph)))
        .id();
    rig.app
        .world_mut()
        .entity_mut(rig.joints[1])
        .insert(AnimatedBy(other));
    run(&mut rig.app, 2);
    let seek = rig
        .app
        .world()
        .get::<AnimationPlayer>(other)
        .unwrap()
        .animation(rig.node(Move::Sway))
        .unwrap()
        .seek_time();
    assert_eq!(rig.poses()[1], rig.sample(Move::Sway, 1, seek));
    for pose in rig.poses() {
        assert!(pose.is_finite(), "{pose:?}");
    }
    // The Inertialization removed mid-blend: the clip is shown at once.
    rig.play(Move::Reach, blend);
    run(&mut rig.app, 2);
    rig.app
        .world_mut()
        .entity_mut(rig.player)
        .remove::<Inertialization>();
    run(&mut rig.app, 1);
    let seek = rig.seek(Move::Reach);
    assert_eq!(rig.poses()[0], rig.sample(Move::Reach, 0, seek));
    // Put back: a switch blends again.
    rig.app
        .world_mut()
        .entity_mut(rig.player)
        .insert(Inertialization::default());
    rig.play(Move::Sway, blend);
    run(&mut rig.app, 2);
    let seek = rig.seek(Move::Sway);
    assert!(
        rig.poses()[0]
            .translation
            .distance(rig.sample(Move::Sway, 0, seek).translation)
            > 1e-2,
        "blending again"
    );
    // The player despawned with its joints mid-blend.
    rig.app.world_mut().entity_mut(rig.player).despawn();
    run(&mut rig.app, 3);
}

/// With an `Inertialization` that never switches, the graph's own blending is untouched: two
/// clips played at once with weights give the same poses, bit for bit, as without it; and once
/// a blend has settled they are the same again.
#[test]
fn the_graphs_own_blending_is_left_working() {
    let weighted = |inertialized: bool, switch: bool| {
        let mut rig = Rig::new(60, inertialized);
        let (sway, reach) = (rig.node(Move::Sway), rig.node(Move::Reach));
        let mut player = rig
            .app
            .world_mut()
            .get_mut::<AnimationPlayer>(rig.player)
            .unwrap();
        player.start(sway).repeat().set_weight(0.3);
        player.start(reach).repeat().set_weight(0.7);
        run(&mut rig.app, 30);
        if switch {
            // A weight set at once, blended away.
            rig.app
                .world_mut()
                .get_mut::<AnimationPlayer>(rig.player)
                .unwrap()
                .animation_mut(sway)
                .unwrap()
                .set_weight(0.9);
            rig.app
                .world_mut()
                .get_mut::<Inertialization>(rig.player)
                .unwrap()
                .inertialize(Duration::from_millis(200));
        } else {
            rig.app
                .world_mut()
                .get_mut::<AnimationPlayer>(rig.player)
                .unwrap()
                .animation_mut(sway)
                .unwrap()
                .set_weight(0.9);
        }
        let mut frames = Vec::new();
        for _ in 0..60 {
            rig.app.update();
            frames.push(rig.poses());
        }
        frames
    };
    let plain = weighted(false, false);
    assert_eq!(weighted(true, false), plain);
    let blended = weighted(true, true);
    assert_ne!(blended[0], plain[0], "the weight change is blended");
    assert_eq!(blended.last(), plain.last(), "and then shown exactly");
}

/// Paused mid-blend (virtual time stopped), nothing moves; resumed, the blend goes on. A switch
/// on the app's first update (no time yet) blends from the pose standing.
#[test]
fn a_pause_holds_the_blend_and_a_first_frame_switch_works() {
    let mut rig = Rig::new(60, true);
    rig.play(Move::Sway, Duration::ZERO);
    rig.play(Move::Reach, Duration::from_millis(300));
    rig.app.update();
    let first = rig.poses();
    for (joint, pose) in first.iter().enumerate() {
        assert_eq!(pose.translation, BASE[joint], "joint {joint} stood still");
    }
    run(&mut rig.app, 5);
    rig.app.world_mut().resource_mut::<Time<Virtual>>().pause();
    let paused = rig.poses();
    run(&mut rig.app, 10);
    assert_eq!(rig.poses(), paused);
    rig.app
        .world_mut()
        .resource_mut::<Time<Virtual>>()
        .unpause();
    run(&mut rig.app, 60);
    let seek = rig.seek(Move::Reach);
    for (joint, pose) in rig.poses().iter().enumerate() {
        let clip = rig.sample(Move::Reach, joint, seek);
        assert!(
            pose.translation.distance(clip.translation) < 1e-3,
            "joint {joint}"
        );
    }
}

/// A real glTF skin (the chain tests' tail: four bones and its "Turn" clip) switched mid-turn
/// to a clip built over its joints' own target ids, and back, interrupting: no joint jumps past
/// the bound at either switch, and the skin ends on the clip's pose.
#[test]
fn a_gltf_skin_switches_without_a_pop() {
    let fps = 60;
    let dt = frame(fps).as_secs_f32();
    let blend = Duration::from_millis(300);
    let mut app = app(fps);
    let (turn, joints) = load_tail(&mut app);
    let (bend, rests) = bend_clip(&mut app, &joints);
    let (graph, nodes) = AnimationGraph::from_clips([turn, bend.clone()]);
    let graph = app
        .world_mut()
        .resource_mut::<Assets<AnimationGraph>>()
        .add(graph);
    let player = app
        .world_mut()
        .query_filtered::<Entity, With<AnimationPlayer>>()
        .single(app.world())
        .unwrap();
    app.world_mut()
        .entity_mut(player)
        .insert((AnimationGraphHandle(graph), Inertialization::default()));
    let play = |app: &mut App, node: AnimationNodeIndex| {
        let world = app.world_mut();
        let mut query = world.query::<(&mut AnimationPlayer, &mut Inertialization)>();
        let (mut animation, mut inertialization) = query.get_mut(world, player).unwrap();
        inertialization.play(&mut animation, node, blend).repeat();
    };
    let rotations = |app: &App| -> Vec<Quat> {
        joints
            .iter()
            .map(|&(joint, _)| app.world().get::<Transform>(joint).unwrap().rotation)
            .collect()
    };
    play(&mut app, nodes[0]);
    app.update();
    // Turn's pose a frame in (its start, within a frame's turn).
    let turn_start = rotations(&app);
    run(&mut app, 19);
    let omega = blend_omega(blend);
    let mut earlier = rotations(&app);
    app.update();
    let mut before = rotations(&app);
    let mut worst = f32::NEG_INFINITY;
    for (switch, node, starts) in [(0, nodes[1], &rests), (9, nodes[0], &turn_start)] {
        for _ in 0..switch {
            earlier = before;
            app.update();
            before = rotations(&app);
        }
        play(&mut app, node);
        app.update();
        let now = rotations(&app);
        for k in 0..joints.len() {
            let moved = angle(before[k], now[k]);
            let moved_before = angle(earlier[k], before[k]);
            // The Turn clip turns 1 rad a second, Bend at most 0.6 rad a second.
            let clip_motion = 1.0 * dt;
            let offset = angle(before[k], starts[k]) + clip_motion;
            let bound = switch_bound(
                Vec3::splat(moved_before),
                Vec3::splat(clip_motion),
                Vec3::splat(offset),
                omega,
                dt,
            )
            .x;
            worst = worst.max(moved - bound);
        }
        earlier = before;
        before = now;
    }
    assert!(worst <= 0.0, "a joint jumped {worst} rad past the bound");
    // Back on Turn, settled: its pose, as the same skin without inertialization would show.
    run(&mut app, 120);
    let seek = app
        .world()
        .get::<AnimationPlayer>(player)
        .unwrap()
        .animation(nodes[0])
        .unwrap()
        .seek_time();
    let turned = Quat::IDENTITY.slerp(Quat::from_rotation_z(1.0), seek.min(1.0));
    assert!(
        angle(rotations(&app)[1], turned) < 1e-4,
        "{:?} vs {turned:?} at {seek}",
        rotations(&app)[1]
    );
}

/// "Bend": each of `joints` bends about x from its present pose and back over a second,
/// linearly; and the joints' present rotations (the clip's start).
fn bend_clip(
    app: &mut App,
    joints: &[(Entity, AnimationTargetId)],
) -> (Handle<AnimationClip>, Vec<Quat>) {
    let mut bend = AnimationClip::default();
    let mut rests = Vec::new();
    for (k, &(joint, id)) in joints.iter().enumerate() {
        let rest = *app.world().get::<Transform>(joint).unwrap();
        rests.push(rest.rotation);
        let bent = rest.rotation * Quat::from_rotation_x(0.3 + 0.1 * k as f32);
        bend.add_curve_to_target(
            id,
            AnimatableCurve::new(
                animated_field!(Transform::rotation),
                AnimatableKeyframeCurve::new([
                    (0.0, rest.rotation),
                    (0.5, bent),
                    (1.0, rest.rotation),
                ])
                .unwrap(),
            ),
        );
    }
    let bend = app
        .world_mut()
        .resource_mut::<Assets<AnimationClip>>()
        .add(bend);
    (bend, rests)
}
