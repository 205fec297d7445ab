//! Game feel with springs: a board of cards you pick up and throw, a hopping character, and a
//! camera that follows it and shakes.
//!
//! - **Cards** lift and glow when hovered, squash when pressed and tilt while dragged
//!   ([`InteractionTargets`] on their scale, colour and rotation springs: every state change is
//!   a retarget, so the motion bends instead of restarting). Drag one and let go while moving:
//!   [`SpringDrag`] flings it with the pointer's velocity to the slot nearest to where the throw
//!   would come to rest, or home when no slot is within reach ([`DragReleased`] reports it).
//! - **The character** hops from spot to spot: its [`TranslationSpring`] is retargeted up and
//!   then down, [`SquashStretch`] stretches it along its velocity (keeping its area) and
//!   squashes it on landing.
//! - **The camera** follows the character sideways ([`SpringFollow`]) and shakes on Space
//!   ([`Shake`]: seeded noise through a spring, scaled by a decaying trauma, added on top of the
//!   follow). P punches every card ([`PropertySpring::punch`]): a pop of exactly 25 %.
//!
//! Without mouse input the example plays a short scripted tour, so CI screenshots show it: a
//! synthetic pointer goes through `bevy_picking`'s real pipeline (`PointerInput` messages), hovers
//! a card, presses it and flings it into a slot, clicks and drags another one that goes home;
//! then the camera shakes and the cards are punched.
//!
//! ```text
//! cargo run --example juice
//! ```

use bevy::asset::RenderAssetUsages;
use bevy::picking::events::{Pointer, Press};
use bevy::picking::pointer::PointerButton;
use bevy::prelude::*;
use bevy::render::render_resource::{Extent3d, TextureDimension, TextureFormat};
use bevy::sprite::Anchor;
use bevy_sprung::color::SpriteColor;
use bevy_sprung::color::SpriteColorSpring;
use bevy_sprung::interaction::{DragReleased, Snap};
use bevy_sprung::juice::Conserve;
use bevy_sprung::juice::JuiceSystems;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::{SpringMotion, SpringSystems};

#[path = "support/pointer.rs"]
mod pointer;
#[path = "support/tour.rs"]
mod tour;

use pointer::{Ease, Goal, TourPointerPlugin, Waypoint};
use tour::{Tour, TourPlugin};

/// The cards' colours.
const CARD_COLORS: [Color; 5] = [
    Color::srgb(0.93, 0.45, 0.40),
    Color::srgb(0.96, 0.72, 0.30),
    Color::srgb(0.42, 0.78, 0.52),
    Color::srgb(0.38, 0.60, 0.95),
    Color::srgb(0.70, 0.50, 0.92),
];
const CARD_SIZE: Vec2 = Vec2::new(90.0, 130.0);
/// The row the cards rest in, and the row of slots above it.
const CARD_Y: f32 = -20.0;
const SLOT_Y: f32 = 170.0;
const SLOT_COUNT: usize = 4;
/// A throw snaps to a slot only if it would come to rest this close to it.
const SNAP_RADIUS: f32 = 110.0;
/// Seconds of the release velocity that a throw carries the card on ([`SpringDrag::throw`]).
const THROW: f32 = 0.3;
/// Pressed and dragged cards are raised above the others, the latest on top.
const RAISED_Z: f32 = 10.0;

/// The floor the character hops on (world y of its feet) and where it hops to, in turn.
const FLOOR: f32 = -270.0;
const HOP_XS: [f32; 4] = [-110.0, 0.0, 110.0, 0.0];
/// A hop: a retarget up for `HOP_RISE` s, then down past the floor, every `HOP_PERIOD` s.
const HOP_PERIOD: f32 = 1.2;
const HOP_RISE: f32 = 0.35;
const HOP_APEX: f32 = 140.0;
const HOP_DROP: f32 = 150.0;
const CHARACTER_Z: f32 = 3.0;

/// The tour's synthetic pointer: how long the tour runs, and the times of its shake and punch.
const TOUR_END: f32 = 6.0;
const TOUR_SHAKE: f32 = 3.6;
const TOUR_PUNCH: f32 = 4.5;
/// How long the tour's fling drags the card before letting go.
const FLING_DRAG: f32 = 0.45;

