//! A spring's motion: [`SpringMotion`], what the step carries from frame to frame, and what it
//! tells of the value it last put on the property. The kernel (`spring::kernel`) steps it.

use core::fmt;

use bevy::math::{NormedVectorSpace, VectorSpace};
use bevy::prelude::*;
use sprung::RestThreshold;

use super::ticket::SlotTicket;
use crate::property::{OffsetOf, SpringProperty, ValueOf, VelocityOf};
use crate::space::FastPath;
use crate::space::{Carried, SpringSpace};

/// The motion of the spring on property `P`: its velocity, and the state it carries from frame
/// to frame. Every [`PropertySpring<P>`](crate::spring::PropertySpring) has one (a required component), which the plugin
/// steps; the spring's configuration is not read while nothing changes it.
///
/// Configuration and motion live in two components so that the per-frame step streams only
/// what moves (80 bytes for a translation) and not the parameters, tolerances and clock
/// beside it. Set or kick the velocity through the spring
/// ([`PropertySpring::set_velocity`](crate::spring::PropertySpring::set_velocity),
/// [`add_impulse`](crate::spring::PropertySpring::add_impulse)): the
/// change applies at its next step.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::spring::SpringMotion;
///
/// // A squash that follows how fast each sprung entity moves.
/// fn speeds(springs: Query<&SpringMotion<Translation>>) {
///     for motion in &springs {
///         let _speed = motion.velocity().length();
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Update, speeds);
/// # app.world_mut().spawn((Transform::default(), TranslationSpring::new(Spring::bouncy(), Vec3::X)));
/// # app.update();
/// ```
#[derive(Component, Reflect)]
#[reflect(Component, Default, Debug, Clone)]
#[repr(C)]
pub struct SpringMotion<P: SpringProperty> {
    /// The offset of the value from `active_target` after the last step, with the digits the
    /// value itself cannot hold, and those the offset cannot.
    #[reflect(ignore)]
    pub(in crate::spring) offset: Carried<OffsetOf<P>>,
    /// The velocity in the offset's space: right after the offset (the last field of
    /// [`Carried`]; the fields are in declared order), so that a `Vec2` spring's state
    /// `[offset, velocity]` is one 16-byte load.
    pub(in crate::spring) velocity: OffsetOf<P>,
    /// The target the spring moved toward in its last step: a `target` that differs was set
    /// since (a retarget), and a hidden spring catches up under this one first. While nothing
    /// but the stepping system touches the spring, it is the spring's target.
    #[reflect(ignore)]
    pub(in crate::spring) active_target: ValueOf<P>,
    /// The squared offset and speed tolerances as applied at `active_target` (raised to what
    /// `f32` resolves there): the rest test is two comparisons.
    #[reflect(ignore)]
    pub(in crate::spring) rest_squared: (f32, f32),
    /// The ticket of the spring's slot in its property's transition table (see
    /// [`ticket`](Self::ticket)), or where it has none, the time not yet simulated while hidden
    /// (see [`pending`](Self::pending)). While nothing but the stepping system touches the
    /// spring, its transition is one indexed load.
    #[reflect(ignore)]
    pub(in crate::spring) ticket: SlotTicket,
}

impl<P: SpringProperty> Default for SpringMotion<P> {
    fn default() -> Self {
        Self::toward(ValueOf::<P>::default(), P::DEFAULT_REST)
    }
}

impl<P: SpringProperty> SpringMotion<P> {
    /// At rest toward `target`, with tolerances `rest`.
    pub(crate) fn toward(target: ValueOf<P>, rest: RestThreshold<f32>) -> Self {
        Self {
            velocity: OffsetOf::<P>::ZERO,
            active_target: target,
            offset: Carried::new(OffsetOf::<P>::ZERO),
            rest_squared: rest_squared::<P>(rest, target),
            ticket: SlotTicket::pending(0.0),
        }
    }

    /// The velocity in the spring's space (units per second; for a rotation, the rate of the
    /// rotation vector relative to the target, in rad/s), as of the spring's last step. A
    /// velocity set or kicked since applies at the next step.
    #[inline]
    #[must_use]
    pub fn velocity(&self) -> VelocityOf<P> {
        self.velocity.into()
    }

