//! [`CameraFraming`]: what a rig framed this frame, for the debug overlay and for games that
//! draw or react to the camera's zones.

use bevy::prelude::*;

/// What a [`CameraRig`](super::CameraRig) framed this frame, in world units: the point it
/// frames, where its [`DeadZone`](super::DeadZone) holds it, the zone's and the view's
/// extents, and the centre the camera springs to. The rig writes it (a required component);
/// read it to draw the zones (the [debug overlay](crate::debug) does) or to react to them.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::camera::CameraFraming;
///
/// // Is the player pushing the camera (on the edge of its dead zone)?
/// fn pushing(rigs: Query<&CameraFraming>) {
///     for framing in &rigs {
///         let _pushing = framing.pushes_dead_zone();
///     }
/// }
/// # bevy::ecs::system::assert_is_system(pushing);
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Debug, Clone, PartialEq, Default)]
pub struct CameraFraming {
    pub(super) goal: Vec3,
    pub(super) point: Vec3,
    pub(super) held: Vec3,
    pub(super) dead_zone: Vec3,
    pub(super) dead_zone_offset: Vec3,
    pub(super) half_view: Vec2,
    pub(super) centre: Vec3,
}

impl CameraFraming {
    /// The goal's point ([`CameraGoal::point`](super::CameraGoal::point)).
    #[inline]
    #[must_use]
    pub fn goal(&self) -> Vec3 {
        self.goal
    }

    /// The point the rig frames: the goal plus its look-ahead.
    #[inline]
    #[must_use]
    pub fn point(&self) -> Vec3 {
        self.point
    }

    /// Where the dead zone holds the framed point: the zone's anchor, which sits at the
    /// [`ScreenPosition`](super::ScreenPosition) (its centre, for a zone without an
    /// [`offset`](super::DeadZone::offset)). The point itself without a dead zone.
    #[inline]
    #[must_use]
    pub fn held(&self) -> Vec3 {
        self.held
    }

    /// The dead zone's half extents (x along the world's x, y along y, z along z; zero
    /// without a zone): the framed point moves within `dead_zone_centre() ± dead_zone` without
    /// moving the camera.
    #[inline]
    #[must_use]
    pub fn dead_zone(&self) -> Vec3 {
        self.dead_zone
    }

    /// The dead zone's centre: the anchor ([`held`](Self::held)) moved by the zone's
    /// [`offset`](super::DeadZone::offset).
    #[inline]
    #[must_use]
    pub fn dead_zone_centre(&self) -> Vec3 {
        self.held + self.dead_zone_offset
    }

    /// Whether the framed point is on an edge of the dead zone (to rounding): it pushes the
    /// zone, and the camera follows. `false` without a dead zone.
    #[must_use]
    pub fn pushes_dead_zone(&self) -> bool {
        let reach = (self.point - self.dead_zone_centre()).abs();
        self.dead_zone != Vec3::ZERO && reach.cmpge(self.dead_zone * (1.0 - 1e-4)).any()
    }

    /// The half extents of the view at the framed point's distance (along the camera's right
    /// and up axes), at the rig's current zoom; zero where the view is not known.
    #[inline]
    #[must_use]
    pub fn half_view(&self) -> Vec2 {
        self.half_view
    }

    /// The centre of the view the camera springs to (before a confiner eases it).
    #[inline]
    #[must_use]
    pub fn centre(&self) -> Vec3 {
        self.centre
    }
}
