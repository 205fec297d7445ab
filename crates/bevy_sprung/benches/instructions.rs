//! Instructions per spring per frame, counted by `valgrind --tool=callgrind`: repeatable figures
//! on a shared, noisy machine (the count does not depend on what else runs).
//!
//! `cargo bench -p bevy_sprung --bench instructions` builds the scenes of `scenarios/mod.rs`,
//! runs each under callgrind with collection only inside [`measured`] (a few frames of the
//! animation's schedule, after warm-up frames), and prints instructions per entity per frame
//! with the ratios the performance goals are stated in. It needs `valgrind` on the `PATH`.
//! With `--features debug` it also counts the debug overlay (`… -- overlay`: only that).
//! `… --bench instructions -- one METHOD COUNT FRAMES VARY` runs one scene without callgrind
//! (what the driver runs under it); `… -- time METHOD COUNT FRAMES VARY [MODE]` times one
//! scene's frames: its schedule, or with MODE `whole` whole frames, `static` whole frames with
//! transform propagation as Bevy sets it up, `moving` with propagation set up for a scene whose
//! `Transform`s mostly move (`idle`, an app with nothing to animate, is the base of whole
//! frames, and `touch`, a system that moves every translation, the floor of propagated ones).

#[path = "support/callgrind.rs"]
mod callgrind;
#[path = "scenarios/mod.rs"]
mod scenarios;

use bevy::ecs::schedule::{Schedules, SingleThreadedExecutor};
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use callgrind::callgrind;
use scenarios::{FRAME, Method, Propagation, varying_dt};

/// Entities per scene.
const COUNT: usize = 100_000;
/// Frames counted per scene.
const FRAMES: u64 = 4;

/// Every scene the driver counts, and whether its `dt` varies.
fn scenes() -> Vec<(Method, bool)> {
    vec![
        (Method::Euler, false),
        (Method::BareExact, false),
        (Method::LanesModel, false),
        (Method::Springs { springs: 1 }, false),
        (Method::EulerUiScale, false),
        (Method::UiScaleSprings, false),
        (Method::UiTranslationSprings, false),
        (Method::Springs { springs: 1 }, true),
        (Method::Springs { springs: 8 }, true),
        (Method::Springs { springs: 0 }, true),
        (Method::SpringDamper { springs: 1 }, true),
        (Method::SpringDamper { springs: 8 }, true),
        (Method::SpringDamper { springs: 0 }, true),
        (Method::SpringsAtRest, false),
    ]
}

/// Scenes that only [`time`] runs (by name): no animation to count.
fn timed_only() -> Vec<Method> {
    vec![Method::Idle, Method::Touch]
}

fn method_named(name: &str) -> Method {
    scenes()
        .into_iter()
        .map(|(method, _)| method)
        .chain(timed_only())
        .find(|method| method.name() == name)
        .unwrap_or_else(|| panic!("no scene {name}"))
}

/// The frames callgrind counts.
#[inline(never)]
fn measured(app: &mut App, method: Method, frames: u64, vary: bool) {
    let schedule = method.schedule();
    for frame in 0..frames {
        let world = app.world_mut();
        Method::set_dt(world, if vary { varying_dt(frame) } else { FRAME });
        world.run_schedule(schedule);
    }
}

/// One scene, as callgrind runs it.
fn one(method: Method, count: usize, frames: u64, vary: bool) {
    let mut app = method.app(count, Propagation::Off);
    // Every schedule (the spring schedule too) on the calling thread: callgrind counts only the
    // thread `measured` runs on. The driver runs this with no compute threads, so the springs
    // step in one loop on this thread as well.
    for (_, schedule) in app.world_mut().resource_mut::<Schedules>().iter_mut() {
        schedule.set_executor(SingleThreadedExecutor::new());
    }
    // Warm-up: the first frames fill caches and allocate.
    measured_warm_up(&mut app, method, vary);
    measured(&mut app, method, frames, vary);
    let world = app.world_mut();
    let since = world.increment_change_tick();
    Method::set_dt(world, FRAME);
    world.run_schedule(method.schedule());
    method.check(world, count, since);
}

