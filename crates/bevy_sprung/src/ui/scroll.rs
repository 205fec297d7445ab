//! Momentum scrolling for `bevy_ui`'s `ScrollPosition`: wheel steps that glide, drags that
//! fling and coast to an exact stop, rubber-band ends, snap points.

use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;
use sprung::{RestThreshold, Spring};

use super::drawn::shift_subtrees;
use crate::rubber_band::rubber_band;
use crate::space::Linear;
use crate::spring::{PropertySpring, SpringSettled, trigger_if_alive};

/// Makes a scroll area (a node with `Overflow::scroll`) scroll with momentum: a fling coasts
/// and slows down exactly as `v·e^(−d·t)` with `d` its [`deceleration`](Self::deceleration),
/// to the rest point `v/d` ahead ([`rest_point`](Self::rest_point)) or to the [snap
/// point](Self::snap) nearest to it; wheel steps glide with [`wheel`](Self::wheel); past either
/// end the content follows a drag less and less (the rubber band of iOS, never as far as
/// [`give`](Self::give)) and springs back with [`edge`](Self::edge), as a fling that reaches an
/// end does. [`ScrollSettled`] is triggered when the area comes to rest.
///
/// It writes the node's `ScrollPosition` (logical pixels); the rubber band is drawn by moving
/// the area's children. Drive it with [`scroll_by`](Self::scroll_by),
/// [`drag_by`](Self::drag_by) and [`fling`](Self::fling), or with the `picking` feature let the
/// pointer do it: the wheel over the area, and drags on it.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::ui::MomentumScroll;
///
/// fn spawn_list(mut commands: Commands) {
///     commands
///         .spawn((
///             Node {
///                 height: px(300.0),
///                 overflow: Overflow::scroll_y(),
///                 flex_direction: FlexDirection::Column,
///                 ..default()
///             },
///             // Comes to rest on a row boundary.
///             MomentumScroll::default().snap_every(Vec2::new(0.0, 48.0)),
///         ))
///         .with_children(|list| {
///             for _ in 0..40 {
///                 list.spawn(Node { height: px(48.0), flex_shrink: 0.0, ..default() });
///             }
///         });
/// }
///
/// // A key flings the list down.
/// fn fling(keys: Res<ButtonInput<KeyCode>>, mut lists: Query<&mut MomentumScroll>) {
///     if keys.just_pressed(KeyCode::PageDown) {
///         for mut list in &mut lists {
///             list.fling(Vec2::new(0.0, 1500.0));
///         }
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default()))
/// #     .init_resource::<ButtonInput<KeyCode>>()
/// #     .add_systems(Startup, spawn_list)
/// #     .add_systems(Update, fling);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[require(
    ScrollPosition,
    ScrollMotion,
    ScrollExtent,
    ScrollOffsetSpring = PropertySpring::new(Spring::smooth(), Vec2::ZERO)
)]
#[cfg_attr(feature = "picking", require(pointer::DragPath))]
#[component(on_add = crate::spring::first_use::<MomentumScroll>)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct MomentumScroll {
    /// How fast a fling slows down: its velocity falls as `e^(−deceleration·t)`, in 1/s. iOS
    /// scroll views: about 2 (normal), 10 (fast).
    pub deceleration: f32,
    /// The spring back from past an end, and onto a snap point.
    pub edge: Spring,
    /// The spring of a wheel step.
    pub wheel: Spring,
    /// How far past an end the content could be pulled, in logical pixels: it is never shown
    /// that far.
    pub give: f32,
    /// Rest only on multiples of this, per axis, in logical pixels (0: anywhere).
    pub snap: Vec2,
    /// Logical pixels per wheel line.
    pub line: f32,
    /// Input since the last step.
    #[reflect(ignore)]
    input: Input,
}

/// Input to a [`MomentumScroll`], applied before its spring steps.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
enum Input {
    #[default]
    None,
    /// Glide by this many logical pixels.
    Wheel(Vec2),
    /// Held by a drag that moved the content by this much.
    Drag(Vec2),
    /// Let go at this velocity (logical pixels per second).
    Fling(Vec2),
}

impl Default for MomentumScroll {
    fn default() -> Self {
        Self {
            deceleration: 2.0,
            edge: Spring::smooth(),
            wheel: Spring::smooth(),
            give: 120.0,
            snap: Vec2::ZERO,
            line: 40.0,
            input: Input::None,
        }
    }
}

