//! Squash & stretch along the velocity, volume (or area) preserved.

use bevy::app::AnimationSystems;
use bevy::log::warn_once;
use bevy::prelude::*;
use sprung::Spring;

use crate::clock::SpringTime;
use crate::layers::{LayerSystems, SpringLayers};
use crate::spring::{SpringMotion, SpringSystems, add_systems_on_first_use};
use crate::tracking::{TargetWarped, WorldPositions, take_warp};
use crate::transform::{Scale, Translation, TranslationSpring};

/// What a [`SquashStretch`] keeps while it deforms.
#[derive(Reflect, Debug, Default, Clone, Copy, PartialEq, Eq)]
#[reflect(Debug, Default, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Conserve {
    /// The volume: stretching by `s` along the motion scales the two other axes by `1/√s`
    /// (3D objects).
    #[default]
    Volume,
    /// The area in the local x–y plane: stretching by `s` scales the other in-plane axis by
    /// `1/s`, and z stays (sprites and UI).
    Area,
}

/// Stretches its entity along its velocity and squashes it on impact, keeping its volume (or
/// area), and returns to rest through its own spring: the classic cartoon deformation, as one
/// component.
///
/// The velocity is the entity's [`TranslationSpring`](crate::transform::TranslationSpring)'s
/// (its [`SpringMotion`]'s) when it has one, otherwise how far it moved in the world over the
/// last frame (anything that moves it: physics, a parent),
/// leaving out a teleport (a [`TargetWarped`] on the entity, or a move in one frame further than
/// [`teleport_distance`](Self::teleport_distance), which keeps the last frame's velocity). The
/// stretch it asks for is `1 + stretch_per_speed·speed`, at most `max_stretch`, along the
/// velocity in the entity's local axes; the deformation springs toward that with `spring`, so
/// when the entity stops short (a landing) the spring's momentum carries on into a squash
/// before it settles. [`impact`](Self::impact) squashes it directly.
///
/// The deformation is the logarithm of the scale per local axis, `ℓ`, sprung toward
/// `ℓᵢ = ln(stretch)·(3dᵢ² − 1)/2` (`Volume`) or `ln(stretch)·(2dᵢ² − 1)` (`Area`, in x–y) for
/// the unit direction of motion `d`. It is a layer of the scale (the [`Squash`] layer of the
/// entity's [`SpringLayers<Scale>`](SpringLayers)): the scale shown is the entity's own scale
/// times `exp(ℓ)` per local axis, so it stacks on a [`ScaleSpring`](crate::transform::ScaleSpring),
/// a hover or a punch layer, and gameplay still reads and writes the undeformed scale. Every
/// target and kick has `Σℓᵢ = 0`, and a spring step is linear, so the volume (area) is kept to
/// rounding for any direction, squash or stretch, with a scale that is always positive. At
/// rest it writes nothing.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::juice::Conserve;
///
/// fn spawn(mut commands: Commands) {
///     commands.spawn((
///         Transform::from_xyz(0.0, 300.0, 0.0),
///         // Falls to the floor with a bounce...
///         TranslationSpring::new(Spring::bouncy(), Vec3::ZERO),
///         // ...stretching while it falls (pixels: 0.1% per px/s, at most 1.4×), 2D area kept.
///         SquashStretch::new(0.001, 1.4).conserving(Conserve::Area),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone)]
#[component(on_add = crate::spring::first_use::<SquashStretch>)]
#[require(SpringLayers<Scale>)]
#[reflect(Component, Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SquashStretch {
    /// The stretch per unit of speed: `1 + stretch_per_speed·speed` along the motion.
    pub stretch_per_speed: f32,
    /// The largest stretch from speed (≥ 1); an [`impact`](Self::impact) may go beyond it.
    pub max_stretch: f32,
    /// The spring the deformation follows its target with: underdamped springs overshoot into
    /// a squash when the motion stops. [`Spring::bouncy`] by default.
    pub spring: Spring<f32>,
    /// What the deformation keeps.
    pub conserve: Conserve,
    /// For an entity without a translation spring: a frame in which it moves further than this
    /// (world units) is a teleport, not a frame of enormous speed. Infinite (never) by
    /// default; a [`TargetWarped`] says so explicitly.
    pub teleport_distance: f32,
    #[reflect(ignore)]
    #[cfg_attr(feature = "serde", serde(skip))]
    motion: SquashMotion,
}