    /// Whether the spring, heading for `target`, is within `distance` of it and slow enough not
    /// to leave it again: the length of its offset at most `distance`, its speed at most
    /// `distance × omega` (its natural frequency). A spring heading elsewhere is not.
    #[inline]
    pub(crate) fn is_within(&self, target: ValueOf<P>, distance: f32, omega: f32) -> bool {
        let reach = distance * distance;
        self.active_target == target
            && self.offset.offset.norm_squared() <= reach
            && self.velocity.norm_squared() <= reach * omega * omega
    }

    /// Whether the property's `current` value is the one this motion put there: the target
    /// it snapped to when it came to rest, or what its last step wrote (a spring put to sleep
    /// by hand mid-flight). Something else wrote any other value.
    #[inline]
    pub(crate) fn holds(&self, current: ValueOf<P>) -> bool {
        let zero = OffsetOf::<P>::ZERO;
        if self.offset.offset == zero && self.offset.remainder == zero {
            // Snapped: the target itself was written (not `at_offset(target, 0)`, which a
            // space may clamp or re-encode).
            P::Space::same(current, self.active_target, FastPath)
        } else {
            P::Space::is_written(current, self.active_target, self.offset, FastPath)
        }
    }

    /// The value this motion put on the property: the target it snapped to at rest, or what its
    /// last step wrote ([`holds`](Self::holds) is true of it).
    #[inline]
    pub(crate) fn shown(&self) -> ValueOf<P> {
        let zero = OffsetOf::<P>::ZERO;
        if self.offset.offset == zero && self.offset.remainder == zero {
            self.active_target
        } else {
            P::Space::at_carried(self.active_target, self.offset)
        }
    }

    /// The ticket of the spring's slot in its property's transition table; from
    /// [`SlotTicket::NO_SLOT`] up, it has none.
    #[inline]
    pub(in crate::spring) fn ticket(&self) -> u64 {
        self.ticket.get()
    }

    /// Remembers `ticket` as the spring's slot's (a spring with time pending has no slot: the
    /// caller has checked there is none).
    #[inline]
    pub(in crate::spring) fn set_ticket(&mut self, ticket: u64) {
        debug_assert!(
            self.pending() == 0.0 && ticket < SlotTicket::NO_SLOT,
            "a slot for a spring with time pending, or a ticket no slot has"
        );
        self.ticket = SlotTicket::slot(ticket);
    }

    /// Forgets the spring's slot, keeping the time pending.
    #[inline]
    pub(in crate::spring) fn clear_ticket(&mut self) {
        self.ticket = SlotTicket::pending(self.pending());
    }

    /// Time not yet simulated while hidden, in seconds (0 for a spring with a slot).
    #[inline]
    pub(in crate::spring) fn pending(&self) -> f32 {
        self.ticket.time_pending()
    }

    /// Sets the time not yet simulated, which forgets the spring's slot.
    #[inline]
    pub(in crate::spring) fn set_pending(&mut self, seconds: f32) {
        self.ticket = SlotTicket::pending(seconds);
    }
}

impl<P: SpringProperty> Clone for SpringMotion<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for SpringMotion<P> {}

impl<P: SpringProperty> fmt::Debug for SpringMotion<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SpringMotion")
            .field("property", &P::short_type_path())
            .field("velocity", &self.velocity)
            .field("active_target", &self.active_target)
            .field("offset", &self.offset)
            .field("pending", &self.pending())
            .finish_non_exhaustive()
    }
}

/// The smallest tolerance the rest test applies: squared offsets and speeds are compared in
/// `f32`, whose squares of values below this would underflow.
const FINEST_REST: f32 = 1e-18;

/// The squared tolerances of `rest` as applied toward `target`: raised to what `f32` resolves
/// near the target ([`RestThreshold::at_magnitude`]) and to [`FINEST_REST`].
pub(in crate::spring) fn rest_squared<P: SpringProperty>(
    rest: RestThreshold<f32>,
    target: ValueOf<P>,
) -> (f32, f32) {
    let magnitude = P::Space::magnitude(target);
    let applied = rest.at_magnitude(if magnitude.is_finite() {
        magnitude
    } else {
        0.0
    });
    let square = |tolerance: f32| {
        let tolerance = f64::from(tolerance.max(FINEST_REST));
        #[expect(
            clippy::cast_possible_truncation,
            reason = "an f32 threshold; squares beyond f32::MAX become infinite (all at rest)"
        )]
        let squared = (tolerance * tolerance) as f32;
        squared
    };
    (square(applied.offset), square(applied.speed))
}
