//! A spring's slot ticket, or its time pending: one 8-byte field for either.

/// A spring's slot ticket or, where it has no slot, its time pending: a spring with time
/// pending has none (its next visible step is the general one, which catches up), so one field
/// holds either. That keeps the motion of a `Vec2` spring to 48 bytes, a multiple of 16, so
/// that fewer of the step's 16-byte loads straddle two cache lines than at 52 bytes; with the
/// time in a field of its own, `Vec2` and UI translation springs stepped slower for the same
/// instructions (the performance log has the figures).
///
/// Two `u32` halves, aligned to 4 bytes (not padding a `Vec2` or `f32` spring's motion to 8),
/// read as one 8-byte load: a slot's ticket, or with the high half all ones (tickets from
/// [`NO_SLOT`](Self::NO_SLOT) up, which the table never hands out) the bits of the time
/// pending in the low half.
#[derive(Clone, Copy)]
pub(in crate::spring) struct SlotTicket([u32; 2]);

impl SlotTicket {
    /// The first of the tickets no slot ever has: a transition table hands out tickets from 0,
    /// one a slot, and could not reach it in the life of any program. A spring without a slot
    /// holds one of them.
    pub(in crate::spring) const NO_SLOT: u64 = 0xFFFF_FFFF_0000_0000;

    /// The ticket of a slot (below [`NO_SLOT`](Self::NO_SLOT)).
    #[inline]
    pub(in crate::spring) fn slot(ticket: u64) -> Self {
        // The low and the high half.
        #[expect(clippy::cast_possible_truncation, reason = "split in halves")]
        Self([ticket as u32, (ticket >> 32) as u32])
    }

    /// No slot, and `seconds` pending.
    #[inline]
    pub(in crate::spring) fn pending(seconds: f32) -> Self {
        Self([seconds.to_bits(), u32::MAX])
    }

    /// The ticket: a slot's, or from [`NO_SLOT`](Self::NO_SLOT) up, no slot's.
    #[inline]
    pub(in crate::spring) fn get(self) -> u64 {
        u64::from(self.0[0]) | (u64::from(self.0[1]) << 32)
    }

    /// The time pending: 0 where the spring has a slot.
    #[inline]
    pub(in crate::spring) fn time_pending(self) -> f32 {
        if self.0[1] == u32::MAX {
            f32::from_bits(self.0[0])
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::SlotTicket;

    /// A slot's ticket reads back as itself with no time pending; time pending reads back bit
    /// for bit with a ticket no slot has.
    #[test]
    fn a_ticket_holds_a_slot_or_the_time_pending() {
        for ticket in [0, 5, u64::from(u32::MAX) + 1, SlotTicket::NO_SLOT - 1] {
            let slot = SlotTicket::slot(ticket);
            assert_eq!((slot.get(), slot.time_pending().to_bits()), (ticket, 0));
        }
        for seconds in [0.0, f32::MIN_POSITIVE, 0.25, f32::MAX, f32::INFINITY] {
            let pending = SlotTicket::pending(seconds);
            assert!(pending.get() >= SlotTicket::NO_SLOT, "{seconds}");
            assert_eq!(pending.time_pending().to_bits(), seconds.to_bits());
        }
    }
}
