//! Drag and fling: follow the pointer, then spring to a snap point with the throw's velocity.

use bevy::ecs::system::SystemParam;
use bevy::log::warn_once;
use bevy::math::primitives::InfinitePlane3d;
use bevy::picking::events::{Drag, DragEnd, DragStart, Pointer};
use bevy::picking::pointer::{Location, PointerButton, PointerId};
use bevy::prelude::*;
use sprung::Spring;

use super::state::{InteractionState, PointerContacts, start_dragging};
use crate::clock::SpringTime;
use crate::inertia::Inertia;
use crate::spring::trigger_if_alive;
use crate::throw::{DragBounds, ReleaseVelocity, Snap};
use crate::transform::TranslationSpring;
#[cfg(feature = "ui")]
use crate::ui::UiTransformTranslationSpring;

/// How a dragged entity follows the pointer.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
#[reflect(Debug, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum DragFollow {
    /// Glued to the pointer (at the point where it was grabbed).
    Exact,
    /// Through this spring, retargeted to the pointer: a card that trails a little behind a
    /// fast pointer ([`Spring::stiff`] is a tight choice).
    Spring(Spring<f32>),
}

/// Makes its entity draggable with the primary button, and flings it on release: it follows
/// the pointer while dragged ([`DragFollow`]), and when let go keeps the pointer's velocity
/// (estimated over the last 100 ms, [`ReleaseVelocity`]) and springs to the [`Snap`] target
/// nearest to where the throw would come to rest, or home. [`DragBounds`] keep it in a box
/// with rubber-band edges. [`DragReleased`] is triggered on release. A world-space entity with
/// an [`Inertia`] is thrown instead: it coasts with the release velocity and stops where its
/// `Inertia` says (its bounds and snap points, not the drag's).
///
/// It moves the entity's spring, which it needs beside it:
/// - a [`TranslationSpring`] (world space: sprites, meshes; positions are the `Transform`'s,
///   in its parent's space). The pointer is projected through the camera that picked the
///   entity onto the plane through the entity facing that camera;
/// - or, with the `ui` feature, a [`UiTransformTranslationSpring`](crate::ui::UiTransformTranslationSpring)
///   (UI nodes; positions are `UiTransform::translation` in logical pixels, `z` unused).
///
/// A world drag moves the entity in the plane through it facing the camera, and the release
/// target keeps its depth along the camera's axis (a 2D card keeps its z, its draw order,
/// whatever the snap point's; snap distances are still measured in 3D). To raise a card while
/// it is dragged, change its z before the drag starts (on `Pointer<Press>`): the grab keeps it.
/// A drag starts on the first move with the button down (`bevy_picking` has no dead zone).
///
/// The spring's own parameters are the release motion's (or [`release_spring`]'s); the state
/// becomes [`InteractionState::Dragged`] while dragged, so [`InteractionTargets`] can lift
/// and tint it. A drag ends on release even if the spring or the value it moves was removed
/// meanwhile (nothing is flung then, and the next drag grabs the entity afresh).
///
/// [`release_spring`]: Self::release_spring
/// [`InteractionTargets`]: super::InteractionTargets
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::interaction::{Snap, SpringDrag};
/// use bevy_sprung::prelude::*;
///
/// fn spawn_card(mut commands: Commands) {
///     let slots = vec![Vec3::new(-200.0, 0.0, 0.0), Vec3::new(200.0, 0.0, 0.0)];
///     commands.spawn((
///         Sprite::from_color(Color::WHITE, Vec2::new(80.0, 120.0)),
///         Transform::default(),
///         TranslationSpring::new(Spring::bouncy(), Vec3::ZERO),
///         SpringDrag::new().snapping(Snap::Points(slots)).within(150.0),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn_card);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone)]
#[reflect(Component, Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[require(InteractionState)]
pub struct SpringDrag {
    /// How it follows the pointer.
    pub follow: DragFollow,
    /// Where a release springs it to.
    pub snap: Snap,
    /// Snap only to a target within this distance of the throw's resting place; farther, go
    /// home. `None`: any distance.
    pub snap_radius: Option<f32>,
    /// The box it stays in.
    pub bounds: Option<DragBounds>,
    /// The throw: seconds of the release velocity added to the release position to find where
    /// the throw would rest (0.3 s by default; 0 snaps from where it was let go).
    pub throw: f32,
    /// Home: where a release with nothing to snap to goes. `None`: the spring's target when the
    /// drag began (where it rested or was heading).
    pub home: Option<Vec3>,
    /// The spring for the release motion. `None`: the spring's own parameters.
    pub release_spring: Option<Spring<f32>>,
    /// How far (logical pixels) the pointer must travel with the button down before the drag
    /// takes the entity: below it a press stays a click (no drag state, no fling, the spring
    /// untouched). 0 by default (`bevy_picking`'s own rule: any motion drags); 4–8 px suits
    /// shaky hands and touch. Once taken, the entity is held where it then is, so it never jumps.
    pub threshold: f32,
    #[reflect(ignore)]
    #[cfg_attr(feature = "serde", serde(skip))]
    state: DragState,
}

