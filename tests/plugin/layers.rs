//! Layers: several springs on one property, added up exactly, each unbent by the others.

use bevy::prelude::*;
use bevy_sprung::layers::{LayerSpring, SpringLayerPlugin, SpringLayers};
use bevy_sprung::prelude::*;

use crate::harness::{app, run};

#[derive(TypePath)]
struct Hover;

#[derive(TypePath)]
struct Kick;

fn layered_app(fps: u32) -> App {
    let mut app = app(fps);
    app.add_plugins((
        SpringLayerPlugin::<Translation, Hover>::default(),
        SpringLayerPlugin::<Translation, Kick>::default(),
        SpringLayerPlugin::<Rotation, Kick>::default(),
        SpringLayerPlugin::<Scale, Hover>::default(),
    ));
    app
}

fn translation(app: &App, entity: Entity) -> Vec3 {
    app.world().get::<Transform>(entity).unwrap().translation
}

/// The largest spacing of `f32` among the components of `v`.
fn ulp(v: Vec3) -> f32 {
    let m = v.abs().max_element().max(f32::MIN_POSITIVE);
    f32::from_bits(m.to_bits() + 1) - m
}

/// A base spring and two layers write, every frame, the sum of the three springs run on
/// separate entities, to a few ulp, at 30 to 240 fps, at pixel magnitudes; with a punch on a
/// layer mid-flight and a retarget of the base. At rest everything sleeps and nothing is
/// written.
#[test]
fn layers_add_up_to_the_separate_springs() {
    for fps in [30, 60, 144, 240, 360] {
        let mut app = layered_app(fps);
        let (from, to) = (
            Vec3::new(-1800.0, 900.0, 0.0),
            Vec3::new(2400.0, -300.0, 5.0),
        );
        let (hover, kick) = (Vec3::new(0.0, 24.0, 0.0), Vec3::new(-40.0, 0.0, 0.0));
        let world = app.world_mut();
        let layered = world
            .spawn((
                Transform::from_translation(from),
                TranslationSpring::new(Spring::smooth(), to),
                LayerSpring::<Translation, Hover>::new(Spring::bouncy(), hover),
                LayerSpring::<Translation, Kick>::new(Spring::snappy(), kick),
            ))
            .id();
        let base = world
            .spawn((
                Transform::from_translation(from),
                TranslationSpring::new(Spring::smooth(), to),
            ))
            .id();
        let separate = [(Spring::bouncy(), hover), (Spring::snappy(), kick)].map(|(s, t)| {
            world
                .spawn((Transform::default(), TranslationSpring::new(s, t)))
                .id()
        });
        let mut worst = 0.0f32;
        for frame in 0..(3 * fps) {
            if frame == fps / 3 {
                let punch = Vec3::new(7.0, -11.0, 0.0);
                app.world_mut()
                    .get_mut::<LayerSpring<Translation, Kick>>(layered)
                    .unwrap()
                    .punch(punch);
                app.world_mut()
                    .get_mut::<TranslationSpring>(separate[1])
                    .unwrap()
                    .punch(punch);
            }
            if frame == fps / 2 {
                let retarget = Vec3::new(100.0, 200.0, -3.0);
                for entity in [layered, base] {
                    app.world_mut()
                        .get_mut::<TranslationSpring>(entity)
                        .unwrap()
                        .set_target(retarget);
                }
            }
            app.update();
            let sum = translation(&app, base)
                + translation(&app, separate[0])
                + translation(&app, separate[1]);
            let error = (translation(&app, layered) - sum).abs().max_element() / ulp(sum);
            worst = worst.max(error);
        }
        assert!(worst <= 2.0, "{fps} fps: {worst} ulp");
        assert_eq!(
            translation(&app, layered),
            Vec3::new(100.0, 200.0, -3.0) + hover + kick
        );
        // At rest: nothing stepped, nothing written.
        run(&mut app, 3);
        let tick = app
            .world()
            .entity(layered)
            .get_ref::<Transform>()
            .unwrap()
            .last_changed();
        run(&mut app, 30);
        let now = app.world().entity(layered).get_ref::<Transform>().unwrap();
        assert_eq!(now.last_changed(), tick, "{fps} fps: written at rest");
    }
}

