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
mod velocity;

pub use drag::{DragBounds, DragFollow, DragReleased, Snap, SnapLine, SpringDrag};
pub use velocity::ReleaseVelocity;

use core::fmt;
use core::marker::PhantomData;

use bevy::picking::PickingSystems;
use bevy::picking::events::{
    Cancel, Drag, DragEnd, DragStart, Enter, Leave, Pointer, Press, Release,
};
use bevy::picking::pointer::{PointerButton, PointerId};
use bevy::prelude::*;

use crate::control::SpringControl;
use crate::property::{SpringProperty, ValueOf};
use crate::spring::{
    PropertySpring, PropertySystems, SpringPhase, SpringSystems, SpringUpdate,
    add_systems_on_first_use, first_use, spring_schedule, warn_missing,
};

/// How a pointer is interacting with an entity, kept up to date from `bevy_picking`'s pointer
/// events: by priority `Disabled` (`bevy_ui`'s `InteractionDisabled`, with the `ui` feature),
/// `Dragged`, `Pressed`, `Hovered`, `Focused` (`InputFocus` is on it), `Idle`.
///
/// Only the primary button presses and drags. A pointer over a child counts for its ancestors
/// too (as CSS's `:hover`), so a card is hovered while the pointer is on its text. Updated in
/// `PreUpdate` after picking ([`InteractionSystems`]): gameplay in `Update` sees this frame's
/// state, and can react to it with `Changed<InteractionState>`.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::interaction::InteractionState;
///
/// fn log_presses(buttons: Query<(Entity, &InteractionState), Changed<InteractionState>>) {
///     for (button, state) in &buttons {
///         if *state == InteractionState::Pressed {
///             info!("{button} pressed");
///         }
///     }
/// }
/// # let mut app = App::new();
/// # app.add_systems(Update, log_presses);
/// ```
#[derive(Component, Reflect, Debug, Default, Clone, Copy, PartialEq, Eq, Hash)]
#[reflect(Component, Debug, Default, PartialEq, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[require(PointerContacts)]
#[component(on_add = first_use::<InteractionState>)]
pub enum InteractionState {
    /// No pointer on it.
    #[default]
    Idle,
    /// A pointer is over it (or over one of its descendants).
    Hovered,
    /// The primary button went down on it and has not been released.
    Pressed,
    /// It is being dragged with the primary button.
    Dragged,
    /// It has the input focus (keyboard or gamepad navigation) and no pointer on it.
    Focused,
    /// It is disabled (`InteractionDisabled`): pointers are ignored.
    Disabled,
}

/// The pointers hovering, pressing and dragging an entity, as its pointer events reported
/// them; [`InteractionState`] is derived from it. Added with `InteractionState`.
#[derive(Component, Reflect, Debug, Default, Clone, PartialEq)]
#[reflect(Component, Debug, Default, Clone)]
pub struct PointerContacts {
    hovering: Vec<PointerId>,
    pressing: Vec<PointerId>,
    dragging: Vec<PointerId>,
}

impl PointerContacts {
    /// Whether a pointer is over the entity or one of its descendants.
    #[must_use]
    pub fn is_hovered(&self) -> bool {
        !self.hovering.is_empty()
    }

    /// Whether a pointer's primary button is down on it.
    #[must_use]
    pub fn is_pressed(&self) -> bool {
        !self.pressing.is_empty()
    }

    /// Whether a pointer is dragging it.
    #[must_use]
    pub fn is_dragged(&self) -> bool {
        !self.dragging.is_empty()
    }

    /// The state these contacts give, before focus and disabling are considered.
    #[must_use]
    fn pointer_state(&self) -> InteractionState {
        if self.is_dragged() {
            InteractionState::Dragged
        } else if self.is_pressed() {
            InteractionState::Pressed
        } else if self.is_hovered() {
            InteractionState::Hovered
        } else {
            InteractionState::Idle
        }
    }
}

/// Adds `pointer` to `set` (once); whether it changed.
fn insert(set: &mut Vec<PointerId>, pointer: PointerId) -> bool {
    let new = !set.contains(&pointer);
    if new {
        set.push(pointer);
    }
    new
}

/// Removes `pointer` from `set`; whether it changed.
fn remove(set: &mut Vec<PointerId>, pointer: PointerId) -> bool {
    let before = set.len();
    set.retain(|p| *p != pointer);
    set.len() != before
}

/// Changes the contacts of `entity`, if it has them, marking them changed only if `change`
/// says it changed something.
fn touch(
    contacts: &mut Query<&mut PointerContacts>,
    entity: Entity,
    change: impl FnOnce(&mut PointerContacts) -> bool,
) {
    if let Ok(mut contacts) = contacts.get_mut(entity)
        && change(contacts.bypass_change_detection())
    {
        contacts.set_changed();
    }
}

fn on_enter(event: On<Pointer<Enter>>, mut contacts: Query<&mut PointerContacts>) {
    let pointer = event.pointer_id;
    touch(&mut contacts, event.entity, |c| {
        insert(&mut c.hovering, pointer)
    });
}

fn on_leave(event: On<Pointer<Leave>>, mut contacts: Query<&mut PointerContacts>) {
    let pointer = event.pointer_id;
    touch(&mut contacts, event.entity, |c| {
        remove(&mut c.hovering, pointer)
    });
}