/// One scene's frames timed one by one (task pools as the criterion suite sets them): the
/// fastest and the median frame, for A/B comparisons that a busy machine's slow frames do not
/// blur. With `whole`, whole frames (`app.update()`: every schedule of `MinimalPlugins`, as a
/// game's frame runs them, with the time step set through Bevy's `TimeUpdateStrategy`) rather
/// than the animation's schedule alone, with transform propagation as `propagation` says.
fn time(
    method: Method,
    count: usize,
    frames: u64,
    vary: bool,
    whole: bool,
    propagation: Propagation,
) {
    let mut app = method.app(count, propagation);
    measured_warm_up(&mut app, method, vary);
    let schedule = method.schedule();
    let mut times: Vec<f64> = (0..frames)
        .map(|frame| {
            let dt = if vary { varying_dt(frame) } else { FRAME };
            let world = app.world_mut();
            if whole {
                world.insert_resource(TimeUpdateStrategy::ManualDuration(
                    core::time::Duration::from_secs_f32(dt),
                ));
            } else {
                Method::set_dt(world, dt);
            }
            let start = std::time::Instant::now();
            if whole {
                app.update();
            } else {
                world.run_schedule(schedule);
            }
            start.elapsed().as_secs_f64() * 1e6
        })
        .collect();
    times.sort_by(f64::total_cmp);
    println!(
        "{:<28} fastest {:8.1} µs  median {:8.1} µs",
        method.name(),
        times[0],
        times[times.len() / 2]
    );
}

#[inline(never)]
fn measured_warm_up(app: &mut App, method: Method, vary: bool) {
    let schedule = method.schedule();
    for frame in 100..102 {
        let world = app.world_mut();
        Method::set_dt(world, if vary { varying_dt(frame) } else { FRAME });
        world.run_schedule(schedule);
    }
}

/// Frames counted in the empty app.
const EMPTY_FRAMES: u64 = 100;

/// What the whole-frame app has besides `TransformPlugin`: `false` nothing, `true`
/// [`SpringPlugins`](bevy_sprung::SpringPlugins); with feature `debug` also: `gizmos` Bevy's
/// gizmos (what an app the overlay draws in has), `hidden` the debug overlay with every group
/// off, `shown` with every group on.
fn empty_setup(app: &mut App, setup: &str) {
    if setup == "false" {
        return;
    }
    app.add_plugins(bevy_sprung::SpringPlugins::default());
    if setup == "true" {
        return;
    }
    #[cfg(feature = "debug")]
    {
        use bevy_sprung::debug::SpringDebugPlugin;
        // What Bevy's gizmos need in a headless app.
        app.add_plugins((
            bevy::asset::AssetPlugin::default(),
            bevy::gizmos::GizmoPlugin,
        ))
        .init_asset::<Mesh>()
        .init_asset::<bevy::mesh::skinning::SkinnedMeshInverseBindposes>();
        match setup {
            "gizmos" => {}
            "hidden" => {
                app.add_plugins(SpringDebugPlugin::hidden());
            }
            "shown" => {
                app.add_plugins(SpringDebugPlugin::default());
            }
            other => panic!("no setup {other}"),
        }
    }
    #[cfg(not(feature = "debug"))]
    panic!("setup {setup} needs `--features debug`");
}

/// An app with nothing to spring (`TransformPlugin`, as any app with something to spring has),
/// set up as [`empty_setup`] says, with `springs` translation springs that keep moving, as
/// callgrind runs it.
fn empty(setup: &str, springs: usize, frames: u64) {
    use bevy_sprung::prelude::{Spring, TranslationSpring};
    let mut app = App::new();
    app.add_plugins((scenarios::minimal_plugins(), TransformPlugin));
    empty_setup(&mut app, setup);
    for index in 0..springs {
        #[expect(clippy::cast_precision_loss, reason = "a few entities")]
        let target = Vec3::splat(1e4 * (index + 1) as f32);
        app.world_mut().spawn((
            Transform::default(),
            TranslationSpring::new(Spring::molasses(), target),
        ));
    }
    app.finish();
    app.cleanup();
    for _ in 0..10 {
        app.update();
    }
    measured_updates(&mut app, frames);
}

/// The whole frames callgrind counts in the empty app.
#[inline(never)]
fn measured_updates(app: &mut App, frames: u64) {
    for _ in 0..frames {
        app.update();
    }
}

/// Runs one scene under callgrind and returns the instructions counted in [`measured`].
fn count(method: Method, vary: bool) -> u64 {
    callgrind(
        "*instructions::measured",
        Some(0),
        &[
            "one",
            &method.name(),
            &COUNT.to_string(),
            &FRAMES.to_string(),
            &vary.to_string(),
        ],
    )
}