/// Gameplay in `Update` reads and writes the base: the layers are off, bit for bit, and a
/// value written there is the base the layers are shown on.
#[test]
fn gameplay_sees_and_writes_the_base() {
    #[derive(Resource, Default)]
    struct Seen(Vec<Vec3>);
    let mut app = layered_app(60);
    app.init_resource::<Seen>();
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_xyz(10.0, 0.0, 0.0),
            LayerSpring::<Translation, Hover>::new(Spring::bouncy(), Vec3::Y * 30.0),
        ))
        .id();
    app.add_systems(
        Update,
        move |mut seen: ResMut<Seen>, mut transforms: Query<&mut Transform>| {
            let mut transform = transforms.get_mut(entity).unwrap();
            seen.0.push(transform.translation);
            transform.translation.x += 1.0;
        },
    );
    run(&mut app, 120);
    let seen = &app.world().resource::<Seen>().0;
    for (frame, seen) in seen.iter().enumerate() {
        assert_eq!(
            *seen,
            Vec3::new(10.0 + frame as f32, 0.0, 0.0),
            "frame {frame}"
        );
    }
    assert_eq!(translation(&app, entity), Vec3::new(130.0, 30.0, 0.0));
}

/// A layer added mid-flight starts from zero: the frame it joins draws exactly what the base
/// alone draws. A layer's spring removed mid-flight leaves the value where it was drawn, and the
/// base spring carries it home with no jump.
#[test]
fn a_layer_added_or_removed_mid_flight_does_not_jump() {
    for fps in [30, 60, 240] {
        let mut app = layered_app(fps);
        let dt = 1.0 / fps as f32;
        let to = Vec3::new(500.0, 0.0, 0.0);
        let layered = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::smooth(), to),
            ))
            .id();
        let alone = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::smooth(), to),
            ))
            .id();
        run(&mut app, fps / 4);
        app.world_mut()
            .entity_mut(layered)
            .insert(LayerSpring::<Translation, Hover>::new(
                Spring::bouncy(),
                Vec3::new(0.0, 80.0, 0.0),
            ));
        let lift = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(Spring::bouncy(), Vec3::new(0.0, 80.0, 0.0)),
            ))
            .id();
        app.update();
        // The layer's first frame is its spring's first step from zero, nothing more.
        let first = translation(&app, alone) + translation(&app, lift);
        assert_eq!(translation(&app, layered), first, "{fps} fps");
        assert!(translation(&app, lift).y < 80.0 * 0.5, "{fps} fps");
        run(&mut app, fps / 5);
        let mut last = translation(&app, layered);
        app.world_mut()
            .entity_mut(layered)
            .remove::<LayerSpring<Translation, Hover>>();
        // The fastest this motion goes, with a margin: a jump would be a frame's worth of the
        // whole lift.
        let bound = 2000.0 * dt + 1e-3;
        for _ in 0..(3 * fps) {
            app.update();
            let now = translation(&app, layered);
            assert!(
                now.distance(last) <= bound,
                "{fps} fps: jumped {last} → {now}"
            );
            last = now;
        }
        assert_eq!(last, to, "{fps} fps: the base spring carried the lift home");
    }
}

/// Rotations compose as products in the value's own axes, scales as factors: a squash on a
/// scale spring keeps the volume of the sprung scale, and both rest exactly on their targets.
#[test]
fn rotation_and_scale_layers_compose_as_products() {
    let mut app = layered_app(60);
    let turn = Quat::from_rotation_z(1.0);
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_xyz(0.0, 200.0, 0.0),
            RotationSpring::new(Spring::smooth(), turn),
            LayerSpring::<Rotation, Kick>::new(Spring::bouncy(), Vec3::new(0.3, 0.0, 0.0)),
            ScaleSpring::new(Spring::bouncy(), Vec3::splat(2.0)),
            TranslationSpring::new(Spring::snappy(), Vec3::ZERO),
            SquashStretch::new(0.004, 1.5),
        ))
        .id();
    let mut stretched = 1.0f32;
    for _ in 0..300 {
        app.update();
        let transform = app.world().get::<Transform>(entity).unwrap();
        let base_scale = app.world().get::<SpringLayers<Scale>>(entity).unwrap();
        let shown = transform.scale;
        let base = base_scale.remove(shown);
        let factors = shown / base;
        assert!(
            (factors.x * factors.y * factors.z - 1.0).abs() < 1e-5,
            "volume kept: {factors}"
        );
        stretched = stretched.max(factors.y);
    }
    assert!(stretched > 1.05, "the fall stretched it: {stretched}");
    let transform = *app.world().get::<Transform>(entity).unwrap();
    assert_eq!(transform.scale, Vec3::splat(2.0));
    let expected = turn * Quat::from_rotation_x(0.3);
    assert!(transform.rotation.angle_between(expected) < 1e-6);
}

