//! The debug overlay: what it draws is what the springs then do (the predicted path is the
//! path taken), a group that is hidden draws nothing until shown, the camera's guides and the
//! chains' bones are drawn where they act, and the world changing underneath breaks nothing.

use bevy::asset::AssetPlugin;
use bevy::camera::{OrthographicProjection, Projection};
use bevy::color::palettes::css;
use bevy::gizmos::config::{GizmoConfigGroup, GizmoConfigStore};
use bevy::gizmos::{GizmoAsset, GizmoHandles, GizmoPlugin};
use bevy::input::ButtonState;
use bevy::input::InputPlugin;
use bevy::input::keyboard::{Key, KeyboardInput};
use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;
use bevy_sprung::camera::{
    CameraFraming, CameraRail, CameraTargets, Confiner, DeadZone, HardLimit, RailAim,
};
use bevy_sprung::chain::SpringChain;
use bevy_sprung::debug::{
    CameraRigGizmos, ChainGizmos, SpringDebugPlugin, SpringGizmos, ThrowGizmos, UiSpringGizmos,
};
use bevy_sprung::inertia::{DragBounds, Inertia, Snap};
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringMotion;

use bevy_sprung::ui::MomentumScroll;

use crate::camera::camera_2d;
use crate::harness::{app, primary_window, run};

/// A headless app at `fps` with the overlay (and what gizmos need: assets, input).
fn overlay_app(fps: u32, overlay: SpringDebugPlugin) -> App {
    let mut app = app(fps);
    app.add_plugins((AssetPlugin::default(), InputPlugin))
        // Bevy's gizmos draw skinned meshes' bounds: they need the mesh assets.
        .init_asset::<Mesh>()
        .init_asset::<bevy::mesh::skinning::SkinnedMeshInverseBindposes>()
        .add_plugins((GizmoPlugin, overlay));
    app
}

/// The line strips group `G` drew this frame, split at their separators.
fn strips<G: GizmoConfigGroup>(app: &App) -> Vec<Vec<Vec3>> {
    let Some(buffer) = drawn::<G>(app) else {
        return Vec::new();
    };
    buffer
        .strip_positions
        .split(|point| point.is_nan())
        .filter(|strip| !strip.is_empty())
        .map(<[Vec3]>::to_vec)
        .collect()
}

/// The segments' end points group `G` drew this frame.
fn list_points<G: GizmoConfigGroup>(app: &App) -> Vec<Vec3> {
    drawn::<G>(app)
        .map(|buffer| buffer.list_positions.clone())
        .unwrap_or_default()
}

/// What group `G` drew this frame, if anything.
fn drawn<G: GizmoConfigGroup>(
    app: &App,
) -> Option<bevy::gizmos::gizmos::GizmoBuffer<bevy::gizmos::config::ErasedGizmoConfigGroup, ()>> {
    let handles = app.world().resource::<GizmoHandles>();
    let handle = handles
        .handles()
        .get(&core::any::TypeId::of::<G>())?
        .as_ref()?;
    let asset = app.world().resource::<Assets<GizmoAsset>>().get(handle)?;
    Some(asset.buffer().clone())
}

/// Where `entity` is in the world this frame.
fn world_position(app: &App, entity: Entity) -> Vec3 {
    app.world()
        .get::<GlobalTransform>(entity)
        .unwrap()
        .translation()
}

/// A spring in flight under a moved, scaled parent: pixels far from the origin.
fn spring_in_flight(app: &mut App) -> (Entity, Entity) {
    let world = app.world_mut();
    let parent = world
        .spawn(Transform::from_xyz(1500.0, -400.0, 0.0).with_scale(Vec3::splat(2.0)))
        .id();
    let spring = world
        .spawn((
            Transform::from_xyz(0.0, 0.0, 0.0),
            TranslationSpring::new(Spring::bouncy(), Vec3::new(300.0, 120.0, 0.0))
                .with_velocity(Vec3::new(-400.0, 900.0, 0.0)),
            ChildOf(parent),
        ))
        .id();
    (parent, spring)
}

#[test]
fn the_drawn_path_is_the_path_the_spring_then_takes() {
    for fps in [30, 60, 144, 240] {
        let mut app = overlay_app(fps, SpringDebugPlugin::default());
        // The path sampled at this app's frames.
        app.world_mut()
            .resource_mut::<GizmoConfigStore>()
            .config_mut::<SpringGizmos>()
            .1
            .path_step = 1.0 / fps as f32;
        let (_, spring) = spring_in_flight(&mut app);
        app.update();
        app.update();
        // The drawn strip that starts where the spring is now.
        let here = world_position(&app, spring);
        let path = strips::<SpringGizmos>(&app)
            .into_iter()
            .find(|strip| strip[0].distance(here) < 1e-3)
            .unwrap_or_else(|| panic!("{fps} fps: no path drawn from {here}"));
        assert!(
            path.len() > fps as usize / 4,
            "{fps} fps: a path of {} points",
            path.len()
        );
        // Each later frame puts the spring on the next point drawn (to rounding at ~2000 px).
        let tolerance = 512.0 * f32::EPSILON * 2500.0;
        let taken = |app: &App| world_position(app, spring);
        assert_follows(&mut app, &path, taken, tolerance, &format!("{fps} fps"));
    }
}