fn on_press(event: On<Pointer<Press>>, mut contacts: Query<&mut PointerContacts>) {
    if event.button == PointerButton::Primary {
        let pointer = event.pointer_id;
        touch(&mut contacts, event.entity, |c| {
            insert(&mut c.pressing, pointer)
        });
    }
}

fn on_release(event: On<Pointer<Release>>, mut contacts: Query<&mut PointerContacts>) {
    if event.button == PointerButton::Primary {
        let pointer = event.pointer_id;
        touch(&mut contacts, event.entity, |c| {
            remove(&mut c.pressing, pointer)
        });
    }
}

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
        let pointer = event.pointer_id;
        touch(&mut contacts, event.entity, |c| {
            insert(&mut c.dragging, pointer)
        });
    }
}

fn on_drag(
    event: On<Pointer<Drag>>,
    mut contacts: Query<&mut PointerContacts>,
    drags: Query<&SpringDrag>,
) {
    if event.button == PointerButton::Primary
        && let Ok(drag) = drags.get(event.entity)
        && drag.engages(event.distance)
    {
        let pointer = event.pointer_id;
        touch(&mut contacts, event.entity, |c| {
            insert(&mut c.dragging, pointer)
        });
    }
}

fn on_drag_end(event: On<Pointer<DragEnd>>, mut contacts: Query<&mut PointerContacts>) {
    if event.button == PointerButton::Primary {
        let pointer = event.pointer_id;
        // The release may land on another entity: the drag's end also ends the press.
        touch(&mut contacts, event.entity, |c| {
            remove(&mut c.dragging, pointer) | remove(&mut c.pressing, pointer)
        });
    }
}

fn on_cancel(event: On<Pointer<Cancel>>, mut contacts: Query<&mut PointerContacts>) {
    let pointer = event.pointer_id;
    touch(&mut contacts, event.entity, |c| {
        remove(&mut c.hovering, pointer)
            | remove(&mut c.pressing, pointer)
            | remove(&mut c.dragging, pointer)
    });
}

/// Where [`InteractionState`]s are brought up to date: in `PreUpdate`, after Bevy's picking
/// (which triggers the pointer events).
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct InteractionSystems;

#[cfg(feature = "ui")]
type Disabled = bevy::ui::InteractionDisabled;
/// Without `bevy_ui` there is no `InteractionDisabled`: nothing is ever disabled.
#[cfg(not(feature = "ui"))]
type Disabled = NeverDisabled;

/// A component no entity has (the `Disabled` state needs `bevy_ui`'s `InteractionDisabled`).
#[cfg(not(feature = "ui"))]
#[derive(Component)]
struct NeverDisabled;

/// Derives every [`InteractionState`] from its contacts, the focus and disabling; writes only
/// states that change.
fn update_states(
    focus: Option<Res<bevy::input_focus::InputFocus>>,
    mut entities: Query<(
        Entity,
        &PointerContacts,
        &mut InteractionState,
        Has<Disabled>,
    )>,
) {
    let focused = focus.and_then(|focus| focus.get());
    for (entity, contacts, mut state, disabled) in &mut entities {
        let new = if disabled {
            InteractionState::Disabled
        } else {
            match contacts.pointer_state() {
                InteractionState::Idle if focused == Some(entity) => InteractionState::Focused,
                other => other,
            }
        };
        state.set_if_neq(new);
    }
}

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
/// # app.add_plugins((MinimalPlugins, SpringPlugin::default())).add_systems(Startup, spawn_button);
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
fn retarget_on_interaction<P, C>(
    mut springs: Query<
        (&InteractionState, &InteractionTargets<P>, &mut C),
        Or<(Changed<InteractionState>, Changed<InteractionTargets<P>>)>,
    >,
) where
    P: SpringProperty,
    C: SpringControl<P>,
{
    for (state, targets, mut spring) in &mut springs {
        let target = targets.target(*state);
        if spring.target() != target {
            spring.retarget(target);
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
            retarget_on_interaction::<P, PropertySpring<P>>
                .in_set(PropertySystems::<P>::phase(SpringPhase::Input))
                .run_if(any_with_component::<InteractionTargets<P>>),
        );
    });
}

/// [`InteractionState`] and [`SpringDrag`] (part of [`SpringPlugin`](crate::SpringPlugin) with
/// the `picking` feature; the app adds Bevy's picking plugins and a backend). The per-property
/// systems of [`InteractionTargets`] come with each property's
/// [`SpringPropertyPlugin`](crate::SpringPropertyPlugin).
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringInteractionPlugin;

impl Plugin for SpringInteractionPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<InteractionState>()
            .register_type::<PointerContacts>()
            .add_observer(on_enter)
            .add_observer(on_leave)
            .add_observer(on_press)
            .add_observer(on_release)
            .add_observer(on_drag_start)
            .add_observer(on_drag)
            .add_observer(on_drag_end)
            .add_observer(on_cancel)
            .configure_sets(PreUpdate, InteractionSystems.after(PickingSystems::Last));
        // With the first interactive entity.
        let interactive = [core::any::TypeId::of::<InteractionState>()];
        add_systems_on_first_use(app, &interactive, PreUpdate, |schedule| {
            schedule.add_systems(
                update_states
                    .in_set(InteractionSystems)
                    .run_if(any_with_component::<InteractionState>),
            );
        });
        drag::build(app);
    }
}
