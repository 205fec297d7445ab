//! The spring step of the plugin, driven directly (no app, so millions of frames run in
//! seconds): random damped springs arrive at every frame rate and magnitude, and a million
//! frames of hitches, retargets and impulses stay finite, follow the exact motion and settle.
//! `tests/plugin` drives the same step through a real app.

use bevy::prelude::*;
use proptest::prelude::*;
use sprung::{RestThreshold, Scalar, Spring, SpringState};

use super::cache::TransitionCache;
use super::step::{Stepped, Transitions};
use super::table::TransitionTable;
use crate::clock::FrameSteps;
use crate::space::{Linear, NeverThroughZero};
use crate::spring::component::{PropertySpring, SlotTicket, SpringMotion};

/// A body the tests spring: its position as a translation is (a `Vec3`, stepped in `Vec3A`),
/// its angle as a spin's, its size as a UI scale's (a `Vec2` kept from crossing zero).
#[derive(Component, Default)]
struct Body {
    position: Vec3,
    angle: f32,
    size: Vec2,
}

spring_property!(
    /// `Body::position`.
    Position: Body::position as Linear<Vec3>
);
spring_property!(
    /// `Body::angle`.
    Angle: Body::angle as Linear<f32>
);
spring_property!(
    /// `Body::size`.
    Size: Body::size as NeverThroughZero<Linear<Vec2>>
);

/// A spring on a body's position.
type PositionSpring = PropertySpring<Position>;

/// The frame rates users run at.
const FRAME_RATES: [u32; 6] = [30, 60, 120, 144, 240, 360];

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

#[expect(
    clippy::cast_possible_truncation,
    reason = "test values narrowed to f32"
)]
fn narrow(x: f64) -> f32 {
    x as f32
}

/// `±10^e` for `e` uniform in `[low, high)`.
fn magnitude(low: f64, high: f64) -> impl Strategy<Value = f32> {
    (low..high, any::<bool>()).prop_map(|(e, negative)| {
        let value = narrow(10f64.powf(e));
        if negative { -value } else { value }
    })
}

/// A damped spring users reach: `ω ∈ [0.5, 50]` rad/s, `ζ ∈ [0.05, 50]`, log-uniform.
fn damped_spring() -> impl Strategy<Value = Spring> {
    ((-0.301..1.699_f64), (-1.301..1.699_f64)).prop_map(|(w, z)| {
        Spring::from_natural_frequency(narrow(10f64.powf(w)), narrow(10f64.powf(z))).unwrap()
    })
}

/// The tolerance at `magnitude`: a thousandth of a unit or four times the spacing of `f32`
/// there, whichever is coarser, with the speed of equal energy.
fn rest_for(spring: &Spring, magnitude: f32) -> RestThreshold {
    RestThreshold::for_spring(spring, 1e-3_f32.max(4.0 * magnitude.spacing()))
}

/// One frame of the stepping system's protocol for one spring: the table prepared for the
/// frame's time steps, the step, and the slots it asked for added.
fn step_frame<P: crate::property::SpringProperty, C: core::ops::DerefMut<Target = P::Component>>(
    (spring, motion): (&mut PropertySpring<P>, &mut SpringMotion<P>),
    component: &mut C,
    steps: FrameSteps,
    skipping: bool,
    (table, cache): (&mut TransitionTable, &mut TransitionCache),
) -> Stepped {
    table.prepare(steps);
    let transitions = Transitions {
        table: &*table,
        cache,
    };
    let stepped = motion.step_on(spring, component, steps, skipping, transitions);
    table.finish(1);
    stepped
}

/// Steps `spring` on `component` at `fps` until it settles or `limit` seconds pass; the settle
/// time in seconds.
fn settle<P: crate::property::SpringProperty>(
    spring: &mut PropertySpring<P>,
    component: &mut P::Component,
    fps: u32,
    limit: f64,
) -> Option<f64> {
    let dt = 1.0 / f64::from(fps);
    let mut cache = TransitionCache::default();
    let mut table = TransitionTable::default();
    let mut motion = SpringMotion::toward(spring.target(), spring.rest());
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a positive, bounded frame count"
    )]
    let frames = (limit / dt).ceil() as u64;
    (1..=frames).find_map(|frame| {
        let steps = FrameSteps::all(narrow(dt));
        let stepped = step_frame(
            (spring, &mut motion),
            &mut &mut *component,
            steps,
            false,
            (&mut table, &mut cache),
        );
        #[expect(clippy::cast_precision_loss, reason = "frame counts are small")]
        (stepped == Stepped::Settled).then_some(frame as f64 * dt)
    })
}

fn check_translation(spring: Spring, start: f32, target: f32) -> Result<(), TestCaseError> {
    let rest = rest_for(&spring, target);
    let distance = (target - start).abs();
    let analytic = f64::from(spring.settle_time(distance, rest.offset).unwrap());
    for fps in FRAME_RATES {
        let mut body = Body {
            position: Vec3::new(start, 0.0, 0.0),
            ..default()
        };
        let mut translation =
            PositionSpring::new(spring, Vec3::new(target, 0.0, 0.0)).with_rest(rest);
        let settled = settle(&mut translation, &mut body, fps, 2.0 * analytic + 1.0);
        let frames = 2.0 / f64::from(fps);
        prop_assert!(
            settled.is_some_and(|at| at <= 1.05 * analytic + frames + 1e-9),
            "{spring:?} at {fps} fps from {start} toward {target}: settled {settled:?}, \
             analytic {analytic}"
        );
        prop_assert_eq!(body.position, Vec3::new(target, 0.0, 0.0));
    }
    Ok(())
}

