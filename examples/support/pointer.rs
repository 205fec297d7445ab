//! A scripted mouse pointer for the tour (`support/tour.rs`): it writes `PointerInput`
//! messages for the mouse, as `bevy_picking`'s mouse input does for a real cursor, so picking,
//! hover, press, drag and release all run for real. A dot shows where it is (no cursor is drawn
//! under Xvfb). When the tour ends, the mouse drives the pointer again.
//!
//! An example includes it with `#[path = "support/pointer.rs"] mod pointer;` beside the tour,
//! and adds `TourPointerPlugin::new(path)` with the pointer's [`Waypoint`]s.

use bevy::camera::RenderTarget;
use bevy::picking::PickingSystems;
use bevy::picking::input::{PointerInputSettings, mouse_pick_events};
use bevy::picking::pointer::{Location, PointerAction, PointerButton, PointerId, PointerInput};
use bevy::prelude::*;
use bevy::window::{PrimaryWindow, WindowRef};

use crate::tour::{Tour, TourSystems};

/// Drives the mouse pointer along a path of [`Waypoint`]s while the tour runs.
pub(crate) struct TourPointerPlugin {
    path: Vec<Waypoint>,
}

impl TourPointerPlugin {
    /// The pointer's path, in the order of its waypoints' times.
    pub(crate) fn new(path: Vec<Waypoint>) -> Self {
        Self { path }
    }
}

impl Plugin for TourPointerPlugin {
    fn build(&self, app: &mut App) {
        app.insert_resource(TourPointer {
            path: self.path.clone(),
            position: None,
            down: false,
            segment: usize::MAX,
            segment_start: None,
        })
        // While the tour runs it owns the mouse pointer: a cursor that merely sits over the
        // window (an X server's, at start-up) does not move it.
        .insert_resource(PointerInputSettings {
            is_mouse_enabled: false,
            is_touch_enabled: true,
        })
        .add_systems(Startup, spawn_dot)
        // Written where the mouse's input is written, so this frame's picking sees it through
        // the same camera transform.
        .add_systems(
            First,
            drive_pointer
                .in_set(PickingSystems::Input)
                .after(mouse_pick_events)
                .after(TourSystems),
        );
    }
}

/// How the pointer moves into a waypoint.
#[derive(Clone, Copy)]
pub(crate) enum Ease {
    /// At a constant speed (a drag that flings).
    Linear,
    /// Starting and stopping smoothly.
    InOut,
    /// Starting at twice the average speed and slowing to a stop (a follow-through).
    Out,
}

impl Ease {
    /// The fraction of the way covered at `u`, the fraction of the time.
    fn apply(self, u: f32) -> f32 {
        match self {
            Self::Linear => u,
            Self::InOut => u * u * (3.0 - 2.0 * u),
            Self::Out => 1.0 - (1.0 - u) * (1.0 - u),
        }
    }
}

/// Where a waypoint takes the pointer.
#[derive(Clone, Copy)]
pub(crate) enum Goal {
    /// Stay: a hand at rest keeps its place on the screen while the camera moves.
    Stay,
    /// To this world point.
    To(Vec2),
    /// By this much (world) from where the pointer was when the move began (a drag).
    By(Vec2),
}

/// A moment of the tour: the pointer reaches `goal` at `at` seconds, moving as `ease` says, and
/// from then on its primary button is `down`.
#[derive(Clone, Copy)]
pub(crate) struct Waypoint {
    at: f32,
    goal: Goal,
    ease: Ease,
    down: bool,
}

impl Waypoint {
    /// The pointer reaches `goal` at `at`, moving as `ease` says; then its button is `down`.
    pub(crate) fn new(at: f32, goal: Goal, ease: Ease, down: bool) -> Self {
        Self {
            at,
            goal,
            ease,
            down,
        }
    }

    /// The pointer stays where it is until `at`; then its button is `down`.
    pub(crate) fn stay(at: f32, down: bool) -> Self {
        Self::new(at, Goal::Stay, Ease::Linear, down)
    }
}

/// The pointer's path, and where it is.
#[derive(Resource)]
struct TourPointer {
    path: Vec<Waypoint>,
    /// Where the pointer was last written (logical window pixels).
    position: Option<Vec2>,
    /// Whether its primary button is down.
    down: bool,
    /// The waypoint it is heading for, and where (world) it was when it set off.
    segment: usize,
    segment_start: Option<Vec2>,
}

