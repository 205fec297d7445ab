//! Inertia: a thrown object, or a panned map, coasting to a stop with no target — the exact
//! exponential decay of a spring without stiffness (react-spring's `decay`), with bounds and
//! snap points shared with [`SpringDrag`](crate::interaction::SpringDrag)'s fling.

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::log::warn_once;
use bevy::prelude::*;
use sprung::Spring;

use crate::spring::{
    PropertySystems, SpringAsleep, SpringMotion, SpringPhase, SpringUpdate,
    add_systems_on_first_use,
};
pub use crate::throw::{DragBounds, Snap, SnapLine};
use crate::transform::{Translation, TranslationSpring};

/// Makes its entity coast when flung: [`fling`](Self::fling) gives it a velocity that decays as
/// `e^(−d·t)` (`d` the [`deceleration`](Self::deceleration)), so it travels exactly
/// `v₀/d` and stops there, `x(t) = x₀ + v₀·(1 − e^(−d·t))/d`, at any frame rate. The motion is
/// the entity's [`TranslationSpring`] with no stiffness and damping `d` (the exact step of the
/// core, [`Spring::new`]`(1, 0, d)`), heading for the place it will stop: it rests there
/// exactly, wakes and sleeps like any spring, and triggers
/// [`SpringSettled`](crate::spring::SpringSettled). When the throw ends (it rests, or
/// something else retargets the spring) the spring gets its own parameters back. An entity
/// without a `TranslationSpring` gets one, resting where it is.
///
/// - **Bounds**: a throw that would stop past the [`bounds`](Self::bounds) decelerates just
///   enough more to stop on the first edge it reaches, so it is never beyond them. One thrown
///   from outside (a drag released past an edge, within its rubber band) springs back inside
///   with [`settle`](Self::settle), keeping its velocity along the edge and inward but not
///   outward: with a settle spring that does not overshoot (the default) it never goes further
///   out than it was let go, so never beyond the rubber band's `give`.
/// - **Snap points**: with a [`Snap`] other than [`Snap::Free`], the throw springs with
///   `settle` and its velocity to the snap point nearest where it would have stopped.
/// - **Drags**: a [`SpringDrag`](crate::interaction::SpringDrag) on an entity with an
///   `Inertia` flings it on release.
///
/// A non-finite velocity is refused with one warning; a deceleration that is not positive
/// and finite is taken as [`Inertia::DEFAULT_DECELERATION`].
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::inertia::{DragBounds, Inertia};
/// use bevy_sprung::prelude::*;
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugins::default()));
/// app.insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(
///     std::time::Duration::from_secs_f64(1.0 / 60.0),
/// ));
/// let puck = app
///     .world_mut()
///     .spawn((Transform::default(), Inertia::new(2.0)))
///     .id();
/// app.update();
/// // Thrown at 300 px/s: it coasts 300 / 2 = 150 px and stops.
/// app.world_mut().get_mut::<Inertia>(puck).unwrap().fling(Vec3::new(300.0, 0.0, 0.0));
/// for _ in 0..900 {
///     app.update();
/// }
/// let x = app.world().get::<Transform>(puck).unwrap().translation.x;
/// assert_eq!(x, 150.0);
/// ```
#[derive(Component, Reflect, Debug, Clone, PartialEq)]
#[component(on_add = Self::on_add)]
#[reflect(Component, Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Inertia {
    /// The rate the velocity decays at, per second: a throw at `v` travels `v / deceleration`.
    /// iOS scroll views decelerate at about 2 ("normal") or 10 ("fast").
    pub deceleration: f32,
    /// A box the throw stops inside.
    pub bounds: Option<DragBounds>,
    /// Where the throw ends: where it stops ([`Snap::Free`], the default), or a snap point
    /// chosen from there.
    pub snap: Snap,
    /// The spring that takes a throw to a snap point, or back inside the bounds.
    /// [`Spring::smooth`] by default.
    pub settle: Spring<f32>,
    /// A velocity to fling with at the next step.
    #[reflect(ignore)]
    #[cfg_attr(feature = "serde", serde(skip))]
    pending: Option<Vec3>,
    /// While thrown: the translation spring's own parameters, given back when the throw ends.
    #[reflect(ignore)]
    #[cfg_attr(feature = "serde", serde(skip))]
    thrown: Option<Thrown>,
}

/// A throw under way.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Thrown {
    /// The translation spring's own parameters.
    own: Spring<f32>,
    /// Where the throw ends.
    target: Vec3,
    /// The coast's deceleration (`None`: a settle spring, which gets there by itself).
    coast: Option<f32>,
}

