//! One joint's inertialization: the poses it showed, and the offset that decays after a switch.

use bevy::prelude::*;
use sprung::SpringState;

use super::pose::{Pose, PoseDelta};
use crate::space::rotation_vector;

/// What a player's joints need this frame: its transition count, where its offsets stand on
/// their decay, and the frame's time.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BlendFrame {
    /// How many transitions the player has started: a joint that has seen fewer starts one.
    pub(crate) transitions: u32,
    /// Where the last transition's offsets stand on their decay (`None`: it was instant, or its
    /// offsets are done).
    pub(crate) decay: Option<Decay>,
    /// This frame's time on the animation's clock, in seconds.
    pub(crate) dt: f32,
}

impl BlendFrame {
    /// A frame in which nothing has been started.
    pub(crate) const IDLE: Self = Self {
        transitions: 0,
        decay: None,
        dt: 0.0,
    };
}

/// The closed-form decay of every offset of one transition at one time after its switch: the
/// offset is `from_offset·x₀ + from_rate·v₀`, for its value `x₀` and rate `v₀` at the switch.
///
/// All the joints of a transition share these two numbers (one spring, one switch time), so a
/// joint's offset costs two multiply-adds per number, and no step accumulates rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Decay {
    pub(crate) from_offset: f32,
    pub(crate) from_rate: f32,
}

/// What inertialization keeps of one joint of a player with an
/// [`Inertialization`](super::Inertialization): the poses it showed in the last two frames (to
/// know where it was heading), the pose the animation gave it, and, while a transition blends,
/// the offset at the switch.
#[derive(Component, Clone, Debug)]
pub(crate) struct InertialJoint {
    /// The pose shown last frame, the one shown the frame before, and the time between them
    /// (zero: no rate known).
    shown: Pose,
    before: Pose,
    step: f32,
    /// The pose the animation gave last frame, before the offset (kept while blending).
    clip: Pose,
    /// The player's transition count this joint has seen.
    transitions: u32,
    /// The offset of the transition in progress.
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
    /// The offset shown − clip and its rate at the switch (without the new clip's part while
    /// that is [`pending`](Self::pending)).
    start: SpringState<PoseDelta>,
    /// The new clip's part of the offset, until the frame after the switch gives its rate.
    pending: Option<PendingSwitch>,
}

/// On the frame of a switch only the new clip's pose at the frame's end is known, not where it
/// stood at the switch nor its rate `w`: it stood `w·dt` back, and the offset moves at the old
/// rate less `w`. So the switch frame shows the offset without them, and the next frame, which
/// gives `w`, puts them into the start.
#[derive(Clone, Copy, Debug)]
struct PendingSwitch {
    /// The rotation shown at the switch, the clip's at the end of the switch's frame, and that
    /// frame's time.
    shown_rotation: Quat,
    clip_rotation: Quat,
    dt: f32,
}

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

    /// The pose the animation gave this frame: `transform`'s, except in the parts that still
    /// show what this joint wrote last frame. No clip animates those (a clip writes its own
    /// pose, which differs from clip + offset), so their clip pose is the last one.
    #[inline]
    pub(crate) fn clip_pose(&self, transform: &Transform) -> Pose {
        let mut clip = Pose::of(transform);
        if self.is_blending() {
            if clip.translation == self.shown.translation {
                clip.translation = self.clip.translation;
            }
            if clip.rotation == self.shown.rotation {
                clip.rotation = self.clip.rotation;
            }
            if clip.scale == self.shown.scale {
                clip.scale = self.clip.scale;
            }
        }
        clip
    }

    /// Drops the blend (the player is gone or no longer inertialized): the clip is shown as it
    /// is.
    pub(crate) fn forget(&mut self) {
        self.blend = None;
    }

    /// Advances the joint by this frame, given the pose the animation gave it (`clip`), and
    /// returns the pose to write if the `Transform` does not show it yet (an offset on the clip,
    /// or the clip once an offset ends).
    #[inline]
    pub(crate) fn advance(&mut self, clip: Pose, frame: &BlendFrame) -> Option<Pose> {
        if self.blend.is_none() && self.transitions == frame.transitions {
            // Nothing blends: only where the joint is heading is kept.
            self.showed(clip, frame.dt);
            return None;
        }
        self.blend_frame(clip, frame)
    }

    /// [`advance`](Self::advance) on a frame that starts, continues or ends a blend.
    ///
    /// A clip pose that is not finite passes through (plus the offset, it stays what it is)
    /// and changes nothing the blend keeps: a start from it is refused, and the new clip's
    /// rate waits for finite poses.
    fn blend_frame(&mut self, clip: Pose, frame: &BlendFrame) -> Option<Pose> {
        let Some(decay) = frame.decay else {
            // An instant switch, or the offsets are done: the clip's pose, written if an offset
            // was (in the parts no clip animates, it is still there).
            self.transitions = frame.transitions;
            self.showed(clip, frame.dt);
            return self.blend.take().map(|_| clip);
        };
        if self.transitions != frame.transitions {
            self.transitions = frame.transitions;
            self.blend = self.start(clip, frame.dt);
        } else if let Some(blend) = &mut self.blend
            && blend.pending.is_some()
            && frame.dt > 0.0
        {
            blend.take_clip_rate(clip.rate_since(&self.clip, frame.dt));
        }
        let shown = self
            .blend
            .as_ref()
            .map(|blend| clip.plus(&blend.offset(decay)));
        self.showed(shown.unwrap_or(clip), frame.dt);
        self.clip = clip;
        shown
    }

    /// Keeps `shown` as the pose shown this frame of `dt` (a frame of no time keeps the rate
    /// known).
    #[inline]
    fn showed(&mut self, shown: Pose, dt: f32) {
        if dt > 0.0 {
            self.before = self.shown;
            self.step = dt;
        }
        self.shown = shown;
    }

    /// A blend from the pose this joint showed last frame, moving at the rate it showed, to
    /// the new clip whose pose at the end of this frame of `dt` is `clip`; none if what was
    /// shown is not finite (a clip wrote it: the joint takes the new clip as it is).
    fn start(&self, clip: Pose, dt: f32) -> Option<JointBlend> {
        let offset = self.shown.minus(&clip);
        let rate = self.shown.rate_since(&self.before, self.step);
        (offset.is_finite() && rate.is_finite()).then_some(JointBlend {
            start: SpringState::new(offset, rate),
            pending: Some(PendingSwitch {
                shown_rotation: self.shown.rotation,
                clip_rotation: clip.rotation,
                dt,
            }),
        })
    }
}

