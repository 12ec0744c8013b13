//! `attlab reproduce p2`: Table 3 as measured here beside the paper's, the ST+Gyro σ of
//! Figs. 4–5, bias convergence, and the disturbance filter's gain for Mag+Sun.
//!
//! Two accuracies per filter: the paper's metric, √max diag P∞ of the attitude (as a
//! rotation angle, twice the λ of the state) at the end of the run, and the measured σ —
//! the RMS over the last 60 s of 200 s of each axis' error against the truth (mean
//! included), largest axis. The checks assert what the paper makes certain; single numbers
//! whose exponents the OCR lost are reported, not asserted.
// Only the CLI and the tests reproduce a paper (the `study` feature): without it, what only
// `reproduce` uses is left out (the page's wasm).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::accuracy::{RUN_S, Runs, acc_of, run_all};
use super::sensors::{GYRO_BIAS, MAG_BIAS};
use super::{PARAMS, TabletSat};
use crate::analysis::scenario::{Trace, run_trace};
use crate::analysis::stats;
use crate::analysis::{AnalysisError, StatsContext};
use crate::estimators::mekf;
use crate::model::{
    Calibration, Expectation, ParamValues, Reproduction, Row, SENSITIVITY_FACTORS, SeriesKey,
};
use crate::page::Lab;

/// Seconds after which |estimate − truth| of a bias stays below `tol` (NaN if never).
fn convergence_time(
    trace: &Trace,
    estimate: &str,
    truth: &str,
    tol: f64,
) -> Result<f64, AnalysisError> {
    let (e, t) = (trace.series(estimate)?, trace.series(truth)?);
    let times = trace.t_s();
    // The last sample that is out of tolerance (NaN counts as out).
    let last_bad = e
        .iter()
        .zip(t)
        .zip(times)
        .rev()
        .find(|((e, t), _)| (*e - *t).abs().partial_cmp(&tol) != Some(std::cmp::Ordering::Less))
        .map(|(_, time)| *time);
    Ok(match last_bad {
        None => 0.0,
        Some(time) if time >= times[times.len() - 1] => f64::NAN,
        Some(time) => time,
    })
}

/// The reproduction table.
pub fn reproduce() -> Result<Reproduction, AnalysisError> {
    let all = run_all(&[], 1)?;
    let mut rows = super::paper_tables::rows(&all)?;
    rows.extend(hierarchy_rows(&all)?);
    rows.extend(super::metrics::rows(&all)?);
    rows.extend(per_axis_rows(&all)?);
    biases(&mut rows)?;
    disturbance(&mut rows, &all)?;
    rows.extend(super::constant_gain::rows()?);
    rows.extend(super::fig7::rows()?);
    rows.extend(super::table4::rows()?);
    rows.extend(super::tune::rows()?);
    Ok(Reproduction {
        lab: super::SPEC.id.into(),
        rows,
        notes: [
            "unstated in the paper and chosen here: circular sun-synchronous orbit 600 km, node at 10:30, 19 June 2026; WMM 2025 as the field; wheel gains K_λ = 5e-4, K_ω = 0.02; sensors at 1 Hz, EKF prediction at 10 Hz; P₀ from a 2° attitude error; star tracker 45° off zenith, away from the sun (it sees stars around the whole default orbit, as in the paper's runs); disturbance filter R_d = 100 × the row's innovation variance, α = 0.999 per second",
            "σ measured = RMS over the last 60 s of a 200-s run (mean included), largest axis; the paper's metric = √max diag P∞ (attitude as a rotation angle, 2λ)",
            "where Table 3's q lost its exponent in the OCR the filter uses this project's q (marked 'q ours'); where the OCR reads it but is unsure (Mag+Sun+Gyro's q, ST+Mag's q_Δb) the filter uses that reading and its NEES row says so",
        ]
        .map(String::from)
        .to_vec(),
    })
}

/// Filter `id`'s measured attitude σ (deg) in a run with parameter `key` at `value`.
fn att_sigma_with(id: &str, key: &str, value: f64) -> Result<f64, AnalysisError> {
    let set = format!("{key}={value}");
    Ok(acc_of(&run_all(&[&set], 1)?, id)?.att_rms_deg)
}

