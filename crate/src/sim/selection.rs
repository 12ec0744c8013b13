//! Which series a simulation records, and the error for a series a lab does not have.

use crate::model::{Lab, PlotTab, SeriesGroup, SeriesSpec};
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

    /// What the page records while `tab` is shown: the tab's series, and the vertical and
    /// (u, v) of every source where the lab has them (the sphere and the w plane draw them),
    /// and the outages the plots shade. `available` is every series the lab has.
    pub fn for_tab(lab: &dyn Lab, available: &[SeriesSpec], tab: PlotTab) -> Self {
        let figures = lab.page().figures;
        let mut names: Vec<String> = match tab {
            PlotTab::Figure(id) => figures
                .iter()
                .find(|f| f.id == id)
                .map(|f| f.series.iter().map(|s| s.to_string()).collect())
                .unwrap_or_default(),
            PlotTab::Group(g) => available
                .iter()
                .filter(|s| s.group == g)
                .map(|s| s.name.clone())
                .collect(),
        };
        names.extend(
            available
                .iter()
                .filter(|s| s.group == SeriesGroup::Sphere && !s.name.ends_with(".z_deg"))
                .map(|s| s.name.clone()),
        );
        // Outages are shaded on every tab (a replay's gaps too).
        names.extend(
            lab.page()
                .outages
                .iter()
                .chain([&crate::model::REPLAY_GAPS])
                .filter(|o| available.iter().any(|s| o.series.is(&s.name)))
                .map(|o| o.series.name()),
        );
        Self::View(names)
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
