//! Markdown tables of the study's results, and its checks.

use std::fmt::Write as _;

use crate::evaluate::{Outcome, Status, median, ranked_error};
use crate::methods::{
    ExactCached, ExactRecomputed, JuckettClosedForm, Method, NaiveClosedForm, SemiImplicitEuler,
};
use crate::scenario::{self, Family};
use crate::{MethodResult, Study, TIMING_DT, plot, timing};

/// An error as a fraction of the amplitude, in short scientific notation.
fn error(e: f64) -> String {
    if e == 0.0 {
        "0".into()
    } else if e.is_finite() {
        format!("{e:.1e}")
    } else {
        "∞".into()
    }
}

/// One table cell for an outcome.
fn cell(outcome: &Outcome) -> String {
    match outcome.status {
        Status::Stable => error(outcome.max_error),
        Status::Unstable if outcome.grows && outcome.max_error > 1.0 => "diverged".into(),
        Status::Unstable if outcome.grows => format!("grows ({})", error(outcome.max_error)),
        Status::Unstable => format!("off ({})", error(outcome.max_error)),
        Status::NonFinite => "NaN".into(),
    }
}

/// A markdown table from a header and rows.
fn table(header: &[String], rows: &[Vec<String>]) -> String {
    let mut out = String::new();
    let line = |cells: &[String]| format!("| {} |\n", cells.join(" | "));
    out.push_str(&line(header));
    let rule: Vec<String> = header
        .iter()
        .enumerate()
        .map(|(i, _)| if i == 0 { "---".into() } else { "---:".into() })
        .collect();
    out.push_str(&line(&rule));
    for row in rows {
        out.push_str(&line(row));
    }
    out
}

/// Unit roundoff of `f64`: errors are fractions of an amplitude of 1, so this is one unit of
/// roundoff of the amplitude.
const U: f64 = f64::EPSILON / 2.0;

/// One scenario where a method was strictly more accurate than the exact f64 step.
#[derive(Clone, Debug)]
pub struct Exception {
    /// The scenario's label.
    pub scenario: String,
    /// The more accurate method.
    pub method: &'static str,
    /// Its error.
    pub error: f64,
    /// The exact f64 step's error.
    pub exact_error: f64,
}

/// Is the exact f64 step the most accurate method everywhere?
#[derive(Clone, Debug)]
pub struct AccuracyCheck {
    /// Scenarios checked.
    pub scenarios: usize,
    /// Where an approximate method (an integrator, a smoothing formula, the f32 step) had a
    /// strictly smaller error.
    pub approximations_ahead: Vec<Exception>,
    /// The smallest ratio of an approximate method's error to the exact step's, over the
    /// scenarios where both are finite and the exact error is nonzero.
    pub approximation_margin: f64,
    /// Where another closed form in f64 (exact in exact arithmetic too) had a strictly smaller
    /// error.
    pub closed_forms_ahead: Vec<Exception>,
    /// Largest error of the exact f64 step over all scenarios.
    pub exact_worst: f64,
}

/// The methods that are, like the exact step, exact in exact arithmetic and run in f64.
const OTHER_CLOSED_FORMS: [&str; 2] = [NaiveClosedForm::NAME, JuckettClosedForm::NAME];

/// Compares the exact f64 step with every other method (but its recomputed twin, which gives
/// bit-identical results) on every scenario, and runs the matrix-form diagnostic where another
/// method comes out ahead.
///
/// # Panics
/// If the study has no [`ExactCached`] results.
#[must_use]
pub fn accuracy_check(study: &Study) -> AccuracyCheck {
    let exact = study
        .method(ExactCached::NAME)
        .expect("the exact method is in the study");
    let mut check = AccuracyCheck {
        scenarios: study.scenarios.len(),
        approximations_ahead: Vec::new(),
        approximation_margin: f64::INFINITY,
        closed_forms_ahead: Vec::new(),
        exact_worst: exact
            .outcomes
            .iter()
            .map(|o| o.max_error)
            .fold(0.0, f64::max),
    };
    for (index, scenario) in study.scenarios.iter().enumerate() {
        let exact_error = exact.outcomes[index].max_error;
        for method in &study.methods {
            if method.name == ExactCached::NAME || method.name == ExactRecomputed::NAME {
                continue;
            }
            let error = method.outcomes[index].max_error;
            let closed_form = OTHER_CLOSED_FORMS.contains(&method.name);
            if !closed_form && error.is_finite() && exact_error > 0.0 {
                check.approximation_margin = check.approximation_margin.min(error / exact_error);
            }
            if error < exact_error {
                let exception = Exception {
                    scenario: scenario.label.clone(),
                    method: method.name,
                    error,
                    exact_error,
                };
                if closed_form {
                    check.closed_forms_ahead.push(exception);
                } else {
                    check.approximations_ahead.push(exception);
                }
            }
        }
    }
    check
}

