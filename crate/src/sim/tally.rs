//! A running tally of each estimator's attitude (or angle) error over the run — the sum of
//! its squares and the count of samples — so the error over any stretch of the run is the
//! difference of two tallies: a branch compares itself with the original over the same
//! stretch without either run keeping its samples ([`super::branch::Difference`]).

use super::Simulation;

/// Per estimator: Σ error² (deg²), the samples counted, and those with no finite error.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Tally {
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
    pub(super) fn new(n: usize) -> Self {
        Self {
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
        self.sum_sq_deg2.capacity() * 8 + self.counted.capacity() * 8 + self.missing.capacity() * 8
    }
}

impl Simulation {
    /// Adds every estimator's error now to the tally.
    pub(super) fn count_errors(&mut self) {
        let Some(mut tally) = self.tally.take() else {
            return;
        };
        let truth = self.run.truth.state();
        for i in 0..self.estimates.len() {
            let e = self.error_deg(i, &truth).unwrap_or(f64::NAN);
            tally.push(i, e);
        }
        self.tally = Some(tally);
    }
}
