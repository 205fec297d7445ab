//! Where the systems run: before transform propagation, without ambiguities.

use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::{LogLevel, ScheduleBuildSettings, ScheduleLabel, Schedules};
use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringUpdate;

use crate::harness::{app, run};

/// `GlobalTransform` is propagated from the sprung `Transform` in the same frame, for roots
/// and for children of sprung parents.
#[test]
fn global_transform_agrees_in_the_same_frame() {
    let mut app = app(60);
    let parent = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::bouncy(), Vec3::new(10.0, 0.0, 0.0)),
            RotationSpring::new(Spring::bouncy(), Quat::from_rotation_z(1.0)),
        ))
        .id();
    let child = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::new(0.0, 5.0, 0.0)),
            ChildOf(parent),
        ))
        .id();
    for _ in 0..40 {
        app.update();
        let world = app.world();
        let parent_local = *world.get::<Transform>(parent).unwrap();
        let child_local = *world.get::<Transform>(child).unwrap();
        let parent_global = world.get::<GlobalTransform>(parent).unwrap();
        let child_global = world.get::<GlobalTransform>(child).unwrap();
        assert!(
            parent_global
                .translation()
                .distance(parent_local.translation)
                < 1e-5
        );
        let expected = parent_local.mul_transform(child_local);
        assert!(child_global.translation().distance(expected.translation) < 1e-4);
    }
}

/// Bevy's ambiguity detection finds no pair of systems involving the plugin's that could run in
/// either order while touching the same data.
#[test]
fn no_ambiguities_with_the_plugins_systems() {
    let mut app = app(60);
    // A user property on Transform as well: it must be ordered against the built-in ones.
    app.add_plugins(SpringPropertyPlugin::<crate::properties::ScaleX>::default());
    for label in [PostUpdate.intern(), SpringUpdate.intern()] {
        app.edit_schedule(label, |schedule| {
            schedule.set_build_settings(ScheduleBuildSettings {
                ambiguity_detection: LogLevel::Warn,
                ..default()
            });
        });
    }
    app.world_mut().spawn((
        Transform::default(),
        TranslationSpring::new(Spring::snappy(), Vec3::X),
        RotationSpring::new(Spring::snappy(), Quat::from_rotation_y(0.5)),
        ScaleSpring::new(Spring::snappy(), Vec3::splat(2.0)),
        PropertySpring::<crate::properties::ScaleX>::new(Spring::snappy(), 3.0),
    ));
    run(&mut app, 3);
    // The names are there to be matched (Bevy's `debug` feature), so the check is not vacuous.
    assert!(spring_system_runs(&app).len() >= 10);
    let world = app.world();
    for label in [PostUpdate.intern(), SpringUpdate.intern()] {
        let schedule = world.resource::<Schedules>().get(label).unwrap();
        // Named through the executable schedule: the graph's conflict list may also hold a sync
        // point Bevy has since replaced (its key is gone and `to_string` would panic on it).
        let names: std::collections::HashMap<_, _> = schedule
            .systems()
            .unwrap()
            .map(|(key, system)| (key, system.name().to_string()))
            .collect();
        let ours: Vec<_> = schedule
            .graph()
            .conflicting_systems()
            .iter()
            .filter_map(|(a, b, _)| Some((names.get(a)?, names.get(b)?)))
            .filter(|(a, b)| a.contains("bevy_sprung") || b.contains("bevy_sprung"))
            .collect();
        assert!(ours.is_empty(), "ambiguities in {label:?}: {ours:#?}");
    }
}

/// The schedules the plugin's systems run in: `PreUpdate` (interaction states, shakes taken
/// off), `PostUpdate` (the spring schedule's runner, choreography, juice) and [`SpringUpdate`]
/// (the properties' systems).
fn spring_schedules() -> [Interned<dyn ScheduleLabel>; 3] {
    [
        PreUpdate.intern(),
        PostUpdate.intern(),
        SpringUpdate.intern(),
    ]
}

/// The last-run ticks of the plugin's systems in [`spring_schedules`].
fn spring_system_runs(app: &App) -> Vec<(String, u32)> {
    let schedules = app.world().resource::<Schedules>();
    spring_schedules()
        .into_iter()
        // A schedule that never ran (the spring schedule, before any spring) has no systems.
        .filter_map(|label| schedules.get(label).unwrap().systems().ok())
        .flatten()
        .filter(|(_, system)| system.name().to_string().contains("bevy_sprung"))
        .map(|(_, system)| (system.name().to_string(), system.get_last_run().get()))
        .collect()
}

