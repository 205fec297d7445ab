//! Every property's springs arrive in a real app: every preset, at 30 to 360 fps, toward
//! targets from `1e-3` to `1e6` (pixels of a large world, UI lengths, scales, turns, colours and
//! rotations), settles within 1.05 times its analytic settle time plus two frames, and none
//! stalls short of its target.

use std::collections::HashMap;

use bevy::color::Oklaba;
use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::property::SpringProperty;
use bevy_sprung::spin::SpinAngle;
use bevy_sprung::spin::{Spin, SpinAngleSpring};
use bevy_sprung::spring::SpringAsleep;
use bevy_sprung::ui::{NodeLeft, NodeLeftSpring, UiTransformTranslation};
use sprung::Scalar;

use crate::harness::app;

/// The frame rates users run at.
const FRAME_RATES: [u32; 6] = [30, 60, 120, 144, 240, 360];

/// Positions in a large 2D world or pixel UI: both signs, non-round, `1e-3` to `1e6`.
const TARGETS: [f32; 10] = [
    1e-3, -2.5e-2, 0.7, -13.3, 100.0, -4096.3, 12_345.67, -1e5, 3.3e5, 1e6,
];

/// The tolerance the test asks for at `magnitude`: a thousandth of a unit, or four times the
/// spacing of `f32` there, whichever is coarser, with the speed of equal energy.
fn rest_for(spring: &Spring, magnitude: f32) -> RestThreshold {
    RestThreshold::for_spring(spring, 1e-3_f32.max(4.0 * magnitude.spacing()))
}

/// One spring of the sweep: what it is, and its analytic settle time.
struct Case {
    what: String,
    analytic: f64,
}

/// When each entity's spring settled, in seconds of game time.
#[derive(Resource, Default)]
struct Settled(HashMap<Entity, f64>);

fn record<P: SpringProperty>(
    settled: On<SpringSettled<P>>,
    time: Res<Time<Virtual>>,
    mut log: ResMut<Settled>,
) {
    log.0.insert(settled.entity, time.elapsed_secs_f64());
}

/// Spawns `bundle` with a spring of `rest` and records the case.
fn spawn(
    app: &mut App,
    cases: &mut HashMap<Entity, Case>,
    bundle: impl Bundle,
    (spring, what): (&Spring, String),
    distance: f32,
    rest: RestThreshold,
) {
    let entity = app.world_mut().spawn(bundle).id();
    let analytic = f64::from(spring.settle_time(distance, rest.offset).unwrap());
    cases.insert(entity, Case { what, analytic });
}

/// Spawns, for every preset, springs on every property toward targets of every magnitude.
fn spawn_cases(app: &mut App) -> HashMap<Entity, Case> {
    let mut cases = HashMap::new();
    for (name, spring) in Spring::presets() {
        for target in TARGETS {
            for start in [0.0, -target, target + 1.0] {
                let rest = rest_for(&spring, target);
                spawn(
                    app,
                    &mut cases,
                    (
                        Transform::from_xyz(start, 0.0, 0.0),
                        TranslationSpring::new(spring, Vec3::X * target).with_rest(rest),
                    ),
                    (&spring, format!("{name} translation {start} → {target}")),
                    (target - start).abs(),
                    rest,
                );
            }
            // UI lengths in pixels, from 0.
            let rest = rest_for(&spring, target).at_magnitude(target);
            spawn(
                app,
                &mut cases,
                (
                    Node::default(),
                    NodeLeftSpring::new(spring, px(target)).with_rest(rest),
                ),
                (&spring, format!("{name} node left → {target} px")),
                target.abs(),
                rest,
            );
            spawn(
                app,
                &mut cases,
                (
                    UiTransform::from_translation(Val2::percent(1.0, 1.0)),
                    UiTransformTranslationSpring::new(spring, Val2::percent(target, 1.0))
                        .with_rest(rest),
                ),
                (&spring, format!("{name} ui translation → {target} %")),
                (target - 1.0).abs(),
                rest,
            );
            // Whole turns, up to thousands of them.
            spawn(
                app,
                &mut cases,
                (
                    Spin::z(0.0),
                    SpinAngleSpring::new(spring, target / 100.0).with_rest(rest),
                ),
                (&spring, format!("{name} spin → {} rad", target / 100.0)),
                (target / 100.0).abs(),
                rest,
            );
        }
        spawn_unit_cases(app, &mut cases, name, spring);
    }
    cases
}

