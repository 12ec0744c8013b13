//! `attlab reproduce p5`: the paper's case — initial Krylov angles (0.5, 0.7, 0.2), reference
//! (0.01, 0.02, 0.01), tolerance 0.01 — for a grid of Δt: the first time each method meets
//! the tolerance, the Δt that gives the paper's 2.36; method (9)'s oscillation (errors at
//! successive updates, the eigenvalues of its linearised update); the re-integrating
//! variant's convergence; the gyro-bias case (p → −b); and U against finite differences.
// Only the CLI and the tests reproduce a paper (the `study` feature): without it, what only
// `reproduce` uses is left out (the page's wasm).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::sensors::REFERENCE;
use super::truth::ANGLES;
use super::{METHODS, SensitivityLab};
use crate::analysis::scenario::{Trace, run_trace};
use crate::analysis::stats;
use crate::analysis::{AnalysisError, StatsContext};
use crate::estimators::sensitivity;
use crate::estimators::{Method, linearised_eigenvalues, sensitivity_finite_difference_check};
use crate::math::{RK_METHODS, wrap_pi};
use crate::model::{Calibration, Expectation, Reproduction, Row, SeriesKey};
use crate::page::Lab;

/// The Δt grid (s).
const GRID: [f64; 10] = [0.5, 0.8, 1.0, 1.1, 1.15, 1.17, 1.2, 1.25, 1.5, 2.0];

/// First time (s) series `id.within_tol` is 1, NaN if never.
pub fn first_hit_s(trace: &Trace, id: &'static str) -> Result<f64, AnalysisError> {
    let within = trace.series(SeriesKey::new(id, &sensitivity::WITHIN_TOL))?;
    Ok(trace
        .t_s()
        .iter()
        .zip(within)
        .find(|(_, w)| **w > 0.5)
        .map_or(f64::NAN, |(t, _)| *t))
}

/// A method's angles and its within-tolerance flag.
fn series(id: &'static str) -> impl Iterator<Item = SeriesKey> {
    ANGLES
        .iter()
        .map(move |q| SeriesKey::new(id, q))
        .chain([SeriesKey::new(id, &sensitivity::WITHIN_TOL)])
}

fn run(assignments: &[&str], duration_s: f64, extra: &[SeriesKey]) -> Result<Trace, AnalysisError> {
    let mut keys: Vec<SeriesKey> = METHODS.iter().flat_map(|(id, ..)| series(id)).collect();
    keys.extend(ANGLES.iter().map(|q| SeriesKey::truth(q)));
    keys.push(SeriesKey::sensors(&REFERENCE));
    keys.extend_from_slice(extra);
    let lab: &'static dyn Lab = &SensitivityLab;
    run_trace(lab, assignments, 1, duration_s, &keys)
}

/// Every method's angles and flags, the true angles and the reference instants for
/// `duration_s` of the run of `params` at seed 1, with the series `extra`.
pub(super) fn run_params(
    params: crate::model::ParamValues,
    duration_s: f64,
    extra: &[SeriesKey],
) -> Result<Trace, AnalysisError> {
    let mut keys: Vec<SeriesKey> = METHODS.iter().flat_map(|(id, ..)| series(id)).collect();
    keys.extend(ANGLES.iter().map(|q| SeriesKey::truth(q)));
    keys.push(SeriesKey::sensors(&REFERENCE));
    keys.extend_from_slice(extra);
    let lab: &'static dyn Lab = &SensitivityLab;
    crate::analysis::scenario::run_trace_with(lab, params, 1, duration_s, &keys)
}

/// Largest angle error (rad) of `id` at each reference instant.
pub(super) fn errors_at_updates(
    trace: &Trace,
    id: &'static str,
) -> Result<Vec<f64>, AnalysisError> {
    let refs = trace.series(SeriesKey::sensors(&REFERENCE))?;
    let mut out = Vec::new();
    for (k, r) in refs.iter().enumerate() {
        if *r < 0.5 {
            continue;
        }
        let mut worst: f64 = 0.0;
        for q in ANGLES {
            let e = trace.series(SeriesKey::new(id, q))?[k] - trace.series(SeriesKey::truth(q))?[k];
            let e = wrap_pi(e).abs();
            worst = if e.is_nan() { f64::NAN } else { worst.max(e) };
        }
        out.push(worst);
    }
    Ok(out)
}

