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

use super::sensors::{GYRO_BIAS, MAG_BIAS};
use super::sets::{FILTERS, FilterRow};
use super::{PARAMS, TabletSat};
use crate::analysis::scenario::{Trace, run_trace};
use crate::analysis::stats;
use crate::analysis::{AnalysisError, StatsContext};
use crate::estimators::mekf;
use crate::model::{
    Calibration, Expectation, Lab, ParamValues, Quantity, Reproduction, Row, SENSITIVITY_FACTORS,
    SeriesKey, StateInfo, q,
};

/// Run length (s) and the window σ is taken over (the last 60 s).
const RUN_S: f64 = 200.0;
const WINDOW_FROM_S: f64 = 140.0;

/// One filter's accuracy over one run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FilterAccuracy {
    /// Largest per-axis RMS attitude error over the window (deg).
    pub att_rms_deg: f64,
    /// Per-axis RMS attitude errors (deg).
    pub att_axes_deg: [f64; 3],
    /// Largest per-axis RMS rate error over the window (deg/s).
    pub rate_rms_deg_s: f64,
    /// Per-axis RMS rate errors (deg/s).
    pub rate_axes_deg_s: [f64; 3],
    /// √max diag P of the attitude at the end (deg, rotation angle).
    pub att_p_deg: f64,
    /// √max diag P of the rate at the end (deg/s), NaN without a rate state.
    pub rate_p_deg_s: f64,
    /// Mean NEES of the attitude over the window (3 degrees of freedom).
    pub nees_mean: f64,
}

fn series_of(id: &'static str, has_rate_state: bool) -> Vec<SeriesKey> {
    let mut s: Vec<SeriesKey> = ATT_ERRORS.iter().map(|q| SeriesKey::new(id, q)).collect();
    s.extend(ATT_STATES.iter().map(|st| SeriesKey::variance(id, st)));
    s.push(SeriesKey::nees_att(id));
    s.extend(RATE_ERRORS.iter().map(|q| SeriesKey::new(id, q)));
    if has_rate_state {
        s.extend(RATE_STATES.iter().map(|st| SeriesKey::variance(id, st)));
    }
    s
}

/// The attitude errors about body x, y, z.
const ATT_ERRORS: [&Quantity; 3] = [&q::ERR_X_DEG, &q::ERR_Y_DEG, &q::ERR_Z_DEG];
/// The rate errors about body x, y, z.
const RATE_ERRORS: [&Quantity; 3] = [
    &q::RATE_ERR_X_DEG_S,
    &q::RATE_ERR_Y_DEG_S,
    &q::RATE_ERR_Z_DEG_S,
];
/// The filters' attitude states.
const ATT_STATES: [&StateInfo; 3] = [&mekf::ATT_X, &mekf::ATT_Y, &mekf::ATT_Z];
/// The filters' rate states (not in the reduced filter).
const RATE_STATES: [&StateInfo; 3] = [&mekf::RATE_X, &mekf::RATE_Y, &mekf::RATE_Z];

/// The accuracy of filter `id` in `trace`.
pub fn accuracy(trace: &Trace, id: &'static str) -> Result<FilterAccuracy, AnalysisError> {
    let rms_axes = |quantities: [&'static Quantity; 3]| -> Result<[f64; 3], AnalysisError> {
        let mut out = [0.0; 3];
        for (o, q) in out.iter_mut().zip(quantities) {
            let key = SeriesKey::new(id, q);
            *o = stats::rms(&trace.after(key, WINDOW_FROM_S)?).of(&key.name())?;
        }
        Ok(out)
    };
    let att = rms_axes(ATT_ERRORS)?;
    let rate = rms_axes(RATE_ERRORS)?;
    let p_max = |states: [&'static StateInfo; 3]| -> Result<f64, AnalysisError> {
        let mut v = Vec::new();
        for st in states {
            v.push(trace.last(SeriesKey::variance(id, st))?);
        }
        Ok(stats::max(&v).of("variances")?.sqrt().to_degrees())
    };
    let rate_p = match trace.series(SeriesKey::variance(id, &mekf::RATE_X)) {
        Ok(_) => p_max(RATE_STATES)?,
        Err(_) => f64::NAN,
    };
    Ok(FilterAccuracy {
        att_rms_deg: stats::max(&att).of("attitude σ")?,
        att_axes_deg: att,
        rate_rms_deg_s: stats::max(&rate).of("rate σ")?,
        rate_axes_deg_s: rate,
        att_p_deg: p_max(ATT_STATES)?,
        rate_p_deg_s: rate_p,
        nees_mean: stats::mean(&trace.after(SeriesKey::nees_att(id), WINDOW_FROM_S)?).of("NEES")?,
    })
}

/// A 200-s run of every filter with `assignments`, and each one's accuracy.
pub(super) fn run_all(
    assignments: &[&str],
    seed: u64,
) -> Result<Vec<(&'static FilterRow, FilterAccuracy)>, AnalysisError> {
    let keys: Vec<SeriesKey> = FILTERS
        .iter()
        .flat_map(|f| {
            series_of(
                f.config.id,
                f.config.states != crate::estimators::StateSet::AttGyroBias,
            )
        })
        .collect();
    let lab: &'static dyn Lab = &TabletSat;
    let trace = run_trace(lab, assignments, seed, RUN_S, &keys)?;
    FILTERS
        .iter()
        .map(|f| Ok((f, accuracy(&trace, f.config.id)?)))
        .collect()
}