/// A card, numbered from 1.
#[derive(Component)]
struct Card {
    number: usize,
}

/// A card's shadow: a child of the card.
#[derive(Component)]
struct CardShadow;

/// The hopping character.
#[derive(Component)]
struct Character;

/// What the camera follows: the character's horizontal position, on the floor's level (so the
/// camera follows the hops sideways without bobbing up and down).
#[derive(Component)]
struct CameraAnchor;

/// The line that reports the last event.
#[derive(Component)]
struct Status;

/// What the status line says.
#[derive(Resource)]
struct LastEvent(String);

impl Default for LastEvent {
    fn default() -> Self {
        Self("cards dealt".into())
    }
}

/// Where the character is in its hop.
#[derive(Clone, Copy, PartialEq, Eq)]
enum HopPhase {
    /// On the floor, waiting for the next take-off.
    Grounded,
    /// Aimed above the floor.
    Rising,
    /// Aimed below the floor, until it lands.
    Falling,
}

/// The character's hops: seconds since the last take-off, which spot it hops to, and where it
/// is in the hop.
#[derive(Resource)]
struct Hop {
    clock: f32,
    count: usize,
    x: f32,
    phase: HopPhase,
}

/// The order in which cards are raised: each press puts its card above every other.
#[derive(Resource, Default)]
struct Layers(u16);

fn main() {
    App::new()
        .add_plugins((
            // With the `bevy_picking` and `sprite_picking` features, `DefaultPlugins` include
            // picking, its mouse input and the sprite backend (sprites need `Pickable`).
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: juice".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            SpringPlugins::default(),
        ))
        .insert_resource(ClearColor(Color::srgb(0.08, 0.09, 0.12)))
        .init_resource::<LastEvent>()
        .init_resource::<Layers>()
        .insert_resource(Hop {
            clock: HOP_PERIOD - 0.5,
            count: 0,
            x: 0.0,
            phase: HopPhase::Grounded,
        })
        .add_plugins((
            TourPlugin::ends_after(TOUR_END),
            TourPointerPlugin::new(tour_path()),
        ))
        .add_systems(Startup, setup)
        .add_systems(
            Update,
            (
                shake_and_punch,
                react_to_card_states,
                hop,
                track_character,
                show_status,
            )
                .chain(),
        )
        // Landing is checked right after the springs moved the character, before its squash
        // is written: it never shows below the floor.
        .add_systems(PostUpdate, land.after(SpringSystems).before(JuiceSystems))
        .add_observer(raise_pressed_card)
        .add_observer(report_release)
        .run();
}

/// A white rounded square of `size` pixels with corners of `radius`, antialiased, for sprites
/// to tint (kept in the main world too: sprite picking reads its alpha).
fn rounded_square(size: u32, radius: f32) -> Image {
    let half = size as f32 / 2.0;
    let mut data = Vec::with_capacity((size * size * 4) as usize);
    for y in 0..size {
        for x in 0..size {
            let p = (Vec2::new(x as f32, y as f32) + 0.5 - half).abs();
            let distance = (p - (half - radius)).max(Vec2::ZERO).length() - radius;
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "a coverage in [0, 1] as a byte"
            )]
            let alpha = ((0.5 - distance).clamp(0.0, 1.0) * 255.0).round() as u8;
            data.extend_from_slice(&[255, 255, 255, alpha]);
        }
    }
    Image::new(
        Extent3d {
            width: size,
            height: size,
            depth_or_array_layers: 1,
        },
        TextureDimension::D2,
        data,
        TextureFormat::Rgba8UnormSrgb,
        RenderAssetUsages::default(),
    )
}

/// A sprite of `size` from the rounded square, its corners kept round at any size (9-slice).
fn tile(image: &Handle<Image>, color: Color, size: Vec2) -> Sprite {
    Sprite {
        image: image.clone(),
        color,
        custom_size: Some(size),
        image_mode: SpriteImageMode::Sliced(TextureSlicer {
            border: BorderRect::all(24.0),
            ..default()
        }),
        ..default()
    }
}

