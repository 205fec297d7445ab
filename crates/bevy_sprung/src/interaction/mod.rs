//! Interaction with `bevy_picking`: pointer states that retarget springs, and drag and fling
//! with snap points (feature `picking`).
//!
//! - [`InteractionState`]: idle, hovered, pressed, dragged, focused or disabled, kept up to
//!   date from Bevy's pointer events for every entity that has it (UI nodes, sprites and meshes
//!   alike — whatever a picking backend hits).
//! - [`InteractionTargets<P>`]: the target of property `P`'s spring in each state (a button
//!   that grows on hover and shrinks when pressed, a card that lifts and glows). A state change
//!   is a retarget, so the velocity is kept: leaving "pressed" for "hovered" mid-way turns the
//!   motion around without a pop.
//! - [`SpringDrag`]: the entity follows the pointer while dragged (exactly or through a stiff
//!   spring), and on release is flung with the pointer's velocity toward the snap point its
//!   throw would come to rest nearest, or home; bounds pull back like a rubber band.
//!
//! Entities without these components cost nothing: the observers look an entity up only when a
//! pointer event reaches it, and the systems iterate only entities that have them.

mod drag;
mod state;

pub use crate::throw::{DragBounds, ReleaseVelocity, Snap, SnapLine};
#[cfg(feature = "ui")]
pub(crate) use drag::pixels;
pub use drag::{DragFollow, DragReleased, SpringDrag};
pub use state::{InteractionState, InteractionSystems, PointerContacts};

use core::fmt;
use core::marker::PhantomData;

use bevy::prelude::*;

use crate::property::{SpringProperty, ValueOf};
use crate::spring::{
    PropertySpring, PropertySystems, SpringPhase, SpringSystems, SpringUpdate,
    add_systems_on_first_use, first_use, spring_schedule, warn_missing,
};

/// The target of property `P`'s spring in each [`InteractionState`]: put it beside the spring,
/// and every state change retargets the spring (keeping its velocity). A state without a
/// target of its own takes the next one down: `dragged` → `pressed` → `hovered` → `idle`,
/// `focused` → `hovered` → `idle`, `disabled` → `idle`.
///
/// Works for every property spring: scale, translation, rotation, colours, UI lengths, your
/// own fields. Adding it adds [`InteractionState`].
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::interaction::InteractionTargets;
/// use bevy_sprung::prelude::*;
///
/// fn spawn_button(mut commands: Commands) {
///     commands.spawn((
///         Button,
///         Node::default(),
///         UiTransformScaleSpring::new(Spring::bouncy(), Vec2::ONE),
///         InteractionTargets::<bevy_sprung::ui::UiTransformScale>::new(Vec2::ONE)
///             .hovered(Vec2::splat(1.08))
///             .pressed(Vec2::splat(0.94)),
///         BackgroundColorSpring::new(Spring::smooth(), Color::srgb(0.2, 0.2, 0.3)),
///         InteractionTargets::<BackgroundColor>::new(Color::srgb(0.2, 0.2, 0.3))
///             .hovered(Color::srgb(0.3, 0.3, 0.5)),
///     ));
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default())).add_systems(Startup, spawn_button);
/// # app.update();
/// ```
#[derive(Component, Reflect)]
#[component(on_add = first_use::<Self>)]
#[reflect(Component, Debug, Clone)]
#[require(InteractionState)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(
    feature = "serde",
    serde(bound(
        serialize = "ValueOf<P>: serde::Serialize",
        deserialize = "ValueOf<P>: serde::Deserialize<'de>"
    ))
)]
pub struct InteractionTargets<P: SpringProperty> {
    /// The target with no pointer on the entity.
    pub idle: ValueOf<P>,
    /// The target while hovered.
    pub hovered: Option<ValueOf<P>>,
    /// The target while pressed.
    pub pressed: Option<ValueOf<P>>,
    /// The target while dragged.
    pub dragged: Option<ValueOf<P>>,
    /// The target while focused.
    pub focused: Option<ValueOf<P>>,
    /// The target while disabled.
    pub disabled: Option<ValueOf<P>>,
    #[reflect(ignore)]
    #[cfg_attr(feature = "serde", serde(skip))]
    property: PhantomData<fn() -> P>,
}

impl<P: SpringProperty> InteractionTargets<P> {
    /// `idle` in every state until others are given.
    #[must_use]
    pub fn new(idle: ValueOf<P>) -> Self {
        Self {
            idle,
            hovered: None,
            pressed: None,
            dragged: None,
            focused: None,
            disabled: None,
            property: PhantomData,
        }
    }

