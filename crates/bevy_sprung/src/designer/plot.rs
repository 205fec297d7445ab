//! The response plot: x(t) above, v(t) below, for the spring being tuned and its reference,
//! drawn into an image the panel shows. It is redrawn only when the design changes.

use bevy::asset::RenderAssetUsages;
use bevy::prelude::*;
use bevy::render::render_resource::{Extent3d, TextureDimension, TextureFormat};
use sprung::Spring;

use super::model::{SpringDesign, step_response};

/// The plot's size in pixels.
pub(super) const PLOT_SIZE: UVec2 = UVec2::new(560, 300);
/// The share of the height given to x(t); v(t) has the rest.
const POSITION_SHARE: f32 = 0.68;
/// Samples per curve.
const SAMPLES: u16 = 560;

const BACKGROUND: [u8; 4] = [24, 26, 31, 255];
const GRID: [u8; 4] = [52, 56, 66, 255];
const BAND: [u8; 4] = [38, 58, 48, 255];
const TARGET: [u8; 4] = [90, 160, 110, 255];
const POSITION: [u8; 4] = [110, 190, 255, 255];
const VELOCITY: [u8; 4] = [255, 170, 80, 255];
const REFERENCE: [u8; 4] = [140, 140, 150, 255];
const SAMPLE: [u8; 4] = [235, 240, 255, 255];
const SETTLE: [u8; 4] = [120, 220, 140, 255];

/// The plot's image, and the time span it shows.
#[derive(Resource, Debug, Clone)]
pub(super) struct ResponsePlot {
    pub(super) image: Handle<Image>,
    /// The seconds the plot spans, left to right.
    pub(super) span: f32,
}

/// The seconds a plot of these springs spans: past the slower one's settle, at least 0.5 s.
pub(super) fn span(design: &SpringDesign) -> f32 {
    let settle = |spring: &Spring<f32>| {
        spring
            .settle_time(1.0, design.tolerance)
            .filter(|t| t.is_finite())
            .unwrap_or(4.0)
    };
    let slowest = design
        .reference()
        .map_or(0.0, |b| settle(&b))
        .max(settle(&design.spring()));
    (slowest * 1.15).clamp(0.5, 30.0)
}

/// RGBA pixels with a y axis pointing up, in plot units mapped by the caller.
struct Canvas {
    size: UVec2,
    pixels: Vec<u8>,
}

#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss,
    reason = "pixel coordinates of a plot a few hundred pixels wide, clipped to it"
)]
impl Canvas {
    fn new(size: UVec2) -> Self {
        let mut pixels = Vec::with_capacity((size.x * size.y * 4) as usize);
        for _ in 0..size.x * size.y {
            pixels.extend_from_slice(&BACKGROUND);
        }
        Self { size, pixels }
    }

    fn dot(&mut self, x: f32, y: f32, radius: i32, color: [u8; 4]) {
        let (cx, cy) = (x.round() as i32, y.round() as i32);
        for dy in -radius..=radius {
            for dx in -radius..=radius {
                let (px, py) = (cx + dx, cy + dy);
                if px < 0 || py < 0 || px >= self.size.x as i32 || py >= self.size.y as i32 {
                    continue;
                }
                // Row 0 of the image is its top.
                let row = self.size.y as i32 - 1 - py;
                let at = ((row * self.size.x as i32 + px) * 4) as usize;
                self.pixels[at..at + 4].copy_from_slice(&color);
            }
        }
    }

    fn line(&mut self, from: Vec2, to: Vec2, radius: i32, color: [u8; 4]) {
        let steps = (to - from).abs().max_element().ceil().max(1.0);
        for i in 0..=steps as u32 {
            let p = from.lerp(to, i as f32 / steps);
            self.dot(p.x, p.y, radius, color);
        }
    }

    fn polyline(&mut self, points: &[Vec2], radius: i32, color: [u8; 4]) {
        for pair in points.windows(2) {
            self.line(pair[0], pair[1], radius, color);
        }
    }

    fn fill(&mut self, min: Vec2, max: Vec2, color: [u8; 4]) {
        let (lo, hi) = (min.min(max), min.max(max));
        for y in lo.y.round() as i32..=hi.y.round() as i32 {
            self.line(
                Vec2::new(lo.x, y as f32),
                Vec2::new(hi.x, y as f32),
                0,
                color,
            );
        }
    }
}

