//! Transitions computed once per distinct spring and frame.

use sprung::{Spring, Transition};

/// The bits of `(mass, stiffness)` and of `(damping, dt)`: what makes a transition.
type Key = (u64, u64);

/// A few transitions keyed by spring parameters and time step, kept for one batch of entities.
///
/// Entities usually share a handful of springs; each distinct `(spring, dt)` is computed once
/// per batch instead of once per entity, so the per-entity cost is the step itself. The entry
/// used last is checked first, with two 64-bit comparisons: consecutive entities of a batch
/// mostly share their spring.
pub(crate) struct TransitionCache {
    /// The key of each filled entry.
    keys: [Key; Self::SIZE],
    transitions: [Transition<f32>; Self::SIZE],
    /// How many entries are filled.
    len: usize,
    /// The entry to replace next once all are filled.
    next: usize,
    /// The entry that answered last.
    last: usize,
}

impl Default for TransitionCache {
    fn default() -> Self {
        Self {
            keys: [(0, 0); Self::SIZE],
            transitions: [Transition::identity(); Self::SIZE],
            len: 0,
            next: 0,
            last: 0,
        }
    }
}

impl TransitionCache {
    const SIZE: usize = 4;

    /// The transition of `spring` over `dt`, or `None` for parameters that are not a valid
    /// spring (possible through reflection, which bypasses `Spring::new`).
    #[inline]
    pub(crate) fn get(&mut self, spring: &Spring<f32>, dt: f32) -> Option<&Transition<f32>> {
        let key = (
            u64::from(spring.mass().to_bits()) | (u64::from(spring.stiffness().to_bits()) << 32),
            u64::from(spring.damping().to_bits()) | (u64::from(dt.to_bits()) << 32),
        );
        if self.len > 0 && self.keys[self.last] == key {
            return Some(&self.transitions[self.last]);
        }
        self.lookup(spring, dt, key)
    }

    /// [`get`](Self::get) when the last entry does not match: search the others, or compute
    /// and insert.
    #[cold]
    #[inline(never)]
    fn lookup(&mut self, spring: &Spring<f32>, dt: f32, key: Key) -> Option<&Transition<f32>> {
        if let Some(index) = self.keys[..self.len]
            .iter()
            .position(|cached| *cached == key)
        {
            self.last = index;
            return Some(&self.transitions[index]);
        }
        // Reflection can write parameters `Spring::new` would refuse; the step repairs them.
        let valid = Spring::new(spring.mass(), spring.stiffness(), spring.damping()).ok()?;
        let index = if self.len < Self::SIZE {
            self.len += 1;
            self.len - 1
        } else {
            let index = self.next;
            self.next = (self.next + 1) % Self::SIZE;
            index
        };
        self.keys[index] = key;
        self.transitions[index] = valid.transition(dt);
        self.last = index;
        Some(&self.transitions[index])
    }
}
