//! A slot of the table: one distinct spring and clock, and the key it is found by.

use sprung::Spring;

/// What makes a slot: the bits of the spring's parameters, and the clock index
/// ([`FrameSteps`](crate::clock::FrameSteps)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) struct Key {
    parameters: [u32; 3],
    pub(super) clock: u8,
}

impl Key {
    #[inline]
    pub(super) fn new(spring: &Spring<f32>, clock: u8) -> Self {
        Self {
            parameters: [
                spring.mass().to_bits(),
                spring.stiffness().to_bits(),
                spring.damping().to_bits(),
            ],
            clock,
        }
    }
}

/// One distinct spring (and clock): what its transitions are computed exactly from, when its
/// anchor does not reach the frame's time step.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Slot {
    /// What the slot is found by.
    pub(super) key: Key,
    /// The spring the key stands for (validated when the slot was made).
    pub(super) spring: Spring<f32>,
}
