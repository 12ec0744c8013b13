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

const EXAMPLE_LOG: &str = include_str!("../../../assets/p4-arduino-mpu6050.csv");

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
    let log = parse_imu_log(lines.join("\n"), ImuScales::default());
    let bad: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
    assert_eq!(bad, vec![1, 2, 3, 50, 100, 200]);
    assert_eq!(log.t_s.len(), 997);
    assert!(
        log.errors[4]
            .to_string()
            .contains("expected 7 columns (time, ax, ay, az, gx, gy, gz), found 3")
    );
}

/// The page's γ sweep (incremental, five seeds) against the same runs made one by one
/// through `run_trace` and scored, the median taken here.
#[test]
fn the_page_gamma_sweep_gives_the_medians_of_runs_made_one_by_one() {
    use attlab::analysis::sweep::Sweep;
    use attlab::labs::p4_quadrotor::score_run;
    let lab = attlab_tests::lab("p4");
    let spec = lab.sweeps()[0];
    let base = attlab::model::ParamValues::defaults(lab.params());
    let sweep = Sweep::new(lab, spec, base.clone(), 1)
        .with_values(vec![1e-5, 0.2])
        .run_to_end();
    assert!(sweep.skipped.is_empty(), "{:?}", sweep.skipped);
    assert_eq!(sweep.points.len(), 2);
    for p in &sweep.points {
        assert_eq!(p.runs, spec.seeds);
        let mut mse = Vec::new();
        for seed in 1..=spec.seeds {
            let g = format!("gamma={}", p.value);
            let t = trace(
                "p4",
                &[&g],
                seed,
                spec.duration_s,
                &["kf.angle_deg", "kf.angle_err_deg", "kf.rate_err_deg_s"],
            );
            let cols: Vec<Vec<f64>> = ["kf.angle_deg", "kf.angle_err_deg", "kf.rate_err_deg_s"]
                .iter()
                .map(|s| t.series(s).unwrap().to_vec())
                .collect();
            let mut params = base.clone();
            params.set(lab.params(), "gamma", p.value).unwrap();
            mse.push(score_run(&params, t.t_s(), &cols).unwrap()[0]);
        }
        let median = stats::median(&mse).unwrap();
        assert_eq!(p.scores[0], median, "γ = {}", p.value);
        let (lo, hi) = (stats::min(&mse).unwrap(), stats::max(&mse).unwrap());
        assert_eq!(p.score_range[0], [lo, hi]);
        // J = α·MSE + β·t_tr of the medians, for the paper's pairs in Table 1's order.
        assert_eq!(p.objectives[0], 0.3 * p.scores[0] + 0.7 * p.scores[1]);
        assert_eq!(p.objectives[1], 0.7 * p.scores[0] + 0.3 * p.scores[1]);
    }
}

/// The Q landscape's grid: setting the two elements to those the γ mapping gives at γ*
/// reproduces the γ* run exactly, and the grid's points come row by row.
#[test]
fn q_set_by_elements_at_the_gamma_mapping_reproduces_the_gamma_run() {
    let lab = attlab_tests::lab("p4");
    let params = attlab::model::ParamValues::defaults(lab.params());
    let tuning = attlab::labs::p4_quadrotor::tuning_of(&params);
    let dt = 1.0 / params.get("sample_hz");
    let [qa, qr] = tuning.q_block(dt);
    let deg2 = (180.0 / std::f64::consts::PI).powi(2);
    let a = format!("kf_q_angle_deg2={}", qa * deg2);
    let r = format!("kf_q_rate_deg2_s2={}", qr * deg2);
    let by_gamma = trace("p4", &[], 3, 4.0, &["kf.angle_err_deg"]);
    let by_elements = trace(
        "p4",
        &["kf_q_from=1", &a, &r],
        3,
        4.0,
        &["kf.angle_err_deg"],
    );
    let (x, y) = (
        by_gamma.series("kf.angle_err_deg").unwrap(),
        by_elements.series("kf.angle_err_deg").unwrap(),
    );
    let worst = x
        .iter()
        .zip(y)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-9, "largest difference {worst}°");
    // And a Q far off that mapping gives a different run (the elements are really used).
    let off = trace(
        "p4",
        &["kf_q_from=1", "kf_q_angle_deg2=1e-3", &r],
        3,
        4.0,
        &["kf.angle_err_deg"],
    );
    let moved = x
        .iter()
        .zip(off.series("kf.angle_err_deg").unwrap())
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(moved > 1e-3, "{moved}");
}

#[test]
fn the_q_landscape_fills_its_grid_row_by_row_and_finds_an_interior_optimum() {
    use attlab::analysis::sweep::Sweep;
    let lab = attlab_tests::lab("p4");
    let spec = lab.sweeps()[1];
    let grid = spec.grid.expect("the landscape is a grid");
    let base = attlab::model::ParamValues::defaults(lab.params());
    let sweep = Sweep::new(lab, spec, base, 1).run_to_end();
    assert!(sweep.skipped.is_empty(), "{:?}", sweep.skipped);
    assert_eq!(sweep.points.len(), spec.values.len() * grid.values.len());
    for (k, p) in sweep.points.iter().enumerate() {
        assert_eq!(p.value, spec.values[k / grid.values.len()]);
        assert_eq!(p.grid_value, Some(grid.values[k % grid.values.len()]));
    }
    let best = sweep.argmin(0).expect("an optimum");
    let corner = |v: f64, values: &[f64]| v == values[0] || v == values[values.len() - 1];
    println!(
        "optimum q_θ = {} deg², q_ω = {:?} (deg/s)², J = {}",
        best.value, best.grid_value, best.objectives[0]
    );
    assert!(
        !corner(best.value, spec.values) || !corner(best.grid_value.unwrap(), grid.values),
        "the optimum sits in a corner of the grid: {best:?}"
    );
}