/// Where card `index` (from 0) rests.
fn card_home(index: usize) -> Vec3 {
    Vec3::new(
        -300.0 + 150.0 * index as f32,
        CARD_Y,
        1.0 + 0.01 * index as f32,
    )
}

/// Where slot `index` (from 0) is.
fn slot(index: usize) -> Vec2 {
    Vec2::new(-270.0 + 180.0 * index as f32, SLOT_Y)
}

/// The camera, the board, the character and the text.
fn setup(mut commands: Commands, mut images: ResMut<Assets<Image>>) {
    let rounded = images.add(rounded_square(64, 18.0));

    // The camera follows an anchor that `track_character` keeps under the character.
    let anchor = commands.spawn((CameraAnchor, Transform::default())).id();
    commands.spawn((
        Camera2d,
        Transform::default(),
        TranslationSpring::new(Spring::smooth(), Vec3::ZERO),
        SpringFollow::new(anchor, Vec3::ZERO),
        Shake::new(7)
            .with_max_translation(Vec3::new(14.0, 14.0, 0.0))
            .with_max_rotation(Vec3::new(0.0, 0.0, 0.04)),
    ));

    spawn_board(&mut commands, &rounded);
    spawn_character(&mut commands, &rounded);
    spawn_text(&mut commands);
}

/// The slots and the cards: each card springs its position (dragged and flung), scale (lift,
/// squash, punch), colour (glow) and rotation (tilt), with a target per interaction state.
fn spawn_board(commands: &mut Commands, rounded: &Handle<Image>) {
    let slots: Vec<Vec3> = (0..SLOT_COUNT).map(|i| slot(i).extend(0.0)).collect();
    for position in &slots {
        commands.spawn((
            tile(rounded, Color::srgb(0.30, 0.33, 0.42), CARD_SIZE + 14.0),
            Transform::from_translation(*position),
            children![(
                tile(rounded, Color::srgb(0.05, 0.055, 0.075), CARD_SIZE + 8.0),
                Transform::from_xyz(0.0, 0.0, 0.1),
            )],
        ));
    }
    for (index, color) in CARD_COLORS.into_iter().enumerate() {
        let home = card_home(index);
        let glow = color.mix(&Color::WHITE, 0.3);
        commands.spawn((
            Card { number: index + 1 },
            tile(rounded, color, CARD_SIZE),
            // Sprites are picked only with `Pickable`.
            Pickable::default(),
            // Dealt small: the scale spring pops the cards in.
            Transform::from_translation(home).with_scale(Vec3::splat(0.3)),
            TranslationSpring::new(Spring::bouncy(), home),
            SpringDrag::new()
                .snapping(Snap::Points(slots.clone()))
                .within(SNAP_RADIUS)
                .with_throw(THROW)
                // A press that wobbles a few pixels is still a click.
                .with_threshold(4.0),
            ScaleSpring::new(Spring::bouncy(), Vec3::ONE),
            InteractionTargets::<Scale>::new(Vec3::ONE)
                .hovered(Vec3::splat(1.08))
                .pressed(Vec3::splat(0.9))
                .dragged(Vec3::splat(1.14)),
            SpriteColorSpring::new(Spring::smooth(), color),
            InteractionTargets::<SpriteColor>::new(color)
                .hovered(glow)
                .pressed(color.mix(&Color::WHITE, 0.12))
                .dragged(glow),
            RotationSpring::new(Spring::bouncy(), Quat::IDENTITY),
            InteractionTargets::<Rotation>::new(Quat::IDENTITY)
                .dragged(Quat::from_rotation_z(-0.07)),
            children![
                (
                    Text2d::new((index + 1).to_string()),
                    TextFont::from_font_size(46.0),
                    TextColor(Color::srgba(0.0, 0.0, 0.0, 0.38)),
                    Transform::from_xyz(0.0, 0.0, 0.001),
                ),
                // A shadow, under every card (and raised with its own), that falls farther
                // the higher the card is lifted.
                (
                    CardShadow,
                    tile(rounded, Color::srgba(0.0, 0.0, 0.0, 0.35), CARD_SIZE),
                    Transform::from_translation(shadow_offset(InteractionState::Idle)),
                    TranslationSpring::new(
                        Spring::snappy(),
                        shadow_offset(InteractionState::Idle),
                    ),
                ),
            ],
        ));
    }
}