/// The study's results as markdown.
#[derive(Debug)]
pub struct Report<'a> {
    study: &'a Study,
    /// Indices of the scenarios of the main table (all but the hard cases).
    main: Vec<usize>,
}

impl<'a> Report<'a> {
    /// A report of `study`.
    #[must_use]
    pub fn new(study: &'a Study) -> Self {
        let main = study
            .scenarios
            .iter()
            .enumerate()
            .filter(|(_, s)| s.family != Family::Hard)
            .map(|(i, _)| i)
            .collect();
        Self { study, main }
    }

    fn baseline_ns(&self) -> f64 {
        self.study
            .method(SemiImplicitEuler::NAME)
            .map_or(f64::NAN, |m| m.timing.fixed_dt_ns)
    }

    /// One row of the main table.
    fn main_row(&self, method: &MethodResult) -> Vec<String> {
        let outcomes: Vec<&Outcome> = self.main.iter().map(|&i| &method.outcomes[i]).collect();
        let count = |status| outcomes.iter().filter(|o| o.status == status).count();
        let stable_max = outcomes
            .iter()
            .filter(|o| o.status == Status::Stable)
            .map(|o| o.max_error)
            .fold(0.0, f64::max);
        let typical = median(outcomes.iter().map(|o| ranked_error(o)).collect());
        vec![
            method.name.to_string(),
            error(stable_max),
            error(typical),
            count(Status::Unstable).to_string(),
            count(Status::NonFinite).to_string(),
            format!("{:.1}", method.timing.fixed_dt_ns),
            format!("{:.1}", method.timing.varying_dt_ns),
            format!("{:.2}", method.timing.fixed_dt_ns / self.baseline_ns()),
        ]
    }

    /// The main table and what its columns mean: what `assets/accuracy_vs_cost.md` holds.
    #[must_use]
    pub fn summary(&self) -> String {
        let header: Vec<String> = [
            "Method",
            "max error (stable)",
            "median error",
            "diverged",
            "NaN/inf",
            "ns/step",
            "ns/step, dt varies",
            "× semi-implicit Euler",
        ]
        .map(String::from)
        .to_vec();
        let rows: Vec<Vec<String>> = self
            .study
            .methods
            .iter()
            .map(|m| self.main_row(m))
            .collect();
        let mut out = table(&header, &rows);
        let _ = write!(
            out,
            "\n{} scenarios: ζ ∈ {{0, 0.1, 0.5, 1, 2, 10, 100}} × ω·dt ∈ {{0.01 … 10}} and × dt ∈ \
             {{1/240 … 1}} s (ω = {} rad/s, {} s or at least {} frames), a 1 s hitch at 60 fps and a \
             retarget at 60 fps (1 → −1 at 0.5 s) for each ζ; start at rest, amplitude 1. \
             **Error**: max over the frames of |x − x_exact| as a fraction of the amplitude, against a \
             {}-bit reference; *max* is over the scenarios where the method did not diverge, \
             *median* over all (diverged = ∞). **Diverged**: error above the amplitude, or a \
             one-step map that grows (spectral radius > 1: the error grows without bound given \
             time). **Time**: median ns per step over {} springs per frame at \
             ζ = {}, dt = 1/60 s (*dt varies*: every frame's dt differs, so per-dt coefficients are \
             recomputed each frame), measured in the same run; the last column is ns/step relative \
             to semi-implicit Euler.\n",
            self.main.len(),
            scenario::OMEGA,
            scenario::DURATION,
            scenario::MIN_FRAMES,
            crate::reference::PRECISION,
            timing::SPRINGS,
            scenario::PLOT_ZETA,
        );
        out
    }

    /// Method × column table, one column per `(label, scenario index)`. Cells: the error, or
    /// *diverged* (error above the amplitude and a growing step), *grows (e)* (growing step,
    /// error `e` so far), *off (e)* (error above the amplitude from a step that does not grow:
    /// the wrong motion rather than an instability), *NaN*.
    fn detail(&self, columns: &[(String, usize)]) -> String {
        let mut header = vec!["Method".to_string()];
        header.extend(columns.iter().map(|(label, _)| label.clone()));
        let rows: Vec<Vec<String>> = self
            .study
            .methods
            .iter()
            .map(|m| {
                let mut row = vec![m.name.to_string()];
                row.extend(columns.iter().map(|&(_, i)| cell(&m.outcomes[i])));
                row
            })
            .collect();
        table(&header, &rows)
    }

