//! Every distinct spring's transition, kept across frames: what the per-entity step reads.

use bevy::platform::collections::HashMap;
use bevy::tasks::ComputeTaskPool;
use bevy::utils::Parallel;
use sprung::{Spring, Transition};

use crate::clock::FrameSteps;

/// What makes a slot: the bits of the spring's parameters, and the clock index
/// ([`FrameSteps`](crate::clock::FrameSteps)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Key {
    parameters: [u32; 3],
    clock: u8,
}

impl Key {
    #[inline]
    fn new(spring: &Spring<f32>, clock: u8) -> Self {
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

/// The data a transition over a nearby time step is extended from: the Taylor coefficients,
/// at `dt`, of `f1` and of `g0 = ∫f1`, and the spring's rates.
#[derive(Clone, Copy, Debug)]
struct Anchor {
    /// The time step the coefficients are at.
    dt: f32,
    /// `f1⁽ⁿ⁾(dt)/n!` for `n = 0..=4`.
    f1: [f32; 5],
    /// `g0(dt)`: `g0⁽ⁿ⁾ = f1⁽ⁿ⁻¹⁾` for the rest of its series.
    g0: f32,
    /// `ω² = k/m` and `2b = c/m`: `f1'' = −2b·f1' − ω²·f1`.
    omega_squared: f32,
    rate: f32,
    /// The largest `|δ|` the extension is accurate for (below `f32`'s rounding); negative for
    /// no anchor at all.
    reach: f32,
}

/// `(ρ·δ)` up to which the degree-4 Taylor extension stays below `f32`'s unit roundoff: its
/// first omitted term is `(ρδ)⁵/5!` of the leading one.
const TAYLOR_REACH: f32 = 0.03;

impl Anchor {
    /// No anchor: nothing is within its reach.
    const NONE: Self = Self {
        dt: 0.0,
        f1: [0.0; 5],
        g0: 0.0,
        omega_squared: 0.0,
        rate: 0.0,
        reach: -1.0,
    };

    /// The anchor of `spring`'s `transition` over `dt`.
    fn new(spring: &Spring<f32>, dt: f32, transition: &Transition<f32>) -> Self {
        let mass = spring.mass();
        let (omega_squared, rate) = (spring.stiffness() / mass, spring.damping() / mass);
        let [[_, f1], [_, g]] = transition.matrix();
        // ρ ≤ 2b + ω bounds the spectral radius of [[0, 1], [−ω², −2b]].
        let radius = rate + omega_squared.sqrt();
        let reach = if radius > 0.0 {
            TAYLOR_REACH / radius
        } else {
            f32::INFINITY
        };
        // The derivatives from the spring's own equation, computed once here rather than
        // every frame the anchor serves.
        let (w2, d0, d1) = (omega_squared, f1, g);
        let d2 = -rate * d1 - w2 * d0;
        let d3 = -rate * d2 - w2 * d1;
        let d4 = -rate * d3 - w2 * d2;
        Self {
            dt,
            f1: [d0, d1, d2 / 2.0, d3 / 6.0, d4 / 24.0],
            g0: transition.acceleration_gain(),
            omega_squared,
            rate,
            reach: reach.min(0.1 * dt),
        }
    }

    /// The increment matrix over `dt`, if within reach: `f1` and `g0` continued by their Taylor
    /// series in `δ = dt − anchor` (Horner), and
    /// `D = [[−ω²·g0, f1], [−ω²·f1, −(ω²·g0 + 2b·f1)]]`: every entry a sum of terms of one sign
    /// at small `δ`, so nothing cancels (`D₁₁` is not formed as `g − 1`).
    #[inline]
    fn increments(&self, dt: f32) -> Option<[f32; 4]> {
        let h = dt - self.dt;
        // NaN-safe: a NaN or infinite delta is not within reach, nor anything of `NONE`.
        let within = h.abs() <= self.reach;
        if !within {
            return None;
        }
        let [c0, c1, c2, c3, c4] = self.f1;
        let f1 = c0 + h * (c1 + h * (c2 + h * (c3 + h * c4)));
        // g0(dt + h) = g0 + Σ f1⁽ⁿ⁾·hⁿ⁺¹/(n+1)!: the same coefficients over n + 1.
        let g0 = self.g0
            + h * (c0
                + h * (c1 / 2.0
                    + h * (c2 * (1.0 / 3.0) + h * (c3 / 4.0 + h * (c4 * (1.0 / 5.0))))));
        let w2 = self.omega_squared;
        let w2g0 = w2 * g0;
        Some([-w2g0, f1, -(w2 * f1), -(w2g0 + self.rate * f1)])
    }
}

/// One distinct spring (and clock): what its transitions are computed from. Read while
/// preparing a frame, written only when a transition is computed exactly.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Slot {
    key: Key,
    /// The spring the key stands for (validated when the slot was made).
    spring: Spring<f32>,
    anchor: Anchor,
}

/// A slot's transition for the current time step: what the per-entity step reads, kept apart
/// from the slots (24 bytes against 68) so that the step and the frame's preparation stream no
/// more than they use, and preparing dirties no slot.
#[derive(Clone, Copy, Debug)]
struct Prepared {
    /// `D = M − I` over `dt`, row-major.
    increments: [f32; 4],
    /// The time step `increments` is for (NaN: none yet).
    dt: f32,
    /// The slot's clock index ([`FrameSteps`]).
    clock: u8,
}

impl Slot {
    /// Makes `prepared`'s increments those over `dt`, if they are for another time step:
    /// extended from the anchor when it is close (inline: a game's time step changes every
    /// frame, and this is a few multiply-adds), otherwise computed exactly (and anchored there).
    #[inline]
    fn prepare(&mut self, prepared: &mut Prepared, dt: f32) {
        #[expect(
            clippy::float_cmp,
            reason = "the increments are for exactly this time step, bit for bit"
        )]
        if prepared.dt != dt {
            match self.anchor.increments(dt) {
                Some(increments) => prepared.increments = increments,
                None => self.recompute(prepared, dt),
            }
            prepared.dt = dt;
        }
    }

    /// The increments over `dt` computed exactly, and the anchor moved there.
    #[cold]
    #[inline(never)]
    fn recompute(&mut self, prepared: &mut Prepared, dt: f32) {
        let spring = self.spring;
        let transition = spring.transition(dt);
        let [[d00, d01], [d10, d11]] = transition.increment_matrix();
        prepared.increments = [d00, d01, d10, d11];
        self.anchor = Anchor::new(&spring, dt, &transition);
    }
}

