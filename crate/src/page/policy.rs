//! The page's policy: the tab a lab opens on, what a tab records, the speeds the page
//! offers. The simulation records whatever it is asked to; these say what the page asks.

use super::Lab;
use crate::model::{PlotTab, SeriesGroup, SeriesSpec};

/// Speeds the page offers (simulated seconds per wall-clock second): up to an orbit of
/// paper 2 (5 800 s) a second; where the steps do not fit the frame, the page says it is
/// behind.
pub const SPEED_RANGE: (f64, f64) = (0.1, 10_000.0);

/// The tab a lab opens on: its first figure, or the errors when it has none.
pub fn default_tab(lab: &dyn Lab) -> PlotTab {
    lab.page()
        .figures
        .first()
        .map_or(PlotTab::Group(SeriesGroup::Error), |f| {
            PlotTab::Figure(f.id)
        })
}

/// The series the page records while `tab` is shown: the tab's series, and the vertical and
/// (u, v) of every source where the lab has them (the sphere and the w plane draw them),
/// and the outages the plots shade. `available` is every series the lab has.
pub fn tab_series(lab: &dyn Lab, available: &[SeriesSpec], tab: PlotTab) -> Vec<String> {
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
            .chain([&super::REPLAY_GAPS])
            .filter(|o| available.iter().any(|s| o.series.is(&s.name)))
            .map(|o| o.series.name()),
    );
    names
}
