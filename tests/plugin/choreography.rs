//! Choreography: sequences (order, timing against the exact settle times, interruption),
//! delays, stagger, loops, group completion; reduced motion; springs as curves.

use std::sync::{Arc, Mutex};

use bevy::prelude::*;
use bevy_sprung::choreography::SequencePhase;
use bevy_sprung::choreography::{
    AllSpringsSettled, OnInterrupt, Repeat, SequenceCompleted, SequenceInterrupted, SpringGroup,
    SpringGroupSettled,
};
use bevy_sprung::prelude::*;
use bevy_sprung::reduced_motion::KeepMotion;
use bevy_sprung::spring::SpringAsleep;

use crate::harness::{app, elapsed, motion, run, targets_visited, translation, translation_spring};

/// What happened, in order: `(seconds, what)`.
#[derive(Resource, Clone, Default)]
struct Log(Arc<Mutex<Vec<(f64, String)>>>);

impl Log {
    fn push(&self, seconds: f64, what: impl Into<String>) {
        self.0.lock().unwrap().push((seconds, what.into()));
    }

    fn entries(&self) -> Vec<(f64, String)> {
        self.0.lock().unwrap().clone()
    }

    fn times_of(&self, what: &str) -> Vec<f64> {
        self.entries()
            .into_iter()
            .filter(|(_, entry)| entry == what)
            .map(|(time, _)| time)
            .collect()
    }
}

/// An app that logs settle, completion and interruption events of translation springs.
fn logging_app(fps: u32) -> (App, Log) {
    let mut app = app(fps);
    let log = Log::default();
    app.insert_resource(log.clone())
        .add_observer(
            |settled: On<SpringSettled<Translation>>, time: Res<Time<Virtual>>, log: Res<Log>| {
                log.push(
                    time.elapsed_secs_f64(),
                    format!("settled {}", settled.entity),
                );
            },
        )
        .add_observer(
            |done: On<SequenceCompleted<Translation>>, time: Res<Time<Virtual>>, log: Res<Log>| {
                log.push(
                    time.elapsed_secs_f64(),
                    format!("completed {}", done.entity),
                );
            },
        )
        .add_observer(
            |stop: On<SequenceInterrupted<Translation>>,
             time: Res<Time<Virtual>>,
             log: Res<Log>| {
                log.push(
                    time.elapsed_secs_f64(),
                    format!("interrupted {}", stop.entity),
                );
            },
        );
    (app, log)
}

/// The seconds a critically damped spring takes from rest `distance` away to within the
/// translation spring's default tolerance.
fn settle_time(spring: &Spring, distance: f32) -> f64 {
    f64::from(spring.settle_time(distance, 1e-3).unwrap())
}

#[test]
fn a_sequence_visits_its_targets_in_order_each_when_the_last_settled() {
    let (mut app, log) = logging_app(120);
    let spring = Spring::from_half_life(0.05).unwrap();
    let targets = [
        Vec3::new(10.0, 0.0, 0.0),
        Vec3::new(10.0, 20.0, 0.0),
        Vec3::ZERO,
    ];
    // The speed tolerance of equal energy, so that the offset's settle time is the analytic one.
    let rest = RestThreshold::for_spring(&spring, 1e-3);
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(spring, Vec3::ZERO).with_rest(rest),
            SpringSequence::<Translation>::new()
                .then(targets[0])
                .then(targets[1])
                .then(targets[2]),
        ))
        .id();
    let visited = targets_visited(&mut app, entity, 600);
    // The three steps, in order (the first is set on the first update).
    assert_eq!(visited, targets);
    assert_eq!(translation(&app, entity), Vec3::ZERO);
    let settles = log.times_of(&format!("settled {entity}"));
    assert_eq!(settles.len(), 3, "{:?}", log.entries());
    // Each segment takes its exact settle time (from rest: each starts where the last settled),
    // plus at most a frame for the step to start and a frame to detect rest.
    let frame = 1.0 / 120.0;
    let mut start = frame; // The first update has dt = 0; the sequence starts on it.
    for (settled, distance) in settles.iter().zip([10.0, 20.0, 22.36]) {
        let expected = settle_time(&spring, distance);
        let took = settled - start;
        assert!(
            took <= expected + 2.0 * frame && took >= 0.5 * expected,
            "segment of {distance}: {took:.4} s, expected {expected:.4} s"
        );
        start = *settled;
    }
    let completed = log.times_of(&format!("completed {entity}"));
    assert_eq!(completed.len(), 1);
    assert!(completed[0] >= settles[2] && completed[0] <= settles[2] + 2.0 * frame);
    assert!(
        app.world()
            .get::<SpringSequence<Translation>>(entity)
            .unwrap()
            .is_finished()
    );
}

