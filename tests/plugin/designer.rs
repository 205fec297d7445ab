//! The spring designer without its panel: its fields round-trip in every parametrisation, its
//! code and its file make the same spring, and attached to a running app it tunes a spring
//! live, saves where the spring loads from, and the app takes the saved file.

use bevy::asset::{AssetPlugin, LoadState};
use bevy::prelude::*;
use bevy_sprung::asset::{SpringPreset, UseSpringPreset};
use bevy_sprung::designer::{
    DesignerStatus, Parametrisation, SaveSpringDesign, SpringDesign, SpringDesignerPlugin,
    TuneSpring, TunedSpring, step_response,
};
use bevy_sprung::prelude::*;
use bevy_sprung::transform::Translation;
use sprung::Parameter;

use crate::harness::{run, translation_spring};

/// The springs the round trips start from: every preset and the corners of the regimes.
fn starting_springs() -> Vec<Spring> {
    let mut springs: Vec<Spring> = Spring::presets().iter().map(|(_, s)| *s).collect();
    springs.extend([
        Spring::from_natural_frequency(3.0, 0.05).unwrap(),
        Spring::from_natural_frequency(40.0, 1.0).unwrap(),
        Spring::from_natural_frequency(8.0, 3.5).unwrap(),
        Spring::new(2.5, 300.0, 20.0).unwrap(),
    ]);
    springs
}

/// A value the field can take, different from `now`.
fn new_value(parameter: Parameter, now: f32) -> f32 {
    match parameter {
        Parameter::Bounce => {
            if now > 0.2 {
                now * 0.5 - 0.1
            } else {
                0.35
            }
        }
        Parameter::DampingRatio => now * 0.6 + 0.1,
        _ => now * 1.37,
    }
}

fn relative(a: f32, b: f32) -> f32 {
    (a - b).abs() / a.abs().max(b.abs()).max(f32::MIN_POSITIVE)
}

fn same_spring(a: &Spring, b: &Spring) -> bool {
    relative(a.mass(), b.mass()) < 1e-6
        && relative(a.stiffness(), b.stiffness()) < 1e-6
        && (relative(a.damping(), b.damping()) < 1e-6
            || (a.damping() - b.damping()).abs() < 1e-6 * a.stiffness().sqrt())
}

/// Edit one field, read back every other: the edited field reads its value, and every group
/// that can say the spring makes the same spring again from its fields.
#[test]
fn every_field_round_trips_in_every_parametrisation() {
    let mut edits = 0;
    for start in starting_springs() {
        for group in Parametrisation::ALL {
            for &parameter in group.fields() {
                let mut design = SpringDesign::new(start);
                let Some(now) = design.field(parameter) else {
                    continue;
                };
                let value = new_value(parameter, now);
                if design.set_field(group, parameter, value).is_err() {
                    assert_eq!(design.spring(), start, "a refused edit changes nothing");
                    continue;
                }
                edits += 1;
                let read = design.field(parameter).unwrap();
                assert!(
                    relative(read, value) < 1e-6,
                    "{parameter} set to {value} reads {read} (from {start:?})"
                );
                let spring = design.spring();
                for other in Parametrisation::ALL
                    .into_iter()
                    .filter(|g| g.speaks(&spring))
                {
                    let values: Vec<f32> = other
                        .fields()
                        .iter()
                        .map(|&p| design.field(p).unwrap())
                        .collect();
                    let again = other.build(&values).unwrap();
                    assert!(
                        same_spring(&again, &spring),
                        "{other:?} {values:?} makes {again:?}, not {spring:?}"
                    );
                }
            }
        }
    }
    assert!(edits > 100, "only {edits} edits were tried");
}

