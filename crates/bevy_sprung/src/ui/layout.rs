//! Layout transitions (FLIP): a node springs from where it was drawn to where `bevy_ui`'s
//! layout puts it now.
//!
//! First, Last, Invert, Play: after layout has placed a node, compare its box with the one
//! layout gave it last frame; add the difference to a visual offset ([`LayoutOffset`]) so that
//! the node is drawn where it was, then spring the offset to nothing. Layout itself is never
//! fought: `Node`, `Children` and `UiTransform` stay as the app wrote them, and only the drawn
//! transforms ([`UiGlobalTransform`]) carry the offset.

use alloc::vec::Vec;

use bevy::prelude::*;
use bevy::ui::{ComputedUiRenderTargetInfo, IgnoreScroll, UiGlobalTransform};
use sprung::{RestThreshold, Spring};

use super::drawn::shift_subtrees;
use crate::presence::Presence;
use crate::space::Linear;
use crate::spring::PropertySpring;

/// Makes a UI node spring to its new place when layout moves or resizes it: a reorder of its
/// parent's `Children`, a sibling inserted or removed, a change of its `Node` or its content, a
/// window resize. The node is drawn where it was and springs to where layout puts it — its
/// position, and with [`size`](Self::size) its size — keeping its velocity when layout moves it
/// again mid-flight.
///
/// Its place is its box in its parent, as layout computes it (its own `UiTransform` and the
/// parent's scrolling are not part of it): a node carried along by its parent moves with it. Put
/// a `LayoutSpring` on the parent too to spring the parent's moves. The offset is drawn, not
/// laid out: the node's `Node`, its `UiTransform` (springs on it add on top) and what picking
/// and focus see next frame are where layout put it, and its descendants move with it. A size
/// change is drawn as a scale of the node's own box (background, border, its own text) about
/// its centre, while its children keep their size and their place from the drawn box's top-left
/// corner, where layout places them from. With [`position_only`](Self::position_only) the
/// top-left corner is what stays where it was (the new size is shown at once). Either way a
/// child whose place in its parent did not change does not move, however layout springs nest:
/// a column with a `LayoutSpring` whose row goes keeps its other rows where they were drawn.
///
/// A node hidden with `Display::None` (laid out with no size) is not sprung: shown again, it
/// appears at its place at once (give it a [`Presence`](crate::presence::Presence) to make it
/// enter). Once the node has arrived its springs sleep, and a node whose layout does not change
/// costs a change-detection test per frame.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// #[derive(Component)]
/// struct List;
///
/// fn spawn_list(mut commands: Commands) {
///     commands
///         .spawn((List, Node { flex_direction: FlexDirection::Column, ..default() }))
///         .with_children(|list| {
///             for _ in 0..5 {
///                 list.spawn((
///                     Node { height: px(40.0), ..default() },
///                     LayoutSpring::new(Spring::snappy()),
///                 ));
///             }
///         });
/// }
///
/// // The last item moves to the top, and every item springs to its new place.
/// fn last_to_top(lists: Query<(Entity, &Children), With<List>>, mut commands: Commands) {
///     for (list, items) in &lists {
///         if let Some(&last) = items.last() {
///             commands.entity(list).insert_child(0, last);
///         }
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default()))
/// #     .add_systems(Startup, spawn_list)
/// #     .add_systems(Update, last_to_top);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq)]
#[component(on_add = crate::spring::first_use::<LayoutSpring>)]
#[require(
    Node,
    LayoutOffset,
    LaidOut,
    LayoutTranslationSpring = PropertySpring::new(Spring::snappy(), Vec2::ZERO),
    LayoutScaleSpring = PropertySpring::new(Spring::snappy(), Vec2::ZERO)
)]
#[reflect(Component, Debug, Clone, PartialEq)]
pub struct LayoutSpring {
    /// The spring of the move (and of the size).
    pub spring: Spring,
    /// Spring size changes too (drawn as a scale), not only moves.
    pub size: bool,
}

impl LayoutSpring {
    /// Springs moves and size changes with `spring`.
    #[must_use]
    pub fn new(spring: Spring) -> Self {
        Self { spring, size: true }
    }

