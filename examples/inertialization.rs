//! Clip transitions by inertialization, side by side with Bevy's cross-fade.
//!
//! Two figures play the same clips (idle, walk, wave) and get the same commands: the left one
//! switches with Bevy's `AnimationTransitions` (both clips evaluated and blended over the
//! fade), the right one with [`Inertialization`] (the new clip at once, the difference from
//! the pose shown decaying on an exact critically damped spring). The lines trail each
//! figure's hands: switch quickly, interrupting a transition, and compare.
//!
//! Keys 1, 2, 3: idle, walk, wave. Without a keyboard the example plays a scripted tour of
//! switches, some interrupting others, so CI screenshots show it.
//!
//! ```text
//! cargo run --example inertialization
//! ```

use std::collections::VecDeque;
use std::f32::consts::TAU;
use std::time::Duration;

use bevy::animation::graph::{AnimationGraph, AnimationGraphHandle, AnimationNodeIndex};
use bevy::animation::transition::AnimationTransitions;
use bevy::animation::{
    AnimatedBy, AnimationClip, AnimationPlayer, AnimationTargetId, animated_field,
    prelude::{AnimatableCurve, AnimatableKeyframeCurve},
};
use bevy::core_pipeline::tonemapping::Tonemapping;
use bevy::prelude::*;
use bevy_sprung::inertialization::Inertialization;
use bevy_sprung::prelude::*;

#[path = "support/tour.rs"]
mod tour;

use tour::{Tour, TourPlugin};

/// How long a transition takes, on both figures.
const BLEND: Duration = Duration::from_millis(350);

/// The figure's joints: name, parent, offset from the parent, and the length and direction of
/// the bone drawn from it.
const JOINTS: [(&str, Option<usize>, Vec3, f32); 13] = [
    ("hips", None, Vec3::new(0.0, 1.0, 0.0), 0.2),
    ("spine", Some(0), Vec3::new(0.0, 0.2, 0.0), 0.25),
    ("chest", Some(1), Vec3::new(0.0, 0.25, 0.0), 0.25),
    ("head", Some(2), Vec3::new(0.0, 0.3, 0.0), 0.0),
    ("arm.l", Some(2), Vec3::new(0.2, 0.2, 0.0), -0.3),
    ("forearm.l", Some(4), Vec3::new(0.0, -0.3, 0.0), -0.28),
    ("arm.r", Some(2), Vec3::new(-0.2, 0.2, 0.0), -0.3),
    ("forearm.r", Some(6), Vec3::new(0.0, -0.3, 0.0), -0.28),
    ("thigh.l", Some(0), Vec3::new(0.1, -0.05, 0.0), -0.45),
    ("shin.l", Some(8), Vec3::new(0.0, -0.45, 0.0), -0.45),
    ("thigh.r", Some(0), Vec3::new(-0.1, -0.05, 0.0), -0.45),
    ("shin.r", Some(10), Vec3::new(0.0, -0.45, 0.0), -0.45),
    ("hand", Some(7), Vec3::new(0.0, -0.28, 0.0), 0.0),
];

/// The clips: each gives a joint's rotation (and the hips' height) at a time of its loop.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Move {
    Idle,
    Walk,
    Wave,
}

impl Move {
    const ALL: [Move; 3] = [Move::Idle, Move::Walk, Move::Wave];

    /// The loop's length in keys, at 30 keys a second.
    fn keys(self) -> u16 {
        match self {
            Move::Idle => 60,
            Move::Walk => 30,
            Move::Wave => 36,
        }
    }

    fn duration(self) -> f32 {
        f32::from(self.keys()) / 30.0
    }

