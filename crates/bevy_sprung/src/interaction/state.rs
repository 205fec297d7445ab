//! [`InteractionState`]: how pointers are interacting with an entity, kept up to date from
//! `bevy_picking`'s pointer events.

use bevy::picking::PickingSystems;
use bevy::picking::events::{Cancel, DragEnd, Enter, Leave, Pointer, Press, Release};
use bevy::picking::pointer::{PointerButton, PointerId};
use bevy::prelude::*;

use crate::spring::{add_systems_on_first_use, first_use};

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

/// Notes that `pointer` drags `entity` (a drag that engaged: see
/// [`SpringDrag`](super::SpringDrag)'s threshold).
pub(super) fn start_dragging(
    contacts: &mut Query<&mut PointerContacts>,
    entity: Entity,
    pointer: PointerId,
) {
    touch(contacts, entity, |c| insert(&mut c.dragging, pointer));
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

/// The pointer states' observers and system: the states update in `PreUpdate`, after picking,
/// with the first interactive entity.
pub(super) fn build(app: &mut App) {
    app.register_type::<InteractionState>()
        .register_type::<PointerContacts>()
        .add_observer(on_enter)
        .add_observer(on_leave)
        .add_observer(on_press)
        .add_observer(on_release)
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
}
