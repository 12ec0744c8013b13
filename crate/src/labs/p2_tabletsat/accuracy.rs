//! One filter's accuracy over a 200-s run, in both of the paper's metrics: the measured σ
//! (the RMS over the last 60 s of each axis' error against the truth, mean included, largest
//! axis) and the paper's own, √max diag P∞ at the end of the run. For the attitude, the rate
//! and, in a filter that estimates one, the bias (gyro bias in deg/s, magnetometer bias in
//! nT, as Tables 3–5 give them).
// Only the CLI and the tests reproduce a paper (the `study` feature).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::TabletSat;
use super::sensors::{GYRO_BIAS, MAG_BIAS};
use super::sets::{FILTERS, FilterRow};
use crate::analysis::scenario::{Trace, run_trace};
use crate::analysis::stats;
use crate::analysis::{AnalysisError, StatsContext};
use crate::estimators::{StateSet, mekf};
use crate::model::{Quantity, SeriesKey, StateInfo, q};
use crate::page::Lab;

/// Run length (s).
pub(super) const RUN_S: f64 = 200.0;
/// The window σ is taken over: the last 60 s of a run.
const WINDOW_S: f64 = 60.0;

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
    /// Largest per-axis RMS of the bias estimate's error over the window (deg/s for a gyro
    /// bias, nT for a magnetometer bias), NaN without a bias state.
    pub bias_rms: f64,
    /// √max diag P of the bias at the end (the unit of `bias_rms`), NaN without one.
    pub bias_p: f64,
    /// Mean NEES of the attitude over the window (3 degrees of freedom).
    pub nees_mean: f64,
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

/// A bias a filter estimates: its estimate, the truth, its states, and the factor from the
/// state's unit to the reported one.
struct Bias {
    estimate: [&'static Quantity; 3],
    truth: &'static [Quantity; 3],
    states: [&'static StateInfo; 3],
    state_to_unit: f64,
    unit: &'static str,
}

/// The gyro bias (states in rad/s, reported in deg/s).
const GYRO: Bias = Bias {
    estimate: [
        &mekf::GBIAS_X_DEG_S,
        &mekf::GBIAS_Y_DEG_S,
        &mekf::GBIAS_Z_DEG_S,
    ],
    truth: &GYRO_BIAS,
    states: [&mekf::GBIAS_X, &mekf::GBIAS_Y, &mekf::GBIAS_Z],
    state_to_unit: 180.0 / std::f64::consts::PI,
    unit: "deg/s",
};

/// The magnetometer bias (nT).
const MAG: Bias = Bias {
    estimate: [&mekf::MBIAS_X_NT, &mekf::MBIAS_Y_NT, &mekf::MBIAS_Z_NT],
    truth: &MAG_BIAS,
    states: [&mekf::MBIAS_X, &mekf::MBIAS_Y, &mekf::MBIAS_Z],
    state_to_unit: 1.0,
    unit: "nT",
};

/// The additive bias a state set estimates (Fig. 7's turn is reported by its own rows).
fn bias_of(states: StateSet) -> Option<&'static Bias> {
    match states {
        StateSet::AttRateGyroBias | StateSet::AttGyroBias => Some(&GYRO),
        StateSet::AttRateMagBias => Some(&MAG),
        StateSet::AttRate | StateSet::AttRateMagTurn => None,
    }
}

/// The unit of a filter's bias accuracy ("" when it estimates no additive bias).
pub(super) fn bias_unit(states: StateSet) -> &'static str {
    bias_of(states).map_or("", |b| b.unit)
}

/// The series `accuracy` reads for `row`.
fn series_of(row: &FilterRow) -> Vec<SeriesKey> {
    let id = row.config.id;
    let mut s: Vec<SeriesKey> = ATT_ERRORS.iter().map(|q| SeriesKey::new(id, q)).collect();
    s.extend(ATT_STATES.iter().map(|st| SeriesKey::variance(id, st)));
    s.push(SeriesKey::nees_att(id));
    s.extend(RATE_ERRORS.iter().map(|q| SeriesKey::new(id, q)));
    if row.config.states != StateSet::AttGyroBias {
        s.extend(RATE_STATES.iter().map(|st| SeriesKey::variance(id, st)));
    }
    if let Some(bias) = bias_of(row.config.states) {
        s.extend(bias.estimate.iter().map(|q| SeriesKey::new(id, q)));
        s.extend(bias.truth.iter().map(SeriesKey::sensors));
        s.extend(bias.states.iter().map(|st| SeriesKey::variance(id, st)));
    }
    s
}

