//! A 2D platformer camera: a [`CameraRig`] that follows the player with a dead zone, a little
//! look-ahead, the player on the lower third, a slower vertical follow that waits while the
//! player is in the air, and level bounds it never shows past; G frames both players as a group.
//!
//! - **Dead zone** (the box): the player moves inside it and the camera does not move at all;
//!   outside, a spring pulls the camera after it.
//! - **Look-ahead**: the camera leads the player by 0.7 s of its run, smoothed by its own spring,
//!   so turning round swings the view over instead of snapping it.
//! - **Confiner**: the level's edges (the dark outside never shows) slow the camera to a stop
//!   within 120 px, as a spring comes to rest, never with a jerk.
//! - **Group framing** (G): both players stay in view with a margin; the zoom springs to fit.
//!
//! The camera's guides are the debug overlay's ([`SpringDebugPlugin`]): the dead zone (green,
//! orange while the player pushes it), the framed point and the look-ahead ahead of it, the
//! view the camera heads for, and the level's bounds with the band where the camera slows. D
//! hides or shows them.
//!
//! Arrow keys run, Space jumps. Without input the example plays a scripted run: right with
//! jumps, back, then group framing.
//!
//! ```text
//! cargo run --example platformer
//! ```

use bevy::prelude::*;
use bevy_sprung::camera::{
    CameraTargets, Confiner, DeadZone, GroupFraming, LookAhead, ScreenPosition,
};
use bevy_sprung::debug::SpringDebugPlugin;
use bevy_sprung::prelude::*;

/// The level: the camera's view stays inside it.
const LEVEL: Rect = Rect {
    min: Vec2::new(-1400.0, -400.0),
    max: Vec2::new(2600.0, 1600.0),
};
/// Ground height and the platforms (centre, width) the player can land on.
const GROUND: f32 = 0.0;
const PLATFORMS: [(Vec2, f32); 4] = [
    (Vec2::new(300.0, 170.0), 260.0),
    (Vec2::new(800.0, 330.0), 220.0),
    (Vec2::new(1400.0, 200.0), 300.0),
    (Vec2::new(-700.0, 220.0), 260.0),
];
const RUN: f32 = 420.0;
const JUMP: f32 = 820.0;
const GRAVITY: f32 = 2200.0;
const SIZE: f32 = 48.0;
/// Where the player sits on screen (lower third) and the dead zone around it (view fractions).
const SCREEN: Vec2 = Vec2::new(0.0, -1.0 / 6.0);
const DEAD_ZONE: Vec2 = Vec2::new(0.12, 0.2);

#[derive(Component, Default)]
struct Player {
    velocity: Vec2,
    grounded: bool,
}

/// The second player, who wanders on its own.
#[derive(Component)]
struct Friend;

#[derive(Component)]
struct Hud;

/// Whether a key has been pressed: until then the script plays.
#[derive(Resource, Default)]
struct Manual(bool);

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: platformer camera".into(),
                    resolution: (1280, 720).into(),
                    ..default()
                }),
                ..default()
            }),
            SpringPlugins::default(),
            SpringDebugPlugin::default().toggled_by(KeyCode::KeyD),
        ))
        .insert_resource(ClearColor(Color::srgb(0.08, 0.08, 0.12)))
        .init_resource::<Manual>()
        .add_systems(Startup, setup)
        .add_systems(
            Update,
            (run, wander, toggle_group.run_if(group_toggled), hud),
        )
        .run();
}

fn setup(mut commands: Commands) {
    // The level's sky, ground, columns every 200 px (to see the camera move) and platforms.
    let sky = Sprite::from_color(Color::srgb(0.62, 0.78, 0.92), LEVEL.size());
    commands.spawn((
        sky,
        Transform::from_translation(LEVEL.center().extend(-10.0)),
    ));
    // The ground fills the level from its floor up to `GROUND`.
    let depth = GROUND - LEVEL.min.y;
    let ground = Sprite::from_color(
        Color::srgb(0.36, 0.52, 0.3),
        Vec2::new(LEVEL.width(), depth),
    );
    let ground_centre = Vec3::new(LEVEL.center().x, GROUND - depth / 2.0, -5.0);
    commands.spawn((ground, Transform::from_translation(ground_centre)));
    for i in 0..20 {
        let x = LEVEL.min.x + 100.0 + 200.0 * i as f32;
        let shade = if i % 2 == 0 { 0.7 } else { 0.76 };
        let column = Sprite::from_color(
            Color::srgb(shade, shade + 0.08, shade + 0.14),
            Vec2::new(60.0, 1200.0),
        );
        commands.spawn((column, Transform::from_xyz(x, 400.0, -8.0)));
    }
    for (centre, width) in PLATFORMS {
        let platform = Sprite::from_color(Color::srgb(0.5, 0.36, 0.24), Vec2::new(width, 24.0));
        commands.spawn((
            platform,
            Transform::from_translation((centre - Vec2::Y * 12.0).extend(-4.0)),
        ));
    }
    let player = commands
        .spawn((
            Player::default(),
            Sprite::from_color(Color::srgb(0.9, 0.35, 0.25), Vec2::splat(SIZE)),
            Transform::from_xyz(-200.0, GROUND + SIZE / 2.0, 1.0),
        ))
        .id();
    commands.spawn((
        Friend,
        Sprite::from_color(Color::srgb(0.3, 0.4, 0.9), Vec2::splat(SIZE)),
        Transform::from_xyz(-600.0, GROUND + SIZE / 2.0, 1.0),
    ));
    commands.spawn((
        Camera2d,
        CameraRig::new(Spring::smooth()).with_vertical(Spring::gentle()),
        CameraTargets::single(player),
        ScreenPosition(SCREEN),
        DeadZone::view(DEAD_ZONE),
        LookAhead::new(0.7),
        Confiner::new(LEVEL).with_slowing_distance(120.0),
    ));
    commands.spawn((
        Hud,
        Text::new(""),
        TextFont::from_font_size(18.0),
        TextColor(Color::srgb(0.05, 0.07, 0.12)),
        Node {
            position_type: PositionType::Absolute,
            top: Val::Px(12.0),
            left: Val::Px(14.0),
            ..default()
        },
    ));
}

