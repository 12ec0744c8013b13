//! What the plot panel keeps between frames (its tab and switches) and the words a plot
//! draws in the reader's language — what both the plot and its legend read.

use attlab::i18n::LegendParts;
use attlab::model::{SeriesGroup, SeriesSpec};
use attlab::page::Lab;

pub use attlab::model::PlotTab as Tab;

/// Plot-panel settings kept by the app.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotState {
    /// Selected tab.
    pub tab: Tab,
    /// Draw covariance elements as log10.
    pub log_covariance: bool,
    /// Draw ±3σ bands around errors that have one.
    pub show_bands: bool,
    /// Shade the lab's sensor outages.
    pub show_outages: bool,
}

impl PlotState {
    /// A lab with figures opens on its first figure, others on the error plot.
    pub fn for_lab(lab: &dyn Lab) -> Self {
        Self {
            tab: attlab::page::default_tab(lab),
            log_covariance: true,
            show_bands: true,
            show_outages: true,
        }
    }
}

/// The words a plot draws, in the reader's language (the page fills them from the
/// catalogue; the renderer knows no language).
pub struct PlotWords<'a> {
    /// A series' legend: its owner, and what it measures with the unit.
    pub legend: Box<dyn Fn(&SeriesSpec) -> LegendParts + 'a>,
    /// The time axis' title.
    pub time_axis: String,
    /// The y axis' title when the series' units differ.
    pub mixed_units: String,
    /// The noun before the unit on the y axis of a plot of one group's series ("error").
    pub group_axis: Box<dyn Fn(SeriesGroup) -> Option<String> + 'a>,
    /// A unit as the code writes it (`deg/s`) in the reader's words (`°/с`).
    pub unit: Box<dyn Fn(&str) -> String + 'a>,
    /// The legend's entry for the ±3σ bands.
    pub bands: String,
    /// After a legend entry whose series has no value anywhere in the run so far ("no values
    /// recorded"): the truth of a live or replayed run, the errors it cannot have.
    pub no_data: String,
    /// The same on a log plot, where only values above 0 can be drawn.
    pub no_positive: String,
    /// The lab's outages' labels, by position.
    pub outages: Vec<String>,
    /// The reset button's hint.
    pub reset: String,
    /// The reader's language, for the numbers on the axes.
    pub lang: attlab::i18n::Lang,
    /// What series of one unit measure when their groups differ ("angle" for `deg`,
    /// "value" for a unit without a word).
    pub unit_noun: Box<dyn Fn(&str) -> String + 'a>,
    /// What a figure fitted to its steady part says of the seconds it leaves off the scale.
    pub steady_note: Box<dyn Fn(f64) -> String + 'a>,
}
