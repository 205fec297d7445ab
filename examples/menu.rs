//! A game's main menu choreographed with springs instead of tweens.
//!
//! - The menu items fly in one after another (a staggered [`SpringSequence`]) and fade up; when
//!   every item has arrived, the group reports it ([`SpringGroupSettled`]).
//! - "Play" pulses (a looping sequence from `assets/springs/pulse.sequence.ron`) until it is
//!   hovered; hovering interrupts the pulse (the sequence pauses), leaving resumes it.
//! - "Settings" opens a panel that first slides in, then fades its contents up (the fade starts
//!   on the slide's [`SequenceCompleted`]). Close it mid-slide and it turns back from where it
//!   is, with its velocity, and the fade never starts ([`SequenceInterrupted`]).
//! - R cycles the reduced-motion preference ([`ReducedMotion`]): full motion, no overshoot,
//!   snap. The choreography keeps working in every mode, because settle events still fire.
//! - The springs' parameters come from `assets/springs/*.spring.ron`; with Bevy's
//!   `file_watcher` feature, edit them while the menu runs and the motion changes live.
//!
//! Without mouse input the example plays a short scripted tour, so CI screenshots show it.
//!
//! ```text
//! cargo run --example menu
//! ```

use bevy::prelude::*;
use bevy_sprung::asset::{UseSequencePreset, UseSpringPreset};
use bevy_sprung::choreography::{
    OnInterrupt, SequenceCompleted, SequenceInterrupted, SpringGroup, SpringGroupSettled,
};
use bevy_sprung::clock::SpringClock;
use bevy_sprung::color::TextColorSpring;
use bevy_sprung::prelude::*;
use bevy_sprung::ui::{UiTransformScale, UiTransformTranslation};

#[path = "support/tour.rs"]
mod tour;

use tour::{Tour, TourPlugin};

const ITEMS: [&str; 5] = ["Play", "Continue", "Settings", "Credits", "Quit"];
const PANEL_WIDTH: f32 = 420.0;
/// Where the items fly in from, relative to their place.
const ITEM_START: Val2 = Val2::new(Val::Px(-520.0), Val::Px(0.0));
const ITEM: Color = Color::srgb(0.15, 0.17, 0.23);
const ITEM_HOVERED: Color = Color::srgb(0.26, 0.44, 0.82);
const LABEL: Color = Color::srgb(0.86, 0.88, 0.93);
const PANEL: Color = Color::srgb(0.11, 0.12, 0.17);

/// A main-menu item.
#[derive(Component)]
struct MenuItem;

/// The item that opens the settings panel.
#[derive(Component)]
struct SettingsItem;

/// Whether the pointer is over an item: from `Interaction`, or from the tour.
#[derive(Component, Default, PartialEq)]
struct Hovered(bool);

/// The settings panel, which slides in from the right.
#[derive(Component)]
struct SettingsPanel;

/// What fades up inside the panel once it has slid in.
#[derive(Component)]
struct PanelContent;

/// The lines that report the menu's state and how to use it.
#[derive(Component)]
struct Status;

/// Whether the settings panel is open.
#[derive(Resource, Default)]
struct Settings {
    open: bool,
}

/// What the status line says besides the reduced-motion mode.
#[derive(Resource)]
struct StatusNote(String);

impl Default for StatusNote {
    fn default() -> Self {
        Self("menu flying in".into())
    }
}

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: a choreographed menu".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            // Menus animate while the game is paused: springs on the real clock.
            SpringPlugins::default().with_clock(SpringClock::Real),
            TourPlugin::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.06, 0.07, 0.09)))
        .init_resource::<Settings>()
        .init_resource::<StatusNote>()
        .add_systems(Startup, setup)
        .add_systems(
            Update,
            (
                tour,
                pointer,
                hover_items,
                click_settings,
                cycle_reduced_motion,
                open_or_close_panel,
                show_status,
            )
                .chain(),
        )
        .add_observer(fade_in_panel_content)
        .add_observer(note_interrupted_slide)
        .add_observer(note_menu_ready)
        .run();
}

