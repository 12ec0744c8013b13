//! Time plots of the recorded series over the whole run: one tab per figure of the lab and
//! per series group, coloured by source, with ±3σ bands where a series says which variance
//! bounds it.

use attlab::model::{Figure, Lab, SeriesGroup, SeriesSpec};
use attlab::record::Recorder;
use egui::{Color32, Ui};
use egui_plot::{Legend, Line, LineStyle, Plot};

/// Colour of a source: truth white, estimators from a fixed palette by position.
pub fn source_color(source_index: usize) -> Color32 {
    const PALETTE: [Color32; 8] = [
        Color32::from_rgb(235, 235, 235),
        Color32::from_rgb(255, 140, 60),
        Color32::from_rgb(80, 200, 255),
        Color32::from_rgb(120, 220, 110),
        Color32::from_rgb(230, 110, 220),
        Color32::from_rgb(250, 220, 80),
        Color32::from_rgb(255, 90, 90),
        Color32::from_rgb(160, 140, 255),
    ];
    PALETTE[source_index % PALETTE.len()]
}

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
}

impl PlotState {
    /// A lab with figures opens on its first figure, others on the error plot.
    pub fn for_lab(lab: &dyn Lab) -> Self {
        Self {
            tab: attlab::sim::default_tab(lab),
            log_covariance: true,
            show_bands: true,
        }
    }
}

/// Points per line on screen.
const MAX_POINTS: usize = 1500;

/// The group tabs a lab offers: every group that has series (recorded or not).
pub fn groups(available: &[SeriesSpec]) -> Vec<SeriesGroup> {
    let mut groups: Vec<SeriesGroup> = Vec::new();
    for s in available {
        if s.group != SeriesGroup::Time && !groups.contains(&s.group) {
            groups.push(s.group);
        }
    }
    groups
}

/// Draws the selected plot (over the whole run). Returns nothing: tab changes are commands.
pub fn show(ui: &mut Ui, rec: &Recorder, figures: &[Figure], state: &PlotState) {
    let tab = match state.tab {
        Tab::Figure(i) if i >= figures.len() => Tab::Group(SeriesGroup::Error),
        t => t,
    };
    // (series index, colour): a figure colours by position so that u and v of one source
    // differ; a group by source.
    let lines: Vec<(usize, Color32)> = match tab {
        Tab::Figure(f) => figures[f]
            .series
            .iter()
            .enumerate()
            .filter_map(|(k, n)| rec.index_of(n).map(|i| (i, source_color(k))))
            .collect(),
        Tab::Group(g) => rec
            .specs()
            .iter()
            .enumerate()
            .filter(|(_, s)| s.group == g)
            .map(|(i, s)| (i, source_color(s.source)))
            .collect(),
    };
    let log = match tab {
        Tab::Figure(f) => figures[f].log,
        Tab::Group(g) => state.log_covariance && g == SeriesGroup::Covariance,
    };
    Plot::new(("series_plot", format!("{tab:?}")))
        .legend(Legend::default().text_style(egui::TextStyle::Small))
        .x_axis_label("t [s]")
        .show(ui, |plot| {
            for (i, color) in lines {
                let spec = &rec.specs()[i];
                let mut pts = rec.plot_points(i, MAX_POINTS);
                let mut label = spec.header();
                if log {
                    for p in &mut pts {
                        p[1] = if p[1] > 0.0 { p[1].log10() } else { f64::NAN };
                    }
                    label = format!("log10 {label}");
                }
                for piece in Recorder::split_at_gaps(&pts) {
                    plot.line(Line::new(label.clone(), piece).color(color).width(1.4));
                }
                // ±3σ from the variance the series names (never from its name).
                let band = spec.band.as_ref().filter(|_| state.show_bands && !log);
                if let Some(var) =
                    band.and_then(|(name, scale)| rec.index_of(name).map(|v| (v, *scale)))
                {
                    let sigma3 = |sign: f64| -> Vec<[f64; 2]> {
                        rec.plot_points(var.0, MAX_POINTS)
                            .into_iter()
                            .map(|p| [p[0], sign * 3.0 * p[1].max(0.0).sqrt() * var.1])
                            .collect()
                    };
                    let name = format!("{} ±3σ", spec.name);
                    for sign in [1.0, -1.0] {
                        plot.line(
                            Line::new(name.clone(), sigma3(sign))
                                .color(color.gamma_multiply(0.6))
                                .style(LineStyle::dashed_loose()),
                        );
                    }
                }
            }
        });
}
