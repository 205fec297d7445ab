//! The pointer's velocity at release, estimated from its recent path.

use std::collections::VecDeque;

use bevy::prelude::*;

/// Estimates a pointer's velocity at release from the positions it reported over the last
/// [`WINDOW`](Self::WINDOW) seconds, by a least-squares line through them (the slope of
/// position over time), instead of from one frame's delta.
///
/// One frame's delta is noise: pointer events arrive unevenly (several per frame or none), a
/// 1 px jitter at 240 Hz is 240 px/s, and the frame of the release often holds no motion. The
/// fit over ~100 ms averages that out, follows a steady throw exactly (a line is fitted
/// exactly), and falls to zero when the pointer stood still for the whole window before it was
/// released — a drag that stops and then lets go does not fling. Positions reported at the same
/// time are one sample (the latest).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::throw::ReleaseVelocity;
///
/// let mut estimate = ReleaseVelocity::default();
/// for frame in 0..30 {
///     let t = f64::from(frame) / 60.0;
///     estimate.record(t, Vec3::new(300.0 * t as f32, 0.0, 0.0));
/// }
/// let velocity = estimate.velocity(29.0 / 60.0);
/// assert!((velocity.x - 300.0).abs() < 0.01);
/// ```
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ReleaseVelocity {
    samples: VecDeque<(f64, Vec3)>,
}

impl ReleaseVelocity {
    /// The span of the pointer's path the estimate fits: 0.1 s.
    pub const WINDOW: f64 = 0.1;

    /// Forgets the path (a new drag).
    pub fn clear(&mut self) {
        self.samples.clear();
    }

    /// Records that the pointer was at `position` at `time` (seconds, non-decreasing). A
    /// non-finite sample is ignored.
    pub fn record(&mut self, time: f64, position: Vec3) {
        if !(time.is_finite() && position.is_finite()) {
            return;
        }
        match self.samples.back_mut() {
            Some(last) if last.0 >= time => last.1 = position,
            _ => self.samples.push_back((time, position)),
        }
        while self
            .samples
            .front()
            .is_some_and(|(t, _)| *t < time - Self::WINDOW)
        {
            self.samples.pop_front();
        }
    }

    /// The velocity at `now`: the least-squares slope of the samples within the window before
    /// `now`; zero with fewer than two of them.
    #[must_use]
    pub fn velocity(&self, now: f64) -> Vec3 {
        let recent = || {
            self.samples
                .iter()
                .filter(move |(t, _)| *t >= now - Self::WINDOW)
        };
        let count = recent().count();
        if count < 2 {
            return Vec3::ZERO;
        }
        // Centred sums, in f64 and relative to `now`, so neither a long run time nor large
        // coordinates cost digits.
        let n = count as f64;
        let (mut mean_t, mut mean_x) = (0.0, [0.0f64; 3]);
        for (t, x) in recent() {
            mean_t += (t - now) / n;
            for (mean, x) in mean_x.iter_mut().zip(x.to_array()) {
                *mean += f64::from(x) / n;
            }
        }
        let (mut stt, mut stx) = (0.0, [0.0f64; 3]);
        for (t, x) in recent() {
            let dt = (t - now) - mean_t;
            stt += dt * dt;
            for (s, (x, mean)) in stx.iter_mut().zip(x.to_array().into_iter().zip(mean_x)) {
                *s += dt * (f64::from(x) - mean);
            }
        }
        if stt <= 0.0 {
            return Vec3::ZERO;
        }
        #[expect(clippy::cast_possible_truncation, reason = "a velocity in f32")]
        let slope = stx.map(|s| (s / stt) as f32);
        Vec3::from_array(slope)
    }
}

#[cfg(test)]
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "test paths: times narrowed to f32 positions, small frame counts"
)]
mod tests {
    use super::*;

    /// A steady throw at 60 Hz with ±1 px of jitter: the fit is within 2% where the last
    /// frame's delta is off by up to 120 px/s.
    #[test]
    fn steady_throw_with_jitter() {
        let mut estimate = ReleaseVelocity::default();
        let jitter = [0.9, -1.0, 0.4, -0.7, 1.0, -0.2, 0.6, -0.9];
        let mut last = [Vec3::ZERO; 2];
        for frame in 0..40 {
            let t = f64::from(frame) / 60.0;
            let position = Vec3::new(
                800.0 * t as f32 + jitter[frame as usize % 8],
                -200.0 * t as f32,
                0.0,
            );
            estimate.record(t, position);
            last = [last[1], position];
        }
        let velocity = estimate.velocity(39.0 / 60.0);
        assert!((velocity.x - 800.0).abs() < 16.0, "{velocity}");
        assert!((velocity.y + 200.0).abs() < 4.0, "{velocity}");
        let delta = (last[1] - last[0]) * 60.0;
        assert!(
            (delta.x - 800.0).abs() > 50.0,
            "the one-frame delta {delta}"
        );
    }

    /// A pointer that stopped for longer than the window before release does not fling; one
    /// that stopped only briefly keeps part of its speed.
    #[test]
    fn stopping_before_release() {
        let mut estimate = ReleaseVelocity::default();
        for frame in 0..30 {
            let t = f64::from(frame) / 60.0;
            estimate.record(t, Vec3::X * (500.0 * t as f32));
        }
        let stop = 29.0 / 60.0;
        let end = Vec3::X * (500.0 * stop as f32);
        estimate.record(stop + 0.05, end);
        let brief = estimate.velocity(stop + 0.05);
        assert!(brief.x > 10.0 && brief.x < 500.0, "{brief}");
        estimate.record(stop + 0.2, end);
        assert_eq!(estimate.velocity(stop + 0.2), Vec3::ZERO);
    }

    /// Events at the same time are one sample; one sample is no velocity; bad input is ignored.
    #[test]
    fn degenerate_paths() {
        let mut estimate = ReleaseVelocity::default();
        estimate.record(1.0, Vec3::ZERO);
        estimate.record(1.0, Vec3::X);
        assert_eq!(estimate.velocity(1.0), Vec3::ZERO);
        estimate.record(f64::NAN, Vec3::Y);
        estimate.record(1.1, Vec3::NAN);
        assert_eq!(estimate.velocity(1.0), Vec3::ZERO);
        estimate.record(1.05, Vec3::X * 2.0);
        assert!((estimate.velocity(1.05).x - 20.0).abs() < 1e-3);
    }
}
