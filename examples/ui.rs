//! A menu that springs instead of tweening: the side panel slides and fades in and out, its
//! buttons lift and glow on hover and squash on press, and a badge pops in with a whole turn (a
//! `Spin`: a rotation spring takes the short way, and a whole turn is no way at all). Every
//! animation is a spring component on the node; the buttons say their targets per pointer state
//! with `InteractionTargets`, and a state change (hover, then leave at once) bends the motion
//! smoothly instead of restarting a tween.
//!
//! Click "Menu" (or press M) to open and close the panel. Without mouse input the example plays
//! a short scripted tour, so it shows the same motion in CI screenshots.
//!
//! ```text
//! cargo run --example ui
//! ```

use bevy::camera::NormalizedRenderTarget;
use bevy::picking::backend::HitData;
use bevy::picking::events::{Enter, Leave, Pointer, Press, Release};
use bevy::picking::pointer::{Location, PointerButton, PointerId};
use bevy::prelude::*;
use bevy_sprung::clock::SpringClock;
use bevy_sprung::color::BorderColorSpring;
use bevy_sprung::prelude::*;
use bevy_sprung::spin::{Spin, SpinAngleSpring};

#[path = "support/tour.rs"]
mod tour;

use tour::{Tour, TourPlugin};

const PANEL_WIDTH: f32 = 300.0;
const IDLE: Color = Color::srgb(0.16, 0.18, 0.24);
const HOVERED: Color = Color::srgb(0.25, 0.42, 0.78);
const PRESSED: Color = Color::srgb(0.12, 0.26, 0.55);

/// The panel that slides in.
#[derive(Component)]
struct Panel;

/// The button that opens and closes the panel.
#[derive(Component)]
struct MenuButton;

/// The badge that pops when the panel opens.
#[derive(Component)]
struct Badge;

#[derive(Resource, Default)]
struct Menu {
    open: bool,
}

/// The tour's pointer.
const TOUR: PointerId = PointerId::Custom(bevy::asset::uuid::Uuid::from_u128(0x5B2));

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: a springy menu".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            // UI keeps animating while the game is paused: springs on the real clock.
            SpringPlugins::default().with_clock(SpringClock::Real),
            TourPlugin::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.07, 0.08, 0.1)))
        .init_resource::<Menu>()
        .add_systems(Startup, setup)
        .add_systems(Update, (tour, toggle, animate_menu).chain())
        .run();
}

/// The layout of a panel button.
fn panel_button() -> Node {
    Node {
        width: Val::Px(240.0),
        height: Val::Px(52.0),
        margin: UiRect::vertical(Val::Px(8.0)),
        justify_content: JustifyContent::Center,
        align_items: AlignItems::Center,
        border: UiRect::all(Val::Px(2.0)),
        border_radius: BorderRadius::all(Val::Px(10.0)),
        ..default()
    }
}

/// A button with its springs and their targets per pointer state: hover lifts and lights it,
/// press squashes and darkens it. A state change retargets each spring, keeping its velocity.
fn button(label: &str, node: Node) -> impl Bundle {
    let edge = Color::srgb(0.3, 0.33, 0.4);
    (
        Button,
        node,
        BackgroundColor(IDLE),
        BorderColor::all(edge),
        UiTransform::default(),
        // One spring per property the button animates...
        BackgroundColorSpring::new(Spring::snappy(), IDLE),
        BorderColorSpring::new(Spring::snappy(), edge),
        UiTransformScaleSpring::new(Spring::bouncy(), Vec2::ONE),
        UiTransformTranslationSpring::new(Spring::snappy(), Val2::ZERO),
        // ...and its target in each state (pressed falls back to hovered where unset).
        InteractionTargets::<BackgroundColor>::new(IDLE)
            .hovered(HOVERED)
            .pressed(PRESSED),
        InteractionTargets::<BorderColor>::new(edge)
            .hovered(Color::srgb(0.55, 0.7, 1.0))
            .pressed(Color::srgb(0.4, 0.55, 0.9)),
        InteractionTargets::<UiTransformScale>::new(Vec2::ONE)
            .hovered(Vec2::splat(1.06))
            .pressed(Vec2::splat(0.94)),
        InteractionTargets::<UiTransformTranslation>::new(Val2::ZERO)
            .hovered(Val2::px(0.0, -3.0))
            .pressed(Val2::px(0.0, 1.0)),
        children![(
            Text::new(label),
            TextFont::from_font_size(20.0),
            TextColor(Color::srgb(0.85, 0.87, 0.92)),
        )],
    )
}