pub(super) fn acc_of<'a>(all: &'a Runs, id: &str) -> Result<&'a FilterAccuracy, AnalysisError> {
    all.iter()
        .find(|(f, _)| f.config.id == id)
        .map(|(_, a)| a)
        .ok_or_else(|| AnalysisError::UnknownSeries(format!("no filter `{id}`")))
}

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
    let mut rows = table3_rows(&all);
    rows.extend(hierarchy_rows(&all)?);
    rows.extend(super::metrics::rows(&all)?);
    rows.extend(per_axis_rows(&all)?);
    biases(&mut rows)?;
    disturbance(&mut rows, &all)?;
    rows.extend(super::constant_gain::rows()?);
    rows.extend(super::fig7::rows()?);
    rows.extend(super::table4::rows()?);
    Ok(Reproduction {
        lab: "p2".into(),
        rows,
        notes: [
            "unstated in the paper and chosen here: circular sun-synchronous orbit 600 km, node at 10:30, 19 June 2026; WMM 2025 as the field; wheel gains K_λ = 5e-4, K_ω = 0.02; sensors at 1 Hz, EKF prediction at 10 Hz; P₀ from a 2° attitude error; star tracker 45° off zenith, away from the sun (it sees stars around the whole default orbit, as in the paper's runs); disturbance filter R_d = 100 × the row's innovation variance, α = 0.999 per second",
            "σ measured = RMS over the last 60 s of a 200-s run (mean included), largest axis; the paper's metric = √max diag P∞ (attitude as a rotation angle, 2λ)",
            "where Table 3's q lost its exponent in the OCR the filter uses this project's q (marked 'q ours')",
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

/// Every filter's run in the default scenario.
pub(super) type Runs = [(&'static FilterRow, FilterAccuracy)];

/// Table 3: each filter's measured σ, the paper's metric √max P∞, its rate σ and NEES.
fn table3_rows(all: &Runs) -> Vec<Row> {
    let mut rows = Vec::new();
    for (f, a) in all {
        let paper = match (f.paper_att_deg, f.paper_rate_deg_s) {
            (Some(x), Some(r)) => format!("{x:e}° / {r:e} °/s"),
            (Some(x), None) => format!("{x:e}° / (unreadable)"),
            (None, Some(r)) => format!("(unreadable) / {r:e} °/s"),
            (None, None) => "(unreadable)".into(),
        };
        let q = if f.q_from_paper {
            "q from Table 3"
        } else {
            "q ours"
        };
        rows.push(Row::measurement(
            format!("{}: attitude σ measured (last 60 s; {q})", f.config.label),
            paper.clone(),
            a.att_rms_deg,
            "deg",
        ));
        rows.push(Row::measurement(
            format!("{}: attitude √max P∞ (paper's metric)", f.config.label),
            "—",
            a.att_p_deg,
            "deg",
        ));
        rows.push(Row::measurement(
            format!("{}: rate σ measured", f.config.label),
            "—",
            a.rate_rms_deg_s,
            "deg/s",
        ));
        rows.push(Row::measurement(
            format!(
                "{}: mean attitude NEES (χ²₃: 3 if consistent)",
                f.config.label
            ),
            "— (the paper tuned Q by hand)",
            a.nees_mean,
            "",
        ));
    }
    rows
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
    rows.push(
        Row::check("Mag+Sun+Gyro attitude σ", "2e-2° (Table 3)", msg, "deg", Expectation::within_factor_of(2e-2, 3.0)).known_to_differ(
            "the gyro here is read at 1 Hz like the other sensors; the paper does not give its rate, and at 10 Hz (next row) the set is within 3×",
        ),
    );
    let fast_gyro = Row::check(
        "Mag+Sun+Gyro attitude σ, gyro read at 10 Hz",
        "2e-2° (Table 3)",
        att_sigma_with("mag-sun-gyro", "gyro_rate_hz", 10.0)?,
        "deg",
        Expectation::within_factor_of(2e-2, 3.0),
    );
    let gyro_rate = Calibration::new("gyro rate", 10.0, "Hz");
    rows.extend(gyro_rate.rows(fast_gyro, |f| {
        att_sigma_with("mag-sun-gyro", "gyro_rate_hz", 10.0 * f)
    })?);
    let defaults = ParamValues::defaults(PARAMS);
    let vector_hz = defaults.get("vector_rate_hz");
    let vector_rate = Calibration::new("magnetometer and sun-sensor rate", vector_hz, "Hz");
    let mag_sun = Row::check(
        "Mag+Sun attitude σ",
        "0.12° (Table 3)",
        ms,
        "deg",
        Expectation::within_factor_of(0.12, 3.0),
    );
    rows.extend(vector_rate.rows(mag_sun, |f| {
        att_sigma_with("mag-sun", "vector_rate_hz", vector_hz * f)
    })?);
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
fn disturbance(
    rows: &mut Vec<Row>,
    all: &[(&'static FilterRow, FilterAccuracy)],
) -> Result<(), AnalysisError> {
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
