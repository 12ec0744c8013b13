//! Time plots of the recorded series over the whole run: one tab per figure of the lab and
//! per series group, coloured by source, with ±3σ bands where a series says which variance
//! bounds it.

use super::outages;
use super::palette::{self, Palette};
pub use super::plot_state::{PlotState, PlotWords, Tab};
use attlab::model::{SeriesGroup, SeriesSpec};
use attlab::page::{Figure, Outage};
use attlab::record::Recorder;
use egui::{Color32, Ui};
use egui_plot::Plot;

/// Points per line on screen.
pub(super) const MAX_POINTS: usize = 1500;

pub use super::series_lines::pieces;

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
    marks: &super::travel_lines::TravelMarks<'_>,
) -> egui::Rect {
    let colours = palette::of(ui.visuals());
    let (tab, log, shown) = selection(rec, figures, state, hidden, colours);
    let full = ui.available_rect_before_wrap();
    // The legend never covers data: beside a wide plot, below a narrow one.
    // A point (a bucket's least and greatest value) every two pixels of the area's width.
    let pixels = (full.width() * ui.ctx().pixels_per_point()) as usize;
    let (points, no_data) = points_up_to(rec, &shown, log, (pixels / 2).clamp(200, MAX_POINTS));
    let patterns = palette::patterns(rec.specs(), &shown);
    let markers = palette::markers(rec.specs(), &shown);
    let series = (&shown[..], &patterns[..], &markers[..]);
    let lines = super::legend::lines(rec, series, (log, state), outages, words, &no_data);
    let (plot_rect, legend_rect, placed) = super::legend::place(ui, full, &lines);
    // The wheel zooms about the pointer (it panned the data out of view); a visible button
    // brings back the whole run once the reader has zoomed or dragged.
    let reset_id = egui::Id::unique(("series_plot_reset", format!("{tab:?}")));
    let plot = new_plot(
        ui,
        rec,
        (tab, log, &shown),
        plot_rect.height(),
        words,
        reset_id,
    );
    let steady = steady_fit(rec, figures, (tab, log, &shown), &points, state.show_bands);
    let plot = fitted(plot, steady, &points, log);
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
                let look = (line_width, log, state.show_bands);
                let drawn = (&shown[..], points, &patterns[..], &markers[..]);
                let dense = draw_lines(plot, rec, drawn, look, words);
                super::travel_lines::draw(plot, rec, &shown, marks, (line_width, log));
                // Moved from where the figure opens (the steady fit keeps its y fixed).
                let auto = plot.auto_bounds();
                let moved = if steady.is_some() {
                    !auto.x
                } else {
                    !auto.all()
                };
                (moved, dense)
            });
            let (moved, dense) = shown_plot.inner;
            for (pieces, look) in &dense {
                super::dense::paint(ui.painter(), &shown_plot.transform, pieces, *look);
            }

            outages::label(ui, &shown_plot.transform, &bands, &words.outages);
            if let Some((t0, ..)) = steady.filter(|_| !moved) {
                super::y_range::note(ui, shown_plot.response.rect, &(words.steady_note)(t0));
            }
            (shown_plot.response.rect, moved)
        })
        .inner;
    if moved {
        reset_button(ui, rect, reset_id, &words.reset);
    }
    ui.scope_builder(egui::UiBuilder::new().max_rect(legend_rect), |ui| {
        super::legend::show(ui, &lines, placed);
    });
    ui.advance_cursor_after_rect(full);
    rect
}

/// The plot of `tab` with its axis titles (the y title fitted to a plot `height` points
/// tall), its ticks in the reader's language, and back at the whole run when its ⟲ was
/// pressed in the last frame.
fn new_plot<'a>(
    ui: &Ui,
    rec: &Recorder,
    (tab, log, shown): (Tab, bool, &[(usize, Color32)]),
    height: f32,
    words: &PlotWords<'_>,
    reset_id: egui::Id,
) -> Plot<'a> {
    let plot = Plot::new(("series_plot", format!("{tab:?}")))
        .x_axis_label(words.time_axis.clone())
        .y_axis_label(fitting_title(ui, y_title(rec, shown, log, words), height))
        .x_grid_spacer(super::ticks::x_marks)
        .y_grid_spacer(super::ticks::y_marks)
        .allow_scroll(false);
    let plot = super::ticks::in_language(plot, words.lang);
    let reset = ui
        .data_mut(|d| d.remove_temp::<bool>(reset_id))
        .unwrap_or(false);
    if reset { plot.reset() } else { plot }
}

/// `plot` with its value axis fitted to the `steady` part, or, where every value drawn is
/// the same to rounding, to a readable range about it.
fn fitted<'a>(
    plot: Plot<'a>,
    steady: Option<(f64, (f64, f64), f64)>,
    points: &[Vec<[f64; 2]>],
    log: bool,
) -> Plot<'a> {
    if let Some((_, (lo, hi), start)) = steady {
        let plot = plot.auto_bounds([true, false]).default_y_bounds(lo, hi);
        return if start.is_finite() {
            plot.include_x(start)
        } else {
            plot
        };
    }
    match super::y_range::flat(points, log) {
        Some((lo, hi)) => plot.include_y(lo).include_y(hi),
        None => plot,
    }
}

