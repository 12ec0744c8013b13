//! The free-rotation lab: perfect model, consistency of the integrators' error model, and
//! the bias drift the lab is there to show.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::scenario::Trace;
use attlab_tests::trace;

fn run(assignments: &[&str], seed: u64, duration_s: f64, series: &[&str]) -> Trace {
    trace("free-rotation", assignments, seed, duration_s, series)
}

#[test]
fn perfect_model_tracks_the_truth() {
    let s = run(
        &["gyro_noise_deg_s=0", "gyro_bias_deg_s=0"],
        1,
        30.0,
        &["quat-rk4.err_deg", "uvz-rk4.err_deg"],
    );
    for id in ["quat-rk4", "uvz-rk4"] {
        let err = s.last(format!("{id}.err_deg")).unwrap();
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
    let series = [
        "quat-rk4.err_x_deg",
        "quat-rk4.err_y_deg",
        "quat-rk4.err_z_deg",
        "quat-rk4.var_att_x",
    ];
    let mut sum = 0.0;
    for seed in 0..seeds {
        let s = run(
            &["gyro_noise_deg_s=0.5", "gyro_bias_deg_s=0"],
            seed,
            20.0,
            &series,
        );
        let e: f64 = series[..3]
            .iter()
            .map(|c| s.last(c).unwrap().to_radians().powi(2))
            .sum();
        sum += e / s.last("quat-rk4.var_att_x").unwrap();
    }
    let mean = sum / f64::from(seeds as u32);
    assert!((2.26..=3.87).contains(&mean), "mean NEES {mean}");
}

#[test]
fn bias_makes_integration_drift_and_larger_bias_drifts_more() {
    let series = ["quat-rk4.err_deg", "uvz-rk4.err_deg"];
    let small = run(
        &["gyro_noise_deg_s=0", "gyro_bias_deg_s=0.1"],
        1,
        30.0,
        &series,
    );
    let large = run(
        &["gyro_noise_deg_s=0", "gyro_bias_deg_s=1.0"],
        1,
        30.0,
        &series,
    );
    let (e1, e2) = (
        small.last(series[0]).unwrap(),
        large.last(series[0]).unwrap(),
    );
    assert!(e1 > 0.05, "0.1 °/s bias: {e1} deg");
    assert!(e2 > 5.0 * e1, "1 °/s bias: {e2} deg vs {e1} deg");
    // Both integrators see the same samples, so they drift identically.
    assert!((large.last(series[1]).unwrap() - e2).abs() < 1e-6);
}