/// What a squash carries between frames.
#[derive(Debug, Clone, Copy, Default)]
struct SquashMotion {
    /// The logarithm of the scale per local axis, and its rate.
    stretch: Vec3,
    rate: Vec3,
    /// Where the entity was last frame and how fast it moved, for entities without a
    /// translation spring.
    last_position: Option<Vec3>,
    last_velocity: Vec3,
    /// Explicit warps since the last frame ([`TargetWarped`]), left out of the velocity.
    warp: Vec3,
    /// The deformation rests: nothing to step or write until the entity moves.
    resting: bool,
}

/// Below these the deformation rests: a scale within 1e-5 of its base.
const REST_STRETCH: f32 = 1e-5;
const REST_RATE: f32 = 1e-4;

impl SquashStretch {
    /// Stretch by `stretch_per_speed` per unit of speed, at most by `max_stretch`, conserving
    /// volume, with [`Spring::bouncy`] and a base scale of 1.
    #[must_use]
    pub fn new(stretch_per_speed: f32, max_stretch: f32) -> Self {
        Self {
            stretch_per_speed,
            max_stretch,
            spring: Spring::bouncy(),
            conserve: Conserve::Volume,
            teleport_distance: f32::INFINITY,
            motion: SquashMotion::default(),
        }
    }

    /// The same, treating a move further than `distance` in one frame as a teleport.
    #[must_use]
    pub fn with_teleport_distance(mut self, distance: f32) -> Self {
        self.teleport_distance = distance;
        self
    }

    /// The same, conserving `conserve`.
    #[must_use]
    pub fn conserving(mut self, conserve: Conserve) -> Self {
        self.conserve = conserve;
        self
    }

    /// The same, with `spring` for the deformation.
    #[must_use]
    pub fn with_spring(mut self, spring: Spring<f32>) -> Self {
        self.spring = spring;
        self
    }

    /// An impact along `axis` (local): kicks the deformation so that it peaks at a scale of
    /// `factor` along `axis` (below 1 squashes: a landing is `impact(Vec3::Y, 0.7)`; above 1
    /// stretches), then springs back. A zero or non-finite axis, or a factor that is not
    /// positive and finite, is ignored.
    pub fn impact(&mut self, axis: Vec3, factor: f32) {
        let Some(direction) = axis.try_normalize() else {
            return;
        };
        if !(factor > 0.0 && factor.is_finite()) {
            return;
        }
        let Some(peak) = self.spring.impulse_peak().filter(|peak| *peak > 0.0) else {
            return;
        };
        let swing = logarithms(factor.ln(), direction, self.conserve);
        self.motion.rate += swing / peak;
        self.motion.resting = false;
    }

    /// The deformation's scale factors per local axis (the entity's own scale is multiplied by
    /// them): their product
    /// is 1 (`Volume`), or that of x and y is (`Area`).
    #[must_use]
    pub fn factors(&self) -> Vec3 {
        factors(self.motion.stretch, self.conserve)
    }
}

impl SquashStretch {
    /// The velocity of an entity without a translation spring, now at `position` after a frame
    /// of `dt`: how far it moved, less any teleport.
    fn velocity_from(&mut self, position: Vec3, dt: f32) -> Vec3 {
        let motion = &mut self.motion;
        let last = motion.last_position.replace(position);
        let expected = motion.last_velocity * dt;
        let shift = take_warp(
            &mut motion.warp,
            self.teleport_distance,
            (last, position),
            expected,
        );
        let velocity = last.map_or(Vec3::ZERO, |last| (position - last - shift) / dt);
        motion.last_velocity = velocity;
        velocity
    }

    /// The velocity of an entity moved by its translation spring, now at `position`: the
    /// spring's own. The estimate's history follows along and pending warps are dropped (the
    /// spring's velocity has no teleport in it), so that a spring removed later hands over
    /// without a stale jump.
    fn velocity_of_spring(&mut self, position: Option<Vec3>, velocity: Vec3) -> Vec3 {
        let motion = &mut self.motion;
        motion.last_position = position;
        motion.last_velocity = velocity;
        motion.warp = Vec3::ZERO;
        velocity
    }
}

/// A [`TargetWarped`]: a squashed entity leaves the jump out of its next velocity.
fn note_warps(warped: On<TargetWarped>, mut bodies: Query<&mut SquashStretch>) {
    if let Ok(mut squash) = bodies.get_mut(warped.entity)
        && warped.delta.is_finite()
    {
        squash.bypass_change_detection().motion.warp += warped.delta;
    }
}