impl MomentumScroll {
    /// The same scrolling, resting only on multiples of `step` per axis (0: anywhere).
    #[must_use]
    pub fn snap_every(mut self, step: Vec2) -> Self {
        self.snap = step.max(Vec2::ZERO);
        self
    }

    /// The same scrolling, slowing a fling at `rate` (1/s).
    #[must_use]
    pub fn with_deceleration(mut self, rate: f32) -> Self {
        self.deceleration = rate;
        self
    }

    /// Scrolls by `delta` logical pixels (a wheel step), gliding with [`wheel`](Self::wheel);
    /// steps made while it glides add up. A non-finite `delta` is ignored.
    pub fn scroll_by(&mut self, delta: Vec2) {
        if delta.is_finite() {
            self.input = match self.input {
                Input::Wheel(before) => Input::Wheel(before + delta),
                _ => Input::Wheel(delta),
            };
        }
    }

    /// Holds the content and moves it by `delta` logical pixels of scroll (a drag: dragging
    /// the content up scrolls down, a positive `delta`); past an end it follows less and less.
    pub fn drag_by(&mut self, delta: Vec2) {
        if delta.is_finite() {
            self.input = match self.input {
                Input::Drag(before) => Input::Drag(before + delta),
                _ => Input::Drag(delta),
            };
        }
    }

    /// Lets go at `velocity` (logical pixels of scroll per second): it coasts to the rest point
    /// (or the snap point nearest to it), or springs back inside if it is past an end.
    pub fn fling(&mut self, velocity: Vec2) {
        if velocity.is_finite() {
            self.input = Input::Fling(velocity);
        }
    }

    /// Where a fling at `velocity` from `from` comes to rest, with no end or snap point in the
    /// way: `from + velocity/deceleration`.
    #[must_use]
    pub fn rest_point(&self, from: Vec2, velocity: Vec2) -> Vec2 {
        from + velocity / self.deceleration.max(MIN_DECELERATION)
    }

    /// The snap point nearest to `rest`.
    fn snapped(&self, rest: Vec2) -> Vec2 {
        let snap = |value: f32, step: f32| {
            if step > 0.0 {
                (value / step).round() * step
            } else {
                value
            }
        };
        Vec2::new(snap(rest.x, self.snap.x), snap(rest.y, self.snap.y))
    }

    /// The spring a fling coasts with: no stiffness, damping `deceleration` (mass 1), so the
    /// motion is the exact exponential decay.
    fn coast(&self) -> Spring {
        Spring::new(1.0, 0.0, self.deceleration.max(MIN_DECELERATION))
            .unwrap_or_else(|_| Spring::smooth())
    }
}

/// The slowest deceleration a fling is given (a coast must come to rest).
const MIN_DECELERATION: f32 = 1e-2;

/// A [`MomentumScroll`]'s scroll position, not clamped: past an end by as far as it is pulled.
/// What is shown there is the rubber band of the excess.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Debug, Default, Clone, PartialEq)]
pub struct ScrollMotion {
    /// The scroll position in logical pixels, not clamped.
    pub position: Vec2,
}

/// A scroll area's extent, from its last layout, and how it moves.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct ScrollExtent {
    /// The largest scroll position (logical pixels).
    max: Vec2,
    /// How it moves.
    mode: ScrollMode,
    /// How far past an end the content is shown (logical pixels of scroll).
    shown_past: Vec2,
}

impl ScrollExtent {
    /// The largest scroll position (logical pixels), from the area's last layout.
    pub(crate) fn max(&self) -> Vec2 {
        self.max
    }

    /// How far past an end the content is shown, by the rubber band (logical pixels of
    /// scroll).
    pub(crate) fn shown_past(&self) -> Vec2 {
        self.shown_past
    }
}

/// How a scroll area moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
enum ScrollMode {
    /// Springing to a place inside (a wheel step, a snap point, back from an end), or there.
    #[default]
    Placed,
    /// Coasting after a fling, with no stiffness.
    Coasting,
    /// Held by a drag.
    Held,
}

spring_property!(
    /// A [`MomentumScroll`]'s unclamped position, [`ScrollMotion::position`], in logical
    /// pixels.
    pub ScrollOffset: ScrollMotion::position as Linear<Vec2>,
    rest: RestThreshold { offset: 0.05, speed: 1.0 }
);

