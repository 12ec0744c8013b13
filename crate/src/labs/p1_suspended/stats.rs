//! Paper 1's run statistics: each filter's errors over one run, their median over seeds,
//! and the paper's angle-error panel — what the reproduction, the readings table and the
//! rocking rows all measure with.
// Only the CLI and the tests reproduce a paper (the `study` feature): without it, what only
// `reproduce` uses is left out (the page's wasm).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::{SuspendedMockup, rates};
use crate::analysis::AnalysisError;
use crate::analysis::StatsContext;
use crate::analysis::scenario::params_with;
use crate::analysis::scenario::run_trace;
use crate::analysis::stats;
use crate::estimators::one_axis_kf;
use crate::model::{SeriesKey, q};
use crate::page::Lab;

/// Seeds over which the window rows take their median.
const SEEDS: [u64; 5] = [1, 2, 3, 4, 5];

/// Error statistics of one filter over one run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FilterStats {
    /// max |φ̂ − φ_int| (deg): the paper's angle-error panel.
    pub max_vs_int_deg: f64,
    /// max |φ̂ − φ| (deg), against the truth.
    pub max_vs_truth_deg: f64,
    /// RMS of φ̂ − φ (deg).
    pub rms_vs_truth_deg: f64,
    /// RMS of φ̇̂ − φ̇ (deg/s).
    pub rate_rms_deg_s: f64,
    /// Fraction of steps with |φ̇̂ − φ̇| inside the averaged sensor's 1σ band (Fig. 5.8).
    pub rate_inside_band: f64,
    /// The filter reported itself diverged during the run (1) or not (0); medians over seeds
    /// give the majority.
    pub diverged: f64,
}

/// (permanent-rotation KF, torsional KF) statistics of one run of p1 with `assignments`,
/// over t > `after_s`.
pub fn run_stats(
    assignments: &[&str],
    seed: u64,
    duration_s: f64,
    after_s: f64,
) -> Result<[FilterStats; 2], AnalysisError> {
    let lab: &'static dyn Lab = &SuspendedMockup;
    let p = params_with(lab, assignments)?;
    let band = p.get("gyro_noise_deg_s") / (rates(&p).1 as f64).sqrt();
    let ids = ["kf-rotation", "kf-torsion"];
    let keys: Vec<SeriesKey> = ids
        .iter()
        .flat_map(|id| {
            [
                SeriesKey::new(id, &one_axis_kf::ANGLE_MINUS_INT_DEG),
                SeriesKey::new(id, &q::ANGLE_ERR_DEG),
                SeriesKey::new(id, &q::RATE_ERR_DEG_S),
                SeriesKey::status(id),
            ]
        })
        .collect();
    let trace = run_trace(lab, assignments, seed, duration_s, &keys)?;
    let mut out = [FilterStats::default(); 2];
    for (o, id) in out.iter_mut().zip(ids) {
        let get = |quantity| trace.after(SeriesKey::new(id, quantity), after_s);
        let (vs_int, vs_truth, rate) = (
            get(&one_axis_kf::ANGLE_MINUS_INT_DEG)?,
            get(&q::ANGLE_ERR_DEG)?,
            get(&q::RATE_ERR_DEG_S)?,
        );
        *o = FilterStats {
            max_vs_int_deg: stats::max_abs(&vs_int).of(&format!("{id} φ̂ − φ_int"))?,
            max_vs_truth_deg: stats::max_abs(&vs_truth).of(&format!("{id} φ̂ − φ"))?,
            rms_vs_truth_deg: stats::rms(&vs_truth).of(&format!("{id} φ̂ − φ"))?,
            rate_rms_deg_s: stats::rms(&rate).of(&format!("{id} rate error"))?,
            rate_inside_band: stats::fraction(&rate, |r| r.abs() <= band)
                .of(&format!("{id} rate error"))?,
            diverged: f64::from(u8::from(
                stats::max(trace.series(SeriesKey::status(id))?).of("status")? > 0.0,
            )),
        };
    }
    Ok(out)
}

/// The median over [`SEEDS`] of each statistic.
pub(super) fn median_stats(
    assignments: &[&str],
    duration_s: f64,
) -> Result<[FilterStats; 2], AnalysisError> {
    let runs: Vec<[FilterStats; 2]> = SEEDS
        .iter()
        .map(|s| run_stats(assignments, *s, duration_s, 0.0))
        .collect::<Result<_, _>>()?;
    let mut out = [FilterStats::default(); 2];
    for (k, o) in out.iter_mut().enumerate() {
        let med = |f: fn(&FilterStats) -> f64| {
            stats::median(&runs.iter().map(|r| f(&r[k])).collect::<Vec<_>>())
                .of("median over seeds")
        };
        *o = FilterStats {
            max_vs_int_deg: med(|s| s.max_vs_int_deg)?,
            max_vs_truth_deg: med(|s| s.max_vs_truth_deg)?,
            rms_vs_truth_deg: med(|s| s.rms_vs_truth_deg)?,
            rate_rms_deg_s: med(|s| s.rate_rms_deg_s)?,
            rate_inside_band: med(|s| s.rate_inside_band)?,
            diverged: med(|s| s.diverged)?,
        };
    }
    Ok(out)
}

/// The statistics of window `n` in `by_n`.
pub(super) fn pick(
    by_n: &[(usize, [FilterStats; 2])],
    n: usize,
) -> Result<[FilterStats; 2], AnalysisError> {
    by_n.iter()
        .find(|x| x.0 == n)
        .map(|x| x.1)
        .ok_or_else(|| AnalysisError::UnknownSeries(format!("window N = {n} was not run")))
}

/// The paper's angle-error panel: the larger of the two filters' max |φ̂ − φ_int|.
pub(super) fn panel(s: &[FilterStats; 2]) -> f64 {
    s[0].max_vs_int_deg.max(s[1].max_vs_int_deg)
}
