//! One joint's inertialization: the poses it showed, and the offset that decays after a switch.

use bevy::prelude::*;
use sprung::{SpringState, Transition};

use super::pose::{Pose, PoseDelta};
use crate::space::rotation_vector;

/// What a player's joints need this frame: its transition count, the step of its blend spring
/// over this frame (`None`: switches are instant), and the frame's time.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BlendFrame {
    /// How many transitions the player has started: a joint that has seen fewer starts one.
    pub(crate) transitions: u32,
    /// The exact step of the blend spring over `dt`, and its natural frequency.
    pub(crate) step: Option<(Transition<f32>, f32)>,
    /// This frame's time on the animation's clock, in seconds.
    pub(crate) dt: f32,
}

impl BlendFrame {
    /// A frame in which nothing has been started.
    pub(crate) const IDLE: Self = Self {
        transitions: 0,
        step: None,
        dt: 0.0,
    };
}

/// What inertialization keeps of one joint of a player with an
/// [`Inertialization`](super::Inertialization): the poses it showed in the last two frames (to
/// know where it was heading), the pose the animation gave it, and, while a transition blends,
/// the offset from that pose.
#[derive(Component, Clone, Debug)]
pub(crate) struct InertialJoint {
    /// The pose shown last frame, the one shown the frame before, and the time between them
    /// (zero: no rate known).
    shown: Pose,
    before: Pose,
    step: f32,
    /// The pose the animation gave last frame, before the offset.
    clip: Pose,
    /// The player's transition count this joint has seen.
    transitions: u32,
    /// The offset shown − clip while a transition blends.
    blend: Option<JointBlend>,
}

/// A transition in progress on one joint.
///
/// The offset starts at the time of the switch (the start of the frame that shows it, where the
/// new clip's time starts) as the pose shown then less the new clip's, moving at the old rate
/// less the new clip's; from there it follows the exact decay, so the pose a given time after
/// a switch does not depend on the frames in between.
#[derive(Clone, Copy, Debug)]
struct JointBlend {
    /// The difference shown − clip and its rate, decaying to zero on the blend spring (without
    /// the new clip's part while that is [`pending`](Self::pending)).
    offset: SpringState<PoseDelta>,
    /// The new clip's part of the offset, until the frame after the switch gives its rate.
    pending: Option<PendingSwitch>,
    /// The sizes (translation, radians, scale) below which the offset is done.
    rest: Vec3,
}

/// On the frame of a switch only the new clip's pose at the frame's end is known, not where it
/// stood at the switch nor its rate. Both are its rate `w` times known factors (it stood
/// `w·dt` back; the offset moves at the old rate less `w`), and the decay is linear in where it
/// starts: so the offset is stepped without them, and what a unit of each would have added is
/// stepped alongside, to be added once the next frame gives `w`.
#[derive(Clone, Copy, Debug)]
struct PendingSwitch {
    /// What one unit of the clip's rate adds to the offset's position and velocity: `(dt, −1)`
    /// at the switch, stepped since.
    per_rate: SpringState<f32>,
    /// What one unit more of the offset at the switch adds: `(1, 0)` at the switch, stepped
    /// since. It carries the part of the rotation the rotation vectors do not add linearly.
    per_offset: SpringState<f32>,
    /// The rotation shown at the switch, the clip's at the end of the switch's frame, and that
    /// frame's time.
    shown_rotation: Quat,
    clip_rotation: Quat,
    dt: f32,
}

/// How small an offset's parts must get, as a fraction of their sizes when the blend began,
/// before the joint shows the clip's pose exactly (the last jump is that much of the first
/// offset: a tenth of a millimetre for a metre, far below what shows).
const REST_FRACTION: f32 = 1e-4;

impl InertialJoint {
    /// A joint showing `pose`, having seen `transitions` of its player: no rate known yet, no
    /// blend.
    pub(crate) fn at(pose: Pose, transitions: u32) -> Self {
        Self {
            shown: pose,
            before: pose,
            step: 0.0,
            clip: pose,
            transitions,
            blend: None,
        }
    }

