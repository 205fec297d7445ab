//! Springs at rest sleep: no writes, no iteration, one settle event, and they wake on demand.

use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::{SpringMotion, SpringSystems};

use crate::harness::{app, asleep, run, spawn_translation, translation};

/// Entities whose `Transform` changed since the last frame, seen right after the springs ran.
#[derive(Resource, Default)]
struct ChangedTransforms(Vec<Entity>);

/// Entities whose translation spring was stepped since the last frame (its motion changed).
#[derive(Resource, Default)]
struct ChangedSprings(Vec<Entity>);

/// Entities whose translation spring's configuration changed since the last frame.
#[derive(Resource, Default)]
struct ChangedConfigurations(Vec<Entity>);

fn record_changes(
    mut transforms: ResMut<ChangedTransforms>,
    mut springs: ResMut<ChangedSprings>,
    mut configurations: ResMut<ChangedConfigurations>,
    changed: Query<Entity, Changed<Transform>>,
    changed_springs: Query<Entity, Changed<SpringMotion<Translation>>>,
    changed_configurations: Query<Entity, Changed<TranslationSpring>>,
) {
    transforms.0 = changed.iter().collect();
    springs.0 = changed_springs.iter().collect();
    configurations.0 = changed_configurations.iter().collect();
}

fn recording_app() -> App {
    let mut app = app(60);
    app.init_resource::<ChangedTransforms>()
        .init_resource::<ChangedSprings>()
        .init_resource::<ChangedConfigurations>()
        .add_systems(PostUpdate, record_changes.after(SpringSystems));
    app
}

#[test]
fn a_sleeping_spring_writes_nothing_and_is_not_iterated() {
    let mut app = recording_app();
    let resting = spawn_translation(&mut app, Spring::stiff(), Vec3::ZERO, Vec3::X);
    let moving = spawn_translation(&mut app, Spring::molasses(), Vec3::ZERO, Vec3::X * 1e4);
    run(&mut app, 240);
    assert!(asleep::<Translation>(&app, resting));
    assert!(!asleep::<Translation>(&app, moving));
    for _ in 0..30 {
        app.update();
        let transforms = &app.world().resource::<ChangedTransforms>().0;
        let springs = &app.world().resource::<ChangedSprings>().0;
        assert!(
            !transforms.contains(&resting),
            "a sleeping spring wrote its Transform"
        );
        assert!(!springs.contains(&resting), "a sleeping spring was stepped");
        assert!(transforms.contains(&moving) && springs.contains(&moving));
        // Stepping reads the configuration; only its owner's changes mark it.
        let configurations = &app.world().resource::<ChangedConfigurations>().0;
        assert!(
            configurations.is_empty(),
            "stepping marked {configurations:?}"
        );
    }
    assert_eq!(translation(&app, resting), Vec3::X);
}

/// The same in a scene large enough (3000 springs, more than a chunk of 2048) that it steps in
/// chunks split over the compute pool's thread and the calling one, which mark the motions and
/// the properties they step: every moving spring is marked stepped and its `Transform`
/// changed, no sleeping one.
#[test]
fn springs_stepped_in_chunks_are_all_marked_and_sleeping_ones_not() {
    let mut app = recording_app();
    assert!(bevy::tasks::ComputeTaskPool::get().thread_num() >= 1);
    let (mut resting, mut moving) = (Vec::new(), Vec::new());
    for i in 0..3000_u16 {
        let target = Vec3::splat(f32::from(i));
        if i % 3 == 0 {
            resting.push(spawn_translation(
                &mut app,
                Spring::stiff(),
                Vec3::ZERO,
                target,
            ));
        } else {
            let far = target * 1e3;
            moving.push(spawn_translation(
                &mut app,
                Spring::molasses(),
                Vec3::ZERO,
                far,
            ));
        }
    }
    run(&mut app, 240);
    assert!(
        resting
            .iter()
            .all(|&entity| asleep::<Translation>(&app, entity))
    );
    for _ in 0..3 {
        app.update();
        let transforms = &app.world().resource::<ChangedTransforms>().0;
        let springs = &app.world().resource::<ChangedSprings>().0;
        assert_eq!(springs.len(), moving.len(), "stepped springs");
        assert_eq!(transforms.len(), moving.len(), "changed transforms");
        let springs: std::collections::HashSet<Entity> = springs.iter().copied().collect();
        let transforms: std::collections::HashSet<Entity> = transforms.iter().copied().collect();
        assert!(moving.iter().all(|entity| springs.contains(entity)));
        assert!(moving.iter().all(|entity| transforms.contains(entity)));
    }
}

