//! A live session (a phone's samples arriving in bursts, with the real world's trouble)
//! run as the page runs it — samples appended to the replay's log as they become final,
//! the loop stepping only onto samples it has — against the replay of its record, as
//! `attlab replay --lab p4 --log record.csv --accel-unit g --gyro-unit deg_s` makes it.
#![cfg(not(target_arch = "wasm32"))]

use attlab::model::ParamValues;
use attlab::sensors::IMU_LOG;
use attlab::sensors::live::{LiveStream, PHONE_SCALES, phone_line, zero_mount};
use attlab::sim::{Selection, SharedLog, SimOptions, Simulation};
use nalgebra::{UnitQuaternion, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The phone's true roll (rad) at `t` s: held level, then turned to 90° and held.
fn roll_rad(t: f64) -> f64 {
    let s = ((t - 4.0) / 3.0).clamp(0.0, 1.0);
    std::f64::consts::FRAC_PI_2 * (3.0 * s * s - 2.0 * s * s * s)
}

/// A phone at 60 Hz rolled about its long axis, with the Gyroscope sensor's rad/s and a
/// few real-world faults: jitter, a repeated event, two swapped, a 0.4-s stall (the tab in
/// the background), a wild timestamp. Each item is (arrival frame, line).
fn phone_session(mount: &UnitQuaternion<f64>) -> Vec<(usize, String)> {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut out = Vec::new();
    let dt = 1.0 / 60.0;
    for k in 0..1200 {
        let t = k as f64 * dt;
        if (6.0..6.4).contains(&t) {
            continue; // the stall
        }
        let jitter = rng.random_range(-0.5..0.5);
        let phi = roll_rad(t);
        let rate = (roll_rad(t + 1e-4) - roll_rad(t - 1e-4)) / 2e-4;
        // What the accelerometer reads (up, 1 g) in the phone's axes after a right-handed
        // turn φ about its long axis y (body x, the roll axis): x = −g sin φ, z = g cos φ.
        let g = 9.80665;
        let accel = Vector3::new(-g * phi.sin(), 0.0, g * phi.cos())
            + Vector3::from_fn(|_, _| rng.random_range(-0.05..0.05));
        let gyro =
            Vector3::new(0.0, rate, 0.0) + Vector3::from_fn(|_, _| rng.random_range(-0.002..0.002));
        let deg = 180.0 / std::f64::consts::PI;
        let line = phone_line(1000.0 * t + jitter, accel, gyro, deg, mount);
        let frame = (t / 0.05) as usize; // bursts of three
        out.push((frame, line.clone()));
        if k == 300 {
            out.push((frame, line.clone())); // the same event twice
        }
        if k == 400 {
            out.push((frame, format!("9e9{}", &line[line.find(',').unwrap()..])));
        }
    }
    out.swap(500, 501);
    out
}

fn options() -> SimOptions {
    SimOptions {
        selection: Selection::All,
        ..Default::default()
    }
}

/// Runs the session through paper 4's lab as the page does; returns every recorded row and
/// the record.
fn run_live(session: &[(usize, String)]) -> (Vec<Vec<f64>>, String, Simulation) {
    run_live_in("p4", session)
}

fn run_live_in(lab: &str, session: &[(usize, String)]) -> (Vec<Vec<f64>>, String, Simulation) {
    run_live_with(lab, session, options())
}

/// [`run_live_in`] recording what `options` select.
fn run_live_with(
    lab: &str,
    session: &[(usize, String)],
    options: SimOptions,
) -> (Vec<Vec<f64>>, String, Simulation) {
    let lab = attlab_tests::lab(lab);
    let params = ParamValues::defaults(lab.params());
    let mut stream = LiveStream::new(PHONE_SCALES);
    let log = SharedLog::default();
    let mut sim: Option<Simulation> = None;
    let mut rows = Vec::new();
    let last_frame = session.last().map_or(0, |(f, _)| *f);
    for frame in 0..=last_frame + 1 {
        for (_, line) in session.iter().filter(|(f, _)| *f == frame) {
            stream.push_line(line);
        }
        if frame > last_frame {
            stream.finish();
        }
        log.append(&stream.take_new());
        if sim.is_none() && log.read().t_s.len() >= 2 {
            let s = Simulation::live(lab, params.clone(), log.clone(), options.clone()).unwrap();
            rows.push(s.last_row().to_vec());
            sim = Some(s);
        }
        if let Some(s) = sim.as_mut() {
            while s.can_step() {
                s.step();
                rows.push(s.last_row().to_vec());
            }
        }
    }
    let record = stream.record("test session");
    (rows, record, sim.expect("the session ran"))
}

#[test]
fn a_recorded_live_session_replays_to_the_same_estimates() {
    let session = phone_session(&UnitQuaternion::identity());
    let (live_rows, record, live) = run_live(&session);
    // What `attlab replay --lab p4 --log record.csv --accel-unit g --gyro-unit deg_s` reads.
    let lab = attlab_tests::lab("p4");
    let mut units = IMU_LOG.default_units();
    for (key, value) in [
        ("accel_unit", "g"),
        ("gyro_unit", "deg_s"),
        ("time_unit", "ms"),
    ] {
        units.set_text(IMU_LOG.units, key, value).unwrap();
    }
    let log = attlab::labs::read_log(lab, record.as_bytes(), &units).unwrap();
    assert_eq!(
        log.errors.len(),
        1,
        "the wild time, again: {:?}",
        log.errors
    );
    let span = log.span_s();
    let params = ParamValues::defaults(lab.params());
    let mut replay = Simulation::replay(lab, params, log, options()).unwrap();
    let mut rows = vec![replay.last_row().to_vec()];
    while replay.t_s() < span - 1e-9 {
        replay.step();
        rows.push(replay.last_row().to_vec());
    }
    assert_eq!(replay.specs(), live.specs());
    assert_eq!(rows.len(), live_rows.len(), "steps");
    let mut compared = 0;
    for (k, (a, b)) in live_rows.iter().zip(&rows).enumerate() {
        for (j, (x, y)) in a.iter().zip(b).enumerate() {
            let same = (x.is_nan() && y.is_nan()) || (x - y).abs() <= 1e-9 * x.abs().max(1e-300);
            assert!(
                same,
                "step {k}, {}: live {x}, replay {y}",
                live.specs()[j].name
            );
            compared += usize::from(!x.is_nan());
        }
    }
    assert!(compared > 10_000, "{compared} numbers compared");
    // The estimate followed the phone: held at 90° after the turn.
    let kf = live.value("kf.angle_deg").unwrap();
    assert!((kf - 90.0).abs() < 3.0, "KF roll at the end: {kf}°");
}

#[test]
fn zero_takes_the_pose_held_then_as_level() {
    // "Zero" pressed while the phone was at 90° (its accelerometer read +1 g on body y):
    // from then on that pose is level, and the level start reads as a roll of −90°.
    let mount = zero_mount(Vector3::new(0.0, 1.0, 0.0));
    let session = phone_session(&mount);
    let (rows, _, live) = run_live(&session);
    let angle = live.series_index("kf.angle_deg").unwrap();
    let time = live.series_index("t_s").unwrap();
    let before_turn = rows
        .iter()
        .find(|r| r[time] >= 3.5)
        .expect("a row at 3.5 s");
    let (start, end) = (before_turn[angle], live.value("kf.angle_deg").unwrap());
    assert!(
        (start + 90.0).abs() < 3.0,
        "KF roll before the turn: {start}°"
    );
    assert!(end.abs() < 3.0, "KF roll at the end: {end}°");
}

/// The roll (deg) of estimator `id`'s vertical in body axes.
fn roll_of(sim: &Simulation, id: &str) -> f64 {
    let k = (sim.estimators().iter())
        .position(|e| e.id() == id)
        .unwrap_or_else(|| panic!("{} has no estimator {id}", sim.lab().id()));
    let up = sim.estimates()[k]
        .attitude
        .vertical_in_body()
        .expect("a vertical");
    up.y.atan2(up.z).to_degrees()
}

#[test]
fn a_phone_turns_paper_3s_estimates_on_the_sphere() {
    // Paper 3's estimators take the three gyro axes and the accelerometer: the tilt of the
    // accelerometer-aided ones (accelerometer only, the blend, the KF) follows the turn.
    let session = phone_session(&UnitQuaternion::identity());
    let (_, _, live) = run_live_in("p3", &session);
    for id in ["accel", "blend", "kf-uv"] {
        let roll = roll_of(&live, id);
        assert!((roll - 90.0).abs() < 3.0, "p3 {id}: roll {roll}°");
    }
    // The gyro-only integrators turn with the phone's gyro until the stall at 6 s.
    let before_stall: Vec<(usize, String)> = (session.iter())
        .filter(|(f, _)| (*f as f64) * 0.05 < 5.9)
        .cloned()
        .collect();
    let (_, _, live) = run_live_in("p3", &before_stall);
    let truth = roll_rad(live.t_s()).to_degrees();
    for id in ["uvz-rk4", "quat-rk4"] {
        let roll = roll_of(&live, id);
        assert!(
            (roll - truth).abs() < 1.0,
            "p3 {id}: {roll}° at {} s, phone at {truth}°",
            live.t_s()
        );
    }
}

/// A live run of paper 3 records what its sphere and w plane draw, as the simulated lab
/// does: each filter's vertical in body axes and its w = u + iv (they had been laid out as
/// a one-axis lab's, an angle each, because a log's truth had an angle). The truth's own
/// series and every error stay empty: a log has no truth (a NaN truth once gave the
/// full-attitude filters an error of exactly 0°).
#[test]
fn a_live_paper_3_run_records_its_filters_on_the_sphere() {
    let session = phone_session(&UnitQuaternion::identity());
    // Every series, and what the page records by default.
    for options in [options(), SimOptions::default()] {
        let (_, _, live) = run_live_with("p3", &session, options);
        assert!(!live.has_truth());
        let values = |name: &str| {
            let i = live.recorder().index_of(name);
            let i = i.unwrap_or_else(|| panic!("p3 live records no `{name}`"));
            live.recorder().recent_vec(i)
        };
        for e in live.estimators() {
            for q in ["k_x", "k_y", "k_z", "u", "v"] {
                let v = values(&format!("{}.{q}", e.id()));
                assert!(v.iter().any(|x| x.is_finite()), "{}.{q}: no value", e.id());
            }
        }
        // Every error, the full-attitude filters' err_deg among them, is empty.
        let rec = live.recorder();
        let errors: Vec<usize> = (0..rec.specs().len())
            .filter(|i| rec.specs()[*i].group == attlab::model::SeriesGroup::Error)
            .collect();
        for name in ["uvz-rk4.err_deg", "quat-rk4.err_deg"] {
            assert!(
                errors.iter().any(|i| rec.specs()[*i].name == name),
                "no {name}"
            );
        }
        for i in errors {
            let v = rec.recent_vec(i);
            assert!(
                v.iter().all(|x| x.is_nan()),
                "{} has values",
                rec.specs()[i].name
            );
        }
        // The accelerometer-aided filters end rolled +90°: their vertical along body +y.
        for id in ["accel", "blend", "kf-uv"] {
            let k_y = values(&format!("{id}.k_y"));
            let last = k_y.iter().rev().find(|x| x.is_finite()).expect("a value");
            assert!((last - 1.0).abs() < 0.01, "{id}'s k_y at the end: {last}");
        }
        for q in ["k_x", "k_y", "k_z", "u", "v"] {
            let v = values(&format!("truth.{q}"));
            assert!(v.iter().all(|x| x.is_nan()), "truth.{q} has values");
        }
    }
}
