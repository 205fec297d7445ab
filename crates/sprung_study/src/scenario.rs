//! The scenario grid: which springs are stepped with which frame times and targets.
//!
//! Every scenario starts at rest at 0 with its first target at 1 (amplitude 1), so errors are
//! fractions of the amplitude.

use crate::methods::{SpringParams, State};

/// Damping ratios of the grid.
pub const ZETAS: [f64; 7] = [0.0, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0];
/// `ω·dt` of the grid (log-spaced).
pub const OMEGA_DTS: [f64; 7] = [0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0];
/// Frame rates of the frame-time sweep, in frames per second (`dt` from 1/240 s to 1 s).
pub const FRAME_RATES: [f64; 7] = [240.0, 144.0, 60.0, 30.0, 10.0, 4.0, 1.0];
/// Natural frequency of every spring of the grid, in rad/s.
pub const OMEGA: f64 = 10.0;
/// Simulated time of the fixed-`dt` scenarios (`ω·T = 20`, about three periods).
pub const DURATION: f64 = 2.0;
/// Fewest frames of a fixed-`dt` scenario (so that long frames still take several steps).
pub const MIN_FRAMES: usize = 20;
/// The damping ratio of the representative setting the plot uses.
pub const PLOT_ZETA: f64 = 0.5;

/// The kind of a scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// Fixed `dt`, from the `ζ × ω·dt` grid.
    Grid,
    /// Fixed `dt`, from the frame-time sweep at `ω = 10`.
    FrameRate,
    /// 59 frames of 1/60 s, one of 1 s, then 60 more of 1/60 s.
    Hitch,
    /// 60 fps; the target jumps from 1 to −1 halfway, while the spring moves.
    Retarget,
    /// Outside the grid: near-critical and very heavy springs (reported separately).
    Hard,
}

/// One frame: its time step and the (constant) target during it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Time step in seconds.
    pub dt: f64,
    /// Target during the frame.
    pub target: f64,
}

/// A spring, a start state and a sequence of frames.
#[derive(Clone, Debug)]
pub struct Scenario {
    /// What kind of scenario this is.
    pub family: Family,
    /// Short human-readable description.
    pub label: String,
    /// The spring.
    pub spring: SpringParams,
    /// Start state.
    pub start: State,
    /// The frames, in order.
    pub frames: Vec<Frame>,
    /// The `dt` of every frame when they are all equal (then the methods' per-step growth
    /// factor is checked too).
    pub fixed_dt: Option<f64>,
}

impl Scenario {
    /// `count` frames of `dt` toward 1.
    fn fixed(family: Family, label: String, spring: SpringParams, dt: f64, count: usize) -> Self {
        Self {
            family,
            label,
            spring,
            start: State::new(0.0, 0.0),
            frames: vec![Frame { dt, target: 1.0 }; count],
            fixed_dt: Some(dt),
        }
    }

    /// The initial distance to the target: what errors are measured against.
    #[must_use]
    pub fn amplitude(&self) -> f64 {
        self.frames
            .first()
            .map_or(1.0, |frame| (frame.target - self.start.position).abs())
    }

    /// The simulated time.
    #[must_use]
    pub fn duration(&self) -> f64 {
        self.frames.iter().map(|frame| frame.dt).sum()
    }
}

/// Frames of `dt` for [`DURATION`], and at least [`MIN_FRAMES`].
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "a small positive frame count"
)]
fn frame_count(dt: f64) -> usize {
    ((DURATION / dt).round() as usize).max(MIN_FRAMES)
}

/// Every scenario of the study, grid first, in a fixed order.
#[must_use]
pub fn all() -> Vec<Scenario> {
    let mut out = Vec::new();
    let springs: Vec<SpringParams> = ZETAS
        .iter()
        .map(|&zeta| SpringParams::new(OMEGA, zeta))
        .collect();
    for &spring in &springs {
        for &omega_dt in &OMEGA_DTS {
            let dt = omega_dt / OMEGA;
            out.push(Scenario::fixed(
                Family::Grid,
                format!("ζ = {}, ω·dt = {omega_dt}", spring.zeta),
                spring,
                dt,
                frame_count(dt),
            ));
        }
    }
    for &spring in &springs {
        for &fps in &FRAME_RATES {
            let dt = 1.0 / fps;
            out.push(Scenario::fixed(
                Family::FrameRate,
                format!("ζ = {}, dt = 1/{fps} s", spring.zeta),
                spring,
                dt,
                frame_count(dt),
            ));
        }
    }
    for &spring in &springs {
        let mut frames = vec![
            Frame {
                dt: 1.0 / 60.0,
                target: 1.0
            };
            120
        ];
        frames[59].dt = 1.0;
        out.push(Scenario {
            family: Family::Hitch,
            label: format!("ζ = {}, 1 s hitch at 60 fps", spring.zeta),
            spring,
            start: State::new(0.0, 0.0),
            frames,
            fixed_dt: None,
        });
    }
    for &spring in &springs {
        let frames = (0..60)
            .map(|i| Frame {
                dt: 1.0 / 60.0,
                target: if i < 30 { 1.0 } else { -1.0 },
            })
            .collect();
        out.push(Scenario {
            family: Family::Retarget,
            label: format!("ζ = {}, retarget 1 → −1 at 0.5 s, 60 fps", spring.zeta),
            spring,
            start: State::new(0.0, 0.0),
            frames,
            fixed_dt: None,
        });
    }
    for (zeta, why) in [
        (1.0 - 5e-5, "inside Juckett's critical band"),
        (1.0 + 5e-5, "inside Juckett's critical band"),
        (1e4, "very heavy: st ≫ 710 per frame"),
    ] {
        let dt = 1.0 / 60.0;
        out.push(Scenario::fixed(
            Family::Hard,
            format!("ζ = {zeta}, 60 fps ({why})"),
            SpringParams::new(OMEGA, zeta),
            dt,
            frame_count(dt),
        ));
    }
    out
}
