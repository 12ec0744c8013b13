//! Time plots of the recorded series over the whole run: one tab per figure of the lab and
//! per series group, coloured by source, with ±3σ bands where a series says which variance
//! bounds it.

use super::outages;
use super::palette::{self, Palette};
use attlab::i18n::LegendParts;
use attlab::model::{Figure, Lab, Outage, SeriesGroup, SeriesSpec};
use attlab::record::Recorder;
use egui::{Color32, Ui};
use egui_plot::{Line, LineStyle, Plot};

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
}

/// Draws the selected plot (over the whole run), the lab's outages shaded. Returns nothing:
/// tab changes are commands.
#[allow(clippy::too_many_arguments)]
pub fn show(
    ui: &mut Ui,
    rec: &Recorder,
    figures: &[Figure],
    outages: &[Outage],
    state: &PlotState,
    line_width: f32,
    hidden: &[usize],
    words: &PlotWords<'_>,
) -> egui::Rect {
    let colours = palette::of(ui.visuals());
    let (tab, log, shown) = selection(rec, figures, state, hidden, colours);
    let full = ui.available_rect_before_wrap();
    // The legend never covers data: beside a wide plot, below a narrow one.
    let (points, no_data) = points(rec, &shown, log);
    let lines = super::legend::lines(rec, &shown, (log, state), outages, words, &no_data);
    let (plot_rect, legend_rect, placed) = super::legend::place(ui, full, &lines);
    // The wheel zooms about the pointer (it panned the data out of view); a visible button
    // brings back the whole run once the reader has zoomed or dragged.
    let reset_id = egui::Id::unique(("series_plot_reset", format!("{tab:?}")));
    let plot = Plot::new(("series_plot", format!("{tab:?}")))
        .x_axis_label(words.time_axis.clone())
        .y_axis_label(fitting_title(
            ui,
            y_title(rec, &shown, log, words),
            plot_rect.height(),
        ))
        .x_grid_spacer(super::ticks::x_marks)
        .y_grid_spacer(super::ticks::y_marks)
        .allow_scroll(false);
    let mut plot = super::ticks::in_language(plot, words.lang);
    if ui
        .data_mut(|d| d.remove_temp::<bool>(reset_id))
        .unwrap_or(false)
    {
        plot = plot.reset();
    }
    if let Some((lo, hi)) = flat_range(&points, log) {
        plot = plot.include_y(lo).include_y(hi);
    }
    let bands = if state.show_outages {
        outages::bands(rec, outages)
    } else {
        Vec::new()
    };
    let (rect, moved) = ui
        .scope_builder(egui::UiBuilder::new().max_rect(plot_rect), |ui| {
            let shown_plot = plot.show(ui, |plot| {
                wheel_zoom(plot);
                outages::shade(plot, &bands, colours);
                for ((i, color), pts) in shown.iter().zip(points) {
                    let style = LineLook {
                        color: *color,
                        width: line_width,
                        pattern: palette::pattern(rec.specs()[*i].source),
                        log,
                        bands: state.show_bands,
                    };
                    draw_series(plot, rec, (*i, pts), style, &words.legend);
                }
                !plot.auto_bounds().all()
            });
            outages::label(ui, &shown_plot.transform, &bands, &words.outages);
            (shown_plot.response.rect, shown_plot.inner)
        })
        .inner;
    if moved {
        reset_button(ui, rect, reset_id, &words.reset);
    }
    ui.scope_builder(egui::UiBuilder::new().max_rect(legend_rect), |ui| {
        super::legend::show(ui, rec, &lines, placed);
    });
    ui.advance_cursor_after_rect(full);
    rect
}