fn setup(mut commands: Commands, assets: Res<AssetServer>) {
    commands.spawn(Camera2d);
    spawn_menu(&mut commands, &assets);
    spawn_settings_panel(&mut commands, &assets);
    spawn_status(&mut commands);
}

/// The title and the menu: a column of items, each starting off to the left and transparent.
fn spawn_menu(commands: &mut Commands, assets: &AssetServer) {
    let menu_spring = assets.load("springs/ui.spring.ron");
    commands.spawn((
        Text::new("sprung"),
        TextFont::from_font_size(56.0),
        TextColor(Color::srgb(0.95, 0.75, 0.35)),
        Node {
            position_type: PositionType::Absolute,
            left: Val::Px(96.0),
            top: Val::Px(60.0),
            ..default()
        },
    ));

    let column = commands
        .spawn(Node {
            position_type: PositionType::Absolute,
            left: Val::Px(96.0),
            top: Val::Px(170.0),
            flex_direction: FlexDirection::Column,
            ..default()
        })
        .id();
    for (index, label) in ITEMS.into_iter().enumerate() {
        let mut item = commands.spawn((
            MenuItem,
            Button,
            Hovered::default(),
            Node {
                width: Val::Px(320.0),
                height: Val::Px(64.0),
                margin: UiRect::vertical(Val::Px(9.0)),
                padding: UiRect::left(Val::Px(28.0)),
                align_items: AlignItems::Center,
                border_radius: BorderRadius::all(Val::Px(12.0)),
                ..default()
            },
            BackgroundColor(ITEM.with_alpha(0.0)),
            UiTransform::from_translation(ITEM_START),
            UiTransformTranslationSpring::new(Spring::default(), ITEM_START),
            // Fly in, 80 ms apart, and fade up on the way.
            SpringSequence::<UiTransformTranslation>::new()
                .staggered(index, 0.08)
                .then(Val2::ZERO),
            BackgroundColorSpring::new(Spring::default(), ITEM.with_alpha(0.0)),
            SpringSequence::<BackgroundColor>::new()
                .staggered(index, 0.08)
                .then(ITEM),
            UiTransformScaleSpring::new(Spring::default(), Vec2::ONE),
            // Every spring of the item takes its parameters from the preset file.
            UseSpringPreset(menu_spring.clone()),
            SpringGroup::named("menu"),
            children![(
                Text::new(label),
                TextFont::from_font_size(26.0),
                TextColor(LABEL),
            )],
        ));
        match label {
            // A pulse from a file, until hovered.
            "Play" => {
                item.insert(UseSequencePreset::<UiTransformScale>::new(
                    assets.load("springs/pulse.sequence.ron"),
                ));
            }
            "Settings" => {
                item.insert(SettingsItem);
            }
            _ => {}
        }
        let item = item.id();
        commands.entity(column).add_child(item);
    }
}

/// The settings panel: off-screen to the right, its contents transparent.
fn spawn_settings_panel(commands: &mut Commands, assets: &AssetServer) {
    commands.spawn((
        SettingsPanel,
        Node {
            position_type: PositionType::Absolute,
            right: Val::Px(0.0),
            top: Val::Px(0.0),
            width: Val::Px(PANEL_WIDTH),
            height: Val::Percent(100.0),
            flex_direction: FlexDirection::Column,
            padding: UiRect::new(Val::Px(40.0), Val::Px(40.0), Val::Px(80.0), Val::Px(0.0)),
            row_gap: Val::Px(22.0),
            ..default()
        },
        BackgroundColor(PANEL),
        UiTransform::from_translation(Val2::px(PANEL_WIDTH, 0.0)),
        UiTransformTranslationSpring::new(Spring::default(), Val2::px(PANEL_WIDTH, 0.0)),
        UseSpringPreset(assets.load("springs/gentle.spring.ron")),
        children![
            panel_line("Settings", 34.0),
            panel_line("Music volume        80 %", 22.0),
            panel_line("Effects volume      65 %", 22.0),
            panel_line("Reduce motion       R", 22.0),
            panel_line("Close               Esc", 22.0),
        ],
    ));
}