    /// Springs moves only: a size change is drawn at once.
    #[must_use]
    pub fn position_only(spring: Spring) -> Self {
        Self {
            spring,
            size: false,
        }
    }
}

impl Default for LayoutSpring {
    fn default() -> Self {
        Self::new(Spring::snappy())
    }
}

/// How far a [`LayoutSpring`] node is drawn from where layout puts it: the offset of its centre
/// in its parent's frame, in physical pixels, and its drawn size as a factor `exp(log_scale)` of
/// its laid-out size (logarithms, so that a bounce never draws it at a negative size). Its
/// springs carry both to zero; the plugin writes it, and draws it after layout.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Debug, Default, Clone, PartialEq)]
pub struct LayoutOffset {
    /// The centre's offset, in the parent's frame, in physical pixels.
    pub translation: Vec2,
    /// The natural logarithm of the drawn size over the laid-out size, per axis.
    pub log_scale: Vec2,
}

impl LayoutOffset {
    /// No offset: drawn where layout puts it.
    pub const ZERO: Self = Self {
        translation: Vec2::ZERO,
        log_scale: Vec2::ZERO,
    };

    /// The drawn size over the laid-out size, per axis.
    #[inline]
    #[must_use]
    pub fn scale(&self) -> Vec2 {
        Vec2::new(self.log_scale.x.exp(), self.log_scale.y.exp())
    }
}

spring_property!(
    /// A [`LayoutSpring`] node's drawn move, [`LayoutOffset::translation`], in physical pixels.
    pub LayoutTranslation: LayoutOffset::translation as Linear<Vec2>,
    rest: RestThreshold { offset: 0.05, speed: 0.5 }
);

spring_property!(
    /// A [`LayoutSpring`] node's drawn size change, [`LayoutOffset::log_scale`].
    pub LayoutScale: LayoutOffset::log_scale as Linear<Vec2>,
    rest: RestThreshold { offset: 1e-4, speed: 1e-3 }
);

/// A spring on [`LayoutTranslation`], toward no offset.
pub type LayoutTranslationSpring = PropertySpring<LayoutTranslation>;
/// A spring on [`LayoutScale`], toward no offset.
pub type LayoutScaleSpring = PropertySpring<LayoutScale>;

/// Where layout put a [`LayoutSpring`] node last: its box in its parent.
#[derive(Component, Reflect, Debug, Clone, Copy, PartialEq, Default)]
#[reflect(Component, Default)]
pub(crate) struct LaidOut(Option<LayoutBox>);

/// A node's box as layout computes it, in physical pixels: its centre and its top-left corner
/// relative to its parent's top-left corner (scrolling and its own `UiTransform` translation
/// taken out), and its size.
#[derive(Reflect, Debug, Clone, Copy, PartialEq)]
struct LayoutBox {
    centre: Vec2,
    /// The corner its children are laid out from, in the parent's frame (the node's own
    /// rotation and scale applied).
    corner: Vec2,
    size: Vec2,
    parent: Option<Entity>,
}

/// Layout moves below this (rounding in the transforms it is read back from) are not sprung.
const SMALLEST_MOVE: f32 = 1e-3;

impl LayoutBox {
    /// Whether layout gave the node no size at all (`Display::None`, or collapsed to nothing).
    fn is_hidden(&self) -> bool {
        self.size == Vec2::ZERO
    }

    /// The offset that draws a node laid out at `self` where it was drawn at `before` with
    /// `offset`: with `size`, the same centre and size; without, the same top-left corner (the
    /// new size shown at once), so that what is laid out inside it stays where it was.
    fn offset_from(&self, before: &Self, offset: LayoutOffset, size: bool) -> LayoutOffset {
        let moved = if size {
            before.centre - self.centre
        } else {
            before.corner - self.corner
        };
        let translation = if moved.abs().max_element() > SMALLEST_MOVE {
            offset.translation + moved
        } else {
            offset.translation
        };
        let mut log_scale = offset.log_scale;
        if size {
            // Ratios of sizes, as logarithms: exact to rounding at any scale. An axis of no size
            // (a collapsed node) has no ratio, and is drawn at once.
            let grown = (before.size / self.size).to_array();
            for (axis, ratio) in grown.into_iter().enumerate() {
                let log = ratio.ln();
                if log.is_finite() {
                    log_scale[axis] += log;
                }
            }
        }
        LayoutOffset {
            translation,
            log_scale,
        }
    }
}

