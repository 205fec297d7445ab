//! The built-in properties' special cases, and a property of the user's own.

use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::space::Linear;
use bevy_sprung::space::rotation_vector;
use bevy_sprung::spring::SpringSystems;
use bevy_sprung::transform::SignedScaleSpring;

use crate::harness::{
    app, asleep, assert_stepped_from, many_translations, motion, run, translation,
};

/// A component of the user's own, with a scalar field.
#[derive(Component, Default)]
pub(crate) struct Loudness(f32);

spring_property!(
    /// A user property in one line: a tuple field of the user's own component.
    pub(crate) LoudnessLevel: Loudness::0 as Linear<f32>
);

spring_property!(
    /// A user property through accessors: the x scale alone, as a scalar spring.
    pub(crate) ScaleX: Transform {
        get: |transform| transform.scale.x,
        set: |transform, value| transform.scale.x = value
    } as Linear<f32>
);

/// The same component, stored in a sparse set: its springs step entity by entity, not from
/// table columns.
#[derive(Component, Default)]
#[component(storage = "SparseSet")]
pub(crate) struct SparseLoudness(f32);

spring_property!(
    /// A user property on a sparse-set component.
    pub(crate) SparseLoudnessLevel: SparseLoudness::0 as Linear<f32>
);

/// Whether `Loudness` and `SparseLoudness` changed since the last frame, seen right after the
/// springs ran.
#[derive(Resource, Default)]
struct LoudnessChanged(bool, bool);

fn record_loudness_changes(
    mut changed: ResMut<LoudnessChanged>,
    table: Query<(), Changed<Loudness>>,
    sparse: Query<(), Changed<SparseLoudness>>,
) {
    *changed = LoudnessChanged(!table.is_empty(), !sparse.is_empty());
}

/// A property on a sparse-set component steps as one in a table does (the same values, bit for
/// bit, every frame), marks its component changed in the same frames, and settles.
#[test]
fn a_sparse_set_property_steps_as_a_table_one_does() {
    let mut app = app(144);
    app.add_plugins((
        SpringPropertyPlugin::<LoudnessLevel>::default(),
        SpringPropertyPlugin::<SparseLoudnessLevel>::default(),
    ))
    .init_resource::<LoudnessChanged>()
    .add_systems(PostUpdate, record_loudness_changes.after(SpringSystems));
    let target = 12_345.67;
    let table = app
        .world_mut()
        .spawn((
            Loudness(0.0),
            PropertySpring::<LoudnessLevel>::new(Spring::bouncy(), target),
        ))
        .id();
    let sparse = app
        .world_mut()
        .spawn((
            SparseLoudness(0.0),
            PropertySpring::<SparseLoudnessLevel>::new(Spring::bouncy(), target),
        ))
        .id();
    let mut changed_frames = 0;
    for _ in 0..1200 {
        app.update();
        let table_value = app.world().get::<Loudness>(table).unwrap().0;
        let sparse_value = app.world().get::<SparseLoudness>(sparse).unwrap().0;
        assert_eq!(table_value.to_bits(), sparse_value.to_bits());
        let changed = app.world().resource::<LoudnessChanged>();
        assert_eq!(changed.0, changed.1);
        changed_frames += usize::from(changed.1);
    }
    assert!(changed_frames > 100, "{changed_frames}");
    assert_eq!(app.world().get::<SparseLoudness>(sparse).unwrap().0, target);
    assert!(asleep::<SparseLoudnessLevel>(&app, sparse));
}

