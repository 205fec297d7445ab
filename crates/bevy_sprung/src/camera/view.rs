//! What a camera sees: its view's half extents in world units, and how a point is eased into
//! bounds without a jump in its velocity.

use bevy::camera::{Camera, OrthographicProjection, Projection};
use bevy::math::{Rect, Vec2};
use bevy::window::Window;

/// The half width and half height of a camera's view in world units, at zoom `zoom` and, for a
/// perspective camera, at `depth` in front of it. Zero where nothing is known (no viewport, a
/// custom projection, a degenerate window): then zones and bounds act on the framed point
/// alone.
#[must_use]
pub(crate) fn half_extents(
    projection: Option<&Projection>,
    viewport: Option<Vec2>,
    zoom: f32,
    depth: f32,
) -> Vec2 {
    let Some(size) = viewport.filter(|size| size.x > 0.0 && size.y > 0.0 && size.is_finite())
    else {
        return Vec2::ZERO;
    };
    let half = match projection {
        Some(Projection::Orthographic(orthographic)) => {
            orthographic_half_extents(orthographic, size, zoom)
        }
        Some(Projection::Perspective(perspective)) => {
            // The frustum's footprint at `depth`: the view scales with distance, and a zoom is
            // a distance factor.
            let half_height = depth.max(0.0) * (perspective.fov * 0.5).tan();
            Vec2::new(half_height * size.x / size.y, half_height)
        }
        _ => Vec2::ZERO,
    };
    if half.is_finite() {
        half.max(Vec2::ZERO)
    } else {
        Vec2::ZERO
    }
}

/// The half extents of an orthographic view of `size` logical pixels with its scale set to
/// `zoom`: Bevy's own area computation, on a copy, so every scaling mode is honoured.
fn orthographic_half_extents(projection: &OrthographicProjection, size: Vec2, zoom: f32) -> Vec2 {
    use bevy::camera::CameraProjection;
    let mut view = projection.clone();
    view.scale = zoom;
    view.update(size.x, size.y);
    view.area.half_size()
}

/// The logical size of what `camera` renders to, or the primary window's.
#[must_use]
pub(crate) fn viewport_size(camera: Option<&Camera>, window: Option<&Window>) -> Option<Vec2> {
    camera
        .and_then(Camera::logical_viewport_size)
        .or_else(|| window.map(Window::size))
}

/// Where the centre of a view with half extents `half` may be for the view to stay inside
/// `bounds`: the bounds shrunk by the half extents. A view wider or taller than the bounds
/// has one place on that axis, the bounds' centre.
#[must_use]
pub(crate) fn centre_range(bounds: Rect, half: Vec2) -> Rect {
    let mut min = bounds.min + half;
    let mut max = bounds.max - half;
    let centre = bounds.center();
    for axis in 0..2 {
        if min[axis] > max[axis] {
            min[axis] = centre[axis];
            max[axis] = centre[axis];
        }
    }
    Rect { min, max }
}

/// `u` eased into `[low, high]` with a slowing distance `slowing`: the identity inside
/// `[low + slowing, high − slowing]`, a quadratic that slows to a stop exactly at the bound over
/// the `2·slowing` around each band's inner edge, and the bound beyond.
///
/// The map is continuously differentiable with a slope in `[0, 1]`, so a point moving
/// smoothly (a spring) is eased smoothly: its velocity is scaled, never cut, and never grows.
/// With `slowing` 0 it is a clamp. A range narrower than two slowing distances shares it
/// between its ends; `low > high` gives their midpoint.
#[inline]
#[must_use]
pub(crate) fn ease_into(u: f32, low: f32, high: f32, slowing: f32) -> f32 {
    if low >= high {
        return (low + high) * 0.5;
    }
    let slowing = slowing.min((high - low) * 0.5).max(0.0);
    if slowing == 0.0 {
        return u.clamp(low, high);
    }
    // Within the band, s ∈ [0, 2·slowing] is how far past the band's inner edge u is, and the
    // eased point is that edge plus s − s²/(4·slowing): every term is bounded by the band, so
    // nothing cancels or overflows for any finite input.
    let eased_band = |s: f32| s - s * s / (4.0 * slowing);
    if u > high - slowing {
        let s = (u - (high - slowing)).min(2.0 * slowing);
        (high - slowing) + eased_band(s)
    } else if u < low + slowing {
        let s = ((low + slowing) - u).min(2.0 * slowing);
        (low + slowing) - eased_band(s)
    } else {
        u
    }
}

