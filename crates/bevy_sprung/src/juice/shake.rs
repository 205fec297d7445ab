//! Shake: seeded noise, filtered through a spring, scaled by a decaying trauma.

use bevy::log::warn_once;
use bevy::prelude::*;
use sprung::Spring;

use crate::clock::SpringTime;
use crate::spring::add_systems_on_first_use;

/// The juice systems that write `Transform`s: in `PostUpdate`, after the springs and their
/// layers (`AnimationSystems`) and before transform propagation, the [`Shake`]s are added.
/// (A shake is taken off again in `PreUpdate`, before the layers.)
/// [`SquashStretch`](super::SquashStretch) is a layer: it runs before
/// [`LayerSystems`](crate::layers::LayerSystems).
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct JuiceSystems;

/// Three translation and three rotation channels.
const CHANNELS: usize = 6;

/// A hitch longer than this many noise samples skips ahead: the filter forgets its past within
/// a sample or two, so only the last ones shape the shake.
const MAX_SAMPLES_PER_FRAME: u64 = 64;

/// Shakes its entity — a camera, a hit character, a UI panel's `Transform` — by an offset and a
/// tilt that follow seeded noise, filtered through a critically damped spring and scaled by
/// `trauma²`, while `trauma` decays linearly (Squirrel Eiserloh's "trauma" model, with a spring
/// instead of Perlin noise).
///
/// - **Deterministic and frame-rate independent**: the noise holds a seeded random value per
///   channel for each `1/frequency` s, and the filter spring is stepped exactly, split at the
///   sample boundaries; the shake at a given time is the same at 30 and at 240 fps (up to
///   rounding) and the same for the same `seed` and trauma.
/// - **Bounded**: a critically damped filter never overshoots, so the offset stays within
///   `max_translation·trauma²` and the tilt within `max_rotation·trauma²`.
/// - **On top of everything else**: the shake is added in `PostUpdate` after the springs and
///   taken off again in `PreUpdate`, so gameplay, [`SpringFollow`](crate::follow::SpringFollow)
///   and the entity's own springs see and move the unshaken `Transform`, and the shake never
///   feeds back into them. The offset is in the entity's local axes (a camera shakes along its
///   own right and up).
/// - **Free when calm**: at zero trauma nothing is stepped or written.
///
/// On a camera, picking in `PreUpdate` still sees last frame's shaken `GlobalTransform` (what
/// the player saw): a pointer held still over a shaking view moves in the world by the shake.
///
/// A non-finite `trauma` (through reflection) is taken as 0, with one warning.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// fn spawn(mut commands: Commands) {
///     commands.spawn((
///         Transform::default(),
///         // Up to 12 units sideways and 0.05 rad of roll at full trauma.
///         Shake::new(7)
///             .with_max_translation(Vec3::new(12.0, 12.0, 0.0))
///             .with_max_rotation(Vec3::new(0.0, 0.0, 0.05)),
///     ));
/// }
///
/// fn on_explosion(mut cameras: Query<&mut Shake>) {
///     for mut shake in &mut cameras {
///         shake.add_trauma(0.6);
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn).add_systems(Update, on_explosion);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone)]
#[component(on_add = crate::spring::first_use::<Shake>)]
#[reflect(Component, Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Shake {
    /// How shaken, from 0 (still) to 1; the motion scales with its square. Add to it with
    /// [`add_trauma`](Self::add_trauma).
    pub trauma: f32,
    /// How much trauma is lost per second (linearly): 1 by default, so a full shake lasts 1 s.
    pub decay: f32,
    /// The largest offset, per local axis, at full trauma.
    pub max_translation: Vec3,
    /// The largest tilt about each local axis, in radians, at full trauma.
    pub max_rotation: Vec3,
    /// New noise values per second: 15 by default. The filter spring's natural frequency is
    /// `π·frequency` rad/s, so it follows each value closely but rounds off its corners.
    pub frequency: f32,
    /// The noise's seed: the same seed gives the same shake.
    pub seed: u64,
    #[reflect(ignore)]
    #[cfg_attr(feature = "serde", serde(skip))]
    motion: ShakeMotion,
}

/// What a shake carries between frames.
#[derive(Debug, Clone, Copy, Default)]
struct ShakeMotion {
    /// The noise sample being played.
    sample: u64,
    /// Seconds into that sample.
    phase: f64,
    /// The filter's state per channel, in units of the noise (within [−1, 1]).
    position: [f32; CHANNELS],
    velocity: [f32; CHANNELS],
    /// What this frame's shake changed, to take it off again.
    applied: Option<Applied>,
}

/// The translation and rotation before and after a shake was added.
#[derive(Debug, Clone, Copy)]
struct Applied {
    base: (Vec3, Quat),
    shaken: (Vec3, Quat),
}

impl Default for Shake {
    fn default() -> Self {
        Self::new(0)
    }
}