fn setup(mut commands: Commands) {
    commands.spawn(Camera2d);
    // The side panel starts closed: off-screen to the left and transparent.
    commands.spawn((
        Panel,
        Node {
            position_type: PositionType::Absolute,
            left: Val::Px(0.0),
            top: Val::Px(0.0),
            width: Val::Px(PANEL_WIDTH),
            height: Val::Percent(100.0),
            flex_direction: FlexDirection::Column,
            align_items: AlignItems::Center,
            padding: UiRect::top(Val::Px(96.0)),
            ..default()
        },
        BackgroundColor(Color::srgba(0.1, 0.11, 0.15, 0.0)),
        UiTransform::from_translation(Val2::px(-PANEL_WIDTH, 0.0)),
        UiTransformTranslationSpring::new(Spring::smooth(), Val2::px(-PANEL_WIDTH, 0.0)),
        BackgroundColorSpring::new(Spring::smooth(), Color::srgba(0.1, 0.11, 0.15, 0.0)),
        children![
            button("New game", panel_button()),
            button("Continue", panel_button()),
            button("Settings", panel_button()),
            button("Quit", panel_button()),
        ],
    ));
    commands
        .spawn((
            MenuButton,
            button(
                "Menu",
                Node {
                    position_type: PositionType::Absolute,
                    right: Val::Px(24.0),
                    top: Val::Px(20.0),
                    width: Val::Px(140.0),
                    height: Val::Px(48.0),
                    justify_content: JustifyContent::Center,
                    align_items: AlignItems::Center,
                    border: UiRect::all(Val::Px(2.0)),
                    border_radius: BorderRadius::all(Val::Px(10.0)),
                    ..default()
                },
            ),
        ))
        .with_child((
            Badge,
            Node {
                position_type: PositionType::Absolute,
                right: Val::Px(-10.0),
                top: Val::Px(-10.0),
                width: Val::Px(24.0),
                height: Val::Px(24.0),
                justify_content: JustifyContent::Center,
                align_items: AlignItems::Center,
                border_radius: BorderRadius::all(Val::Px(12.0)),
                ..default()
            },
            BackgroundColor(Color::srgb(0.9, 0.3, 0.35)),
            UiTransform::from_scale(Vec2::ZERO),
            // Pops from nothing; `UiTransformScaleSpring` never passes through zero, so closing lands
            // on 0 instead of flipping.
            UiTransformScaleSpring::new(Spring::bouncy(), Vec2::ZERO),
            // Turns once as it pops in, and back as it goes.
            Spin::z(0.0),
            SpinAngleSpring::new(Spring::smooth(), 0.0),
            children![(Text::new("3"), TextFont::from_font_size(14.0))],
        ));
    commands.spawn((
        Text::new("M or click Menu: open / close. Hover and press the buttons."),
        TextFont::from_font_size(16.0),
        TextColor(Color::srgb(0.6, 0.63, 0.7)),
        Node {
            position_type: PositionType::Absolute,
            bottom: Val::Px(14.0),
            right: Val::Px(20.0),
            ..default()
        },
    ));
}

