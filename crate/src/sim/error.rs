//! Why a run could not be built, rebuilt or written out: typed here with its facts, worded
//! in the reader's language by the catalogue (`i18n::errors`).

use super::journal::{Refused, ReplayError};
use super::selection::UnknownSeries;
use std::convert::Infallible;

/// Why a run, a re-run, a replay or an export failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error, serde::Serialize, serde::Deserialize)]
pub enum SimError {
    /// A series asked for that the lab does not record.
    #[error(transparent)]
    Series(#[from] UnknownSeries),
    /// A log without two samples at increasing times: no step can be taken from it.
    #[error("the log needs at least two samples with increasing times")]
    FewSamples,
    /// A change the run took that its re-run refused.
    #[error(transparent)]
    Refused(#[from] Refused),
    /// The CSV writer failed (the system's own words: a full disk, a closed stream).
    #[error("cannot write the CSV: {detail}")]
    Csv {
        /// What the writer said.
        detail: String,
    },
}

impl SimError {
    /// One of each kind (the match fails to compile when a kind is added and not listed):
    /// the catalogue's test words every one in both languages.
    pub fn examples() -> Vec<SimError> {
        let all = vec![
            SimError::Series(UnknownSeries {
                name: "kf.nope".into(),
                lab: "p4".into(),
                known: "t_s, kf.angle_deg".into(),
            }),
            SimError::FewSamples,
            SimError::Refused(Refused {
                step: 120,
                key: "gyro_noise_deg_s".into(),
                value: 9.0,
                reason: crate::model::ParamError::NotFinite {
                    key: "gyro_noise_deg_s".into(),
                },
            }),
            SimError::Csv {
                detail: "No space left on device".into(),
            },
        ];
        for e in &all {
            match e {
                SimError::Series(_)
                | SimError::FewSamples
                | SimError::Refused(_)
                | SimError::Csv { .. } => {}
            }
        }
        all
    }
}

impl From<csv::Error> for SimError {
    fn from(e: csv::Error) -> Self {
        SimError::Csv {
            detail: e.to_string(),
        }
    }
}

impl From<std::io::Error> for SimError {
    fn from(e: std::io::Error) -> Self {
        SimError::Csv {
            detail: e.to_string(),
        }
    }
}

impl<W> From<csv::IntoInnerError<W>> for SimError {
    fn from(e: csv::IntoInnerError<W>) -> Self {
        SimError::Csv {
            detail: e.error().to_string(),
        }
    }
}

impl<E: Into<SimError>> From<ReplayError<E>> for SimError {
    fn from(e: ReplayError<E>) -> Self {
        match e {
            ReplayError::Refused(r) => SimError::Refused(r),
            ReplayError::Step(e) => e.into(),
        }
    }
}

impl From<Infallible> for SimError {
    fn from(e: Infallible) -> Self {
        match e {}
    }
}
