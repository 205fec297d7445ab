//! What a camera sees: its view's half extents in world units, and how a point is eased into
//! bounds without a jump in its velocity.

use bevy::camera::{Camera, OrthographicProjection, Projection};
use bevy::math::{Rect, Vec2};
use bevy::window::Window;

/// The part of the world a camera's view covers, relative to the camera's position, in its own
/// right/up axes, at zoom `zoom` and, for a perspective camera, at `depth` in front of it. An
/// orthographic view is Bevy's own area, so an off-centre `viewport_origin` is honoured (the
/// camera's position is then not the view's centre). Empty at the origin where nothing is
/// known (no viewport, a custom projection, a degenerate window): then zones and bounds act on
/// the framed point alone.
#[must_use]
pub(crate) fn view_area(
    projection: Option<&Projection>,
    viewport: Option<Vec2>,
    zoom: f32,
    depth: f32,
) -> Rect {
    let Some(size) = viewport.filter(|size| size.x > 0.0 && size.y > 0.0 && size.is_finite())
    else {
        return Rect::default();
    };
    let area = match projection {
        Some(Projection::Orthographic(orthographic)) => orthographic_area(orthographic, size, zoom),
        Some(Projection::Perspective(perspective)) => {
            // The frustum's footprint at `depth`: the view scales with distance, and a zoom is
            // a distance factor.
            let half_height = depth.max(0.0) * (perspective.fov * 0.5).tan();
            let half = Vec2::new(half_height * size.x / size.y, half_height);
            Rect::from_center_half_size(Vec2::ZERO, half)
        }
        _ => Rect::default(),
    };
    if area.min.is_finite() && area.max.is_finite() && area.min.cmple(area.max).all() {
        area
    } else {
        Rect::default()
    }
}

/// The area of an orthographic view of `size` logical pixels with its scale set to `zoom`:
/// Bevy's own area computation, on a copy, so every scaling mode and viewport origin is
/// honoured.
fn orthographic_area(projection: &OrthographicProjection, size: Vec2, zoom: f32) -> Rect {
    use bevy::camera::CameraProjection;
    let mut view = projection.clone();
    view.scale = zoom;
    view.update(size.x, size.y);
    view.area
}

/// The logical size of what `camera` renders to, or the primary window's.
#[must_use]
pub(crate) fn viewport_size(camera: Option<&Camera>, window: Option<&Window>) -> Option<Vec2> {
    camera
        .and_then(Camera::logical_viewport_size)
        .or_else(|| window.map(Window::size))
}

/// Where a camera whose view covers `area` (relative to the camera, see [`view_area`]) may be
/// for the view to stay inside `bounds`: the bounds shrunk by the view on each side. A view
/// wider or taller than the bounds has one place on that axis, the one that centres it.
#[must_use]
pub(crate) fn centre_range(bounds: Rect, area: Rect) -> Rect {
    let mut min = bounds.min - area.min;
    let mut max = bounds.max - area.max;
    let centred = bounds.center() - area.center();
    for axis in 0..2 {
        if min[axis] > max[axis] {
            min[axis] = centred[axis];
            max[axis] = centred[axis];
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
        let view = Rect::from_center_half_size(Vec2::ZERO, Vec2::new(60.0, 10.0));
        let range = centre_range(Rect::new(0.0, 0.0, 100.0, 50.0), view);
        assert_eq!(range.min, Vec2::new(50.0, 10.0));
        assert_eq!(range.max, Vec2::new(50.0, 40.0));
        // A view whose camera is at its lower left corner: the camera ranges over the bounds
        // less the view's size, from the bounds' lower left corner.
        let view = Rect::new(0.0, 0.0, 40.0, 20.0);
        let range = centre_range(Rect::new(0.0, 0.0, 100.0, 50.0), view);
        assert_eq!(range.min, Vec2::new(0.0, 0.0));
        assert_eq!(range.max, Vec2::new(60.0, 30.0));
    }

    #[test]
    fn orthographic_extents_follow_the_window_and_the_zoom() {
        let projection = Projection::Orthographic(OrthographicProjection::default_2d());
        let area = view_area(Some(&projection), Some(Vec2::new(800.0, 600.0)), 2.0, 0.0);
        assert_eq!(area.half_size(), Vec2::new(800.0, 600.0));
        assert_eq!(area.center(), Vec2::ZERO);
        assert_eq!(
            view_area(Some(&projection), None, 1.0, 0.0),
            Rect::default()
        );
        assert_eq!(
            view_area(Some(&projection), Some(Vec2::new(0.0, 600.0)), 1.0, 0.0),
            Rect::default()
        );
        // An origin at the lower left: the view lies up and right of the camera.
        let projection = Projection::Orthographic(OrthographicProjection {
            viewport_origin: Vec2::ZERO,
            ..OrthographicProjection::default_2d()
        });
        let area = view_area(Some(&projection), Some(Vec2::new(800.0, 600.0)), 1.0, 0.0);
        assert_eq!(area, Rect::new(0.0, 0.0, 800.0, 600.0));
    }
}
