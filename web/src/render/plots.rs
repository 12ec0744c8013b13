//! Time plots of the recorded series over the whole run: one tab per figure of the lab and
//! per series group, coloured by source, with ±3σ bands where a series says which variance
//! bounds it.

use attlab::model::{Figure, Lab, Outage, SeriesGroup, SeriesSpec};
use attlab::record::Recorder;
use egui::{Color32, Ui};
use egui_plot::{Legend, Line, LineStyle, Plot, Span};

/// Colour of a source: truth white, estimators from a fixed palette by position — the same
/// colour in the 3D ghost, the sphere, the dial, every plot and the tables. Past the first
/// eight, hues step by the golden angle so sixteen filters stay tellable apart.
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
    if let Some(c) = PALETTE.get(source_index) {
        return *c;
    }
    let hue = (source_index as f32 * 0.618_034 + 0.13).fract();
    let value = if source_index.is_multiple_of(2) {
        0.95
    } else {
        0.75
    };
    egui::ecolor::Hsva::new(hue, 0.55, value, 1.0).into()
}

/// Colours of a figure's series: an estimator's series in its source colour when it is that
/// source's only series in the figure; several series of one estimator (its x, y, z) in the
/// bright palette by position, so they stay apart; the truth's first series white; a second
/// truth series and sensor readings in muted colours no estimator uses.
pub fn figure_colors(specs: &[&SeriesSpec]) -> Vec<Color32> {
    const OTHERS: [Color32; 5] = [
        Color32::from_rgb(150, 150, 150),
        Color32::from_rgb(90, 140, 160),
        Color32::from_rgb(200, 170, 130),
        Color32::from_rgb(130, 170, 120),
        Color32::from_rgb(170, 130, 170),
    ];
    let count = |src: usize| specs.iter().filter(|s| s.source == src).count();
    let mut other = 0;
    let mut truth_seen = false;
    specs
        .iter()
        .enumerate()
        .map(|(position, s)| {
            let is_truth = s.name.starts_with("truth.");
            if is_truth && !truth_seen {
                truth_seen = true;
                return source_color(0);
            }
            if !is_truth && s.source > 0 {
                if count(s.source) == 1 {
                    return source_color(s.source);
                }
                return source_color(position + 1);
            }
            other += 1;
            OTHERS[(other - 1) % OTHERS.len()]
        })
        .collect()
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
    /// Shade the lab's sensor outages.
    pub show_outages: bool,
}