#[test]
fn a_timed_step_moves_on_after_its_time_with_the_velocity_kept() {
    let mut app = app(100);
    let spring = Spring::from_natural_frequency(6.0, 0.8).unwrap();
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(spring, Vec3::ZERO),
            SpringSequence::<Translation>::new()
                .then_after(0.25, Vec3::X * 100.0)
                .then(Vec3::Y * 100.0),
        ))
        .id();
    let mut switched_at = None;
    for _ in 0..100 {
        let velocity_before = motion::<Translation>(&app, entity).velocity();
        app.update();
        if switched_at.is_none() && translation_spring(&app, entity).target() == Vec3::Y * 100.0 {
            switched_at = Some(elapsed(&app));
            // Still moving along +x: the new target bent the motion, it did not restart it.
            assert!(velocity_before.x > 10.0);
            assert!(motion::<Translation>(&app, entity).velocity().x > 0.5 * velocity_before.x);
        }
    }
    let switched_at = switched_at.expect("the timed step moved on");
    // The step began on the first update (t = 0) and lasts 0.25 s: it ends within a frame.
    assert!(
        (0.25..=0.25 + 0.011).contains(&switched_at),
        "moved on at {switched_at}"
    );
}

#[test]
fn a_delay_holds_the_spring_and_stagger_offsets_each_start() {
    let mut app = app(200);
    let spring = Spring::snappy();
    let entities: Vec<Entity> = (0..4)
        .map(|index| {
            app.world_mut()
                .spawn((
                    Transform::default(),
                    TranslationSpring::new(spring, Vec3::ZERO),
                    SpringSequence::<Translation>::new()
                        .delayed(0.1)
                        .staggered(index, 0.05)
                        .then(Vec3::X * 50.0),
                ))
                .id()
        })
        .collect();
    let mut started = vec![None; entities.len()];
    for _ in 0..200 {
        app.update();
        let now = elapsed(&app);
        for (index, &entity) in entities.iter().enumerate() {
            if started[index].is_none() && translation(&app, entity).x > 0.0 {
                started[index] = Some(now);
            }
        }
    }
    for (index, start) in started.iter().enumerate() {
        let start = start.expect("every item started");
        // `staggered` replaces the delay: entity `index` waits `index × 0.05` s; it moves in
        // the frame its wait ends (within a frame, and not before).
        #[expect(clippy::cast_precision_loss, reason = "small index")]
        let due = index as f64 * 0.05;
        assert!(
            start >= due && start <= due + 2.0 / 200.0,
            "item {index} started at {start}, due {due}"
        );
    }
}

#[test]
fn loops_cycle_and_ping_pong_a_given_number_of_times_then_complete_once() {
    let (mut app, log) = logging_app(120);
    let spring = Spring::from_half_life(0.02).unwrap();
    let cycle = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(spring, Vec3::ZERO),
            SpringSequence::<Translation>::new()
                .then(Vec3::X)
                .then(Vec3::Y)
                .repeat(Repeat::Times(3)),
        ))
        .id();
    let ping_pong = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(spring, Vec3::ZERO),
            SpringSequence::<Translation>::new()
                .then(Vec3::X)
                .then(Vec3::Y)
                .then(Vec3::Z)
                .ping_pong()
                .repeat(Repeat::Times(3)),
        ))
        .id();
    let mut visits = [Vec::new(), Vec::new()];
    for _ in 0..1200 {
        app.update();
        for (visits, entity) in visits.iter_mut().zip([cycle, ping_pong]) {
            let target = translation_spring(&app, entity).target();
            if visits.last() != Some(&target) {
                visits.push(target);
            }
        }
    }
    let (x, y, z) = (Vec3::X, Vec3::Y, Vec3::Z);
    assert_eq!(visits[0], [x, y, x, y, x, y]);
    // Forward, back, forward: the turning points are not repeated.
    assert_eq!(visits[1], [x, y, z, y, x, y, z]);
    for entity in [cycle, ping_pong] {
        assert_eq!(log.times_of(&format!("completed {entity}")).len(), 1);
        let sequence = app
            .world()
            .get::<SpringSequence<Translation>>(entity)
            .unwrap();
        assert_eq!(sequence.plays(), 3);
    }
}