/// What the selected tab draws: the tab (a figure the lab lacks falls back to the errors),
/// whether as log10, and its series (index into `rec`, colour) without the hidden sources.
pub fn selection(
    rec: &Recorder,
    figures: &[Figure],
    state: &PlotState,
    hidden: &[usize],
    colours: &Palette,
) -> (Tab, bool, Vec<(usize, Color32)>) {
    let tab = match state.tab {
        Tab::Figure(i) if i >= figures.len() => Tab::Group(SeriesGroup::Error),
        t => t,
    };
    let log = match tab {
        Tab::Figure(f) => figures[f].log,
        Tab::Group(g) => state.log_covariance && g == SeriesGroup::Covariance,
    };
    let shown = lines(rec, figures, tab, colours)
        .into_iter()
        .filter(|(i, _)| {
            let source = rec.specs()[*i].source;
            source == 0 || !hidden.contains(&source)
        })
        .collect();
    (tab, log, shown)
}

/// The plot points of each of `shown` series (read once a frame, for the legend and the
/// lines), and which series have no value anywhere in the run that the plot can draw
/// (none positive on a `log` plot): the legend says so.
pub fn points(
    rec: &Recorder,
    shown: &[(usize, Color32)],
    log: bool,
) -> (Vec<Vec<[f64; 2]>>, Vec<usize>) {
    let drawable = |y: f64| y.is_finite() && (!log || y > 0.0);
    let points: Vec<Vec<[f64; 2]>> = shown
        .iter()
        .map(|(i, _)| rec.plot_points(*i, MAX_POINTS))
        .collect();
    let no_data = shown
        .iter()
        .zip(&points)
        .filter(|(_, pts)| !pts.iter().any(|p| drawable(p[1])))
        .map(|((i, _), _)| *i)
        .collect();
    (points, no_data)
}

/// A y range to show when every value drawn is the same to rounding (a lesson step paused
/// at t = 0; log10 of two equal errors): egui_plot fits the data's own range, 10⁻¹⁶ wide,
/// and its marks read "0.301029995663981". The value ± a tenth of it, at least ± 1, as
/// egui_plot does for an exactly flat line. `None` when the values spread (or there are
/// none).
fn flat_range(points: &[Vec<[f64; 2]>], log: bool) -> Option<(f64, f64)> {
    let shown = |y: f64| -> f64 { if log { y.log10() } else { y } };
    let (lo, hi) = points
        .iter()
        .flatten()
        .map(|p| shown(p[1]))
        .filter(|y| y.is_finite())
        .fold(
            (f64::INFINITY, f64::NEG_INFINITY),
            |(lo, hi): (f64, f64), y| (lo.min(y), hi.max(y)),
        );
    let scale = lo.abs().max(hi.abs()).max(1.0);
    if lo > hi || hi - lo > 1e-9 * scale {
        return None;
    }
    let centre = 0.5 * (lo + hi);
    let pad = (0.1 * centre.abs()).max(1.0);
    Some((centre - pad, centre + pad))
}

/// The "⟲" in the plot's top-right corner: the next frame shows the whole run again.
fn reset_button(ui: &mut Ui, plot: egui::Rect, reset_id: egui::Id, hint: &str) {
    let at = egui::Rect::from_min_size(
        egui::pos2(plot.max.x - 30.0, plot.min.y + 4.0),
        egui::vec2(26.0, 22.0),
    );
    if ui
        .put(at, egui::Button::new("⟲"))
        .on_hover_text(hint)
        .clicked()
    {
        ui.data_mut(|d| d.insert_temp(reset_id, true));
    }
}

/// A turn of the wheel over the plot zooms about the pointer (up: in), as a map does.
fn wheel_zoom(plot: &mut egui_plot::PlotUi<'_>) {
    if !plot.response().hovered() {
        return;
    }
    let scroll = plot.response().ctx.input(|i| i.smooth_scroll_delta.y);
    if scroll != 0.0 {
        plot.zoom_bounds_around_hovered(egui::Vec2::splat((scroll * 0.003).exp()));
    }
}

