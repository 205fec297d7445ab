//! A rail's geometry: distance along a cubic curve, and the point of it nearest a target.

use alloc::vec::Vec;

use bevy::math::cubic_splines::{CubicCurve, CubicSegment};
use bevy::prelude::*;

/// Samples per curve segment in the distance table. The chords between them are shorter than
/// the arc by at most `(θ/n)²/24` of its length, for a segment turning by θ: under 1e-4 for a
/// half turn.
const SAMPLES_PER_SEGMENT: usize = 32;

/// Newton steps refining the nearest point from the nearest chord: each one squares the error,
/// and the chord's point is already within a fraction of a sample of it.
const NEWTON_STEPS: usize = 3;

/// How many chords either side of a constant speed's guess are looked at before searching the
/// whole table.
const LOCAL_SEARCH: usize = 3;

/// A Newton step this small (of a segment's parameter) has converged: the next would move the
/// point by less than `f32` resolves on a segment a few thousand units long.
const CONVERGED: f32 = 1e-6;

/// A rail's curve with its distance table: the curve sampled evenly in its parameter, and the
/// distance along the chords to each sample. Distance and parameter map to each other linearly
/// between samples, both ways, so the maps are inverse, and exact on a straight stretch the
/// curve runs at a constant speed.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RailTrack {
    curve: CubicCurve<Vec3>,
    looped: bool,
    points: Vec<Vec3>,
    distances: Vec<f32>,
}

impl RailTrack {
    /// The table of `curve`, whose end joins its start when `looped`.
    pub(crate) fn new(curve: &CubicCurve<Vec3>, looped: bool) -> Self {
        let chords = curve.segments().len() * SAMPLES_PER_SEGMENT;
        let points: Vec<Vec3> = curve.iter_positions(chords).collect();
        let mut distances = Vec::with_capacity(points.len());
        let mut travelled = 0.0;
        distances.push(0.0);
        for pair in points.windows(2) {
            let chord = pair[0].distance(pair[1]);
            travelled += if chord.is_finite() { chord } else { 0.0 };
            distances.push(travelled);
        }
        Self {
            curve: curve.clone(),
            looped,
            points,
            distances,
        }
    }

    /// Whether this is the table of `curve`, looped as `looped`.
    pub(crate) fn is_of(&self, curve: &CubicCurve<Vec3>, looped: bool) -> bool {
        self.looped == looped && &self.curve == curve
    }

    /// The curve.
    pub(crate) fn curve(&self) -> &CubicCurve<Vec3> {
        &self.curve
    }

    /// Whether the end joins the start.
    pub(crate) fn looped(&self) -> bool {
        self.looped
    }

    /// How far the curve's end is from its start, as a fraction of its length: a looped rail
    /// should be closed (`CubicCardinalSpline::to_curve_cyclic`).
    pub(crate) fn gap(&self) -> f32 {
        let (Some(first), Some(last)) = (self.points.first(), self.points.last()) else {
            return 0.0;
        };
        let length = self.length();
        if length > 0.0 {
            first.distance(*last) / length
        } else {
            0.0
        }
    }

    /// The length along the curve.
    pub(crate) fn length(&self) -> f32 {
        self.distances.last().copied().unwrap_or(0.0)
    }

    /// The samples of the curve, for drawing it.
    #[cfg(any(feature = "debug", test))]
    pub(crate) fn points(&self) -> &[Vec3] {
        &self.points
    }

    /// `distance` on the rail: wrapped into `[0, length)` on a loop, clamped to `[0, length]`
    /// otherwise (a non-finite distance is the start).
    #[must_use]
    pub(crate) fn on_rail(&self, distance: f32) -> f32 {
        let length = self.length();
        if !distance.is_finite() || length <= 0.0 {
            0.0
        } else if self.looped {
            // `rem_euclid` can round up to `length` itself for a tiny negative distance.
            let wrapped = distance.rem_euclid(length);
            if wrapped < length { wrapped } else { 0.0 }
        } else {
            distance.clamp(0.0, length)
        }
    }