    fn scenario_index(&self, family: Family, zeta: f64, dt: Option<f64>) -> Option<usize> {
        self.study.scenarios.iter().position(|s| {
            s.family == family
                && s.spring.zeta.to_bits() == zeta.to_bits()
                && dt.is_none_or(|dt| s.fixed_dt.is_some_and(|d| d.to_bits() == dt.to_bits()))
        })
    }

    /// Every table, the checks and the notes: what the program prints.
    #[must_use]
    pub fn full(&self) -> String {
        let mut out = String::from("# Accuracy vs cost of spring steps\n\n");
        out.push_str(&self.summary());
        out.push_str(
            "\nIn the tables below a cell is the error, or *diverged* (error above the amplitude \
             and a growing step), *grows (e)* (a growing step, error e so far), *off (e)* (error \
             above the amplitude from a step that does not grow: the wrong motion rather than an \
             instability), or *NaN*.\n",
        );
        for &zeta in &scenario::ZETAS {
            let _ = writeln!(
                out,
                "\n## ζ = {zeta}: error by ω·dt (ω = {}, {} s or ≥ {} frames)\n",
                scenario::OMEGA,
                scenario::DURATION,
                scenario::MIN_FRAMES
            );
            let columns: Vec<(String, usize)> = scenario::OMEGA_DTS
                .iter()
                .filter_map(|&w| {
                    self.scenario_index(Family::Grid, zeta, Some(w / scenario::OMEGA))
                        .map(|i| (format!("ω·dt {w}"), i))
                })
                .collect();
            out.push_str(&self.detail(&columns));
        }
        for &zeta in &scenario::ZETAS {
            let _ = writeln!(
                out,
                "\n## ζ = {zeta}: error by frame time (ω = {})\n",
                scenario::OMEGA
            );
            let columns: Vec<(String, usize)> = scenario::FRAME_RATES
                .iter()
                .filter_map(|&fps| {
                    self.scenario_index(Family::FrameRate, zeta, Some(1.0 / fps))
                        .map(|i| (format!("1/{fps} s"), i))
                })
                .collect();
            out.push_str(&self.detail(&columns));
        }
        for (family, title) in [
            (
                Family::Hitch,
                "1 s hitch in a 60 fps run (59 × 1/60 s, 1 s, 60 × 1/60 s)",
            ),
            (
                Family::Retarget,
                "retarget mid-flight (60 fps, target 1 → −1 at 0.5 s, velocity kept)",
            ),
        ] {
            let _ = writeln!(out, "\n## {title}, by ζ\n");
            let columns: Vec<(String, usize)> = scenario::ZETAS
                .iter()
                .filter_map(|&zeta| {
                    self.scenario_index(family, zeta, None)
                        .map(|i| (format!("ζ {zeta}"), i))
                })
                .collect();
            out.push_str(&self.detail(&columns));
        }
        out.push_str("\n## Hard cases outside the grid (ω = 10, 60 fps, 2 s)\n\n");
        let columns: Vec<(String, usize)> = self
            .study
            .scenarios
            .iter()
            .enumerate()
            .filter(|(_, s)| s.family == Family::Hard)
            .map(|(i, s)| (format!("ζ {}", s.spring.zeta), i))
            .collect();
        out.push_str(&self.detail(&columns));
        out.push_str(&self.checks());
        out.push_str("\n## Methods\n\n");
        for method in &self.study.methods {
            let _ = writeln!(out, "- **{}**: {}", method.name, method.note);
        }
        let _ = writeln!(
            out,
            "\nFirst-order rates fitted for the exponential lerp (r/ω by ζ): {}.",
            self.fitted_rates()
        );
        let _ = writeln!(
            out,
            "Timing: {} springs, each its own method instance, stepped per frame at dt = {:.5} s; \
             ≥ {} ms per measurement, median of {}.",
            timing::SPRINGS,
            TIMING_DT,
            timing::MIN_MEASUREMENT.as_millis(),
            timing::REPETITIONS
        );
        out
    }

