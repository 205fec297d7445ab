//! Spins: whole turns, which a rotation spring cannot express.

use core::f32::consts::TAU;

use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spin::SpinAngle;
use bevy_sprung::spin::{Spin, SpinAngleSpring};

use crate::harness::{app, asleep, run};

/// The signed angle about z from `from` to `to`, in (−π, π]: a frame's turn.
fn turn_about_z(from: Quat, to: Quat) -> f32 {
    let delta = from.inverse() * to;
    let (axis, angle) = delta.to_axis_angle();
    if angle == 0.0 {
        0.0
    } else {
        angle * axis.z.signum()
    }
}

/// A critically damped spin to two turns turns the rotation through both turns, forward every
/// frame, and lands on the angle exactly; a rotation spring to the same orientation would not
/// move at all.
#[test]
fn a_spin_turns_through_whole_turns_and_lands_exactly() {
    let spring = Spring::from_natural_frequency(10.0, 1.0).unwrap();
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            Spin::z(0.0),
            SpinAngleSpring::new(spring, 2.0 * TAU),
        ))
        .id();
    let mut previous = Quat::IDENTITY;
    let mut turned = 0.0_f32;
    for frame in 0..240 {
        app.update();
        let rotation = app.world().get::<Transform>(entity).unwrap().rotation;
        let turn = turn_about_z(previous, rotation);
        assert!(turn >= -1e-6, "frame {frame}: turned back by {turn}");
        turned += turn;
        previous = rotation;
        let spin = app.world().get::<Spin>(entity).unwrap();
        assert_eq!(rotation, spin.rotation(), "frame {frame}");
    }
    assert!((turned - 2.0 * TAU).abs() < 1e-3, "turned {turned} rad");
    assert_eq!(app.world().get::<Spin>(entity).unwrap().angle, 2.0 * TAU);
    assert!(asleep::<SpinAngle>(&app, entity));
}

/// Once the spin sleeps, neither it nor the `Transform` is written.
#[test]
fn a_resting_spin_writes_nothing() {
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            Spin::new(Dir3::X, 0.0),
            SpinAngleSpring::new(Spring::snappy(), TAU),
        ))
        .id();
    run(&mut app, 300);
    assert!(asleep::<SpinAngle>(&app, entity));
    let before = app
        .world()
        .entity(entity)
        .get_ref::<Transform>()
        .unwrap()
        .last_changed();
    run(&mut app, 10);
    let world = app.world();
    assert_eq!(
        world
            .entity(entity)
            .get_ref::<Transform>()
            .unwrap()
            .last_changed(),
        before
    );
    // Retargeting wakes it and turns it on.
    app.world_mut()
        .get_mut::<SpinAngleSpring>(entity)
        .unwrap()
        .set_target(2.0 * TAU);
    run(&mut app, 2);
    let spin = app.world().get::<Spin>(entity).unwrap();
    assert!(spin.angle > TAU && spin.angle < 2.0 * TAU, "{spin:?}");
}

/// On a UI node a spin turns `UiTransform::rotation`.
#[test]
fn a_spin_turns_a_ui_node() {
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            UiTransform::default(),
            Spin::z(0.0),
            SpinAngleSpring::new(Spring::smooth(), -TAU),
        ))
        .id();
    run(&mut app, 10);
    let angle = app.world().get::<Spin>(entity).unwrap().angle;
    assert!(angle < -0.1 && angle > -TAU, "{angle}");
    let rotation = app.world().get::<UiTransform>(entity).unwrap().rotation;
    assert_eq!(rotation, Rot2::radians(angle));
    run(&mut app, 600);
    assert_eq!(app.world().get::<Spin>(entity).unwrap().angle, -TAU);
    assert_eq!(
        app.world().get::<UiTransform>(entity).unwrap().rotation,
        Rot2::radians(-TAU)
    );
}