/// The hierarchy of sensor sets the paper makes certain, and the two sets it gives numbers
/// for.
fn hierarchy_rows(all: &Runs) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let st_sets = [
        "st-gyro-mag-sun",
        "st-gyro-mag",
        "st-mag-sun",
        "st-mag-mbias",
        "st-gyro",
        "st-gyro-gbias",
        "st",
    ];
    let worst_st = stats::max(
        &st_sets
            .iter()
            .map(|id| acc_of(all, id).map(|a| a.att_rms_deg))
            .collect::<Result<Vec<_>, _>>()?,
    )
    .of("star-tracker sets")?;
    let msg = acc_of(all, "mag-sun-gyro")?.att_rms_deg;
    let ms = acc_of(all, "mag-sun")?.att_rms_deg;
    let mg = acc_of(all, "mag-gyro")?.att_rms_deg;
    rows.push(Row::check(
        "finding: worst star-tracker set below Mag+Sun+Gyro",
        "ST sets ≈ 5e-4–8e-4° ≪ Mag+Sun+Gyro ≈ 0.02°",
        worst_st,
        "deg",
        Expectation::below(msg),
    ));
    rows.push(Row::check(
        "finding: Mag+Sun+Gyro below Mag+Sun",
        "0.02° < 0.12°",
        msg,
        "deg",
        Expectation::below(ms),
    ));
    rows.push(Row::check(
        "finding: Mag+Sun+Gyro below Mag+Gyro",
        "0.02° < 0.2°",
        msg,
        "deg",
        Expectation::below(mg),
    ));
    rows.push(Row::measurement(
        "Mag+Sun vs Mag+Gyro (ratio; swaps with the field–sun geometry, not asserted)",
        "0.12° vs 0.2°",
        ms / mg,
        "",
    ));
    Ok(rows)
}

/// Figs. 4–5: ST+Gyro's attitude and rate σ per axis. They match at the star tracker's and
/// the gyro's rate chosen here (1 Hz): the same rows at ±50 % sit beside them.
fn per_axis_rows(all: &Runs) -> Result<Vec<Row>, AnalysisError> {
    let defaults = ParamValues::defaults(PARAMS);
    let (star_hz, gyro_hz) = (defaults.get("star_rate_hz"), defaults.get("gyro_rate_hz"));
    let rates = Calibration {
        how: "the gyro's too, and the star tracker 45° off zenith, also chosen here",
        ..Calibration::new("star-tracker rate", star_hz, "Hz")
    };
    let mut at = Vec::new();
    for factor in SENSITIVITY_FACTORS {
        let star = format!("star_rate_hz={}", star_hz * factor);
        let gyro = format!("gyro_rate_hz={}", gyro_hz * factor);
        at.push((factor, *acc_of(&run_all(&[&star, &gyro], 1)?, "st-gyro")?));
    }
    let stg_at = |factor: f64| {
        at.iter()
            .find(|(f, _)| *f == factor)
            .map(|(_, a)| *a)
            .ok_or_else(|| AnalysisError::Scenario(format!("×{factor} rates were not run")))
    };
    let stg = acc_of(all, "st-gyro")?;
    let mut rows = Vec::new();
    for (k, (paper, axis)) in [1.448e-3, 8.211e-4, 1.150e-3]
        .iter()
        .zip(["x", "y", "z"])
        .enumerate()
    {
        let check = Row::check(
            format!("ST+Gyro attitude σ about {axis} (Fig. 4)"),
            format!("{paper:e}°"),
            stg.att_axes_deg[k],
            "deg",
            Expectation::within_factor_of(*paper, 3.0),
        );
        rows.extend(rates.rows(check, |f| {
            Ok::<_, AnalysisError>(stg_at(f)?.att_axes_deg[k])
        })?);
    }
    for (k, (paper, axis)) in [2.305e-4, 3.449e-4, 2.089e-4]
        .iter()
        .zip(["x", "y", "z"])
        .enumerate()
    {
        let check = Row::check(
            format!("ST+Gyro rate σ about {axis} (Fig. 5)"),
            format!("{paper:e} °/s"),
            stg.rate_axes_deg_s[k],
            "deg/s",
            Expectation::within_factor_of(*paper, 3.0),
        );
        rows.extend(rates.rows(check, |f| {
            Ok::<_, AnalysisError>(stg_at(f)?.rate_axes_deg_s[k])
        })?);
    }
    Ok(rows)
}

