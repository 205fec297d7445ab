//! NaN and infinity are refused and never reach a component; faults never freeze a spring.

use bevy::ecs::component::Mutable;
use bevy::prelude::*;
use bevy::reflect::PartialReflect;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringInputError;
use bevy_sprung::spring::SpringMotion;

use crate::harness::{
    app, asleep, assert_move_alike, motion, run, spawn_translation, translation, translation_spring,
};

const BAD: [Vec3; 3] = [
    Vec3::NAN,
    Vec3::new(f32::INFINITY, 0.0, 0.0),
    Vec3::new(0.0, f32::NEG_INFINITY, 1.0),
];

#[test]
fn non_finite_targets_and_impulses_are_refused_and_the_state_kept() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ZERO, Vec3::X * 10.0);
    // A twin that gets none of the bad inputs.
    let twin = spawn_translation(&mut app, Spring::wobbly(), Vec3::ZERO, Vec3::X * 10.0);
    run(&mut app, 5);
    let before = translation_spring(&app, entity);
    let velocity = motion::<Translation>(&app, entity).velocity();
    let mut spring = app
        .world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap();
    for bad in BAD {
        assert_eq!(
            spring.try_set_target(bad),
            Err(SpringInputError::NonFiniteTarget)
        );
        assert_eq!(
            spring.try_add_impulse(bad),
            Err(SpringInputError::NonFiniteVelocity)
        );
        assert_eq!(
            spring.try_set_velocity(bad),
            Err(SpringInputError::NonFiniteVelocity)
        );
        assert_eq!(
            spring.try_set_target_velocity(bad),
            Err(SpringInputError::NonFiniteVelocity)
        );
        // The infallible forms refuse the same values, and so does the retarget-if-changed.
        spring.set_target(bad);
        spring.add_impulse(bad);
        spring.set_velocity(bad);
        spring.set_target_velocity(bad);
        assert!(!spring.set_target_if_neq(bad));
    }
    // A finite impulse whose sum overflows is refused too.
    assert_eq!(spring.try_add_impulse(Vec3::X * f32::MAX), Ok(()));
    assert_eq!(
        spring.try_add_impulse(Vec3::X * f32::MAX),
        Err(SpringInputError::NonFiniteVelocity)
    );
    // Setting the velocity it has replaces the impulse that was accepted.
    spring.set_velocity(velocity);
    assert_eq!(spring.target(), before.target());
    assert_eq!(spring.target_velocity(), Vec3::ZERO);
    app.world_mut()
        .get_mut::<TranslationSpring>(twin)
        .unwrap()
        .set_velocity(velocity);
    // Nothing of the refused inputs is left: the spring moves exactly as its twin.
    assert_move_alike(&mut app, (entity, twin), 30);
    run(&mut app, 600);
    assert_eq!(translation(&app, entity), Vec3::X * 10.0);
}

/// Writes `value` into the named field of the entity's component `C` (a translation spring or
/// its motion) by reflection, as an inspector or a scene would: the setters are bypassed.
pub(crate) fn write_by_reflection<C: Component<Mutability = Mutable> + Reflect>(
    world: &mut World,
    entity: Entity,
    path: &[&str],
    value: &dyn PartialReflect,
) {
    let mut spring = world.get_mut::<C>(entity).unwrap();
    let mut field = spring
        .reflect_mut()
        .as_struct()
        .unwrap()
        .field_mut(path[0])
        .unwrap();
    for name in &path[1..] {
        field = field
            .reflect_mut()
            .as_struct()
            .unwrap()
            .field_mut(name)
            .unwrap();
    }
    field.apply(value);
}

/// Runs up to ten seconds, asserting the translation finite every frame, and returns whether the
/// spring came to rest on `target`.
fn finite_until_rest(app: &mut App, entity: Entity, target: Vec3) -> bool {
    for _ in 0..600 {
        app.update();
        assert!(translation(app, entity).is_finite());
        if asleep::<Translation>(app, entity) {
            return translation(app, entity) == target;
        }
    }
    false
}

/// Reflection (an inspector, a scene file) bypasses the setters: the step refuses the value,
/// keeps the last valid target, and never writes a NaN.
#[test]
fn a_nan_target_written_through_reflection_is_refused_by_the_step() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ZERO, Vec3::X * 10.0);
    run(&mut app, 5);
    write_by_reflection::<TranslationSpring>(app.world_mut(), entity, &["target"], &Vec3::NAN);
    assert!(finite_until_rest(&mut app, entity, Vec3::X * 10.0));
    assert_eq!(translation_spring(&app, entity).target(), Vec3::X * 10.0);
}