/// The status line and the help line.
fn spawn_status(commands: &mut Commands) {
    commands.spawn((
        Node {
            position_type: PositionType::Absolute,
            left: Val::Px(96.0),
            bottom: Val::Px(24.0),
            flex_direction: FlexDirection::Column,
            row_gap: Val::Px(6.0),
            ..default()
        },
        children![
            (
                Status,
                Text::default(),
                TextFont::from_font_size(17.0),
                TextColor(Color::srgb(0.85, 0.75, 0.5)),
            ),
            (
                Text::new("Hover the items, click Settings, Esc closes, R: reduced motion"),
                TextFont::from_font_size(17.0),
                TextColor(Color::srgb(0.6, 0.63, 0.7)),
            ),
        ],
    ));
}

/// A line of the settings panel, transparent until the panel has slid in.
fn panel_line(text: &str, size: f32) -> impl Bundle {
    (
        PanelContent,
        Text::new(text),
        TextFont::from_font_size(size),
        TextColor(LABEL.with_alpha(0.0)),
        TextColorSpring::new(Spring::smooth(), LABEL.with_alpha(0.0)),
    )
}

/// The scripted tour: the menu flies in, "Play" pulses, the pointer hovers "Continue", the
/// settings panel opens, and so on, every 9 s.
fn tour(
    tour: Res<Tour>,
    mut settings: ResMut<Settings>,
    mut items: Query<&mut Hovered, With<MenuItem>>,
) {
    let Some(elapsed) = tour.time() else {
        return;
    };
    let t = elapsed % 9.0;
    // The pointer passes over "Play" (its pulse pauses), "Continue" and "Settings".
    let hovered = [(1.0, 1.6), (1.6, 2.0), (2.0, 2.4)]
        .iter()
        .position(|(from, to)| (*from..*to).contains(&t));
    for (index, mut item) in items.iter_mut().enumerate() {
        item.set_if_neq(Hovered(hovered == Some(index)));
    }
    // Open the settings, close them mid-slide (the slide turns back and its fade never starts),
    // open them again and let the choreography finish.
    let open = (2.2..2.45).contains(&t) || (2.9..7.0).contains(&t);
    if settings.open != open {
        settings.open = open;
    }
}

/// With the user in control, items are hovered as their `Interaction` says.
fn pointer(tour: Res<Tour>, mut items: Query<(&Interaction, &mut Hovered), Changed<Interaction>>) {
    if tour.is_running() {
        return;
    }
    for (interaction, mut hovered) in &mut items {
        hovered.set_if_neq(Hovered(*interaction != Interaction::None));
    }
}

/// Hovering an item lights it and grows it; on "Play" that interrupts the pulse, which goes on
/// when the pointer leaves.
fn hover_items(
    mut items: Query<
        (
            Ref<Hovered>,
            &mut BackgroundColorSpring,
            &mut UiTransformScaleSpring,
            Option<&mut SpringSequence<UiTransformScale>>,
        ),
        Changed<Hovered>,
    >,
) {
    for (hovered, mut background, mut scale, pulse) in &mut items {
        if hovered.is_added() {
            // Spawned unhovered: the fly-in owns the colour.
            continue;
        }
        if hovered.0 {
            background.set_target(ITEM_HOVERED);
            scale.set_target(Vec2::splat(1.06));
        } else {
            background.set_target(ITEM);
            scale.set_target(Vec2::ONE);
            if let Some(mut pulse) = pulse {
                pulse.resume();
            }
        }
    }
}

/// Clicking "Settings" toggles the panel; Escape closes it.
fn click_settings(
    keys: Res<ButtonInput<KeyCode>>,
    clicked: Query<&Interaction, (With<SettingsItem>, Changed<Interaction>)>,
    mut settings: ResMut<Settings>,
) {
    if clicked.iter().any(|i| *i == Interaction::Pressed) {
        settings.open = !settings.open;
    }
    if keys.just_pressed(KeyCode::Escape) && settings.open {
        settings.open = false;
    }
}