/// The floor, with marks that show the camera moving, and the character on it: a rounded
/// square with eyes, anchored at its feet so that it squashes onto the floor.
fn spawn_character(commands: &mut Commands, rounded: &Handle<Image>) {
    commands.spawn((
        Sprite::from_color(Color::srgb(0.11, 0.12, 0.16), Vec2::new(4000.0, 200.0)),
        Transform::from_xyz(0.0, FLOOR - 100.0, 0.0),
    ));
    commands.spawn((
        Sprite::from_color(Color::srgb(0.30, 0.33, 0.42), Vec2::new(4000.0, 6.0)),
        Transform::from_xyz(0.0, FLOOR - 3.0, 0.1),
    ));
    for mark in -25..=25 {
        commands.spawn((
            Sprite::from_color(Color::srgb(0.20, 0.22, 0.28), Vec2::new(4.0, 14.0)),
            Transform::from_xyz(80.0 * mark as f32, FLOOR - 18.0, 0.1),
        ));
    }
    let feet = Vec3::new(0.0, FLOOR, CHARACTER_Z);
    let hop = Spring::from_natural_frequency(8.0, 1.0).expect("a valid spring");
    let eye = Color::srgb(0.1, 0.1, 0.14);
    commands.spawn((
        Character,
        Sprite {
            image: rounded.clone(),
            color: Color::srgb(1.0, 0.82, 0.3),
            custom_size: Some(Vec2::splat(64.0)),
            ..default()
        },
        Anchor::BOTTOM_CENTER,
        Transform::from_translation(feet),
        TranslationSpring::new(hop, feet),
        // Stretched by 0.06 % per px/s, at most 1.4×, keeping its area; no `ScaleSpring`
        // beside it, since the squash writes the scale.
        SquashStretch::new(0.0006, 1.4).conserving(Conserve::Area),
        children![
            (
                Sprite::from_color(eye, Vec2::new(8.0, 14.0)),
                Transform::from_xyz(-12.0, 40.0, 0.1),
            ),
            (
                Sprite::from_color(eye, Vec2::new(8.0, 14.0)),
                Transform::from_xyz(12.0, 40.0, 0.1),
            ),
        ],
    ));
}

/// The help line and the status line, top left.
fn spawn_text(commands: &mut Commands) {
    commands.spawn((
        Node {
            position_type: PositionType::Absolute,
            left: Val::Px(24.0),
            top: Val::Px(18.0),
            flex_direction: FlexDirection::Column,
            row_gap: Val::Px(6.0),
            ..default()
        },
        children![
            (
                Text::new("drag the cards onto the slots  |  Space: shake  |  P: punch"),
                TextFont::from_font_size(20.0),
                TextColor(Color::srgb(0.86, 0.88, 0.93)),
            ),
            (
                Status,
                Text::default(),
                TextFont::from_font_size(16.0),
                TextColor(Color::srgb(0.85, 0.75, 0.5)),
            ),
        ],
    ));
}