/// The per-axis logarithms of a stretch by `e^log` along the unit `direction` (a squash for a
/// negative `log`) that keep the volume (area): they sum to zero.
fn logarithms(log: f32, direction: Vec3, conserve: Conserve) -> Vec3 {
    let d2 = direction * direction;
    match conserve {
        Conserve::Volume => log * (3.0 * d2 - 1.0) * 0.5,
        Conserve::Area => {
            let d2 = d2.truncate() / (d2.x + d2.y).max(f32::MIN_POSITIVE);
            (log * (2.0 * d2 - 1.0)).extend(0.0)
        }
    }
}

/// The scale factors of the per-axis logarithms `stretch`.
fn factors(stretch: Vec3, conserve: Conserve) -> Vec3 {
    match conserve {
        Conserve::Volume => stretch.exp(),
        Conserve::Area => stretch.truncate().exp().extend(1.0),
    }
}

/// The layer of the scale a [`SquashStretch`] writes: the logarithms of its factors.
#[derive(TypePath)]
pub struct Squash;

/// After the springs: steps every deformation toward the stretch its velocity asks for and
/// writes it as the [`Squash`] layer of the scale, on the default spring clock.
fn squash_and_stretch(
    time: SpringTime,
    mut bodies: Query<(
        Entity,
        &mut SquashStretch,
        &mut SpringLayers<Scale>,
        &Transform,
        // The motion of a removed spring stays behind, frozen: only a live one counts.
        Option<(&SpringMotion<Translation>, &TranslationSpring)>,
    )>,
    positions: WorldPositions,
) {
    let dt = time.delta(None);
    if !(dt > 0.0 && dt.is_finite()) {
        return;
    }
    for (entity, mut squash, mut layers, transform, motion) in &mut bodies {
        let squash = squash.bypass_change_detection();
        let velocity = match (motion, positions.of(entity)) {
            (Some((motion, _)), position) => squash.velocity_of_spring(position, motion.velocity()),
            (None, Some(position)) => squash.velocity_from(position, dt),
            (None, None) => Vec3::ZERO,
        };
        let local = transform.rotation.inverse() * velocity;
        let local = match squash.conserve {
            Conserve::Volume => local,
            Conserve::Area => local.with_z(0.0),
        };
        let speed = local.length();
        let stretch = (1.0 + squash.stretch_per_speed * speed).min(squash.max_stretch);
        let goal = if speed > 0.0 && stretch > 1.0 && stretch.is_finite() {
            logarithms(stretch.ln(), local / speed, squash.conserve)
        } else {
            Vec3::ZERO
        };
        let motion = &mut squash.motion;
        if motion.resting && goal == Vec3::ZERO {
            continue;
        }
        // The exact step of the logarithms toward their goal (linear: their sum stays 0).
        let [[f0, f1], [g0, g1]] = squash.spring.transition(dt).matrix();
        let offset = motion.stretch - goal;
        let (stretch, rate) = (
            goal + f0 * offset + f1 * motion.rate,
            g0 * offset + g1 * motion.rate,
        );
        if !(stretch.is_finite() && rate.is_finite()) {
            warn_once!("bevy_sprung: a SquashStretch deformation was not finite; reset");
            *motion = SquashMotion::default();
            continue;
        }
        motion.stretch = stretch;
        motion.rate = rate;
        motion.resting =
            goal == Vec3::ZERO && stretch.length() < REST_STRETCH && rate.length() < REST_RATE;
        if motion.resting {
            motion.stretch = Vec3::ZERO;
            motion.rate = Vec3::ZERO;
        }
        let logarithms = match squash.conserve {
            Conserve::Volume => motion.stretch,
            Conserve::Area => motion.stretch.with_z(0.0),
        };
        if layers.get::<Squash>() != logarithms {
            layers.set::<Squash>(logarithms);
        }
    }
}

/// A squash removed mid-deformation: its layer joins the scale, so that nothing jumps.
fn fold_squash(
    removed: On<Remove, SquashStretch>,
    mut bodies: Query<(&mut SpringLayers<Scale>, &mut Transform)>,
) {
    if let Ok((mut layers, mut transform)) = bodies.get_mut(removed.entity) {
        layers.fold::<Squash>(&mut transform);
    }
}

pub(super) fn build(app: &mut App) {
    app.register_type::<SquashStretch>()
        .register_type::<Conserve>()
        .add_observer(fold_squash)
        .add_observer(note_warps);
    crate::layers::add_layered_property::<Scale>(app);
    // With the first squash and stretch.
    let squashes = [core::any::TypeId::of::<SquashStretch>()];
    add_systems_on_first_use(app, &squashes, PostUpdate, |schedule| {
        schedule.add_systems(
            squash_and_stretch
                .in_set(AnimationSystems)
                .after(SpringSystems)
                .before(LayerSystems)
                .run_if(any_with_component::<SquashStretch>),
        );
    });
}