impl JointBlend {
    /// The offset at the time `decay` stands at.
    #[inline]
    fn offset(&self, decay: Decay) -> PoseDelta {
        self.start.position * decay.from_offset + self.start.velocity * decay.from_rate
    }

    /// The new clip's rate `w` is known: the start becomes the offset from where the clip stood
    /// at the switch (`w·dt` back), moving at the old rate less `w`. A rate that is not finite
    /// (a clip pose that is not) leaves it pending.
    fn take_clip_rate(&mut self, clip_rate: PoseDelta) {
        let Some(pending) = self.pending.filter(|_| clip_rate.is_finite()) else {
            return;
        };
        let back = clip_rate * pending.dt;
        // Where the clip's rotation stood at the switch, exactly: rotation vectors about
        // different axes do not add, so the rotation part is taken again rather than added.
        let clip_then = Quat::from_scaled_axis(-back.rotation) * pending.clip_rotation;
        self.start.position = PoseDelta {
            translation: self.start.position.translation + back.translation,
            rotation: rotation_vector(pending.shown_rotation * clip_then.inverse()),
            scale: self.start.position.scale + back.scale,
        };
        self.start.velocity = self.start.velocity - clip_rate;
        self.pending = None;
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

    /// A frame `since` seconds after the switch of transition `transitions`, on a spring of
    /// ω = 20.
    fn frame(transitions: u32, dt: f32, since: f32) -> BlendFrame {
        let spring = Spring::<f32>::from_natural_frequency(20.0, 1.0).unwrap();
        let [[from_offset, from_rate], _] = spring.transition(since).matrix();
        BlendFrame {
            transitions,
            decay: Some(Decay {
                from_offset,
                from_rate,
            }),
            dt,
        }
    }

    fn shown(joint: &mut InertialJoint, clip: Pose, frame: &BlendFrame) -> Pose {
        joint.advance(clip, frame).unwrap_or(clip)
    }

    #[test]
    fn the_offset_starts_at_the_switch_and_decays_exactly() {
        let dt = 1.0 / 60.0;
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        // Moving at 3 units/s along x.
        for i in 1..=10 {
            shown(&mut joint, pose_at(3.0 * dt * i as f32), &frame(0, dt, 1.0));
        }
        // Switch to a clip standing at 100: at the switch the offset is 0.5 − 100, moving at
        // 3 units/s, and each frame shows its exact decay.
        let spring = Spring::<f64>::from_natural_frequency(20.0, 1.0).unwrap();
        let start = sprung::SpringState::new(0.5 - 100.0, 3.0);
        for k in 1..=30 {
            let since = dt * k as f32;
            let shown = shown(&mut joint, pose_at(100.0), &frame(1, dt, since));
            let exact = spring
                .transition(f64::from(since))
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
    fn a_done_decay_shows_exactly_the_clip() {
        let dt = 1.0 / 60.0;
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        shown(&mut joint, pose_at(0.0), &frame(0, dt, 1.0));
        shown(&mut joint, pose_at(5.0), &frame(1, dt, dt));
        assert!(joint.is_blending());
        let done = BlendFrame {
            transitions: 1,
            decay: None,
            dt,
        };
        assert_eq!(joint.advance(pose_at(5.0), &done), Some(pose_at(5.0)));
        assert_eq!(joint.advance(pose_at(5.0), &done), None);
        assert!(!joint.is_blending());
    }

    #[test]
    fn an_instant_switch_shows_the_clip() {
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        let instant = BlendFrame {
            transitions: 1,
            decay: None,
            dt: 0.1,
        };
        assert_eq!(joint.advance(pose_at(7.0), &instant), None);
        assert!(!joint.is_blending());
    }

    #[test]
    fn a_non_finite_clip_pose_passes_through_and_leaves_the_blend() {
        let dt = 1.0 / 60.0;
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        shown(&mut joint, pose_at(4.0), &frame(1, dt, dt));
        let mut bad = pose_at(4.0);
        bad.translation.x = f32::NAN;
        joint.advance(bad, &frame(1, dt, 2.0 * dt));
        let shown = shown(&mut joint, pose_at(4.0), &frame(1, dt, 3.0 * dt));
        assert!(shown.translation.is_finite() && shown.rotation.is_finite() && joint.is_blending());
    }

    #[test]
    fn a_switch_from_a_non_finite_pose_takes_the_clip() {
        let dt = 1.0 / 60.0;
        let mut joint = InertialJoint::at(pose_at(0.0), 0);
        let mut bad = pose_at(1.0);
        bad.rotation.x = f32::NAN;
        // Nothing blends: the clip's pose is kept as shown, whatever it is.
        assert_eq!(joint.advance(bad, &frame(0, dt, 1.0)), None);
        assert_eq!(joint.advance(pose_at(2.0), &frame(1, dt, dt)), None);
        assert!(!joint.is_blending());
    }
}