/// The reproduction table.
pub fn reproduce() -> Result<Reproduction, AnalysisError> {
    let mut rows = first_hit_rows()?;
    let trace = run(&["interval_s=1"], 30.0, &[])?;
    rows.extend(oscillation_rows(&trace)?);
    rows.extend(convergence_rows(&trace)?);
    bias_case(&mut rows)?;
    rows.extend(integration_rows()?);
    rows.push(Row::check(
        "U from the sensitivity equations vs finite differences of the integrated Λ",
        "— (∂Λ/∂p, independent computation)",
        sensitivity_finite_difference_check(),
        "",
        Expectation::below(1e-6),
    ));
    Ok(Reproduction {
        lab: super::SPEC.id.into(),
        rows,
        notes: [
            "the paper's case: ω = 0, Q = I, p₀ = 0, ε = 0 for (9) and the variant, ε = 0.1 for (10) and (11), RK4 at 0.01 s, Krylov angles z-y′-x″; Δt, ε and the integration step are not given in the paper",
            "2.36 is a first-hit time: method (9) meets the tolerance just after 2Δt and leaves it again",
        ]
        .map(String::from)
        .to_vec(),
    })
}

/// Over the grid of Δt: each method's first time within tolerance, and the Δt at which
/// method (9) comes nearest the paper's 2.36 s.
fn first_hit_rows() -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let mut best: Option<(f64, f64)> = None;
    for dt in GRID {
        let set = format!("interval_s={dt}");
        let trace = run(&[&set], 12.0 * dt.max(1.0), &[])?;
        for (id, label, method) in METHODS.iter().filter(|m| m.2 != Method::Uncorrected) {
            let t = first_hit_s(&trace, id)?;
            let shown = never_is_infinite(t);
            rows.push(Row::measurement(
                format!("Δt = {dt} s: {label}, first time within 0.01"),
                if *method == Method::Plain {
                    "2.36 (one Δt, unstated)"
                } else {
                    "—"
                },
                shown,
                "s",
            ));
            if *method == Method::Plain
                && t.is_finite()
                && best.is_none_or(|(_, b)| (t - 2.36).abs() < (b - 2.36).abs())
            {
                best = Some((dt, t));
            }
        }
    }
    let (best_dt, best_t) = best.unwrap_or((f64::NAN, f64::NAN));
    let check = Row::check(
        "method (9): first time within 0.01 at the Δt of the grid nearest the paper's 2.36",
        "reached within t = 2.36",
        best_t,
        "s",
        Expectation::Near {
            value: 2.36,
            tol: 0.03,
        },
    );
    let setting = Calibration {
        how: "the grid's Δt whose first hit is nearest 2.36",
        ..Calibration::new("reference interval Δt", best_dt, "s")
    };
    rows.extend(setting.rows(check, |factor| plain_first_hit_s(best_dt * factor))?);
    Ok(rows)
}

/// A first-hit time, ∞ when the tolerance was never met (NaN).
fn never_is_infinite(t: f64) -> f64 {
    if t.is_nan() { f64::INFINITY } else { t }
}

/// Method (9)'s first time within tolerance with reference interval `dt_s`.
fn plain_first_hit_s(dt_s: f64) -> Result<f64, AnalysisError> {
    let set = format!("interval_s={dt_s}");
    let trace = run(&[&set], 12.0 * dt_s.max(1.0), &[])?;
    let (id, ..) = METHODS
        .iter()
        .find(|m| m.2 == Method::Plain)
        .ok_or_else(|| AnalysisError::UnknownSeries("no method (9)".into()))?;
    Ok(never_is_infinite(first_hit_s(&trace, id)?))
}

/// Method (9) at Δt = 1 s oscillates: its errors at the updates, and the eigenvalues of its
/// linearised update on the unit circle.
fn oscillation_rows(trace: &Trace) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let gn = errors_at_updates(trace, "gn9")?;
    for (k, e) in gn.iter().take(6).enumerate() {
        rows.push(Row::measurement(
            format!(
                "method (9), Δt = 1 s: largest angle error at update {}",
                k + 1
            ),
            "— (digest: 0.68, 0.019, 0.67, 0.70, 0.058, 0.64)",
            *e,
            "rad",
        ));
    }
    let late = stats::max(&gn[10.min(gn.len())..]).of("late errors of (9)")?;
    rows.push(Row::check(
        "method (9): largest error at updates 11–30 (does not settle)",
        "oscillates (marginally stable)",
        late,
        "rad",
        Expectation::above(0.1),
    ));
    let [l1, l2] = linearised_eigenvalues(Method::Plain, 1.0, 0.0);
    rows.push(Row::measurement(
        "method (9): |eigenvalues| of the linearised update (closed form)",
        "on the unit circle",
        l1.norm().max(l2.norm()),
        "",
    ));
    rows.push(Row::measurement(
        "method (9): eigenvalue angle (closed form; 60° = period of 6 updates)",
        "—",
        l1.arg().abs().to_degrees(),
        "deg",
    ));
    Ok(rows)
}