#[test]
fn setting_the_same_target_does_not_wake_it() {
    let mut app = recording_app();
    let entity = spawn_translation(&mut app, Spring::stiff(), Vec3::ZERO, Vec3::Y);
    run(&mut app, 240);
    assert!(asleep::<Translation>(&app, entity));
    app.world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap()
        .set_target(Vec3::Y);
    run(&mut app, 2);
    assert!(asleep::<Translation>(&app, entity));
    assert!(
        !app.world()
            .resource::<ChangedTransforms>()
            .0
            .contains(&entity)
    );
}

/// Among ten thousand sleeping springs in one table (several of the long stretches and short
/// blocks the waking system tests their change ticks in), exactly the retargeted ones wake:
/// at the first and last row, on both sides of block and stretch boundaries, and in the
/// short last stretch. Each arrives; none of the others moves.
#[test]
fn among_many_sleeping_springs_exactly_the_retargeted_ones_wake() {
    let mut app = recording_app();
    let count: u16 = 10_000;
    let springs: Vec<Entity> = (0..count)
        .map(|i| {
            let at = Vec3::X * f32::from(i);
            spawn_translation(&mut app, Spring::stiff(), at, at)
        })
        .collect();
    run(&mut app, 3);
    assert!(
        springs
            .iter()
            .all(|&entity| asleep::<Translation>(&app, entity))
    );
    let rows: [u16; 9] = [0, 255, 256, 4095, 4096, 4097, 8191, 8192, 9999];
    let target = |row: u16| Vec3::new(f32::from(row), 100.0, 0.0);
    for row in rows {
        app.world_mut()
            .get_mut::<TranslationSpring>(springs[usize::from(row)])
            .unwrap()
            .set_target(target(row));
    }
    app.update();
    let moved: std::collections::HashSet<Entity> = app
        .world()
        .resource::<ChangedTransforms>()
        .0
        .iter()
        .copied()
        .collect();
    let retargeted: std::collections::HashSet<Entity> =
        rows.iter().map(|&row| springs[usize::from(row)]).collect();
    assert_eq!(moved, retargeted, "the springs that moved");
    run(&mut app, 300);
    for (row, &entity) in (0..count).zip(&springs) {
        let expected = if rows.contains(&row) {
            target(row)
        } else {
            Vec3::X * f32::from(row)
        };
        assert_eq!(translation(&app, entity), expected, "row {row}");
        assert!(asleep::<Translation>(&app, entity), "row {row}");
    }
}

/// Counts settle events per entity.
#[derive(Resource, Default)]
struct Settled(Vec<Entity>);

#[test]
fn exactly_one_settle_event_per_settle() {
    let mut app = app(60);
    app.init_resource::<Settled>().add_observer(
        |settled: On<SpringSettled<Translation>>, mut log: ResMut<Settled>| {
            log.0.push(settled.entity);
        },
    );
    let a = spawn_translation(&mut app, Spring::snappy(), Vec3::ZERO, Vec3::X * 50.0);
    let b = spawn_translation(&mut app, Spring::slow(), Vec3::ZERO, Vec3::X * 50.0);
    let count = |app: &App, e: Entity| {
        app.world()
            .resource::<Settled>()
            .0
            .iter()
            .filter(|&&x| x == e)
            .count()
    };
    run(&mut app, 30);
    assert_eq!(
        (count(&app, a), count(&app, b)),
        (0, 0),
        "nothing has settled yet"
    );
    run(&mut app, 600);
    assert_eq!((count(&app, a), count(&app, b)), (1, 1));
    run(&mut app, 60);
    assert_eq!(
        (count(&app, a), count(&app, b)),
        (1, 1),
        "no repeat while asleep"
    );
    // Wake one: one more settle for it only.
    app.world_mut()
        .get_mut::<TranslationSpring>(a)
        .unwrap()
        .set_target(Vec3::ZERO);
    run(&mut app, 600);
    assert_eq!((count(&app, a), count(&app, b)), (2, 1));
}

/// The event also reaches an observer on the entity itself, as a tween's completion would.
#[test]
fn entity_observers_see_their_own_settle() {
    #[derive(Resource, Default)]
    struct Done(u32);
    let mut app = app(60);
    app.init_resource::<Done>();
    app.world_mut()
        .spawn((
            Transform::default(),
            ScaleSpring::new(Spring::snappy(), Vec3::splat(2.0)),
        ))
        .observe(|_: On<SpringSettled<Scale>>, mut done: ResMut<Done>| done.0 += 1);
    run(&mut app, 300);
    assert_eq!(app.world().resource::<Done>().0, 1);
}

/// Despawning a spring while it settles, or its marker racing a despawn, is harmless.
#[test]
fn despawned_springs_are_harmless() {
    let mut app = app(60);
    let entity = spawn_translation(&mut app, Spring::stiff(), Vec3::ZERO, Vec3::X);
    run(&mut app, 5);
    app.world_mut().despawn(entity);
    run(&mut app, 300);
}