/// A figure that starts with a transient fits its value axis to what follows it: the time
/// it leaves off the scale, the range and where the run starts (so the x axis still shows
/// the transient's seconds, its lines cut to the scale).
fn steady_fit(
    rec: &Recorder,
    figures: &[Figure],
    (tab, log, shown): (Tab, bool, &[(usize, Color32)]),
    points: &[Vec<[f64; 2]>],
    bands: bool,
) -> Option<(f64, (f64, f64), f64)> {
    let Tab::Figure(f) = tab else {
        return None;
    };
    let t0 = figures.iter().find(|x| x.id == f)?.steady_after_s?;
    let range = super::y_range::steady(rec, shown, log, t0, bands)?;
    let start = (points.iter())
        .filter_map(|p| p.first())
        .map(|p| p[0])
        .fold(f64::INFINITY, f64::min);
    Some((t0, range, start))
}

/// Every shown series' line and band in the plot; returns the dense ones, for
/// [`super::dense`] to paint over it, with their colours and width.
#[allow(clippy::type_complexity)]
fn draw_lines(
    plot: &mut egui_plot::PlotUi<'_>,
    rec: &Recorder,
    (shown, points, patterns, markers): (
        &[(usize, Color32)],
        Vec<Vec<[f64; 2]>>,
        &[egui_plot::LineStyle],
        &[Option<egui_plot::MarkerShape>],
    ),
    (width, log, bands): (f32, bool, bool),
    words: &PlotWords<'_>,
) -> Vec<(Vec<Vec<[f64; 2]>>, (Color32, f32))> {
    let mut dense = Vec::new();
    let looks = patterns.iter().zip(markers);
    for (((i, color), pts), (pattern, marker)) in shown.iter().zip(points).zip(looks) {
        let style = super::series_lines::LineLook {
            color: *color,
            width,
            pattern: *pattern,
            marker: *marker,
            log,
            bands,
        };
        let drawn = super::series_lines::draw_series(plot, rec, (*i, pts), style, &words.legend);
        dense.extend(drawn.map(|pieces| (pieces, (*color, width))));
    }
    dense
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
    let figure = |id: &str| figures.iter().find(|f| f.id == id);
    let tab = match state.tab {
        Tab::Figure(id) if figure(id).is_none() => Tab::Group(SeriesGroup::Error),
        t => t,
    };
    let log = match tab {
        Tab::Figure(id) => figure(id).is_some_and(|f| f.log),
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
    points_up_to(rec, shown, log, MAX_POINTS)
}

/// The same with at most about `max_points` points a series: a noisy line is drawn as a
/// stroke from each bucket's least to its greatest value, and at two points a pixel paper
/// 2's errors at the scale of their steady part had shaded their plot three times over.
fn points_up_to(
    rec: &Recorder,
    shown: &[(usize, Color32)],
    log: bool,
    max_points: usize,
) -> (Vec<Vec<[f64; 2]>>, Vec<usize>) {
    let drawable = |y: f64| y.is_finite() && (!log || y > 0.0);
    let points: Vec<Vec<[f64; 2]>> = shown
        .iter()
        .map(|(i, _)| rec.plot_points(*i, max_points))
        .collect();
    let no_data = shown
        .iter()
        .zip(&points)
        .filter(|(_, pts)| !pts.iter().any(|p| drawable(p[1])))
        .map(|((i, _), _)| *i)
        .collect();
    (points, no_data)
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
    // What the series measure: their group's noun, else what their one unit measures
    // ("angle" for degrees), else "value" (a lone "[°]" or "[–]" had said nothing).
    let noun = specs()
        .all(|s| s.group == first.group)
        .then(|| (words.group_axis)(first.group))
        .flatten()
        .unwrap_or_else(|| (words.unit_noun)(first.unit));
    let [full, short] = if !specs().all(|s| s.unit == first.unit) {
        [words.mixed_units.clone(), String::new()]
    } else {
        match first.unit {
            "" => [noun, String::new()],
            unit => {
                let unit = format!("[{}]", (words.unit)(unit));
                [format!("{noun} {unit}"), unit]
            }
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
        Tab::Figure(id) => {
            let series = (figures.iter().find(|f| f.id == id)).map_or(&[][..], |f| f.series);
            let idx: Vec<usize> = series
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

#[cfg(test)]
mod tests {
    use super::*;

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
            steady_note: Box::new(|_| String::new()),
            unit_noun: Box::new(|u| format!("noun-of-{u}")),
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
        // Without a unit, the noun alone (no "[–]").
        assert_eq!(full(&[4], true), "log10 axis-covariance");
        // A lab's own series, or two groups with one unit: what the unit measures.
        assert_eq!(full(&[3], false), "noun-of-deg [°]");
        assert_eq!(full(&[0, 3], false), "noun-of-deg [°]");
        assert_eq!(full(&[0, 2], true), "log10 mixed");
        // Without the words, for a short plot: the unit, or log10 alone.
        assert_eq!(title(&[0, 1], false)[1], "[°]");
        assert_eq!(title(&[4], true)[1], "log10");
        assert_eq!(title(&[0, 2], true)[1], "log10");
        assert_eq!(title(&[0, 2], false)[1], "");
        assert_eq!(title(&[], false), ["", ""]);
    }
}