#[test]
fn a_forever_loop_keeps_going() {
    let mut app = app(60);
    let entity = app
        .world_mut()
        .spawn((
            Transform::default(),
            ScaleSpring::new(Spring::gentle(), Vec3::ONE),
            SpringSequence::<Scale>::new()
                .then_after(0.2, Vec3::splat(1.2))
                .then_after(0.2, Vec3::ONE)
                .repeat(Repeat::Forever),
        ))
        .id();
    run(&mut app, 60 * 10);
    let sequence = app.world().get::<SpringSequence<Scale>>(entity).unwrap();
    assert_eq!(sequence.phase(), SequencePhase::Playing);
    // 10 s of 0.4 s loops.
    assert!(
        (24..=26).contains(&sequence.plays()),
        "{}",
        sequence.plays()
    );
    assert!(app.world().get::<SpringAsleep<Scale>>(entity).is_none());
}

#[test]
fn an_interruption_cancels_or_pauses_and_keeps_the_velocity() {
    let (mut app, log) = logging_app(60);
    let spring = Spring::from_natural_frequency(5.0, 0.7).unwrap();
    let spawn = |app: &mut App, on_interrupt| {
        app.world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(spring, Vec3::ZERO),
                SpringSequence::<Translation>::new()
                    .then(Vec3::X * 100.0)
                    .then(Vec3::Y * 100.0)
                    .on_interrupt(on_interrupt),
            ))
            .id()
    };
    let cancelled = spawn(&mut app, OnInterrupt::Cancel);
    let paused = spawn(&mut app, OnInterrupt::Pause);
    run(&mut app, 12);
    let before = motion::<Translation>(&app, cancelled).velocity();
    assert!(before.x > 10.0);
    for entity in [cancelled, paused] {
        app.world_mut()
            .get_mut::<TranslationSpring>(entity)
            .unwrap()
            .set_target(Vec3::new(-30.0, 0.0, 0.0));
    }
    app.update();
    // The interrupting target stands, and the motion carries on from the same velocity.
    let after = motion::<Translation>(&app, cancelled).velocity();
    assert!(after.x > 0.5 * before.x, "{before} → {after}");
    for entity in [cancelled, paused] {
        assert_eq!(
            translation_spring(&app, entity).target(),
            Vec3::new(-30.0, 0.0, 0.0)
        );
        assert_eq!(log.times_of(&format!("interrupted {entity}")).len(), 1);
    }
    let phase = |app: &App, entity| {
        app.world()
            .get::<SpringSequence<Translation>>(entity)
            .unwrap()
            .phase()
    };
    assert_eq!(phase(&app, cancelled), SequencePhase::Finished);
    assert_eq!(phase(&app, paused), SequencePhase::Paused);
    run(&mut app, 600);
    assert_eq!(translation(&app, cancelled), Vec3::new(-30.0, 0.0, 0.0));
    assert_eq!(translation(&app, paused), Vec3::new(-30.0, 0.0, 0.0));
    // The paused one goes on from its step when resumed.
    app.world_mut()
        .get_mut::<SpringSequence<Translation>>(paused)
        .unwrap()
        .resume();
    run(&mut app, 600);
    assert_eq!(translation(&app, paused), Vec3::Y * 100.0);
    assert_eq!(log.times_of(&format!("completed {paused}")).len(), 1);
    assert!(log.times_of(&format!("completed {cancelled}")).is_empty());
}

/// Group and entity completion events, counted.
#[derive(Resource, Default)]
struct Reports {
    groups: Vec<String>,
    entities: Vec<Entity>,
}