#[test]
fn the_settle_label_is_the_forecast_and_a_spring_asleep_is_a_ring() {
    let mut app = overlay_app(60, SpringDebugPlugin::default());
    let (_, spring) = spring_in_flight(&mut app);
    app.update();
    app.update();
    let world = app.world();
    let forecast = world
        .get::<TranslationSpring>(spring)
        .unwrap()
        .forecast(world.get::<SpringMotion<Translation>>(spring).unwrap());
    let settle = forecast.settle_time().unwrap();
    assert!(
        settle > 0.5,
        "a bouncy spring in flight settles in {settle} s"
    );
    // The label's strokes: more strips than the path and the arrow alone.
    let awake = strips::<SpringGizmos>(&app).len();
    assert!(awake > 3, "{awake} strips drawn");
    // Asleep: one ring where it rests, nothing else.
    for _ in 0..600 {
        app.update();
    }
    let rest = world_position(&app, spring);
    let drawn = strips::<SpringGizmos>(&app);
    assert_eq!(drawn.len(), 1, "asleep: {} strips", drawn.len());
    let ring = &drawn[0];
    let centre = ring.iter().copied().sum::<Vec3>() / ring.len() as f32;
    assert!(
        centre.distance(rest) < 0.5,
        "a ring around {centre}, the spring at {rest}"
    );
}

/// A key press as the window system sends it.
fn press(app: &mut App, key: KeyCode) {
    let window = app.world_mut().spawn_empty().id();
    for state in [ButtonState::Pressed, ButtonState::Released] {
        app.world_mut().write_message(KeyboardInput {
            key_code: key,
            logical_key: Key::Character("d".into()),
            state,
            text: None,
            repeat: false,
            window,
        });
        app.update();
    }
}

#[test]
fn a_hidden_overlay_draws_nothing_until_its_key_shows_it() {
    let mut app = overlay_app(60, SpringDebugPlugin::hidden().toggled_by(KeyCode::KeyD));
    spring_in_flight(&mut app);
    for _ in 0..3 {
        app.update();
        assert!(strips::<SpringGizmos>(&app).is_empty());
    }
    press(&mut app, KeyCode::KeyD);
    app.update();
    assert!(!strips::<SpringGizmos>(&app).is_empty(), "shown by the key");
    let store = app.world().resource::<GizmoConfigStore>();
    assert!(store.config::<ChainGizmos>().0.enabled && store.config::<CameraRigGizmos>().0.enabled);
    press(&mut app, KeyCode::KeyD);
    app.update();
    assert!(strips::<SpringGizmos>(&app).is_empty(), "hidden again");
}

#[test]
fn the_dead_zone_is_drawn_around_the_held_point() {
    let mut app = overlay_app(60, SpringDebugPlugin::default());
    primary_window(app.world_mut(), 1280, 720);
    let player = app
        .world_mut()
        .spawn(Transform::from_xyz(100.0, 50.0, 0.0))
        .id();
    let camera = app
        .world_mut()
        .spawn((
            Camera2d,
            Projection::Orthographic(OrthographicProjection::default_2d()),
            CameraRig::new(Spring::smooth()),
            CameraTargets::single(player),
            DeadZone::view(Vec2::new(0.2, 0.3)),
            Confiner::new(Rect::new(-2000.0, -1000.0, 2000.0, 1000.0)).with_slowing_distance(64.0),
        ))
        .id();
    for frame in 0..30 {
        app.world_mut()
            .get_mut::<Transform>(player)
            .unwrap()
            .translation
            .x += 12.0;
        app.update();
        let framing = *app.world().get::<CameraFraming>(camera).unwrap();
        // The zone is a fifth of 1280 wide and 0.3 of 720 high.
        assert!((framing.dead_zone().truncate() - Vec2::new(128.0, 108.0)).length() < 1e-3);
        // The player never leaves the zone around the held point.
        let reach = (framing.point() - framing.held()).abs();
        assert!(
            reach.cmple(framing.dead_zone() + 1e-3).all(),
            "frame {frame}: {reach}"
        );
        // The zone's corners are drawn.
        let corner = framing.held() + framing.dead_zone();
        let lines = list_points::<CameraRigGizmos>(&app);
        assert!(
            lines.iter().any(|point| point.distance(corner) < 1e-3),
            "frame {frame}: no corner at {corner}"
        );
    }
}

