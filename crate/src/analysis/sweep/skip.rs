//! Why a sweep's value or a worker's point could not be run: typed with its facts (they
//! cross the sweep workers' boundary as data), worded in the reader's language by the
//! catalogue (`i18n::errors`).

use crate::model::ParamError;
use crate::sim::{SimError, UnknownSeries};
use serde::{Deserialize, Serialize};

/// Why a point of a sweep could not be run.
#[derive(Clone, Debug, PartialEq, thiserror::Error, Serialize, Deserialize)]
pub enum SweepError {
    /// A swept or fixed value the lab refused.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The run could not be built (a series, a log).
    #[error(transparent)]
    Sim(#[from] SimError),
    /// A worker was handed another lab's job.
    #[error("the job is for lab {job}, not {lab}")]
    WrongLab {
        /// The job's lab.
        job: String,
        /// The lab it was run on.
        lab: String,
    },
    /// A worker was handed a sweep the lab does not have.
    #[error("lab {lab} has no sweep {sweep}")]
    NoSweep {
        /// The lab.
        lab: String,
        /// The sweep's place in the lab's list.
        sweep: usize,
    },
    /// A worker was handed a point past the sweep's last.
    #[error("sweep {sweep} has no point {point}")]
    NoPoint {
        /// The sweep's place in the lab's list.
        sweep: usize,
        /// The point asked for.
        point: usize,
    },
}

impl From<UnknownSeries> for SweepError {
    fn from(e: UnknownSeries) -> Self {
        SweepError::Sim(SimError::Series(e))
    }
}

impl SweepError {
    /// One of each kind (the match fails to compile when a kind is added and not listed):
    /// the catalogue's test words every one in both languages.
    pub fn examples() -> Vec<SweepError> {
        let all = vec![
            SweepError::Param(ParamError::NotFinite {
                key: "q_scale".into(),
            }),
            SweepError::Sim(SimError::FewSamples),
            SweepError::WrongLab {
                job: "p2".into(),
                lab: "p4".into(),
            },
            SweepError::NoSweep {
                lab: "p4".into(),
                sweep: 7,
            },
            SweepError::NoPoint {
                sweep: 1,
                point: 99,
            },
        ];
        for e in &all {
            match e {
                SweepError::Param(_)
                | SweepError::Sim(_)
                | SweepError::WrongLab { .. }
                | SweepError::NoSweep { .. }
                | SweepError::NoPoint { .. } => {}
            }
        }
        all
    }
}

/// A value of a sweep that could not be run, and why: the whole point is skipped.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Skipped {
    /// The swept parameter's key and value.
    pub at: (String, f64),
    /// The grid's parameter and value, for a grid sweep.
    pub grid: Option<(String, f64)>,
    /// Why.
    pub why: SweepError,
}

impl std::fmt::Display for Skipped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} = {}", self.at.0, self.at.1)?;
        if let Some((key, value)) = &self.grid {
            write!(f, ", {key} = {value}")?;
        }
        write!(f, ": {}", self.why)
    }
}