/// A drag in progress.
#[derive(Debug, Clone, Default)]
struct DragState {
    active: Option<ActiveDrag>,
    path: ReleaseVelocity,
}

#[derive(Debug, Clone, Copy)]
struct ActiveDrag {
    pointer: PointerId,
    space: DragSpace,
    /// The entity's position minus the pointer's, in the drag space.
    grab: Vec3,
    /// Where a release with nothing to snap to goes.
    home: Vec3,
    /// The spring's parameters before the drag, for the release.
    spring: Spring<f32>,
    /// Whether the pointer has gone past the threshold (the drag holds the entity).
    engaged: bool,
}

/// The space a drag moves its entity in.
#[derive(Debug, Clone, Copy)]
enum DragSpace {
    /// The `Transform`'s translation; the pointer is projected through `camera` onto the plane
    /// through `origin` (world) with normal `normal`.
    World {
        camera: Entity,
        origin: Vec3,
        normal: Vec3,
    },
    /// `UiTransform::translation`, in logical pixels.
    #[cfg(feature = "ui")]
    Ui,
}

impl Default for SpringDrag {
    fn default() -> Self {
        Self::new()
    }
}

impl SpringDrag {
    /// Glued to the pointer, springing home on release (add a [`Snap`] with
    /// [`snapping`](Self::snapping)), with a 0.3 s throw.
    #[must_use]
    pub fn new() -> Self {
        Self {
            follow: DragFollow::Exact,
            snap: Snap::Home,
            snap_radius: None,
            bounds: None,
            throw: 0.3,
            home: None,
            release_spring: None,
            threshold: 0.0,
            state: DragState::default(),
        }
    }

    /// The same, following the pointer as `follow` says.
    #[must_use]
    pub fn following(mut self, follow: DragFollow) -> Self {
        self.follow = follow;
        self
    }

    /// The same, snapping as `snap` says.
    #[must_use]
    pub fn snapping(mut self, snap: Snap) -> Self {
        self.snap = snap;
        self
    }

    /// The same, snapping only within `radius` of the throw's resting place (home otherwise).
    #[must_use]
    pub fn within(mut self, radius: f32) -> Self {
        self.snap_radius = Some(radius);
        self
    }

    /// The same, kept in `bounds`.
    #[must_use]
    pub fn bounded(mut self, bounds: DragBounds) -> Self {
        self.bounds = Some(bounds);
        self
    }

    /// The same, with a throw of `seconds`.
    #[must_use]
    pub fn with_throw(mut self, seconds: f32) -> Self {
        self.throw = seconds;
        self
    }

    /// The same, with a fixed home.
    #[must_use]
    pub fn with_home(mut self, home: Vec3) -> Self {
        self.home = Some(home);
        self
    }

    /// The same, releasing with `spring`.
    #[must_use]
    pub fn releasing_with(mut self, spring: Spring<f32>) -> Self {
        self.release_spring = Some(spring);
        self
    }

