//! Springs and sequences as assets: loaded from RON by the `AssetServer`, applied to springs by
//! handle, re-applied when they change; invalid files are clear errors, never panics.

use bevy::asset::{AssetPlugin, LoadState};
use bevy::prelude::*;
use bevy_sprung::asset::{
    SequencePreset, SpringPreset, UsePropertyPreset, UseSequencePreset, UseSpringPreset,
};
use bevy_sprung::prelude::*;
use bevy_sprung::transform::Scale;

use crate::harness::{run, targets_visited, translation, translation_spring};

/// A headless app that loads assets from `folder` (relative to the workspace root). The
/// spring plugin comes first: its assets are registered once every plugin is built.
fn asset_app(folder: &str) -> App {
    let mut app = crate::harness::app(60);
    app.add_plugins(AssetPlugin {
        file_path: folder.into(),
        ..default()
    });
    app.finish();
    app.cleanup();
    app
}

/// Runs frames until `handle` has loaded or failed (at most ten seconds of wall time).
fn wait_for<A: Asset>(app: &mut App, handle: &Handle<A>) -> LoadState {
    let start = std::time::Instant::now();
    loop {
        app.update();
        let state = app.world().resource::<AssetServer>().load_state(handle);
        if matches!(state, LoadState::Loaded | LoadState::Failed(_))
            || start.elapsed().as_secs() > 10
        {
            return state;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
}

#[test]
fn a_preset_file_loads_and_reaches_every_spring_of_the_entity() {
    let mut app = asset_app("assets");
    let handle: Handle<SpringPreset> = app
        .world()
        .resource::<AssetServer>()
        .load("springs/ui.spring.ron");
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::molasses(), Vec3::X * 100.0),
            ScaleSpring::new(Spring::molasses(), Vec3::splat(2.0)),
            UseSpringPreset(handle.clone()),
        ))
        .id();
    assert!(matches!(wait_for(&mut app, &handle), LoadState::Loaded));
    app.update();
    let expected = Spring::from_duration_and_bounce(0.35, 0.15).unwrap();
    assert_eq!(*translation_spring(&app, entity).spring(), expected);
    assert_eq!(
        *app.world().get::<ScaleSpring>(entity).unwrap().spring(),
        expected
    );
    assert_eq!(
        translation_spring(&app, entity).rest(),
        RestThreshold::new(0.05, 0.5)
    );
    // Edited (as the file watcher would): the springs follow.
    let stiff = Spring::stiff();
    app.world_mut()
        .resource_mut::<Assets<SpringPreset>>()
        .get_mut(&handle)
        .unwrap()
        .spring = stiff;
    run(&mut app, 2);
    assert_eq!(*translation_spring(&app, entity).spring(), stiff);
}

/// A preset for one property reaches that property's spring only, and wins over the entity's
/// preset for every spring.
#[test]
fn a_property_preset_reaches_its_property_only_and_wins_over_the_entitys() {
    let mut app = asset_app("assets");
    let server = app.world().resource::<AssetServer>().clone();
    let every: Handle<SpringPreset> = server.load("springs/ui.spring.ron");
    let scale: Handle<SpringPreset> = server.load("springs/gentle.spring.ron");
    let only = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::molasses(), Vec3::X * 100.0),
            ScaleSpring::new(Spring::molasses(), Vec3::splat(2.0)),
            UsePropertyPreset::<Scale>::new(scale.clone()),
        ))
        .id();
    let both = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::molasses(), Vec3::X * 100.0),
            ScaleSpring::new(Spring::molasses(), Vec3::splat(2.0)),
            UseSpringPreset(every.clone()),
            UsePropertyPreset::<Scale>::new(scale.clone()),
        ))
        .id();
    assert!(matches!(wait_for(&mut app, &every), LoadState::Loaded));
    assert!(matches!(wait_for(&mut app, &scale), LoadState::Loaded));
    app.update();
    let presets = app.world().resource::<Assets<SpringPreset>>();
    let (every, scale) = (
        presets.get(&every).unwrap().spring,
        presets.get(&scale).unwrap().spring,
    );
    assert_ne!(every, scale);
    let scale_spring = |entity| *app.world().get::<ScaleSpring>(entity).unwrap().spring();
    assert_eq!(*translation_spring(&app, only).spring(), Spring::molasses());
    assert_eq!(scale_spring(only), scale);
    assert_eq!(*translation_spring(&app, both).spring(), every);
    assert_eq!(scale_spring(both), scale);
}

#[test]
fn a_sequence_file_drives_a_property() {
    let mut app = asset_app("tests/assets");
    let handle: Handle<SequencePreset> = app
        .world()
        .resource::<AssetServer>()
        .load("bob.sequence.ron");
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::ZERO),
            UseSequencePreset::<Translation>::new(handle.clone()),
        ))
        .id();
    assert!(matches!(wait_for(&mut app, &handle), LoadState::Loaded));
    let visited = targets_visited(&mut app, entity, 600);
    let up = Vec3::new(0.0, 10.0, 0.0);
    // Two passes, forth and back (the turning point is not repeated); `visited` starts once the
    // file has loaded and the sequence began.
    assert_eq!(visited, [up, Vec3::ZERO, up]);
    assert_eq!(translation(&app, entity), up);
    let sequence = app
        .world()
        .get::<SpringSequence<Translation>>(entity)
        .unwrap();
    assert!(sequence.is_finished());
    assert_eq!(sequence.plays(), 2);
}

#[test]
fn invalid_files_fail_with_clear_errors_and_springs_keep_what_they_had() {
    let mut app = asset_app("tests/assets");
    let server = app.world().resource::<AssetServer>().clone();
    for (file, needle) in [
        ("invalid.spring.ron", "damping must not be negative"),
        ("typo.spring.ron", "sprng"),
    ] {
        let handle: Handle<SpringPreset> = server.load(file);
        let entity = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::wobbly(), Vec3::X),
                UseSpringPreset(handle.clone()),
            ))
            .id();
        let LoadState::Failed(error) = wait_for(&mut app, &handle) else {
            panic!("{file} should fail to load");
        };
        let message = error.to_string();
        assert!(message.contains(needle), "{file}: {message}");
        assert!(
            message.contains(file),
            "{file}: the error names the file: {message}"
        );
        run(&mut app, 3);
        assert_eq!(*translation_spring(&app, entity).spring(), Spring::wobbly());
    }
    // A sequence whose target is not the property's value: logged, and no sequence.
    let handle: Handle<SequencePreset> = server.load("wrong_target.sequence.ron");
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::wobbly(), Vec3::X),
            UseSequencePreset::<Translation>::new(handle.clone()),
        ))
        .id();
    assert!(matches!(wait_for(&mut app, &handle), LoadState::Loaded));
    run(&mut app, 3);
    assert!(
        app.world()
            .get::<SpringSequence<Translation>>(entity)
            .is_none()
    );
    let error = app
        .world()
        .resource::<Assets<SequencePreset>>()
        .get(&handle)
        .unwrap()
        .sequence::<Translation>()
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("step 0") && error.contains("Translation"),
        "{error}"
    );
}
