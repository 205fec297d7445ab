//! An inventory list whose structure animates: items that enter and leave, reorder, filter and
//! scroll, and a toast that slides in and out.
//!
//! - The items stagger in when the list opens ([`StaggerChildren`]), each one entering with
//!   [`Presence`]: it grows and fades in from [`EnterFrom`] values.
//! - A, D, R: add an item at the top, remove the selected one (it slides out, then is
//!   despawned: [`despawn_after_exit`](PresenceCommands::despawn_after_exit); with
//!   [`PopLayout`] the rows below move up as it goes), move the last to the top. The other
//!   items spring to their new places ([`LayoutSpring`]): `Children` is
//!   reordered and layout does the rest.
//! - F filters the list to the equipped items: the others leave, and come back when the filter
//!   is cleared.
//! - Up and Down move the selection; the highlight is written as a plain `BackgroundColor`
//!   and fades ([`ImplicitSpring`]).
//! - The wheel, a drag, or Space (a fling) scroll the list with momentum and rubber-band ends
//!   ([`MomentumScroll`]).
//! - Each change shows a toast that slides in, stays two seconds and slides out.
//! - G shows the springs' guides (the debug overlay's UI group, [`UiSpringGizmos`]): each row
//!   in flight drawn where it is and where layout puts it, with the path between; the list's
//!   bounds, the give of its rubber band, its content and where a fling will rest.
//!
//! Without input the example plays a scripted tour, so CI screenshots show it.
//!
//! ```text
//! cargo run --example list
//! ```

use bevy::gizmos::config::GizmoConfigStore;
use bevy::prelude::*;
use bevy_sprung::debug::{SpringDebugPlugin, UiSpringGizmos};
use bevy_sprung::prelude::*;
use bevy_sprung::presence::StaggerChildren;
use bevy_sprung::ui::{MomentumScroll, PopLayout};

#[path = "support/tour.rs"]
mod tour;

use tour::{Tour, TourPlugin};

const NAMES: [&str; 12] = [
    "Iron sword",
    "Oak shield",
    "Healing potion",
    "Rope",
    "Lantern",
    "Map of the north",
    "Silver ring",
    "Bread",
    "Arrows (20)",
    "Lockpick",
    "Cloak",
    "Compass",
];
const ROW: Color = Color::srgb(0.15, 0.17, 0.23);
const SELECTED: Color = Color::srgb(0.26, 0.44, 0.82);
const EQUIPPED: Color = Color::srgb(0.95, 0.75, 0.35);
const TEXT: Color = Color::srgb(0.86, 0.88, 0.93);

/// One item of the inventory, as the game keeps it.
#[derive(Clone)]
struct Item {
    id: u32,
    name: &'static str,
    equipped: bool,
}

/// The inventory, the filter and the selection: the list's rows follow it.
#[derive(Resource)]
struct Inventory {
    items: Vec<Item>,
    next_id: u32,
    equipped_only: bool,
    selected: usize,
}

/// A row showing the item with this id.
#[derive(Component)]
struct Row(u32);

/// The list of rows.
#[derive(Component)]
struct List;

/// A message shown as a toast.
#[derive(Message)]
struct Toast(String);

/// How long a toast stays before it leaves.
#[derive(Component)]
struct ToastTimer(Timer);

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: a list that springs".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            SpringPlugins::default(),
            SpringDebugPlugin::hidden().toggled_by(KeyCode::KeyG),
            TourPlugin::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.06, 0.07, 0.09)))
        .insert_resource(Inventory {
            items: (0..24)
                .map(|id| Item {
                    id,
                    name: NAMES[id as usize % NAMES.len()],
                    equipped: id % 3 == 0,
                })
                .collect(),
            next_id: 24,
            equipped_only: false,
            selected: 0,
        })
        .add_message::<Toast>()
        .add_systems(Startup, setup)
        .add_systems(
            Update,
            (
                tour,
                keys,
                fling,
                sync_rows,
                highlight,
                show_toasts,
                dismiss_toasts,
            )
                .chain(),
        )
        .run();
}

fn setup(mut commands: Commands) {
    commands.spawn(Camera2d);
    commands.spawn((
        Text::new("A add   D remove   R last to top   F equipped only   Up/Down select   wheel, drag or Space to scroll   G guides"),
        TextFont::from_font_size(16.0),
        TextColor(TEXT.with_alpha(0.6)),
        Node { position_type: PositionType::Absolute, left: px(48.0), top: px(24.0), ..default() },
    ));
    commands.spawn((
        List,
        Node {
            position_type: PositionType::Absolute,
            left: px(48.0),
            top: px(64.0),
            width: px(420.0),
            height: px(600.0),
            flex_direction: FlexDirection::Column,
            row_gap: px(8.0),
            overflow: Overflow::scroll_y(),
            ..default()
        },
        MomentumScroll::default(),
        StaggerChildren::new(0.05),
    ));
}