/// Runs the mode `args` name (`one`, `time`, `overlay`, `empty`), if they name one.
fn run_mode(args: &[String]) -> bool {
    if args.first().map(String::as_str) == Some("one") {
        let method = method_named(&args[1]);
        one(
            method,
            args[2].parse().expect("a count"),
            args[3].parse().expect("a frame count"),
            args[4].parse().expect("true or false"),
        );
        return true;
    }
    if args.first().map(String::as_str) == Some("time") {
        let (whole, propagation) = match args.get(5).map(String::as_str) {
            None => (false, Propagation::Off),
            Some("whole") => (true, Propagation::Off),
            Some("static") => (true, Propagation::StaticScene),
            Some("moving") => (true, Propagation::MovingScene),
            Some(mode) => panic!("no mode {mode}: whole, static or moving"),
        };
        time(
            method_named(&args[1]),
            args[2].parse().expect("a count"),
            args[3].parse().expect("a frame count"),
            args[4].parse().expect("true or false"),
            whole,
            propagation,
        );
        return true;
    }
    #[cfg(feature = "debug")]
    if args.first().map(String::as_str) == Some("overlay") {
        overlay_cost();
        return true;
    }
    if args.first().map(String::as_str) == Some("empty") {
        empty(
            &args[1],
            args[2].parse().expect("a spring count"),
            args[3].parse().expect("a frame count"),
        );
        return true;
    }
    false
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if run_mode(&args) {
        return;
    }
    #[expect(clippy::cast_precision_loss, reason = "counts for a report")]
    let per_spring = |total: u64| total as f64 / (COUNT as f64 * FRAMES as f64);
    let mut results = Vec::new();
    println!("instructions per entity per frame ({COUNT} entities, {FRAMES} frames counted)");
    for (method, vary) in scenes() {
        let value = per_spring(count(method, vary));
        let dt = if vary { "dt varies" } else { "dt fixed" };
        println!("{:<28} {dt:<10} {value:>8.1}", method.name());
        results.push(((method, vary), value));
    }
    let get = |method: Method, vary: bool| {
        results
            .iter()
            .find(|(scene, _)| *scene == (method, vary))
            .map(|(_, value)| *value)
            .expect("counted")
    };
    let shared = Method::Springs { springs: 1 };
    println!("\nratios (instructions):");
    println!(
        "  translation, shared spring / Euler:          {:.2}",
        get(shared, false) / get(Method::Euler, false)
    );
    println!(
        "  UI scale / Euler on the UI scale:            {:.2}",
        get(Method::UiScaleSprings, false) / get(Method::EulerUiScale, false)
    );
    for springs in [1, 8, 0] {
        println!(
            "  {:<18} / spring_damper (dt varies):  {:.2}",
            Method::Springs { springs }.name(),
            get(Method::Springs { springs }, true) / get(Method::SpringDamper { springs }, true)
        );
    }
    println!(
        "  per entity / shared (dt varies):             {:.2}",
        get(Method::Springs { springs: 0 }, true) / get(shared, true)
    );
    println!(
        "  at rest / active:                            {:.3}",
        get(Method::SpringsAtRest, false) / get(shared, false)
    );
    let frames = EMPTY_FRAMES.to_string();
    let [without, with, one] =
        [("false", "0"), ("true", "0"), ("true", "1")].map(|(plugin, springs)| {
            // As games run: the multi-threaded executor, whose bookkeeping (what idle systems
            // cost) runs on the calling thread.
            callgrind(
                "*instructions::measured_updates",
                None,
                &["empty", plugin, springs, &frames],
            ) / EMPTY_FRAMES
        });
    println!(
        "\nwhole frames of an app with TransformPlugin, instructions per frame:\n  \
         without SpringPlugins {without}; with it and no springs {with} ({:+}); \
         with one moving translation spring {one} ({:+})",
        i128::from(with) - i128::from(without),
        i128::from(one) - i128::from(without)
    );
    #[cfg(feature = "debug")]
    overlay_cost();
}

/// Springs in whole frames with the debug overlay added, hidden and shown, against an app with
/// Bevy's gizmos and no overlay: what the overlay costs per frame, and per spring.
#[cfg(feature = "debug")]
fn overlay_cost() {
    const SPRINGS: u64 = 1000;
    const FRAMES: u64 = 10;
    let frames = FRAMES.to_string();
    let frame = |setup: &str, springs: u64| {
        callgrind(
            "*instructions::measured_updates",
            None,
            &["empty", setup, &springs.to_string(), &frames],
        ) / FRAMES
    };
    let [gizmos, hidden, shown] =
        ["gizmos", "hidden", "shown"].map(|setup| (frame(setup, 0), frame(setup, SPRINGS)));
    #[expect(
        clippy::cast_possible_wrap,
        reason = "instruction counts far below i64::MAX"
    )]
    let extra = |(none, many): (u64, u64)| {
        let fixed = none as i64 - gizmos.0 as i64;
        let per_spring = ((many as i64 - none as i64) - (gizmos.1 as i64 - gizmos.0 as i64)) as f64
            / SPRINGS as f64;
        (fixed, per_spring)
    };
    let (hidden_fixed, hidden_each) = extra(hidden);
    let (shown_fixed, shown_each) = extra(shown);
    println!(
        "\nthe debug overlay, whole frames, instructions, against an app with Bevy's gizmos and \
         no overlay ({} per frame without springs, {} with {SPRINGS} moving translation \
         springs):\n  added, every group off: {hidden_fixed:+} per frame, {hidden_each:+.2} per \
         spring\n  shown: {shown_fixed:+} per frame, {shown_each:+.0} per spring",
        gizmos.0, gizmos.1
    );
}
