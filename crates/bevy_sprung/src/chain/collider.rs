//! Spheres and capsules the bones of a chain stay out of.

use bevy::prelude::*;

/// A sphere, or a capsule along the entity's local y axis, that the bones of the
/// [`SpringChain`](super::SpringChain)s naming it stay out of (a head the hair falls around, a
/// body a tail drapes over). Sizes are in the entity's local units (scaled by its largest
/// scale).
///
/// A bone whose end would be inside turns about its joint until its end is on the surface,
/// and its tip loses its velocity into the collider; a bone whose joint is inside one is left
/// alone. Every joint of a chain outside its colliders stays outside to rounding for spheres;
/// for capsules, to within a thousandth of the bone's length.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, PartialEq, Clone)]
#[require(Transform)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ChainCollider {
    /// The radius.
    pub radius: f32,
    /// Half the length of the capsule's axis (0: a sphere).
    pub half_length: f32,
}

impl ChainCollider {
    /// A sphere of `radius`.
    #[must_use]
    pub fn sphere(radius: f32) -> Self {
        Self {
            radius,
            half_length: 0.0,
        }
    }

    /// A capsule of `radius` around a segment of `length` along local y.
    #[must_use]
    pub fn capsule(radius: f32, length: f32) -> Self {
        Self {
            radius,
            half_length: 0.5 * length,
        }
    }
}

/// A collider placed in the world: a segment and a radius.
#[derive(Debug, Clone, Copy)]
pub(super) struct PlacedCollider {
    pub(super) a: Vec3,
    pub(super) b: Vec3,
    pub(super) radius: f32,
}

impl PlacedCollider {
    /// `collider` on an entity whose world transform is `global`.
    pub(super) fn new(collider: ChainCollider, global: &GlobalTransform) -> Option<Self> {
        let (scale, rotation, translation) = global.to_scale_rotation_translation();
        let size = scale.abs().max_element();
        let axis = rotation * Vec3::Y * (collider.half_length.max(0.0) * size);
        let placed = Self {
            a: translation - axis,
            b: translation + axis,
            radius: collider.radius.max(0.0) * size,
        };
        (placed.a.is_finite() && placed.b.is_finite() && placed.radius.is_finite())
            .then_some(placed)
    }

    /// The point of the axis nearest `point`.
    pub(super) fn nearest(&self, point: Vec3) -> Vec3 {
        let axis = self.b - self.a;
        let length_squared = axis.length_squared();
        if length_squared > 0.0 {
            self.a + axis * ((point - self.a).dot(axis) / length_squared).clamp(0.0, 1.0)
        } else {
            self.a
        }
    }
}