#[test]
fn a_user_property_springs_and_settles() {
    let mut app = app(60);
    app.add_plugins((
        SpringPropertyPlugin::<LoudnessLevel>::default(),
        SpringPropertyPlugin::<ScaleX>::default(),
    ));
    let entity = app
        .world_mut()
        .spawn((
            Loudness(0.0),
            PropertySpring::<LoudnessLevel>::new(Spring::snappy(), 0.8),
            Transform::default(),
            PropertySpring::<ScaleX>::new(Spring::bouncy(), 3.0),
        ))
        .id();
    run(&mut app, 10);
    let loudness = app.world().get::<Loudness>(entity).unwrap().0;
    assert!(loudness > 0.3 && loudness < 0.8, "{loudness}");
    run(&mut app, 300);
    assert_eq!(app.world().get::<Loudness>(entity).unwrap().0, 0.8);
    assert_eq!(
        app.world().get::<Transform>(entity).unwrap().scale,
        Vec3::new(3.0, 1.0, 1.0)
    );
    assert!(asleep::<LoudnessLevel>(&app, entity) && asleep::<ScaleX>(&app, entity));
    // The component is reflected and registered like the built-in ones.
    let registry = app.world().resource::<AppTypeRegistry>().read();
    assert!(
        registry
            .get(core::any::TypeId::of::<PropertySpring<LoudnessLevel>>())
            .is_some()
    );
    assert!(
        registry
            .get(core::any::TypeId::of::<TranslationSpring>())
            .is_some()
    );
}

#[test]
fn rotation_takes_the_short_way_and_settles_exactly() {
    let mut app = app(60);
    // From +170° to −170° about z: the short way is 20° through 180°, not 340° through 0°.
    let from = Quat::from_rotation_z(170f32.to_radians());
    let to = Quat::from_rotation_z(-170f32.to_radians());
    let entity = app
        .world_mut()
        .spawn((
            Transform::from_rotation(from),
            RotationSpring::new(Spring::smooth(), to),
        ))
        .id();
    for _ in 0..240 {
        app.update();
        let rotation = app.world().get::<Transform>(entity).unwrap().rotation;
        // Never further than the start from the target (critically damped, no overshoot).
        assert!(rotation.angle_between(to) <= from.angle_between(to) + 1e-5);
        assert!(rotation.angle_between(Quat::from_rotation_z(0.0)) > 160f32.to_radians());
    }
    assert!(asleep::<Rotation>(&app, entity));
    assert_eq!(app.world().get::<Transform>(entity).unwrap().rotation, to);
}

#[test]
fn rotation_vector_is_accurate_near_the_identity() {
    for angle in [1e-7_f32, 1e-5, 1e-3, 0.1, 1.0, 3.0, std::f32::consts::PI] {
        let axis = Vec3::new(1.0, -2.0, 0.5).normalize();
        let v = rotation_vector(Quat::from_axis_angle(axis, angle));
        assert!(
            (v.length() - angle).abs() <= 4.0 * f32::EPSILON * angle,
            "{angle}: {}",
            v.length()
        );
        // And the other hemisphere gives the same rotation vector.
        let w = rotation_vector(-Quat::from_axis_angle(axis, angle));
        assert!(v.distance(w) <= 4.0 * f32::EPSILON * angle.max(1.0));
    }
}

/// Retargeting a rotation keeps its angular velocity in the world: the velocity, expressed in
/// the old target's frame, is re-expressed in the new target's frame before the step.
#[test]
fn rotation_retarget_keeps_the_world_angular_velocity() {
    let spring = Spring::wobbly();
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            RotationSpring::new(spring, Quat::from_rotation_y(1.0)),
        ))
        .id();
    run(&mut app, 6);
    let before = *app.world().get::<RotationSpring>(entity).unwrap();
    let velocity_before = motion::<Rotation>(&app, entity).velocity();
    let rotation = app.world().get::<Transform>(entity).unwrap().rotation;
    let new_target = Quat::from_rotation_x(1.5);
    app.world_mut()
        .get_mut::<RotationSpring>(entity)
        .unwrap()
        .set_target(new_target);
    app.update();
    let after = motion::<Rotation>(&app, entity).velocity();
    // The exact step from the same rotation with the same world angular velocity.
    let kept = new_target.inverse() * (before.target() * velocity_before);
    let dt = app.world().resource::<Time>().delta_secs();
    let step = spring.transition(dt).step(
        sprung::SpringState::new(rotation_vector(new_target.inverse() * rotation), kept),
        Vec3::ZERO,
    );
    assert!(
        after.distance(step.velocity) < 1e-3,
        "{} vs {}",
        after,
        step.velocity
    );
    let expected = new_target * Quat::from_scaled_axis(step.position);
    let actual = app.world().get::<Transform>(entity).unwrap().rotation;
    assert!(actual.angle_between(expected) < 1e-4);
    // Keeping the raw numbers instead would have been a different motion.
    assert!(kept.distance(velocity_before) > 1.0);
}

