//! Paper 2 lab: the perfect model, the degenerate geometry, the outages.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::stats;
use attlab::labs::p2_tabletsat::sets::FILTERS;
use attlab_tests::trace;

#[test]
fn with_perfect_sensors_and_model_every_filter_stays_on_the_truth() {
    let set = [
        "mag_noise_nt=0",
        "sun_noise_deg=0",
        "gyro_noise_deg_s=0",
        "gyro_bias_deg_s=0",
        "star_noise_deg=0",
        "dist_torque_n_m=0",
        "filter_init_err_deg=0",
    ];
    let names: Vec<String> = FILTERS
        .iter()
        .map(|f| format!("{}.err_deg", f.config.id))
        .collect();
    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
    let t = trace("p2", &set, 1, 120.0, &refs);
    for name in &names {
        let worst = stats::max_abs(t.series(name).unwrap()).unwrap();
        assert!(
            worst < 2e-3,
            "{name}: {worst}° with perfect sensors and model"
        );
    }
}

#[test]
fn the_sun_along_the_field_is_flagged_and_never_nan() {
    let t = trace(
        "p2",
        &["sun_along_field=1", "sun_field_angle_deg=0.5"],
        1,
        120.0,
        &["mag-sun.status", "mag-sun.err_deg", "st-mag-sun.status"],
    );
    let status = t.series("mag-sun.status").unwrap();
    assert!(
        status.iter().any(|s| *s > 0.0),
        "Mag+Sun never said unobservable or diverged"
    );
    // With a star tracker the same geometry is fine.
    assert!(
        t.series("st-mag-sun.status")
            .unwrap()
            .iter()
            .all(|s| *s == 0.0)
    );
    assert!(
        t.series("mag-sun.err_deg")
            .unwrap()
            .iter()
            .all(|e| !e.is_nan()),
        "NaN on screen"
    );
}

#[test]
fn a_blinded_star_tracker_and_the_eclipse_show_as_outages() {
    let t = trace(
        "p2",
        &["star_sun_exclusion_deg=90", "ltan_h=12"],
        1,
        3600.0,
        &[
            "sensors.star_available",
            "sensors.eclipse",
            "sensors.sun_seen",
        ],
    );
    let frac = |n: &str| stats::mean(t.series(n).unwrap()).unwrap();
    assert!(
        frac("sensors.eclipse") > 0.1,
        "a noon–midnight orbit has an eclipse within an hour"
    );
    assert!(frac("sensors.star_available") < 0.9);
    // In eclipse no sun sensor sees the sun.
    let both = t
        .series("sensors.eclipse")
        .unwrap()
        .iter()
        .zip(t.series("sensors.sun_seen").unwrap())
        .any(|(e, s)| *e > 0.5 && *s > 0.5);
    assert!(!both);
}

/// Table 5's (λ, ω, d) rows: with the gain frozen before the torque is switched on, the
/// disturbance filter behind the frozen gain still finds d = J⁻¹M_d. Were it frozen with the
/// gain, d̂ would stay at the zero it had before the step and its error would be |d|.
#[test]
fn the_disturbance_filter_keeps_running_behind_a_frozen_gain() {
    let axes = ["x", "y", "z"];
    let mut names: Vec<String> = axes.iter().map(|a| format!("truth.dist_{a}_s2")).collect();
    names.extend(axes.iter().map(|a| format!("st-dist-const.d_{a}_s2")));
    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
    let set = ["freeze_after_s=20", "dist_from_s=60"];
    let t = trace("p2", &set, 1, 300.0, &refs);
    let last_minute = |name: &str| -> Vec<f64> {
        let v = t.series(name).unwrap();
        v[v.len() - v.len() / 5..].to_vec()
    };
    let (mut size, mut worst) = (0.0_f64, 0.0_f64);
    for a in axes {
        let truth = last_minute(&format!("truth.dist_{a}_s2"));
        let est = last_minute(&format!("st-dist-const.d_{a}_s2"));
        let err: Vec<f64> = est.iter().zip(&truth).map(|(e, t)| e - t).collect();
        size += stats::rms(&truth).unwrap().powi(2);
        worst = worst.max(stats::rms(&err).unwrap());
    }
    let size = size.sqrt();
    assert!(
        size > 1e-7,
        "the torque's d is {size} s⁻²: the step did not happen"
    );
    assert!(
        worst < 0.25 * size,
        "d̂ − d {worst} s⁻² behind the frozen gain, against |d| = {size} s⁻²"
    );
}

/// "Tune this set": at multipliers of 1 the tuned filter is the chosen set, sample for
/// sample; a multiplier changes it, live.
#[test]
fn the_tuned_set_is_its_row_at_one_and_moves_with_its_sliders() {
    // Set 8, ST+Gyro [λ,ω], is option 7.
    let names = ["tuned.err_deg", "st-gyro.err_deg"];
    let t = trace("p2", &["tune_set=7"], 1, 60.0, &names);
    assert_eq!(t.series(names[0]).unwrap(), t.series(names[1]).unwrap());
    let t = trace("p2", &["tune_set=7", "tune_q_att=100"], 1, 60.0, &names);
    let (tuned, row) = (t.series(names[0]).unwrap(), t.series(names[1]).unwrap());
    assert!(
        tuned.iter().zip(row).any(|(a, b)| a != b),
        "q_Λ × 100 changed nothing"
    );
}
