//! The free-rotation lab: perfect model, consistency of the integrators' error model, and
//! the bias drift the lab is there to show.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::params::ParamValues;
use attlab::sim::Simulation;

fn sim(assignments: &[&str], seed: u64, duration_s: f64) -> Simulation {
    let lab = labs::find("free-rotation").unwrap();
    let mut p = ParamValues::defaults(lab.params());
    assert!(
        p.apply_assignments(lab.params(), assignments.iter().copied())
            .is_empty()
    );
    let mut s = Simulation::with_history(lab, p, seed, (duration_s * 100.0) as usize + 10);
    s.run_for(duration_s);
    s
}

fn last(s: &Simulation, name: &str) -> f64 {
    let r = s.recorder();
    r.last(
        r.index_of(name)
            .unwrap_or_else(|| panic!("no series {name}")),
    )
    .unwrap()
}

#[test]
fn perfect_model_tracks_the_truth() {
    let s = sim(&["gyro_noise_deg_s=0", "gyro_bias_deg_s=0"], 1, 30.0);
    for id in ["quat-rk4", "uvz-rk4"] {
        let err = last(&s, &format!("{id}.err_deg"));
        assert!(
            err < 1e-3,
            "{id}: {err} deg after 30 s without sensor errors"
        );
    }
}

#[test]
fn noise_only_errors_are_consistent_with_the_published_variance() {
    // NEES = |e|²/σ² per run (3 axes); the mean over 40 seeds of a χ²(3) variable lies in
    // [χ²₁₂₀(0.005), χ²₁₂₀(0.995)]/40 = [2.26, 3.87] with 99 % probability.
    let seeds = 40;
    let mut sum = 0.0;
    for seed in 0..seeds {
        let s = sim(&["gyro_noise_deg_s=0.5", "gyro_bias_deg_s=0"], seed, 20.0);
        let e: f64 = ["err_x_deg", "err_y_deg", "err_z_deg"]
            .iter()
            .map(|c| last(&s, &format!("quat-rk4.{c}")).to_radians().powi(2))
            .sum();
        sum += e / last(&s, "quat-rk4.P_axis_rad2");
    }
    let mean = sum / f64::from(seeds as u32);
    assert!((2.26..=3.87).contains(&mean), "mean NEES {mean}");
}

#[test]
fn bias_makes_integration_drift_and_larger_bias_drifts_more() {
    let small = sim(&["gyro_noise_deg_s=0", "gyro_bias_deg_s=0.1"], 1, 30.0);
    let large = sim(&["gyro_noise_deg_s=0", "gyro_bias_deg_s=1.0"], 1, 30.0);
    let (e1, e2) = (
        last(&small, "quat-rk4.err_deg"),
        last(&large, "quat-rk4.err_deg"),
    );
    assert!(e1 > 0.05, "0.1 °/s bias: {e1} deg");
    assert!(e2 > 5.0 * e1, "1 °/s bias: {e2} deg vs {e1} deg");
    // Both integrators see the same samples, so they drift identically.
    assert!((last(&large, "uvz-rk4.err_deg") - e2).abs() < 1e-6);
}