#[test]
fn scale_never_passes_through_zero_but_signed_scale_may() {
    let bouncy = Spring::from_natural_frequency(20.0, 0.05).unwrap();
    let mut app = app(60);
    let scale = app
        .world_mut()
        .spawn((Transform::default(), ScaleSpring::new(bouncy, Vec3::ZERO)))
        .id();
    let signed = app
        .world_mut()
        .spawn((
            Transform::default(),
            SignedScaleSpring::new(bouncy, Vec3::ZERO),
        ))
        .id();
    let mut signed_went_negative = false;
    for _ in 0..600 {
        app.update();
        let s = app.world().get::<Transform>(scale).unwrap().scale;
        assert!(s.min_element() >= 0.0, "scale crossed zero: {s}");
        signed_went_negative |= app.world().get::<Transform>(signed).unwrap().scale.x < 0.0;
    }
    assert!(signed_went_negative);
    // A pop-out lands on zero and rests there.
    assert!(asleep::<Scale>(&app, scale));
    assert_eq!(
        app.world().get::<Transform>(scale).unwrap().scale,
        Vec3::ZERO
    );
    // A target of the other sign is still reached (the crossing is asked for).
    app.world_mut()
        .get_mut::<ScaleSpring>(scale)
        .unwrap()
        .set_target(Vec3::new(-1.0, 2.0, 1.0));
    run(&mut app, 1200);
    assert_eq!(
        app.world().get::<Transform>(scale).unwrap().scale,
        Vec3::new(-1.0, 2.0, 1.0)
    );
}

/// A value written by something else mid-flight (a drag, a reset, another system) is sprung
/// on from where it was put, with the velocity the spring had: the next frame is the exact
/// step from there. For a translation (`Linear`), a scale and a UI scale (`NeverThroughZero`,
/// whose usual step tests the written value after the step, with its sign test).
#[test]
fn a_value_written_mid_flight_is_sprung_on_from_where_it_was_put() {
    let spring = Spring::from_natural_frequency(10.0, 0.6).unwrap();
    let transition = spring.transition(1.0 / 60.0);
    let mut app = app(60);
    let target = Vec3::new(3.0, 2.0, 4.0);
    let translation = app
        .world_mut()
        .spawn((Transform::default(), TranslationSpring::new(spring, target)))
        .id();
    let scale = app
        .world_mut()
        .spawn((Transform::default(), ScaleSpring::new(spring, target)))
        .id();
    let ui_scale = app
        .world_mut()
        .spawn((
            UiTransform::default(),
            UiTransformScaleSpring::new(spring, target.truncate()),
        ))
        .id();
    run(&mut app, 6);
    let put = Vec3::new(2.5, 0.5, 1.5);
    let velocities = (
        motion::<Translation>(&app, translation).velocity(),
        motion::<Scale>(&app, scale).velocity(),
        motion::<bevy_sprung::ui::UiTransformScale>(&app, ui_scale).velocity(),
    );
    assert!(
        velocities.0.length() > 1.0,
        "still moving: {}",
        velocities.0
    );
    {
        let world = app.world_mut();
        world.get_mut::<Transform>(translation).unwrap().translation = put;
        world.get_mut::<Transform>(scale).unwrap().scale = put;
        world.get_mut::<UiTransform>(ui_scale).unwrap().scale = put.truncate();
    }
    app.update();
    let step = |velocity: Vec3| {
        transition
            .step(sprung::SpringState::new(put, velocity), target)
            .position
    };
    let moved = [
        (
            app.world()
                .get::<Transform>(translation)
                .unwrap()
                .translation,
            step(velocities.0),
        ),
        (
            app.world().get::<Transform>(scale).unwrap().scale,
            step(velocities.1),
        ),
        (
            app.world()
                .get::<UiTransform>(ui_scale)
                .unwrap()
                .scale
                .extend(0.0),
            step(velocities.2.extend(0.0)).truncate().extend(0.0),
        ),
    ];
    for (moved, expected) in moved {
        assert!(moved.distance(expected) < 1e-4, "{moved} vs {expected}");
    }
}