/// R cycles the reduced-motion preference: full, no overshoot, snap.
fn cycle_reduced_motion(keys: Res<ButtonInput<KeyCode>>, mut reduced: ResMut<ReducedMotion>) {
    if keys.just_pressed(KeyCode::KeyR) {
        *reduced = match *reduced {
            ReducedMotion::Full => ReducedMotion::NoOvershoot,
            ReducedMotion::NoOvershoot => ReducedMotion::Snap,
            _ => ReducedMotion::Full,
        };
    }
}

/// Opening starts the slide; its completion starts the fade ([`fade_in_panel_content`]).
/// Closing retargets the slide from wherever it is, which interrupts an unfinished opening, and
/// fades the contents out at once.
fn open_or_close_panel(
    settings: Res<Settings>,
    panel: Single<(Entity, &mut UiTransformTranslationSpring), With<SettingsPanel>>,
    mut content: Query<&mut TextColorSpring, With<PanelContent>>,
    mut commands: Commands,
) {
    if !settings.is_changed() || settings.is_added() {
        return;
    }
    let (panel, mut slide) = panel.into_inner();
    if settings.open {
        commands.entity(panel).insert(
            SpringSequence::<UiTransformTranslation>::new()
                .then(Val2::ZERO)
                .on_interrupt(OnInterrupt::Cancel),
        );
    } else {
        slide.set_target(Val2::px(PANEL_WIDTH, 0.0));
        for mut line in &mut content {
            line.set_target(LABEL.with_alpha(0.0));
        }
    }
}

/// The second half of the panel's choreography: once it has slid in, its contents fade up.
fn fade_in_panel_content(
    slid_in: On<SequenceCompleted<UiTransformTranslation>>,
    panels: Query<(), With<SettingsPanel>>,
    mut content: Query<&mut TextColorSpring, With<PanelContent>>,
    mut note: ResMut<StatusNote>,
) {
    if !panels.contains(slid_in.entity) {
        return;
    }
    note.0 = "settings panel in; contents fading up".into();
    info!("{}", note.0);
    for mut line in &mut content {
        line.set_target(LABEL);
    }
}

/// A panel closed before it had slid in: its fade never starts.
fn note_interrupted_slide(
    interrupted: On<SequenceInterrupted<UiTransformTranslation>>,
    panels: Query<(), With<SettingsPanel>>,
    mut note: ResMut<StatusNote>,
) {
    if panels.contains(interrupted.entity) {
        note.0 = "closed mid-slide: turned back with its velocity, no fade".into();
        info!("{}", note.0);
    }
}

/// Every item of the menu has arrived (reported once; the group reports again each time its
/// springs settle after moving, e.g. between pulses).
fn note_menu_ready(
    settled: On<SpringGroupSettled>,
    mut reported: Local<bool>,
    mut note: ResMut<StatusNote>,
) {
    if settled.group == "menu" && !*reported {
        *reported = true;
        note.0 = "every menu item has arrived".into();
        info!("{}", note.0);
    }
}

fn show_status(
    reduced: Res<ReducedMotion>,
    note: Res<StatusNote>,
    tour: Res<Tour>,
    mut status: Single<&mut Text, With<Status>>,
) {
    if !(reduced.is_changed() || note.is_changed() || tour.is_changed()) {
        return;
    }
    let mode = match *reduced {
        ReducedMotion::Full => "full motion",
        ReducedMotion::NoOvershoot => "reduced motion: no overshoot",
        ReducedMotion::Snap => "reduced motion: snap",
        ReducedMotion::Scaled(_) => "reduced motion: slower",
    };
    let who = if tour.is_running() {
        "  |  scripted tour"
    } else {
        ""
    };
    status.0 = format!("{mode}  |  {}{who}", note.0);
}