fn check_spin(spring: Spring, target: f32) -> Result<(), TestCaseError> {
    let rest = rest_for(&spring, target);
    let analytic = f64::from(spring.settle_time(target.abs(), rest.offset).unwrap());
    for fps in FRAME_RATES {
        let mut body = Body::default();
        let mut angle = PropertySpring::<Angle>::new(spring, target).with_rest(rest);
        let settled = settle(&mut angle, &mut body, fps, 2.0 * analytic + 1.0);
        let frames = 2.0 / f64::from(fps);
        prop_assert!(
            settled.is_some_and(|at| at <= 1.05 * analytic + frames + 1e-9),
            "{spring:?} spin at {fps} fps toward {target}: settled {settled:?}, analytic \
             {analytic}"
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(64))]

    #[test]
    fn random_damped_translations_arrive(
        spring in damped_spring(),
        target in magnitude(-3.0, 6.0),
        start in prop_oneof![magnitude(-3.0, 6.0), Just(0.0_f32)],
    ) {
        check_translation(spring, start, target)?;
    }

    #[test]
    fn random_damped_spins_arrive(spring in damped_spring(), target in magnitude(-3.0, 4.0)) {
        check_spin(spring, target)?;
    }
}

/// A small, seeded generator (`SplitMix64`): the run is the same every time.
struct Random(u64);

impl Random {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        #[expect(clippy::cast_precision_loss, reason = "53 random bits")]
        let unit = (self.next() >> 11) as f64 / (1_u64 << 53) as f64;
        unit
    }

    /// Uniform in `[-scale, scale)`, in `f32`.
    fn symmetric(&mut self, scale: f64) -> f32 {
        narrow(scale * (2.0 * self.unit() - 1.0))
    }
}

/// A million frames of random frame times (a hitch of up to half a second one frame in a
/// hundred, no time at all one in a hundred), retargets and impulses, over translation springs
/// of many kinds, each shadowed by the exact motion in `f64` (per axis). Every frame the state
/// is finite and follows its shadow; after the last retarget each spring settles exactly on its
/// target no later than two frames after its shadow is well within the tolerance.
#[test]
fn a_million_frames_of_hitches_retargets_and_impulses() {
    const FRAMES: u32 = 1_000_000;
    const SPRINGS: usize = 8;
    let mut random = Random(0xB0B);
    let mut worst = 0.0_f64;
    for index in 0..SPRINGS {
        let omega = narrow(10f64.powf(-0.3 + 2.0 * random.unit()));
        let zeta = narrow(10f64.powf(-1.3 + 3.0 * random.unit()));
        let scale = 10f64.powf(-2.0 + 8.0 * random.unit());
        let parameters = Spring::from_natural_frequency(omega, zeta).unwrap();
        let exact = Spring::<f64>::from(parameters);
        let mut body = Body::default();
        let mut spring = PositionSpring::new(parameters, Vec3::ZERO);
        let mut motion = SpringMotion::toward(Vec3::ZERO, spring.rest());
        let mut shadow = [SpringState::at_rest(0.0_f64); 3];
        let mut cache = TransitionCache::default();
        let mut table = TransitionTable::default();
        for frame in 0..=FRAMES {
            let event = random.unit();
            if event < 0.01 {
                let target = Vec3::new(
                    random.symmetric(scale),
                    random.symmetric(scale),
                    random.symmetric(scale),
                );
                spring.set_target(target);
            } else if event < 0.015 {
                let speed = f64::from(omega) * scale;
                let kick = Vec3::new(
                    random.symmetric(speed),
                    random.symmetric(speed),
                    random.symmetric(speed),
                );
                spring.add_impulse(kick);
                for (state, kick) in shadow.iter_mut().zip(kick.to_array()) {
                    state.velocity += f64::from(kick);
                }
            }
            let target = spring.target().to_array();
            let dt = match random.unit() {
                x if x < 0.01 => 0.0,
                x if x < 0.02 => narrow(0.5 * random.unit()),
                _ => narrow(1.0 / (30.0 + 330.0 * random.unit())),
            };
            let stepped = step_frame(
                (&mut spring, &mut motion),
                &mut &mut body,
                FrameSteps::all(dt),
                false,
                (&mut table, &mut cache),
            );
            let step = exact.transition(f64::from(dt));
            for (state, target) in shadow.iter_mut().zip(target) {
                *state = if stepped == Stepped::Settled {
                    // The spring snapped onto its target; so does its shadow.
                    SpringState::at_rest(f64::from(target))
                } else {
                    step.step(*state, f64::from(target))
                };
            }
            let translation = body.position;
            assert!(
                translation.is_finite() && motion.velocity().is_finite(),
                "spring {index} frame {frame}: {translation} {spring:?} {motion:?}"
            );
            for (axis, state) in shadow.iter().enumerate() {
                let gap = (f64::from(translation[axis]) - state.position).abs() / scale;
                worst = worst.max(gap);
                assert!(
                    gap < 1e-4,
                    "spring {index} frame {frame} axis {axis}: {translation} vs {state:?}"
                );
            }
        }
        settle_after_the_last_retarget(
            (index, omega, zeta),
            &exact,
            (&mut spring, &mut motion, &mut body),
            &mut shadow,
            (&mut table, &mut cache),
        );
    }
    println!("largest gap to the f64 shadow: {worst:.1e} of the scale");
}

