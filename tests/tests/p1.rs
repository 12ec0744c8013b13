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