    fn rotation(self, joint: &str, t: f32) -> Quat {
        let phase = TAU * t / self.duration();
        let (s, c) = phase.sin_cos();
        let (x, z) = match (self, joint) {
            (Move::Idle, "chest") => (0.03 * s, 0.0),
            (Move::Idle, "arm.l") => (0.05 * c, 0.12),
            (Move::Idle, "arm.r") => (-0.05 * c, -0.12),
            (Move::Idle, "forearm.l" | "forearm.r") => (-0.15, 0.0),
            (Move::Walk, "thigh.l") => (0.5 * s, 0.0),
            (Move::Walk, "thigh.r") => (-0.5 * s, 0.0),
            // A shin bends while its thigh swings back.
            (Move::Walk, "shin.l") => (-0.7 * (-s).max(0.0) - 0.1, 0.0),
            (Move::Walk, "shin.r") => (-0.7 * s.max(0.0) - 0.1, 0.0),
            (Move::Walk, "arm.l") => (-0.45 * s, 0.08),
            (Move::Walk, "arm.r") => (0.45 * s, -0.08),
            (Move::Walk, "forearm.l" | "forearm.r") => (-0.5, 0.0),
            (Move::Walk, "chest") => (0.08, 0.0),
            (Move::Wave, "arm.r") => (0.0, -2.5),
            (Move::Wave, "forearm.r") => (0.0, 0.5 * s - 0.3),
            (Move::Wave, "arm.l") => (0.0, 0.15),
            (Move::Wave, "head") => (0.0, -0.15),
            _ => (0.0, 0.0),
        };
        Quat::from_rotation_x(x) * Quat::from_rotation_z(z)
    }

    fn hips_height(self, t: f32) -> f32 {
        match self {
            Move::Walk => 1.0 + 0.04 * (TAU * t * 2.0).cos(),
            _ => 1.0,
        }
    }

    /// The clip, sampled 30 times a second over its loop.
    fn clip(self, ids: &[AnimationTargetId]) -> AnimationClip {
        let mut clip = AnimationClip::default();
        let times = || (0..=self.keys()).map(|k| f32::from(k) / 30.0);
        for (joint, &id) in ids.iter().enumerate() {
            let name = JOINTS[joint].0;
            clip.add_curve_to_target(
                id,
                AnimatableCurve::new(
                    animated_field!(Transform::rotation),
                    AnimatableKeyframeCurve::new(times().map(|t| (t, self.rotation(name, t))))
                        .unwrap(),
                ),
            );
        }
        clip.add_curve_to_target(
            ids[0],
            AnimatableCurve::new(
                animated_field!(Transform::translation),
                AnimatableKeyframeCurve::new(
                    times().map(|t| (t, Vec3::new(0.0, self.hips_height(t), 0.0))),
                )
                .unwrap(),
            ),
        );
        clip
    }
}

/// The clips' graph nodes.
#[derive(Resource)]
struct Moves {
    nodes: Vec<AnimationNodeIndex>,
}