#[test]
fn the_gamma_sweep_runs_on_the_example_log_with_its_own_scores() {
    use attlab::analysis::sweep::Sweep;
    use attlab::sensors::{ImuScales, parse_imu_log};
    let lab = attlab_tests::lab("p4");
    let spec = lab.sweeps()[0];
    let log = parse_imu_log(EXAMPLE_LOG, ImuScales::default());
    let base = attlab::model::ParamValues::defaults(lab.params());
    let sweep = Sweep::new(lab, spec, base, 1)
        .on_log(log)
        .expect("the γ sweep can run on a log")
        .run_to_end();
    assert!(sweep.skipped.is_empty(), "{:?}", sweep.skipped);
    assert_eq!(sweep.points.len(), spec.values.len());
    for p in &sweep.points {
        assert_eq!(p.runs, 1, "one run per value on a log");
        assert!(p.unscored.is_empty(), "{:?}", p.unscored);
        assert!(p.scores.iter().all(|s| s.is_finite()), "{p:?}");
    }
    // Trusting the sensors more passes more of their noise: θ̂'s jitter grows with γ.
    let jitter: Vec<f64> = sweep.points.iter().map(|p| p.scores[1]).collect();
    println!("jitter over γ: {jitter:?}");
    assert!(jitter.windows(2).all(|w| w[1] >= w[0]), "{jitter:?}");
    assert!(jitter[jitter.len() - 1] > jitter[0], "{jitter:?}");
    let best = sweep.argmin(0).expect("an argmin");
    println!(
        "on the example log the proxy is smallest at γ = {}",
        best.value
    );
}

/// A Sweep that cannot run on a log says so (the p1 sweep has no log scoring).
#[test]
fn a_sweep_without_log_scoring_refuses_a_log() {
    use attlab::analysis::sweep::Sweep;
    let lab = attlab_tests::lab("p1");
    let base = attlab::model::ParamValues::defaults(lab.params());
    let log = attlab::sensors::RateLog::default();
    assert!(
        Sweep::new(lab, lab.sweeps()[0], base, 1)
            .on_log(log)
            .is_none()
    );
}

/// The rig's true angle over a run with the loop on `loop_on` (0: the KF's θ̂, 1: the truth)
/// and γ = `gamma`.
fn rig_angle(loop_on: u32, gamma: f64) -> Vec<f64> {
    let set = [format!("loop_on={loop_on}"), format!("gamma={gamma}")];
    let set: Vec<&str> = set.iter().map(String::as_str).collect();
    let t = trace("p4", &set, 1, 6.0, &["truth.angle_deg"]);
    t.series("truth.angle_deg").unwrap().to_vec()
}

#[test]
fn with_the_loop_on_the_estimate_the_filter_moves_the_rig_and_on_the_truth_it_does_not() {
    // On the truth: the rig's motion is the controller's alone, whatever γ is.
    assert_eq!(rig_angle(1, 2e-3), rig_angle(1, 0.2));
    // On θ̂ (Fig. 1, the default): a noisier estimate shakes the rig itself.
    // Its scatter at rest, 1–4 s at 100 Hz (the set-point steps at 4 s).
    let (star, noisy) = (rig_angle(0, 2e-3), rig_angle(0, 0.2));
    let scatter = |a: &[f64]| stats::std_dev(&a[100..400]).unwrap();
    assert!(
        scatter(&noisy) > 1.2 * scatter(&star),
        "γ = 0.2 should shake the rig more than γ* = 2·10⁻³: {}° vs {}°",
        scatter(&noisy),
        scatter(&star)
    );
}

/// The rig's true angle over a run with `set`.
fn rig_with(set: &[&str]) -> Vec<f64> {
    let t = trace("p4", set, 1, 6.0, &["truth.angle_deg"]);
    t.series("truth.angle_deg").unwrap().to_vec()
}

/// Each filter can close the loop: on the complementary filter the rig moves with its gain
/// and not with γ; on either other KF with γ and not with the complementary gain.
#[test]
fn the_loop_closes_on_the_filter_chosen_and_on_no_other() {
    for (loop_on, moves_with_gamma) in [
        ("loop_on=2", false),
        ("loop_on=3", true),
        ("loop_on=4", true),
    ] {
        let gamma = rig_with(&[loop_on, "gamma=2e-3"]) != rig_with(&[loop_on, "gamma=0.2"]);
        let cf = rig_with(&[loop_on, "cf_gain=0.9"]) != rig_with(&[loop_on, "cf_gain=0.99"]);
        assert_eq!(
            (gamma, cf),
            (moves_with_gamma, !moves_with_gamma),
            "{loop_on}: the rig moves with γ: {gamma}, with the complementary gain: {cf}"
        );
    }
}