    /// The same, taking the entity only after the pointer travelled `pixels` (see
    /// [`threshold`](Self::threshold)).
    #[must_use]
    pub fn with_threshold(mut self, pixels: f32) -> Self {
        self.threshold = pixels;
        self
    }

    /// Whether a pointer is dragging it (past the threshold).
    #[must_use]
    pub fn is_dragged(&self) -> bool {
        self.state.active.is_some_and(|active| active.engaged)
    }

    /// Whether a pointer that travelled `distance` (logical pixels) drags it.
    pub(super) fn engages(&self, distance: Vec2) -> bool {
        if self.threshold > 0.0 {
            distance.length() >= self.threshold
        } else {
            true
        }
    }

    /// Where the release target is for a release at `position` with `velocity`: the throw's
    /// resting place (in the bounds), the snap target chosen from it, and the snap's index.
    #[must_use]
    pub fn release_target(
        &self,
        position: Vec3,
        velocity: Vec3,
        home: Vec3,
    ) -> (Vec3, Vec3, Option<usize>) {
        let throw = if self.throw.is_finite() {
            self.throw.max(0.0)
        } else {
            0.0
        };
        let mut projected = position + velocity * throw;
        if let Some(bounds) = self.bounds {
            projected = bounds.clamp(projected);
        }
        let (target, snapped) = self.snap.choose(projected, home);
        match self.snap_radius {
            Some(radius) if target.distance(projected) > radius => (projected, home, None),
            _ => (projected, target, snapped),
        }
    }
}

/// Triggered on an entity with a [`SpringDrag`] when it is let go: with the release velocity,
/// where the throw would have come to rest, the target it springs to, and the index of the
/// snap point or line it chose (`None`: home, free or a grid).
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq)]
pub struct DragReleased {
    /// The entity released.
    pub entity: Entity,
    /// The pointer's velocity at release, in the drag space's units per second.
    pub velocity: Vec3,
    /// Where the throw would have come to rest (in the bounds).
    pub projected: Vec3,
    /// Where the spring now takes it.
    pub target: Vec3,
    /// The snap point or line chosen.
    pub snapped: Option<usize>,
}

/// What the drag observers need besides the dragged entity.
#[derive(SystemParam)]
struct DragContext<'w, 's> {
    time: SpringTime<'w>,
    cameras: Query<'w, 's, (&'static Camera, &'static GlobalTransform)>,
    globals: Query<'w, 's, &'static GlobalTransform>,
    #[cfg(feature = "ui")]
    ui_scale: Option<Res<'w, UiScale>>,
}

impl DragContext<'_, '_> {
    fn now(&self) -> f64 {
        self.time.pointer_now()
    }

    /// The pointer at `location` in `space` (for world space, in the space of `parent`).
    fn pointer(
        &self,
        space: DragSpace,
        location: &Location,
        parent: Option<Entity>,
    ) -> Option<Vec3> {
        match space {
            DragSpace::World {
                camera,
                origin,
                normal,
            } => {
                let (camera, camera_transform) = self.cameras.get(camera).ok()?;
                let ray = camera
                    .viewport_to_world(camera_transform, location.position)
                    .ok()?;
                let plane = InfinitePlane3d::new(normal);
                let distance = ray.intersect_plane(origin, plane)?;
                let world = ray.get_point(distance);
                Some(
                    match parent.and_then(|parent| self.globals.get(parent).ok()) {
                        Some(parent) => parent.affine().inverse().transform_point3(world),
                        None => world,
                    },
                )
            }
            #[cfg(feature = "ui")]
            DragSpace::Ui => {
                let scale = self.ui_scale.as_ref().map_or(1.0, |scale| scale.0);
                (scale > 0.0).then(|| (location.position / scale).extend(0.0))
            }
        }
    }
}

