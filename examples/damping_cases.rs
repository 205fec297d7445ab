//! The six damping cases side by side: critical, unimpeded (free), under-damped, undamped,
//! over-damped and unsprung.
//!
//! Each row releases a body one unit left of its target, moving right at 1.5 units/s, and
//! draws its exact trajectory x(t) over a 4-second cycle. Select a row with ↑/↓ and change its
//! mass (Q/A), damping (W/S) and stiffness (E/D) live: the row's damping ratio ζ and its regime
//! update as you go, and the motion stays exact whatever the frame rate. Space restarts.
//!
//! ```text
//! cargo run --example damping_cases
//! ```

use bevy::prelude::*;
use bevy_sprung::prelude::*;
use bevy_sprung::spring::SpringSystems;
use sprung::Regime;

/// Pixels per unit of displacement.
const UNIT: f32 = 90.0;
/// Seconds per cycle: each row restarts from its initial state this often.
const CYCLE: f32 = 4.0;
/// Where each body starts relative to its target, and how fast.
const START_OFFSET: f32 = -1.0;
const START_SPEED: f32 = 1.5;
/// Layout.
const ROW_HEIGHT: f32 = 110.0;
const RAIL_CENTER_X: f32 = -330.0;
const PLOT_LEFT_X: f32 = -120.0;
const PLOT_WIDTH: f32 = 720.0;

/// One row of the demo.
#[derive(Component)]
struct Row {
    index: usize,
    name: &'static str,
    /// The trajectory of the current cycle, `(t, x)` in seconds and units.
    trace: Vec<Vec2>,
}

/// The row's label.
#[derive(Component)]
struct Label(usize);

/// Which row the keys change.
#[derive(Resource, Default)]
struct Selected(usize);

/// Time since the current cycle started.
#[derive(Resource, Default)]
struct Cycle(f32);

fn main() {
    App::new()
        .add_plugins((
            DefaultPlugins.set(WindowPlugin {
                primary_window: Some(Window {
                    title: "sprung: the six damping cases".into(),
                    resolution: (1280, 760).into(),
                    ..default()
                }),
                ..default()
            }),
            SpringPlugins::default(),
        ))
        .init_resource::<Selected>()
        .init_resource::<Cycle>()
        .insert_resource(ClearColor(Color::srgb(0.06, 0.07, 0.09)))
        .add_systems(Startup, setup)
        .add_systems(Update, (controls, restart_cycle, label_rows).chain())
        // Trace after the springs moved the bodies this frame.
        .add_systems(
            PostUpdate,
            (record_traces, draw_traces).chain().after(SpringSystems),
        )
        .run();
}

