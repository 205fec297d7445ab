//! A model of the plugin's usual translation step run four springs at a time (one spring per SSE
//! lane, components as vectors over the lanes), to measure what that layout would save before the
//! plugin adopts it. It keeps the usual step's work and checks: the configuration's changed tick,
//! the transition by ticket, the external-write test, the compensated offset, the finiteness and
//! rest tests, and writing (and marking) only the values that changed. A group of four where any
//! spring is not usual goes spring by spring, by a simplified step (no rest test) that the scene,
//! whose springs all keep moving, never takes: the model measures the group path.

use bevy::ecs::change_detection::{ContiguousMut, Tick};
use bevy::math::{Mat4, Vec3A, Vec4};
use bevy::prelude::*;

use super::{HALF_LIFE, sprung_spring, start, target};

/// The model's configuration: only its changed tick is read, as the plugin reads
/// `PropertySpring`'s (the same 64 bytes, so the same memory).
#[derive(Component, Clone, Copy)]
#[repr(C, align(16))]
pub(crate) struct ModelConfig([f32; 16]);

/// The model's motion: the plugin's `SpringMotion<Translation>` fields, in the same 80 bytes.
#[derive(Component, Clone, Copy)]
pub(crate) struct ModelMotion {
    velocity: Vec3A,
    offset: Vec3A,
    remainder: Vec3A,
    target: Vec3,
    pending: f32,
    rest_squared: (f32, f32),
    ticket: u64,
}

/// Spawns `count` entities as the plugin's shared-spring scene does.
pub(crate) fn spawn(world: &mut World, count: usize) {
    world.spawn_batch((0..count).map(|i| {
        let (from, to) = (start(i), target(i));
        (
            Transform::from_translation(from),
            ModelConfig([0.0; 16]),
            ModelMotion {
                velocity: Vec3A::ZERO,
                offset: Vec3A::from(from - to),
                remainder: Vec3A::ZERO,
                target: to,
                pending: 0.0,
                rest_squared: (1e-6, 1e-4),
                ticket: 0,
            },
        )
    }));
}

/// A `Vec3A` as the four lanes it is held in (on x86-64 a no-op; its fourth lane unspecified).
#[inline]
fn lanes(v: Vec3A) -> Vec4 {
    #[cfg(target_arch = "x86_64")]
    return Vec4::from(core::arch::x86_64::__m128::from(v));
    #[cfg(not(target_arch = "x86_64"))]
    return v.extend(0.0);
}

/// Four `Vec3A`s as their components over four lanes (`x`, `y`, `z`).
#[expect(
    clippy::inline_always,
    reason = "the model's loop body, measured inlined"
)]
#[inline(always)]
fn by_component(vectors: [Vec3A; 4]) -> [Vec4; 3] {
    let m = Mat4::from_cols(
        lanes(vectors[0]),
        lanes(vectors[1]),
        lanes(vectors[2]),
        lanes(vectors[3]),
    )
    .transpose();
    [m.x_axis, m.y_axis, m.z_axis]
}

/// Components over lanes back to four `Vec3A`s.
#[expect(
    clippy::inline_always,
    reason = "the model's loop body, measured inlined"
)]
#[inline(always)]
fn by_spring([x, y, z]: [Vec4; 3]) -> [Vec3A; 4] {
    let m = Mat4::from_cols(x, y, z, Vec4::ZERO).transpose();
    [m.x_axis, m.y_axis, m.z_axis, m.w_axis].map(Vec3A::from_vec4)
}

/// Four springs' `f(spring)` as the lanes of one vector.
#[expect(
    clippy::inline_always,
    reason = "the model's loop body, measured inlined"
)]
#[inline(always)]
fn gather<T>(springs: &[T; 4], f: impl Fn(&T) -> f32) -> Vec4 {
    Vec4::new(
        f(&springs[0]),
        f(&springs[1]),
        f(&springs[2]),
        f(&springs[3]),
    )
}

/// `(x² + y²) + z²` over the lanes: `Vec3A::length_squared`'s order.
#[expect(
    clippy::inline_always,
    reason = "the model's loop body, measured inlined"
)]
#[inline(always)]
fn squared([x, y, z]: [Vec4; 3]) -> Vec4 {
    (x * x + y * y) + z * z
}

/// One spring, as the plugin's usual step (or, if it was written, from its value): whether the
/// translation changed.
fn step_one(motion: &mut ModelMotion, transform: &mut Transform, increments: Vec4) -> bool {
    let [d00, d01, d10, d11] = increments.to_array();
    let current = Vec3A::from(transform.translation);
    let target = Vec3A::from(motion.target);
    let (y, remainder) = if (target + motion.offset) + motion.remainder == current {
        (motion.offset, motion.remainder)
    } else {
        (current - target, Vec3A::ZERO)
    };
    let v = motion.velocity;
    let increment = (y * d00 + v * d01) + remainder;
    let offset = y + increment;
    motion.remainder = increment - (offset - y);
    motion.offset = offset;
    motion.velocity = v + (v * d11 + y * d10);
    let value = (target + offset) + motion.remainder;
    let moved = value != current;
    if moved {
        transform.translation = value.into();
    }
    moved
}

/// [`step_one`] for each row, marking the translations that changed.
fn step_each(
    motions: &mut [ModelMotion],
    transforms: &mut [Transform],
    written: &mut [Tick],
    increments: Vec4,
    this_run: Tick,
) {
    for ((motion, transform), written) in motions.iter_mut().zip(transforms).zip(written) {
        if step_one(motion, transform, increments) {
            *written = this_run;
        }
    }
}