/// The dragged entity: its drag, and the spring and value it moves.
#[cfg(feature = "ui")]
type Body = (
    &'static mut SpringDrag,
    Option<&'static mut TranslationSpring>,
    Option<&'static mut Transform>,
    Option<&'static mut UiTransformTranslationSpring>,
    Option<&'static mut UiTransform>,
    Option<&'static ChildOf>,
    Option<&'static GlobalTransform>,
);
#[cfg(not(feature = "ui"))]
type Body = (
    &'static mut SpringDrag,
    Option<&'static mut TranslationSpring>,
    Option<&'static mut Transform>,
    Option<&'static ChildOf>,
    Option<&'static GlobalTransform>,
);

/// A UI translation in pixels (another unit counts as 0: drags move pixels).
#[cfg(feature = "ui")]
pub(crate) fn pixels(value: Val2) -> Vec3 {
    let px = |v: Val| if let Val::Px(x) = v { x } else { 0.0 };
    Vec3::new(px(value.x), px(value.y), 0.0)
}

/// One body's spring and value, whichever space it lives in.
enum Moved<'a> {
    World(Mut<'a, TranslationSpring>, Mut<'a, Transform>),
    #[cfg(feature = "ui")]
    Ui(Mut<'a, UiTransformTranslationSpring>, Mut<'a, UiTransform>),
}

impl Moved<'_> {
    fn position(&self) -> Vec3 {
        match self {
            Self::World(_, transform) => transform.translation,
            #[cfg(feature = "ui")]
            Self::Ui(_, transform) => pixels(transform.translation),
        }
    }

    fn target(&self) -> Vec3 {
        match self {
            Self::World(spring, _) => spring.target(),
            #[cfg(feature = "ui")]
            Self::Ui(spring, _) => pixels(spring.target()),
        }
    }

    fn spring(&self) -> Spring<f32> {
        match self {
            Self::World(spring, _) => *spring.spring(),
            #[cfg(feature = "ui")]
            Self::Ui(spring, _) => *spring.spring(),
        }
    }

    fn set_spring(&mut self, parameters: Spring<f32>) {
        match self {
            Self::World(spring, _) => spring.set_spring(parameters),
            #[cfg(feature = "ui")]
            Self::Ui(spring, _) => spring.set_spring(parameters),
        }
    }

    /// Retargets with `velocity` (`None`: keep it).
    fn retarget(&mut self, target: Vec3, velocity: Option<Vec3>) {
        match self {
            Self::World(spring, _) => {
                spring.set_target(target);
                if let Some(velocity) = velocity {
                    spring.set_velocity(velocity);
                }
            }
            #[cfg(feature = "ui")]
            Self::Ui(spring, _) => {
                spring.set_target(Val2::px(target.x, target.y));
                if let Some(velocity) = velocity {
                    spring.set_velocity(velocity.truncate());
                }
            }
        }
    }

    /// Puts the value at `position` and the spring's target with it, without waking the
    /// spring (asleep, it does not pull against the pointer).
    fn glue(&mut self, position: Vec3) {
        match self {
            Self::World(spring, transform) => {
                transform.translation = position;
                spring.bypass_change_detection().set_target(position);
            }
            #[cfg(feature = "ui")]
            Self::Ui(spring, transform) => {
                let value = Val2::px(position.x, position.y);
                transform.translation = value;
                spring.bypass_change_detection().set_target(value);
            }
        }
    }
}

/// The drag, what it moves, and the entity's parent and place.
fn body<'a>(
    item: bevy::ecs::query::QueryItem<'a, '_, Body>,
) -> (
    Mut<'a, SpringDrag>,
    Option<Moved<'a>>,
    Option<Entity>,
    Option<Vec3>,
) {
    #[cfg(feature = "ui")]
    let (drag, spring, transform, ui_spring, ui_transform, parent, global) = item;
    #[cfg(not(feature = "ui"))]
    let (drag, spring, transform, parent, global) = item;
    let moved = match (spring, transform) {
        (Some(spring), Some(transform)) => Some(Moved::World(spring, transform)),
        #[cfg(feature = "ui")]
        _ => match (ui_spring, ui_transform) {
            (Some(spring), Some(transform)) => Some(Moved::Ui(spring, transform)),
            _ => None,
        },
        #[cfg(not(feature = "ui"))]
        _ => None,
    };
    (
        drag,
        moved,
        parent.map(ChildOf::parent),
        global.map(GlobalTransform::translation),
    )
}