#[test]
fn chains_draw_their_bones_and_survive_a_despawned_joint() {
    let mut app = overlay_app(60, SpringDebugPlugin::default());
    let world = app.world_mut();
    let root = world
        .spawn((
            Transform::default(),
            SpringChain::new(Spring::bouncy()).with_gravity(Vec3::NEG_Y * 300.0),
        ))
        .id();
    let mut joints = vec![root];
    for _ in 0..3 {
        let joint = world.spawn(Transform::from_xyz(20.0, 0.0, 0.0)).id();
        world.entity_mut(*joints.last().unwrap()).add_child(joint);
        joints.push(joint);
    }
    for _ in 0..20 {
        app.update();
    }
    let bones: Vec<_> = app
        .world()
        .get::<SpringChain>(root)
        .unwrap()
        .bones()
        .collect();
    assert_eq!(bones.len(), 3, "three joints with a child joint");
    let lines = list_points::<ChainGizmos>(&app);
    for bone in &bones {
        assert!(
            lines.iter().any(|point| point.distance(bone.tip) < 1e-3),
            "no bone drawn to {}",
            bone.tip
        );
    }
    // The world changes underneath: a joint despawned, then the chain's root.
    app.world_mut().entity_mut(joints[2]).despawn();
    for _ in 0..5 {
        app.update();
    }
    app.world_mut().entity_mut(root).despawn();
    for _ in 0..5 {
        app.update();
    }
    assert!(list_points::<ChainGizmos>(&app).is_empty());
}

#[test]
fn springs_whose_parent_or_component_goes_away_are_still_drawn_or_dropped() {
    let mut app = overlay_app(60, SpringDebugPlugin::default());
    let (parent, spring) = spring_in_flight(&mut app);
    app.update();
    // The parent loses its transform: the spring is drawn in its own space.
    app.world_mut()
        .entity_mut(parent)
        .remove::<(Transform, GlobalTransform)>();
    app.update();
    assert!(!strips::<SpringGizmos>(&app).is_empty());
    // The spring's component removed: nothing to draw.
    app.world_mut()
        .entity_mut(spring)
        .remove::<TranslationSpring>();
    app.update();
    assert!(strips::<SpringGizmos>(&app).is_empty());
}

#[test]
fn without_bevy_s_gizmos_the_overlay_says_so_and_draws_nothing() {
    let mut app = app(60);
    app.add_plugins(SpringDebugPlugin::default());
    spring_in_flight(&mut app);
    // No gizmo storage, no systems: frames run as without it.
    for _ in 0..3 {
        app.update();
    }
    assert!(!app.world().contains_resource::<GizmoConfigStore>());
}

/// The lowest and highest corners of a drawn strip's box.
fn bounds(strip: &[Vec3]) -> (Vec3, Vec3) {
    strip
        .iter()
        .fold((Vec3::MAX, Vec3::MIN), |(l, h), p| (l.min(*p), h.max(*p)))
}

/// The width and height of a drawn strip.
fn extent(strip: &[Vec3]) -> Vec2 {
    let (low, high) = bounds(strip);
    (high - low).truncate()
}

/// The centre and radius of a drawn circle (a closed strip).
fn circle_of(strip: &[Vec3]) -> (Vec3, f32) {
    let ring = &strip[..strip.len() - 1];
    let centre = ring.iter().copied().sum::<Vec3>() / ring.len() as f32;
    (centre, strip[0].distance(centre))
}

/// A rail is drawn along its curve with a ring where the camera is on it, and a hard limit
/// as its rectangle and slowing band around where the camera looks, frame by frame.
#[test]
fn a_rail_and_a_hard_limit_are_drawn_where_they_act() {
    use bevy::math::cubic_splines::{CubicCardinalSpline, CubicGenerator};

    let mut app = overlay_app(60, SpringDebugPlugin::default());
    primary_window(app.world_mut(), 1280, 720);
    let player = app
        .world_mut()
        .spawn(Transform::from_xyz(-800.0, 0.0, 0.0))
        .id();
    // A rail across the level with a rise in the middle, in the camera's plane.
    let rail = CubicCardinalSpline::new_catmull_rom([
        Vec3::new(-3000.0, 0.0, 500.0),
        Vec3::new(0.0, 400.0, 500.0),
        Vec3::new(3000.0, 0.0, 500.0),
    ])
    .to_curve()
    .unwrap();
    let camera = app
        .world_mut()
        .spawn((
            camera_2d(CameraRig::new(Spring::smooth())),
            CameraTargets::single(player),
            CameraRail::new(rail).aiming(RailAim::Unchanged),
        ))
        .id();
    // A second camera, not on a rail, keeps the player inside its hard limit.
    let limited = app
        .world_mut()
        .spawn((
            camera_2d(CameraRig::new(Spring::smooth())),
            CameraTargets::single(player),
            HardLimit::view(Vec2::new(0.8, 0.6)),
        ))
        .id();
    // Fast enough to reach the limit.
    for frame in 0..60 {
        app.world_mut()
            .get_mut::<Transform>(player)
            .unwrap()
            .translation
            .x += 40.0;
        app.update();
        let eye = world_position(&app, camera);
        // The rail from end to end, every point on the curve's plane.
        let rails = strips_in::<CameraRigGizmos>(&app, css::TEAL);
        assert_eq!(rails.len(), 1, "frame {frame}");
        let rail = &rails[0];
        assert!(rail[0].distance(Vec3::new(-3000.0, 0.0, 500.0)) < 1e-2);
        assert!(rail[rail.len() - 1].distance(Vec3::new(3000.0, 0.0, 500.0)) < 1e-2);
        assert!(rail.iter().all(|point| point.z == 500.0));
        // A ring round the camera's place on it.
        let rings = strips_in::<CameraRigGizmos>(&app, css::AQUAMARINE);
        assert!(
            rings
                .iter()
                .any(|ring| circle_of(ring).0.distance(eye) < 1e-2),
            "frame {frame}: no ring at {eye}"
        );
        // The limit: 0.8 × 0.6 of the view round where the camera looks, and inside it the
        // band a tenth of the view wide.
        for (color, size) in [
            (css::TOMATO, Vec2::new(1024.0, 432.0)),
            (css::DARK_SALMON, Vec2::new(768.0, 176.0)),
        ] {
            let drawn = strips_in::<CameraRigGizmos>(&app, color);
            assert_eq!(drawn.len(), 1, "frame {frame}");
            assert!((extent(&drawn[0]) - size).length() < 1e-2, "frame {frame}");
            let (low, high) = bounds(&drawn[0]);
            let centre = (low + high).truncate() * 0.5;
            let looking = world_position(&app, limited).truncate();
            assert!(
                centre.distance(looking) < 1e-2,
                "frame {frame}: {centre} {looking}"
            );
        }
    }
}