/// Seconds after which every axis of a bias estimate stays within `tol` of the truth, in a
/// 200-s run with `assignment`: `estimate` and `truth` are series names with `{a}` for the
/// axis. NaN if some axis never settles.
fn bias_convergence_s(
    assignment: &str,
    estimate: [SeriesKey; 3],
    truth: [SeriesKey; 3],
    tol: f64,
) -> Result<f64, AnalysisError> {
    let keys: Vec<SeriesKey> = estimate.iter().chain(&truth).copied().collect();
    let lab: &'static dyn Lab = &TabletSat;
    let trace = run_trace(lab, &[assignment], 1, RUN_S, &keys)?;
    let mut worst: f64 = 0.0;
    for (e, t) in estimate.iter().zip(&truth) {
        let t = convergence_time(&trace, &e.name(), &t.name(), tol)?;
        worst = if t.is_nan() || worst.is_nan() {
            f64::NAN
        } else {
            worst.max(t)
        };
    }
    Ok(worst)
}

/// Bias convergence: the gyro bias of ST+Gyro+Δω and the magnetometer bias of
/// Mag+Sun+Gyro+Δb reach and stay within tolerance of the truth.
fn biases(rows: &mut Vec<Row>) -> Result<(), AnalysisError> {
    rows.push(Row::check(
        "ST+Gyro+Δω: gyro bias 0.05 °/s within 0.005 °/s after",
        "biases converge from 0 in < 1 min (Figs. 6–7)",
        bias_convergence_s(
            "gyro_bias_deg_s=0.05",
            [
                &mekf::GBIAS_X_DEG_S,
                &mekf::GBIAS_Y_DEG_S,
                &mekf::GBIAS_Z_DEG_S,
            ]
            .map(|q| SeriesKey::new("st-gyro-gbias", q)),
            GYRO_BIAS.each_ref().map(SeriesKey::sensors),
            0.005,
        )?,
        "s",
        Expectation::below(60.0),
    ));
    rows.push(
        Row::check(
            "Mag+Sun+Gyro+Δb: magnetometer bias 2000 nT within 400 nT (Table 3's Δb accuracy) after",
            "biases converge from 0 in < 1 min (Figs. 6–7)",
            bias_convergence_s(
                "mag_bias_nt=2000",
                [&mekf::MBIAS_X_NT, &mekf::MBIAS_Y_NT, &mekf::MBIAS_Z_NT]
                    .map(|q| SeriesKey::new("mag-sun-gyro-mbias", q)),
                MAG_BIAS.each_ref().map(SeriesKey::sensors),
                400.0,
            )?,
            "s",
            Expectation::below(60.0),
        )
        .known_to_differ(
            "a bias across both the field and the sun looks like a turn about the sun line; only the slowly turning geometry separates them (the other components converge within seconds)",
        ),
    );
    Ok(())
}

/// The disturbance filter's gain for Mag+Sun (paper: 0.12° → 0.03°).
fn disturbance(rows: &mut Vec<Row>, all: &Runs) -> Result<(), AnalysisError> {
    let plain = acc_of(all, "mag-sun")?.att_rms_deg;
    let with = acc_of(all, "mag-sun-dist")?.att_rms_deg;
    let check = Row::check(
        "Mag+Sun with the disturbance filter, attitude σ, below Mag+Sun without",
        "0.12° → 0.03° (§3.2)",
        with,
        "deg",
        Expectation::below(plain),
    );
    let rd_scale = ParamValues::defaults(PARAMS).get("rd_scale");
    let rd = Calibration {
        how: "× each row's innovation variance",
        ..Calibration::new("disturbance filter R_d scale", rd_scale, "")
    };
    rows.extend(rd.rows(check, |f| {
        att_sigma_with("mag-sun-dist", "rd_scale", rd_scale * f)
    })?);
    rows.push(Row::measurement(
        "Mag+Sun: σ without / with the disturbance filter",
        "4",
        plain / with,
        "×",
    ));
    Ok(())
}
