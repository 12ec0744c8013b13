//! Time plots of the recorded series, one tab per series group, coloured by source.

use attlab::labs::Figure;
use attlab::record::{Recorder, SeriesGroup};
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

/// A plot tab: one of the lab's figures, or every series of a group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Tab {
    /// The lab's figure with this index.
    Figure(usize),
    /// All series of a group.
    Group(SeriesGroup),
}

/// Plot-panel settings kept by the app.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotState {
    /// Selected tab.
    pub tab: Tab,
    /// Draw covariance elements as log10.
    pub log_covariance: bool,
    /// Draw ±3σ envelopes on the error plot.
    pub show_envelope: bool,
}

impl Default for PlotState {
    fn default() -> Self {
        Self {
            tab: Tab::Group(SeriesGroup::Error),
            log_covariance: true,
            show_envelope: true,
        }
    }
}

const MAX_POINTS: usize = 1500;

fn source_of(name: &str) -> &str {
    name.split('.').next().unwrap_or(name)
}

/// Tabs (the lab's figures, then the series groups) and the selected plot. `sources` lists
/// "truth" then the estimator ids, which fixes their colours in group plots; a figure colours
/// its series by position so that u and v of one source differ.
pub fn show(
    ui: &mut Ui,
    rec: &Recorder,
    sources: &[&str],
    figures: &[Figure],
    state: &mut PlotState,
) {
    let mut groups: Vec<SeriesGroup> = Vec::new();
    for s in rec.specs() {
        if s.group != SeriesGroup::Time && !groups.contains(&s.group) && has_data(rec, &s.name) {
            groups.push(s.group);
        }
    }
    if matches!(state.tab, Tab::Figure(i) if i >= figures.len()) {
        state.tab = Tab::Group(SeriesGroup::Error);
    }
    ui.horizontal_wrapped(|ui| {
        for (i, f) in figures.iter().enumerate() {
            ui.selectable_value(&mut state.tab, Tab::Figure(i), f.title);
        }
        if !figures.is_empty() {
            ui.separator();
        }
        for g in &groups {
            ui.selectable_value(&mut state.tab, Tab::Group(*g), g.title());
        }
        ui.separator();
        match state.tab {
            Tab::Group(SeriesGroup::Covariance) => {
                ui.checkbox(&mut state.log_covariance, "log10");
            }
            Tab::Group(SeriesGroup::Error) => {
                ui.checkbox(&mut state.show_envelope, "±3σ envelope");
            }
            _ => {}
        }
    });
    let Some(t) = rec.index_of("t_s") else { return };
    let color_of = |name: &str| {
        source_color(
            sources
                .iter()
                .position(|s| *s == source_of(name))
                .unwrap_or(0),
        )
    };
    let tab = state.tab;
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
            .map(|(i, s)| (i, color_of(&s.name)))
            .collect(),
    };
    let log_cov = match tab {
        Tab::Figure(f) => figures[f].log,
        Tab::Group(g) => state.log_covariance && g == SeriesGroup::Covariance,
    };
    let envelope = state.show_envelope && tab == Tab::Group(SeriesGroup::Error);
    Plot::new(("series_plot", format!("{tab:?}")))
        .legend(Legend::default().text_style(egui::TextStyle::Small))
        .x_axis_label("t [s]")
        .show(ui, |plot| {
            for (i, color) in lines {
                let spec = &rec.specs()[i];
                if !has_data(rec, &spec.name) {
                    continue;
                }
                let mut pts = rec.decimated(t, i, MAX_POINTS);
                let mut label = spec.header();
                if log_cov {
                    pts.retain(|p| p[1] > 0.0);
                    pts.iter_mut().for_each(|p| p[1] = p[1].log10());
                    label = format!("log10 {label}");
                }
                for piece in Recorder::split_at_gaps(&pts) {
                    plot.line(Line::new(label.clone(), piece).color(color).width(1.4));
                }
            }
            if envelope {
                for (i, spec) in rec
                    .specs()
                    .iter()
                    .enumerate()
                    .filter(|(_, s)| s.name.ends_with("P_axis_rad2"))
                {
                    let pts: Vec<[f64; 2]> = rec
                        .decimated(t, i, MAX_POINTS)
                        .into_iter()
                        .map(|p| [p[0], 3.0 * p[1].max(0.0).sqrt().to_degrees()])
                        .collect();
                    let name = format!("{} 3σ per axis [deg]", source_of(&spec.name));
                    plot.line(
                        Line::new(name, pts)
                            .color(color_of(&spec.name).gamma_multiply(0.6))
                            .style(LineStyle::dashed_loose()),
                    );
                }
            }
        });
}

fn has_data(rec: &Recorder, name: &str) -> bool {
    rec.index_of(name)
        .and_then(|i| rec.column(i))
        .is_some_and(|c| c.iter().rev().take(64).any(|v| v.is_finite()))
}