    /// The signed distance from `from` to `to` along the rail: the shorter way round on a loop
    /// (in `[-length/2, length/2)`).
    #[must_use]
    pub(crate) fn toward(&self, from: f32, to: f32) -> f32 {
        let length = self.length();
        let step = to - from;
        if self.looped && length > 0.0 {
            (step + 0.5 * length).rem_euclid(length) - 0.5 * length
        } else {
            step
        }
    }

    /// The curve's parameter `distance` along the rail (wrapped or clamped onto it).
    #[must_use]
    pub(crate) fn parameter_at(&self, distance: f32) -> f32 {
        let distance = self.on_rail(distance);
        let chords = self.distances.len().saturating_sub(1);
        let length = self.length();
        if chords == 0 || length <= 0.0 {
            return 0.0;
        }
        let index = self.chord_containing(distance, chords, length);
        let (start, end) = (self.distances[index], self.distances[index + 1]);
        let fraction = if end > start {
            ((distance - start) / (end - start)).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (index as f32 + fraction) / SAMPLES_PER_SEGMENT as f32
    }

    /// The chord (of `chords`, along a rail `length` long) whose samples bracket `distance`,
    /// in `[0, length]`. The chord a constant speed would put it on is tried first, with a
    /// few neighbours: a table as long as a rail's reads a cache line or two instead of a
    /// binary search's dozen.
    fn chord_containing(&self, distance: f32, chords: usize, length: f32) -> usize {
        let contains = |chord: usize| {
            self.distances[chord] <= distance
                && (distance < self.distances[chord + 1] || chord + 1 == chords)
        };
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a fraction of the chords: in 0..=chords"
        )]
        let guess = ((distance / length * chords as f32) as usize).min(chords - 1);
        let nearby = (guess.saturating_sub(LOCAL_SEARCH)..=(guess + LOCAL_SEARCH).min(chords - 1))
            .find(|&chord| contains(chord));
        nearby.unwrap_or_else(|| {
            // The last sample not past `distance`.
            self.distances
                .partition_point(|&sample| sample <= distance)
                .clamp(1, chords)
                - 1
        })
    }

    /// The distance along the rail at the curve's parameter `parameter`.
    #[must_use]
    pub(crate) fn distance_at(&self, parameter: f32) -> f32 {
        let chords = self.distances.len().saturating_sub(1);
        if chords == 0 || !parameter.is_finite() {
            return 0.0;
        }
        let scaled = (parameter * SAMPLES_PER_SEGMENT as f32).clamp(0.0, chords as f32);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "in 0..=chords"
        )]
        let index = (scaled as usize).min(chords - 1);
        let fraction = scaled - index as f32;
        let (start, end) = (self.distances[index], self.distances[index + 1]);
        start + (end - start) * fraction
    }

    /// The point `distance` along the rail.
    #[must_use]
    pub(crate) fn position_at(&self, distance: f32) -> Vec3 {
        self.curve.position(self.parameter_at(distance))
    }

    /// The direction of travel `distance` along the rail (not normalised; zero where the curve
    /// stops).
    #[must_use]
    pub(crate) fn direction_at(&self, distance: f32) -> Vec3 {
        self.curve.velocity(self.parameter_at(distance))
    }

    /// The place on the rail nearest `target`: its distance along the rail and the curve's
    /// parameter there. From `near` (last frame's parameter), the search walks the chords
    /// downhill to the nearest one close by, so that a rail passing near itself keeps the
    /// branch it was on; without it, every chord is looked at. Newton's method then finds the
    /// point on the curve itself.
    #[must_use]
    pub(crate) fn nearest(&self, target: Vec3, near: Option<f32>) -> RailPlace {
        let chords = self.points.len().saturating_sub(1);
        if chords == 0 || !target.is_finite() {
            return RailPlace::default();
        }
        let per = SAMPLES_PER_SEGMENT as f32;
        let chord = match near.filter(|near| near.is_finite()) {
            Some(near) => {
                #[expect(
                    clippy::cast_possible_truncation,
                    clippy::cast_sign_loss,
                    reason = "clamped to the chords"
                )]
                let chord = (near * per).clamp(0.0, (chords - 1) as f32) as usize;
                self.walk_downhill(target, chord)
            }
            None => (0..chords)
                .map(|chord| (chord, self.chord_distance(target, chord).0))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map_or(0, |(chord, _)| chord),
        };
        let (_, along) = self.chord_distance(target, chord);
        let low = chord.saturating_sub(1) as f32 / per;
        let high = (chord + 2).min(chords) as f32 / per;
        let start = (chord as f32 + along) / per;
        let parameter = self.refine(target, start, (low, high));
        RailPlace {
            distance: self.distance_at(parameter),
            parameter,
        }
    }

    /// The squared distance from `target` to chord `chord`, and how far along the chord (0 to
    /// 1) its nearest point is.
    fn chord_distance(&self, target: Vec3, chord: usize) -> (f32, f32) {
        let (start, end) = (self.points[chord], self.points[chord + 1]);
        let span = end - start;
        let length_squared = span.length_squared();
        let along = if length_squared > 0.0 {
            ((target - start).dot(span) / length_squared).clamp(0.0, 1.0)
        } else {
            0.0
        };
        ((start + span * along).distance_squared(target), along)
    }

    /// From chord `chord`, the chords toward `target` while they come nearer: a local nearest
    /// chord (across the seam on a loop).
    fn walk_downhill(&self, target: Vec3, mut chord: usize) -> usize {
        let chords = self.points.len() - 1;
        let step = |chord: usize, forward: bool| -> Option<usize> {
            match (forward, self.looped) {
                (true, _) if chord + 1 < chords => Some(chord + 1),
                (true, true) => Some(0),
                (false, _) if chord > 0 => Some(chord - 1),
                (false, true) => Some(chords - 1),
                _ => None,
            }
        };
        let mut best = self.chord_distance(target, chord).0;
        // Each step comes strictly nearer, so no chord is visited twice.
        for _ in 0..chords {
            let nearer = [step(chord, true), step(chord, false)]
                .into_iter()
                .flatten()
                .map(|next| (next, self.chord_distance(target, next).0))
                .filter(|&(_, distance)| distance < best)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            match nearer {
                Some((next, distance)) => (chord, best) = (next, distance),
                None => break,
            }
        }
        chord
    }

    /// The curve's parameter nearest `target` near `start`, in `bounds`: Newton's method on
    /// `C'(t)·(C(t) − target) = 0`, each step kept only if it comes nearer.
    fn refine(&self, target: Vec3, start: f32, bounds: (f32, f32)) -> f32 {
        let mut parameter = start;
        let mut best = self.curve.position(parameter).distance_squared(target);
        for _ in 0..NEWTON_STEPS {
            let (segment, local) = self.segment_at(parameter);
            let offset = segment.position(local) - target;
            let velocity = segment.velocity(local);
            let slope = velocity.dot(offset);
            let curvature = segment.acceleration(local).dot(offset) + velocity.dot(velocity);
            // Only where the distance is convex: elsewhere the chord's point stands.
            if curvature <= 0.0 || !curvature.is_finite() {
                break;
            }
            let next = (parameter - slope / curvature).clamp(bounds.0, bounds.1);
            let distance = self.curve.position(next).distance_squared(target);
            if distance.partial_cmp(&best) != Some(core::cmp::Ordering::Less) {
                break;
            }
            let settled = (next - parameter).abs() <= CONVERGED;
            (parameter, best) = (next, distance);
            if settled {
                break;
            }
        }
        parameter
    }

    /// The segment the curve's parameter `parameter` is on, and the parameter within it.
    fn segment_at(&self, parameter: f32) -> (&CubicSegment<Vec3>, f32) {
        let segments = self.curve.segments();
        let last = segments.len().saturating_sub(1);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "clamped to the segments"
        )]
        let index = parameter.floor().clamp(0.0, last as f32) as usize;
        (&segments[index], parameter - index as f32)
    }
}