    fn fitted_rates(&self) -> String {
        scenario::ZETAS
            .iter()
            .filter_map(|&zeta| {
                self.study
                    .scenarios
                    .iter()
                    .find(|s| s.spring.zeta.to_bits() == zeta.to_bits())
                    .map(|s| {
                        format!(
                            "ζ {zeta}: {:.3}",
                            s.spring.first_order_rate / s.spring.omega
                        )
                    })
            })
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The most-accurate and Pareto checks, as text.
    fn checks(&self) -> String {
        let mut out = String::from("\n## Checks\n\n");
        out.push_str(&self.accuracy_checks());
        out.push_str(&self.pareto_check());
        out
    }

    /// Whether the exact f64 step is the most accurate method, as text.
    fn accuracy_checks(&self) -> String {
        let mut out = String::new();
        let check = accuracy_check(self.study);
        if check.approximations_ahead.is_empty() {
            let _ = writeln!(
                out,
                "- PASS: the exact f64 step is more accurate than every approximate method \
                 (integrators, smoothing formulas, the f32 step) in all {} scenarios, by a \
                 factor of at least {:.1e}. Its worst error is {} ({:.0} u).",
                check.scenarios,
                check.approximation_margin,
                error(check.exact_worst),
                check.exact_worst / U
            );
        } else {
            let _ = writeln!(
                out,
                "- FAIL: an approximate method beat the exact f64 step in {} (scenario, method) \
                 pairs:",
                check.approximations_ahead.len()
            );
            for e in &check.approximations_ahead {
                let _ = writeln!(
                    out,
                    "  - {}: {} {} < exact {}",
                    e.scenario,
                    e.method,
                    error(e.error),
                    error(e.exact_error)
                );
            }
        }
        out.push_str(&self.closed_form_ties(&check));
        out
    }

    /// Where the other closed forms come out ahead of the exact step, as text.
    fn closed_form_ties(&self, check: &AccuracyCheck) -> String {
        let mut out = String::new();
        if check.closed_forms_ahead.is_empty() {
            let _ = writeln!(
                out,
                "- PASS: no other closed form (naive, Juckett) is ever more accurate than the \
                 exact f64 step."
            );
        } else {
            let behind = |e: &Exception| (e.exact_error - e.error) / U;
            let worst = check
                .closed_forms_ahead
                .iter()
                .map(behind)
                .fold(0.0, f64::max);
            let _ = write!(
                out,
                "- TIE AT ROUNDING LEVEL: the other f64 closed forms (exact in exact arithmetic \
                 too) come out ahead of the exact f64 step in {} (scenario, method) pairs, by at \
                 most {worst:.0} u (u = 2⁻⁵³ of the amplitude). All three are accurate to ~1e-15 \
                 over the run; gaps of a few u are rounding luck, and the larger ones come at \
                 ω·dt ≳ 1 with light damping, where `Transition::step`'s increment form \
                 x + (M − I)·y rounds a larger update than x* + M·y would (|M − I| reaches 2 \
                 while |M| ≤ 1). The increment form is kept: it is what keeps f32 accurate at \
                 small dt, and choosing the form per step cost more than a semi-implicit Euler \
                 step (measured).",
                check.closed_forms_ahead.len(),
            );
            let _ = writeln!(
                out,
                " Where the other forms break the exact step is ahead by orders of magnitude \
                 (worst errors over all scenarios: {}).",
                self.closed_form_worst()
            );
            let _ = writeln!(
                out,
                "\n  | scenario | method | its error | exact f64 step |\n  | --- | --- | ---: | ---: |"
            );
            for e in &check.closed_forms_ahead {
                let _ = writeln!(
                    out,
                    "  | {} | {} | {} | {} |",
                    e.scenario,
                    e.method,
                    error(e.error),
                    error(e.exact_error)
                );
            }
        }
        out
    }

    /// The worst stable error and the non-finite count of each other closed form, and the
    /// exact step's, over all scenarios.
    fn closed_form_worst(&self) -> String {
        [ExactCached::NAME]
            .iter()
            .chain(&OTHER_CLOSED_FORMS)
            .filter_map(|&name| self.study.method(name))
            .map(|m| {
                let worst = m
                    .outcomes
                    .iter()
                    .filter(|o| o.status == Status::Stable)
                    .map(|o| o.max_error)
                    .fold(0.0, f64::max);
                let nan = m
                    .outcomes
                    .iter()
                    .filter(|o| o.status == Status::NonFinite)
                    .count();
                format!("{} {} and {nan} NaN", m.name, error(worst))
            })
            .collect::<Vec<_>>()
            .join("; ")
    }

    /// Whether the exact f64 step is on the plot's Pareto front, as text.
    fn pareto_check(&self) -> String {
        let mut out = String::new();
        let points = plot::points(self.study);
        let front = plot::pareto_front(&points);
        let exact_on_front = front.iter().any(|&i| points[i].name == ExactCached::NAME);
        let names: Vec<&str> = front.iter().map(|&i| points[i].name).collect();
        let _ = writeln!(
            out,
            "- {}: the exact f64 step is {}on the Pareto front of the plot (error = median over \
             the ω·dt grid at ζ = {}); front: {}.",
            if exact_on_front { "PASS" } else { "FAIL" },
            if exact_on_front { "" } else { "not " },
            scenario::PLOT_ZETA,
            names.join(" → ")
        );
        out
    }
}