#[test]
fn a_group_reports_once_when_all_its_springs_settled() {
    let mut app = app(60);
    app.init_resource::<Reports>()
        .add_observer(
            |settled: On<SpringGroupSettled>, mut reports: ResMut<Reports>| {
                reports.groups.push(settled.group.to_string());
            },
        )
        .add_observer(
            |settled: On<AllSpringsSettled>, mut reports: ResMut<Reports>| {
                reports.entities.push(settled.entity);
            },
        );
    // Three entities: a quick translation, a slow scale, and both on one entity.
    let quick = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::X),
            SpringGroup::named("menu"),
        ))
        .id();
    let slow = app
        .world_mut()
        .spawn((
            Transform::default(),
            ScaleSpring::new(Spring::molasses(), Vec3::splat(2.0)),
            SpringGroup::named("menu"),
        ))
        .id();
    let both = app
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::Y),
            ScaleSpring::new(Spring::slow(), Vec3::splat(0.5)),
            SpringGroup::this_entity(),
        ))
        .id();
    let mut menu_settled_when = None;
    for frame in 0..600 {
        app.update();
        let reports = app.world().resource::<Reports>();
        if menu_settled_when.is_none() && reports.groups.contains(&"menu".to_string()) {
            menu_settled_when = Some(frame);
            // The whole group: the slow scale too.
            assert!(app.world().get::<SpringAsleep<Scale>>(slow).is_some());
            assert!(
                app.world()
                    .get::<SpringAsleep<Translation>>(quick)
                    .is_some()
            );
        }
    }
    let reports = app.world().resource::<Reports>();
    assert_eq!(reports.groups, ["menu"], "once, and only the named group");
    // Each entity once, the one with two springs when both settled.
    for entity in [quick, slow, both] {
        assert_eq!(
            reports.entities.iter().filter(|&&e| e == entity).count(),
            1,
            "{entity}"
        );
    }
    assert!(app.world().get::<SpringAsleep<Scale>>(both).is_some());
    // Moving again, it reports again.
    app.world_mut()
        .get_mut::<TranslationSpring>(quick)
        .unwrap()
        .set_target(Vec3::ZERO);
    run(&mut app, 120);
    assert_eq!(app.world().resource::<Reports>().groups, ["menu", "menu"]);
}

#[test]
fn reduced_motion_snaps_calms_or_scales_and_keep_motion_opts_out() {
    let bouncy = Spring::from_natural_frequency(12.0, 0.2).unwrap();
    let run_with = |preference: ReducedMotion, keep: bool| {
        let (mut app, log) = logging_app(60);
        app.insert_resource(preference);
        let entity = app
            .world_mut()
            .spawn((
                Transform::default(),
                TranslationSpring::new(bouncy, Vec3::X * 10.0),
            ))
            .id();
        if keep {
            app.world_mut().entity_mut(entity).insert(KeepMotion);
        }
        let mut peak = 0.0_f32;
        for _ in 0..600 {
            app.update();
            peak = peak.max(translation(&app, entity).x);
        }
        let settled = log.times_of(&format!("settled {entity}"));
        assert_eq!(
            settled.len(),
            1,
            "{preference:?}: settle events still fire once"
        );
        assert_eq!(translation(&app, entity), Vec3::X * 10.0);
        (peak, settled[0])
    };
    let (full_peak, full_time) = run_with(ReducedMotion::Full, false);
    assert!(
        full_peak > 13.0,
        "the bouncy spring overshoots: {full_peak}"
    );
    // Snap: there on the first update.
    let (_, snap_time) = run_with(ReducedMotion::Snap, false);
    assert!(snap_time <= 1.0 / 60.0 + 1e-9, "snapped at {snap_time}");
    // No overshoot, about as quick (critically damped at the same natural frequency).
    let (calm_peak, calm_time) = run_with(ReducedMotion::NoOvershoot, false);
    assert!(calm_peak <= 10.0, "overshot to {calm_peak}");
    assert!(calm_time < full_time, "{calm_time} vs {full_time}");
    // Half the duration: the same motion twice as fast.
    let (scaled_peak, scaled_time) = run_with(ReducedMotion::Scaled(0.5), false);
    assert!((scaled_peak - full_peak).abs() < 0.05 * full_peak);
    assert!(
        (scaled_time - full_time / 2.0).abs() <= 2.0 / 60.0,
        "{scaled_time} vs {full_time}"
    );
    // Opted out: as if nothing were reduced.
    let (kept_peak, kept_time) = run_with(ReducedMotion::Snap, true);
    assert_eq!((kept_peak, kept_time), (full_peak, full_time));
}

