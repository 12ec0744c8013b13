//! The free-rotation lab's checks: no paper anchors, but the perfect model, the
//! conservation laws, the chart switch and the bias drift against an independent
//! first-order computation.
// Only the CLI and the tests reproduce a paper (the `study` feature): without it, what only
// `reproduce` uses is left out (the page's wasm).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::FreeRotation;
use super::sensors::BIAS_PATTERN;
use crate::analysis::scenario::{Trace, run_trace};
use crate::analysis::stats;
use crate::analysis::{AnalysisError, StatsContext};
use crate::model::{Expectation, Reproduction, Row, SeriesKey, q};
use crate::page::Lab;
use nalgebra::Vector3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

fn run(
    assignments: &[&str],
    duration_s: f64,
    series: &[SeriesKey],
) -> Result<Trace, AnalysisError> {
    run_trace(&FreeRotation, assignments, 1, duration_s, series)
}

/// An independent first-order prediction of the attitude error a constant gyro bias causes:
/// the error in the reference frame grows as dδ/dt = R_ref_from_body(t)·b, so
/// |δ(T)| = |∫₀ᵀ R(t) b dt|, integrated (trapezoid) along the true motion alone — no
/// estimator code involved.
fn bias_error_first_order(assignments: &[&str], duration_s: f64) -> Result<f64, AnalysisError> {
    let p = crate::analysis::scenario::params_with(&FreeRotation, assignments)?;
    let b = BIAS_PATTERN * p.get("gyro_bias_deg_s").to_radians();
    let dt = FreeRotation.dt_s(&p);
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    let mut truth = FreeRotation.build(&p, &mut rng).truth;
    let mut delta = Vector3::zeros();
    let mut prev = truth.state().q_ref_from_body * b;
    let steps = (duration_s / dt).round() as usize;
    for _ in 0..steps {
        truth.step(dt);
        let now = truth.state().q_ref_from_body * b;
        delta += (prev + now) * (0.5 * dt);
        prev = now;
    }
    Ok(delta.norm())
}

pub(super) fn reproduce() -> Result<Reproduction, AnalysisError> {
    let clean = run(&CLEAN, 60.0, &CLEAN_SERIES)?;
    let mut rows = integration_rows(&clean)?;
    rows.extend(truth_rows(&clean)?);
    rows.extend(bias_rows()?);
    Ok(Reproduction {
        lab: super::SPEC.id.into(),
        rows,
        notes: vec![
            "no paper anchors: this foundation lab checks the perfect model, conservation laws, the chart switch and the bias drift against an independent first-order computation".into(),
        ],
    })
}

/// No noise, no bias: the perfect model.
const CLEAN: [&str; 2] = ["gyro_noise_deg_s=0", "gyro_bias_deg_s=0"];

/// What the error-free run records.
const CLEAN_SERIES: [SeriesKey; 9] = [
    SeriesKey::new("quat-rk4", &q::ERR_DEG),
    SeriesKey::new("quat-rk4", &q::K_X),
    SeriesKey::new("quat-rk4", &q::K_Y),
    SeriesKey::new("quat-rk4", &q::K_Z),
    SeriesKey::new("uvz-rk4", &q::K_X),
    SeriesKey::new("uvz-rk4", &q::K_Y),
    SeriesKey::new("uvz-rk4", &q::K_Z),
    SeriesKey::truth(&super::truth::ENERGY_J),
    SeriesKey::truth(&q::K_Z),
];