/// A pane of the plot: a value range mapped onto a band of rows.
#[derive(Clone, Copy)]
struct Pane {
    bottom: f32,
    height: f32,
    min: f32,
    max: f32,
    span: f32,
    width: f32,
}

impl Pane {
    fn at(&self, t: f32, value: f32) -> Vec2 {
        Vec2::new(
            t / self.span * (self.width - 1.0),
            self.bottom + (value - self.min) / (self.max - self.min) * (self.height - 1.0),
        )
    }
}

/// Draws the design's plot into fresh pixels.
pub(super) fn draw(design: &SpringDesign, span: f32) -> Vec<u8> {
    let size = PLOT_SIZE.as_vec2();
    let mut canvas = Canvas::new(PLOT_SIZE);
    let springs: Vec<Spring<f32>> = design
        .reference()
        .into_iter()
        .chain([design.spring()])
        .collect();
    let curves: Vec<Vec<(f32, f32, f32)>> = springs
        .iter()
        .map(|spring| {
            (0..=SAMPLES)
                .map(|i| {
                    let t = span * f32::from(i) / f32::from(SAMPLES);
                    let (x, v) = step_response(spring, t);
                    (t, x, v)
                })
                .collect()
        })
        .collect();
    let (mut low, mut high, mut speed) = (-0.1_f32, 1.1_f32, 1e-6_f32);
    for &(_, x, v) in curves.iter().flatten() {
        (low, high, speed) = (low.min(x), high.max(x), speed.max(v.abs()));
    }
    let split = size.y * (1.0 - POSITION_SHARE);
    let position = Pane {
        bottom: split + 6.0,
        height: size.y - split - 12.0,
        min: low,
        max: high,
        span,
        width: size.x,
    };
    let velocity = Pane {
        bottom: 6.0,
        height: split - 12.0,
        min: -speed * 1.05,
        max: speed * 1.05,
        ..position
    };
    let tolerance = design.tolerance;
    canvas.fill(
        position.at(0.0, 1.0 - tolerance),
        position.at(span, 1.0 + tolerance),
        BAND,
    );
    for pane in [position, velocity] {
        canvas.line(pane.at(0.0, 0.0), pane.at(span, 0.0), 0, GRID);
    }
    canvas.line(Vec2::new(0.0, split), Vec2::new(size.x, split), 0, GRID);
    canvas.line(position.at(0.0, 1.0), position.at(span, 1.0), 0, TARGET);
    let tuned = curves.len() - 1;
    for (index, curve) in curves.iter().enumerate() {
        let (x_color, v_color, radius) = if index == tuned {
            (POSITION, VELOCITY, 1)
        } else {
            (REFERENCE, REFERENCE, 0)
        };
        let xs: Vec<Vec2> = curve.iter().map(|&(t, x, _)| position.at(t, x)).collect();
        let vs: Vec<Vec2> = curve.iter().map(|&(t, _, v)| velocity.at(t, v)).collect();
        canvas.polyline(&xs, radius, x_color);
        canvas.polyline(&vs, radius, v_color);
    }
    // The frames a game at the preview's rate would show: on the curve at any rate.
    let frame = 1.0 / design.preview.fps;
    let spring = design.spring();
    let mut t = 0.0;
    while t <= span && frame * 4.0 < span {
        let (x, _) = step_response(&spring, t);
        canvas.dot(position.at(t, x).x, position.at(t, x).y, 2, SAMPLE);
        t += frame;
    }
    if let Some(settle) = design.readouts().settle_time.filter(|&s| s <= span) {
        canvas.line(
            position.at(settle, low),
            position.at(settle, high),
            0,
            SETTLE,
        );
    }
    canvas.pixels
}

/// A new image of the plot's size.
pub(super) fn image(pixels: Vec<u8>) -> Image {
    Image::new(
        Extent3d {
            width: PLOT_SIZE.x,
            height: PLOT_SIZE.y,
            depth_or_array_layers: 1,
        },
        TextureDimension::D2,
        pixels,
        TextureFormat::Rgba8UnormSrgb,
        RenderAssetUsages::default(),
    )
}

/// Redraws the plot when the design changed.
pub(super) fn redraw(
    design: Res<SpringDesign>,
    mut plot: ResMut<ResponsePlot>,
    mut images: ResMut<Assets<Image>>,
) {
    if !design.is_changed() {
        return;
    }
    plot.span = span(&design);
    let pixels = draw(&design, plot.span);
    if let Some(mut image) = images.get_mut(&plot.image) {
        image.data = Some(pixels);
    }
}
