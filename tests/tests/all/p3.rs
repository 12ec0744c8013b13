//! Paper 3 lab: the paper's findings and the Kalman filter's consistency.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::scenario::Trace;
use attlab::analysis::stats;
use attlab_tests::trace;

fn run(assignments: &[&str], seed: u64, duration_s: f64, series: &[&str]) -> Trace {
    trace("p3", assignments, seed, duration_s, series)
}

fn rms_after(t: &Trace, name: &str, after_s: f64) -> f64 {
    stats::rms(&t.after(name, after_s).unwrap()).unwrap()
}

fn last(t: &Trace, name: &str) -> f64 {
    t.last(name).unwrap()
}

#[test]
fn blending_removes_the_drift_and_the_noise() {
    let s = run(
        &[],
        1,
        100.0,
        &[
            "uvz-rk4.tilt_err_deg",
            "blend.tilt_err_deg",
            "accel.tilt_err_deg",
        ],
    );
    let gyro = last(&s, "uvz-rk4.tilt_err_deg");
    let blend = last(&s, "blend.tilt_err_deg");
    assert!(gyro > 5.0, "gyro-only tilt error after 100 s: {gyro} deg");
    assert!(
        blend < gyro / 20.0,
        "blend {blend} deg vs gyro-only {gyro} deg"
    );
    let (accel_rms, blend_rms) = (
        rms_after(&s, "accel.tilt_err_deg", 5.0),
        rms_after(&s, "blend.tilt_err_deg", 5.0),
    );
    assert!(
        blend_rms < accel_rms / 3.0,
        "blend rms {blend_rms} vs accel rms {accel_rms}"
    );
}

#[test]
fn longer_time_constant_trusts_the_gyro_longer() {
    // With the bias on, a long T lets the gyro drift through; a short T lets the noise in.
    let series = ["blend.tilt_err_deg", "blend.hpf_v"];
    let short = run(&["blend_time_const_s=0.05"], 1, 60.0, &series);
    let long = run(&["blend_time_const_s=50"], 1, 60.0, &series);
    let default = run(&[], 1, 60.0, &series);
    assert!(
        rms_after(&long, "blend.tilt_err_deg", 30.0)
            > 2.0 * rms_after(&default, "blend.tilt_err_deg", 30.0)
    );
    assert!(
        rms_after(&short, "blend.hpf_v", 5.0) < rms_after(&long, "blend.hpf_v", 5.0),
        "HPF(v) carries less when T is short"
    );
}

#[test]
fn a_lateral_bump_fools_the_accelerometer_more_than_the_blend() {
    // A 0.5 g bump (1 s wide) tilts the accelerometer's vertical by atan(0.5) ≈ 27°. The
    // blend low-passes it with T: at T = 1 s the bump is about as fast as T and partly gets
    // through; at T = 10 s most of it is filtered out.
    let peak = |t_const: &str, id: &str| {
        let name = format!("{id}.tilt_err_deg");
        let s = run(
            &["bump_g=0.5", "bump_time_s=30", "accel_noise_g=0", t_const],
            1,
            40.0,
            &[&name],
        );
        let window: Vec<f64> = s
            .t_s()
            .iter()
            .zip(s.series(&name).unwrap())
            .filter(|(t, _)| (27.0..35.0).contains(*t))
            .map(|(_, v)| *v)
            .collect();
        stats::max(&window).unwrap()
    };
    let accel = peak("blend_time_const_s=1", "accel");
    assert!(
        (25.0..28.0).contains(&accel),
        "accelerometer tilt error in the bump: {accel} deg"
    );
    let (blend_1, blend_10) = (
        peak("blend_time_const_s=1", "blend"),
        peak("blend_time_const_s=10", "blend"),
    );
    assert!(blend_1 < accel, "T = 1 s: blend {blend_1} vs accel {accel}");
    assert!(
        blend_10 < accel / 3.0,
        "T = 10 s: blend {blend_10} vs accel {accel}"
    );
}

#[test]
fn upside_down_tumble_keeps_every_estimate_bounded() {
    let s = run(
        &["profile=2"],
        3,
        100.0,
        &[
            "truth.k_z",
            "blend.tilt_err_deg",
            "kf-uv.tilt_err_deg",
            "uvz-rk4.err_deg",
            "quat-rk4.err_deg",
        ],
    );
    assert!(stats::min(s.series("truth.k_z").unwrap()).unwrap() < -0.95);
    for id in ["blend", "kf-uv"] {
        let m = stats::max(s.series(format!("{id}.tilt_err_deg")).unwrap()).unwrap();
        assert!(m < 2.0, "{id}: max tilt error {m} deg through w = ∞");
    }
    let d: Vec<f64> = s
        .series("uvz-rk4.err_deg")
        .unwrap()
        .iter()
        .zip(s.series("quat-rk4.err_deg").unwrap())
        .map(|(x, y)| x - y)
        .collect();
    let d = stats::max_abs(&d).unwrap();
    assert!(
        d < 1e-6,
        "(u,v,z) and quaternion integrators differ by {d} deg"
    );
}

#[test]
fn kalman_filter_nees_is_within_chi_square_bounds() {
    // Without bias the filter's model is exact. NEES = eᵀP⁻¹e of (u, v) at t = 30 s; the sum
    // over 40 seeds is χ²(80): 99 % of the time in [51.2, 116.3], i.e. mean in [1.28, 2.91].
    // The bounds come from the χ² distribution, the error from the truth; P is what is tested.
    let seeds = 40u64;
    let series = [
        "kf-uv.u",
        "kf-uv.v",
        "truth.u",
        "truth.v",
        "kf-uv.var_u",
        "kf-uv.var_v",
        "kf-uv.cov_u_v",
    ];
    let mut sum = 0.0;
    for seed in 0..seeds {
        let s = run(
            &["gyro_bias_deg_s=0", "gyro_noise_deg_s=0.05"],
            seed,
            30.0,
            &series,
        );
        let e = nalgebra::Vector2::new(
            last(&s, "kf-uv.u") - last(&s, "truth.u"),
            last(&s, "kf-uv.v") - last(&s, "truth.v"),
        );
        let p = nalgebra::Matrix2::new(
            last(&s, "kf-uv.var_u"),
            last(&s, "kf-uv.cov_u_v"),
            last(&s, "kf-uv.cov_u_v"),
            last(&s, "kf-uv.var_v"),
        );
        assert!(
            attlab::math::is_symmetric_positive_definite(&p),
            "seed {seed}: P = {p}"
        );
        sum += attlab::math::nees(&e, &p).expect("P is positive definite");
    }
    let mean = sum / seeds as f64;
    assert!((1.28..=2.91).contains(&mean), "mean NEES {mean}");
}
