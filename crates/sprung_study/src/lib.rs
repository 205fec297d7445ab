//! What does accuracy cost in time? An accuracy-vs-cost study of `sprung`'s exact step against
//! the numeric integrators and smoothing formulas games animate springs with.
//!
//! Every [method](methods) is run over the same [scenarios](scenario) (a grid of damping ratios
//! and `ω·dt`, a frame-time sweep, a 1 s hitch and a mid-flight retarget) and compared with a
//! 256-bit [reference](mod@reference); its cost per step is [timed](timing) in the same run. The
//! [report] prints markdown tables and the [plot] draws error against cost.
//!
//! Run with `cargo run --release -p sprung_study`; it writes `assets/accuracy_vs_cost.md` and
//! `assets/accuracy_vs_cost.svg` at the workspace root. Everything except the timings is
//! deterministic.

pub mod evaluate;
pub mod methods;
pub mod plot;
pub mod reference;
pub mod report;
pub mod scenario;
pub mod timing;

use std::path::{Path, PathBuf};
use std::time::Instant;

use evaluate::Outcome;
use methods::{Method, MethodVisitor, SpringParams};
use scenario::Scenario;
use timing::Timing;

/// The `dt` at which methods are timed (60 fps).
pub const TIMING_DT: f64 = 1.0 / 60.0;

/// One method's results over every scenario, and its cost.
#[derive(Clone, Debug)]
pub struct MethodResult {
    /// [`Method::NAME`].
    pub name: &'static str,
    /// [`Method::NOTE`].
    pub note: &'static str,
    /// One outcome per scenario, in the order of [`Study::scenarios`].
    pub outcomes: Vec<Outcome>,
    /// Time per step.
    pub timing: Timing,
}

/// Everything the study measured.
#[derive(Clone, Debug)]
pub struct Study {
    /// The scenarios, in order.
    pub scenarios: Vec<Scenario>,
    /// The reference position at the end of every frame, per scenario.
    pub references: Vec<Vec<f64>>,
    /// One result per method, in the order of [`methods::for_each_method`].
    pub methods: Vec<MethodResult>,
}

impl Study {
    /// The result of the method named `name`.
    #[must_use]
    pub fn method(&self, name: &str) -> Option<&MethodResult> {
        self.methods.iter().find(|m| m.name == name)
    }
}

/// Evaluates and times each method in turn.
struct Collector<'a> {
    scenarios: &'a [Scenario],
    references: &'a [Vec<f64>],
    timing_spring: SpringParams,
    results: Vec<MethodResult>,
}

impl MethodVisitor for Collector<'_> {
    fn visit<M: Method>(&mut self) {
        let outcomes = self
            .scenarios
            .iter()
            .zip(self.references)
            .map(|(scenario, reference)| evaluate::run::<M>(scenario, reference))
            .collect();
        let timing = timing::time::<M>(&self.timing_spring, TIMING_DT);
        eprintln!(
            "  {:<34} {:>8.2} ns/step ({:.2} with dt varying)",
            M::NAME,
            timing.fixed_dt_ns,
            timing.varying_dt_ns
        );
        self.results.push(MethodResult {
            name: M::NAME,
            note: M::NOTE,
            outcomes,
            timing,
        });
    }
}

/// Computes the reference trajectories of all scenarios, on all available cores.
fn references(scenarios: &[Scenario]) -> Vec<Vec<f64>> {
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    let mut out = vec![Vec::new(); scenarios.len()];
    std::thread::scope(|scope| {
        let chunk = scenarios.len().div_ceil(threads);
        for (scenarios, out) in scenarios.chunks(chunk).zip(out.chunks_mut(chunk)) {
            scope.spawn(move || {
                for (scenario, out) in scenarios.iter().zip(out) {
                    *out = reference::trajectory(scenario);
                }
            });
        }
    });
    out
}

/// Runs every method over every scenario and times it.
#[must_use]
pub fn measure() -> Study {
    let scenarios = scenario::all();
    let frames: usize = scenarios.iter().map(|s| s.frames.len()).sum();
    let start = Instant::now();
    let references = references(&scenarios);
    eprintln!(
        "reference: {} scenarios, {frames} frames at {} bits in {:.1} s",
        scenarios.len(),
        reference::PRECISION,
        start.elapsed().as_secs_f64()
    );
    let start = Instant::now();
    let mut collector = Collector {
        scenarios: &scenarios,
        references: &references,
        timing_spring: SpringParams::new(scenario::OMEGA, scenario::PLOT_ZETA),
        results: Vec::new(),
    };
    eprintln!(
        "methods (timed at ζ = {}, ω = {}, dt = 1/60 s, {} springs per frame):",
        scenario::PLOT_ZETA,
        scenario::OMEGA,
        timing::SPRINGS
    );
    methods::for_each_method(&mut collector);
    eprintln!(
        "evaluation and timing in {:.1} s",
        start.elapsed().as_secs_f64()
    );
    let methods = collector.results;
    Study {
        scenarios,
        references,
        methods,
    }
}

/// The workspace's `assets/` directory.
#[must_use]
pub fn assets_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets")
}

/// Measures, prints the report, and writes the markdown table and the plot to `assets/`.
///
/// # Errors
/// If `assets/` cannot be written or the plot cannot be drawn.
pub fn run() -> Result<(), Box<dyn std::error::Error>> {
    let study = measure();
    let report = report::Report::new(&study);
    println!("{}", report.full());
    let assets = assets_dir();
    std::fs::create_dir_all(&assets)?;
    std::fs::write(assets.join("accuracy_vs_cost.md"), report.summary())?;
    plot::draw(&study, &assets.join("accuracy_vs_cost.svg"))?;
    eprintln!("wrote assets/accuracy_vs_cost.md and assets/accuracy_vs_cost.svg");
    Ok(())
}