/// A figure's hand, and where it has been.
#[derive(Component, Default)]
struct Trail(VecDeque<Vec3>);

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins,
            SpringPlugins::default(),
            TourPlugin::default(),
        ))
        .add_systems(Startup, (setup, spawn_figures))
        .add_systems(Update, (switch, trail))
        .run();
}

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    commands.spawn((
        Camera3d::default(),
        // Bevy's default tonemapping needs the `tonemapping_luts` feature.
        Tonemapping::None,
        Transform::from_xyz(2.3, 1.5, 3.7).looking_at(Vec3::new(0.0, 0.95, 0.0), Vec3::Y),
    ));
    commands.spawn((
        DirectionalLight::default(),
        Transform::from_xyz(2.0, 4.0, 3.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
    commands.spawn((
        Mesh3d(meshes.add(Plane3d::default().mesh().size(8.0, 4.0))),
        MeshMaterial3d(materials.add(Color::srgb(0.25, 0.27, 0.3))),
    ));
    commands.spawn((
        Text::new(
            "1 idle   2 walk   3 wave\n\
             left: cross-fade (AnimationTransitions)   right: Inertialization",
        ),
        Node {
            position_type: PositionType::Absolute,
            top: px(12),
            left: px(12),
            ..default()
        },
    ));
}

/// The two figures: the same joints, clips and graph; the left one switches by cross-fade, the
/// right one by inertialization.
fn spawn_figures(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
    mut clips: ResMut<Assets<AnimationClip>>,
    mut graphs: ResMut<Assets<AnimationGraph>>,
) {
    let ids: Vec<AnimationTargetId> = JOINTS
        .iter()
        .map(|(name, ..)| AnimationTargetId::from_name(&Name::new(*name)))
        .collect();
    let handles: Vec<_> = Move::ALL
        .iter()
        .map(|clip| clips.add(clip.clip(&ids)))
        .collect();
    let (graph, nodes) = AnimationGraph::from_clips(handles);
    let graph = graphs.add(graph);
    let bone = meshes.add(Cuboid::new(0.09, 1.0, 0.09));
    let head = meshes.add(Sphere::new(0.13));
    for (x, inertialized, color) in [
        (-0.9, false, Color::srgb(0.85, 0.55, 0.35)),
        (0.9, true, Color::srgb(0.35, 0.7, 0.9)),
    ] {
        let material = materials.add(color);
        let mut player = AnimationPlayer::default();
        let figure = commands
            .spawn((
                Transform::from_xyz(x, 0.0, 0.0),
                Visibility::default(),
                AnimationGraphHandle(graph.clone()),
            ))
            .id();
        if inertialized {
            let mut inertialization = Inertialization::default();
            inertialization
                .play(&mut player, nodes[0], Duration::ZERO)
                .repeat();
            commands.entity(figure).insert((player, inertialization));
        } else {
            let mut transitions = AnimationTransitions::new();
            transitions
                .play(&mut player, nodes[0], Duration::ZERO)
                .repeat();
            commands.entity(figure).insert((player, transitions));
        }
        let mut joints: Vec<Entity> = Vec::new();
        for (joint, &(name, parent, offset, length)) in JOINTS.iter().enumerate() {
            let parent = parent.map_or(figure, |parent| joints[parent]);
            let entity = commands
                .spawn((
                    Name::new(name),
                    Transform::from_translation(offset),
                    Visibility::default(),
                    ids[joint],
                    AnimatedBy(figure),
                    ChildOf(parent),
                ))
                .id();
            if name == "head" {
                commands.spawn((
                    Mesh3d(head.clone()),
                    MeshMaterial3d(material.clone()),
                    Transform::from_xyz(0.0, 0.1, 0.0),
                    ChildOf(entity),
                ));
            } else if length != 0.0 {
                commands.spawn((
                    Mesh3d(bone.clone()),
                    MeshMaterial3d(material.clone()),
                    Transform::from_xyz(0.0, length / 2.0, 0.0).with_scale(Vec3::new(
                        1.0,
                        length.abs(),
                        1.0,
                    )),
                    ChildOf(entity),
                ));
            }
            if name == "hand" {
                commands.entity(entity).insert(Trail::default());
            }
            joints.push(entity);
        }
    }
    commands.insert_resource(Moves { nodes });
}

/// Keys 1–3, or the tour's script: the same switch on both figures.
fn switch(
    keys: Res<ButtonInput<KeyCode>>,
    tour: Res<Tour>,
    moves: Res<Moves>,
    mut figures: Query<(
        &mut AnimationPlayer,
        Option<&mut AnimationTransitions>,
        Option<&mut Inertialization>,
    )>,
) {
    // Walk, wave, then idle 0.2 s into the wave's transition, walk, wave 0.15 s into that…
    const SCRIPT: [(f32, usize); 7] = [
        (0.5, 1),
        (1.5, 2),
        (1.7, 0),
        (2.5, 1),
        (2.65, 2),
        (3.6, 0),
        (4.4, 1),
    ];
    let pressed = [KeyCode::Digit1, KeyCode::Digit2, KeyCode::Digit3]
        .iter()
        .position(|&key| keys.just_pressed(key));
    let scripted = SCRIPT
        .iter()
        .find(|&&(at, _)| tour.passed(at))
        .map(|&(_, clip)| clip);
    let Some(clip) = pressed.or(scripted) else {
        return;
    };
    let node = moves.nodes[clip];
    for (mut player, transitions, inertialization) in &mut figures {
        if let Some(mut transitions) = transitions {
            transitions.play(&mut player, node, BLEND).repeat();
        } else if let Some(mut inertialization) = inertialization {
            inertialization.play(&mut player, node, BLEND).repeat();
        }
    }
}

/// The last second and a half of each hand, as a line.
fn trail(mut hands: Query<(&GlobalTransform, &mut Trail)>, mut gizmos: Gizmos) {
    for (hand, mut trail) in &mut hands {
        trail.0.push_back(hand.translation());
        if trail.0.len() > 90 {
            trail.0.pop_front();
        }
        gizmos.linestrip(trail.0.iter().copied(), Color::srgb(1.0, 0.9, 0.3));
    }
}
