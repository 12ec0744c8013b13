//! Paper 1 lab: the paper's findings about adaptation, checked on the simulated mock-up.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::stats;
use attlab::analysis::sweep::Sweep;
use attlab::labs::p1_suspended::{run_stats, true_period_s};
use attlab::model::ParamValues;
use attlab::sensors::{RateUnit, TimeUnit, parse_rate_log};
use attlab::sim::{SimOptions, Simulation};
use attlab_tests::{lab, trace};

#[test]
fn without_adaptation_p_collapses_and_the_torsional_error_grows() {
    let s = trace(
        "p1",
        &["kf_window=0"],
        1,
        600.0,
        &["kf-torsion.var_phidot", "kf-torsion.angle_minus_int_deg"],
    );
    let c = s.series("kf-torsion.var_phidot").unwrap();
    let err = s.series("kf-torsion.angle_minus_int_deg").unwrap();
    let at = |t: f64| (t * 100.0).round() as usize;
    assert!(
        c[c.len() - 1] < c[0] * 1e-3,
        "c: {:e} → {:e}",
        c[0],
        c[c.len() - 1]
    );
    let (e100, e600) = (err[at(100.0)].abs(), err[err.len() - 1].abs());
    let max = stats::max_abs(err).unwrap();
    // Fig. 5.3: the undamped model drifts from the damped truth to the order of ±100°.
    assert!(
        e600 > 5.0 * e100 && max > 50.0,
        "error {e100}° at 100 s, {e600}° at 600 s, max {max}°"
    );
}

#[test]
fn the_saw_tooth_jumps_every_n_samples_and_decays_between() {
    // Fig. 5.6: with N = 1000 at 100 Hz, P jumps every 10 s and decays in between.
    let s = trace(
        "p1",
        &["kf_window=1000"],
        1,
        35.0,
        &["kf-rotation.var_phidot"],
    );
    let c = s.series("kf-rotation.var_phidot").unwrap();
    let jumps: Vec<usize> = c
        .windows(2)
        .enumerate()
        .filter(|(_, w)| w[1] > 2.0 * w[0])
        .map(|(k, _)| k + 1)
        .collect();
    assert_eq!(jumps, vec![1000, 2000, 3000], "resets at 10, 20, 30 s");
    assert!(
        c[1999] < c[1000] / 10.0,
        "decays between resets: {} → {}",
        c[1000],
        c[1999]
    );
}

#[test]
fn the_literal_reset_collapses_like_q_zero_and_the_saw_tooth_does_not() {
    // kf_adaptation: 0 = saw-tooth, 2 = literal q = K r.
    let literal = trace(
        "p1",
        &["kf_window=100", "kf_adaptation=2"],
        1,
        200.0,
        &["kf-rotation.var_phidot"],
    );
    let saw = trace(
        "p1",
        &["kf_window=100"],
        1,
        200.0,
        &["kf-rotation.var_phidot"],
    );
    let (l, s) = (
        literal.last("kf-rotation.var_phidot").unwrap(),
        saw.last("kf-rotation.var_phidot").unwrap(),
    );
    assert!(l < s * 1e-3, "literal c = {l:e}, saw-tooth c = {s:e}");
}

#[test]
fn an_unstable_adaptation_is_reported_as_diverged_not_hidden() {
    // The full-matrix saw-tooth runs away for small N (measured: N = 10); the filter must say
    // so, and the diagonal variant must not.
    let [rot, _] = run_stats(&["kf_window=10"], 1, 200.0, 0.0).unwrap();
    assert_eq!(rot.diverged, 1.0, "{rot:?}");
    let [rot, tor] = run_stats(&["kf_window=10", "kf_adaptation=1"], 1, 200.0, 0.0).unwrap();
    assert_eq!((rot.diverged, tor.diverged), (0.0, 0.0), "{rot:?} {tor:?}");
    assert!(
        rot.max_vs_int_deg < 1.0 && tor.max_vs_int_deg < 1.0,
        "{rot:?} {tor:?}"
    );
}