/// The scripted tour, every 7 s: open, hover down the buttons, press one, close, with a pointer
/// of its own (`on`: the button it is over, and whether it presses it), as a user would.
fn tour(
    tour: Res<Tour>,
    mut on: Local<Option<(Entity, bool)>>,
    mut menu: ResMut<Menu>,
    panel: Single<&Children, With<Panel>>,
    mut commands: Commands,
) {
    let Some(elapsed) = tour.time() else {
        return;
    };
    let t = elapsed % 7.0;
    menu.open = (0.3..5.5).contains(&t);
    // Hover each button in turn for 0.6 s from 1.2 s on; press the third in the second half.
    let wanted = hovered_button(t)
        .and_then(|index| panel.get(index).map(|&button| (index, button)))
        .map(|(index, button)| (button, index == 2 && (t - 1.2) % 0.6 > 0.3));
    if wanted == *on {
        return;
    }
    if let Some((button, pressed)) = *on {
        if pressed {
            commands.trigger(pointer(
                button,
                Release {
                    button: PointerButton::Primary,
                    hit: hit(),
                },
            ));
        }
        if wanted.is_none_or(|(next, _)| next != button) {
            commands.trigger(pointer(
                button,
                Leave {
                    hit: hit(),
                    was_in_bounds: true,
                },
            ));
        }
    }
    if let Some((button, pressed)) = wanted {
        if on.is_none_or(|(last, _)| last != button) {
            commands.trigger(pointer(
                button,
                Enter {
                    hit: hit(),
                    is_in_bounds: true,
                },
            ));
        }
        if pressed {
            commands.trigger(pointer(
                button,
                Press {
                    button: PointerButton::Primary,
                    hit: hit(),
                    count: 1,
                },
            ));
        }
    }
    *on = wanted;
}

/// The tour's pointer event `event` on `button`.
fn pointer<E: core::fmt::Debug + Clone + Reflect>(button: Entity, event: E) -> Pointer<E> {
    let location = Location {
        target: NormalizedRenderTarget::None {
            width: 1280,
            height: 720,
        },
        position: Vec2::ZERO,
    };
    Pointer::new(TOUR, location, event, button)
}

/// Where the tour's pointer hits: nowhere in particular.
fn hit() -> HitData {
    HitData::new(Entity::PLACEHOLDER, 0.0, None, None)
}

/// Which button the tour hovers at `t` seconds into its loop: one every 0.6 s from 1.2 s on.
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "a small non-negative step count"
)]
fn hovered_button(t: f32) -> Option<usize> {
    (t >= 1.2).then(|| ((t - 1.2) / 0.6) as usize)
}

fn toggle(
    keys: Res<ButtonInput<KeyCode>>,
    mut menu: ResMut<Menu>,
    pressed: Query<&Interaction, (With<MenuButton>, Changed<Interaction>)>,
) {
    let clicked = pressed.iter().any(|i| *i == Interaction::Pressed);
    if keys.just_pressed(KeyCode::KeyM) || clicked {
        menu.open = !menu.open;
    }
}

/// Open or close: the panel slides and fades, the badge pops. Only targets change; the springs
/// do the rest, from wherever they are.
fn animate_menu(
    menu: Res<Menu>,
    mut panel: Single<
        (
            &mut UiTransformTranslationSpring,
            &mut BackgroundColorSpring,
        ),
        With<Panel>,
    >,
    mut badge: Single<(&mut UiTransformScaleSpring, &mut SpinAngleSpring), With<Badge>>,
) {
    if !menu.is_changed() {
        return;
    }
    let (slide, fade) = &mut *panel;
    let (x, alpha, badge_scale, badge_turn) = if menu.open {
        (0.0, 0.92, 1.0, core::f32::consts::TAU)
    } else {
        (-PANEL_WIDTH, 0.0, 0.0, 0.0)
    };
    slide.set_target(Val2::px(x, 0.0));
    fade.set_target(Color::srgba(0.1, 0.11, 0.15, alpha));
    let (pop, turn) = &mut *badge;
    pop.set_target(Vec2::splat(badge_scale));
    turn.set_target(badge_turn);
}
