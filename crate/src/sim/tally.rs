//! A running tally of each estimator's attitude (or angle) error — the sum of its squares
//! and the count of samples — kept by a branch and by the original re-run beside it
//! ([`super::branch::Branch`]), so the two compare over the same stretch without keeping
//! their samples. The main run keeps none (its step costs nothing more).

use super::Simulation;
use crate::model::{Estimator, Outputs};

/// Per estimator: Σ error² (deg²), the samples counted, and those with no finite error.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Tally {
    /// What each estimator estimates (fixed for an estimator, read once).
    outputs: Vec<Outputs>,
    sum_sq_deg2: Vec<f64>,
    counted: Vec<u64>,
    missing: Vec<u64>,
}

/// The tally of one estimator between two moments.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stretch {
    /// RMS attitude (or angle) error over the samples with one (deg); NaN with none.
    pub rms_deg: f64,
    /// Samples with an error.
    pub counted: u64,
    /// Samples without a finite error (no truth, no estimate yet, diverged).
    pub missing: u64,
}

impl Tally {
    pub(super) fn new(estimators: &[Box<dyn Estimator>]) -> Self {
        let n = estimators.len();
        Self {
            outputs: estimators.iter().map(|e| e.outputs()).collect(),
            sum_sq_deg2: vec![0.0; n],
            counted: vec![0; n],
            missing: vec![0; n],
        }
    }

    /// Adds estimator `i`'s error now.
    pub(super) fn push(&mut self, i: usize, error_deg: f64) {
        if error_deg.is_finite() {
            self.sum_sq_deg2[i] += error_deg * error_deg;
            self.counted[i] += 1;
        } else {
            self.missing[i] += 1;
        }
    }

    /// Estimator `i` over the samples added since `earlier` was this tally.
    pub(super) fn since(&self, earlier: &Tally, i: usize) -> Stretch {
        let counted = self.counted[i] - earlier.counted[i];
        let sum = self.sum_sq_deg2[i] - earlier.sum_sq_deg2[i];
        Stretch {
            rms_deg: if counted == 0 {
                f64::NAN
            } else {
                (sum.max(0.0) / counted as f64).sqrt()
            },
            counted,
            missing: self.missing[i] - earlier.missing[i],
        }
    }

    pub(super) fn heap_bytes(&self) -> usize {
        self.outputs.capacity() * std::mem::size_of::<Outputs>()
            + self.sum_sq_deg2.capacity() * 8
            + self.counted.capacity() * 8
            + self.missing.capacity() * 8
    }
}

impl Simulation {
    /// Adds every estimator's error now to the tally.
    pub(super) fn count_errors(&mut self, truth: &crate::model::TruthState) {
        let Some(mut tally) = self.tally.take() else {
            return;
        };
        let has_truth = self.has_truth();
        for (i, estimate) in self.estimates.iter().enumerate() {
            let e = if has_truth {
                super::glance::error_deg(tally.outputs[i], estimate, truth)
            } else {
                f64::NAN
            };
            tally.push(i, e);
        }
        self.tally = Some(tally);
    }
}