/// The scripted run: which way to go and whether to jump, at time `t`.
fn script(t: f32) -> (f32, bool) {
    let run = if t < 3.5 {
        1.0
    } else if t < 5.5 {
        -1.0
    } else {
        0.0
    };
    let jump = t % 1.3 < 0.05 && t > 0.5;
    (run, jump)
}

/// Gameplay: run and jump with gravity, landing on the ground and platforms; the camera holds
/// its height while the player is in the air.
fn run(
    time: Res<Time>,
    keys: Res<ButtonInput<KeyCode>>,
    mut manual: ResMut<Manual>,
    mut player: Single<(&mut Player, &mut Transform)>,
    mut rig: Single<&mut CameraRig>,
) {
    manual.0 |= keys.get_just_pressed().next().is_some();
    let (direction, jump) = if manual.0 {
        let key = |code: KeyCode| if keys.pressed(code) { 1.0 } else { 0.0 };
        let direction = key(KeyCode::ArrowRight) - key(KeyCode::ArrowLeft);
        (direction, keys.just_pressed(KeyCode::Space))
    } else {
        script(time.elapsed_secs())
    };
    let (player, transform) = &mut *player;
    let dt = time.delta_secs();
    player.velocity.x = direction * RUN;
    if jump && player.grounded {
        player.velocity.y = JUMP;
    }
    player.velocity.y -= GRAVITY * dt;
    let before = transform.translation.y - SIZE / 2.0;
    transform.translation += (player.velocity * dt).extend(0.0);
    let half_width = SIZE / 2.0;
    transform.translation.x = transform
        .translation
        .x
        .clamp(LEVEL.min.x + half_width, LEVEL.max.x - half_width);
    // Land on whatever surface the feet crossed going down.
    let feet = transform.translation.y - SIZE / 2.0;
    let x = transform.translation.x;
    let surfaces = PLATFORMS
        .iter()
        .filter(|(centre, width)| (x - centre.x).abs() < width / 2.0 + half_width)
        .map(|(centre, _)| centre.y)
        .chain([GROUND]);
    let landing = surfaces
        .filter(|&y| before >= y && feet <= y)
        .fold(None, |best: Option<f32>, y| {
            Some(best.map_or(y, |b| b.max(y)))
        });
    player.grounded = false;
    if let Some(y) = landing.filter(|_| player.velocity.y <= 0.0) {
        transform.translation.y = y + SIZE / 2.0;
        player.velocity.y = 0.0;
        player.grounded = true;
    }
    // Vertical follow waits for the landing (set only when it changes: the rig stays asleep).
    let airborne = !player.grounded;
    if rig.hold_vertical != airborne {
        rig.hold_vertical = airborne;
    }
}

/// The friend strolls to and fro near the level's start.
fn wander(time: Res<Time>, mut friend: Single<&mut Transform, With<Friend>>) {
    friend.translation.x = -600.0 + 300.0 * (time.elapsed_secs() * 0.6).sin();
}

/// Whether to switch group framing this frame: G, or the script after 6 s.
fn group_toggled(
    time: Res<Time>,
    keys: Res<ButtonInput<KeyCode>>,
    manual: Res<Manual>,
    grouped: Single<Has<GroupFraming>, With<CameraRig>>,
) -> bool {
    keys.just_pressed(KeyCode::KeyG) || (!manual.0 && !*grouped && time.elapsed_secs() > 6.0)
}

/// Frames both players as a group, zooming to fit them, or the player alone again.
fn toggle_group(
    mut commands: Commands,
    camera: Single<(Entity, Has<GroupFraming>), With<CameraRig>>,
    player: Single<Entity, With<Player>>,
    friend: Single<Entity, With<Friend>>,
) {
    let (camera, grouped) = *camera;
    if grouped {
        commands
            .entity(camera)
            .remove::<GroupFraming>()
            .insert(CameraTargets::single(*player));
        commands.entity(camera).insert((
            DeadZone::view(DEAD_ZONE),
            ScreenPosition(SCREEN),
            LookAhead::new(0.7),
        ));
    } else {
        // The group is framed around its centre: no dead zone or lower-third offset.
        commands
            .entity(camera)
            .remove::<(DeadZone, ScreenPosition, LookAhead)>()
            .insert((
                CameraTargets::new(
                    [*player, *friend].map(|e| CameraTarget::new(e).with_radius(60.0)),
                ),
                GroupFraming::new(0.12).with_zoom_range(1.0, 2.0),
            ));
    }
}

fn hud(
    mut text: Single<&mut Text, With<Hud>>,
    camera: Single<(
        &CameraRig,
        Has<GroupFraming>,
        &bevy_sprung::camera::RigMotion,
    )>,
    manual: Res<Manual>,
) {
    let (rig, grouped, motion) = *camera;
    text.0 = format!(
        "{}\nG: group framing ({})   D: camera guides\nlook-ahead {:+.0} px   zoom {:.2}   vertical follow {}",
        if manual.0 {
            "Arrows run, Space jumps"
        } else {
            "scripted run (press a key to play)"
        },
        if grouped { "on" } else { "off" },
        motion.look_ahead().x,
        motion.zoom(),
        if rig.hold_vertical {
            "held (in the air)"
        } else {
            "on"
        },
    );
}
