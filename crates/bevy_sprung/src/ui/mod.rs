//! UI geometry: `UiTransform` and `Node` lengths, in the units they are laid out in.
//!
//! `Node` fields and `UiTransform::translation` are `Val`s, sprung as
//! [`Length`]: on their number, in the unit of their target (a
//! `left: Val::Percent(10.0)` sprung to `Val::Percent(50.0)` slides to 50 %). Targets are
//! `Val`s, so a spring toward `px(200.0)` writes pixels.

mod drawn;
mod layout;
mod scroll;

pub use layout::{
    LayoutOffset, LayoutScale, LayoutScaleSpring, LayoutSpring, LayoutTranslation,
    LayoutTranslationSpring, PopLayout,
};
pub(crate) use scroll::ScrollExtent;
pub use scroll::{MomentumScroll, ScrollMotion, ScrollOffset, ScrollOffsetSpring, ScrollSettled};

use core::any::TypeId;

use bevy::prelude::*;
use bevy::ui::UiSystems;
use bevy::ui::update::update_clipping_system;

use crate::space::{Length, Length2, Linear, NeverThroughZero, ShortestAngle};
use crate::spring::{
    PropertySpring, PropertySystems, SpringPhase, SpringUpdate, add_systems_on_first_use,
};

spring_property!(
    /// `UiTransform::translation`, each axis a [`Length`]: moves a node without relayout (a
    /// hover lift, a slide-in).
    pub UiTransformTranslation: UiTransform::translation as Length2
);

spring_property!(
    /// `UiTransform::scale`, kept from passing through zero like
    /// [`Scale`](crate::transform::Scale) (a button that pops to 0 lands on 0 instead of
    /// mirroring).
    pub UiTransformScale: UiTransform::scale as NeverThroughZero<Linear<Vec2>>
);

spring_property!(
    /// `UiTransform::rotation`, the short way round, in radians (clockwise on screen, as
    /// `UiTransform`).
    pub UiTransformRotation: UiTransform::rotation as ShortestAngle
);

spring_property!(
    /// `Node::width` and `Node::height` as one `Val2` (a panel that grows). Sizes do not pass
    /// through zero: a panel that collapses with a bounce stops at 0 instead of going negative.
    pub NodeSize: Node {
        get: |node| Val2::new(node.width, node.height),
        set: |node, size| (node.width, node.height) = (size.x, size.y)
    } as NeverThroughZero<Length2>
);

spring_property!(
    /// `Node::left` and `Node::top` as one `Val2` (an absolutely positioned node that moves).
    pub NodePosition: Node {
        get: |node| Val2::new(node.left, node.top),
        set: |node, position| (node.left, node.top) = (position.x, position.y)
    } as Length2
);

spring_property!(
    /// `Node::width`; it does not pass through zero, as [`NodeSize`].
    pub NodeWidth: Node::width as NeverThroughZero<Length>
);
spring_property!(
    /// `Node::height`; it does not pass through zero, as [`NodeSize`].
    pub NodeHeight: Node::height as NeverThroughZero<Length>
);
spring_property!(
    /// `Node::left`.
    pub NodeLeft: Node::left as Length
);
spring_property!(
    /// `Node::top`.
    pub NodeTop: Node::top as Length
);
spring_property!(
    /// `Node::right`.
    pub NodeRight: Node::right as Length
);
spring_property!(
    /// `Node::bottom`.
    pub NodeBottom: Node::bottom as Length
);

/// A spring on [`UiTransformTranslation`].
pub type UiTransformTranslationSpring = PropertySpring<UiTransformTranslation>;
/// A spring on [`UiTransformScale`].
pub type UiTransformScaleSpring = PropertySpring<UiTransformScale>;
/// A spring on [`UiTransformRotation`].
pub type UiTransformRotationSpring = PropertySpring<UiTransformRotation>;
/// A spring on [`NodeSize`].
pub type NodeSizeSpring = PropertySpring<NodeSize>;
/// A spring on [`NodePosition`].
pub type NodePositionSpring = PropertySpring<NodePosition>;
/// A spring on [`NodeWidth`].
pub type NodeWidthSpring = PropertySpring<NodeWidth>;
/// A spring on [`NodeHeight`].
pub type NodeHeightSpring = PropertySpring<NodeHeight>;
/// A spring on [`NodeLeft`].
pub type NodeLeftSpring = PropertySpring<NodeLeft>;
/// A spring on [`NodeTop`].
pub type NodeTopSpring = PropertySpring<NodeTop>;
/// A spring on [`NodeRight`].
pub type NodeRightSpring = PropertySpring<NodeRight>;
/// A spring on [`NodeBottom`].
pub type NodeBottomSpring = PropertySpring<NodeBottom>;

/// Layout transitions ([`LayoutSpring`], [`PopLayout`]) and momentum scrolling
/// ([`MomentumScroll`]): their systems join the frame with their first component. Part of
/// [`SpringUiPlugin`](crate::SpringUiPlugin), which also adds the properties they move.
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringUiLayoutPlugin;

impl Plugin for SpringUiLayoutPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<LayoutSpring>()
            .register_type::<PopLayout>()
            .register_type::<LayoutOffset>()
            .register_type::<MomentumScroll>()
            .register_type::<ScrollMotion>()
            .add_observer(scroll::announce_settled);
        #[cfg(feature = "picking")]
        app.add_observer(scroll::pointer::wheel)
            .add_observer(scroll::pointer::start)
            .add_observer(scroll::pointer::drag)
            .add_observer(scroll::pointer::release);
        // With the first scroll area: input and ends before its spring steps, the position
        // shown after; the rubber band drawn after layout.
        let scrolls = [TypeId::of::<MomentumScroll>()];
        add_systems_on_first_use(app, &scrolls, SpringUpdate, |schedule| {
            schedule.add_systems((
                scroll::steer_scrolls
                    .in_set(PropertySystems::<ScrollOffset>::phase(SpringPhase::Input)),
                scroll::show_scrolls
                    .in_set(PropertySystems::<ScrollOffset>::phase(SpringPhase::Observe)),
            ));
        });
        add_systems_on_first_use(app, &scrolls, PostUpdate, |schedule| {
            schedule.add_systems(
                (
                    scroll::warn_unscrollable.before(UiSystems::Prepare),
                    scroll::draw_rubber_bands
                        .in_set(UiSystems::PostLayout)
                        .before(update_clipping_system),
                )
                    .run_if(any_with_component::<MomentumScroll>),
            );
        });
        // With the first node that pops out of layout: before layout, so the frame its exit
        // starts is laid out without it.
        add_systems_on_first_use(app, &[TypeId::of::<PopLayout>()], PostUpdate, |schedule| {
            schedule.add_systems(
                layout::pop_exiting
                    .before(UiSystems::Prepare)
                    .run_if(any_with_component::<PopLayout>),
            );
        });
        // With the first layout spring: after layout placed the nodes, and before the clipping
        // rectangles are computed from where they are drawn.
        add_systems_on_first_use(
            app,
            &[TypeId::of::<LayoutSpring>()],
            PostUpdate,
            |schedule| {
                schedule.add_systems(
                    (layout::note_reflows, layout::draw_offsets)
                        .chain()
                        .in_set(UiSystems::PostLayout)
                        .before(update_clipping_system)
                        .run_if(any_with_component::<LayoutSpring>),
                );
            },
        );
    }
}