/// How a throw moves: the spring, the target it heads for, and the velocity it starts with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Throw {
    /// The spring: no stiffness and the deceleration as damping for a coast, the settle spring
    /// for a snap or a return inside.
    pub spring: Spring<f32>,
    /// Where it ends.
    pub target: Vec3,
    /// Its velocity at the start.
    pub velocity: Vec3,
}

impl Inertia {
    /// The deceleration taken for one that is not positive and finite: iOS's "normal", 2 per
    /// second (0.998 per millisecond).
    pub const DEFAULT_DECELERATION: f32 = 2.0;

    /// Coasting with `deceleration` per second, free, without bounds.
    #[must_use]
    pub fn new(deceleration: f32) -> Self {
        Self {
            deceleration,
            bounds: None,
            snap: Snap::Free,
            settle: Spring::smooth(),
            pending: None,
            thrown: None,
        }
    }

    /// The same, stopping inside `bounds`.
    #[must_use]
    pub fn bounded(mut self, bounds: DragBounds) -> Self {
        self.bounds = Some(bounds);
        self
    }

    /// The same, ending on `snap`.
    #[must_use]
    pub fn snapping(mut self, snap: Snap) -> Self {
        self.snap = snap;
        self
    }

    /// The same, settling with `spring`.
    #[must_use]
    pub fn settling_with(mut self, spring: Spring<f32>) -> Self {
        self.settle = spring;
        self
    }

    /// Throws the entity with `velocity` (units per second) from where it is, at the next step
    /// of its translation spring. A non-finite velocity is refused, with one warning.
    pub fn fling(&mut self, velocity: Vec3) {
        if velocity.is_finite() {
            self.pending = Some(velocity);
        } else {
            warn_once!("bevy_sprung: refused an Inertia fling with a non-finite velocity");
        }
    }

    /// The deceleration applied: [`deceleration`](Self::deceleration), or the default where it
    /// is not positive and finite.
    #[must_use]
    pub fn rate(&self) -> f32 {
        if self.deceleration > 0.0 && self.deceleration.is_finite() {
            self.deceleration
        } else {
            Self::DEFAULT_DECELERATION
        }
    }

    /// Where a throw from `position` with `velocity` stops, with no bounds or snap:
    /// `position + velocity / deceleration`.
    #[must_use]
    pub fn rest_position(&self, position: Vec3, velocity: Vec3) -> Vec3 {
        position + velocity / self.rate()
    }

    /// How a throw from `position` with `velocity` moves (see the type's docs): a coast that
    /// stops where it would (on the first edge of the bounds it reaches), or a spring to a
    /// snap point or back inside.
    #[must_use]
    pub fn throw(&self, position: Vec3, velocity: Vec3) -> Throw {
        let rate = self.rate();
        let settle = |target| Throw {
            spring: self.settle,
            target,
            velocity,
        };
        let (rate, projected) = match self.bounds {
            Some(bounds) if bounds.clamp(position) != position => {
                // Thrown from outside (a drag released past an edge): back inside, to where the
                // throw would have led, without going further out than it is.
                let excess = position - bounds.clamp(position);
                let mut inward = velocity;
                for axis in 0..3 {
                    if excess[axis] * velocity[axis] > 0.0 {
                        inward[axis] = 0.0;
                    }
                }
                return Throw {
                    spring: self.settle,
                    target: bounds.clamp(self.rest_position(position, inward)),
                    velocity: inward,
                };
            }
            Some(bounds) => {
                // Stopping on the first edge reached: the throw's reach scaled down by the
                // smallest fraction of it that an axis has room for.
                let reach = velocity / rate;
                let room = bounds.clamp(position + reach) - position;
                let fraction = (0..3)
                    .filter(|&axis| reach[axis] != 0.0)
                    .map(|axis| room[axis] / reach[axis])
                    .fold(1.0_f32, f32::min)
                    .max(0.0);
                if fraction == 0.0 {
                    return settle(position);
                }
                (rate / fraction, position + reach * fraction)
            }
            None => (rate, self.rest_position(position, velocity)),
        };
        match self.snap {
            Snap::Free => Throw {
                spring: coast(rate),
                target: projected,
                velocity,
            },
            ref snap => {
                let (target, _) = snap.choose(projected, position);
                settle(self.bounds.map_or(target, |bounds| bounds.clamp(target)))
            }
        }
    }