impl Shake {
    /// A calm shake (no trauma, no amplitude yet) with noise seed `seed`, a decay of 1 per
    /// second and 15 noise values per second. Give it amplitudes with
    /// [`with_max_translation`](Self::with_max_translation) and
    /// [`with_max_rotation`](Self::with_max_rotation).
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self {
            trauma: 0.0,
            decay: 1.0,
            max_translation: Vec3::ZERO,
            max_rotation: Vec3::ZERO,
            frequency: 15.0,
            seed,
            motion: ShakeMotion::default(),
        }
    }

    /// The same shake with `max` as the largest offset per local axis at full trauma.
    #[must_use]
    pub fn with_max_translation(mut self, max: Vec3) -> Self {
        self.max_translation = max;
        self
    }

    /// The same shake with `max` as the largest tilt about each local axis (radians) at full
    /// trauma.
    #[must_use]
    pub fn with_max_rotation(mut self, max: Vec3) -> Self {
        self.max_rotation = max;
        self
    }

    /// The same shake losing `decay` trauma per second.
    #[must_use]
    pub fn with_decay(mut self, decay: f32) -> Self {
        self.decay = decay;
        self
    }

    /// The same shake with `frequency` new noise values per second.
    #[must_use]
    pub fn with_frequency(mut self, frequency: f32) -> Self {
        self.frequency = frequency;
        self
    }

    /// Adds `amount` of trauma (a hit 0.3, an explosion 0.8), keeping the total in `[0, 1]`.
    /// A non-finite `amount` is ignored.
    #[inline]
    pub fn add_trauma(&mut self, amount: f32) {
        if amount.is_finite() {
            self.trauma = (self.trauma + amount).clamp(0.0, 1.0);
        }
    }

    /// The offset (in the entity's local axes) and tilt the shake adds this frame.
    #[must_use]
    pub fn current(&self) -> (Vec3, Quat) {
        let [tx, ty, tz, rx, ry, rz] = self.motion.position;
        let gain = self.trauma * self.trauma;
        let translation = self.max_translation * Vec3::new(tx, ty, tz) * gain;
        let tilt = self.max_rotation * Vec3::new(rx, ry, rz) * gain;
        (translation, Quat::from_scaled_axis(tilt))
    }

    /// Advances the noise and its filter by `dt` seconds and the trauma's decay.
    fn advance(&mut self, dt: f32) {
        if !self.trauma.is_finite() {
            warn_once!(
                "bevy_sprung: a Shake's trauma was not finite ({}); set to 0",
                self.trauma
            );
            self.trauma = 0.0;
        }
        self.trauma = self.trauma.clamp(0.0, 1.0);
        let frequency = f64::from(self.frequency);
        let filter = if frequency > 0.0 && frequency.is_finite() {
            Spring::<f32>::from_natural_frequency(core::f32::consts::PI * self.frequency, 1.0).ok()
        } else {
            None
        };
        let (Some(filter), true) = (filter, dt > 0.0 && dt.is_finite()) else {
            if !(frequency > 0.0 && frequency.is_finite()) {
                warn_once!("bevy_sprung: a Shake's frequency is not positive ({frequency})");
            }
            return;
        };
        let period = frequency.recip();
        let mut remaining = f64::from(dt);
        // After a long hitch, play only the last samples (the filter has forgotten the rest).
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a non-negative count of samples; a huge one saturates, and is skipped"
        )]
        let skip = (remaining / period).floor() as u64;
        if skip > MAX_SAMPLES_PER_FRAME {
            let skipped = skip - MAX_SAMPLES_PER_FRAME;
            self.motion.sample = self.motion.sample.wrapping_add(skipped);
            remaining -= skipped as f64 * period;
        }
        let motion = &mut self.motion;
        while remaining > 0.0 {
            let step = (period - motion.phase).min(remaining);
            // Exact for a target held over the step: the same motion however frames split it.
            #[expect(
                clippy::cast_possible_truncation,
                reason = "a sub-step of at most one frame, as an f32 time step"
            )]
            let [[f0, f1], [g0, g1]] = filter.transition(step as f32).matrix();
            for channel in 0..CHANNELS {
                let target = noise(self.seed, motion.sample, channel as u64);
                let offset = motion.position[channel] - target;
                let velocity = motion.velocity[channel];
                motion.position[channel] = target + f0 * offset + f1 * velocity;
                motion.velocity[channel] = g0 * offset + g1 * velocity;
            }
            remaining -= step;
            motion.phase += step;
            // A boundary met to rounding starts the next sample.
            if motion.phase >= period * (1.0 - 1e-9) {
                motion.sample = motion.sample.wrapping_add(1);
                motion.phase = 0.0;
            }
        }
        self.trauma = (self.trauma - self.decay.max(0.0) * dt).max(0.0);
        if self.trauma == 0.0 {
            // Calm again: the next shake starts from still.
            self.motion.position = [0.0; CHANNELS];
            self.motion.velocity = [0.0; CHANNELS];
        }
    }
}

