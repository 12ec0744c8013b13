//! `attlab reproduce p3`: the paper's scenario measured, and the lab's cost comparison.

use super::super::scenario::{last_value, max_abs, rms, run_scenario, series_after};
use super::super::{AnchorRow, Reproduction, TimingItem};
use super::WzSphere;
use crate::dynamics::EulerMotion;
use crate::math::{
    EulerYpr, WzAttitude, rk4_step, step_quaternion_rk4, step_uvz_rk4, uv_derivative,
};
use crate::sim::Simulation;
use nalgebra::{Vector2, Vector3};
use std::hint::black_box;

fn run(assignments: &[&str], seed: u64, duration_s: f64) -> Simulation {
    run_scenario(&WzSphere, assignments, seed, duration_s)
}

fn last(sim: &Simulation, name: &str) -> f64 {
    last_value(sim, name)
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
        worst = d
            .iter()
            .fold(worst, |m, x| m.max(crate::sim::wrap_pi(*x).abs()));
    }
    worst
}

/// The reproduction table.
pub fn reproduce() -> Reproduction {
    let mut rows = Vec::new();
    let e = error_free_euler_error(0.01);
    rows.push(AnchorRow::new(
        "error-free (w,z) → Euler vs true angles, max, 100 s",
        "≤ 1e-9",
        e,
        "rad",
        e <= 1e-9,
    ));
    let sim = run(&[], 1, 100.0);
    let d = |q: &str| last(&sim, &format!("uvz-rk4.{q}")) - last(&sim, &format!("truth.{q}"));
    // (series, unit, paper figures, threshold for "drifts")
    for (q, unit, figs, threshold) in [
        ("u", "", "Fig. 4, 7", 1e-3),
        ("v", "", "Fig. 4, 7, 8", 1e-3),
        ("z_deg", "deg", "Fig. 4", 0.1),
    ] {
        let drift = d(q);
        let name = q.trim_end_matches("_deg");
        rows.push(AnchorRow::new(
            format!("gyro-only drift of {name} at 100 s (bias 0.1 °/s)"),
            format!("drifts ({figs})"),
            drift,
            unit,
            drift.abs() > threshold,
        ));
    }
    let resid = |q: &str| -> Vec<f64> {
        series_after(&sim, &format!("accel.{q}"), 0.0)
            .iter()
            .zip(series_after(&sim, &format!("truth.{q}"), 0.0))
            .map(|(a, t)| a - t)
            .collect()
    };
    // (uᵃ, vᵃ) = (n_ξ, n_η)/(1 + n_ζ): noise across k enters scaled by about 1/(1 + c′).
    let kz = series_after(&sim, "truth.k_z", 0.0);
    let predicted = 0.01 * rms(&kz.iter().map(|c| 1.0 / (1.0 + c)).collect::<Vec<_>>());
    let (nu, nv) = (rms(&resid("u")), rms(&resid("v")));
    rows.push(AnchorRow::new(
        "accelerometer-only noise of uᵃ (rms)",
        format!("≈ σ/(1+c′) = {predicted:.4}"),
        nu,
        "",
        (nu / predicted - 1.0).abs() < 0.1,
    ));
    rows.push(AnchorRow::new(
        "accelerometer-only noise of vᵃ (rms)",
        format!("≈ σ/(1+c′) = {predicted:.4}"),
        nv,
        "",
        (nv / predicted - 1.0).abs() < 0.1,
    ));
    let tilt = |id: &str| series_after(&sim, &format!("{id}.tilt_err_deg"), 5.0);
    let (gyro_end, accel_rms) = (last(&sim, "uvz-rk4.tilt_err_deg"), rms(&tilt("accel")));
    rows.push(AnchorRow::new(
        "gyro-only tilt error at 100 s",
        "grows with t",
        gyro_end,
        "deg",
        gyro_end > 0.5,
    ));
    rows.push(AnchorRow::new(
        "accelerometer-only tilt error, rms t>5 s",
        "noisy (Fig. 7)",
        accel_rms,
        "deg",
        accel_rms > 0.1,
    ));
    for (id, name) in [("blend", "blend T = 1 s"), ("kf-uv", "Kalman filter (u,v)")] {
        let t = tilt(id);
        let (r, m, end) = (
            rms(&t),
            max_abs(&t),
            last(&sim, &format!("{id}.tilt_err_deg")),
        );
        rows.push(AnchorRow::new(
            format!("{name}: tilt error rms t>5 s"),
            format!("< accel rms/2 = {:.3}", accel_rms / 2.0),
            r,
            "deg",
            r < accel_rms / 2.0,
        ));
        rows.push(AnchorRow::new(
            format!("{name}: tilt error max t>5 s"),
            "bounded, no drift",
            m,
            "deg",
            m < gyro_end,
        ));
        rows.push(AnchorRow::new(
            format!("{name}: tilt error at 100 s"),
            format!("< gyro-only/5 = {:.3}", gyro_end / 5.0),
            end,
            "deg",
            end < gyro_end / 5.0,
        ));
    }
    let tumble = run(&["profile=2"], 1, 100.0);
    let min_kz = series_after(&tumble, "truth.k_z", 0.0)
        .into_iter()
        .fold(1.0_f64, f64::min);
    rows.push(AnchorRow::new(
        "tumble: lowest vertical k_z (upside down)",
        "< -0.95",
        min_kz,
        "",
        min_kz < -0.95,
    ));
    let diff: Vec<f64> = series_after(&tumble, "uvz-rk4.err_deg", 0.0)
        .iter()
        .zip(series_after(&tumble, "quat-rk4.err_deg", 0.0))
        .map(|(a, b)| a - b)
        .collect();
    rows.push(AnchorRow::new(
        "tumble: |err (u,v,z) − err quaternion| max",
        "≤ 1e-6 (chart switch exact)",
        max_abs(&diff),
        "deg",
        max_abs(&diff) <= 1e-6,
    ));
    for id in ["blend", "kf-uv"] {
        let m = max_abs(&series_after(&tumble, &format!("{id}.tilt_err_deg"), 5.0));
        rows.push(AnchorRow::new(
            format!("tumble: {id} tilt error max t>5 s"),
            "< 2 (bounded through w = ∞)",
            m,
            "deg",
            m < 2.0,
        ));
    }
    Reproduction {
        lab: "p3".into(),
        rows,
        notes: vec![
            "the paper prints no table: drift, noise and blend values are this simulator's (RK4, 100 Hz, bias +0.1 °/s on all axes, σ = 0.01 g)".into(),
            "tilt error = angle between the true and the estimated vertical (pitch and roll together)".into(),
        ],
    }
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
            run: Box::new(move || {
                uv = rk4_step(0.0, black_box(&uv), dt, |_, x| {
                    uv_derivative(x, &black_box(rate))
                })
            }),
        },
        TimingItem {
            name: "RK4 step (u, v, z), eq. 21",
            run: Box::new(move || wz = step_uvz_rk4(black_box(&wz), |_| black_box(rate), dt)),
        },
        TimingItem {
            name: "RK4 step quaternion (normalised)",
            run: Box::new(move || q = step_quaternion_rk4(black_box(&q), |_| black_box(rate), dt)),
        },
    ]
}
