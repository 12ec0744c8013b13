//! Paper 4 lab: the asymmetry needs u₀, the accelerometer is fooled by fast motion, the γ
//! trend, and the sweep is deterministic.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::stats;
use attlab::labs::p4_quadrotor::score_gamma;
use attlab_tests::trace;

#[test]
fn the_asymmetric_quadrotor_needs_a_constant_command_and_the_symmetric_one_does_not() {
    let asym = trace(
        "p4",
        &["rig=2", "asymmetry_pct=15"],
        1,
        6.0,
        &["truth.u0_needed_rad_s2", "truth.u0_rad_s2"],
    );
    let sym = trace("p4", &["rig=1"], 1, 6.0, &["truth.u0_needed_rad_s2"]);
    let needed = asym.last("truth.u0_needed_rad_s2").unwrap();
    assert!(
        needed.abs() > 1.0,
        "asymmetric hover needs u₀, got {needed}"
    );
    // The integral has found it (the loop holds the set-point).
    let found = asym.last("truth.u0_rad_s2").unwrap();
    assert!(
        (found - needed).abs() < 0.05 * needed.abs(),
        "integral {found} vs needed {needed}"
    );
    assert!(sym.last("truth.u0_needed_rad_s2").unwrap().abs() < 1e-12);
}

#[test]
fn fast_motion_fools_the_accelerometer_and_not_the_filter() {
    let set = [
        "bandwidth_rad_s=12",
        "setpoint_deg=40",
        "imu_offset_m=0.25",
        "accel_density_ug=0",
        "gyro_density_deg_s=0",
    ];
    let t = trace(
        "p4",
        &set,
        1,
        8.0,
        &[
            "sensors.accel_angle_deg",
            "truth.angle_deg",
            "kf.angle_err_deg",
        ],
    );
    let acc = t.series("sensors.accel_angle_deg").unwrap();
    let truth = t.series("truth.angle_deg").unwrap();
    let worst_acc = stats::max_abs(
        &acc.iter()
            .zip(truth)
            .map(|(a, b)| a - b)
            .collect::<Vec<_>>(),
    )
    .unwrap();
    assert!(
        worst_acc > 5.0,
        "with no noise the accelerometer angle is still off by {worst_acc}° in the steps"
    );
    let worst_kf = stats::max_abs(t.series("kf.angle_err_deg").unwrap()).unwrap();
    assert!(
        worst_kf < worst_acc,
        "the KF ({worst_kf}°) should lean on the gyro in the steps"
    );
}

#[test]
fn the_gamma_scores_are_deterministic() {
    assert_eq!(score_gamma(2e-3).unwrap(), score_gamma(2e-3).unwrap());
}

#[test]
fn small_gamma_is_offset_and_large_gamma_is_noisy() {
    let (small, star, large) = (
        score_gamma(1e-6).unwrap(),
        score_gamma(2e-3).unwrap(),
        score_gamma(1.0).unwrap(),
    );
    assert!(
        small.offset_deg.abs() > star.offset_deg.abs(),
        "{small:?} vs {star:?}"
    );
    assert!(large.noise_deg > star.noise_deg, "{large:?} vs {star:?}");
}

const EXAMPLE_LOG: &str = include_str!("../../assets/p4-arduino-mpu6050.csv");

#[test]
fn the_example_log_replays_with_no_flags_and_reports_only_the_banner() {
    use attlab::sensors::{ImuScales, parse_imu_log};
    let log = parse_imu_log(EXAMPLE_LOG, ImuScales::default());
    assert_eq!(log.t_s.len(), 1000);
    let lines: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
    assert_eq!(lines, vec![1, 2, 3], "{:?}", log.errors);
    let lab = attlab_tests::lab("p4");
    let params = attlab::model::ParamValues::defaults(lab.params());
    let options = attlab::sim::SimOptions {
        selection: attlab::sim::Selection::All,
        ..Default::default()
    };
    let mut sim = attlab::sim::Simulation::replay(lab, params, log, options).unwrap();
    sim.run_for(7.9);
    let angle = sim.value("kf.angle_deg").unwrap();
    // The logged lever has settled 3.9 s into its 20° step.
    assert!(
        (angle - 20.0).abs() < 2.0,
        "KF angle 3.9 s into the logged step: {angle}°"
    );
}

#[test]
fn a_corrupted_log_reports_its_bad_lines_by_number_and_keeps_the_rest() {
    use attlab::sensors::{ImuScales, parse_imu_log};
    let mut lines: Vec<String> = EXAMPLE_LOG.lines().map(String::from).collect();
    lines[49] = "garbage from a loose wire".into(); // line 50
    lines[99] = "990,1,2".into(); // line 100: too few columns
    lines[199] = "1950,1,2,x,4,5,6".into(); // line 200
    let log = parse_imu_log(&lines.join("\n"), ImuScales::default());
    let bad: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
    assert_eq!(bad, vec![1, 2, 3, 50, 100, 200]);
    assert_eq!(log.t_s.len(), 997);
    assert!(log.errors[4].to_string().contains("seven columns"));
}
