//! `attlab reproduce p3`: the paper's scenario measured, and the lab's cost comparison.
// Only the CLI and the tests reproduce a paper (the `study` feature): without it, what only
// `reproduce` uses is left out (the page's wasm).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::WzSphere;
use crate::analysis::scenario::{Trace, run_trace};
use crate::analysis::stats::{max_abs, min, rms};
use crate::analysis::{AnalysisError, StatsContext};
use crate::dynamics::EulerMotion;
use crate::math::{
    EulerYpr, WzAttitude, rk4_step, step_quaternion_rk4, step_uvz_rk4, uv_derivative, wrap_pi,
};
use crate::model::{Expectation, Quantity, Reproduction, Row, SeriesKey, TimingItem, q};
use nalgebra::{Vector2, Vector3};
use std::hint::black_box;

fn run(
    assignments: &[&str],
    seed: u64,
    duration_s: f64,
    series: &[SeriesKey],
) -> Result<Trace, AnalysisError> {
    run_trace(&WzSphere, assignments, seed, duration_s, series)
}

/// Largest Euler-angle difference (rad) between (w, z) integrated by RK4 from the exact
/// rates of the paper's motion and the true angles, over 100 s at `dt_s`.
pub fn error_free_euler_error(dt_s: f64) -> f64 {
    let motion = EulerMotion::paper3();
    let mut wz = WzAttitude::from_euler(&motion.euler(0.0));
    let mut worst = 0.0_f64;
    let steps = (100.0 / dt_s).round() as usize;
    for k in 0..steps {
        let t0 = k as f64 * dt_s;
        wz = step_uvz_rk4(&wz, |f| motion.body_rate_rad_s(t0 + f * dt_s), dt_s);
        let (e, truth) = (wz.to_euler(), motion.euler(t0 + dt_s));
        let d = [
            e.yaw_rad - truth.yaw_rad,
            e.pitch_rad - truth.pitch_rad,
            e.roll_rad - truth.roll_rad,
        ];
        worst = d.iter().fold(worst, |m, x| m.max(wrap_pi(*x).abs()));
    }
    worst
}

/// The reproduction table.
pub fn reproduce() -> Result<Reproduction, AnalysisError> {
    let e = error_free_euler_error(0.01);
    let mut rows = vec![Row::check(
        "error-free (w,z) → Euler vs true angles, max, 100 s",
        "exact kinematics (eq. 21)",
        e,
        "rad",
        Expectation::below(1e-9),
    )];
    let sim = run(&[], 1, 100.0, &SERIES)?;
    rows.extend(drift_rows(&sim)?);
    rows.extend(noise_rows(&sim)?);
    rows.extend(blend_rows(&sim)?);
    rows.extend(tumble_rows()?);
    Ok(Reproduction {
        lab: super::SPEC.id.into(),
        rows,
        notes: vec![
            "the paper prints no table: drift, noise and blend values are this simulator's (RK4, 100 Hz, bias +0.1 °/s on all axes, σ = 0.01 g)".into(),
            "tilt error = angle between the true and the estimated vertical (pitch and roll together)".into(),
        ],
    })
}

/// What the standard motion records for the checks.
const SERIES: [SeriesKey; 13] = [
    SeriesKey::truth(&q::U),
    SeriesKey::truth(&q::V),
    SeriesKey::truth(&q::Z_DEG),
    SeriesKey::truth(&q::K_Z),
    SeriesKey::new("uvz-rk4", &q::U),
    SeriesKey::new("uvz-rk4", &q::V),
    SeriesKey::new("uvz-rk4", &q::Z_DEG),
    SeriesKey::new("accel", &q::U),
    SeriesKey::new("accel", &q::V),
    SeriesKey::new("uvz-rk4", &q::TILT_ERR_DEG),
    SeriesKey::new("accel", &q::TILT_ERR_DEG),
    SeriesKey::new("blend", &q::TILT_ERR_DEG),
    SeriesKey::new("kf-uv", &q::TILT_ERR_DEG),
];

/// The gyro-only (u, v, z) integration drifts with the bias (Figs. 4, 7, 8).
fn drift_rows(sim: &Trace) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let last = |key: SeriesKey| sim.last(key);
    // (series, unit, paper figures, how large a drift counts as drifting)
    for (quantity, unit, figs, threshold) in [
        (&q::U, "", "Fig. 4, 7", 1e-3),
        (&q::V, "", "Fig. 4, 7, 8", 1e-3),
        (&q::Z_DEG, "deg", "Fig. 4", 0.1),
    ] {
        let drift = last(SeriesKey::new("uvz-rk4", quantity))? - last(SeriesKey::truth(quantity))?;
        let name = quantity.key.trim_end_matches("_deg");
        rows.push(Row::check(
            format!("gyro-only |drift| of {name} at 100 s (bias 0.1 °/s)"),
            format!("drifts ({figs})"),
            drift.abs(),
            unit,
            Expectation::above(threshold),
        ));
    }
    Ok(rows)
}

/// The accelerometer-only (uᵃ, vᵃ) are noisy as the closed form says (Fig. 7).
fn noise_rows(sim: &Trace) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let resid = |quantity: &'static Quantity| -> Result<Vec<f64>, AnalysisError> {
        Ok(sim
            .after(SeriesKey::new("accel", quantity), 0.0)?
            .iter()
            .zip(sim.after(SeriesKey::truth(quantity), 0.0)?)
            .map(|(a, t)| a - t)
            .collect())
    };
    // (uᵃ, vᵃ) = (n_ξ, n_η)/(1 + n_ζ): noise across k enters scaled by about 1/(1 + c′).
    let kz = sim.after(SeriesKey::truth(&q::K_Z), 0.0)?;
    let predicted =
        0.01 * rms(&kz.iter().map(|c| 1.0 / (1.0 + c)).collect::<Vec<_>>()).of("1/(1 + c′)")?;
    for (name, quantity) in [("u", &q::U), ("v", &q::V)] {
        rows.push(Row::check(
            format!("accelerometer-only noise of {name}ᵃ (rms)"),
            "— (closed form σ/(1+c′) along the true motion)",
            rms(&resid(quantity)?).of("accelerometer residual")?,
            "",
            Expectation::Near {
                value: predicted,
                tol: 0.1 * predicted,
            },
        ));
    }
    Ok(rows)
}

