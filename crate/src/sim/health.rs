//! Each estimator's health as the loop sees it: the status the estimator reports, turned
//! into "diverged" when its state or covariance is no longer finite, and a numeric code per
//! estimator for the recorded `status` series.

use crate::math::all_finite;
use crate::model::{Estimate, Estimator, EstimatorStatus, Trouble};

/// The health of every estimator of a run, by position.
#[derive(Clone, Debug)]
pub(super) struct Health {
    statuses: Vec<EstimatorStatus>,
    codes: Vec<f64>,
}

impl Health {
    /// `n` estimators, all healthy.
    pub(super) fn new(n: usize) -> Self {
        Self {
            statuses: vec![EstimatorStatus::Ok; n],
            codes: vec![0.0; n],
        }
    }

    /// Takes estimator `i`'s reported status and its latest estimate `est` into account.
    pub(super) fn update(&mut self, i: usize, e: &dyn Estimator, est: &Estimate) {
        let status = e.status();
        let healthy = status.is_ok() && finite(est, e);
        let code = if healthy { 0.0 } else { status.code().max(1.0) };
        if code != self.codes[i] || (!status.is_ok() && self.statuses[i] != *status) {
            self.statuses[i] = match (healthy, status) {
                (true, _) => EstimatorStatus::Ok,
                (false, EstimatorStatus::Ok) => EstimatorStatus::Diverged(Trouble::NotFinite),
                (false, s) => *s,
            };
            self.codes[i] = self.statuses[i].code();
        }
    }

    /// The heap a clone allocates (bytes).
    pub(super) fn heap_bytes(&self) -> usize {
        self.statuses.capacity() * std::mem::size_of::<EstimatorStatus>()
            + self.codes.capacity() * 8
    }

    /// Every estimator's status.
    pub(super) fn statuses(&self) -> &[EstimatorStatus] {
        &self.statuses
    }

    /// Every estimator's status code (0 = healthy), as recorded.
    pub(super) fn codes(&self) -> &[f64] {
        &self.codes
    }
}

/// State, rate and covariance are all finite.
fn finite(est: &Estimate, e: &dyn Estimator) -> bool {
    est.is_finite() && e.covariance().is_none_or(|c| all_finite(c.matrix))
}