    /// Whether an offset is being shown (the `Transform` holds `clip + offset`).
    #[inline]
    pub(crate) fn is_blending(&self) -> bool {
        self.blend.is_some()
    }

    /// Puts back the animation's pose in each part of `transform` that still shows what this
    /// joint wrote, so that a clip which does not animate a part starts from the clip's pose
    /// and not from last frame's offset pose. Parts written by anything else since are kept.
    #[inline]
    pub(crate) fn restore_clip_pose(&self, transform: &mut Transform) {
        if transform.translation == self.shown.translation {
            transform.translation = self.clip.translation;
        }
        if transform.rotation == self.shown.rotation {
            transform.rotation = self.clip.rotation;
        }
        if transform.scale == self.shown.scale {
            transform.scale = self.clip.scale;
        }
    }

    /// Drops the blend (the player is gone or no longer inertialized): the clip is shown as it
    /// is.
    pub(crate) fn forget(&mut self) {
        self.blend = None;
    }

    /// Advances the joint by this frame, given the pose the animation gave it (`clip`), and
    /// returns the pose to show.
    pub(crate) fn advance(&mut self, clip: Pose, frame: &BlendFrame) -> Pose {
        if !clip.is_finite() {
            // Nothing to add to; the blend waits for a pose it can use.
            return clip;
        }
        if self.transitions != frame.transitions {
            self.transitions = frame.transitions;
            self.blend = frame
                .step
                .map(|(step, _)| self.start(clip, frame.dt, &step));
        } else if let (Some(blend), Some((step, omega))) = (&mut self.blend, frame.step)
            && frame.dt > 0.0
        {
            if blend.pending.is_some() {
                blend.take_clip_rate(clip.rate_since(&self.clip, frame.dt), omega);
            }
            blend.step(&step);
            if blend.is_done(omega) {
                self.blend = None;
            }
        }
        let shown = match &self.blend {
            Some(blend) => clip.plus(&blend.offset.position),
            None => clip,
        };
        if frame.dt > 0.0 {
            self.before = self.shown;
            self.step = frame.dt;
        }
        self.shown = shown;
        self.clip = clip;
        shown
    }

    /// A blend from the pose this joint showed last frame, moving at the rate it showed, to
    /// the new clip whose pose at the end of this frame of `dt` is `clip`: the offset at the
    /// switch, stepped over the frame.
    fn start(&self, clip: Pose, dt: f32, step: &Transition<f32>) -> JointBlend {
        let rate = self.shown.rate_since(&self.before, self.step);
        let mut blend = JointBlend {
            offset: SpringState::new(self.shown.minus(&clip), rate),
            pending: Some(PendingSwitch {
                per_rate: SpringState::new(dt, -1.0),
                per_offset: SpringState::new(1.0, 0.0),
                shown_rotation: self.shown.rotation,
                clip_rotation: clip.rotation,
                dt,
            }),
            rest: Vec3::ZERO,
        };
        if dt > 0.0 {
            blend.step(step);
        }
        blend
    }
}

impl JointBlend {
    /// One exact step of the offset (and of the pending parts) toward zero.
    fn step(&mut self, step: &Transition<f32>) {
        self.offset = step.step(self.offset, PoseDelta::default());
        if let Some(pending) = &mut self.pending {
            pending.per_rate = step.step(pending.per_rate, 0.0);
            pending.per_offset = step.step(pending.per_offset, 0.0);
        }
    }

    /// The new clip's rate is known: its part of the offset is added, and the sizes at which the
    /// offset is done follow from where it is.
    fn take_clip_rate(&mut self, clip_rate: PoseDelta, omega: f32) {
        if let Some(pending) = self.pending.take() {
            // Where the clip's rotation stood at the switch, exactly, against the linear
            // `w·dt` that `per_rate` adds (rotations about different axes do not add).
            let clip_then =
                Quat::from_scaled_axis(-clip_rate.rotation * pending.dt) * pending.clip_rotation;
            let exact = rotation_vector(pending.shown_rotation * clip_then.inverse());
            let taken = rotation_vector(pending.shown_rotation * pending.clip_rotation.inverse());
            let correction = PoseDelta {
                rotation: exact - taken - clip_rate.rotation * pending.dt,
                ..PoseDelta::default()
            };
            self.offset = SpringState::new(
                self.offset.position
                    + clip_rate * pending.per_rate.position
                    + correction * pending.per_offset.position,
                self.offset.velocity
                    + clip_rate * pending.per_rate.velocity
                    + correction * pending.per_offset.velocity,
            );
        }
        self.rest = self.size(omega) * REST_FRACTION;
    }