/// How far past a range an eased point can usefully be: beyond `slowing` outside the range
/// the eased point stands on the bound, so a goal is kept within this.
#[inline]
#[must_use]
pub(crate) fn goal_range(low: f32, high: f32, slowing: f32) -> (f32, f32) {
    if low >= high {
        let centre = (low + high) * 0.5;
        return (centre, centre);
    }
    let slowing = slowing.min((high - low) * 0.5).max(0.0);
    (low - slowing, high + slowing)
}

#[cfg(test)]
#[expect(clippy::float_cmp, reason = "the identity and the bounds are exact")]
mod tests {
    use super::*;

    #[test]
    fn easing_is_the_identity_inside_and_reaches_the_bound_with_zero_slope() {
        let (low, high, slowing) = (-10.0, 10.0, 2.0);
        for u in [-8.0, -3.0, 0.0, 7.5, 8.0] {
            assert_eq!(ease_into(u, low, high, slowing), u);
        }
        assert_eq!(ease_into(12.0, low, high, slowing), 10.0);
        assert_eq!(ease_into(-12.0, low, high, slowing), -10.0);
        assert_eq!(ease_into(1e30, low, high, slowing), 10.0);
        // Slope: 1 at the band's inner edge, 0 at its outer edge, in between inside.
        let slope = |u: f32| {
            (ease_into(u + 1e-3, low, high, slowing) - ease_into(u - 1e-3, low, high, slowing))
                / 2e-3
        };
        assert!((slope(8.0 + 1e-3) - 1.0).abs() < 1e-2);
        assert!(slope(12.0 - 1e-3).abs() < 1e-2);
        let mut last = f32::NEG_INFINITY;
        for i in 0..=4000 {
            let u = -15.0 + i as f32 * 0.0075;
            let eased = ease_into(u, low, high, slowing);
            assert!((low..=high).contains(&eased));
            assert!(eased >= last, "monotone at {u}");
            assert!(slope(u) <= 1.0 + 1e-2);
            last = eased;
        }
    }

    #[test]
    fn easing_degenerate_ranges() {
        assert_eq!(ease_into(5.0, 1.0, 1.0, 3.0), 1.0);
        assert_eq!(ease_into(5.0, 3.0, 1.0, 3.0), 2.0);
        assert_eq!(ease_into(5.0, 0.0, 1.0, 0.0), 1.0);
        // A slowing distance wider than half the range is cut to it: still inside, monotone.
        assert_eq!(ease_into(0.5, 0.0, 1.0, 10.0), 0.5);
        assert_eq!(ease_into(2.0, 0.0, 1.0, 10.0), 1.0);
        assert_eq!(goal_range(0.0, 1.0, 10.0), (-0.5, 1.5));
    }

    #[test]
    fn a_view_larger_than_its_bounds_is_centred() {
        let range = centre_range(Rect::new(0.0, 0.0, 100.0, 50.0), Vec2::new(60.0, 10.0));
        assert_eq!(range.min, Vec2::new(50.0, 10.0));
        assert_eq!(range.max, Vec2::new(50.0, 40.0));
    }

    #[test]
    fn orthographic_extents_follow_the_window_and_the_zoom() {
        let projection = Projection::Orthographic(OrthographicProjection::default_2d());
        let half = half_extents(Some(&projection), Some(Vec2::new(800.0, 600.0)), 2.0, 0.0);
        assert_eq!(half, Vec2::new(800.0, 600.0));
        assert_eq!(half_extents(Some(&projection), None, 1.0, 0.0), Vec2::ZERO);
        assert_eq!(
            half_extents(Some(&projection), Some(Vec2::new(0.0, 600.0)), 1.0, 0.0),
            Vec2::ZERO
        );
    }
}