/// A rotation spring's pointer: the path drawn for its tip is where the tip then is, frame by
/// frame, under a moved and turned parent.
#[test]
fn a_rotation_springs_drawn_tip_path_is_the_turn_it_then_takes() {
    for fps in [30, 60, 144, 240] {
        let mut app = overlay_app(fps, SpringDebugPlugin::default());
        let mut store = app.world_mut().resource_mut::<GizmoConfigStore>();
        store.config_mut::<SpringGizmos>().1.path_step = 1.0 / fps as f32;
        let size = store.config::<SpringGizmos>().1.size;
        let parent = app
            .world_mut()
            .spawn(
                Transform::from_xyz(-1800.0, 700.0, 0.0).with_rotation(Quat::from_rotation_z(0.7)),
            )
            .id();
        let spring = app
            .world_mut()
            .spawn((
                Transform::from_xyz(40.0, 0.0, 0.0),
                RotationSpring::new(Spring::wobbly(), Quat::from_rotation_z(2.5))
                    .with_velocity(Vec3::new(0.0, 0.0, -6.0)),
                ChildOf(parent),
            ))
            .id();
        app.update();
        app.update();
        let tip = |app: &App| {
            let global = app.world().get::<GlobalTransform>(spring).unwrap();
            global.translation() + global.rotation() * Vec3::X * size * 4.0
        };
        let now = tip(&app);
        let path = strips::<SpringGizmos>(&app)
            .into_iter()
            .find(|strip| strip.len() > 2 && strip[0].distance(now) < 1e-2)
            .unwrap_or_else(|| panic!("{fps} fps: no tip path drawn from {now}"));
        assert_follows(&mut app, &path, tip, 2e-3, &format!("{fps} fps"));
    }
}

/// A fling is drawn with its bounds and snap points, and the rest ring drawn at the start of
/// the throw is where it comes to rest: a free coast, and a snap to a point.
#[test]
fn a_throws_rest_ring_is_where_it_comes_to_rest() {
    let bounds = DragBounds {
        min: Vec3::new(-2000.0, -900.0, 0.0),
        max: Vec3::new(2000.0, 900.0, 0.0),
        give: 60.0,
    };
    let slots = vec![
        Vec3::new(1200.0, 300.0, 0.0),
        Vec3::new(-900.0, -500.0, 0.0),
    ];
    for (inertia, fling) in [
        (Inertia::new(2.0), Vec3::new(900.0, -400.0, 0.0)),
        (
            Inertia::new(3.0)
                .bounded(bounds)
                .snapping(Snap::Points(slots.clone())),
            Vec3::new(2400.0, 700.0, 0.0),
        ),
    ] {
        let mut app = overlay_app(60, SpringDebugPlugin::default());
        let size = app
            .world()
            .resource::<GizmoConfigStore>()
            .config::<ThrowGizmos>()
            .1
            .size;
        let puck = app
            .world_mut()
            .spawn((Transform::from_xyz(150.0, 80.0, 0.0), inertia.clone()))
            .id();
        app.update();
        app.world_mut()
            .get_mut::<Inertia>(puck)
            .unwrap()
            .fling(fling);
        app.update();
        app.update();
        let circles: Vec<(Vec3, f32)> = strips::<ThrowGizmos>(&app)
            .iter()
            .filter(|strip| strip.len() > 8)
            .map(|strip| circle_of(strip))
            .collect();
        let rest = circles
            .iter()
            .find(|(_, radius)| (radius - size).abs() < 0.1)
            .unwrap_or_else(|| panic!("no rest ring among {circles:?}"))
            .0;
        if inertia.bounds.is_some() {
            for slot in &slots {
                assert!(
                    circles
                        .iter()
                        .any(|(centre, _)| centre.distance(*slot) < 1e-2),
                    "slot {slot} not drawn"
                );
            }
            let extents: Vec<Vec2> = strips::<ThrowGizmos>(&app)
                .iter()
                .map(|strip| extent(strip))
                .collect();
            for (name, give) in [("bounds", 0.0), ("give", 2.0 * bounds.give)] {
                let wanted = (bounds.max - bounds.min).truncate() + give;
                assert!(
                    extents.iter().any(|e| e.distance(wanted) < 1e-3),
                    "the {name} box {wanted} is not among {extents:?}"
                );
            }
        }
        for _ in 0..1200 {
            app.update();
        }
        let stopped = world_position(&app, puck);
        assert!(
            stopped.distance(rest) < 1e-3 * stopped.length().max(1.0),
            "drawn rest {rest}, stopped at {stopped}"
        );
    }
}

