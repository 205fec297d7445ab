//! Where the systems run: before transform propagation, without ambiguities.

use bevy::ecs::intern::Interned;
use bevy::ecs::schedule::{LogLevel, ScheduleBuildSettings, ScheduleLabel, Schedules};
use bevy::prelude::*;
use bevy_sprung::choreography::SpringGroup;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringAsleep;
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
    let checked = [
        PreUpdate.intern(),
        PostUpdate.intern(),
        SpringUpdate.intern(),
    ];
    for label in checked {
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
    // What brings in the other systems that join with their first component: a group, juice,
    // a follower and a sequence.
    let leader = app.world_mut().spawn(Transform::default()).id();
    app.world_mut().spawn((
        Transform::default(),
        TranslationSpring::new(Spring::snappy(), Vec3::Y),
        SpringGroup::named("menu"),
        Shake::new(1),
        SquashStretch::new(0.01, 1.2),
        SpringFollow::new(leader, Vec3::ONE),
    ));
    app.world_mut().spawn((
        Transform::default(),
        TranslationSpring::new(Spring::snappy(), Vec3::Z),
        SpringSequence::<Translation>::new().then(Vec3::X),
    ));
    run(&mut app, 3);
    // The names are there to be matched (Bevy's `debug` feature), so the check is not vacuous.
    assert!(spring_system_runs(&app).len() >= 10);
    let world = app.world();
    for label in checked {
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

/// Every schedule the plugin's systems can join: `PreUpdate` (interaction states, shakes taken
/// off), `FixedPostUpdate` (followers' fixed-step targets), `PostUpdate` (the spring schedule's
/// runner, choreography, juice), [`SpringUpdate`] (the properties' systems), and `First` and
/// `Last` (where systems wait for a schedule that was running when they were needed).
fn spring_schedules() -> [Interned<dyn ScheduleLabel>; 6] {
    [
        First.intern(),
        PreUpdate.intern(),
        FixedPostUpdate.intern(),
        PostUpdate.intern(),
        SpringUpdate.intern(),
        Last.intern(),
    ]
}

/// The last-run ticks of the plugin's systems in [`spring_schedules`].
fn spring_system_runs(app: &App) -> Vec<(String, u32)> {
    let schedules = app.world().resource::<Schedules>();
    spring_schedules()
        .into_iter()
        // A schedule that never ran (the spring schedule, before any spring) has no systems.
        .filter_map(|label| schedules.get(label)?.systems().ok())
        .flatten()
        .filter(|(_, system)| system.name().to_string().contains("bevy_sprung"))
        .map(|(_, system)| (system.name().to_string(), system.get_last_run().get()))
        .collect()
}

/// With the plugin and no springs, none of the plugin's systems is in any schedule (nothing
/// runs, nothing is even skipped); spawning a spring brings in and runs its property's systems
/// and the spring schedule's runner, and only those.
#[test]
fn no_springs_no_work() {
    let mut app = app(60);
    run(&mut app, 2);
    // The check is not vacuous: Bevy's own systems are found by name in these schedules.
    let schedules = app.world().resource::<Schedules>();
    assert!(
        spring_schedules()
            .into_iter()
            .filter_map(|label| schedules.get(label)?.systems().ok())
            .flatten()
            .any(|(_, system)| system.name().to_string().contains("bevy_time")),
        "Bevy's systems are named"
    );
    assert_eq!(
        spring_system_runs(&app),
        Vec::new(),
        "systems without springs"
    );
    app.world_mut().spawn((
        Transform::default(),
        TranslationSpring::new(Spring::snappy(), Vec3::X),
    ));
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
    // The spring schedule's runner, and the translation springs' wake and step, and their
    // check for springs added without a `Transform`.
    assert_eq!(ran.len(), 4, "{ran:?}");
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
    assert!(
        ran.iter().any(|name| name.contains("misconfigured::warn_")
            && name.contains("Translation")
            && name.contains("Transform")),
        "{ran:?}"
    );
    // Only translation's systems came in, besides the runner: not those of sequences or
    // followers, which wait for their own first component.
    assert!(busy.len() >= 4, "{busy:?}");
    assert!(
        busy.iter().all(|(name, _)| (name.contains("Translation")
            && !name.contains("drive_sequences"))
            || name.contains("run_spring_update")),
        "{busy:?}"
    );
}

/// The largest distance of `entity`'s translation from `base` over the next `frames` frames.
fn largest_offset(app: &mut App, entity: Entity, base: Vec3, frames: u32) -> f32 {
    let mut largest = 0.0_f32;
    for _ in 0..frames {
        run(app, 1);
        let translation = app.world().get::<Transform>(entity).unwrap().translation;
        largest = largest.max(translation.distance(base));
    }
    largest
}

/// A shake added by a system of `PostUpdate`, the schedule its systems join (and which cannot
/// change while it runs), gets them from the next frame: it shakes, and calms back exactly to
/// where it was. Systems that waited so are added by one system in `First`, which is then
/// skipped.
#[test]
fn a_first_shake_added_while_its_schedule_runs_shakes_from_the_next_frame() {
    #[derive(Component)]
    struct ShakeMe;
    let mut app = app(60);
    app.add_systems(
        PostUpdate,
        |mut commands: Commands, marked: Query<Entity, With<ShakeMe>>| {
            for entity in &marked {
                let mut shake = Shake::new(3).with_max_translation(Vec3::splat(5.0));
                shake.add_trauma(1.0);
                commands.entity(entity).remove::<ShakeMe>().insert(shake);
            }
        },
    );
    let base = Vec3::new(10.0, 20.0, 0.0);
    let entity = app
        .world_mut()
        .spawn((Transform::from_translation(base), ShakeMe))
        .id();
    run(&mut app, 1);
    assert!(
        app.world().get::<Shake>(entity).is_some(),
        "the shake was added"
    );
    let moved = largest_offset(&mut app, entity, base, 10);
    assert!(moved > 0.5, "it shakes: {moved}");
    let runs = spring_system_runs(&app);
    let waiting: Vec<_> = runs
        .iter()
        .filter(|(name, _)| name.contains("install_ready_systems"))
        .collect();
    assert_eq!(waiting.len(), 1, "{runs:?}");
    run(&mut app, 300);
    let transform = app.world().get::<Transform>(entity).unwrap();
    assert_eq!(transform.translation, base);
    assert_eq!(transform.rotation, Quat::IDENTITY);
    assert_eq!(
        spring_system_runs(&app)
            .iter()
            .find(|(name, _)| name.contains("install_ready_systems")),
        waiting.first().copied(),
        "the installer is skipped once it has nothing to add"
    );
}

/// Springs and juice spawned into the world before the plugin is added (their hooks had no
/// plugin to tell) still bring in their systems: the spring arrives, and the shake shakes.
#[test]
fn springs_added_before_the_plugin_move() {
    let mut app = App::new();
    let target = Vec3::new(40.0, -25.0, 3.0);
    let spring = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), target),
        ))
        .id();
    let mut shake = Shake::new(5).with_max_translation(Vec3::splat(4.0));
    shake.add_trauma(1.0);
    let base = Vec3::new(-300.0, 0.0, 0.0);
    let shaken = app
        .world_mut()
        .spawn((Transform::from_translation(base), shake))
        .id();
    app.add_plugins((MinimalPlugins, TransformPlugin, SpringPlugins::default()))
        .insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(
            crate::harness::frame(60),
        ));
    let moved = largest_offset(&mut app, shaken, base, 10);
    assert!(moved > 0.5, "it shakes: {moved}");
    run(&mut app, 600);
    assert_eq!(
        app.world().get::<Transform>(spring).unwrap().translation,
        target
    );
    assert!(
        app.world()
            .get::<SpringAsleep<Translation>>(spring)
            .is_some()
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
