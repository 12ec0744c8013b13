//! Paper 1 lab: the paper's findings about adaptation, checked on the simulated mock-up.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs::{self, p1_run_stats};
use attlab::params::ParamValues;
use attlab::sim::Simulation;

#[test]
fn without_adaptation_p_collapses_and_the_torsional_error_grows() {
    let lab = labs::find("p1").expect("p1 registered");
    let mut p = ParamValues::defaults(lab.params());
    p.set(lab.params(), "kf_window", 0.0).unwrap();
    let mut sim = Simulation::with_history(lab, p, 1, 4);
    let last = |sim: &Simulation, name: &str| {
        sim.recorder()
            .last(sim.recorder().index_of(name).unwrap())
            .unwrap()
    };
    let c0 = last(&sim, "kf-torsion.c_rad2_s2");
    sim.run_for(100.0);
    let err_100 = last(&sim, "kf-torsion.angle_err_deg").abs();
    sim.run_for(500.0);
    let c_end = last(&sim, "kf-torsion.c_rad2_s2");
    let err_600 = last(&sim, "kf-torsion.angle_err_deg").abs();
    assert!(c_end < c0 * 1e-3, "c: {c0:e} → {c_end:e}");
    assert!(
        err_600 > 3.0 * err_100 && err_600 > 5.0,
        "angle error {err_100} deg at 100 s, {err_600} deg at 600 s"
    );
}

#[test]
fn n100_beats_n1000_beats_no_adaptation_and_is_near_the_best_window() {
    let max_rot =
        |n: u32| p1_run_stats(&[&format!("kf_window={n}")], 1, 600.0, 10.0)[0].angle_max_deg;
    let sweep: Vec<(u32, f64)> = [0, 1, 10, 30, 100, 300, 1000, 3000]
        .iter()
        .map(|&n| (n, max_rot(n)))
        .collect();
    let at = |n: u32| sweep.iter().find(|x| x.0 == n).unwrap().1;
    assert!(at(100) < at(1000) && at(1000) < at(0), "{sweep:?}");
    assert!(at(3000) > at(1000), "N > 2000 is worse: {sweep:?}");
    let best = sweep
        .iter()
        .filter(|x| x.0 > 0)
        .map(|x| x.1)
        .fold(f64::INFINITY, f64::min);
    assert!(
        at(100) <= 2.0 * best,
        "N = 100 not near the best: {sweep:?}"
    );
}

#[test]
fn torsional_rate_estimate_stays_inside_the_noise_band_more_often() {
    let [rot, tor] = p1_run_stats(&["kf_window=1000"], 1, 600.0, 10.0);
    assert!(
        tor.rate_inside_noise_band > rot.rate_inside_noise_band,
        "torsional {tor:?} vs rotation {rot:?}"
    );
    assert!(tor.rate_rms_deg_s < rot.rate_rms_deg_s);
}

#[test]
fn the_window_sweep_agrees_with_a_direct_run_and_finds_a_best_window() {
    let lab = labs::find("p1").unwrap();
    let spec = lab.sweeps()[0];
    let mut sweep = attlab::sweep::Sweep::new(lab, spec, ParamValues::defaults(lab.params()), 1);
    let mut calls = 0;
    while !sweep.advance(50_000) {
        calls += 1;
        assert!(sweep.progress() < 1.0 && calls < 10_000);
    }
    assert_eq!(sweep.points.len(), spec.values.len());
    let at_100 = sweep.points.iter().find(|p| p.value == 100.0).unwrap();
    let direct =
        p1_run_stats(&["kf_window=100"], 1, spec.duration_s, spec.after_s)[0].angle_rms_deg;
    assert!(
        (at_100.rms[0] - direct).abs() <= 1e-12 * direct,
        "sweep {} vs direct {direct}",
        at_100.rms[0]
    );
    let (best_n, best) = sweep.best(0).unwrap();
    assert!(
        at_100.rms[0] <= 2.0 * best,
        "best N = {best_n} with {best} deg, N = 100 gives {}",
        at_100.rms[0]
    );
}

#[test]
fn a_recorded_log_with_junk_lines_replays_through_the_filters() {
    // A log of the undamped pendulum φ = 360° cos Ωt at 100 Hz, in the lab's own units
    // (ms and millidegrees per second), with bad lines mixed in.
    let lab = labs::find("p1").unwrap();
    let mut p = ParamValues::defaults(lab.params());
    p.set(lab.params(), "damping_ratio", 0.0).unwrap();
    let omega = std::f64::consts::TAU / labs::p1_true_period_s(&p);
    let mut text = String::from("time_ms,rate_mdeg_s\n");
    for k in 0..6000 {
        let t = k as f64 * 0.01;
        let rate_deg_s = -360.0 * omega * (omega * t).sin();
        text += &format!("{},{}\n", t * 1e3, rate_deg_s * 1e3);
        if k == 100 {
            text += "1005,not-a-rate\n";
        }
        if k == 2000 {
            text += "garbage\n";
        }
    }
    let log = attlab::sensors::parse_rate_log(
        &text,
        attlab::sensors::RateUnit::MilliDegPerS,
        attlab::sensors::TimeUnit::Milliseconds,
    );
    assert_eq!(log.errors.len(), 2);
    assert_eq!(log.errors[0].line, 103);
    assert_eq!(log.t_s.len(), 6000);
    let mut sim = Simulation::replay(lab, p, log, 8).unwrap();
    sim.run_for(59.9);
    let phi_true = 360.0 * (omega * sim.t_s()).cos();
    let r = sim.recorder();
    let kf = r.last(r.index_of("kf-torsion.angle_deg").unwrap()).unwrap();
    assert!(
        (kf - phi_true).abs() < 0.2,
        "torsional KF {kf} deg vs {phi_true} deg"
    );
}