/// A scale spring's boxes: the target's, at the target scale times the parent's.
#[test]
fn a_scale_springs_target_box_is_its_target_scale() {
    let mut app = overlay_app(60, SpringDebugPlugin::default());
    let size = app
        .world()
        .resource::<GizmoConfigStore>()
        .config::<SpringGizmos>()
        .1
        .size;
    let parent = app
        .world_mut()
        .spawn(Transform::from_xyz(600.0, 200.0, 0.0).with_scale(Vec3::splat(3.0)))
        .id();
    app.world_mut().spawn((
        Transform::default(),
        ScaleSpring::new(Spring::bouncy(), Vec3::new(2.0, 0.5, 1.0)),
        ChildOf(parent),
    ));
    app.update();
    app.update();
    let widths: Vec<Vec2> = strips::<SpringGizmos>(&app)
        .iter()
        .map(|strip| extent(strip))
        .collect();
    let target = Vec2::new(2.0, 0.5) * 3.0 * size * 4.0;
    assert!(
        widths.iter().any(|w| w.distance(target) < 1e-3),
        "no box of {target} among {widths:?}"
    );
}

/// A one-second hitch: the spring lands on the point of the path drawn before it for the time
/// the game clock advanced (Bevy caps a frame's virtual step at a quarter second).
#[test]
fn after_a_hitch_the_spring_is_on_the_path_drawn_before_it() {
    let mut app = overlay_app(60, SpringDebugPlugin::default());
    let (_, spring) = spring_in_flight(&mut app);
    app.update();
    app.update();
    let here = world_position(&app, spring);
    let path = strips::<SpringGizmos>(&app)
        .into_iter()
        .find(|strip| strip[0].distance(here) < 1e-3)
        .expect("a path drawn from the spring");
    app.insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(
        std::time::Duration::from_secs(1),
    ));
    app.update();
    let advanced = app.world().resource::<Time<Virtual>>().delta_secs();
    // The virtual step in frames of 1/60 s: a whole number (0.25 s is 15).
    let index = (1..=60)
        .find(|&frames| (frames as f32 / 60.0 - advanced).abs() < 1e-4)
        .expect("a whole number of frames");
    assert!(
        index >= 15,
        "the hitch advanced the game clock {advanced} s"
    );
    let taken = world_position(&app, spring);
    assert!(
        taken.distance(path[index]) <= 512.0 * f32::EPSILON * 2500.0,
        "after {advanced} s: drawn {}, taken {taken}",
        path[index]
    );
}

/// A change of shot: the blend path drawn is where the camera then goes, frame by frame.
#[test]
fn the_drawn_blend_is_the_path_the_camera_then_takes() {
    use bevy_sprung::camera::{CameraBlend, VirtualCamera};
    let mut app = overlay_app(60, SpringDebugPlugin::default());
    app.world_mut()
        .spawn((VirtualCamera::new(2), Transform::from_xyz(0.0, 0.0, 900.0)));
    let close = app
        .world_mut()
        .spawn((
            VirtualCamera::new(1),
            Transform::from_xyz(1400.0, -300.0, 400.0),
        ))
        .id();
    let camera = app
        .world_mut()
        .spawn((Camera3d::default(), CameraBlend::new(Spring::smooth())))
        .id();
    app.update();
    app.update();
    app.world_mut()
        .get_mut::<VirtualCamera>(close)
        .unwrap()
        .priority = 3;
    app.update();
    app.update();
    let here = world_position(&app, camera);
    let path = strips::<CameraRigGizmos>(&app)
        .into_iter()
        .find(|strip| strip.len() > 10 && strip[0].distance(here) < 1e-3)
        .unwrap_or_else(|| panic!("no blend path drawn from {here}"));
    assert!(path.len() > 20, "a blend of {} points", path.len());
    let tolerance = 512.0 * f32::EPSILON * 1500.0;
    let taken = |app: &App| world_position(app, camera);
    assert_follows(&mut app, &path[..61], taken, tolerance, "blend");
}

/// Each later frame puts what `taken` reads on the next point of `path` (drawn the frame before
/// the first of them), to `tolerance`.
fn assert_follows(
    app: &mut App,
    path: &[Vec3],
    taken: impl Fn(&App) -> Vec3,
    tolerance: f32,
    case: &str,
) {
    for (frame, &point) in path.iter().enumerate().skip(1) {
        app.update();
        let taken = taken(app);
        assert!(
            taken.distance(point) <= tolerance,
            "{case}, frame {frame}: drawn {point}, taken {taken}"
        );
    }
}

