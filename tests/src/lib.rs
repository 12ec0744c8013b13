//! Shared helpers for the Attitude Lab test suites: random attitudes, angle comparisons and
//! the golden scenario that native and browser runs must agree on.

use attlab::labs;
use attlab::params::ParamValues;
use attlab::sim::Simulation;
use std::f64::consts::{PI, TAU};

/// Difference of two angles wrapped to (−π, π].
pub fn angle_diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    if d > PI { d - TAU } else { d }
}

/// The golden scenario: free rotation, seed 7, noise and bias on, 10 s at 100 Hz.
pub fn golden_run() -> Simulation {
    let lab = labs::find("free-rotation").expect("registered");
    let mut p = ParamValues::defaults(lab.params());
    let errors = p.apply_assignments(
        lab.params(),
        [
            "gyro_noise_deg_s=0.05",
            "gyro_bias_deg_s=0.2",
            "gyro_walk_deg_s_sqrt_s=0.01",
        ],
    );
    assert!(errors.is_empty(), "{errors:?}");
    let mut sim = Simulation::with_history(lab, p, 7, 4);
    sim.run_for(10.0);
    sim
}

/// Values of the golden run's last row that are compared across platforms, by series name.
pub const GOLDEN_SERIES: &[&str] = &[
    "truth.yaw_deg",
    "truth.pitch_deg",
    "truth.roll_deg",
    "quat-rk4.yaw_deg",
    "quat-rk4.err_deg",
    "uvz-rk4.pitch_deg",
    "uvz-rk4.err_deg",
    "uvz-rk4.P_axis_rad2",
];

/// The golden values, computed natively (see `golden.rs`, which checks and can print them).
pub const GOLDEN_VALUES: &[f64] = &[
    10.94222678100655,
    -18.61883488801251,
    61.85298985972472,
    10.359708488303822,
    1.931445912798706,
    -18.815604350450197,
    1.9314459126690424,
    0.0012185458335017398,
];

/// The golden run's values of [`GOLDEN_SERIES`].
pub fn golden_values(sim: &Simulation) -> Vec<f64> {
    let rec = sim.recorder();
    GOLDEN_SERIES
        .iter()
        .map(|name| {
            rec.index_of(name)
                .and_then(|i| rec.last(i))
                .unwrap_or(f64::NAN)
        })
        .collect()
}

/// Largest relative difference between two equally long slices (absolute below 1e-12).
pub fn max_relative_diff(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / x.abs().max(y.abs()).max(1e-12))
        .fold(0.0, f64::max)
}