/// A node's layout box, read back from what layout computed: its drawn transform without its
/// own `UiTransform` translation, in its parent's frame, with the parent's scrolling undone.
struct LaidOutNode<'a> {
    node: &'a ComputedNode,
    global: &'a UiGlobalTransform,
    transform: &'a UiTransform,
    target: &'a ComputedUiRenderTargetInfo,
    ignore_scroll: Option<&'a IgnoreScroll>,
}

impl LaidOutNode<'_> {
    fn layout_box(&self, parent: Option<(Entity, &ComputedNode, &UiGlobalTransform)>) -> LayoutBox {
        let own = self.transform.translation.resolve(
            self.target.scale_factor(),
            self.node.size,
            self.target.physical_size().as_vec2(),
        );
        let (centre, axes, parent) = match parent {
            Some((entity, parent, parent_global)) => {
                // Layout placed the centre at `location − scroll + (size − parent size) / 2` in
                // the parent's frame, plus the node's own translation.
                let local = parent_global.inverse() * **self.global;
                let kept = self.ignore_scroll.map_or(Vec2::ONE, |ignore| {
                    Vec2::select(ignore.0, Vec2::ZERO, Vec2::ONE)
                });
                let scroll = parent.scroll_position * kept;
                (
                    local.translation - own + scroll + 0.5 * parent.size,
                    local.matrix2,
                    Some(entity),
                )
            }
            None => (self.global.translation - own, self.global.matrix2, None),
        };
        LayoutBox {
            centre,
            corner: centre - axes * (0.5 * self.node.size),
            size: self.node.size,
            parent,
        }
    }
}

/// What a node's layout box is read from: its own computed layout and drawn transform, and its
/// parent.
type LayoutParts<'a> = (
    &'a ComputedNode,
    &'a UiGlobalTransform,
    &'a UiTransform,
    &'a ComputedUiRenderTargetInfo,
    Option<&'a IgnoreScroll>,
    Option<&'a ChildOf>,
);

/// The layout box of the node of `parts`, and its parent's computed layout (if it has one).
fn layout_box_of<'p>(
    (node, global, transform, target, ignore_scroll, child_of): LayoutParts,
    parents: &'p Query<(&ComputedNode, &UiGlobalTransform)>,
) -> (LayoutBox, Option<&'p ComputedNode>) {
    let parent = child_of.and_then(|child_of| {
        let parent = child_of.parent();
        parents
            .get(parent)
            .ok()
            .map(|(node, global)| (parent, node, global))
    });
    let laid_out = LaidOutNode {
        node,
        global,
        transform,
        target,
        ignore_scroll,
    }
    .layout_box(parent);
    (laid_out, parent.map(|(_, node, _)| node))
}

/// After layout: each [`LayoutSpring`] node whose layout box changed is given the offset that
/// draws it where it was; its springs carry it from there (keeping their velocities).
pub(super) fn note_reflows(
    mut nodes: Query<
        (
            Ref<LayoutSpring>,
            &mut LaidOut,
            &mut LayoutOffset,
            &mut LayoutTranslationSpring,
            &mut LayoutScaleSpring,
            LayoutParts<'static>,
        ),
        Or<(
            Changed<UiGlobalTransform>,
            Changed<ComputedNode>,
            Changed<LayoutSpring>,
        )>,
    >,
    parents: Query<(&ComputedNode, &UiGlobalTransform)>,
) {
    for (config, mut laid_out, mut offset, mut translation, mut scale, node) in &mut nodes {
        if config.is_changed() {
            translation.set_spring(config.spring);
            scale.set_spring(config.spring);
        }
        let (now, _) = layout_box_of(node, &parents);
        let before = laid_out.0.replace(now);
        if now.is_hidden() {
            // Hidden (`Display::None` lays a node out with no size): nothing is drawn, and
            // nothing of its motion is kept for when it shows again.
            if *offset != LayoutOffset::ZERO {
                *offset = LayoutOffset::ZERO;
                translation.set_velocity(Vec2::ZERO);
                scale.set_velocity(Vec2::ZERO);
            }
            continue;
        }
        // First laid out, shown again, or moved to another parent: drawn where layout puts it.
        let Some(before) =
            before.filter(|before| before.parent == now.parent && !before.is_hidden())
        else {
            continue;
        };
        if before == now {
            continue;
        }
        let moved = now.offset_from(&before, *offset, config.size);
        offset.set_if_neq(moved);
    }
}

