//! Turns by an angle, for motion that orientations cannot express: whole turns.

use core::any::TypeId;

use bevy::prelude::*;

use crate::space::Linear;
use crate::spring::{PropertySpring, PropertySystems, SpringPhase, add_property_systems};

/// An angle about a fixed axis that sets the entity's rotation: `Transform::rotation` becomes
/// the rotation by [`angle`](Self::angle) about [`axis`](Self::axis) (and, with feature `ui`,
/// `UiTransform::rotation` becomes the angle in the node's plane, clockwise on screen as
/// `UiTransform` turns) whenever the `Spin` changes.
///
/// A [`RotationSpring`](crate::transform::RotationSpring) moves between orientations the short way, so a
/// whole turn is no motion to it: 0 and 2π are the same orientation. A [`SpinAngleSpring`] springs
/// the angle itself, so a coin flip of 3 turns or a settings cog that turns once on hover (what
/// `bevy_tweening`'s `TransformRotateZLens` tweens) springs through every turn. The angle is not
/// wrapped; after many turns, subtract the same multiple of τ from it and from the spring's
/// target where convenient (`f32` keeps a thousandth of a radian up to ~8 000 rad).
///
/// The `Spin` owns the rotation: do not also put a `RotationSpring` on the entity. It needs no
/// component of its own kind: it turns the `Transform` (or `UiTransform`) the entity has.
///
/// # Example
/// ```
/// use core::f32::consts::TAU;
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::spin::{Spin, SpinAngleSpring};
///
/// fn spawn(mut commands: Commands) {
///     // A coin that flips three times about its x axis, with a little bounce at the end.
///     commands.spawn((
///         Transform::default(),
///         Spin::new(Dir3::X, 0.0),
///         SpinAngleSpring::new(Spring::bouncy(), 3.0 * TAU),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Component, Debug, PartialEq, Default)]
pub struct Spin {
    /// The axis of the turn (for 2D and UI, [`Dir3::Z`]).
    pub axis: Dir3,
    /// The angle in radians, counter-clockwise about `axis`, unwrapped.
    pub angle: f32,
}

impl Default for Spin {
    /// No turn, about [`Dir3::Z`].
    fn default() -> Self {
        Self::z(0.0)
    }
}

impl Spin {
    /// A turn of `angle` radians about `axis`.
    #[inline]
    #[must_use]
    pub const fn new(axis: Dir3, angle: f32) -> Self {
        Self { axis, angle }
    }

    /// A turn of `angle` radians about the z axis: the turn of a 2D sprite or a UI node.
    #[inline]
    #[must_use]
    pub const fn z(angle: f32) -> Self {
        Self::new(Dir3::Z, angle)
    }

    /// The rotation this spin sets. A non-finite angle gives the identity (a [`SpinAngleSpring`]
    /// never writes one).
    #[inline]
    #[must_use]
    pub fn rotation(&self) -> Quat {
        if self.angle.is_finite() {
            Quat::from_axis_angle(self.axis.as_vec3(), self.angle)
        } else {
            Quat::IDENTITY
        }
    }

    /// The rotation this spin sets in a plane (a UI node's `UiTransform::rotation`): the angle
    /// alone, the axis ignored. A non-finite angle gives the identity, as for
    /// [`rotation`](Self::rotation).
    #[inline]
    #[must_use]
    pub fn plane_rotation(&self) -> Rot2 {
        if self.angle.is_finite() {
            Rot2::radians(self.angle)
        } else {
            Rot2::IDENTITY
        }
    }
}

spring_property!(
    /// [`Spin::angle`], in radians. It rests within a thousandth of a radian (0.06°) and a
    /// hundredth of a radian per second, as [`Rotation`](crate::transform::Rotation).
    pub SpinAngle: Spin::angle as Linear<f32>
);

/// A spring on [`Spin::angle`]: whole turns, see [`Spin`].
pub type SpinAngleSpring = PropertySpring<SpinAngle>;

/// Sets `Transform::rotation` from each [`Spin`] that changed, writing only a rotation that
/// differs.
fn apply_spin(mut spins: Query<(&Spin, &mut Transform), Changed<Spin>>) {
    for (spin, mut transform) in &mut spins {
        let rotation = spin.rotation();
        if transform.rotation != rotation {
            transform.rotation = rotation;
        }
    }
}

/// Sets `UiTransform::rotation` from each [`Spin`] that changed (the angle in the node's plane:
/// clockwise on screen, as `UiTransform`'s y axis points down), writing only a rotation that
/// differs.
#[cfg(feature = "ui")]
fn apply_ui_spin(mut spins: Query<(&Spin, &mut UiTransform), Changed<Spin>>) {
    for (spin, mut transform) in &mut spins {
        let rotation = spin.plane_rotation();
        if transform.rotation != rotation {
            transform.rotation = rotation;
        }
    }
}

/// [`Spin`]: whole turns (part of [`SpringPlugins`](crate::SpringPlugins), which also adds the
/// [`SpinAngle`] property its spring moves, in
/// [`SpringTransformPlugin`](crate::SpringTransformPlugin)).
/// A spin sets the rotation right after its spring stepped, in the spin property's
/// [`SpringPhase::Observe`], so it is ordered with every other property that writes a
/// `Transform`.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringSpinPlugin;

impl Plugin for SpringSpinPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<Spin>();
        let springs = [TypeId::of::<PropertySpring<SpinAngle>>()];
        add_property_systems(app, &springs, |schedule| {
            schedule.add_systems(
                apply_spin
                    .in_set(PropertySystems::<SpinAngle>::phase(SpringPhase::Observe))
                    .run_if(any_with_component::<Spin>),
            );
            #[cfg(feature = "ui")]
            schedule.add_systems(
                apply_ui_spin
                    .in_set(PropertySystems::<SpinAngle>::phase(SpringPhase::Observe))
                    .run_if(any_with_component::<Spin>),
            );
        });
    }
}