    /// The same, with `target` while hovered.
    #[must_use]
    pub fn hovered(mut self, target: ValueOf<P>) -> Self {
        self.hovered = Some(target);
        self
    }

    /// The same, with `target` while pressed.
    #[must_use]
    pub fn pressed(mut self, target: ValueOf<P>) -> Self {
        self.pressed = Some(target);
        self
    }

    /// The same, with `target` while dragged.
    #[must_use]
    pub fn dragged(mut self, target: ValueOf<P>) -> Self {
        self.dragged = Some(target);
        self
    }

    /// The same, with `target` while focused.
    #[must_use]
    pub fn focused(mut self, target: ValueOf<P>) -> Self {
        self.focused = Some(target);
        self
    }

    /// The same, with `target` while disabled.
    #[must_use]
    pub fn disabled(mut self, target: ValueOf<P>) -> Self {
        self.disabled = Some(target);
        self
    }

    /// The target for `state`, with the fallbacks described on the type.
    #[must_use]
    pub fn target(&self, state: InteractionState) -> ValueOf<P> {
        let hovered = self.hovered.unwrap_or(self.idle);
        match state {
            InteractionState::Idle => self.idle,
            InteractionState::Hovered => hovered,
            InteractionState::Pressed => self.pressed.unwrap_or(hovered),
            InteractionState::Dragged => self.dragged.or(self.pressed).unwrap_or(hovered),
            InteractionState::Focused => self.focused.unwrap_or(hovered),
            InteractionState::Disabled => self.disabled.unwrap_or(self.idle),
        }
    }
}

impl<P: SpringProperty> Clone for InteractionTargets<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for InteractionTargets<P> {}

impl<P: SpringProperty> fmt::Debug for InteractionTargets<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("InteractionTargets")
            .field("property", &P::short_type_path())
            .field("idle", &self.idle)
            .field("hovered", &self.hovered)
            .field("pressed", &self.pressed)
            .field("dragged", &self.dragged)
            .field("focused", &self.focused)
            .field("disabled", &self.disabled)
            .finish()
    }
}

/// Before property `P`'s springs step: retargets the spring of every entity whose state or
/// targets changed (a retarget keeps the velocity).
fn retarget_on_interaction<P>(
    mut springs: Query<
        (
            &InteractionState,
            &InteractionTargets<P>,
            &mut PropertySpring<P>,
        ),
        Or<(Changed<InteractionState>, Changed<InteractionTargets<P>>)>,
    >,
) where
    P: SpringProperty,
{
    for (state, targets, mut spring) in &mut springs {
        let target = targets.target(*state);
        if spring.target() != target {
            spring.set_target(target);
        }
    }
}

/// Pointer states retarget property `P`'s springs, in [`SpringPhase::Input`]: what
/// [`SpringPropertyPlugin<P>`](crate::SpringPropertyPlugin) adds of interaction. The system
/// joins with the first [`InteractionTargets<P>`].
pub(crate) fn add_property<P: SpringProperty>(app: &mut App) {
    app.register_type::<InteractionTargets<P>>();
    let targets = [core::any::TypeId::of::<InteractionTargets<P>>()];
    let outer = spring_schedule(app);
    add_systems_on_first_use(app, &targets, outer, |schedule| {
        schedule.add_systems(
            warn_missing::<InteractionTargets<P>, PropertySpring<P>>(
                "the pointer states retarget that spring and do nothing without it; add the \
                 spring",
            )
            .before(SpringSystems)
            .run_if(any_with_component::<InteractionTargets<P>>),
        );
    });
    add_systems_on_first_use(app, &targets, SpringUpdate, |schedule| {
        schedule.add_systems(
            retarget_on_interaction::<P>
                .in_set(PropertySystems::<P>::phase(SpringPhase::Input))
                .run_if(any_with_component::<InteractionTargets<P>>),
        );
    });
}

/// [`InteractionState`] and [`SpringDrag`] (part of [`SpringPlugins`](crate::SpringPlugins) with
/// the `picking` feature; the app adds Bevy's picking plugins and a backend). The per-property
/// systems of [`InteractionTargets`] come with each property's
/// [`SpringPropertyPlugin`](crate::SpringPropertyPlugin).
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringInteractionPlugin;

impl Plugin for SpringInteractionPlugin {
    fn build(&self, app: &mut App) {
        state::build(app);
        drag::build(app);
    }
}
