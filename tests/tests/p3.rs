//! Paper 3 lab: the paper's findings and the Kalman filter's consistency.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::params::ParamValues;
use attlab::sim::Simulation;

fn run(assignments: &[&str], seed: u64, duration_s: f64) -> Simulation {
    let lab = labs::find("p3").expect("p3 registered");
    let mut p = ParamValues::defaults(lab.params());
    let errors = p.apply_assignments(lab.params(), assignments.iter().copied());
    assert!(errors.is_empty(), "{errors:?}");
    let mut s = Simulation::with_history(lab, p, seed, (duration_s * 100.0) as usize + 10);
    s.run_for(duration_s);
    s
}

fn col(s: &Simulation, name: &str) -> Vec<f64> {
    let r = s.recorder();
    r.column(
        r.index_of(name)
            .unwrap_or_else(|| panic!("no series {name}")),
    )
    .unwrap()
    .iter()
    .copied()
    .collect()
}

fn rms_after(s: &Simulation, name: &str, after_s: f64) -> f64 {
    let t = col(s, "t_s");
    let v: Vec<f64> = col(s, name)
        .into_iter()
        .zip(t)
        .filter(|(_, t)| *t > after_s)
        .map(|(v, _)| v)
        .collect();
    (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt()
}

fn last(s: &Simulation, name: &str) -> f64 {
    *col(s, name).last().unwrap()
}

#[test]
fn blending_removes_the_drift_and_the_noise() {
    let s = run(&[], 1, 100.0);
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
    let short = run(&["blend_time_const_s=0.05"], 1, 60.0);
    let long = run(&["blend_time_const_s=50"], 1, 60.0);
    let noise = |s: &Simulation| rms_after(s, "blend.hpf_v", 5.0);
    assert!(
        rms_after(&long, "blend.tilt_err_deg", 30.0)
            > 2.0 * rms_after(&run(&[], 1, 60.0), "blend.tilt_err_deg", 30.0)
    );
    assert!(
        noise(&short) < noise(&long),
        "HPF(v) carries less when T is short"
    );
}

#[test]
fn a_lateral_bump_fools_the_accelerometer_more_than_the_blend() {
    // A 0.5 g bump (1 s wide) tilts the accelerometer's vertical by atan(0.5) ≈ 27°. The
    // blend low-passes it with T: at T = 1 s the bump is about as fast as T and partly gets
    // through; at T = 10 s most of it is filtered out.
    let peak = |t_const: &str, id: &str| {
        let s = run(
            &["bump_g=0.5", "bump_time_s=30", "accel_noise_g=0", t_const],
            1,
            40.0,
        );
        let t = col(&s, "t_s");
        col(&s, &format!("{id}.tilt_err_deg"))
            .into_iter()
            .zip(&t)
            .filter(|(_, t)| (27.0..35.0).contains(*t))
            .fold(0.0_f64, |m, (v, _)| m.max(v))
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
    let s = run(&["profile=2"], 3, 100.0);
    assert!(col(&s, "truth.k_z").into_iter().fold(1.0_f64, f64::min) < -0.95);
    for id in ["blend", "kf-uv"] {
        let m = col(&s, &format!("{id}.tilt_err_deg"))
            .into_iter()
            .fold(0.0_f64, f64::max);
        assert!(
            m.is_finite() && m < 2.0,
            "{id}: max tilt error {m} deg through w = ∞"
        );
    }
    let a = col(&s, "uvz-rk4.err_deg");
    let b = col(&s, "quat-rk4.err_deg");
    let d = a
        .iter()
        .zip(&b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
    assert!(
        d < 1e-6,
        "(u,v,z) and quaternion integrators differ by {d} deg"
    );
}

#[test]
fn kalman_filter_nees_is_within_chi_square_bounds() {
    // Without bias the filter's model is exact. NEES = eᵀP⁻¹e of (u, v) at t = 30 s; the sum
    // over 40 seeds is χ²(80): 99 % of the time in [51.2, 116.3], i.e. mean in [1.28, 2.91].
    let seeds = 40u64;
    let mut sum = 0.0;
    for seed in 0..seeds {
        let s = run(&["gyro_bias_deg_s=0", "gyro_noise_deg_s=0.05"], seed, 30.0);
        let e = nalgebra::Vector2::new(
            last(&s, "kf-uv.u") - last(&s, "truth.u"),
            last(&s, "kf-uv.v") - last(&s, "truth.v"),
        );
        let p = nalgebra::Matrix2::new(
            last(&s, "kf-uv.P_uu"),
            last(&s, "kf-uv.P_uv"),
            last(&s, "kf-uv.P_uv"),
            last(&s, "kf-uv.P_vv"),
        );
        assert!(
            attlab::math::is_symmetric_positive_definite(&p),
            "seed {seed}: P = {p}"
        );
        sum += e.dot(&(p.try_inverse().unwrap() * e));
    }
    let mean = sum / seeds as f64;
    assert!((1.28..=2.91).contains(&mean), "mean NEES {mean}");
}