/// A layer's offset set by hand is refused when not finite; a layer set to zero stops being
/// drawn, and the base is back bit for bit.
#[test]
fn hand_set_layers_refuse_nan_and_zero_restores_the_base() {
    let mut app = layered_app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_xyz(1.0e6, -3.0, 0.0),
            SpringLayers::<Translation>::default(),
        ))
        .id();
    app.update();
    let set = |app: &mut App, value: Vec3| {
        app.world_mut()
            .get_mut::<SpringLayers<Translation>>(entity)
            .unwrap()
            .set::<Hover>(value);
    };
    set(&mut app, Vec3::new(0.5, 2.0, 0.0));
    app.update();
    assert_eq!(translation(&app, entity), Vec3::new(1.0e6 + 0.5, -1.0, 0.0));
    set(&mut app, Vec3::NAN);
    app.update();
    assert_eq!(translation(&app, entity), Vec3::new(1.0e6 + 0.5, -1.0, 0.0));
    set(&mut app, Vec3::ZERO);
    app.update();
    assert_eq!(translation(&app, entity), Vec3::new(1.0e6, -3.0, 0.0));
}

/// Despawning a layered entity, or removing its stack, inside an observer of its own layer's
/// settling, panics nowhere.
#[test]
fn despawned_inside_a_layer_observer() {
    let mut app = layered_app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            LayerSpring::<Translation, Hover>::new(Spring::snappy(), Vec3::X),
        ))
        .id();
    app.world_mut().entity_mut(entity).observe(
        |settled: On<SpringSettled<bevy_sprung::layers::Layer<Translation, Hover>>>,
         mut commands: Commands| {
            commands.entity(settled.entity).despawn();
        },
    );
    run(&mut app, 240);
    assert!(app.world().get_entity(entity).is_err());
}

/// `InteractionTargets` on a layer: hovering swells the scale by its own spring, on top of a
/// base scale spring in flight that it does not bend (the base lands exactly on its target,
/// and the shown scale is the base times the hover factor).
#[test]
fn interaction_targets_drive_a_layer() {
    use bevy_sprung::interaction::InteractionTargets;
    use bevy_sprung::layers::Layer;
    use bevy_sprung::transform::Scale;

    let mut app = layered_app(60);
    let swell = Vec3::splat(1.2_f32.ln());
    let card = app
        .world_mut()
        .spawn((
            Transform::default(),
            ScaleSpring::new(Spring::smooth(), Vec3::splat(2.0)),
            LayerSpring::<Scale, Hover>::new(Spring::bouncy(), Vec3::ZERO),
            InteractionTargets::<Layer<Scale, Hover>>::new(Vec3::ZERO).hovered(swell),
        ))
        .id();
    let alone = app
        .world_mut()
        .spawn((
            Transform::default(),
            ScaleSpring::new(Spring::smooth(), Vec3::splat(2.0)),
        ))
        .id();
    run(&mut app, 5);
    crate::interaction::enter(app.world_mut(), card);
    for _ in 0..240 {
        app.update();
        let base = app.world().get::<Transform>(alone).unwrap().scale;
        let layers = app.world().get::<SpringLayers<Scale>>(card).unwrap();
        let shown = app.world().get::<Transform>(card).unwrap().scale;
        assert!(
            (layers.remove(shown) - base).abs().max_element() < 1e-6,
            "{shown} over {base}"
        );
    }
    let shown = app.world().get::<Transform>(card).unwrap().scale;
    assert!(
        (shown - Vec3::splat(2.4)).abs().max_element() < 1e-5,
        "{shown}"
    );
    crate::interaction::leave(app.world_mut(), card);
    run(&mut app, 240);
    assert_eq!(
        app.world().get::<Transform>(card).unwrap().scale,
        Vec3::splat(2.0)
    );
}