/// The slots of every distinct `(spring, clock)` of one property, kept by its stepping system
/// across frames. A spring remembers its slot's index (and the table's generation), so that
/// while nothing touches it, finding its transition is one indexed load, however many springs
/// the scene has: one shared spring, a handful, or one per entity.
///
/// A frame goes: [`prepare`](Self::prepare) makes every slot's increments those of this
/// frame's time steps (in parallel when the compute pool has threads to spare); the springs
/// step, reading the table only (so that they can step in parallel), and a spring whose
/// parameters have no slot yet [`request`](Self::request)s one and steps the general way;
/// [`finish`](Self::finish) adds the requested slots and collects the table.
///
/// Slots are added when a spring first needs one and never move; when the table has far more
/// slots than springs (springs despawned or changed), it is cleared and its generation advances,
/// so every spring finds (or makes) its slot again.
#[derive(Default)]
pub(crate) struct TransitionTable {
    slots: Vec<Slot>,
    /// Each slot's transition for this frame, by the same index.
    prepared: Vec<Prepared>,
    index: HashMap<Key, u32>,
    generation: u32,
    /// Slots springs asked for this frame, per thread.
    requests: Parallel<Vec<(Key, Spring<f32>)>>,
}

/// The threads of Bevy's compute pool (1 before it is made): whether work is worth splitting.
pub(crate) fn compute_threads() -> usize {
    ComputeTaskPool::try_get().map_or(1, |pool| pool.thread_num())
}