/// The spring of a [`MomentumScroll`].
pub type ScrollOffsetSpring = PropertySpring<ScrollOffset>;

/// Triggered on a [`MomentumScroll`] area when it has come to rest.
#[derive(EntityEvent, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ScrollSettled {
    /// The scroll area.
    pub entity: Entity,
}

/// Warns once about a [`MomentumScroll`] on a node that cannot scroll (no `Overflow::scroll*`
/// on either axis, or no `Node`): `bevy_ui` keeps its `ScrollPosition` at zero, so a fling
/// would do nothing.
pub(super) fn warn_unscrollable(
    areas: Query<(Entity, Option<&Node>), Added<MomentumScroll>>,
    mut warned: Local<bool>,
) {
    if *warned {
        return;
    }
    let scrolls = |node: &Node| {
        node.overflow.x == OverflowAxis::Scroll || node.overflow.y == OverflowAxis::Scroll
    };
    if let Some((entity, _)) = areas.iter().find(|(_, node)| !node.is_some_and(scrolls)) {
        *warned = true;
        warn!(
            "bevy_sprung: {entity} has a MomentumScroll but its Node does not scroll \
             (Overflow is not scroll on either axis): bevy_ui keeps it at the top and a fling \
             does nothing; set `overflow: Overflow::scroll_y()` (or scroll_x, scroll) on it"
        );
    }
}

/// Before the scroll springs step: input, and ends. A wheel step glides to a place inside, a
/// drag moves the position (the spring holding still there), a fling coasts with no stiffness
/// or springs to a snap point; a coast that crosses an end, or a place left outside the extent,
/// springs back to the end with the velocity it has.
pub(super) fn steer_scrolls(
    mut areas: Query<(
        &mut MomentumScroll,
        &mut ScrollExtent,
        &mut ScrollOffsetSpring,
        &mut ScrollMotion,
        &ComputedNode,
    )>,
) {
    for (mut scroll, mut extent, mut spring, mut motion, node) in &mut areas {
        let max = ((node.content_size - node.size + node.scrollbar_size).max(Vec2::ZERO)
            * node.inverse_scale_factor)
            .max(Vec2::ZERO);
        extent.set_if_neq(ScrollExtent { max, ..*extent });
        let inside = |position: Vec2| position.clamp(Vec2::ZERO, max);
        let input = core::mem::take(&mut scroll.bypass_change_detection().input);
        let position = motion.position;
        match input {
            Input::None => {}
            Input::Wheel(delta) => {
                let from = if extent.mode == ScrollMode::Placed {
                    spring.target()
                } else {
                    position
                };
                spring.set_spring(scroll.wheel);
                spring.set_target(inside(from + delta));
                extent.mode = ScrollMode::Placed;
            }
            Input::Drag(delta) => {
                // Held: the position is where the finger puts it, the spring at rest there.
                motion.position = position + delta;
                spring.set_target(motion.position);
                spring.set_velocity(Vec2::ZERO);
                extent.mode = ScrollMode::Held;
            }
            Input::Fling(velocity) => {
                spring.set_velocity(velocity);
                let rest = scroll.rest_point(position, velocity);
                if scroll.snap == Vec2::ZERO {
                    spring.set_spring(scroll.coast());
                    spring.set_target(rest);
                    extent.mode = ScrollMode::Coasting;
                } else {
                    spring.set_spring(scroll.edge);
                    spring.set_target(inside(scroll.snapped(inside(rest))));
                    extent.mode = ScrollMode::Placed;
                }
            }
        }
        // A coast that crossed an end, or a place outside the extent (the content shrank, a
        // fling let go past an end): back to the end, keeping the velocity.
        let back_to = match extent.mode {
            ScrollMode::Coasting => Some(motion.position),
            ScrollMode::Placed => Some(spring.target()),
            ScrollMode::Held => None,
        };
        if let Some(place) = back_to
            && inside(place) != place
        {
            spring.set_spring(scroll.edge);
            spring.set_target(inside(place));
            extent.mode = ScrollMode::Placed;
        }
    }
}

