//! Springs of entities disabled for a while (Bevy's `Disabled`, which hides them from every
//! query, the stepping system's too) take up what changed meanwhile when they are enabled: the
//! stepping system ran without them, so "changed since its last run" is not "changed since the
//! spring's last step".

use bevy::ecs::entity_disabling::Disabled;
use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringAsleep;

use crate::harness::{
    app, asleep, assert_stepped_from, many_translations, motion, run, translation,
};

/// Many springs in one table, so that the one disabled and enabled again shares its blocks
/// of rows with springs that were stepped all along (and the systems run while it is
/// disabled: they run only where there are springs); the middle one, after `frames`.
fn springs(app: &mut App, spring: Spring, target: Vec3, frames: u32) -> Entity {
    let springs = many_translations(app, spring, target);
    run(app, frames);
    springs[500]
}

/// Two frames with `C` inserted on the entity (out of the systems' sight), `change` applied,
/// two frames more, and `C` removed (not yet a frame after).
fn while_away<C: Component + Default>(
    app: &mut App,
    entity: Entity,
    change: impl FnOnce(EntityWorldMut),
) {
    app.world_mut().entity_mut(entity).insert(C::default());
    run(app, 2);
    change(app.world_mut().entity_mut(entity));
    run(app, 2);
    app.world_mut().entity_mut(entity).remove::<C>();
}

/// A spring retargeted while disabled heads for the new target from its first frame enabled
/// (the exact step toward it from the state it had), and arrives.
#[test]
fn a_target_set_while_disabled_is_headed_for() {
    let mut app = app(60);
    let spring = Spring::from_natural_frequency(10.0, 0.6).unwrap();
    let entity = springs(&mut app, spring, Vec3::new(3.0, 2.0, 4.0), 10);
    let (at, velocity) = (
        translation(&app, entity),
        motion::<Translation>(&app, entity).velocity(),
    );
    assert!(velocity.length() > 1.0, "still moving: {velocity}");
    let new_target = Vec3::new(-50.0, 7.0, 1.0);
    while_away::<Disabled>(&mut app, entity, |mut entity| {
        entity
            .get_mut::<TranslationSpring>()
            .unwrap()
            .set_target(new_target);
    });
    app.update();
    assert_stepped_from(&app, entity, spring, (at, velocity), new_target);
    run(&mut app, 600);
    assert_eq!(translation(&app, entity), new_target);
    assert!(asleep::<Translation>(&app, entity));
}

/// A value written while the spring's entity was disabled is sprung on from where it was
/// put, with the velocity the spring had: the first frame after enabling is the exact step
/// from there.
#[test]
fn a_value_written_while_disabled_is_sprung_on_from_where_it_was_put() {
    let mut app = app(60);
    let spring = Spring::from_natural_frequency(10.0, 0.6).unwrap();
    let target = Vec3::new(3.0, 2.0, 4.0);
    let entity = springs(&mut app, spring, target, 10);
    let velocity = motion::<Translation>(&app, entity).velocity();
    assert!(velocity.length() > 1.0, "still moving: {velocity}");
    let put = Vec3::new(2.5, 0.5, 1.5);
    while_away::<Disabled>(&mut app, entity, |mut entity| {
        entity.get_mut::<Transform>().unwrap().translation = put;
    });
    app.update();
    assert_stepped_from(&app, entity, spring, (put, velocity), target);
}

/// A spring asleep when its entity was disabled, retargeted meanwhile, wakes once enabled and
/// arrives.
#[test]
fn a_sleeping_spring_retargeted_while_disabled_wakes() {
    let mut app = app(60);
    let entity = springs(&mut app, Spring::snappy(), Vec3::ONE, 600);
    assert!(asleep::<Translation>(&app, entity));
    let new_target = Vec3::new(-5.0, 7.0, 1.0);
    while_away::<Disabled>(&mut app, entity, |mut entity| {
        entity
            .get_mut::<TranslationSpring>()
            .unwrap()
            .set_target(new_target);
    });
    run(&mut app, 600);
    assert_eq!(translation(&app, entity), new_target);
}

/// A moving spring put to sleep by hand (its `SpringAsleep` inserted, as a scene could) holds
/// still; its value written meanwhile wakes it, and it is sprung on from where the value was
/// put, with the velocity it had.
#[test]
fn a_spring_put_to_sleep_by_hand_takes_up_what_was_written_meanwhile() {
    let mut app = app(60);
    let spring = Spring::from_natural_frequency(10.0, 0.6).unwrap();
    let target = Vec3::new(3.0, 2.0, 4.0);
    let entity = springs(&mut app, spring, target, 10);
    let velocity = motion::<Translation>(&app, entity).velocity();
    let held = translation(&app, entity);
    app.world_mut()
        .entity_mut(entity)
        .insert(SpringAsleep::<Translation>::default());
    run(&mut app, 2);
    assert_eq!(translation(&app, entity), held, "asleep, it does not move");
    assert!(asleep::<Translation>(&app, entity));
    let put = Vec3::new(2.5, 0.5, 1.5);
    app.world_mut()
        .get_mut::<Transform>(entity)
        .unwrap()
        .translation = put;
    app.update();
    assert!(!asleep::<Translation>(&app, entity), "the write wakes it");
    assert_stepped_from(&app, entity, spring, (put, velocity), target);
}

/// A sleeping spring whose property was written while its entity was disabled (its component
/// removed and inserted again, here) springs back to its target once enabled.
#[test]
fn a_sleeping_spring_whose_value_was_written_while_disabled_springs_back() {
    let mut app = app(60);
    let target = Vec3::new(3.0, 2.0, 4.0);
    let entity = springs(&mut app, Spring::snappy(), target, 600);
    assert!(asleep::<Translation>(&app, entity));
    while_away::<Disabled>(&mut app, entity, |mut entity| {
        entity.remove::<Transform>();
        entity.insert(Transform::from_xyz(-1.0, 0.0, 0.0));
    });
    app.update();
    assert!(!asleep::<Translation>(&app, entity));
    run(&mut app, 600);
    assert_eq!(translation(&app, entity), target);
}
