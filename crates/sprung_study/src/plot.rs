//! The accuracy-vs-cost figure: error against time per step, one point per method, with the
//! Pareto front, drawn to SVG with `plotters` (no font or bitmap dependencies).

use std::path::Path;

use plotters::prelude::*;

use crate::Study;
use crate::evaluate::{median, ranked_error};
use crate::scenario::{self, Family};

/// Errors are drawn no lower than this (an exact 0 would be off a log axis).
const ERROR_FLOOR: f64 = 1e-17;
/// Where points whose error is unbounded (unstable at the median setting) are drawn.
const ERROR_CEILING: f64 = 10.0;

/// Distinct colours, one per method (in report order).
const COLORS: [(u8, u8, u8); 14] = [
    (214, 39, 40),
    (240, 128, 128),
    (148, 103, 189),
    (127, 127, 127),
    (31, 119, 180),
    (23, 190, 207),
    (0, 110, 110),
    (44, 160, 44),
    (160, 160, 20),
    (140, 86, 75),
    (227, 119, 194),
    (255, 127, 14),
    (60, 60, 200),
    (200, 150, 0),
];

fn color(i: usize) -> RGBColor {
    let (r, g, b) = COLORS[i % COLORS.len()];
    RGBColor(r, g, b)
}

/// One method's point on the plot.
#[derive(Clone, Copy, Debug)]
pub struct Point {
    /// The method's name.
    pub name: &'static str,
    /// Nanoseconds per step (fixed `dt`).
    pub ns: f64,
    /// Median error over the `ω·dt` grid at `ζ = PLOT_ZETA` (infinite if the method is
    /// unstable at more than half of those points).
    pub error: f64,
}

/// Every method's point: its fixed-`dt` time per step and its median error over the `ω·dt`
/// grid at the representative damping ratio [`scenario::PLOT_ZETA`].
#[must_use]
pub fn points(study: &Study) -> Vec<Point> {
    let indices: Vec<usize> = study
        .scenarios
        .iter()
        .enumerate()
        .filter(|(_, s)| {
            s.family == Family::Grid && s.spring.zeta.to_bits() == scenario::PLOT_ZETA.to_bits()
        })
        .map(|(i, _)| i)
        .collect();
    study
        .methods
        .iter()
        .map(|m| Point {
            name: m.name,
            ns: m.timing.fixed_dt_ns,
            error: median(
                indices
                    .iter()
                    .map(|&i| ranked_error(&m.outcomes[i]))
                    .collect(),
            ),
        })
        .collect()
}

/// Indices of the points no other point beats in both time and error (finite errors only),
/// sorted by time.
#[must_use]
pub fn pareto_front(points: &[Point]) -> Vec<usize> {
    let dominates = |a: &Point, b: &Point| {
        a.ns <= b.ns && a.error <= b.error && (a.ns < b.ns || a.error < b.error)
    };
    let mut front: Vec<usize> = (0..points.len())
        .filter(|&i| points[i].error.is_finite())
        .filter(|&i| !points.iter().any(|p| dominates(p, &points[i])))
        .collect();
    front.sort_by(|&a, &b| points[a].ns.total_cmp(&points[b].ns));
    front
}

fn shown_error(error: f64) -> f64 {
    if error.is_finite() {
        error.max(ERROR_FLOOR)
    } else {
        ERROR_CEILING
    }
}

/// Draws the figure to `path` (SVG).
///
/// # Errors
/// If the file cannot be written.
pub fn draw(study: &Study, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let points = points(study);
    let front = pareto_front(&points);
    let root = SVGBackend::new(path, (1120, 620)).into_drawing_area();
    root.fill(&WHITE)?;
    let (plot_area, legend_area) = root.split_horizontally(700);
    draw_chart(&plot_area, &points, &front)?;
    draw_legend(&legend_area, &points, &front)?;
    root.present()?;
    Ok(())
}

