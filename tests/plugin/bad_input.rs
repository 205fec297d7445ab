//! NaN and infinity are refused and never reach a component.

use bevy::prelude::*;
use bevy::reflect::PartialReflect;
use bevy_sprung::SpringInputError;
use bevy_sprung::prelude::*;

use crate::harness::{app, run, spawn_translation, translation, translation_spring};

#[test]
fn non_finite_targets_and_impulses_are_refused_and_the_state_kept() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ZERO, Vec3::X * 10.0);
    run(&mut app, 5);
    let before = translation_spring(&app, entity);
    let mut spring = app
        .world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap();
    for bad in [
        Vec3::NAN,
        Vec3::new(f32::INFINITY, 0.0, 0.0),
        Vec3::new(0.0, f32::NEG_INFINITY, 1.0),
    ] {
        assert_eq!(
            spring.set_target(bad),
            Err(SpringInputError::NonFiniteTarget)
        );
        assert_eq!(
            spring.add_impulse(bad),
            Err(SpringInputError::NonFiniteVelocity)
        );
        assert_eq!(
            spring.set_velocity(bad),
            Err(SpringInputError::NonFiniteVelocity)
        );
        assert_eq!(
            spring.set_target_velocity(bad),
            Err(SpringInputError::NonFiniteVelocity)
        );
    }
    // A finite impulse whose sum overflows is refused too.
    assert_eq!(spring.add_impulse(Vec3::X * f32::MAX), Ok(()));
    assert_eq!(
        spring.add_impulse(Vec3::X * f32::MAX),
        Err(SpringInputError::NonFiniteVelocity)
    );
    let _ = spring.set_velocity(before.velocity());
    assert_eq!(spring.target(), before.target());
    assert_eq!(spring.velocity(), before.velocity());
    run(&mut app, 600);
    assert_eq!(translation(&app, entity), Vec3::X * 10.0);
}

/// Reflection (an inspector, a scene file) bypasses the setters: the step refuses the value,
/// keeps the last valid target, and never writes a NaN.
#[test]
fn a_nan_target_written_through_reflection_is_refused_by_the_step() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ZERO, Vec3::X * 10.0);
    run(&mut app, 5);
    {
        let mut spring = app
            .world_mut()
            .get_mut::<TranslationSpring>(entity)
            .unwrap();
        let field = spring
            .reflect_mut()
            .as_struct()
            .unwrap()
            .field_mut("target")
            .unwrap();
        field.apply(&Vec3::NAN as &dyn PartialReflect);
    }
    for _ in 0..600 {
        app.update();
        assert!(translation(&app, entity).is_finite());
    }
    assert_eq!(translation(&app, entity), Vec3::X * 10.0);
    assert_eq!(translation_spring(&app, entity).target(), Vec3::X * 10.0);
}

/// Spring parameters made invalid through reflection stop the spring instead of producing NaN.
#[test]
fn invalid_parameters_written_through_reflection_do_not_step() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ZERO, Vec3::X * 10.0);
    run(&mut app, 5);
    let held = translation(&app, entity);
    {
        let mut spring = app
            .world_mut()
            .get_mut::<TranslationSpring>(entity)
            .unwrap();
        let parameters = spring
            .reflect_mut()
            .as_struct()
            .unwrap()
            .field_mut("spring")
            .unwrap()
            .reflect_mut()
            .as_struct()
            .unwrap()
            .field_mut("mass")
            .unwrap();
        parameters.apply(&-1.0_f32 as &dyn PartialReflect);
    }
    run(&mut app, 30);
    assert_eq!(translation(&app, entity), held);
}

#[test]
fn a_spring_created_with_a_nan_target_holds_still() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ONE, Vec3::NAN);
    run(&mut app, 30);
    assert_eq!(translation(&app, entity), Vec3::ONE);
    assert_eq!(translation_spring(&app, entity).target(), Vec3::ONE);
}