/// Four usual springs at once, or `false` (nothing changed) if one of them is not usual.
#[expect(
    clippy::inline_always,
    reason = "the model's loop body, measured inlined"
)]
#[inline(always)]
fn step_four(
    motions: &mut [ModelMotion; 4],
    transforms: &mut [Transform; 4],
    written: &mut [Tick; 4],
    increments: [Vec4; 4],
    this_run: Tick,
) -> bool {
    let m = Mat4::from_cols(increments[0], increments[1], increments[2], increments[3]).transpose();
    let (d00, d01, d10, d11) = (m.x_axis, m.y_axis, m.z_axis, m.w_axis);
    let current = [0, 1, 2].map(|c| gather(transforms, |t| t.translation[c]));
    let target = [0, 1, 2].map(|c| gather(motions, |m| m.target[c]));
    let offset = by_component(motions.each_ref().map(|m| m.offset));
    let remainder = by_component(motions.each_ref().map(|m| m.remainder));
    let velocity = by_component(motions.each_ref().map(|m| m.velocity));
    // Written by something else: that spring is not usual.
    let mut unwritten = 0;
    for c in 0..3 {
        unwritten |= ((target[c] + offset[c]) + remainder[c])
            .cmpne(current[c])
            .bitmask();
    }
    let mut after = [Vec4::ZERO; 3];
    let mut kept = [Vec4::ZERO; 3];
    let mut speed = [Vec4::ZERO; 3];
    for c in 0..3 {
        let (y, v) = (offset[c], velocity[c]);
        let increment = (y * d00 + v * d01) + remainder[c];
        after[c] = y + increment;
        kept[c] = increment - (after[c] - y);
        speed[c] = v + (v * d11 + y * d10);
    }
    let (offset_squared, speed_squared) = (squared(after), squared(speed));
    let (offset_tolerance, speed_tolerance) = (
        gather(motions, |m| m.rest_squared.0),
        gather(motions, |m| m.rest_squared.1),
    );
    let at_rest = offset_squared.cmple(offset_tolerance) & speed_squared.cmple(speed_tolerance);
    let finite = (offset_squared + speed_squared).cmplt(Vec4::INFINITY);
    if (unwritten | at_rest.bitmask() | (!finite.bitmask() & 0xf)) != 0 {
        return false;
    }
    let [o0, o1, o2, o3] = by_spring(after);
    let [r0, r1, r2, r3] = by_spring(kept);
    let [v0, v1, v2, v3] = by_spring(speed);
    for (motion, (offset, (remainder, velocity))) in motions.iter_mut().zip(
        [o0, o1, o2, o3]
            .into_iter()
            .zip([r0, r1, r2, r3].into_iter().zip([v0, v1, v2, v3])),
    ) {
        motion.offset = offset;
        motion.remainder = remainder;
        motion.velocity = velocity;
    }
    let value = [0, 1, 2].map(|c| (target[c] + after[c]) + kept[c]);
    let mut moved = 0;
    for c in 0..3 {
        moved |= value[c].cmpne(current[c]).bitmask();
    }
    let [x, y, z] = value.map(|v| v.to_array());
    for lane in 0..4 {
        if moved & (1 << lane) != 0 {
            transforms[lane].translation = Vec3::new(x[lane], y[lane], z[lane]);
            written[lane] = this_run;
        }
    }
    true
}

/// The model's system: one shared transition, each table's rows four at a time.
pub(crate) fn lanes_model(
    time: Res<Time>,
    mut table: Local<Vec<Vec4>>,
    mut query: Query<(&mut ModelConfig, &mut ModelMotion, &mut Transform)>,
) {
    let [[d00, d01], [d10, d11]] = sprung_spring(HALF_LIFE)
        .transition(time.delta_secs())
        .increment_matrix();
    table.clear();
    table.push(Vec4::new(d00, d01, d10, d11));
    let table = &table[..];
    let Ok(tables) = query.contiguous_iter_mut() else {
        return;
    };
    for (configs, motions, transforms) in tables {
        let (_, config_ticks) = ContiguousMut::bypass_change_detection_split(configs);
        let (motions, mut motion_ticks) = ContiguousMut::bypass_change_detection_split(motions);
        let (transforms, mut transform_ticks) =
            ContiguousMut::bypass_change_detection_split(transforms);
        let (last_run, this_run) = (config_ticks.last_run(), config_ticks.this_run());
        let changed = config_ticks.changed();
        let written = transform_ticks.changed_mut();
        let (motion_groups, motion_rest) = motions.as_chunks_mut::<4>();
        let (transform_groups, transform_rest) = transforms.as_chunks_mut::<4>();
        let (changed_groups, _) = changed.as_chunks::<4>();
        let (written_groups, written_rest) = written.as_chunks_mut::<4>();
        let groups = motion_groups
            .iter_mut()
            .zip(transform_groups.iter_mut())
            .zip(changed_groups.iter().zip(written_groups.iter_mut()));
        for ((motions, transforms), (changed, written)) in groups {
            let untouched = changed.iter().fold(true, |all, tick| {
                all & !tick.is_newer_than(last_run, this_run)
            });
            let increments = motions.each_ref().map(|m| {
                usize::try_from(m.ticket)
                    .ok()
                    .and_then(|i| table.get(i))
                    .copied()
            });
            if untouched
                && let [Some(a), Some(b), Some(c), Some(d)] = increments
                && step_four(motions, transforms, written, [a, b, c, d], this_run)
            {
                continue;
            }
            step_each(motions, transforms, written, table[0], this_run);
        }
        step_each(
            motion_rest,
            transform_rest,
            written_rest,
            table[0],
            this_run,
        );
        motion_ticks.mark_all_as_changed();
    }
}
