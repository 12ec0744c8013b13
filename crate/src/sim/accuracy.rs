//! A lab's live accuracy table: each estimator's attitude and rate error against the truth
//! over the last window, its own √max diag P, and the paper's value beside them.

use crate::math::small_angle_error_body;
use crate::model::{Estimate, Estimator, StateKind, TruthState};
use crate::page::AccuracyTable;
use std::collections::VecDeque;

/// One estimator's row.
#[derive(Clone, Debug, PartialEq)]
pub struct AccuracyRow {
    /// Estimator id.
    pub id: &'static str,
    /// Estimator label.
    pub label: &'static str,
    /// Largest per-axis RMS attitude error over the window (deg, mean included); NaN before
    /// the first sample or for an estimator without an attitude.
    pub att_sigma_deg: f64,
    /// Largest per-axis RMS rate error over the window (deg/s); NaN without a rate.
    pub rate_sigma_deg_s: f64,
    /// √max diag P of the attitude now (deg), NaN if the estimator publishes none.
    pub att_p_deg: f64,
    /// √max diag P of the rate now (deg/s), NaN if none.
    pub rate_p_deg_s: f64,
    /// The paper's (attitude deg, rate deg/s), where given.
    pub paper: [Option<f64>; 2],
    /// The number of the paper's table the row's values are from, if any.
    pub paper_table: Option<u8>,
}

/// Per-axis errors of one sample: attitude (deg) and rate (deg/s), NaN when not estimated.
type Sample = (f64, [f64; 3], [f64; 3]);

/// Keeps the last window of errors of every estimator.
#[derive(Clone, Debug)]
pub struct AccuracyTracker {
    table: AccuracyTable,
    samples: Vec<VecDeque<Sample>>,
}

impl AccuracyTracker {
    /// A tracker for `n` estimators.
    pub fn new(table: AccuracyTable, n: usize) -> Self {
        Self {
            table,
            samples: vec![VecDeque::new(); n],
        }
    }

    /// The table's declaration.
    pub fn table(&self) -> &AccuracyTable {
        &self.table
    }

    /// Adds this step's errors.
    pub fn push(&mut self, truth: &TruthState, estimates: &[Estimate]) {
        let from = truth.t_s - self.table.window_s;
        for (queue, est) in self.samples.iter_mut().zip(estimates) {
            let att = est.attitude.quaternion().map_or([f64::NAN; 3], |q| {
                let e = small_angle_error_body(&truth.q_ref_from_body, &q);
                [e.x.to_degrees(), e.y.to_degrees(), e.z.to_degrees()]
            });
            let rate = est.rate_body_rad_s.map_or([f64::NAN; 3], |w| {
                let e = w - truth.rate_body_rad_s;
                [e.x.to_degrees(), e.y.to_degrees(), e.z.to_degrees()]
            });
            queue.push_back((truth.t_s, att, rate));
            while queue.front().is_some_and(|s| s.0 < from) {
                queue.pop_front();
            }
        }
    }

    /// The rows, in estimator order.
    pub fn rows(&self, estimators: &[Box<dyn Estimator>]) -> Vec<AccuracyRow> {
        self.samples
            .iter()
            .zip(estimators)
            .map(|(queue, e)| {
                let (att_p, rate_p) = covariance_sigmas(e.as_ref());
                AccuracyRow {
                    id: e.id(),
                    label: e.label(),
                    att_sigma_deg: worst_axis_rms(queue.iter().map(|s| s.1)),
                    rate_sigma_deg_s: worst_axis_rms(queue.iter().map(|s| s.2)),
                    att_p_deg: att_p,
                    rate_p_deg_s: rate_p,
                    paper: (self.table.paper)(e.id()),
                    paper_table: (self.table.paper_table)(e.id()),
                }
            })
            .collect()
    }
}

/// The largest per-axis RMS; NaN if there is no sample or any value is NaN.
fn worst_axis_rms(samples: impl Iterator<Item = [f64; 3]>) -> f64 {
    let mut sum = [0.0; 3];
    let mut n = 0usize;
    for s in samples {
        for (acc, v) in sum.iter_mut().zip(s) {
            *acc += v * v;
        }
        n += 1;
    }
    if n == 0 {
        return f64::NAN;
    }
    let rms = sum.map(|s| (s / n as f64).sqrt());
    if rms.iter().any(|v| v.is_nan()) {
        return f64::NAN;
    }
    rms.into_iter().fold(0.0, f64::max)
}

/// √max diag P of the attitude axes (deg) and of the rate axes (deg/s); NaN where absent.
fn covariance_sigmas(e: &dyn Estimator) -> (f64, f64) {
    let Some(c) = e.covariance() else {
        return (f64::NAN, f64::NAN);
    };
    let n = c.dim();
    let (mut att, mut rate): (Option<f64>, Option<f64>) = (None, None);
    for (i, s) in c.states.iter().enumerate() {
        let v = c.matrix.get(i * n + i).copied().unwrap_or(f64::NAN);
        let slot = match s.kind {
            StateKind::AttitudeAxis(_) => &mut att,
            StateKind::RateAxis(_) => &mut rate,
            _ => continue,
        };
        // A variance that is not a number makes the whole entry NaN (shown as such).
        *slot = Some(match *slot {
            None => v,
            Some(x) if x.is_nan() || v.is_nan() => f64::NAN,
            Some(x) => x.max(v),
        });
    }
    let sigma = |v: Option<f64>| v.map_or(f64::NAN, |v| v.sqrt().to_degrees());
    (sigma(att), sigma(rate))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rms_is_per_axis_and_fails_on_nan() {
        let s = [[1.0, 0.0, 3.0], [-1.0, 0.0, -3.0]];
        assert!((worst_axis_rms(s.into_iter()) - 3.0).abs() < 1e-12);
        assert!(worst_axis_rms([[1.0, f64::NAN, 0.0]].into_iter()).is_nan());
        assert!(worst_axis_rms(std::iter::empty()).is_nan());
    }
}