#[test]
fn against_the_truth_no_window_beats_the_integrated_gyro_noise() {
    // σ√(t/f) is the 1σ of φ_int's error at t; the filters track φ_int, so over 200 s their
    // largest error against the truth is of that size whatever N is.
    let floor = attlab::labs::p1_suspended::p1_noise_floor_deg(0.04, 200.0, 100.0);
    for n in [30, 100, 300] {
        let mut worst = Vec::new();
        for seed in 1..=5 {
            let [rot, tor] = run_stats(&[&format!("kf_window={n}")], seed, 200.0, 0.0).unwrap();
            worst.push(rot.max_vs_truth_deg.min(tor.max_vs_truth_deg));
        }
        let median = stats::median(&worst).unwrap();
        assert!(
            median > 0.3 * floor,
            "N = {n}: best filter's max error {median}° vs floor {floor}°"
        );
    }
}

#[test]
fn the_window_sweep_agrees_with_a_direct_run_and_finds_a_best_window() {
    let lab = lab("p1");
    let spec = lab.sweeps()[0];
    let mut sweep = Sweep::new(lab, spec, ParamValues::defaults(lab.params()), 1);
    let mut calls = 0;
    while !sweep.advance(50_000) {
        calls += 1;
        assert!(sweep.progress() < 1.0 && calls < 10_000);
    }
    assert_eq!(sweep.points.len(), spec.values.len());
    let at_100 = sweep.points.iter().find(|p| p.value == 100.0).unwrap();
    let direct =
        run_stats(&["kf_window=100"], 1, spec.duration_s, spec.after_s).unwrap()[0].max_vs_int_deg;
    assert!(
        (at_100.max_abs[0] - direct).abs() <= 1e-12 * direct,
        "sweep {} vs direct {direct}",
        at_100.max_abs[0]
    );
    let (best_n, best) = sweep.best(0).unwrap();
    assert!(
        at_100.rms[0] <= 3.0 * best,
        "best N = {best_n} with {best} deg, N = 100 gives {}",
        at_100.rms[0]
    );
}

#[test]
fn a_recorded_log_with_junk_lines_replays_through_the_filters() {
    // A log of the undamped pendulum φ = 360° cos Ωt at 100 Hz, in the lab's own units
    // (ms and millidegrees per second), with bad lines mixed in.
    let lab = lab("p1");
    let mut p = ParamValues::defaults(lab.params());
    p.set(lab.params(), "damping_ratio", 0.0).unwrap();
    let omega = std::f64::consts::TAU / true_period_s(&p);
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
    let log = parse_rate_log(&text, RateUnit::MilliDegPerS, TimeUnit::Milliseconds);
    assert_eq!(log.errors.len(), 2);
    assert_eq!(log.errors[0].line, 103);
    assert_eq!(log.t_s.len(), 6000);
    let mut sim =
        Simulation::replay(lab, p, log, SimOptions::named(&["kf-torsion.angle_deg"])).unwrap();
    sim.run_for(59.9);
    let phi_true = 360.0 * (omega * sim.t_s()).cos();
    let kf = sim.value("kf-torsion.angle_deg").unwrap();
    assert!(
        (kf - phi_true).abs() < 0.2,
        "torsional KF {kf} deg vs {phi_true} deg"
    );
}

/// The raw-count example (assets/make_p1_log.py): the lab's default twist from 360° at rest,
/// read by a VG-910D as unsigned 24-bit words with a 1 258-count zero, at 10 Hz. Read with
/// its calibration it gives back the twist it was written from; read with a wrong word
/// width or without its zero it does not.
#[test]
fn the_raw_count_example_replays_to_the_twist_it_was_written_from() {
    let lab = lab("p1");
    let page = lab.page();
    let (example, format) = (page.example_log.unwrap(), page.log_format.unwrap());
    let p = ParamValues::defaults(lab.params());
    let (w, zeta) = (std::f64::consts::TAU / true_period_s(&p), 0.05f64);
    let wd = w * (1.0 - zeta * zeta).sqrt();
    let phi_deg =
        |t: f64| 360.0 * (-zeta * w * t).exp() * ((wd * t).cos() + zeta * w / wd * (wd * t).sin());
    let worst_error = |units: &[(&str, &str)]| {
        let mut values = example.unit_values(format).unwrap();
        for (k, v) in units {
            values.set_text(format.units, k, v).unwrap();
        }
        let log = attlab::labs::read_log(lab, example.text.as_bytes(), &values).unwrap();
        assert_eq!(
            (log.t_s.len(), log.counts.rejected),
            (6001, 0),
            "{:?}",
            log.errors
        );
        let names = ["integration.angle_deg", "kf-torsion.angle_deg"];
        let mut sim = Simulation::replay(lab, p.clone(), log, SimOptions::named(&names)).unwrap();
        let mut worst: f64 = 0.0;
        for t in [100.0, 200.0, 300.0, 450.0, 600.0] {
            sim.run_for(t - sim.t_s());
            for name in names {
                let e = sim.value(name).unwrap() - phi_deg(sim.t_s());
                worst = worst.max(e.abs());
            }
        }
        worst
    };
    let calibrated = worst_error(&[]);
    assert!(calibrated < 1.5, "{calibrated}° off the written twist");
    let signed = worst_error(&[("rate_counts", "signed")]);
    assert!(signed > 100.0, "words read as signed counts: {signed}°");
    let no_zero = worst_error(&[("count_zero", "0")]);
    assert!(no_zero > 10.0, "without the zero: {no_zero}°");
}