/// The dot that shows where the pointer is.
#[derive(Component)]
struct PointerDot;

fn spawn_dot(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<ColorMaterial>>,
) {
    commands.spawn((
        PointerDot,
        Mesh2d(meshes.add(Circle::new(9.0))),
        MeshMaterial2d(materials.add(Color::srgba(1.0, 1.0, 1.0, 0.85))),
        Transform::from_xyz(0.0, 0.0, 50.0),
        Visibility::Hidden,
    ));
}

/// Moves the pointer along its path while the tour runs; once it is over, lets go of a button
/// still down, hides the dot and hands the pointer back to the mouse.
fn drive_pointer(
    tour: Res<Tour>,
    pointer: ResMut<TourPointer>,
    mut mouse: ResMut<PointerInputSettings>,
    window: Single<Entity, With<PrimaryWindow>>,
    camera: Single<(&Camera, &GlobalTransform)>,
    mut input: MessageWriter<PointerInput>,
    dot: Single<(&mut Transform, &mut Visibility), With<PointerDot>>,
) {
    if mouse.is_mouse_enabled {
        return;
    }
    let (mut dot, mut visibility) = dot.into_inner();
    let Some(target) = RenderTarget::Window(WindowRef::Primary).normalize(Some(*window)) else {
        return;
    };
    let Some(elapsed) = tour.time() else {
        mouse.is_mouse_enabled = true;
        *visibility = Visibility::Hidden;
        if let (true, Some(position)) = (pointer.down, pointer.position) {
            let location = Location { target, position };
            let release = PointerAction::Release(PointerButton::Primary);
            input.write(PointerInput::new(PointerId::Mouse, location, release));
        }
        return;
    };
    let (camera, camera_transform) = *camera;
    let pointer = pointer.into_inner();
    let path = &pointer.path;
    // Where the pointer is now, in the world (the camera may have moved under it).
    let here = pointer
        .position
        .and_then(|position| camera.viewport_to_world_2d(camera_transform, position).ok());
    // The waypoint the pointer is heading for, and whether its button is down meanwhile.
    let next = path
        .iter()
        .position(|waypoint| waypoint.at > elapsed)
        .unwrap_or(path.len());
    let down = next > 0 && path[next - 1].down;
    if pointer.segment != next {
        pointer.segment = next;
        pointer.segment_start = here.or(match path.first().map(|first| first.goal) {
            Some(Goal::To(point)) => Some(point),
            _ => None,
        });
    }
    let Some(start) = pointer.segment_start else {
        return;
    };
    // Past the last waypoint, the pointer stays on its point (or where it is).
    let (goal, ease, u) = match path.get(next) {
        Some(waypoint) if next > 0 => {
            let from = path[next - 1].at;
            let u = ((elapsed - from) / (waypoint.at - from)).clamp(0.0, 1.0);
            (waypoint.goal, waypoint.ease, u)
        }
        Some(waypoint) => (waypoint.goal, waypoint.ease, 1.0),
        None => match path.last().map(|last| last.goal) {
            Some(Goal::To(point)) => (Goal::To(point), Ease::Linear, 1.0),
            _ => (Goal::Stay, Ease::Linear, 1.0),
        },
    };
    let world = match goal {
        Goal::Stay => here.unwrap_or(start),
        Goal::To(point) => start.lerp(point, ease.apply(u)),
        Goal::By(offset) => start + offset * ease.apply(u),
    };
    dot.translation = world.extend(dot.translation.z);
    *visibility = Visibility::Visible;
    let position = match (goal, pointer.position) {
        (Goal::Stay, Some(position)) => position,
        _ => match camera.world_to_viewport(camera_transform, world.extend(0.0)) {
            Ok(position) => position,
            Err(_) => return,
        },
    };
    let location = Location { target, position };
    if pointer.position != Some(position) {
        let delta = pointer.position.map_or(Vec2::ZERO, |last| position - last);
        let moved = PointerAction::Move { delta };
        input.write(PointerInput::new(PointerId::Mouse, location.clone(), moved));
        pointer.position = Some(position);
    }
    // After the move: a fling's release comes with its last motion, as a real throw's does.
    if down != pointer.down {
        pointer.down = down;
        let action = if down {
            PointerAction::Press(PointerButton::Primary)
        } else {
            PointerAction::Release(PointerButton::Primary)
        };
        input.write(PointerInput::new(PointerId::Mouse, location, action));
    }
}