/// The strips group `G` drew this frame in `color`, split at their separators.
fn strips_in<G: GizmoConfigGroup>(app: &App, color: impl Into<LinearRgba>) -> Vec<Vec<Vec3>> {
    let color = color.into();
    let Some(buffer) = drawn::<G>(app) else {
        return Vec::new();
    };
    let mut found = Vec::new();
    let mut strip: Vec<Vec3> = Vec::new();
    let mut matches = false;
    for (&point, &drawn_in) in buffer.strip_positions.iter().zip(&buffer.strip_colors) {
        if point.is_nan() {
            if matches && !strip.is_empty() {
                found.push(core::mem::take(&mut strip));
            }
            strip.clear();
            continue;
        }
        if strip.is_empty() {
            matches = drawn_in.to_vec4().distance(color.to_vec4()) < 1e-4;
        }
        strip.push(point);
    }
    if matches && !strip.is_empty() {
        found.push(strip);
    }
    found
}

/// The UI test app (800×600, `bevy_ui`'s layout) with the overlay, its camera given the
/// projection a renderer would: `perspective` puts a 3D camera at an angle, else the 2D one
/// stays at the origin.
fn ui_overlay_app(fps: u32, perspective: bool) -> App {
    use bevy::camera::CameraProjection;
    let mut app = crate::layout::ui_app(fps);
    app.add_plugins((AssetPlugin::default(), InputPlugin))
        .init_asset::<Mesh>()
        .init_asset::<bevy::mesh::skinning::SkinnedMeshInverseBindposes>()
        .add_plugins((GizmoPlugin, SpringDebugPlugin::default()));
    let size = Vec2::new(crate::layout::WIDTH as f32, crate::layout::HEIGHT as f32);
    let world = app.world_mut();
    let camera = world
        .query_filtered::<Entity, With<Camera>>()
        .single(world)
        .unwrap();
    let mut entity = world.entity_mut(camera);
    let clip_from_view = if perspective {
        entity.insert(Transform::from_xyz(3.0, 2.0, 10.0).looking_at(Vec3::ZERO, Vec3::Y));
        PerspectiveProjection {
            aspect_ratio: size.x / size.y,
            ..default()
        }
        .get_clip_from_view()
    } else {
        let mut projection = OrthographicProjection::default_2d();
        projection.update(size.x, size.y);
        projection.get_clip_from_view()
    };
    entity.get_mut::<Camera>().unwrap().computed.clip_from_view = clip_from_view;
    app
}

/// The UI pixel a world point is drawn at, through the app's camera (Bevy's own projection).
fn ui_pixel(app: &mut App, point: Vec3) -> Vec2 {
    let world = app.world_mut();
    let (camera, global) = world
        .query::<(&Camera, &GlobalTransform)>()
        .single(world)
        .unwrap();
    let ndc = camera.world_to_ndc(global, point).unwrap();
    Vec2::new(
        (ndc.x + 1.0) * 0.5 * crate::layout::WIDTH as f32,
        (1.0 - ndc.y) * 0.5 * crate::layout::HEIGHT as f32,
    )
}

/// A strip's corners in UI pixels, and the box they span.
fn pixel_box(app: &mut App, strip: &[Vec3]) -> Rect {
    let mut rect = Rect::EMPTY;
    for &point in strip {
        rect = rect.union_point(ui_pixel(app, point));
    }
    rect
}

/// How far outside a node's edges the UI group draws its boxes, in logical pixels (so that the
/// node's background, drawn over the gizmos, does not hide them).
const OUTSET: f32 = 2.0;

/// The UI group's paths sampled at `fps`, the app's frames.
fn ui_paths_at(app: &mut App, fps: u32) {
    app.world_mut()
        .resource_mut::<GizmoConfigStore>()
        .config_mut::<UiSpringGizmos>()
        .1
        .path_step = 1.0 / fps as f32;
}

/// A 100 px node at (300, 200) scaled by 2: its children move twice as far on screen.
fn scaled_parent(app: &mut App) -> Entity {
    app.world_mut()
        .spawn((
            Node {
                width: px(100.0),
                height: px(100.0),
                left: px(300.0),
                top: px(200.0),
                ..default()
            },
            UiTransform::from_scale(Vec2::splat(2.0)),
        ))
        .id()
}

/// The box spanned by the first strip the UI group drew in `color`, in UI pixels.
fn first_box(app: &mut App, color: impl Into<LinearRgba>) -> Rect {
    let strip = strips_in::<UiSpringGizmos>(app, color)
        .into_iter()
        .next()
        .expect("a strip in that colour");
    pixel_box(app, &strip)
}