/// The y axis' title: what the drawn series measure, when they are of one group, and the
/// unit they share ("error [°]", "log10 covariance [°²]", "[–]" for none), or "mixed units
/// (see the legend)"; then the same without the words, for a plot too short to hold them
/// ("[°]", "log10"; the legend names every series with its unit).
fn y_title(
    rec: &Recorder,
    shown: &[(usize, Color32)],
    log: bool,
    words: &PlotWords<'_>,
) -> [String; 2] {
    let specs = || shown.iter().map(|(i, _)| &rec.specs()[*i]);
    let Some(first) = specs().next() else {
        return [String::new(), String::new()];
    };
    let noun = specs()
        .all(|s| s.group == first.group)
        .then(|| (words.group_axis)(first.group))
        .flatten();
    let [full, short] = if !specs().all(|s| s.unit == first.unit) {
        [words.mixed_units.clone(), String::new()]
    } else {
        let unit = match first.unit {
            "" => "[–]".to_string(),
            unit => format!("[{}]", (words.unit)(unit)),
        };
        match noun {
            Some(noun) => [format!("{noun} {unit}"), unit],
            None => [unit.clone(), unit],
        }
    };
    [full, short].map(|t| match (log, t.is_empty()) {
        (false, _) => t,
        (true, true) => "log10".to_string(),
        (true, false) => format!("log10 {t}"),
    })
}

/// The first of `titles` that fits along a plot `height` points tall (the x axis' marks and
/// title take the bottom), else the last: egui_plot centres the y axis' title on the frame
/// and lets a longer one run over the tabs above the plot (paper 1's lesson on a projector).
fn fitting_title(ui: &egui::Ui, titles: [String; 2], height: f32) -> String {
    let font = egui::TextStyle::Body.resolve(ui.style());
    let room = height - 3.0 * ui.text_style_height(&egui::TextStyle::Body);
    let [full, short] = titles;
    let width = (ui.painter())
        .layout_no_wrap(full.clone(), font, Color32::WHITE)
        .size()
        .x;
    if width <= room { full } else { short }
}

/// The series a tab draws with their colours: by source, so an estimator has one colour
/// everywhere; a figure that shows several series of one source tells them apart by
/// position.
fn lines(rec: &Recorder, figures: &[Figure], tab: Tab, colours: &Palette) -> Vec<(usize, Color32)> {
    match tab {
        Tab::Figure(f) => {
            let idx: Vec<usize> = figures[f]
                .series
                .iter()
                .filter_map(|n| rec.index_of(&n.name()))
                .collect();
            let specs: Vec<&SeriesSpec> = idx.iter().map(|i| &rec.specs()[*i]).collect();
            idx.iter()
                .copied()
                .zip(palette::figure_colors(colours, &specs))
                .collect()
        }
        Tab::Group(g) => rec
            .specs()
            .iter()
            .enumerate()
            .filter(|(_, s)| s.group == g)
            .map(|(i, s)| (i, colours.source(s.source)))
            .collect(),
    }
}

/// How one series is drawn.
#[derive(Clone, Copy)]
struct LineLook {
    color: Color32,
    width: f32,
    /// The source's line pattern.
    pattern: LineStyle,
    /// log10 of the values.
    log: bool,
    /// ±3σ bands where the series has one.
    bands: bool,
}

