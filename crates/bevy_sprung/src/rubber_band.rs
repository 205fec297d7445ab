//! The rubber band of iOS scroll views, shared by `DragBounds` (drags and inertia) and
//! momentum scrolling (`MomentumScroll`, feature `ui`).

/// How far past an edge something pulled `excess` past it is shown, with at most `give`:
/// `give·(1 − 1/(1 + 0.55·|excess|/give))` with the sign of `excess`. It starts at 0.55 of the
/// pull and never reaches `give`; a `give` of 0 (or not finite) is a hard edge.
#[inline]
#[must_use]
pub(crate) fn rubber_band(excess: f32, give: f32) -> f32 {
    if !(give > 0.0 && give.is_finite()) {
        return 0.0;
    }
    // 1 − 1/(1 + a) = a/(1 + a): no cancellation for small pulls.
    let pull = 0.55 * excess.abs() / give;
    (give * (pull / (1.0 + pull))).copysign(excess)
}

#[cfg(test)]
mod tests {
    use super::rubber_band;

    #[test]
    #[expect(clippy::float_cmp, reason = "zero and hard edges are exact")]
    fn starts_at_055_and_never_reaches_the_give() {
        assert_eq!(rubber_band(0.0, 100.0), 0.0);
        let small = rubber_band(1e-3, 100.0);
        assert!((small / 1e-3 - 0.55).abs() < 1e-3);
        assert!(rubber_band(1e9, 100.0) < 100.0);
        assert!(rubber_band(-1e9, 100.0) > -100.0);
        assert_eq!(rubber_band(50.0, 0.0), 0.0);
        assert_eq!(rubber_band(50.0, f32::INFINITY), 0.0);
    }
}