    /// The size of the offset in each unit: how far it is, plus how far its velocity would carry
    /// it in `1/ω` (the spring's time scale), each in the largest of its three axes.
    fn size(&self, omega: f32) -> Vec3 {
        self.offset.position.sizes() + self.offset.velocity.sizes() / omega
    }

    /// Whether every part of the offset is below its rest size (an offset that was zero is done
    /// at once). A non-finite offset is done too: nothing could bring it back.
    fn is_done(&self, omega: f32) -> bool {
        let size = self.size(omega);
        !size.is_finite() || size.cmple(self.rest).all()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sprung::Spring;

    fn pose_at(x: f32) -> Pose {
        Pose {
            translation: Vec3::X * x,
            rotation: Quat::from_rotation_z(x * 0.1),
            scale: Vec3::ONE,
        }
    }

    fn frame(transitions: u32, dt: f32) -> BlendFrame {
        let spring = Spring::<f32>::from_natural_frequency(20.0, 1.0).unwrap();
        BlendFrame {
            transitions,
            step: Some((spring.transition(dt), 20.0)),
            dt,
        }
    }

    #[test]
    fn the_offset_starts_at_the_switch_and_decays_exactly() {
        let dt = 1.0 / 60.0;
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        // Moving at 3 units/s along x.
        for i in 1..=10 {
            joint.advance(pose_at(3.0 * dt * i as f32), &frame(0, dt));
        }
        // Switch to a clip standing at 100: at the switch the offset is 0.5 − 100, moving at
        // 3 units/s, and each frame shows its exact decay.
        let spring = Spring::<f64>::from_natural_frequency(20.0, 1.0).unwrap();
        let start = sprung::SpringState::new(0.5 - 100.0, 3.0);
        for k in 1..=30 {
            let shown = joint.advance(pose_at(100.0), &frame(1, dt));
            let exact = spring
                .transition(f64::from(dt) * f64::from(k))
                .step(start, 0.0)
                .position;
            assert!(
                (f64::from(shown.translation.x) - (100.0 + exact)).abs() < 1e-4,
                "frame {k}: {} vs {}",
                shown.translation.x,
                100.0 + exact
            );
        }
    }

    #[test]
    fn an_offset_decays_to_exactly_the_clip_and_stops() {
        let dt = 1.0 / 60.0;
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        joint.advance(pose_at(0.0), &frame(0, dt));
        joint.advance(pose_at(5.0), &frame(1, dt));
        for _ in 0..240 {
            joint.advance(pose_at(5.0), &frame(1, dt));
        }
        assert!(!joint.is_blending());
        assert_eq!(joint.advance(pose_at(5.0), &frame(1, dt)), pose_at(5.0));
    }

    #[test]
    fn an_instant_switch_shows_the_clip() {
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        let instant = BlendFrame {
            transitions: 1,
            step: None,
            dt: 0.1,
        };
        assert_eq!(joint.advance(pose_at(7.0), &instant), pose_at(7.0));
        assert!(!joint.is_blending());
    }

    #[test]
    fn a_non_finite_clip_pose_passes_through_and_leaves_the_blend() {
        let dt = 1.0 / 60.0;
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        joint.advance(pose_at(4.0), &frame(1, dt));
        let mut bad = pose_at(4.0);
        bad.translation.x = f32::NAN;
        joint.advance(bad, &frame(1, dt));
        let shown = joint.advance(pose_at(4.0), &frame(1, dt));
        assert!(shown.is_finite() && joint.is_blending());
    }
}
