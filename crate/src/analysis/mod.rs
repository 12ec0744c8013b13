//! Analysis on top of the loop: NaN-aware statistics, scenarios that keep full-rate traces,
//! parameter sweeps, and the registry fuzzer.

pub mod fuzz;
pub mod readme;
pub mod scenario;
pub mod stats;
pub mod sweep;

use crate::model::{ParamError, ReproError};
use thiserror::Error;

/// What can go wrong computing a reproduction or a sweep: always a programming error (a
/// name that does not exist, a statistic of nothing or of NaN), reported, never hidden.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum AnalysisError {
    /// A series that the run does not have.
    #[error("unknown series: {0}")]
    UnknownSeries(String),
    /// A bad parameter assignment.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// A statistic that could not be taken.
    #[error("{context}: {source}")]
    Stats {
        /// Of what.
        context: String,
        /// Why not.
        source: stats::StatsError,
    },
    /// A run of a scenario or sweep that could not be made or scored.
    #[error("{0}")]
    Scenario(String),
}

impl From<AnalysisError> for ReproError {
    fn from(e: AnalysisError) -> Self {
        ReproError(e.to_string())
    }
}

/// Attaches what a statistic was taken of to its error.
pub trait StatsContext<T> {
    /// Names the statistic's input in the error.
    fn of(self, context: &str) -> Result<T, AnalysisError>;
}

impl<T> StatsContext<T> for Result<T, stats::StatsError> {
    fn of(self, context: &str) -> Result<T, AnalysisError> {
        self.map_err(|source| AnalysisError::Stats {
            context: context.to_string(),
            source,
        })
    }
}