fn start_drag(event: On<Pointer<DragStart>>, context: DragContext, mut bodies: Query<Body>) {
    if event.button != PointerButton::Primary {
        return;
    }
    let Ok(item) = bodies.get_mut(event.entity) else {
        return;
    };
    let (mut drag, moved, parent, world_position) = body(item);
    let Some(mut moved) = moved else {
        warn_once!(
            "bevy_sprung: a SpringDrag needs a TranslationSpring (or a UiTransformTranslationSpring) \
             beside it"
        );
        return;
    };
    // A second pointer does not take an entity another one drags; the same pointer starting
    // again ends a drag whose end it never heard (its entity was not pickable then) and starts
    // afresh.
    if drag
        .state
        .active
        .is_some_and(|active| active.pointer != event.pointer_id)
    {
        return;
    }
    let space = match moved {
        Moved::World(..) => {
            let Ok((_, camera)) = context.cameras.get(event.hit.camera) else {
                return;
            };
            DragSpace::World {
                camera: event.hit.camera,
                origin: world_position.unwrap_or(moved.position()),
                normal: camera.back().as_vec3(),
            }
        }
        #[cfg(feature = "ui")]
        Moved::Ui(..) => DragSpace::Ui,
    };
    let Some(pointer) = context.pointer(space, &event.pointer_location, parent) else {
        warn_once!("bevy_sprung: could not place the pointer for a drag (camera not ready?)");
        return;
    };
    let position = moved.position();
    let home = drag.home.unwrap_or_else(|| moved.target());
    let spring = moved.spring();
    let drag = drag.as_mut();
    let mut active = ActiveDrag {
        pointer: event.pointer_id,
        space,
        grab: position - pointer,
        home,
        spring,
        engaged: false,
    };
    drag.state.path.clear();
    if drag.engages(Vec2::ZERO) {
        engage(drag, &mut active, &mut moved, position, context.now());
    }
    drag.state.active = Some(active);
}

/// The drag takes the entity where it is: the pointer's path starts there, and the spring stops
/// (exact follow: it settles and sleeps while the pointer moves the value) or becomes the
/// follow spring.
fn engage(
    drag: &mut SpringDrag,
    active: &mut ActiveDrag,
    moved: &mut Moved,
    position: Vec3,
    now: f64,
) {
    active.engaged = true;
    drag.state.path.record(now, position);
    match drag.follow {
        DragFollow::Exact => moved.retarget(position, Some(Vec3::ZERO)),
        DragFollow::Spring(follow) => moved.set_spring(follow),
    }
}

/// Where the pointer at `location` puts the dragged entity (rubber-banded at the bounds).
fn dragged_position(
    drag: &SpringDrag,
    active: ActiveDrag,
    context: &DragContext,
    location: &Location,
    parent: Option<Entity>,
) -> Option<Vec3> {
    let position = context.pointer(active.space, location, parent)? + active.grab;
    Some(match drag.bounds {
        Some(bounds) => bounds.rubber_band(position),
        None => position,
    })
}

fn continue_drag(event: On<Pointer<Drag>>, context: DragContext, mut bodies: Query<Body>) {
    let Ok(item) = bodies.get_mut(event.entity) else {
        return;
    };
    let (mut drag, moved, parent, _) = body(item);
    let (Some(mut moved), Some(mut active)) = (moved, drag.state.active) else {
        return;
    };
    if active.pointer != event.pointer_id {
        return;
    }
    if !active.engaged {
        if !drag.engages(event.distance) {
            return;
        }
        // Taken where it is now: the grab is measured again, so nothing jumps.
        let Some(pointer) = context.pointer(active.space, &event.pointer_location, parent) else {
            return;
        };
        let position = moved.position();
        active.grab = position - pointer;
        engage(
            drag.as_mut(),
            &mut active,
            &mut moved,
            position,
            context.now(),
        );
        drag.state.active = Some(active);
    }
    let Some(position) = dragged_position(&drag, active, &context, &event.pointer_location, parent)
    else {
        return;
    };
    drag.state.path.record(context.now(), position);
    match drag.follow {
        DragFollow::Exact => moved.glue(position),
        DragFollow::Spring(_) => moved.retarget(position, None),
    }
}

