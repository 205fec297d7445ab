//! Where a throw may go: the box it stays in ([`DragBounds`], with iOS's rubber band past its
//! edges) and the places it snaps to ([`Snap`]).

use bevy::prelude::*;

use crate::rubber_band::rubber_band;

/// A line a fling can snap onto: the point of it nearest the throw's resting place.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Debug, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SnapLine {
    /// A point of the line.
    pub origin: Vec3,
    /// Its direction (any length; zero makes the line its origin).
    pub direction: Vec3,
}

impl SnapLine {
    /// The point of the line nearest `point`.
    #[must_use]
    pub fn nearest(&self, point: Vec3) -> Vec3 {
        let length_squared = self.direction.length_squared();
        if length_squared > 0.0 && length_squared.is_finite() {
            self.origin
                + self.direction * ((point - self.origin).dot(self.direction) / length_squared)
        } else {
            self.origin
        }
    }
}

/// Where a thrown entity springs to, chosen from where its throw would come to rest (a drag's
/// release, or an [`Inertia`](crate::inertia::Inertia) fling).
#[derive(Reflect, Debug, Clone, PartialEq)]
#[reflect(Debug, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Snap {
    /// Where the throw comes to rest (within the bounds): a free throw, or a scroll panel's
    /// momentum.
    Free,
    /// Back home (where a drag started, or where a fling was thrown from) whatever the throw.
    Home,
    /// The nearest of these points (a slot, a card pile).
    Points(Vec<Vec3>),
    /// The nearest point of the nearest of these lines (a track, a shelf).
    Lines(Vec<SnapLine>),
    /// The nearest point of a grid: `origin + spacing·n` per axis (an axis with spacing 0 is
    /// free).
    Grid {
        /// A grid point.
        origin: Vec3,
        /// The cell size per axis.
        spacing: Vec3,
    },
}

impl Snap {
    /// The snap target for a throw coming to rest at `projected`, and the index of the point or
    /// line it chose; `home` when there is nothing to snap to.
    #[must_use]
    pub fn choose(&self, projected: Vec3, home: Vec3) -> (Vec3, Option<usize>) {
        let nearest = |candidates: &mut dyn Iterator<Item = Vec3>| {
            candidates
                .enumerate()
                .map(|(index, point)| (point.distance_squared(projected), index, point))
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .map_or((home, None), |(_, index, point)| (point, Some(index)))
        };
        match self {
            Self::Free => (projected, None),
            Self::Home => (home, None),
            Self::Points(points) => nearest(&mut points.iter().copied()),
            Self::Lines(lines) => nearest(&mut lines.iter().map(|line| line.nearest(projected))),
            Self::Grid { origin, spacing } => {
                let snap = |p: f32, o: f32, s: f32| {
                    if s > 0.0 && s.is_finite() {
                        o + ((p - o) / s).round() * s
                    } else {
                        p
                    }
                };
                (
                    Vec3::new(
                        snap(projected.x, origin.x, spacing.x),
                        snap(projected.y, origin.y, spacing.y),
                        snap(projected.z, origin.z, spacing.z),
                    ),
                    None,
                )
            }
        }
    }
}

/// A box a dragged entity stays in: dragged past an edge it follows the pointer less and
/// less (a rubber band, as iOS scroll views), and released it springs back inside.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Debug, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DragBounds {
    /// The lower corner.
    pub min: Vec3,
    /// The upper corner.
    pub max: Vec3,
    /// How far past an edge the entity can be pulled, at most (approached as the pointer goes
    /// on; 0 is a hard edge).
    pub give: f32,
}

impl DragBounds {
    /// Where an entity the pointer would put at `position` is shown: inside, exactly there;
    /// past an edge by `e`, at `give·(1 − 1/(1 + 0.55·e/give))` past it (it starts at 0.55 of
    /// the pointer's speed and never reaches `give`).
    #[must_use]
    pub fn rubber_band(&self, position: Vec3) -> Vec3 {
        let band = |x: f32, lo: f32, hi: f32| {
            let excess = if x < lo {
                x - lo
            } else if x > hi {
                x - hi
            } else {
                return x;
            };
            let edge = if excess < 0.0 { lo } else { hi };
            edge + rubber_band(excess, self.give)
        };
        Vec3::new(
            band(position.x, self.min.x, self.max.x),
            band(position.y, self.min.y, self.max.y),
            band(position.z, self.min.z, self.max.z),
        )
    }

    /// `position` clamped into the box.
    #[must_use]
    pub fn clamp(&self, position: Vec3) -> Vec3 {
        position.clamp(self.min.min(self.max), self.max.max(self.min))
    }
}