/// The integrators on error-free samples: their error, its order in dt, and the
/// quaternion and (u, v, z) integrators agreeing.
fn integration_rows(clean: &Trace) -> Result<Vec<Row>, AnalysisError> {
    let fine = run(
        &[CLEAN[0], CLEAN[1], "rate_hz=200"],
        60.0,
        &[SeriesKey::new("quat-rk4", &q::ERR_DEG)],
    )?;
    let q_err = stats::max_abs(clean.series(SeriesKey::new("quat-rk4", &q::ERR_DEG))?)
        .of("error-free quaternion error")?
        .to_radians();
    let q_err_fine = stats::max_abs(fine.series(SeriesKey::new("quat-rk4", &q::ERR_DEG))?)
        .of("error-free error at 200 Hz")?
        .to_radians();
    let mut k_diff = Vec::new();
    for axis in [&q::K_X, &q::K_Y, &q::K_Z] {
        let a = clean.series(SeriesKey::new("quat-rk4", axis))?;
        let b = clean.series(SeriesKey::new("uvz-rk4", axis))?;
        k_diff.extend(a.iter().zip(b).map(|(x, y)| x - y));
    }
    Ok(vec![
        Row::check(
            "error-free: max quaternion error, 100 Hz, 60 s",
            "— (perfect model)",
            q_err,
            "rad",
            Expectation::below(1e-4),
        ),
        // The integrators see the rate only at the samples (linear in between) while the
        // truth integrates the exact rate, so the error-free error is O(dt²): halving dt
        // quarters it.
        Row::check(
            "error-free: error ratio 100 Hz / 200 Hz",
            "— (O(dt²): 4)",
            q_err / q_err_fine,
            "",
            Expectation::Near {
                value: 4.0,
                tol: 0.5,
            },
        ),
        Row::check(
            "quaternion vs (u,v,z) on the same samples: max |Δk|",
            "— (same kinematics)",
            stats::max_abs(&k_diff).of("quaternion vs (u, v, z)")?,
            "",
            Expectation::below(1e-9),
        ),
    ])
}

/// The truth itself: energy conserved, and the intermediate-axis tumble flipping over.
fn truth_rows(clean: &Trace) -> Result<Vec<Row>, AnalysisError> {
    let energy = clean.series(SeriesKey::truth(&super::truth::ENERGY_J))?;
    let e0 = *energy
        .first()
        .ok_or_else(|| AnalysisError::UnknownSeries("no energy rows".into()))?;
    let kz = clean.series(SeriesKey::truth(&q::K_Z))?;
    Ok(vec![
        Row::check(
            "truth: relative energy drift, 60 s",
            "— (torque free: 0)",
            ((clean.last(SeriesKey::truth(&super::truth::ENERGY_J))? - e0) / e0).abs(),
            "",
            Expectation::below(1e-9),
        ),
        Row::check(
            "intermediate-axis tumble: lowest vertical k_z",
            "— (Dzhanibekov: flips)",
            stats::min(kz).of("truth k_z")?,
            "",
            Expectation::below(-0.9),
        ),
        Row::check(
            "intermediate-axis tumble: highest vertical k_z",
            "— (and back)",
            stats::max(kz).of("truth k_z")?,
            "",
            Expectation::above(0.9),
        ),
    ])
}

/// A constant bias of 0.1 °/s: the quaternion error against an independent first-order
/// computation and a closed-form bound.
fn bias_rows() -> Result<Vec<Row>, AnalysisError> {
    let biased_set = ["gyro_noise_deg_s=0", "gyro_bias_deg_s=0.1"];
    let biased = run(
        &biased_set,
        60.0,
        &[SeriesKey::new("quat-rk4", &q::ERR_DEG)],
    )?;
    let b_err = biased.last(SeriesKey::new("quat-rk4", &q::ERR_DEG))?;
    let reference = bias_error_first_order(&biased_set, 60.0)?.to_degrees();
    Ok(vec![
        Row::check(
            "bias 0.1 °/s: quaternion error at 60 s vs first-order |∫R b dt|",
            "— (independent reference computation)",
            b_err,
            "deg",
            Expectation::Near {
                value: reference,
                tol: 0.05 * reference,
            },
        ),
        Row::check(
            "bias 0.1 °/s: quaternion error at 60 s vs √3·b·t",
            "— (closed-form bound: a body that never turns)",
            b_err,
            "deg",
            Expectation::below(3f64.sqrt() * 0.1 * 60.0),
        ),
    ])
}