/// Slots per parallel task when preparing: enough work to outweigh handing it out.
const PREPARE_CHUNK: usize = 4096;

impl TransitionTable {
    /// A generation no table is ever in: what a spring without a slot remembers (generations
    /// are even).
    pub(crate) const NO_GENERATION: u32 = 1;

    /// The generation the table is in: a spring's slot index is valid only in its generation.
    #[inline]
    pub(crate) fn generation(&self) -> u32 {
        self.generation
    }

    /// Makes every slot's increments those over its clock's time step in `steps`. A frame with
    /// the same time steps as the last costs one comparison per slot; with new ones (Bevy's
    /// virtual time varies from frame to frame), each slot is extended or recomputed, split
    /// over the compute pool's threads when it has more than one.
    pub(crate) fn prepare(&mut self, steps: FrameSteps) {
        // The steps copied into the closure: captured by reference, a slot cost 4 instructions
        // more (callgrind) where the closure was not inlined.
        let prepare = move |slots: &mut [Slot], prepared: &mut [Prepared]| {
            for (slot, prepared) in slots.iter_mut().zip(prepared) {
                // The clock from `prepared`: a frame with the same steps reads nothing else.
                let dt = steps.of(prepared.clock);
                slot.prepare(prepared, dt);
            }
        };
        if compute_threads() > 1 && self.slots.len() > PREPARE_CHUNK {
            ComputeTaskPool::get().scope(|scope| {
                let chunks = self
                    .slots
                    .chunks_mut(PREPARE_CHUNK)
                    .zip(self.prepared.chunks_mut(PREPARE_CHUNK));
                for (slots, prepared) in chunks {
                    scope.spawn(async move { prepare(slots, prepared) });
                }
            });
        } else {
            prepare(&mut self.slots, &mut self.prepared);
        }
    }

    /// The increments of slot `index` (prepared for this frame), from a spring that remembered
    /// it in this generation.
    #[inline]
    pub(crate) fn increments(&self, index: u32) -> Option<[f32; 4]> {
        self.prepared
            .get(index as usize)
            .map(|prepared| prepared.increments)
    }

    /// The index of the slot of `spring` on clock `clock`, if the table has one.
    #[inline]
    pub(crate) fn lookup(&self, spring: &Spring<f32>, clock: u8) -> Option<u32> {
        self.index.get(&Key::new(spring, clock)).copied()
    }

    /// Asks for a slot for `spring` on clock `clock`, added when the frame
    /// [`finish`](Self::finish)es: from the next frame on, the spring finds it.
    #[cold]
    pub(crate) fn request(&self, spring: &Spring<f32>, clock: u8) {
        self.requests
            .borrow_local_mut()
            .push((Key::new(spring, clock), *spring));
    }

    /// After a frame that stepped `springs` springs: adds the slots requested (for parameters
    /// that are a valid spring; reflection can write others), then clears the table when it
    /// holds more than twice as many slots as there are springs (and a few more), so that
    /// springs despawned or changed do not keep slots for ever.
    pub(crate) fn finish(&mut self, springs: usize) {
        let mut requests = core::mem::take(&mut self.requests);
        for (key, spring) in requests.iter_mut().flat_map(|requests| requests.drain(..)) {
            if self.index.contains_key(&key)
                || Spring::new(spring.mass(), spring.stiffness(), spring.damping()).is_err()
            {
                continue;
            }
            let Ok(index) = u32::try_from(self.slots.len()) else {
                break;
            };
            self.slots.push(Slot {
                key,
                spring,
                anchor: Anchor::NONE,
            });
            self.prepared.push(Prepared {
                increments: [0.0; 4],
                dt: f32::NAN,
                clock: key.clock,
            });
            self.index.insert(key, index);
        }
        // The per-thread buffers keep their capacity for the next frame.
        self.requests = requests;
        if self.slots.len() > 2 * springs + 64 {
            self.slots.clear();
            self.prepared.clear();
            self.index.clear();
            self.generation = self.generation.wrapping_add(2);
        }
    }