/// The tour: a few seconds of the list's changes, then a fling; the guides shown for the last
/// changes.
fn tour(
    tour: Res<Tour>,
    mut inventory: ResMut<Inventory>,
    mut lists: Query<&mut MomentumScroll, With<List>>,
    mut toasts: MessageWriter<Toast>,
    mut guides: ResMut<GizmoConfigStore>,
) {
    let at = |moment: f32| tour.passed(moment);
    let mut fling = |velocity: f32| {
        for mut list in &mut lists {
            list.fling(Vec2::Y * velocity);
        }
    };
    if at(1.0) {
        fling(1200.0);
    }
    if at(3.6) {
        fling(-2400.0);
    }
    if at(4.3) {
        guides.config_mut::<UiSpringGizmos>().0.enabled = true;
    }
    let change = if at(2.2) || at(3.2) {
        toggle_filter(&mut inventory)
    } else if at(4.4) {
        add_item(&mut inventory)
    } else if at(4.8) {
        last_to_top(&mut inventory)
    } else if at(5.2) {
        inventory.selected = 3;
        remove_selected(&mut inventory)
    } else {
        return;
    };
    toasts.write(change);
}

/// The keys, once the tour is over.
fn keys(
    keys: Res<ButtonInput<KeyCode>>,
    mut inventory: ResMut<Inventory>,
    mut toasts: MessageWriter<Toast>,
) {
    let message = if keys.just_pressed(KeyCode::KeyA) {
        add_item(&mut inventory)
    } else if keys.just_pressed(KeyCode::KeyD) {
        remove_selected(&mut inventory)
    } else if keys.just_pressed(KeyCode::KeyR) {
        last_to_top(&mut inventory)
    } else if keys.just_pressed(KeyCode::KeyF) {
        toggle_filter(&mut inventory)
    } else {
        let shown = visible(&inventory).count().max(1);
        if keys.just_pressed(KeyCode::ArrowDown) {
            inventory.selected = (inventory.selected + 1) % shown;
        } else if keys.just_pressed(KeyCode::ArrowUp) {
            inventory.selected = (inventory.selected + shown - 1) % shown;
        }
        return;
    };
    toasts.write(message);
}

fn add_item(inventory: &mut Inventory) -> Toast {
    let id = inventory.next_id;
    inventory.next_id += 1;
    let name = NAMES[id as usize % NAMES.len()];
    inventory.items.insert(
        0,
        Item {
            id,
            name,
            equipped: false,
        },
    );
    Toast(format!("Picked up: {name}"))
}

fn last_to_top(inventory: &mut Inventory) -> Toast {
    let last = inventory.items.pop().expect("an item");
    let message = Toast(format!("{} moved to the top", last.name));
    inventory.items.insert(0, last);
    message
}

fn remove_selected(inventory: &mut Inventory) -> Toast {
    let Some(id) = visible(inventory)
        .nth(inventory.selected)
        .map(|item| item.id)
    else {
        return Toast("Nothing to drop".into());
    };
    let index = inventory
        .items
        .iter()
        .position(|item| item.id == id)
        .expect("shown");
    let item = inventory.items.remove(index);
    Toast(format!("Dropped: {}", item.name))
}

fn toggle_filter(inventory: &mut Inventory) -> Toast {
    inventory.equipped_only = !inventory.equipped_only;
    inventory.selected = 0;
    Toast(
        if inventory.equipped_only {
            "Equipped only"
        } else {
            "Everything"
        }
        .into(),
    )
}

/// The items the filter lets through, in order.
fn visible(inventory: &Inventory) -> impl Iterator<Item = &Item> {
    inventory
        .items
        .iter()
        .filter(|item| item.equipped || !inventory.equipped_only)
}

/// Space flings the list down.
fn fling(keys: Res<ButtonInput<KeyCode>>, mut lists: Query<&mut MomentumScroll, With<List>>) {
    if keys.just_pressed(KeyCode::Space) {
        for mut list in &mut lists {
            list.fling(Vec2::Y * 1800.0);
        }
    }
}