fn end_drag(
    event: On<Pointer<DragEnd>>,
    context: DragContext,
    mut commands: Commands,
    mut bodies: Query<Body>,
    mut inertias: Query<&mut Inertia>,
) {
    let Ok(item) = bodies.get_mut(event.entity) else {
        return;
    };
    let (mut drag, moved, parent, _) = body(item);
    let Some(active) = drag.state.active else {
        return;
    };
    if active.pointer != event.pointer_id {
        return;
    }
    // The drag ends whatever happened to the entity meanwhile.
    drag.state.active = None;
    // A click (nothing was taken), or the spring or its value removed mid-drag: nothing to
    // fling.
    let (Some(mut moved), true) = (moved, active.engaged) else {
        drag.state.path.clear();
        return;
    };
    let now = context.now();
    if let Some(position) =
        dragged_position(&drag, active, &context, &event.pointer_location, parent)
    {
        drag.state.path.record(now, position);
    }
    let velocity = drag.state.path.velocity(now);
    let position = moved.position();
    let (projected, target, snapped) = if let (Ok(mut inertia), Moved::World(spring, _)) =
        (inertias.get_mut(event.entity), &mut moved)
    {
        // An entity with inertia is thrown: it coasts (or snaps) as its `Inertia` says.
        let throw = inertia.start(position, velocity, spring);
        (
            inertia.rest_position(position, velocity),
            throw.target,
            None,
        )
    } else {
        let (projected, mut target, snapped) = drag.release_target(position, velocity, active.home);
        // A world drag moves in the plane facing the camera: the entity keeps its depth (in
        // 2D, its z, the draw order) whatever the snap point's.
        #[cfg_attr(
            not(feature = "ui"),
            expect(
                irrefutable_let_patterns,
                reason = "without `ui` every drag is a world drag"
            )
        )]
        if let DragSpace::World { normal, .. } = active.space {
            target -= normal * (target - position).dot(normal);
        }
        moved.set_spring(drag.release_spring.unwrap_or(active.spring));
        moved.retarget(target, Some(velocity));
        (projected, target, snapped)
    };
    drag.state.path.clear();
    trigger_if_alive(
        &mut commands,
        DragReleased {
            entity: event.entity,
            velocity,
            projected,
            target,
            snapped,
        },
    );
}

/// A primary-button drag starts: the entity is dragged at once, unless its [`SpringDrag`] has
/// a threshold to pass first.
fn on_drag_start(
    event: On<Pointer<DragStart>>,
    mut contacts: Query<&mut PointerContacts>,
    drags: Query<&SpringDrag>,
) {
    // An entity with a drag threshold is dragged once the pointer passes it (`on_drag`).
    let engaged = drags
        .get(event.entity)
        .map_or(true, |drag| drag.engages(Vec2::ZERO));
    if event.button == PointerButton::Primary && engaged {
        start_dragging(&mut contacts, event.entity, event.pointer_id);
    }
}

/// A drag moves: an entity whose [`SpringDrag`] has a threshold is dragged once past it.
fn on_drag(
    event: On<Pointer<Drag>>,
    mut contacts: Query<&mut PointerContacts>,
    drags: Query<&SpringDrag>,
) {
    if event.button == PointerButton::Primary
        && let Ok(drag) = drags.get(event.entity)
        && drag.engages(event.distance)
    {
        start_dragging(&mut contacts, event.entity, event.pointer_id);
    }
}

pub(super) fn build(app: &mut App) {
    app.register_type::<SpringDrag>()
        .register_type::<DragFollow>()
        .add_observer(on_drag_start)
        .add_observer(on_drag)
        .add_observer(start_drag)
        .add_observer(continue_drag)
        .add_observer(end_drag);
}