    /// The parameters of slot `index` in `generation`, if that is this table's: the last valid
    /// parameters of the spring that remembers it.
    pub(crate) fn parameters(&self, index: u32, generation: u32) -> Option<Spring<f32>> {
        self.slots
            .get(index as usize)
            .filter(|_| generation == self.generation)
            .map(|slot| slot.spring)
    }

    /// Whether `spring` is what slot `index` was made for (after it was touched).
    #[inline]
    pub(crate) fn holds(&self, index: u32, spring: &Spring<f32>, clock: u8) -> bool {
        self.slots
            .get(index as usize)
            .is_some_and(|slot| slot.key == Key::new(spring, clock))
    }
}

#[cfg(test)]
mod tests {
    use super::Anchor;
    use sprung::Spring;

    /// The worst error of an extended increment matrix against the exact one (computed in
    /// `f64` for the same `f32` parameters), in units of `f32`'s roundoff relative to each
    /// entry: over springs from nearly undamped to heavily over-damped, slow to stiff, at frame
    /// rates from 30 to 360 fps, and time steps across the anchor's reach on both sides.
    fn worst_extension_error() -> f64 {
        let unit = f64::from(f32::EPSILON) / 2.0;
        let mut worst = 0.0_f64;
        for omega in [0.1_f32, 1.0, 8.0, 40.0, 300.0, 2000.0] {
            for zeta in [0.02_f32, 0.3, 1.0, 1.0001, 4.0, 60.0] {
                let spring = Spring::from_natural_frequency(omega, zeta).unwrap();
                let exact = Spring::<f64>::from(spring);
                for fps in [30.0_f32, 60.0, 144.0, 360.0] {
                    let dt = 1.0 / fps;
                    let anchor = Anchor::new(&spring, dt, &spring.transition(dt));
                    assert!(anchor.reach > 0.0);
                    for fraction in [-0.99_f32, -0.5, -0.01, 0.01, 0.5, 0.99] {
                        let step = dt + fraction * anchor.reach;
                        let extended = anchor.increments(step).unwrap();
                        let [[e00, e01], [e10, e11]] =
                            exact.transition(f64::from(step)).increment_matrix();
                        for (got, want) in extended.into_iter().zip([e00, e01, e10, e11]) {
                            let error = (f64::from(got) - want).abs() / (unit * want.abs());
                            worst = worst.max(error);
                        }
                    }
                }
            }
        }
        worst
    }

    /// The extension is as accurate as an exactly computed `f32` transition (a few `u` per
    /// entry; every entry is a sum of terms of one sign, so relative error is the measure).
    #[test]
    fn an_extended_transition_is_accurate_to_a_few_roundoffs() {
        let worst = worst_extension_error();
        println!("worst extension error: {worst:.2} u");
        assert!(worst < 8.0, "{worst} u");
    }

    /// Out of reach, and for no anchor at all, there is no extension (a NaN step included).
    #[test]
    fn nothing_is_extended_out_of_reach() {
        let spring = Spring::from_natural_frequency(10.0, 0.5).unwrap();
        let dt = 1.0 / 60.0;
        let anchor = Anchor::new(&spring, dt, &spring.transition(dt));
        assert!(anchor.increments(dt + 1.01 * anchor.reach).is_none());
        assert!(anchor.increments(dt - 1.01 * anchor.reach).is_none());
        assert!(anchor.increments(f32::NAN).is_none());
        assert!(anchor.increments(f32::INFINITY).is_none());
        assert!(Anchor::NONE.increments(0.0).is_none());
        assert!(Anchor::NONE.increments(1.0 / 60.0).is_none());
    }
}