/// Among a thousand springs of one table (in blocks of rows whose change ticks are tested
/// together), a value written mid-flight into one is sprung on from where it was put, and the
/// springs beside it move exactly as in an app where nothing was written.
#[test]
fn a_value_written_among_many_springs_moves_that_one_alone() {
    let spring = Spring::from_natural_frequency(10.0, 0.6).unwrap();
    let target = Vec3::new(3.0, 2.0, 4.0);
    let (mut written, mut untouched) = (app(60), app(60));
    let springs = many_translations(&mut written, spring, target);
    let twins = many_translations(&mut untouched, spring, target);
    run(&mut written, 6);
    run(&mut untouched, 6);
    let one = springs[300];
    let velocity = motion::<Translation>(&written, one).velocity();
    let put = Vec3::new(2.5, 0.5, 1.5);
    written
        .world_mut()
        .get_mut::<Transform>(one)
        .unwrap()
        .translation = put;
    for frame in 0..3 {
        written.update();
        untouched.update();
        if frame == 0 {
            assert_stepped_from(&written, one, spring, (put, velocity), target);
        }
        for (row, (&spring, &twin)) in springs.iter().zip(&twins).enumerate() {
            if spring != one {
                assert_eq!(
                    translation(&written, spring),
                    translation(&untouched, twin),
                    "row {row}, frame {frame}"
                );
            }
        }
    }
}

/// Springs on two fields of one component (a translation and a scale on a `Transform`: to
/// each, the other's write is a write of the component by something else) move exactly as
/// each alone, frame by frame in tables of hundreds, and settle.
#[test]
fn springs_on_two_fields_of_one_component_move_as_each_alone() {
    let mut app = app(60);
    let spring = Spring::wobbly();
    let scale_target = Vec3::new(2.0, 0.5, 3.0);
    let rows: Vec<(Entity, Entity, Entity)> = (0..300_u16)
        .map(|i| {
            let from = Transform::from_translation(Vec3::splat(f32::from(i)));
            let world = app.world_mut();
            let both = world
                .spawn((
                    from,
                    TranslationSpring::new(spring, Vec3::ZERO),
                    ScaleSpring::new(spring, scale_target),
                ))
                .id();
            let translated = world
                .spawn((from, TranslationSpring::new(spring, Vec3::ZERO)))
                .id();
            let scaled = world
                .spawn((from, ScaleSpring::new(spring, scale_target)))
                .id();
            (both, translated, scaled)
        })
        .collect();
    let transform = |app: &App, entity: Entity| *app.world().get::<Transform>(entity).unwrap();
    for frame in 0..600 {
        app.update();
        for &(both, translated, scaled) in &rows {
            let both = transform(&app, both);
            assert_eq!(
                both.translation,
                transform(&app, translated).translation,
                "frame {frame}"
            );
            assert_eq!(both.scale, transform(&app, scaled).scale, "frame {frame}");
        }
    }
    for &(both, _, _) in &rows {
        assert_eq!(transform(&app, both).translation, Vec3::ZERO);
        assert_eq!(transform(&app, both).scale, scale_target);
        assert!(asleep::<Translation>(&app, both) && asleep::<Scale>(&app, both));
    }
}