/// After the scroll springs stepped: each area shows its position, clamped into its extent
/// (`ScrollPosition`), and how far past an end it is pulled, as a rubber band.
pub(super) fn show_scrolls(
    mut areas: Query<(
        &MomentumScroll,
        &ScrollMotion,
        &mut ScrollExtent,
        &mut ScrollPosition,
    )>,
) {
    for (scroll, motion, mut extent, mut shown) in &mut areas {
        let inside = motion.position.clamp(Vec2::ZERO, extent.max);
        let past = motion.position - inside;
        let band = Vec2::new(
            rubber_band(past.x, scroll.give),
            rubber_band(past.y, scroll.give),
        );
        extent.set_if_neq(ScrollExtent {
            shown_past: band,
            ..*extent
        });
        if shown.0 != inside {
            shown.0 = inside;
        }
    }
}

/// After layout: the children of an area pulled past an end are drawn moved by the rubber
/// band.
pub(super) fn draw_rubber_bands(
    areas: Query<(&ScrollExtent, &ComputedNode, &Children)>,
    descendants: Query<&Children>,
    mut globals: Query<&mut UiGlobalTransform>,
    mut stack: Local<Vec<Entity>>,
) {
    for (extent, node, children) in &areas {
        if extent.shown_past == Vec2::ZERO {
            continue;
        }
        // Scrolling down moves the content up: the content moves against the scroll.
        let by = -extent.shown_past / node.inverse_scale_factor;
        shift_subtrees(&mut globals, &descendants, &mut stack, children.iter(), by);
    }
}

/// The scroll spring settled: the area has come to rest.
pub(super) fn announce_settled(settled: On<SpringSettled<ScrollOffset>>, mut commands: Commands) {
    trigger_if_alive(
        &mut commands,
        ScrollSettled {
            entity: settled.entity,
        },
    );
}

/// The pointer scrolls: the wheel over an area and drags on it (with `picking`).
#[cfg(feature = "picking")]
pub(super) mod pointer {
    use bevy::input::mouse::MouseScrollUnit;
    use bevy::picking::events::{Drag, DragEnd, DragStart, Pointer, Scroll};
    use bevy::prelude::*;

    use super::MomentumScroll;
    use crate::clock::SpringTime;
    use crate::throw::ReleaseVelocity;

    /// The path of the pointer dragging an area, for its release velocity.
    #[derive(Component, Default)]
    pub(in crate::ui) struct DragPath(ReleaseVelocity);

    /// The wheel over an area scrolls it (lines are [`MomentumScroll::line`] pixels).
    pub(in crate::ui) fn wheel(
        mut event: On<Pointer<Scroll>>,
        mut areas: Query<&mut MomentumScroll>,
    ) {
        let Ok(mut scroll) = areas.get_mut(event.entity) else {
            return;
        };
        let unit = match event.unit {
            MouseScrollUnit::Line => scroll.line,
            MouseScrollUnit::Pixel => 1.0,
        };
        let delta = -Vec2::new(event.x, event.y) * unit;
        scroll.scroll_by(delta);
        event.propagate(false);
    }

    /// A drag starts on an area: a new path.
    pub(in crate::ui) fn start(
        mut event: On<Pointer<DragStart>>,
        mut areas: Query<&mut DragPath, With<MomentumScroll>>,
    ) {
        if let Ok(mut path) = areas.get_mut(event.entity) {
            path.0.clear();
            event.propagate(false);
        }
    }

    /// A drag moves the content with the pointer.
    pub(in crate::ui) fn drag(
        mut event: On<Pointer<Drag>>,
        mut areas: Query<(&mut MomentumScroll, &mut DragPath)>,
        time: SpringTime,
    ) {
        let Ok((mut scroll, mut path)) = areas.get_mut(event.entity) else {
            return;
        };
        scroll.drag_by(-event.delta);
        path.0
            .record(time.pointer_now(), (-event.distance).extend(0.0));
        event.propagate(false);
    }

    /// A drag ends: a fling at the pointer's last velocity.
    pub(in crate::ui) fn release(
        mut event: On<Pointer<DragEnd>>,
        mut areas: Query<(&mut MomentumScroll, &DragPath)>,
        time: SpringTime,
    ) {
        let Ok((mut scroll, path)) = areas.get_mut(event.entity) else {
            return;
        };
        scroll.fling(path.0.velocity(time.pointer_now()).truncate());
        event.propagate(false);
    }
}