/// The code the designer copies makes the spring it shows, in whichever group was edited.
#[test]
fn the_copied_code_makes_the_same_spring() {
    for start in starting_springs() {
        for group in Parametrisation::ALL {
            let mut design = SpringDesign::new(start);
            let parameter = group.fields()[0];
            let Some(now) = design.field(parameter) else {
                continue;
            };
            if design.set_field(group, parameter, now).is_err() {
                continue;
            }
            let code = design.code();
            let inside = code
                .split_once('(')
                .and_then(|(_, rest)| rest.strip_suffix(')'))
                .unwrap();
            let values: Vec<f32> = inside.split(", ").map(|v| v.parse().unwrap()).collect();
            let written_in = design.written_in();
            assert!(code.starts_with(&format!("Spring::{}(", written_in.constructor())));
            let made = written_in.build(&values).unwrap();
            assert!(
                same_spring(&made, &design.spring()),
                "{code} makes {made:?}"
            );
        }
    }
}

/// The readouts are the step response's: it never leaves the band after the settle time and
/// is at its edge just before; the overshoot is its highest point past the target.
#[test]
fn the_readouts_are_those_of_the_exact_response() {
    for start in starting_springs() {
        let mut design = SpringDesign::new(start);
        design.tolerance = 0.02;
        let readouts = design.readouts();
        let settle = readouts.settle_time.unwrap();
        let x = |t: f32| step_response(&start, t).0;
        let before = (1.0 - x(settle * 0.999)).abs();
        assert!(
            before > 0.02 * 0.9,
            "{start:?}: {before} just before {settle}"
        );
        let mut peak = 0.0_f32;
        for i in 0..4000 {
            let t = settle * 4.0 * i as f32 / 4000.0;
            if t > settle {
                assert!((1.0 - x(t)).abs() <= 0.02 + 1e-5, "{start:?} leaves at {t}");
            }
            peak = peak.max(x(t) - 1.0);
        }
        assert!(
            (peak - readouts.overshoot).abs() < 2e-3,
            "{start:?}: peak {peak}, overshoot {}",
            readouts.overshoot
        );
    }
}

/// A headless app whose assets are in a fresh folder holding `springs/ball.spring.ron`, and
/// the turn it takes with the tests that capture warnings: without Bevy's UI the designer
/// warns as it is built, and a warning reached on this thread while another test listens for
/// it can leave that test's listener out (see `first_hour::warnings`).
fn designer_app(name: &str) -> (App, std::path::PathBuf, std::sync::MutexGuard<'static, ()>) {
    let turn = crate::first_hour::CAPTURING
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let folder =
        std::env::temp_dir().join(format!("sprung-designer-{name}-{}", std::process::id()));
    std::fs::create_dir_all(folder.join("springs")).unwrap();
    std::fs::write(
        folder.join("springs/ball.spring.ron"),
        "(spring: (duration: 0.5, bounce: 0.15))",
    )
    .unwrap();
    let mut app = crate::harness::app(60);
    app.add_plugins(AssetPlugin {
        file_path: folder.to_string_lossy().into_owned(),
        ..default()
    })
    .add_plugins(SpringDesignerPlugin::default());
    app.finish();
    app.cleanup();
    (app, folder, turn)
}