/// Series `i` from its plot points, broken at its missing samples, with its ±3σ band from
/// the variance series it names (never from its name).
fn draw_series(
    plot: &mut egui_plot::PlotUi<'_>,
    rec: &Recorder,
    (i, mut pts): (usize, Vec<[f64; 2]>),
    look: LineLook,
    legend: &dyn Fn(&SeriesSpec) -> LegendParts,
) {
    let spec = &rec.specs()[i];
    let mut label = legend(spec).joined();
    if look.log {
        for p in &mut pts {
            p[1] = if p[1] > 0.0 { p[1].log10() } else { f64::NAN };
        }
        label = format!("log10 {label}");
    }
    for piece in pieces(plot, &pts, look.pattern) {
        plot.line(
            Line::new(label.clone(), piece)
                .color(look.color)
                .width(look.width)
                .style(look.pattern),
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
    let name = format!("{} ±3σ", legend(spec).joined());
    for sign in [1.0, -1.0] {
        for piece in pieces(plot, &sigma3(sign), LineStyle::dashed_loose()) {
            plot.line(
                Line::new(name.clone(), piece)
                    .color(look.color.gamma_multiply(0.6))
                    .style(LineStyle::dashed_loose()),
            );
        }
    }
}

/// The pieces of a series to draw: broken at its missing samples, a dashed or dotted one cut
/// to what the plot shows, and each thinned to the plot's pixels (see [`super::clip`]).
pub fn pieces(
    plot: &egui_plot::PlotUi<'_>,
    pts: &[[f64; 2]],
    style: LineStyle,
) -> Vec<Vec<[f64; 2]>> {
    let pieces = if style == LineStyle::Solid {
        Recorder::split_at_gaps(pts)
    } else {
        super::clip::clip_to_bounds(pts, &plot.plot_bounds())
    };
    let px = plot.transform().dvalue_dpos().map(f64::abs);
    let thin = |piece| super::clip::thin_to_pixels(piece, px);
    pieces.into_iter().map(thin).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_run_gets_a_readable_range_and_a_spread_one_none() {
        let two = |a: f64, b: f64| vec![vec![[0.0, a]], vec![[0.0, b]]];
        // log10 of two equal errors of 2°, the second one ulp off.
        let (lo, hi) = flat_range(&two(2.0, 2.0 + 4e-16), true).expect("flat");
        assert!(
            (lo + 0.69897).abs() < 1e-4 && (hi - 1.30103).abs() < 1e-4,
            "{lo} {hi}"
        );
        assert_eq!(flat_range(&two(360.0, 360.0), false), Some((324.0, 396.0)));
        assert_eq!(flat_range(&two(0.0, 0.0), false), Some((-1.0, 1.0)));
        assert_eq!(flat_range(&two(0.0, 1e-6), false), None);
        assert_eq!(flat_range(&two(2.0, 2.1), true), None);
        assert_eq!(flat_range(&[], false), None);
        assert_eq!(flat_range(&two(f64::NAN, f64::NAN), false), None);
        // A log plot draws no value ≤ 0 and ignores it here too.
        assert_eq!(flat_range(&two(0.0, 0.0), true), None);
    }

    fn words() -> PlotWords<'static> {
        PlotWords {
            legend: Box::new(|_| unreachable!("the title needs no legend")),
            time_axis: String::new(),
            mixed_units: "mixed".into(),
            group_axis: Box::new(|g| g.axis_message().map(str::to_string)),
            unit: Box::new(attlab::model::display_unit),
            bands: String::new(),
            no_data: String::new(),
            no_positive: String::new(),
            outages: Vec::new(),
            reset: String::new(),
            lang: attlab::i18n::Lang::En,
        }
    }

    #[test]
    fn the_y_axis_names_what_one_groups_series_measure_before_their_unit() {
        let spec = |name: &str, unit, group| SeriesSpec::new(name, unit, group);
        let rec = Recorder::with_window(
            vec![
                spec("ex", "deg", SeriesGroup::Error),
                spec("ey", "deg", SeriesGroup::Error),
                spec("wx", "deg/s", SeriesGroup::Rate),
                spec("roll", "deg", SeriesGroup::Lab),
                spec("pxx", "", SeriesGroup::Covariance),
            ],
            8,
        );
        let title = |shown: &[usize], log| {
            let shown: Vec<_> = shown.iter().map(|i| (*i, Color32::RED)).collect();
            y_title(&rec, &shown, log, &words())
        };
        let full = |shown: &[usize], log| title(shown, log)[0].clone();
        assert_eq!(full(&[0, 1], false), "axis-error [°]");
        assert_eq!(full(&[2], false), "axis-rate [°/s]");
        assert_eq!(full(&[4], true), "log10 axis-covariance [–]");
        // A lab's own series, or two groups with one unit: the unit alone.
        assert_eq!(full(&[3], false), "[°]");
        assert_eq!(full(&[0, 3], false), "[°]");
        assert_eq!(full(&[0, 2], true), "log10 mixed");
        // Without the words, for a short plot: the unit, or log10 alone.
        assert_eq!(title(&[0, 1], false)[1], "[°]");
        assert_eq!(title(&[4], true)[1], "log10 [–]");
        assert_eq!(title(&[0, 2], true)[1], "log10");
        assert_eq!(title(&[0, 2], false)[1], "");
        assert_eq!(title(&[], false), ["", ""]);
    }
}