impl PlotState {
    /// A lab with figures opens on its first figure, others on the error plot.
    pub fn for_lab(lab: &dyn Lab) -> Self {
        Self {
            tab: attlab::sim::default_tab(lab),
            log_covariance: true,
            show_bands: true,
            show_outages: true,
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

/// The intervals [t₀, t₁] where series `index` equals `out_when`, from its plotted points.
pub fn outage_intervals(rec: &Recorder, index: usize, out_when: f64) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    let mut start: Option<f64> = None;
    let mut last_t = 0.0;
    for p in rec.plot_points(index, 4 * MAX_POINTS) {
        let is_out = (p[1] - out_when).abs() < 0.5;
        match (is_out, start) {
            (true, None) => start = Some(p[0]),
            (false, Some(t0)) => {
                out.push([t0, p[0]]);
                start = None;
            }
            _ => {}
        }
        last_t = p[0];
    }
    if let Some(t0) = start {
        out.push([t0, last_t]);
    }
    out
}

/// Shading colours of outages, by position.
fn outage_color(k: usize) -> Color32 {
    const C: [Color32; 3] = [
        Color32::from_rgba_premultiplied(60, 50, 0, 40),
        Color32::from_rgba_premultiplied(60, 0, 30, 40),
        Color32::from_rgba_premultiplied(0, 40, 60, 40),
    ];
    C[k % C.len()]
}

/// Draws the selected plot (over the whole run), the lab's outages shaded. Returns nothing:
/// tab changes are commands.
pub fn show(
    ui: &mut Ui,
    rec: &Recorder,
    figures: &[Figure],
    outages: &[Outage],
    state: &PlotState,
    line_width: f32,
    hidden: &[usize],
) -> egui::Rect {
    let tab = match state.tab {
        Tab::Figure(i) if i >= figures.len() => Tab::Group(SeriesGroup::Error),
        t => t,
    };
    let lines = tab_lines(rec, figures, tab);
    let log = match tab {
        Tab::Figure(f) => figures[f].log,
        Tab::Group(g) => state.log_covariance && g == SeriesGroup::Covariance,
    };
    let full = ui.available_rect_before_wrap();
    // On a wide plot the legend stands beside it and covers no data.
    let side = full.width() >= SIDE_LEGEND_MIN_PT;
    let legend_w = if side {
        (full.width() * 0.27).min(380.0)
    } else {
        0.0
    };
    let plot_rect = egui::Rect::from_min_max(full.min, full.max - egui::vec2(legend_w, 0.0));
    let mut plot = Plot::new(("series_plot", format!("{tab:?}"))).x_axis_label("t [s]");
    if !side {
        plot = plot.legend(Legend::default().text_style(egui::TextStyle::Small));
    }
    let shown: Vec<(usize, Color32)> = lines
        .into_iter()
        .filter(|(i, _)| {
            let source = rec.specs()[*i].source;
            source == 0 || !hidden.contains(&source)
        })
        .collect();
    let rect = ui
        .scope_builder(egui::UiBuilder::new().max_rect(plot_rect), |ui| {
            plot.show(ui, |plot| {
                if state.show_outages {
                    shade_outages(plot, rec, outages);
                }
                for (i, color) in &shown {
                    let style = LineLook {
                        color: *color,
                        width: line_width,
                        log,
                        bands: state.show_bands,
                    };
                    draw_series(plot, rec, *i, style);
                }
            })
            .response
            .rect
        })
        .inner;
    if side {
        let legend_rect =
            egui::Rect::from_min_max(egui::pos2(plot_rect.max.x + 8.0, full.min.y), full.max);
        ui.scope_builder(egui::UiBuilder::new().max_rect(legend_rect), |ui| {
            side_legend(ui, rec, &shown, log, state, outages);
        });
    }
    ui.advance_cursor_after_rect(full);
    rect
}

/// A plot at least this wide (points) has its legend beside it.
const SIDE_LEGEND_MIN_PT: f32 = 560.0;

/// The legend beside a plot: each drawn series' label and unit in its colour, the ±3σ
/// bands' line style and the outages' shading.
fn side_legend(
    ui: &mut Ui,
    rec: &Recorder,
    shown: &[(usize, Color32)],
    log: bool,
    state: &PlotState,
    outages: &[Outage],
) {
    let swatch = |ui: &mut Ui, color: Color32, dashed: bool| {
        let (r, _) = ui.allocate_exact_size(egui::vec2(18.0, 10.0), egui::Sense::hover());
        let y = r.center().y;
        let stroke = egui::Stroke::new(3.0, color);
        if dashed {
            for k in 0..3 {
                let x = r.min.x + 7.0 * k as f32;
                ui.painter()
                    .line_segment([egui::pos2(x, y), egui::pos2(x + 4.0, y)], stroke);
            }
        } else {
            ui.painter()
                .line_segment([egui::pos2(r.min.x, y), egui::pos2(r.max.x, y)], stroke);
        }
    };
    egui::ScrollArea::vertical().show(ui, |ui| {
        for (i, color) in shown {
            let spec = &rec.specs()[*i];
            let text = if log {
                format!("log10 {}", spec.legend())
            } else {
                spec.legend()
            };
            ui.horizontal(|ui| {
                swatch(ui, *color, false);
                ui.add(egui::Label::new(text).wrap());
            });
        }
        let banded = shown.iter().any(|(i, _)| rec.specs()[*i].band.is_some());
        if state.show_bands && banded && !log {
            ui.horizontal(|ui| {
                swatch(ui, Color32::GRAY, true);
                ui.label("±3σ of the filter's own covariance");
            });
        }
        if state.show_outages {
            for (k, o) in outages.iter().enumerate() {
                ui.horizontal(|ui| {
                    let (r, _) =
                        ui.allocate_exact_size(egui::vec2(18.0, 10.0), egui::Sense::hover());
                    ui.painter().rect_filled(r, 2.0, outage_color(k));
                    ui.label(o.label);
                });
            }
        }
    });
}

/// The series a tab draws with their colours: by source, so an estimator has one colour
/// everywhere; a figure that shows several series of one source tells them apart by
/// position.
fn tab_lines(rec: &Recorder, figures: &[Figure], tab: Tab) -> Vec<(usize, Color32)> {
    match tab {
        Tab::Figure(f) => {
            let idx: Vec<usize> = figures[f]
                .series
                .iter()
                .filter_map(|n| rec.index_of(&n.name()))
                .collect();
            let specs: Vec<&SeriesSpec> = idx.iter().map(|i| &rec.specs()[*i]).collect();
            idx.iter().copied().zip(figure_colors(&specs)).collect()
        }
        Tab::Group(g) => rec
            .specs()
            .iter()
            .enumerate()
            .filter(|(_, s)| s.group == g)
            .map(|(i, s)| (i, source_color(s.source)))
            .collect(),
    }
}

/// The intervals of every outage the lab declares, shaded.
fn shade_outages(plot: &mut egui_plot::PlotUi<'_>, rec: &Recorder, outages: &[Outage]) {
    for (k, o) in outages.iter().enumerate() {
        let Some(i) = rec.index_of(&o.series.name()) else {
            continue;
        };
        for [t0, t1] in outage_intervals(rec, i, o.out_when) {
            plot.span(
                Span::new(o.label, t0..=t1)
                    .fill(outage_color(k))
                    .border_width(0.0),
            );
        }
    }
}

/// How one series is drawn.
#[derive(Clone, Copy)]
struct LineLook {
    color: Color32,
    width: f32,
    /// log10 of the values.
    log: bool,
    /// ±3σ bands where the series has one.
    bands: bool,
}

/// Series `i`, broken at its missing samples, with its ±3σ band from the variance series it
/// names (never from its name).
fn draw_series(plot: &mut egui_plot::PlotUi<'_>, rec: &Recorder, i: usize, look: LineLook) {
    let spec = &rec.specs()[i];
    let mut pts = rec.plot_points(i, MAX_POINTS);
    let mut label = spec.legend();
    if look.log {
        for p in &mut pts {
            p[1] = if p[1] > 0.0 { p[1].log10() } else { f64::NAN };
        }
        label = format!("log10 {label}");
    }
    for piece in Recorder::split_at_gaps(&pts) {
        plot.line(
            Line::new(label.clone(), piece)
                .color(look.color)
                .width(look.width),
        );
    }
    let band = spec.band.as_ref().filter(|_| look.bands && !look.log);
    let Some((var, scale)) = band.and_then(|(name, scale)| rec.index_of(name).map(|v| (v, *scale)))
    else {
        return;
    };
    let sigma3 = |sign: f64| -> Vec<[f64; 2]> {
        rec.plot_points(var, MAX_POINTS)
            .into_iter()
            .map(|p| [p[0], sign * 3.0 * p[1].max(0.0).sqrt() * scale])
            .collect()
    };
    let name = format!("{} ±3σ", spec.label);
    for sign in [1.0, -1.0] {
        plot.line(
            Line::new(name.clone(), sigma3(sign))
                .color(look.color.gamma_multiply(0.6))
                .style(LineStyle::dashed_loose()),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use attlab::model::{SeriesKey, q};

    fn spec(key: SeriesKey, source: usize) -> SeriesSpec {
        SeriesSpec::of(key, SeriesGroup::Attitude).from_source(source)
    }

    #[test]
    fn sixteen_sources_get_sixteen_distinct_colours() {
        let colours: Vec<Color32> = (0..17).map(source_color).collect();
        for (i, a) in colours.iter().enumerate() {
            for b in &colours[i + 1..] {
                assert_ne!(a, b);
            }
        }
    }

    #[test]
    fn a_figure_keeps_each_estimators_colour_and_gives_the_rest_others() {
        let specs = [
            spec(SeriesKey::truth(&q::ANGLE_DEG), 0),
            spec(SeriesKey::truth(&q::RATE_DEG_S), 0),
            spec(SeriesKey::sensors(&q::ANGLE_DEG), 0),
            spec(SeriesKey::new("kf", &q::ANGLE_DEG), 1),
            spec(SeriesKey::new("cf", &q::ANGLE_DEG), 2),
        ];
        let refs: Vec<&SeriesSpec> = specs.iter().collect();
        let c = figure_colors(&refs);
        assert_eq!(c[0], source_color(0));
        assert_eq!(c[3], source_color(1));
        assert_eq!(c[4], source_color(2));
        for other in &c[1..3] {
            assert!((0..17).all(|s| *other != source_color(s)), "{other:?}");
        }
        assert_ne!(c[1], c[2]);
        // One filter's three axes: three different bright colours.
        let axes = [
            spec(SeriesKey::new("st", &q::ERR_X_DEG), 3),
            spec(SeriesKey::new("st", &q::ERR_Y_DEG), 3),
            spec(SeriesKey::new("st", &q::ERR_Z_DEG), 3),
        ];
        let refs: Vec<&SeriesSpec> = axes.iter().collect();
        let c = figure_colors(&refs);
        assert!(c[0] != c[1] && c[1] != c[2] && c[0] != c[2], "{c:?}");
    }
}