/// Largest per-axis RMS over the window of `estimate − truth` (truth `None`: 0).
fn rms_axes(
    trace: &Trace,
    estimate: [SeriesKey; 3],
    truth: Option<[SeriesKey; 3]>,
) -> Result<[f64; 3], AnalysisError> {
    let from = window_from(trace);
    let mut out = [0.0; 3];
    for (k, o) in out.iter_mut().enumerate() {
        let mut err = trace.after(estimate[k], from)?;
        if let Some(truth) = truth {
            for (e, t) in err.iter_mut().zip(trace.after(truth[k], from)?) {
                *e -= t;
            }
        }
        *o = stats::rms(&err).of(&estimate[k].name())?;
    }
    Ok(out)
}

/// Where the window of `trace` starts: 60 s before its end.
fn window_from(trace: &Trace) -> f64 {
    trace.t_s().last().copied().unwrap_or(0.0) - WINDOW_S
}

/// √max over `states` of the last variance, times `scale`.
fn p_max(
    trace: &Trace,
    id: &'static str,
    states: [&'static StateInfo; 3],
    scale: f64,
) -> Result<f64, AnalysisError> {
    let mut v = Vec::new();
    for st in states {
        v.push(trace.last(SeriesKey::variance(id, st))?);
    }
    Ok(stats::max(&v).of("variances")?.sqrt() * scale)
}

/// The accuracy of filter `row` in `trace`.
pub fn accuracy(trace: &Trace, row: &FilterRow) -> Result<FilterAccuracy, AnalysisError> {
    let id = row.config.id;
    let att = rms_axes(trace, ATT_ERRORS.map(|q| SeriesKey::new(id, q)), None)?;
    let rate = rms_axes(trace, RATE_ERRORS.map(|q| SeriesKey::new(id, q)), None)?;
    let deg = 180.0 / std::f64::consts::PI;
    let rate_p = match row.config.states {
        StateSet::AttGyroBias => f64::NAN,
        _ => p_max(trace, id, RATE_STATES, deg)?,
    };
    let (bias_rms, bias_p) = match bias_of(row.config.states) {
        Some(b) => {
            let truth = b.truth.each_ref().map(SeriesKey::sensors);
            let axes = rms_axes(
                trace,
                b.estimate.map(|q| SeriesKey::new(id, q)),
                Some(truth),
            )?;
            let p = p_max(trace, id, b.states, b.state_to_unit)?;
            (stats::max(&axes).of("bias σ")?, p)
        }
        None => (f64::NAN, f64::NAN),
    };
    Ok(FilterAccuracy {
        att_rms_deg: stats::max(&att).of("attitude σ")?,
        att_axes_deg: att,
        rate_rms_deg_s: stats::max(&rate).of("rate σ")?,
        rate_axes_deg_s: rate,
        att_p_deg: p_max(trace, id, ATT_STATES, deg)?,
        rate_p_deg_s: rate_p,
        bias_rms,
        bias_p,
        nees_mean: stats::mean(&trace.after(SeriesKey::nees_att(id), window_from(trace))?)
            .of("NEES")?,
    })
}

/// Every filter's run in one scenario.
pub(super) type Runs = [(&'static FilterRow, FilterAccuracy)];

/// A 200-s run of every filter with `assignments`, and each one's accuracy.
pub(super) fn run_all(
    assignments: &[&str],
    seed: u64,
) -> Result<Vec<(&'static FilterRow, FilterAccuracy)>, AnalysisError> {
    run_all_for(assignments, seed, RUN_S)
}

/// A run of `run_s` seconds of every filter with `assignments`, and each one's accuracy
/// over its last 60 s.
pub(super) fn run_all_for(
    assignments: &[&str],
    seed: u64,
    run_s: f64,
) -> Result<Vec<(&'static FilterRow, FilterAccuracy)>, AnalysisError> {
    let mut keys: Vec<SeriesKey> = Vec::new();
    for key in FILTERS.iter().flat_map(series_of) {
        if !keys.contains(&key) {
            keys.push(key);
        }
    }
    let lab: &'static dyn Lab = &TabletSat;
    let trace = run_trace(lab, assignments, seed, run_s, &keys)?;
    FILTERS
        .iter()
        .map(|f| Ok((f, accuracy(&trace, f)?)))
        .collect()
}

/// Filter `id`'s accuracy in `all`.
pub(super) fn acc_of<'a>(all: &'a Runs, id: &str) -> Result<&'a FilterAccuracy, AnalysisError> {
    all.iter()
        .find(|(f, _)| f.config.id == id)
        .map(|(_, a)| a)
        .ok_or_else(|| AnalysisError::UnknownSeries(format!("no filter `{id}`")))
}