/// Springs of unit-sized values for one preset: scales from 1 (either side of zero), rotations
/// and colours.
fn spawn_unit_cases(app: &mut App, cases: &mut HashMap<Entity, Case>, name: &str, spring: Spring) {
    // Scales from 1, either side of zero; rotations and colours of unit size.
    for target in [1e-3, 0.25, 2.0, 1e3, -3.0] {
        let rest = rest_for(&spring, target);
        spawn(
            app,
            cases,
            (
                Transform::default(),
                ScaleSpring::new(spring, Vec3::splat(target)).with_rest(rest),
            ),
            (&spring, format!("{name} scale → {target}")),
            Vec3::splat(target - 1.0).length(),
            rest,
        );
    }
    for angle in [1e-3_f32, 0.5, 3.0] {
        let rest = rest_for(&spring, 1.0);
        let target = Quat::from_axis_angle(Vec3::new(1.0, -2.0, 0.5).normalize(), angle);
        spawn(
            app,
            cases,
            (
                Transform::default(),
                RotationSpring::new(spring, target).with_rest(rest),
            ),
            (&spring, format!("{name} rotation → {angle} rad")),
            angle,
            rest,
        );
    }
    for (from, to) in [
        (Color::BLACK, Color::WHITE),
        (Color::srgba(0.1, 0.9, 0.3, 0.2), Color::srgb(0.9, 0.1, 0.6)),
    ] {
        let rest = rest_for(&spring, 1.0);
        let (a, b) = (Oklaba::from(from), Oklaba::from(to));
        let distance = Vec4::new(
            a.lightness - b.lightness,
            a.a - b.a,
            a.b - b.b,
            a.alpha - b.alpha,
        )
        .length();
        spawn(
            app,
            cases,
            (
                BackgroundColor(from),
                BackgroundColorSpring::new(spring, to).with_rest(rest),
            ),
            (&spring, format!("{name} colour {from:?} → {to:?}")),
            distance,
            rest,
        );
    }
}

#[test]
fn every_property_arrives_at_every_frame_rate_and_magnitude() {
    let mut worst = 0.0_f64;
    let mut count = 0;
    for fps in FRAME_RATES {
        let mut app = app(fps);
        app.init_resource::<Settled>()
            .add_observer(record::<Translation>)
            .add_observer(record::<Scale>)
            .add_observer(record::<NodeLeft>)
            .add_observer(record::<UiTransformTranslation>)
            .add_observer(record::<SpinAngle>)
            .add_observer(record::<Rotation>)
            .add_observer(record::<BackgroundColor>);
        let cases = spawn_cases(&mut app);
        let longest = cases.values().map(|case| case.analytic).fold(0.0, f64::max);
        let dt = 1.0 / f64::from(fps);
        // The first update has dt = 0; then run past the longest settle time with margin.
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a positive, bounded frame count"
        )]
        let frames = ((1.1 * longest + 4.0 * dt) / dt).ceil() as u32 + 1;
        for _ in 0..frames {
            app.update();
        }
        let settled = &app.world().resource::<Settled>().0;
        for (entity, case) in &cases {
            let Some(&at) = settled.get(entity) else {
                panic!("{fps} fps: {} never settled", case.what);
            };
            assert!(
                at <= 1.05 * case.analytic + 2.0 * dt + 1e-6,
                "{fps} fps: {} settled at {at:.4} s, analytic {:.4} s",
                case.what,
                case.analytic
            );
            worst = worst.max((at - 2.0 * dt) / case.analytic.max(dt));
            count += 1;
        }
    }
    println!("{count} springs settled; the latest at {worst:.3}x analytic (+2 frames)");
}

/// With its default tolerances a spring toward a target at `1e6` settles: the tolerances are
/// raised to the spacing of `f32` there (`0.0625`), which the spring reaches.
#[test]
fn default_tolerances_settle_at_a_million() {
    for fps in [60, 240] {
        let mut app = app(fps);
        let entity = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::molasses(), Vec3::new(1e6, -1e6, 3.3e5)),
            ))
            .id();
        for _ in 0..(12 * fps) {
            app.update();
        }
        assert!(
            app.world()
                .get::<SpringAsleep<Translation>>(entity)
                .is_some(),
            "{fps} fps: still awake at {:?}",
            app.world().get::<Transform>(entity).unwrap().translation
        );
        assert_eq!(
            app.world().get::<Transform>(entity).unwrap().translation,
            Vec3::new(1e6, -1e6, 3.3e5)
        );
    }
}