/// With the plugin and no springs, no property's systems are even in a schedule and none of
/// the plugin's systems runs (their run conditions skip them); spawning a spring brings in and
/// runs its property's systems, and only those.
#[test]
fn no_springs_no_work() {
    let mut app = app(60);
    run(&mut app, 2);
    let idle = spring_system_runs(&app);
    assert!(idle.len() >= 5, "{idle:?}");
    let in_spring_update = |app: &App| {
        let schedules = app.world().resource::<Schedules>();
        schedules.get(SpringUpdate).unwrap().systems_len()
    };
    assert_eq!(
        in_spring_update(&app),
        0,
        "property systems without springs"
    );
    run(&mut app, 5);
    assert_eq!(
        spring_system_runs(&app),
        idle,
        "a spring system ran without springs"
    );
    app.world_mut().spawn((
        Transform::default(),
        TranslationSpring::new(Spring::snappy(), Vec3::X),
    ));
    // The first frame brings the systems in; which run is seen over the next.
    run(&mut app, 1);
    let before = spring_system_runs(&app);
    run(&mut app, 1);
    let busy = spring_system_runs(&app);
    let ran: Vec<_> = busy
        .iter()
        .zip(&before)
        .filter(|(a, b)| a.1 != b.1)
        .map(|(a, _)| a.0.as_str())
        .collect();
    // The spring schedule's runner, and the translation springs' wake and step.
    assert_eq!(ran.len(), 3, "{ran:?}");
    assert!(
        ran.iter().any(|name| name.contains("run_spring_update")),
        "{ran:?}"
    );
    assert_eq!(
        ran.iter()
            .filter(|name| name.contains("Translation") && name.contains("_springs"))
            .count(),
        2,
        "only the translation systems run: {ran:?}"
    );
    // Only translation's systems (and the followers', which move translation springs) came in.
    let added: Vec<_> = busy
        .iter()
        .filter(|(name, _)| !idle.iter().any(|(idle_name, _)| idle_name == name))
        .map(|(name, _)| name.as_str())
        .collect();
    assert!(in_spring_update(&app) >= 3, "{added:?}");
    assert!(
        added
            .iter()
            .all(|name| name.contains("Translation") || name.contains("follow")),
        "{added:?}"
    );
}

/// Adding a property's plugin again (a library and the app both asking for it) changes nothing:
/// the spring is still stepped once per frame.
#[test]
fn adding_a_property_twice_is_harmless() {
    let spring = Spring::from_natural_frequency(6.0, 0.5).unwrap();
    let mut app = app(60);
    app.add_plugins(SpringPropertyPlugin::<Translation>::default());
    let entity = crate::harness::spawn_translation(&mut app, spring, Vec3::ZERO, Vec3::X * 10.0);
    run(&mut app, 20);
    let expected =
        crate::harness::exact(&spring, 0.0, 10.0, crate::harness::elapsed(&app)).position;
    let x = f64::from(crate::harness::translation(&app, entity).x);
    assert!((x - expected).abs() < 1e-4, "{x} vs {expected}");
}

/// A spring on a new property added while the spring schedule runs (an observer of another
/// spring settling) brings its property's systems in for the next frame, and arrives.
#[test]
fn a_first_spring_added_during_the_spring_schedule_moves_from_the_next_frame() {
    let mut app = app(60);
    app.add_observer(
        |settled: On<SpringSettled<Translation>>, mut commands: Commands| {
            commands
                .entity(settled.entity)
                .insert(ScaleSpring::new(Spring::snappy(), Vec3::splat(3.0)));
        },
    );
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::X),
        ))
        .id();
    run(&mut app, 300);
    let world = app.world();
    assert!(
        world.get::<ScaleSpring>(entity).is_some(),
        "the observer ran"
    );
    assert!(
        world.get::<SpringAsleep<Scale>>(entity).is_some(),
        "the scale spring settled"
    );
    assert_eq!(
        world.get::<Transform>(entity).unwrap().scale,
        Vec3::splat(3.0)
    );
}