/// A uniform value in [−1, 1] for each (seed, sample, channel): `SplitMix64`'s finaliser over
/// the three mixed together. A hash, not a generator, so any sample is found without replaying
/// the ones before it (five lines, where a noise crate would add a dependency for one function).
fn noise(seed: u64, sample: u64, channel: u64) -> f32 {
    let mut z = seed
        ^ sample.wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ channel.wrapping_mul(0xD1B5_4A32_D192_ED03);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    // The top 24 bits, exactly representable, mapped onto [−1, 1].
    let unit = (z >> 40) as f32 / ((1u32 << 24) - 1) as f32;
    2.0 * unit - 1.0
}

/// `PreUpdate`: takes last frame's shake off. Where nothing else wrote the `Transform` since,
/// the unshaken values come back bit for bit; otherwise the shake is subtracted from what was
/// written.
fn take_off_shakes(mut shakes: Query<(&mut Shake, &mut Transform)>) {
    for (mut shake, mut transform) in &mut shakes {
        let Some(applied) = shake.bypass_change_detection().motion.applied.take() else {
            continue;
        };
        take_off(applied, &mut transform);
    }
}

fn take_off(applied: Applied, transform: &mut Transform) {
    let Applied { base, shaken } = applied;
    if transform.translation == shaken.0 {
        transform.translation = base.0;
    } else {
        transform.translation -= shaken.0 - base.0;
    }
    if transform.rotation == shaken.1 {
        transform.rotation = base.1;
    } else {
        let tilt = base.1.inverse() * shaken.1;
        let rotation = (transform.rotation * tilt.inverse()).normalize();
        // A tilt that is not a rotation (the shake was added to one that is not) cannot be
        // taken off: what was written is kept.
        if rotation.is_finite() {
            transform.rotation = rotation;
        }
    }
}

/// `PostUpdate`: advances every shaking entity's shake (on the default spring clock) and adds
/// it to its `Transform`.
pub(super) fn add_shakes(time: SpringTime, mut shakes: Query<(&mut Shake, &mut Transform)>) {
    let dt = time.delta(None);
    for (mut shake, mut transform) in &mut shakes {
        if shake.trauma == 0.0 && shake.motion.applied.is_none() {
            continue;
        }
        let shake = shake.bypass_change_detection();
        if let Some(applied) = shake.motion.applied.take() {
            take_off(applied, &mut transform);
        }
        shake.advance(dt);
        if shake.trauma == 0.0 {
            continue;
        }
        let (offset, tilt) = shake.current();
        if !(offset.is_finite() && tilt.is_finite()) {
            warn_once!("bevy_sprung: a Shake's amplitudes are not finite; not applied");
            continue;
        }
        let base = (transform.translation, transform.rotation);
        let shaken = (base.0 + base.1 * offset, base.1 * tilt);
        // A rotation that is not a unit quaternion (written by something else) can carry the
        // offset out of `f32`: a shake is never what makes a `Transform` non-finite.
        if !(shaken.0.is_finite() && shaken.1.is_finite()) {
            warn_once!(
                "bevy_sprung: a Shake on a Transform whose rotation is not a unit quaternion; not \
                 applied"
            );
            continue;
        }
        (transform.translation, transform.rotation) = shaken;
        shake.motion.applied = Some(Applied { base, shaken });
    }
}

pub(super) fn build(app: &mut App) {
    app.register_type::<Shake>();
    // With the first shake.
    let shakes = [core::any::TypeId::of::<Shake>()];
    add_systems_on_first_use(app, &shakes, PreUpdate, |schedule| {
        schedule.add_systems(
            take_off_shakes
                .before(crate::layers::LayerSystems)
                .run_if(any_with_component::<Shake>),
        );
    });
    add_systems_on_first_use(app, &shakes, PostUpdate, |schedule| {
        schedule.add_systems(
            add_shakes
                .in_set(JuiceSystems)
                .run_if(any_with_component::<Shake>),
        );
    });
}

#[cfg(test)]
#[expect(clippy::float_cmp, reason = "the same inputs give the same bits")]
mod tests {
    use super::*;

    #[test]
    fn noise_is_uniform_in_range_and_seeded() {
        let values: Vec<f32> = (0..100_000).map(|i| noise(3, i, i % 6)).collect();
        assert!(values.iter().all(|v| (-1.0..=1.0).contains(v)));
        let mean = values.iter().sum::<f32>() / values.len() as f32;
        assert!(mean.abs() < 0.01, "mean {mean}");
        assert_ne!(noise(3, 5, 0), noise(4, 5, 0));
        assert_ne!(noise(3, 5, 0), noise(3, 5, 1));
        assert_eq!(noise(3, 5, 0), noise(3, 5, 0));
    }
}