#[test]
fn a_spring_curve_is_the_closed_form() {
    use bevy::math::curve::Curve;
    use bevy_sprung::curve::{SpringCurve, SpringEasing};

    let spring = Spring::from_natural_frequency(7.0, 0.3).unwrap();
    let exact = sprung::Spring::<f64>::from(spring);
    let (start, target, velocity) = (
        Vec3::new(3.0, -2.0, 1.0),
        Vec3::new(-5.0, 8.0, 0.5),
        Vec3::new(40.0, 0.0, -3.0),
    );
    let curve = SpringCurve::new(spring, start, target).with_velocity(velocity);
    let end = curve.domain().end();
    assert!(end > 0.0);
    for i in 0..=200 {
        let t = end * i as f32 / 200.0;
        let sample = curve.sample_clamped(t);
        for axis in 0..3 {
            let state = exact.transition(f64::from(t)).step(
                sprung::SpringState::new(f64::from(start[axis]), f64::from(velocity[axis])),
                f64::from(target[axis]),
            );
            // The end of the domain is the target itself (it has settled within 1e-3 there).
            let tolerance = if i == 200 { 1e-3 } else { 2e-5 };
            assert!(
                (f64::from(sample[axis]) - state.position).abs() <= tolerance,
                "t = {t}, axis {axis}: {} vs {}",
                sample[axis],
                state.position
            );
        }
    }
    assert_eq!(curve.sample_clamped(end), target);
    // The easing is the normalised step response from rest.
    let easing = SpringEasing::new(spring);
    let duration = easing.settle_time();
    for i in 0..100 {
        let s = i as f32 / 100.0;
        let [[f0, _], _] = exact.transition(f64::from(s * duration)).matrix();
        assert!(
            (f64::from(easing.ease(s)) - (1.0 - f0)).abs() < 1e-6,
            "s = {s}"
        );
    }
    assert_eq!(easing.ease(1.0), 1.0);
}

/// What a toast does over time: when it is first visually there (within half a pixel of where
/// it shows, slowly), and when its target leaves for the exit.
fn toast_timing(sequence: SpringSequence<Translation>) -> (f64, f64) {
    let mut app = app(60);
    let (shown, hidden) = (Vec3::new(0.0, 40.0, 0.0), Vec3::new(0.0, -80.0, 0.0));
    let toast = app
        .world_mut()
        .spawn((
            Transform::from_translation(hidden),
            TranslationSpring::new(Spring::snappy(), hidden),
            sequence,
        ))
        .id();
    let omega: f32 = Spring::snappy().natural_frequency();
    let (mut there, mut left) = (None, None);
    for _ in 0..600 {
        app.update();
        let (position, velocity) = (
            translation(&app, toast),
            motion::<Translation>(&app, toast).velocity(),
        );
        if there.is_none() && position.distance(shown) <= 0.5 && velocity.length() <= 0.5 * omega {
            there = Some(elapsed(&app));
        }
        if left.is_none() && translation_spring(&app, toast).target() == hidden && there.is_some() {
            left = Some(elapsed(&app));
        }
    }
    (there.unwrap(), left.unwrap())
}

/// A toast that "stays 2 s" stays 2 s: `then_within` moves on when the toast is visually there,
/// and `hold` keeps it there for its time; a step that waits for the strict settle holds it
/// noticeably longer than asked.
#[test]
fn a_hold_after_a_step_within_a_distance_lasts_its_time_on_screen() {
    let (shown, hidden) = (Vec3::new(0.0, 40.0, 0.0), Vec3::new(0.0, -80.0, 0.0));
    let frame = 1.0 / 60.0;
    let (there, left) = toast_timing(
        SpringSequence::new()
            .then_within(0.5, shown)
            .hold(2.0)
            .then(hidden),
    );
    // Seen the frame after it is there (the sequence reads the last step's state), and moved
    // on the frame its time is up: within three frames.
    let on_screen = left - there;
    assert!(
        (on_screen - 2.0).abs() <= 3.0 * frame,
        "stayed {on_screen:.3} s"
    );
    let (there, left) = toast_timing(SpringSequence::new().then(shown).hold(2.0).then(hidden));
    let on_screen = left - there;
    assert!(on_screen > 2.2, "on settle: stayed {on_screen:.3} s");
}

/// A hold first waits before the sequence starts, as a delay does.
#[test]
fn a_first_hold_is_a_delay() {
    let sequence = SpringSequence::<Translation>::new().hold(0.5).then(Vec3::X);
    assert_eq!(sequence.steps().len(), 1);
    let delayed = SpringSequence::<Translation>::new()
        .delayed(0.5)
        .then(Vec3::X);
    let (mut a, mut b) = (app(60), app(60));
    let one = a
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::ZERO),
            sequence,
        ))
        .id();
    let two = b
        .world_mut()
        .spawn((
            Transform::default(),
            TranslationSpring::new(Spring::snappy(), Vec3::ZERO),
            delayed,
        ))
        .id();
    for _ in 0..120 {
        a.update();
        b.update();
        assert_eq!(translation(&a, one), translation(&b, two));
    }
    assert!(translation(&a, one).x > 0.5);
}