/// The re-integrating variant and method (11) at Δt = 1 s converge.
fn convergence_rows(trace: &Trace) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let reint = errors_at_updates(trace, "reint")?;
    for (k, e) in reint.iter().take(4).enumerate() {
        rows.push(Row::measurement(
            format!(
                "re-integrating variant, Δt = 1 s: error at update {}",
                k + 1
            ),
            "— (digest: 0.019 → 0.016 → 1e-5)",
            *e,
            "rad",
        ));
    }
    rows.push(Row::check(
        "re-integrating variant: error at the 4th update",
        "converges within a few intervals (beyond the paper)",
        reint.get(3).copied().unwrap_or(f64::NAN),
        "rad",
        Expectation::below(0.01),
    ));
    let search = errors_at_updates(trace, "search11")?;
    rows.push(Row::check(
        "method (11): largest error at updates 11–30",
        "the approach is effective (digest: (11) re-integrates, so it converges like the variant)",
        stats::max(&search[10.min(search.len())..]).of("late errors of (11)")?,
        "rad",
        Expectation::below(0.01),
    ));
    Ok(rows)
}

/// Beyond the paper, which makes the integration method a setting without naming its own:
/// method (9)'s first hit at Δt = 1.17 s and the re-integrating variant's error after four
/// updates of a turning body with each method, at the default step and at 0.1 s.
fn integration_rows() -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    for (k, method) in RK_METHODS.iter().enumerate() {
        for step in [0.01, 0.1] {
            let set = [format!("integration={k}"), format!("step_s={step}")];
            let with = |extra: &[&str]| -> Vec<String> {
                set.iter()
                    .cloned()
                    .chain(extra.iter().map(|s| s.to_string()))
                    .collect()
            };
            let paper = with(&["interval_s=1.17"]);
            let paper: Vec<&str> = paper.iter().map(String::as_str).collect();
            let trace = run(&paper, 14.0, &[])?;
            rows.push(Row::measurement(
                format!(
                    "beyond the paper: {}, step {step} s ({} evaluations per step): method (9) first time within 0.01 at Δt = 1.17 s (∞: not in 14 s)",
                    method.name, method.stages
                ),
                "— (the paper does not name its method)",
                never_is_infinite(first_hit_s(&trace, "gn9")?),
                "s",
            ));
            let turning = with(&["profile=2", "interval_s=1"]);
            let turning: Vec<&str> = turning.iter().map(String::as_str).collect();
            let trace = run(&turning, 10.0, &[])?;
            let reint = errors_at_updates(&trace, "reint")?;
            rows.push(Row::measurement(
                format!(
                    "beyond the paper: {}, step {step} s: re-integrating variant's error at the 8th update, harmonic rate",
                    method.name
                ),
                "—",
                reint.get(7).copied().unwrap_or(f64::NAN),
                "rad",
            ));
        }
    }
    Ok(rows)
}

/// A turning body with a biased gyro: p converges to −b (the variant, and (10)).
fn bias_case(rows: &mut Vec<Row>) -> Result<(), AnalysisError> {
    // The estimate starts on the truth, so what p must learn is the bias alone.
    let set = [
        "profile=1",
        "gyro_bias_deg_s=2",
        "interval_s=0.5",
        "eps=0.01",
        "init_1_rad=0.01",
        "init_2_rad=0.02",
        "init_3_rad=0.01",
    ];
    let names = [
        SeriesKey::new("reint", &sensitivity::P_X_DEG_S),
        SeriesKey::new("reint", &sensitivity::P_Y_DEG_S),
        SeriesKey::new("reint", &sensitivity::P_Z_DEG_S),
        SeriesKey::new("lm10", &sensitivity::P_X_DEG_S),
        SeriesKey::new("lm10", &sensitivity::P_Y_DEG_S),
        SeriesKey::new("lm10", &sensitivity::P_Z_DEG_S),
    ];
    let trace = run(&set, 30.0, &names)?;
    let b = nalgebra::Vector3::new(1.0, -1.0, 2.0).normalize() * 2.0;
    for (id, label) in [("reint", "re-integrating variant"), ("lm10", "method (10)")] {
        let p = nalgebra::Vector3::new(
            trace.last(SeriesKey::new(id, &sensitivity::P_X_DEG_S))?,
            trace.last(SeriesKey::new(id, &sensitivity::P_Y_DEG_S))?,
            trace.last(SeriesKey::new(id, &sensitivity::P_Z_DEG_S))?,
        );
        let rel = (p + b).norm() / b.norm();
        let row = Row::check(
            format!("gyro bias 2 °/s, {label}: |p + b| / |b| after 30 s"),
            "p converges to −b",
            rel,
            "",
            Expectation::below(0.05),
        );
        rows.push(if id == "reint" {
            row
        } else {
            row.known_to_differ(
                "method (10) keeps oscillating about −b (|eigenvalues| near 1 for small ε)",
            )
        });
    }
    Ok(())
}
