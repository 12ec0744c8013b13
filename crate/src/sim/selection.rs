//! Which series a simulation records, and the error for a series a lab does not have.

use thiserror::Error;

/// Which series a simulation records.
#[derive(Clone, Debug, PartialEq)]
pub enum Selection {
    /// Every series the lab has (CSV exports, `attlab run`).
    All,
    /// What the page shows: the lab's figures, every estimator's errors with their
    /// covariance, innovations and status, and the vertical and (u, v) of three-axis labs.
    Standard,
    /// Exactly these series (analysis). A name that does not exist is an error.
    Named(Vec<String>),
    /// What a view shows: these series where the lab has them, the variances that bound
    /// them, and every estimator's status. The page records this and re-runs the simulation
    /// when another view needs series it has not recorded, so derived quantities are
    /// computed only for what someone looks at.
    View(Vec<String>),
}

impl Selection {
    /// `Named` from string slices.
    pub fn named(names: &[&str]) -> Self {
        Self::Named(names.iter().map(|s| s.to_string()).collect())
    }
}

/// A series asked for that the lab does not have.
#[derive(Clone, Debug, Error, PartialEq, serde::Serialize, serde::Deserialize)]
#[error("no series `{name}` in lab `{lab}` (it has: {known})")]
pub struct UnknownSeries {
    /// The name asked for.
    pub name: String,
    /// The lab.
    pub lab: String,
    /// Every series the lab has, comma separated.
    pub known: String,
}