/// A reordered column's moving item: its box is drawn where it is drawn and where layout puts
/// it, and the path drawn for its centre is the one it then takes, frame by frame — with a 2D
/// camera and a 3D one at an angle (checked through Bevy's own projection).
#[test]
fn a_layout_springs_boxes_and_path_are_where_it_is_drawn_and_placed() {
    use crate::layout::{drawn as drawn_at, last_to_top, slot, spawn_column};
    for perspective in [false, true] {
        for fps in [30, 60, 144, 240] {
            let mut app = ui_overlay_app(fps, perspective);
            ui_paths_at(&mut app, fps);
            let (column, items) = spawn_column(&mut app, 5, Spring::bouncy());
            run(&mut app, 3);
            last_to_top(&mut app, column);
            app.update();
            app.update();
            let item = items[4];
            let case = format!("{fps} fps, perspective {perspective}");
            let gold = strips_in::<UiSpringGizmos>(&app, css::GOLD);
            let placed = pixel_box(&mut app, &gold[0]);
            let expected = Rect::from_center_size(slot(0), Vec2::new(200.0, 40.0)).inflate(OUTSET);
            assert!(
                placed.min.distance(expected.min) < 0.05
                    && placed.max.distance(expected.max) < 0.05,
                "{case}: placed box {placed:?}, layout puts it at {expected:?}"
            );
            let now = drawn_at(&app, item);
            let aqua = strips_in::<UiSpringGizmos>(&app, css::AQUA);
            let shown = aqua
                .iter()
                .find(|strip| strip.len() == 5)
                .map(|strip| pixel_box(&mut app, strip))
                .unwrap();
            assert!(
                shown.center().distance(now) < 0.05,
                "{case}: drawn box at {:?}, the node at {now}",
                shown.center()
            );
            let path: Vec<Vec2> = aqua
                .iter()
                .find(|strip| strip.len() > 5)
                .unwrap()
                .iter()
                .map(|&point| ui_pixel(&mut app, point))
                .collect();
            assert!(
                path[0].distance(now) < 0.05,
                "{case}: path from {}",
                path[0]
            );
            assert!(
                path.len() > fps as usize / 4,
                "{case}: {} points",
                path.len()
            );
            let path: Vec<Vec3> = path.iter().map(|point| point.extend(0.0)).collect();
            let taken = |app: &App| drawn_at(app, item).extend(0.0);
            assert_follows(&mut app, &path, taken, 0.05, &case);
        }
    }
}

/// A fling's rest is drawn where the scroll then rests: inside, and at the end for a fling
/// that would pass it; the area's give is drawn along the axis it scrolls.
#[test]
fn a_scrolls_drawn_rest_is_where_it_comes_to_rest() {
    use crate::layout::{scroll_position, spawn_scroll_area, steer};
    for (from, velocity) in [(1000.0, 800.0), (3600.0, 2500.0), (500.0, -2000.0)] {
        let mut app = ui_overlay_app(60, false);
        let (area, _) = spawn_scroll_area(&mut app, MomentumScroll::default());
        run(&mut app, 3);
        steer(&mut app, area, |scroll| scroll.drag_by(Vec2::Y * from));
        app.update();
        steer(&mut app, area, |scroll| scroll.fling(Vec2::Y * velocity));
        app.update();
        let case = format!("fling at {velocity} from {from}");
        let rest_box = first_box(&mut app, css::MAGENTA);
        let give = first_box(&mut app, css::YELLOW.with_alpha(0.35));
        assert!(
            (give.size() - Vec2::new(200.0, 200.0 + 2.0 * 120.0) - Vec2::splat(2.0 * OUTSET))
                .length()
                < 0.05,
            "{case}: give {give:?}"
        );
        run(&mut app, 600);
        let rest = scroll_position(&app, area);
        // The content, 4000 px high, drawn with its top `rest` above the area's.
        let expected = Rect::new(0.0, -rest, 200.0, 4000.0 - rest).inflate(OUTSET);
        assert!(
            rest_box.min.distance(expected.min) < 0.1 && rest_box.max.distance(expected.max) < 0.1,
            "{case}: rest drawn at {rest_box:?}, came to rest at {expected:?}"
        );
        let shown = first_box(&mut app, css::AQUA.with_alpha(0.6));
        assert!(
            shown.min.distance(expected.min) < 0.1,
            "{case}: shown {shown:?}"
        );
        assert!(
            strips_in::<UiSpringGizmos>(&app, css::MAGENTA).is_empty(),
            "{case}"
        );
    }
}