/// A place on a rail: how far along it, and the curve's parameter there.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct RailPlace {
    pub(crate) distance: f32,
    pub(crate) parameter: f32,
}

#[cfg(test)]
mod tests {
    use super::*;
    use bevy::math::cubic_splines::{CubicBezier, CubicCardinalSpline, CubicGenerator};

    fn straight() -> CubicCurve<Vec3> {
        CubicBezier::new([[
            Vec3::ZERO,
            Vec3::new(100.0, 0.0, 0.0),
            Vec3::new(200.0, 0.0, 0.0),
            Vec3::new(300.0, 0.0, 0.0),
        ]])
        .to_curve()
        .unwrap()
    }

    fn ring(radius: f32) -> CubicCurve<Vec3> {
        let points = (0..12).map(|i| {
            let angle = i as f32 * core::f32::consts::TAU / 12.0;
            Vec3::new(angle.cos(), 0.0, angle.sin()) * radius
        });
        CubicCardinalSpline::new_catmull_rom(points)
            .to_curve_cyclic()
            .unwrap()
    }

    #[test]
    fn a_straight_rail_maps_distance_exactly() {
        let track = RailTrack::new(&straight(), false);
        assert!((track.length() - 300.0).abs() < 1e-3);
        for distance in [0.0, 0.3, 17.25, 150.0, 299.9] {
            let point = track.position_at(distance);
            assert!((point.x - distance).abs() < 1e-3, "{distance}: {point}");
            let back = track
                .nearest(point + Vec3::new(0.0, 40.0, -3.0), None)
                .distance;
            assert!((back - distance).abs() < 1e-3, "{distance}: {back}");
        }
        // Past the ends: clamped.
        assert_eq!(track.position_at(-5.0), Vec3::ZERO);
        assert!((track.position_at(400.0).x - 300.0).abs() < 1e-3);
    }