/// The log-log chart: the front as a staircase and one numbered marker per method.
fn draw_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    points: &[Point],
    front: &[usize],
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let (min_ns, max_ns) = points.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), p| {
        (lo.min(p.ns), hi.max(p.ns))
    });
    let mut chart = ChartBuilder::on(area)
        .caption(
            format!(
                "Accuracy vs cost (ζ = {}, ω = {} rad/s)",
                scenario::PLOT_ZETA,
                scenario::OMEGA
            ),
            ("sans-serif", 22),
        )
        .margin(12)
        .x_label_area_size(48)
        .y_label_area_size(70)
        .build_cartesian_2d(
            (min_ns / 1.6..max_ns * 1.6).log_scale(),
            (ERROR_FLOOR / 3.0..ERROR_CEILING * 3.0).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("time per step, ns (64 springs per frame, dt = 1/60 s, measured in the same run)")
        .y_desc("error: median over ω·dt ∈ [0.01, 10] of max |x − x_exact| / amplitude")
        .axis_desc_style(("sans-serif", 15))
        .label_style(("sans-serif", 13))
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .light_line_style(WHITE.mix(0.0))
        .draw()?;

    // The Pareto front as a staircase: the boundary of what some method achieves.
    let mut stairs = Vec::new();
    for (k, &i) in front.iter().enumerate() {
        let p = points[i];
        if k > 0 {
            let previous = points[front[k - 1]];
            stairs.push((p.ns, shown_error(previous.error)));
        }
        stairs.push((p.ns, shown_error(p.error)));
    }
    chart.draw_series(LineSeries::new(stairs, BLACK.mix(0.5).stroke_width(2)))?;

    for (i, p) in points.iter().enumerate() {
        let color = color(i);
        let position = (p.ns, shown_error(p.error));
        // Numbers alternate above and below their marker so that neighbours stay legible.
        let offset = if i % 2 == 0 { (7, -20) } else { (7, 4) };
        let label = Text::new(format!("{}", i + 1), offset, ("sans-serif", 15));
        if p.error.is_finite() {
            chart.draw_series(std::iter::once(
                EmptyElement::at(position) + Circle::new((0, 0), 6, color.filled()) + label,
            ))?;
        } else {
            chart.draw_series(std::iter::once(
                EmptyElement::at(position) + Cross::new((0, 0), 7, color.stroke_width(3)) + label,
            ))?;
        }
    }
    Ok(())
}

/// The legend: number, marker, name, time and error of each method, then the conventions.
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    points: &[Point],
    front: &[usize],
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let line = 26;
    let mut y = 40;
    area.draw(&Text::new("Methods", (10, 12), ("sans-serif", 18)))?;
    for (i, p) in points.iter().enumerate() {
        let color = color(i);
        if p.error.is_finite() {
            area.draw(&Circle::new((18, y + 7), 6, color.filled()))?;
        } else {
            area.draw(&Cross::new((18, y + 7), 7, color.stroke_width(3)))?;
        }
        let error = if p.error.is_finite() {
            format!("{:.1e}", p.error)
        } else {
            "unstable".into()
        };
        let pareto = if front.contains(&i) { " (Pareto)" } else { "" };
        let label = format!("{} {}: {:.1} ns, {error}{pareto}", i + 1, p.name, p.ns);
        area.draw(&Text::new(label, (32, y), ("sans-serif", 14)))?;
        y += line;
    }
    y += 8;
    area.draw(&PathElement::new(
        vec![(8, y + 7), (28, y + 7)],
        BLACK.mix(0.5).stroke_width(2),
    ))?;
    area.draw(&Text::new("Pareto front", (32, y), ("sans-serif", 14)))?;
    y += line;
    area.draw(&Text::new(
        format!("× unstable at most ω·dt: drawn at {ERROR_CEILING}"),
        (10, y),
        ("sans-serif", 13),
    ))?;
    y += line - 6;
    area.draw(&Text::new(
        format!("errors below {ERROR_FLOOR:.0e} drawn at {ERROR_FLOOR:.0e}"),
        (10, y),
        ("sans-serif", 13),
    ))?;
    Ok(())
}