fn wait_until(app: &mut App, done: impl Fn(&App) -> bool) {
    let start = std::time::Instant::now();
    while !done(app) {
        assert!(start.elapsed().as_secs() < 10, "timed out");
        app.update();
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
}

#[test]
fn tuned_live_then_saved_the_running_app_takes_the_file() {
    let (mut app, folder, _turn) = designer_app("save");
    let preset: Handle<SpringPreset> = app
        .world()
        .resource::<AssetServer>()
        .load("springs/ball.spring.ron");
    let spawn = |app: &mut App| {
        app.world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::molasses(), Vec3::X * 500.0),
                UseSpringPreset(preset.clone()),
            ))
            .id()
    };
    let (tuned, other) = (spawn(&mut app), spawn(&mut app));
    wait_until(&mut app, |app| {
        matches!(
            app.world().resource::<AssetServer>().load_state(&preset),
            LoadState::Loaded
        )
    });
    run(&mut app, 2);
    let loaded = Spring::from_duration_and_bounce(0.5, 0.15).unwrap();
    assert_eq!(*translation_spring(&app, tuned).spring(), loaded);

    // Picked: the design takes the spring, and keeps it as B.
    app.world_mut()
        .trigger(TuneSpring::of::<Translation>(tuned));
    run(&mut app, 1);
    let design = app.world().resource::<SpringDesign>();
    assert_eq!(design.spring(), loaded);
    assert_eq!(design.reference(), Some(loaded));

    // Edited: the tuned spring follows in the same frame, the other does not.
    app.world_mut()
        .resource_mut::<SpringDesign>()
        .set_field(Parametrisation::DurationBounce, Parameter::Bounce, 0.4)
        .unwrap();
    run(&mut app, 1);
    let designed = app.world().resource::<SpringDesign>().spring();
    assert_eq!(*translation_spring(&app, tuned).spring(), designed);
    assert_eq!(*translation_spring(&app, other).spring(), loaded);

    // Saved: to the file the spring loads from, which reads back to the same spring, bit for
    // bit; the app reloads it, and the other spring that uses it takes it too.
    app.world_mut().trigger(SaveSpringDesign);
    wait_until(&mut app, |app| {
        *translation_spring(app, other).spring() == designed
    });
    let text = std::fs::read(folder.join("springs/ball.spring.ron")).unwrap();
    assert_eq!(SpringPreset::from_ron(&text).unwrap().spring, designed);
    assert_eq!(*translation_spring(&app, tuned).spring(), designed);
    assert!(
        app.world()
            .resource::<DesignerStatus>()
            .0
            .starts_with("Saved")
    );
    std::fs::remove_dir_all(folder).ok();
}

/// A snappy translation spring, picked by the designer.
fn spawn_tuned(app: &mut App) -> Entity {
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::X * 500.0),
        ))
        .id();
    app.world_mut()
        .trigger(TuneSpring::of::<Translation>(entity));
    run(app, 1);
    entity
}

/// The tuned spring's file changed by someone else (reloaded): the design follows it.
#[test]
fn a_tuned_spring_changed_elsewhere_comes_back_to_the_design() {
    let (mut app, folder, _turn) = designer_app("follow");
    let entity = spawn_tuned(&mut app);
    app.world_mut()
        .get_mut::<TranslationSpring>(entity)
        .unwrap()
        .set_spring(Spring::wobbly());
    run(&mut app, 1);
    assert_eq!(
        app.world().resource::<SpringDesign>().spring(),
        Spring::wobbly()
    );
    std::fs::remove_dir_all(folder).ok();
}

/// The tuned entity despawned, or its spring removed, mid-tuning: the designer lets it go
/// and says so; nothing panics, and edits go on in the preview.
#[test]
fn a_tuned_spring_that_goes_away_is_let_go() {
    let (mut app, folder, _turn) = designer_app("despawn");
    for removal in [true, false] {
        let entity = spawn_tuned(&mut app);
        assert!(app.world().resource::<TunedSpring>().0.is_some());
        if removal {
            app.world_mut().despawn(entity);
        } else {
            app.world_mut()
                .entity_mut(entity)
                .remove::<TranslationSpring>();
        }
        app.world_mut()
            .resource_mut::<SpringDesign>()
            .set_spring(Spring::stiff());
        run(&mut app, 2);
        assert_eq!(app.world().resource::<TunedSpring>().0, None);
        assert!(
            app.world()
                .resource::<DesignerStatus>()
                .0
                .contains("previewing only")
        );
        assert_eq!(
            app.world().resource::<SpringDesign>().spring(),
            Spring::stiff()
        );
    }
    std::fs::remove_dir_all(folder).ok();
}

/// A preset's code reads as the preset was written: `0.5`, not the `0.50000006` its rounding
/// to `f32` leaves.
#[test]
fn a_presets_code_has_short_numbers() {
    for (name, spring) in Spring::presets() {
        let code = SpringDesign::new(spring).code();
        let inside = code.split_once('(').unwrap().1.trim_end_matches(')');
        for number in inside.split(", ") {
            assert!(number.len() <= 6, "{name}: {code}");
        }
    }
}