    #[test]
    fn distance_and_parameter_are_inverse_however_unevenly_the_curve_runs() {
        // Crawling through its first half and racing through its second: a constant speed's
        // guess of the chord is far off, and the search falls back to the whole table.
        let curve = CubicBezier::new([
            [
                Vec3::ZERO,
                Vec3::new(1.0, 0.0, 0.0),
                Vec3::new(2.0, 0.0, 0.0),
                Vec3::new(3.0, 1.0, 0.0),
            ],
            [
                Vec3::new(3.0, 1.0, 0.0),
                Vec3::new(900.0, 300.0, 0.0),
                Vec3::new(1800.0, -300.0, 0.0),
                Vec3::new(2700.0, 0.0, 0.0),
            ],
        ])
        .to_curve()
        .unwrap();
        let track = RailTrack::new(&curve, false);
        for i in 0..=400 {
            let parameter = i as f32 / 200.0;
            let distance = track.distance_at(parameter);
            let back = track.parameter_at(distance);
            assert!((back - parameter).abs() < 1e-4, "{parameter}: {back}");
        }
    }

    #[test]
    fn a_ring_is_measured_and_wraps() {
        let radius = 500.0;
        let track = RailTrack::new(&ring(radius), true);
        // Catmull-Rom through twelve points of a circle is within 0.1 % of its length.
        let circle = core::f32::consts::TAU * radius;
        assert!(
            (track.length() / circle - 1.0).abs() < 1e-3,
            "{}",
            track.length()
        );
        assert!(track.gap() < 1e-6);
        let length = track.length();
        assert!((track.on_rail(length + 10.0) - 10.0).abs() < 1e-3);
        assert!((track.on_rail(-10.0) - (length - 10.0)).abs() < 1e-3);
        assert!((track.toward(length - 5.0, 5.0) - 10.0).abs() < 1e-3);
        assert!((track.toward(5.0, length - 5.0) + 10.0).abs() < 1e-3);
    }