/// §3.2's 5-DOF body as the truth: with the gyro aligned and no noise, a prescribed swing
/// leaves φ_int on the twist (the 1-DOF model), while the rocking body moves it off, because
/// its z rate is not the twist rate once it tilts — the swing reaches the gyro through the
/// dynamics. Its energy is a series, constant without damping.
#[test]
fn the_rocking_body_reaches_an_aligned_gyro_through_its_dynamics() {
    let worst = |model: &str| {
        let key = "integration.angle_err_deg";
        let s = trace(
            "p1",
            &[model, "swing_amp_deg=5", "gyro_noise_deg_s=0"],
            1,
            600.0,
            &[key, "truth.energy_mj"],
        );
        let e = s.series("truth.energy_mj").unwrap();
        let worst = s
            .series(key)
            .unwrap()
            .iter()
            .fold(0.0, |m: f64, v| m.max(v.abs()));
        (worst, e[0], e[e.len() - 1])
    };
    let (prescribed, _, _) = worst("body_model=0");
    let (rocking, e0, e600) = worst("body_model=1");
    assert!(prescribed < 0.05, "1 DOF: φ_int {prescribed}° off");
    assert!(rocking > 0.5, "5 DOF: φ_int only {rocking}° off");
    // ζ = 0.05 takes energy from the twist: 600 s is 1.5 periods of T ≈ 401 s.
    assert!(e600 < 0.5 * e0 && e600 > 0.0, "E {e0} → {e600} mJ");
}

#[test]
fn a_two_hour_run_fits_the_budget_and_its_plots_cover_the_whole_run() {
    let lab = lab("p1");
    let mut sim = Simulation::new(lab, ParamValues::defaults(lab.params()), 1);
    let bytes = sim.recorder().memory_bytes();
    sim.run_for(7200.0);
    let rec = sim.recorder();
    assert_eq!(rec.memory_bytes(), bytes);
    assert!(bytes <= attlab::record::DEFAULT_BUDGET_BYTES, "{bytes} B");
    let i = rec
        .index_of("kf-rotation.angle_deg")
        .expect("the first tab's series are recorded");
    let pts = rec.plot_points(i, 1500);
    assert!(pts.len() <= 1600, "{} points", pts.len());
    assert_eq!(pts.first().map(|p| p[0]), Some(0.0));
    let end = pts.last().map_or(0.0, |p| p[0]);
    assert!((end - 7200.0).abs() < 0.02, "the plot ends at {end} s");
}

#[test]
fn the_output_file_has_the_paper_s_columns_and_no_truth() {
    let lab = lab("p1");
    let p = ParamValues::defaults(lab.params());
    let file = lab.output_file(&p).expect("paper 1 defines an output file");
    let mut buf = Vec::new();
    let (rows, stopped) = attlab::sim::write_output_file(lab, p, 1, 2.0, &file, &mut buf).unwrap();
    assert!(!stopped, "the file has no stop condition");
    let text = String::from_utf8(buf).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "omega,phi_int,phi1,phi1_dot,phi2,phi2_dot,t");
    assert_eq!(lines.len() as u64, rows + 1);
    assert_eq!(rows, 201, "2 s at 100 Hz and the start");
    // Each row equals the run's own series at that step: φ_int and the torsional KF's angle.
    let t = trace(
        lab.id(),
        &[],
        1,
        2.0,
        &["integration.angle_deg", "kf-torsion.angle_deg"],
    );
    let last: Vec<f64> = lines[lines.len() - 1]
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    assert!((last[6] - 2.0).abs() < 1e-9, "t = {}", last[6]);
    assert_eq!(last[1], t.last("integration.angle_deg").unwrap());
    assert_eq!(last[4], t.last("kf-torsion.angle_deg").unwrap());
}