/// What drawing the offsets does to one node's transform.
#[derive(Clone, Copy)]
pub(super) enum Drawn {
    /// The node and its descendants move by this, on screen.
    Shift(Vec2),
    /// The node's own box is drawn scaled by this (its children are shifted, not scaled).
    Scale(Vec2),
}

/// After [`note_reflows`]: draws every offset. Each node with an offset, and its descendants,
/// move by the offset (in its parent's frame); a node drawn at another size has its own box
/// scaled about its centre, and its children keep their size and their place from the drawn
/// box's top-left corner (where layout places them from): a child whose place in its parent did
/// not change does not move, at any nesting of layout springs.
pub(super) fn draw_offsets(
    mut queries: ParamSet<(
        Query<
            (Entity, &LayoutOffset, &ComputedNode, Option<&ChildOf>),
            Or<(Changed<LayoutOffset>, Changed<UiGlobalTransform>)>,
        >,
        Query<&mut UiGlobalTransform>,
    )>,
    descendants: Query<&Children>,
    mut offsets: Local<Vec<(Entity, LayoutOffset, Vec2, Option<Entity>)>>,
    mut drawn: Local<Vec<(Entity, Drawn)>>,
    mut stack: Local<Vec<Entity>>,
) {
    offsets.clear();
    drawn.clear();
    for (entity, offset, node, child_of) in &queries.p0() {
        if *offset != LayoutOffset::ZERO {
            offsets.push((entity, *offset, node.size, child_of.map(ChildOf::parent)));
        }
    }
    if offsets.is_empty() {
        return;
    }
    // Read from the transforms layout computed, before any is drawn.
    let globals = queries.p1();
    for &(entity, offset, size, parent) in &*offsets {
        let Ok(global) = globals.get(entity) else {
            continue;
        };
        let parent_frame = parent
            .and_then(|parent| globals.get(parent).ok())
            .map_or(Mat2::IDENTITY, |parent| parent.matrix2);
        drawn.push((entity, Drawn::Shift(parent_frame * offset.translation)));
        let scale = offset.scale();
        if scale == Vec2::ONE {
            continue;
        }
        drawn.push((entity, Drawn::Scale(scale)));
        // The box scaled about its centre moves its top-left corner by this: the children go
        // with the corner.
        let corner_moved = global.matrix2 * ((Vec2::ONE - scale) * (0.5 * size));
        let children = descendants
            .get(entity)
            .map_or(&[][..], |children| &**children);
        for &child in children {
            drawn.push((child, Drawn::Shift(corner_moved)));
        }
    }
    let mut globals = queries.p1();
    for &(entity, change) in &*drawn {
        match change {
            Drawn::Scale(scale) => {
                if let Ok(mut global) = globals.get_mut(entity) {
                    let mut affine = **global;
                    affine.matrix2 *= Mat2::from_diagonal(scale);
                    *global = affine.into();
                }
            }
            Drawn::Shift(by) => {
                shift_subtrees(&mut globals, &descendants, &mut stack, [entity], by);
            }
        }
    }
}