/// Invalid spring parameters written through reflection are replaced by the last valid ones
/// (with a warning): the spring goes on as before and arrives, never frozen and never NaN.
#[test]
fn invalid_parameters_written_through_reflection_are_replaced_by_the_last_valid_ones() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ZERO, Vec3::X * 10.0);
    run(&mut app, 5);
    let held = translation(&app, entity);
    write_by_reflection::<TranslationSpring>(
        app.world_mut(),
        entity,
        &["spring", "mass"],
        &-1.0_f32,
    );
    app.update();
    assert_ne!(translation(&app, entity), held, "the spring froze");
    assert_eq!(*translation_spring(&app, entity).spring(), Spring::wobbly());
    assert!(finite_until_rest(&mut app, entity, Vec3::X * 10.0));
}

/// An infinite or NaN velocity written through reflection is reset to zero (with a warning):
/// the spring goes on from where it is and arrives.
#[test]
fn a_non_finite_velocity_written_through_reflection_is_reset() {
    for bad in BAD {
        let mut app = app(60);
        let entity = spawn_translation(&mut app, Spring::snappy(), Vec3::ZERO, Vec3::X * 10.0);
        run(&mut app, 5);
        write_by_reflection::<SpringMotion<Translation>>(
            app.world_mut(),
            entity,
            &["velocity"],
            &bad,
        );
        assert!(finite_until_rest(&mut app, entity, Vec3::X * 10.0), "{bad}");
    }
}

/// A step whose exact result leaves `f32` (a velocity of 3e38 toward a far target) is not
/// dropped: the state is held at the largest finite values and the spring comes back.
#[test]
fn a_step_that_overflows_keeps_a_finite_state_and_comes_back() {
    let mut app = app(60);
    let target = Vec3::new(-1000.0, 0.0, 5.0);
    let entity = spawn_translation(&mut app, Spring::snappy(), Vec3::X * 3e38, target);
    app.world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap()
        .set_velocity(Vec3::X * 3e38);
    run(&mut app, 2);
    let velocity = motion::<Translation>(&app, entity).velocity();
    assert!(translation(&app, entity).is_finite() && velocity.is_finite());
    assert!(finite_until_rest(&mut app, entity, target));
}

/// States on both sides of where the usual step stops and the general one (which redoes an
/// overflowing step) takes over, far beyond any scene: a stiff, nearly undamped spring and an
/// ordinary one, from `10¹⁵` to `10³⁸` with velocities as large, stay finite every frame and
/// arrive.
#[test]
fn states_across_the_usual_steps_range_stay_finite_and_arrive() {
    let stiff = Spring::from_natural_frequency(1.0e4, 0.05).unwrap();
    for spring in [Spring::snappy(), stiff] {
        for start in [1.0e15_f32, 1.0e18, 3.0e19, 1.0e25, 1.0e38] {
            for speed in [0.0, start, -start] {
                let mut app = app(60);
                let target = Vec3::new(-1000.0, 0.0, 5.0);
                let entity = spawn_translation(&mut app, spring, Vec3::X * start, target);
                app.world_mut()
                    .get_mut::<TranslationSpring>(entity)
                    .unwrap()
                    .set_velocity(Vec3::new(speed, -speed, 0.0));
                assert!(
                    finite_until_rest(&mut app, entity, target),
                    "{spring:?} from {start} at {speed}"
                );
            }
        }
    }
}

/// Something writes NaN into the sprung `Transform` itself: the spring restores it from its own
/// state instead of reading the NaN, and arrives.
#[test]
fn a_nan_written_into_the_property_is_overwritten() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::gentle(), Vec3::ZERO, Vec3::Y * 10.0);
    run(&mut app, 5);
    app.world_mut()
        .get_mut::<Transform>(entity)
        .unwrap()
        .translation = Vec3::NAN;
    app.update();
    assert!(translation(&app, entity).is_finite());
    assert!(finite_until_rest(&mut app, entity, Vec3::Y * 10.0));
}

#[test]
fn a_spring_created_with_a_nan_target_holds_still() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::wobbly(), Vec3::ONE, Vec3::NAN);
    run(&mut app, 30);
    assert_eq!(translation(&app, entity), Vec3::ONE);
    assert_eq!(translation_spring(&app, entity).target(), Vec3::ONE);
}