    #[test]
    fn the_nearest_point_is_on_the_curve_and_maps_back() {
        let track = RailTrack::new(&ring(500.0), true);
        for i in 0..50 {
            let angle = i as f32 * 0.37;
            let target = Vec3::new(angle.cos(), 0.3, angle.sin()) * 620.0;
            let place = track.nearest(target, None);
            let distance = place.distance;
            let point = track.position_at(distance);
            // The nearest point: the offset to it is normal to the curve.
            let direction = track.direction_at(distance).normalize();
            let offset = target - point;
            assert!(
                offset.normalize().dot(direction).abs() < 1e-3,
                "{i}: {}",
                offset.normalize().dot(direction)
            );
            // No sample of the curve is nearer.
            let nearest = track
                .points()
                .iter()
                .map(|sample| sample.distance(target))
                .fold(f32::INFINITY, f32::min);
            assert!(offset.length() <= nearest + 1e-3);
            // Warm-started from close by, the same point.
            let warm = track
                .nearest(target, Some(track.parameter_at(distance + 30.0)))
                .distance;
            assert!(
                track.toward(distance, warm).abs() < 1e-2,
                "{distance} {warm}"
            );
        }
    }

    #[test]
    fn a_warm_start_keeps_the_branch_of_a_rail_passing_near_itself() {
        // A hairpin: out along y = 0, back along y = 10.
        let curve = CubicBezier::new([
            [
                Vec3::ZERO,
                Vec3::new(100.0, 0.0, 0.0),
                Vec3::new(200.0, 0.0, 0.0),
                Vec3::new(300.0, 0.0, 0.0),
            ],
            [
                Vec3::new(300.0, 0.0, 0.0),
                Vec3::new(340.0, 0.0, 0.0),
                Vec3::new(340.0, 10.0, 0.0),
                Vec3::new(300.0, 10.0, 0.0),
            ],
            [
                Vec3::new(300.0, 10.0, 0.0),
                Vec3::new(200.0, 10.0, 0.0),
                Vec3::new(100.0, 10.0, 0.0),
                Vec3::ZERO.with_y(10.0),
            ],
        ])
        .to_curve()
        .unwrap();
        let track = RailTrack::new(&curve, false);
        // Just nearer the way back, but followed on the way out.
        let target = Vec3::new(150.0, 5.5, 0.0);
        let cold = track.nearest(target, None).distance;
        assert!(track.position_at(cold).y > 9.0);
        let warm = track
            .nearest(target, Some(track.parameter_at(140.0)))
            .distance;
        assert!((warm - 150.0).abs() < 1e-2, "{warm}");
    }

    #[test]
    #[expect(clippy::float_cmp, reason = "the start of a rail is exact")]
    fn degenerate_input_stays_finite() {
        let track = RailTrack::new(&straight(), false);
        assert_eq!(track.nearest(Vec3::NAN, None), RailPlace::default());
        assert_eq!(track.nearest(Vec3::ZERO, Some(f32::NAN)).distance, 0.0);
        assert_eq!(track.on_rail(f32::INFINITY), 0.0);
        let point = CubicBezier::new([[Vec3::ONE; 4]]).to_curve().unwrap();
        let track = RailTrack::new(&point, true);
        assert_eq!(track.length(), 0.0);
        assert_eq!(track.position_at(10.0), Vec3::ONE);
        assert_eq!(track.nearest(Vec3::X, None).distance, 0.0);
        assert_eq!(track.toward(0.0, 3.0), 3.0);
    }
}