/// The tour's pointer path.
fn tour_path() -> Vec<Waypoint> {
    let at = Waypoint::new;
    let stay = Waypoint::stay;
    let on_card = |index| Goal::To(card_home(index).truncate() - Vec2::Y * 15.0);
    // Drag so that the throw carries on to slot 3: the card comes to rest `THROW` s of its
    // release velocity further on, i.e. `1 + THROW / FLING_DRAG` times the drag.
    let drag = (slot(2) - card_home(1).truncate()) / (1.0 + THROW / FLING_DRAG);
    vec![
        at(0.0, Goal::To(Vec2::new(-520.0, 60.0)), Ease::Linear, false),
        stay(0.35, false),
        // Hover card 2, press it, and fling it toward slot 3.
        at(0.8, on_card(1), Ease::InOut, false),
        stay(1.05, true),
        stay(1.35, true),
        at(1.35 + FLING_DRAG, Goal::By(drag), Ease::Linear, false),
        // The hand follows through at the release speed, slowing down.
        at(
            1.92,
            Goal::By(drag * (0.12 / FLING_DRAG) * 0.5),
            Ease::Out,
            false,
        ),
        // Hover card 4 and click it; then drag it a little, stop, and let go: it goes home.
        at(2.4, on_card(3), Ease::InOut, false),
        stay(2.55, true),
        stay(2.8, false),
        stay(2.9, true),
        stay(3.0, true),
        at(3.25, Goal::By(Vec2::new(50.0, 70.0)), Ease::InOut, true),
        stay(3.42, false),
        // Rest on card 5.
        at(4.2, on_card(4), Ease::InOut, false),
    ]
}

/// A pressed card is raised above the others (its position spring keeps the new depth), before
/// a drag starts from it.
fn raise_pressed_card(
    press: On<Pointer<Press>>,
    mut cards: Query<(&mut Transform, &mut TranslationSpring), With<Card>>,
    mut layers: ResMut<Layers>,
) {
    if press.button != PointerButton::Primary {
        return;
    }
    let Ok((mut transform, mut spring)) = cards.get_mut(press.entity) else {
        return;
    };
    layers.0 = layers.0.wrapping_add(1);
    let z = RAISED_Z + 0.01 * f32::from(layers.0 % 1000);
    transform.translation.z = z;
    let target = spring.target();
    spring.set_target(target.with_z(z));
}

/// A card was let go: it springs to the slot its throw chose, or home, staying on its layer.
fn report_release(
    released: On<DragReleased>,
    time: Res<Time>,
    mut cards: Query<(&Card, &Transform, &mut TranslationSpring)>,
    mut note: ResMut<LastEvent>,
) {
    let Ok((card, transform, mut spring)) = cards.get_mut(released.entity) else {
        return;
    };
    spring.set_target(released.target.with_z(transform.translation.z));
    // Rounded, and without the sign of a zero.
    let velocity = released.velocity.round() + Vec3::ZERO;
    let destination = match released.snapped {
        Some(index) => format!("slot {}", index + 1),
        None => "home".into(),
    };
    note.0 = format!(
        "card {} flung at ({}, {}) px/s -> {destination}",
        card.number, velocity.x, velocity.y
    );
    info!(
        "{:.2} s: {} (projected ({:.0}, {:.0}), snapped: {:?})",
        time.elapsed_secs(),
        note.0,
        released.projected.x,
        released.projected.y,
        released.snapped
    );
}

/// Space shakes the camera, P punches the cards; the tour does both once.
fn shake_and_punch(
    time: Res<Time>,
    keys: Res<ButtonInput<KeyCode>>,
    tour: Res<Tour>,
    mut shake: Single<&mut Shake>,
    mut cards: Query<&mut ScaleSpring, With<Card>>,
    mut note: ResMut<LastEvent>,
) {
    if keys.just_pressed(KeyCode::Space) || tour.passed(TOUR_SHAKE) {
        shake.add_trauma(0.7);
        note.0 = format!("shake: trauma {:.2}", shake.trauma);
        info!("{:.2} s: {}", time.elapsed_secs(), note.0);
    }
    if keys.just_pressed(KeyCode::KeyP) || tour.passed(TOUR_PUNCH) {
        for mut scale in &mut cards {
            scale.punch(Vec3::splat(0.25));
        }
        note.0 = "punch: every card pops by 25 %".into();
        info!("{:.2} s: {}", time.elapsed_secs(), note.0);
    }
}

/// Where a card's shadow falls, relative to the card, in each interaction state: the higher
/// the card is lifted, the farther (a pressed card is pushed onto the table).
fn shadow_offset(state: InteractionState) -> Vec3 {
    let offset = match state {
        InteractionState::Hovered => Vec2::new(10.0, -14.0),
        InteractionState::Pressed => Vec2::new(3.0, -4.0),
        InteractionState::Dragged => Vec2::new(18.0, -26.0),
        _ => Vec2::new(6.0, -8.0),
    };
    offset.extend(-0.5)
}