/// A `UiTransform` translation spring under a scaled parent: its path is drawn along the
/// parent's axes and is the path its node then takes, and its target is drawn where it ends.
#[test]
fn a_ui_translation_springs_path_is_the_path_its_node_takes() {
    for fps in [30, 60, 144, 240] {
        let mut app = ui_overlay_app(fps, true);
        ui_paths_at(&mut app, fps);
        let parent = scaled_parent(&mut app);
        let node = app
            .world_mut()
            .spawn((
                Node {
                    width: px(20.0),
                    height: px(20.0),
                    ..default()
                },
                UiTransformTranslationSpring::new(Spring::bouncy(), Val2::px(60.0, -30.0))
                    .with_velocity(Vec2::new(-300.0, 200.0)),
                ChildOf(parent),
            ))
            .id();
        app.update();
        app.update();
        let case = format!("{fps} fps");
        let path: Vec<Vec2> = strips_in::<UiSpringGizmos>(&app, css::AQUA)[0]
            .iter()
            .map(|&point| ui_pixel(&mut app, point))
            .collect();
        let centre = |app: &App| {
            app.world()
                .get::<UiGlobalTransform>(node)
                .unwrap()
                .translation
        };
        assert!(path[0].distance(centre(&app)) < 0.05, "{case}");
        // The target's cross: its segments' ends, symmetric about its centre.
        let gold = LinearRgba::from(css::GOLD);
        let cross: Vec<Vec3> = drawn::<UiSpringGizmos>(&app)
            .map(|buffer| {
                buffer
                    .list_positions
                    .iter()
                    .zip(&buffer.list_colors)
                    .filter(|(_, color)| color.to_vec4().distance(gold.to_vec4()) < 1e-4)
                    .map(|(&point, _)| point)
                    .collect()
            })
            .unwrap_or_default();
        assert_eq!(cross.len(), 6, "{case}: a cross of three segments");
        let target = ui_pixel(&mut app, cross.iter().sum::<Vec3>() / 6.0);
        let followed: Vec<Vec3> = path.iter().map(|point| point.extend(0.0)).collect();
        let taken = |app: &App| centre(app).extend(0.0);
        assert_follows(&mut app, &followed, taken, 0.05, &case);
        run(&mut app, 2 * fps);
        // At rest where the path ends and the cross is.
        let end = *path.last().unwrap();
        assert!(
            centre(&app).distance(end) < 0.1,
            "{case}: ends at {}",
            centre(&app)
        );
        assert!(
            centre(&app).distance(target) < 0.05,
            "{case}: rests at {}, the target drawn at {target}",
            centre(&app)
        );
    }
}

/// A UI drag's bounds and snap points are drawn in its translation's pixels, along its
/// parent's axes (twice as large under a parent scaled by 2), around where it is drawn.
#[test]
fn a_ui_drags_bounds_and_snap_points_are_drawn_in_its_pixels() {
    use bevy_sprung::interaction::SpringDrag;
    let mut app = ui_overlay_app(60, true);
    let parent = scaled_parent(&mut app);
    let bounds = DragBounds {
        min: Vec3::new(-50.0, -20.0, 0.0),
        max: Vec3::new(70.0, 40.0, 0.0),
        give: 10.0,
    };
    let node = app
        .world_mut()
        .spawn((
            Node {
                width: px(20.0),
                height: px(20.0),
                ..default()
            },
            UiTransform::from_translation(Val2::px(10.0, 0.0)),
            UiTransformTranslationSpring::new(Spring::snappy(), Val2::px(10.0, 0.0)),
            SpringDrag::new()
                .bounded(bounds)
                .snapping(Snap::Points(vec![Vec3::new(60.0, 30.0, 0.0)])),
            ChildOf(parent),
        ))
        .id();
    app.update();
    app.update();
    let centre = app
        .world()
        .get::<UiGlobalTransform>(node)
        .unwrap()
        .translation;
    // Bounds from 60 px left of the node to 60 px right (twice (−50 − 10) and (70 − 10)).
    let drawn = first_box(&mut app, css::YELLOW);
    let expected = Rect::from_corners(
        centre + 2.0 * Vec2::new(-60.0, -20.0),
        centre + 2.0 * Vec2::new(60.0, 40.0),
    );
    assert!(
        drawn.min.distance(expected.min) < 0.05 && drawn.max.distance(expected.max) < 0.05,
        "bounds drawn {drawn:?}, expected {expected:?}"
    );
    let give = first_box(&mut app, css::YELLOW.with_alpha(0.35));
    assert!((give.size() - expected.size() - Vec2::splat(40.0)).length() < 0.05);
    let point = first_box(&mut app, css::DEEP_SKY_BLUE).center();
    let expected_point = centre + 2.0 * Vec2::new(50.0, 30.0);
    assert!(
        point.distance(expected_point) < 0.05,
        "snap point drawn at {point}, expected {expected_point}"
    );
}

/// The world changing under a UI overlay: the camera despawned, a node despawned or its
/// parent taken away mid-flight, all in one frame: nothing panics, and nothing is drawn for
/// UI with no camera.
#[test]
fn ui_nodes_losing_their_camera_or_parent_mid_flight_break_nothing() {
    use crate::layout::{last_to_top, spawn_column, spawn_scroll_area, steer};
    let mut app = ui_overlay_app(60, false);
    let (column, items) = spawn_column(&mut app, 5, Spring::bouncy());
    let (area, _) = spawn_scroll_area(&mut app, MomentumScroll::default());
    run(&mut app, 3);
    last_to_top(&mut app, column);
    steer(&mut app, area, |scroll| scroll.fling(Vec2::Y * 900.0));
    app.update();
    app.update();
    assert!(!strips_in::<UiSpringGizmos>(&app, css::GOLD).is_empty());
    app.world_mut().entity_mut(items[4]).despawn();
    app.world_mut().entity_mut(items[2]).remove::<ChildOf>();
    run(&mut app, 2);
    let world = app.world_mut();
    let camera = world
        .query_filtered::<Entity, With<Camera>>()
        .single(world)
        .unwrap();
    world.entity_mut(camera).despawn();
    run(&mut app, 30);
    assert!(drawn::<UiSpringGizmos>(&app).is_none_or(|buffer| buffer.strip_positions.is_empty()));
}
