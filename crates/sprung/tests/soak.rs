//! A long run: a million frames of random frame times (hitches of half a second included),
//! retargets and impulses over many `f32` springs, each shadowed by the same run in `f64`.
//! Every state stays finite, follows its `f64` shadow, and after the last retarget comes to
//! rest no later than the shadow does.

use sprung::{RestThreshold, Spring, SpringState};

/// Frames of events per spring.
const FRAMES: u32 = 1_000_000;
/// Springs, each with its own run.
const SPRINGS: u64 = 12;

/// A small, seeded generator (SplitMix64): the run is the same every time.
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

    /// `±10^e`, `e` uniform in `[low, high)`.
    fn magnitude(&mut self, low: f64, high: f64) -> f64 {
        let value = 10f64.powf(low + (high - low) * self.unit());
        if self.unit() < 0.5 { -value } else { value }
    }
}

#[expect(
    clippy::cast_possible_truncation,
    reason = "test values narrowed to f32"
)]
fn narrow(x: f64) -> f32 {
    x as f32
}

#[test]
fn a_million_frames_of_hitches_retargets_and_impulses() {
    let mut random = Random(0x5EED);
    for index in 0..SPRINGS {
        // ω in [0.5, 50], ζ in [0.05, 50]; a scale for targets from 1e-3 to 1e6.
        let omega = narrow(10f64.powf(-0.3 + 2.0 * random.unit()));
        let zeta = narrow(10f64.powf(-1.3 + 3.0 * random.unit()));
        let scale = 10f64.powf(-3.0 + 9.0 * random.unit());
        let spring = Spring::<f32>::from_natural_frequency(omega, zeta).unwrap();
        let shadow_spring = Spring::<f64>::from(spring);
        let mut state = SpringState::at_rest(narrow(scale * random.unit()));
        let mut shadow = SpringState::at_rest(f64::from(state.position));
        let mut target = state.position;
        let mut worst_gap = 0.0_f64;
        for frame in 0..FRAMES {
            let event = random.unit();
            if event < 0.01 {
                target = narrow(scale * random.magnitude(-1.0, 0.0));
            } else if event < 0.015 {
                let kick = narrow(scale * f64::from(omega) * random.magnitude(-1.0, 0.0));
                state.velocity += kick;
                shadow.velocity = f64::from(state.velocity);
            }
            // Mostly frames of 1/360 to 1/30 s; one in a hundred a hitch of up to 0.5 s, one in
            // a hundred no time at all.
            let dt = match random.unit() {
                x if x < 0.01 => 0.0,
                x if x < 0.02 => narrow(0.5 * random.unit()),
                _ => narrow(1.0 / (30.0 + 330.0 * random.unit())),
            };
            state = spring.transition(dt).step(state, target);
            shadow = shadow_spring
                .transition(f64::from(dt))
                .step(shadow, f64::from(target));
            assert!(
                state.position.is_finite() && state.velocity.is_finite(),
                "spring {index} frame {frame}: {state:?}"
            );
            // Both follow the same exact motion; they differ by rounding only, which the
            // damping forgets.
            let gap = (f64::from(state.position) - shadow.position).abs() / scale;
            worst_gap = worst_gap.max(gap);
            assert!(
                gap < 1e-4,
                "spring {index} frame {frame}: {state:?} vs {shadow:?}"
            );
        }
        // The last retarget: now it settles, no later than its shadow does.
        let rest = RestThreshold::for_spring(&spring, narrow(1e-6 * scale)).at_magnitude(target);
        let dt = 1.0 / 144.0;
        let (step, shadow_step) = (
            spring.transition(dt),
            shadow_spring.transition(f64::from(dt)),
        );
        let half = |x: f32| f64::from(x) / 2.0;
        let mut frames = 0_u32;
        let mut shadow_settled = None;
        while !rest.is_at_rest(state.position - target, state.velocity) {
            state = step.step(state, target);
            shadow = shadow_step.step(shadow, f64::from(target));
            frames += 1;
            if (shadow.position - f64::from(target)).abs() <= half(rest.offset)
                && shadow.velocity.abs() <= half(rest.speed)
            {
                shadow_settled.get_or_insert(frames);
            }
            assert!(
                shadow_settled.is_none_or(|settled| frames <= settled + 2),
                "spring {index} (ω {omega}, ζ {zeta}) stays away from {target} after its shadow \
                 settled: {state:?}"
            );
        }
        println!(
            "spring {index}: ω {omega:.2}, ζ {zeta:.3}, scale {scale:.1e}: largest gap to f64 \
             {worst_gap:.1e} of the scale; settled {frames} frames after the last retarget"
        );
    }
}