/// The rows follow the inventory: new items enter, items gone leave, and `Children` takes the
/// inventory's order (a leaving row keeps its place after the row it followed).
fn sync_rows(
    inventory: Res<Inventory>,
    lists: Query<(Entity, Option<&Children>), With<List>>,
    rows: Query<(&Row, &Presence)>,
    mut commands: Commands,
) {
    if !inventory.is_changed() {
        return;
    }
    let Ok((list, children)) = lists.single() else {
        return;
    };
    let shown: Vec<u32> = visible(&inventory).map(|item| item.id).collect();
    let mut places: Vec<(Entity, f32)> = Vec::new();
    let mut before = -0.5;
    for &child in children.into_iter().flatten() {
        let Ok((row, presence)) = rows.get(child) else {
            continue;
        };
        if let Some(index) = shown.iter().position(|&id| id == row.0) {
            // Back before it was gone: it turns round, keeping its velocity.
            if presence.is_exiting() {
                commands.entity(child).cancel_exit();
            }
            before = index as f32;
            places.push((child, before));
        } else {
            commands.entity(child).despawn_after_exit();
            places.push((child, before + 0.5));
        }
    }
    for (index, item) in visible(&inventory).enumerate() {
        if !places
            .iter()
            .any(|&(child, _)| rows.get(child).is_ok_and(|(row, _)| row.0 == item.id))
        {
            let new = commands.spawn((row(item), ChildOf(list))).id();
            places.push((new, index as f32));
        }
    }
    commands
        .entity(list)
        .queue(move |mut list: EntityWorldMut| {
            if let Some(mut children) = list.get_mut::<Children>() {
                let place = |child: &Entity| {
                    places
                        .iter()
                        .find(|(row, _)| row == child)
                        .map_or(f32::MAX, |&(_, place)| place)
                };
                children.sort_by(|a, b| place(a).total_cmp(&place(b)));
            }
        });
}

/// A row: it enters growing and fading in, leaves sliding right and fading out, and springs to
/// its place when the list changes.
fn row(item: &Item) -> impl Bundle {
    let color = if item.equipped { EQUIPPED } else { TEXT };
    (
        Row(item.id),
        Node {
            height: px(44.0),
            flex_shrink: 0.0,
            padding: UiRect::horizontal(px(16.0)),
            align_items: AlignItems::Center,
            ..default()
        },
        BackgroundColor(ROW),
        ImplicitSpring::<BackgroundColor>::new(Spring::smooth()),
        LayoutSpring::new(Spring::snappy()),
        Presence::default(),
        // A leaving row leaves the layout at once: the rows below close the gap as it slides.
        PopLayout,
        UiTransformScaleSpring::new(Spring::bouncy(), Vec2::ONE),
        EnterFrom::<UiTransformScale>(Vec2::splat(0.6)),
        UiTransformTranslationSpring::new(Spring::snappy(), Val2::ZERO),
        ExitTo::<UiTransformTranslation>(Val2::px(460.0, 0.0)),
        children![(
            Text::new(item.name),
            TextFont::from_font_size(20.0),
            TextColor(color)
        )],
    )
}

/// The selected row is lit: a plain write, which the row's implicit spring animates.
fn highlight(
    inventory: Res<Inventory>,
    lists: Query<&Children, With<List>>,
    mut rows: Query<(&Presence, &mut BackgroundColor), With<Row>>,
) {
    let Ok(children) = lists.single() else { return };
    let mut index = 0;
    for &child in children {
        let Ok((presence, mut color)) = rows.get_mut(child) else {
            continue;
        };
        if presence.is_exiting() {
            continue;
        }
        let lit = if index == inventory.selected {
            SELECTED
        } else {
            ROW
        };
        color.set_if_neq(BackgroundColor(lit));
        index += 1;
    }
}

/// A toast enters from below, stays two seconds, and leaves.
fn show_toasts(
    mut messages: MessageReader<Toast>,
    toasts: Query<Entity, With<ToastTimer>>,
    mut commands: Commands,
) {
    for Toast(text) in messages.read() {
        for old in &toasts {
            commands.entity(old).despawn_after_exit();
        }
        commands.spawn((
            ToastTimer(Timer::from_seconds(2.0, TimerMode::Once)),
            Node {
                position_type: PositionType::Absolute,
                right: px(48.0),
                bottom: px(48.0),
                padding: UiRect::all(px(16.0)),
                ..default()
            },
            BackgroundColor(Color::srgb(0.2, 0.24, 0.32)),
            Presence::default(),
            UiTransformTranslationSpring::new(Spring::snappy(), Val2::ZERO),
            EnterFrom::<UiTransformTranslation>(Val2::px(0.0, 140.0)),
            ExitTo::<UiTransformTranslation>(Val2::px(0.0, 140.0)),
            children![(
                Text::new(text.clone()),
                TextFont::from_font_size(20.0),
                TextColor(TEXT)
            )],
        ));
    }
}

/// A toast that has stayed its time leaves.
fn dismiss_toasts(
    time: Res<Time>,
    mut toasts: Query<(Entity, &mut ToastTimer)>,
    mut commands: Commands,
) {
    for (toast, mut timer) in &mut toasts {
        if timer.0.tick(time.delta()).just_finished() {
            commands.entity(toast).despawn_after_exit();
        }
    }
}