/// Moves the cards' shadows as their interaction states change, and logs the changes.
fn react_to_card_states(
    time: Res<Time>,
    cards: Query<(&Card, &InteractionState, &Children), Changed<InteractionState>>,
    mut shadows: Query<&mut TranslationSpring, With<CardShadow>>,
) {
    for (card, state, children) in &cards {
        let mut shadows = shadows.iter_many_mut(children);
        while let Some(mut shadow) = shadows.fetch_next() {
            shadow.set_target(shadow_offset(*state));
        }
        let what = match state {
            InteractionState::Hovered => "hovered: lift and glow",
            InteractionState::Pressed => "pressed: squash",
            InteractionState::Dragged => "dragged: lifted and tilted",
            _ => continue,
        };
        info!("{:.2} s: card {} {what}", time.elapsed_secs(), card.number);
    }
}

/// Every [`HOP_PERIOD`] s the character takes off toward its next spot: its spring is aimed
/// above it, then, after [`HOP_RISE`] s, below the floor, so it falls faster and faster until
/// [`land`] stops it.
fn hop(
    time: Res<Time>,
    mut hop: ResMut<Hop>,
    mut character: Single<&mut TranslationSpring, With<Character>>,
) {
    hop.clock += time.delta_secs();
    match hop.phase {
        HopPhase::Grounded if hop.clock >= HOP_PERIOD => {
            hop.clock = 0.0;
            hop.count += 1;
            hop.x = HOP_XS[hop.count % HOP_XS.len()];
            hop.phase = HopPhase::Rising;
            character.set_target(Vec3::new(hop.x, FLOOR + HOP_APEX, CHARACTER_Z));
        }
        HopPhase::Rising if hop.clock >= HOP_RISE => {
            hop.phase = HopPhase::Falling;
            character.set_target(Vec3::new(hop.x, FLOOR - HOP_DROP, CHARACTER_Z));
        }
        _ => {}
    }
}

/// Right after the springs moved it: a falling character that reached the floor stops on it,
/// keeps its sideways motion, and squashes.
fn land(
    time: Res<Time>,
    mut hop: ResMut<Hop>,
    character: Single<
        (
            &mut Transform,
            &mut TranslationSpring,
            &SpringMotion<Translation>,
            &mut SquashStretch,
        ),
        With<Character>,
    >,
) {
    let (mut transform, mut spring, motion, mut squash) = character.into_inner();
    if hop.phase != HopPhase::Falling || transform.translation.y > FLOOR {
        return;
    }
    hop.phase = HopPhase::Grounded;
    let velocity = motion.velocity();
    transform.translation.y = FLOOR;
    spring.set_target(Vec3::new(hop.x, FLOOR, CHARACTER_Z));
    spring.set_velocity(Vec3::new(velocity.x, 0.0, 0.0));
    squash.impact(Vec3::Y, 0.7);
    info!(
        "{:.2} s: character landed at x = {:.0}, falling at {:.0} px/s: squash",
        time.elapsed_secs(),
        transform.translation.x,
        -velocity.y
    );
}

/// Keeps the camera's anchor under the character, on the floor's level.
fn track_character(
    character: Single<&Transform, With<Character>>,
    mut anchor: Single<&mut Transform, (With<CameraAnchor>, Without<Character>)>,
) {
    anchor.translation.x = character.translation.x;
}

/// Shows the last event, and whether the tour is running.
fn show_status(
    note: Res<LastEvent>,
    tour: Res<Tour>,
    mut status: Single<&mut Text, With<Status>>,
    mut shown_running: Local<Option<bool>>,
) {
    if !note.is_changed() && *shown_running == Some(tour.is_running()) {
        return;
    }
    *shown_running = Some(tour.is_running());
    let who = if tour.is_running() {
        "  |  scripted tour"
    } else {
        ""
    };
    status.0 = format!("last: {}{who}", note.0);
}