/// The blend and the Kalman filter remove both the noise and the drift (Fig. 10).
fn blend_rows(sim: &Trace) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let last = |key: SeriesKey| sim.last(key);
    let tilt = |id: &'static str| sim.after(SeriesKey::new(id, &q::TILT_ERR_DEG), 5.0);
    let gyro_end = last(SeriesKey::new("uvz-rk4", &q::TILT_ERR_DEG))?;
    let accel_rms = rms(&tilt("accel")?).of("accelerometer tilt error")?;
    rows.push(Row::check(
        "gyro-only tilt error at 100 s",
        "grows with t (Fig. 8)",
        gyro_end,
        "deg",
        Expectation::above(0.5),
    ));
    rows.push(Row::check(
        "accelerometer-only tilt error, rms t>5 s",
        "noisy (Fig. 7)",
        accel_rms,
        "deg",
        Expectation::above(0.1),
    ));
    for (id, name) in [("blend", "blend T = 1 s"), ("kf-uv", "Kalman filter (u,v)")] {
        let t = tilt(id)?;
        rows.push(Row::check(
            format!("{name}: tilt error rms t>5 s, below half the accelerometer's"),
            "the blend removes the noise (Fig. 10)",
            rms(&t).of("tilt error")?,
            "deg",
            Expectation::below(accel_rms / 2.0),
        ));
        rows.push(Row::check(
            format!("{name}: tilt error max t>5 s, below the gyro-only error at 100 s"),
            "and the drift (Fig. 10)",
            max_abs(&t).of("tilt error")?,
            "deg",
            Expectation::below(gyro_end),
        ));
        rows.push(Row::check(
            format!("{name}: tilt error at 100 s, below a fifth of the gyro-only error"),
            "no drift (Fig. 10)",
            last(SeriesKey::new(id, &q::TILT_ERR_DEG))?,
            "deg",
            Expectation::below(gyro_end / 5.0),
        ));
    }
    Ok(rows)
}

/// A tumble through upside down: the chart switch is exact and the blends stay bounded.
fn tumble_rows() -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let tumble = run(
        &["profile=2"],
        1,
        100.0,
        &[
            SeriesKey::truth(&q::K_Z),
            SeriesKey::new("uvz-rk4", &q::ERR_DEG),
            SeriesKey::new("quat-rk4", &q::ERR_DEG),
            SeriesKey::new("blend", &q::TILT_ERR_DEG),
            SeriesKey::new("kf-uv", &q::TILT_ERR_DEG),
        ],
    )?;
    rows.push(Row::check(
        "tumble: lowest vertical k_z (upside down)",
        "— (the motion passes w = ∞)",
        min(tumble.series(SeriesKey::truth(&q::K_Z))?).of("k_z")?,
        "",
        Expectation::below(-0.95),
    ));
    let diff: Vec<f64> = tumble
        .series(SeriesKey::new("uvz-rk4", &q::ERR_DEG))?
        .iter()
        .zip(tumble.series(SeriesKey::new("quat-rk4", &q::ERR_DEG))?)
        .map(|(a, b)| a - b)
        .collect();
    rows.push(Row::check(
        "tumble: |err (u,v,z) − err quaternion| max",
        "— (the chart switch is exact)",
        max_abs(&diff).of("(u, v, z) vs quaternion")?,
        "deg",
        Expectation::below(1e-6),
    ));
    for id in ["blend", "kf-uv"] {
        rows.push(Row::check(
            format!("tumble: {id} tilt error max t>5 s"),
            "— (bounded through w = ∞)",
            max_abs(&tumble.after(SeriesKey::new(id, &q::TILT_ERR_DEG), 5.0)?).of("tilt error")?,
            "deg",
            Expectation::below(2.0),
        ));
    }
    Ok(rows)
}

/// One RK4 step each of (u, v), (u, v, z) and the quaternion, same rates: the cost claim.
pub fn timing_items() -> Vec<TimingItem> {
    let rate = Vector3::new(0.01, -0.02, 0.03);
    let dt = 0.01;
    let mut uv = Vector2::new(0.1, 0.2);
    let mut wz = WzAttitude::north(0.1, 0.2, 0.0);
    let mut q = EulerYpr::new(0.0, 0.2, 0.1).to_quaternion();
    vec![
        TimingItem {
            name: "RK4 step (u, v), eqs. 18–19",
            flops: None,
            run: Box::new(move || {
                uv = rk4_step(0.0, black_box(&uv), dt, |_, x| {
                    uv_derivative(x, &black_box(rate))
                })
            }),
        },
        TimingItem {
            name: "RK4 step (u, v, z), eq. 21",
            flops: None,
            run: Box::new(move || wz = step_uvz_rk4(black_box(&wz), |_| black_box(rate), dt)),
        },
        TimingItem {
            name: "RK4 step quaternion (normalised)",
            flops: None,
            run: Box::new(move || q = step_quaternion_rk4(black_box(&q), |_| black_box(rate), dt)),
        },
    ]
}