/// After the last retarget of the soak: the spring settles exactly on its target, no later than
/// two frames after its `f64` shadow is well within the tolerances.
fn settle_after_the_last_retarget(
    (index, omega, zeta): (usize, f32, f32),
    exact: &Spring<f64>,
    (spring, motion, body): (&mut PositionSpring, &mut SpringMotion<Position>, &mut Body),
    shadow: &mut [SpringState<f64>; 3],
    (table, cache): (&mut TransitionTable, &mut TransitionCache),
) {
    let target = spring.target();
    let rest = spring.rest().at_magnitude(target.abs().max_element());
    let dt = 1.0 / 144.0;
    let step = exact.transition(f64::from(dt));
    let mut shadow_at_rest = None;
    for frame in 1_u32.. {
        let settled = step_frame(
            (spring, motion),
            &mut &mut *body,
            FrameSteps::all(dt),
            false,
            (&mut *table, &mut *cache),
        ) == Stepped::Settled;
        for (axis, state) in shadow.iter_mut().enumerate() {
            *state = step.step(*state, f64::from(target[axis]));
        }
        let within = shadow.iter().enumerate().all(|(axis, state)| {
            (state.position - f64::from(target[axis])).abs() <= f64::from(rest.offset) / 4.0
                && state.velocity.abs() <= f64::from(rest.speed) / 4.0
        });
        if within {
            shadow_at_rest.get_or_insert(frame);
        }
        if settled {
            assert_eq!(body.position, target);
            break;
        }
        assert!(
            shadow_at_rest.is_none_or(|at| frame <= at + 2),
            "spring {index} (ω {omega}, ζ {zeta}) stays away from {target} after its shadow \
             settled: {}",
            body.position
        );
    }
}

/// Every awake spring's motion is streamed through each frame, its configuration only when it
/// changed: a translation's motion (whose offsets are 16-byte `Vec3A`s) stays within 80 bytes,
/// and the configuration within one cache line.
#[test]
fn a_translation_spring_streams_80_bytes() {
    let motion = size_of::<SpringMotion<Position>>();
    assert!(motion <= 80, "motion: {motion} bytes");
    let configuration = size_of::<PositionSpring>();
    assert!(configuration <= 64, "configuration: {configuration} bytes");
}

/// A `Vec2` spring's motion is packed into a multiple of 16 bytes (in a column that starts
/// 16-byte aligned, as the allocator's do, its 16-byte state load then straddles two cache
/// lines in one motion of four, and its other accesses never): the ticket is kept in 4-byte halves (8-byte aligned, it padded the motion to
/// 56), and holds the time pending (in a field of its own, the motion was 52 bytes).
#[test]
fn a_ui_scale_spring_streams_48_bytes() {
    let motion = size_of::<SpringMotion<Size>>();
    assert!(
        motion <= 48 && motion.is_multiple_of(16),
        "motion: {motion} bytes"
    );
}

/// The slot ticket and the time pending share a field: each reads back what was set, a spring
/// with time pending has a ticket no slot has, and forgetting the slot keeps the time.
#[test]
fn the_time_pending_and_the_slot_ticket_share_a_field() {
    let mut motion = SpringMotion::<Position>::default();
    assert_eq!(motion.pending().to_bits(), 0);
    assert!(motion.ticket() >= SlotTicket::NO_SLOT);
    for ticket in [0, 5, u64::from(u32::MAX) + 1, SlotTicket::NO_SLOT - 1] {
        motion.set_ticket(ticket);
        assert_eq!((motion.ticket(), motion.pending().to_bits()), (ticket, 0));
        motion.clear_ticket();
        assert!(motion.ticket() >= SlotTicket::NO_SLOT);
        assert_eq!(motion.pending().to_bits(), 0);
    }
    for seconds in [
        f32::MIN_POSITIVE,
        1.0e-6,
        0.25,
        1.0e6,
        f32::MAX,
        f32::INFINITY,
    ] {
        motion.set_ticket(7);
        motion.set_pending(seconds);
        assert!(motion.ticket() >= SlotTicket::NO_SLOT, "{seconds}");
        assert_eq!(motion.pending().to_bits(), seconds.to_bits());
        motion.clear_ticket();
        assert_eq!(motion.pending().to_bits(), seconds.to_bits());
        motion.set_pending(0.0);
        assert_eq!(motion.pending().to_bits(), 0);
    }
}