/// `(name, mass, damping, stiffness)`: ω = 2π rad/s where there is a spring.
fn cases() -> [(&'static str, f32, f32, f32); 6] {
    let k = 4.0 * std::f32::consts::PI * std::f32::consts::PI;
    let critical = 2.0 * k.sqrt();
    [
        ("critical", 1.0, critical, k),
        ("unimpeded", 1.0, 0.0, 0.0),
        ("under-damped", 1.0, 0.25 * critical, k),
        ("undamped", 1.0, 0.0, k),
        ("over-damped", 1.0, 4.0 * critical, k),
        ("unsprung", 1.0, 1.2, 0.0),
    ]
}

fn row_y(index: usize) -> f32 {
    ROW_HEIGHT * (2.5 - index as f32) - 20.0
}

fn setup(mut commands: Commands) {
    commands.spawn(Camera2d);
    let palette = [
        Color::srgb(0.95, 0.55, 0.2),
        Color::srgb(0.6, 0.8, 0.95),
        Color::srgb(0.45, 0.85, 0.5),
        Color::srgb(0.9, 0.35, 0.5),
        Color::srgb(0.7, 0.55, 0.95),
        Color::srgb(0.95, 0.85, 0.35),
    ];
    for (index, (name, m, c, k)) in cases().into_iter().enumerate() {
        let y = row_y(index);
        let target = Vec3::new(RAIL_CENTER_X, y, 1.0);
        let spring = Spring::new(m, k, c).expect("valid demo spring");
        // Rail and target mark.
        commands.spawn((
            Sprite::from_color(
                Color::srgba(1.0, 1.0, 1.0, 0.08),
                Vec2::new(4.6 * UNIT, 2.0),
            ),
            Transform::from_xyz(RAIL_CENTER_X + 1.3 * UNIT, y, 0.0),
        ));
        commands.spawn((
            Sprite::from_color(Color::srgba(1.0, 1.0, 1.0, 0.35), Vec2::new(2.0, 40.0)),
            Transform::from_xyz(RAIL_CENTER_X, y, 0.0),
        ));
        // Plot frame: the zero line of x(t).
        commands.spawn((
            Sprite::from_color(
                Color::srgba(1.0, 1.0, 1.0, 0.08),
                Vec2::new(PLOT_WIDTH, 1.0),
            ),
            Transform::from_xyz(PLOT_LEFT_X + PLOT_WIDTH / 2.0, y, 0.0),
        ));
        // The sprung body.
        commands.spawn((
            Row {
                index,
                name,
                trace: Vec::new(),
            },
            Sprite::from_color(palette[index], Vec2::splat(26.0)),
            Transform::from_translation(target + Vec3::X * START_OFFSET * UNIT),
            TranslationSpring::new(spring, target)
                .with_velocity(Vec3::X * START_SPEED * UNIT)
                // Nothing here should fall asleep mid-demo: a tight rest tolerance.
                .with_rest(RestThreshold::new(0.01, 0.01)),
        ));
        commands.spawn((
            Label(index),
            Text2d::new(""),
            TextFont::from_font_size(15.0),
            TextColor(palette[index]),
            bevy::sprite::Anchor::CENTER_LEFT,
            Transform::from_xyz(-620.0, y + 36.0, 1.0),
        ));
    }
    commands.spawn((
        Text::new(
            "Up/Down select a row   Q/A mass   W/S damping   E/D stiffness   Space restart\n\
             each row: released 1 unit left of its target at 1.5 units/s; right: x(t) over 4 s",
        ),
        TextFont::from_font_size(15.0),
        TextColor(Color::srgb(0.75, 0.78, 0.85)),
        Node {
            position_type: PositionType::Absolute,
            top: Val::Px(10.0),
            left: Val::Px(14.0),
            ..default()
        },
    ));
}

/// Keys change the selected row's spring; the motion carries on from where it is.
fn controls(
    keys: Res<ButtonInput<KeyCode>>,
    mut selected: ResMut<Selected>,
    mut cycle: ResMut<Cycle>,
    mut rows: Query<(&Row, &mut TranslationSpring)>,
) {
    if keys.just_pressed(KeyCode::ArrowUp) {
        selected.0 = (selected.0 + 5) % 6;
    }
    if keys.just_pressed(KeyCode::ArrowDown) {
        selected.0 = (selected.0 + 1) % 6;
    }
    if keys.just_pressed(KeyCode::Space) {
        cycle.0 = CYCLE;
    }
    let factor = |up: KeyCode, down: KeyCode| {
        if keys.just_pressed(up) {
            1.25
        } else if keys.just_pressed(down) {
            0.8
        } else {
            1.0
        }
    };
    let (fm, fc, fk) = (
        factor(KeyCode::KeyQ, KeyCode::KeyA),
        factor(KeyCode::KeyW, KeyCode::KeyS),
        factor(KeyCode::KeyE, KeyCode::KeyD),
    );
    if (fm, fc, fk) == (1.0, 1.0, 1.0) {
        return;
    }
    for (row, mut spring) in &mut rows {
        if row.index != selected.0 {
            continue;
        }
        let old = *spring.spring();
        // A zero damping or stiffness stays zero under scaling: nudge it into existence.
        let grow = |value: f32, factor: f32, seed: f32| {
            if value == 0.0 && factor > 1.0 {
                seed
            } else {
                value * factor
            }
        };
        if let Ok(new) = Spring::new(
            old.mass() * fm,
            grow(old.stiffness(), fk, 1.0),
            grow(old.damping(), fc, 0.2),
        ) {
            spring.set_spring(new);
        }
    }
}

/// Every cycle, release every body again from the same start.
fn restart_cycle(
    time: Res<Time>,
    mut cycle: ResMut<Cycle>,
    mut rows: Query<(&mut Row, &mut Transform, &mut TranslationSpring)>,
) {
    cycle.0 += time.delta_secs();
    if cycle.0 < CYCLE {
        return;
    }
    cycle.0 = 0.0;
    for (mut row, mut transform, mut spring) in &mut rows {
        transform.translation = spring.target() + Vec3::X * START_OFFSET * UNIT;
        spring.set_velocity(Vec3::X * START_SPEED * UNIT);
        row.trace.clear();
    }
}

fn label_rows(
    selected: Res<Selected>,
    rows: Query<(&Row, &TranslationSpring)>,
    mut labels: Query<(&Label, &mut Text2d)>,
) {
    for (row, spring) in &rows {
        let s = spring.spring();
        let zeta = match s.damping_ratio() {
            Some(zeta) => format!("{zeta:.2}"),
            None if s.damping() > 0.0 => "inf".into(),
            None => "undefined".into(),
        };
        let regime = match s.regime() {
            Regime::Underdamped => "under-damped",
            Regime::CriticallyDamped => "critically damped",
            Regime::Overdamped => "over-damped",
            Regime::Undamped => "undamped",
            Regime::Unsprung => "unsprung",
            Regime::Free => "free (unimpeded)",
        };
        let marker = if row.index == selected.0 { "> " } else { "  " };
        for (label, mut text) in &mut labels {
            if label.0 == row.index {
                text.0 = format!(
                    "{marker}{}   m = {:.2}  c = {:.2}  k = {:.1}   zeta = {zeta}   now {regime}",
                    row.name,
                    s.mass(),
                    s.damping(),
                    s.stiffness()
                );
            }
        }
    }
}

fn record_traces(cycle: Res<Cycle>, mut rows: Query<(&mut Row, &Transform, &TranslationSpring)>) {
    for (mut row, transform, spring) in &mut rows {
        let x = (transform.translation.x - spring.target().x) / UNIT;
        row.trace.push(Vec2::new(cycle.0, x));
    }
}

/// Draws each row's x(t); the part of a trajectory that leaves the row's band (the free body
/// keeps going) is not drawn.
fn draw_traces(mut gizmos: Gizmos, rows: Query<(&Row, &Sprite)>) {
    let band = 0.48 * ROW_HEIGHT;
    for (row, sprite) in &rows {
        let y = row_y(row.index);
        let points = row
            .trace
            .iter()
            .map(|p| {
                Vec2::new(
                    PLOT_LEFT_X + p.x / CYCLE * PLOT_WIDTH,
                    p.y * 0.4 * ROW_HEIGHT,
                )
            })
            .take_while(|p| p.y.abs() <= band)
            .map(|p| p + Vec2::Y * y);
        gizmos.linestrip_2d(points, sprite.color);
    }
}