    /// The hook: an entity without a translation spring gets one, resting where it is.
    fn on_add(mut world: DeferredWorld, context: HookContext) {
        crate::spring::first_use::<Self>(world.reborrow(), context);
        let entity = context.entity;
        if world.get::<TranslationSpring>(entity).is_some() {
            return;
        }
        let at = world
            .get::<Transform>(entity)
            .map(|transform| transform.translation)
            .filter(|at| at.is_finite())
            .unwrap_or_default();
        let Some(settle) = world.get::<Self>(entity).map(|inertia| inertia.settle) else {
            return;
        };
        world
            .commands()
            .entity(entity)
            .try_insert_if_new(TranslationSpring::new(settle, at));
    }
}

impl Default for Inertia {
    fn default() -> Self {
        Self::new(Self::DEFAULT_DECELERATION)
    }
}

/// A spring with no stiffness and damping `rate` per unit mass: the exact exponential coast.
fn coast(rate: f32) -> Spring<f32> {
    // Positive and finite mass and damping, zero stiffness: always a valid spring.
    Spring::new(1.0, 0.0, rate).unwrap_or_else(|_| Spring::smooth())
}

/// Before the translation springs step: gives a thrown spring its own parameters back once
/// the throw has ended, then applies every pending fling.
fn apply_flings(
    mut flung: Query<(
        &mut Inertia,
        &mut TranslationSpring,
        &SpringMotion<Translation>,
        &Transform,
        Has<SpringAsleep<Translation>>,
    )>,
) {
    for (mut inertia, mut spring, motion, transform, asleep) in &mut flung {
        let inertia = inertia.bypass_change_detection();
        if let Some(thrown) = inertia.thrown
            && (asleep || thrown.is_over(&spring, motion.velocity(), transform.translation))
        {
            spring.set_spring(thrown.own);
            inertia.thrown = None;
        }
        if let Some(velocity) = inertia.pending.take() {
            let _ = inertia.start(transform.translation, velocity, &mut spring);
        }
    }
}

impl Inertia {
    /// Throws `spring`'s entity from `position` with `velocity` now, remembering the spring's
    /// own parameters to give back when the throw ends, and returns the throw. A throw whose
    /// end is not finite (a velocity near `f32::MAX`) is refused, with one warning: the spring
    /// is left as it was.
    pub(crate) fn start(
        &mut self,
        position: Vec3,
        velocity: Vec3,
        spring: &mut TranslationSpring,
    ) -> Throw {
        let throw = self.throw(position, velocity);
        if !(throw.target.is_finite() && throw.velocity.is_finite()) {
            warn_once!("bevy_sprung: refused an Inertia fling that would end out of f32's range");
            return throw;
        }
        let own = self.thrown.map_or(*spring.spring(), |thrown| thrown.own);
        let coast = (throw.spring.stiffness() == 0.0).then(|| throw.spring.damping());
        self.thrown = Some(Thrown {
            own,
            target: throw.target,
            coast,
        });
        spring.set_spring(throw.spring);
        spring.set_target(throw.target);
        spring.set_velocity(throw.velocity);
        throw
    }
}

impl Thrown {
    /// Whether the throw is over before it rests: the spring was retargeted, or a coast was
    /// knocked off its course (its value written, its velocity set), so that it no longer
    /// stops on its target (without stiffness, it never would).
    fn is_over(&self, spring: &TranslationSpring, velocity: Vec3, position: Vec3) -> bool {
        if spring.target() != self.target {
            return true;
        }
        let Some(rate) = self.coast else {
            return false;
        };
        // Where the coast stops from here, against where it should: apart by more than the
        // spring's rest tolerance and rounding at these magnitudes.
        let stops = position + velocity / rate;
        let magnitude = position
            .abs()
            .max_element()
            .max(self.target.abs().max_element());
        let slack = spring.rest().offset + 8.0 * f32::EPSILON * magnitude;
        stops.distance(self.target) > slack
    }
}

/// [`Inertia`] (part of [`SpringPlugins`](crate::SpringPlugins)): its system joins the
/// translation springs' input phase with the first `Inertia`.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringInertiaPlugin;

impl Plugin for SpringInertiaPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<Inertia>()
            .register_type::<Snap>()
            .register_type::<SnapLine>()
            .register_type::<DragBounds>();
        add_systems_on_first_use(
            app,
            &[core::any::TypeId::of::<Inertia>()],
            SpringUpdate,
            |schedule| {
                schedule.add_systems(
                    apply_flings
                        .in_set(PropertySystems::<Translation>::phase(SpringPhase::Input))
                        .run_if(any_with_component::<Inertia>),
                );
            },
        );
    }
}