/// Motion's `popLayout` for a node with a [`Presence`]: the moment its exit starts it leaves
/// the layout flow — laid out absolutely, where it was and at the size it had — so that its
/// siblings close the gap at once (each with a [`LayoutSpring`] springs into it) while it
/// animates out where it stood. An exit cancelled puts it back into the flow as it was.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::ui::PopLayout;
/// use bevy_sprung::ui::UiTransformScale;
///
/// fn spawn_row(mut commands: Commands) {
///     commands.spawn((
///         Node { height: px(40.0), ..default() },
///         LayoutSpring::new(Spring::snappy()),
///         Presence::default(),
///         PopLayout,
///         UiTransformScaleSpring::new(Spring::snappy(), Vec2::ONE),
///         ExitTo::<UiTransformScale>(Vec2::ZERO),
///     ));
/// }
///
/// // The row shrinks away where it stood; the rows below move up at once.
/// fn remove(rows: Query<Entity, With<PopLayout>>, mut commands: Commands) {
///     for row in &rows {
///         commands.entity(row).despawn_after_exit();
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default()))
/// #     .add_systems(Startup, spawn_row)
/// #     .add_systems(Update, remove);
/// # app.update();
/// ```
#[derive(Component, Reflect, Debug, Default, Clone, Copy, PartialEq, Eq)]
#[component(on_add = crate::spring::first_use::<PopLayout>)]
#[require(Presence)]
#[reflect(Component, Debug, Default, Clone, PartialEq)]
pub struct PopLayout;

/// What a popped node's `Node` said before it left the flow, restored if its exit is cancelled.
#[derive(Component, Debug, Clone, PartialEq)]
pub(super) struct Popped {
    position_type: PositionType,
    inset: [Val; 4],
    size: [Val; 2],
    margin: UiRect,
}

impl Popped {
    /// Takes `node` out of the flow, to the place and size of `laid_out` (physical pixels, its
    /// box in its parent's frame), the parent's `border` inside which absolute nodes are placed,
    /// and returns what it said before.
    fn pop(node: &mut Node, laid_out: &LayoutBox, border: Vec2, inverse_scale: f32) -> Self {
        let popped = Self {
            position_type: node.position_type,
            inset: [node.left, node.top, node.right, node.bottom],
            size: [node.width, node.height],
            margin: node.margin,
        };
        let corner = (laid_out.centre - 0.5 * laid_out.size - border) * inverse_scale;
        let size = laid_out.size * inverse_scale;
        node.position_type = PositionType::Absolute;
        (node.left, node.top, node.right, node.bottom) =
            (Val::Px(corner.x), Val::Px(corner.y), Val::Auto, Val::Auto);
        (node.width, node.height) = (Val::Px(size.x), Val::Px(size.y));
        node.margin = UiRect::ZERO;
        popped
    }

    /// Puts `node` back into the flow as it was.
    fn restore(&self, node: &mut Node) {
        node.position_type = self.position_type;
        [node.left, node.top, node.right, node.bottom] = self.inset;
        [node.width, node.height] = self.size;
        node.margin = self.margin;
    }
}

/// Before layout: a [`PopLayout`] node whose exit started leaves the flow, where and as large
/// as layout last put it; one whose exit was cancelled comes back.
pub(super) fn pop_exiting(
    mut nodes: Query<
        (
            Entity,
            &Presence,
            &mut Node,
            Option<&Popped>,
            LayoutParts<'static>,
        ),
        (With<PopLayout>, Changed<Presence>),
    >,
    parents: Query<(&ComputedNode, &UiGlobalTransform)>,
    mut commands: Commands,
) {
    for (entity, presence, mut node, popped, laid) in &mut nodes {
        match (presence.is_exiting(), popped) {
            (true, None) => {
                let inverse_scale = laid.0.inverse_scale_factor;
                let (laid_out, parent) = layout_box_of(laid, &parents);
                let border = parent.map_or(Vec2::ZERO, |parent| parent.border.min_inset);
                let popped = Popped::pop(&mut node, &laid_out, border, inverse_scale);
                commands.entity(entity).try_insert(popped);
            }
            (false, Some(popped)) => {
                popped.restore(&mut node);
                commands.entity(entity).try_remove::<Popped>();
            }
            _ => {}
        }
    }
}
