//! A plot's legend: each drawn series in its colour and line pattern, the ±3σ bands' line
//! and the outages' shading, beside or below the plot.
//!
//! Words said twice are said once: series of one owner ("8 ST+Gyro \[λ,ω\]") stand under the
//! owner's name with only what they measure ("attitude error about x [°]"), and owners that
//! share one measure stand under the measure. On a projector the legend's column is narrow
//! and each full label wraps to three lines; grouped, a figure's legend fits its plot's
//! height.

use super::outages;
use super::palette;
use super::plot_state::{PlotState, PlotWords};
use attlab::i18n::LegendParts;
use attlab::page::Outage;
use attlab::record::Recorder;
use egui::{Color32, Ui};
use egui_plot::{LineStyle, MarkerShape};

/// One line of a legend.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Row {
    /// Words the entries under it share: their owner or their measure.
    Heading(String),
    /// Entry `index` (into the legends given to [`rows`]) with its words; `under` when it
    /// stands under a heading, which it leaves out.
    Entry {
        /// The series' position in the legends given.
        index: usize,
        /// What the entry says.
        text: String,
        /// It stands under a heading (drawn indented).
        under: bool,
    },
}

/// The rows of a legend of `legends`, in their order: under one heading when all share a
/// measure (two or more), else the series of an owner that has two or more in a row under
/// its heading, each other series with its full legend.
pub fn rows(legends: &[LegendParts]) -> Vec<Row> {
    let entry = |index: usize, text: &str, under: bool| Row::Entry {
        index,
        text: text.to_string(),
        under,
    };
    let all_owned = legends.iter().all(|l| l.owner.is_some());
    let one_measure = legends.windows(2).all(|w| w[0].what == w[1].what);
    if legends.len() >= 2 && all_owned && one_measure {
        let mut out = vec![Row::Heading(legends[0].what.clone())];
        for (i, l) in legends.iter().enumerate() {
            out.push(entry(i, l.owner.as_deref().unwrap_or_default(), true));
        }
        return out;
    }
    // The length of the run of one owner each series stands in.
    let mut run = vec![1; legends.len()];
    let mut start = 0;
    for i in 1..=legends.len() {
        let same = i < legends.len()
            && legends[i].owner.is_some()
            && legends[i].owner == legends[start].owner;
        if !same {
            run[start..i].fill(i - start);
            start = i;
        }
    }
    let mut out = Vec::new();
    for (i, l) in legends.iter().enumerate() {
        match l.owner.as_deref() {
            Some(owner) if run[i] >= 2 => {
                if i == 0 || legends[i - 1].owner.as_deref() != Some(owner) {
                    out.push(Row::Heading(owner.to_string()));
                }
                out.push(entry(i, &l.what, true));
            }
            _ => out.push(entry(i, &l.joined(), false)),
        }
    }
    out
}

/// A line of the legend as drawn: a [`Row`] of the series, the ±3σ bands' line, or an
/// outage's shading (its position among the outages) with its words.
#[derive(Clone, Debug, PartialEq)]
pub enum Line {
    /// A heading or a series' entry; an entry's series (index into the recorder), colour,
    /// line pattern and marker.
    Series(
        Row,
        Option<(usize, Color32, LineStyle, Option<MarkerShape>)>,
    ),
    /// The ±3σ bands, with their words.
    Bands(String),
    /// Outage `k` and its words.
    Outage(usize, String),
}

impl Line {
    /// What the line says.
    pub fn text(&self) -> &str {
        match self {
            Line::Series(Row::Heading(t) | Row::Entry { text: t, .. }, _)
            | Line::Bands(t)
            | Line::Outage(_, t) => t,
        }
    }
}

/// A plot's shown series (index into the recorder, colour), each one's line pattern and
/// each one's marker.
pub type Looks<'a> = (
    &'a [(usize, Color32)],
    &'a [LineStyle],
    &'a [Option<MarkerShape>],
);

/// The lines of the legend of `shown` series (index into `rec`, colour), in order: the
/// series grouped by [`rows`] (an entry of a series in `no_data` says it has no values),
/// then the ±3σ bands where a drawn series has one, then each outage where they are
/// shaded.
pub fn lines(
    rec: &Recorder,
    (shown, patterns, markers): Looks<'_>,
    (log, state): (bool, &PlotState),
    outages: &[Outage],
    words: &PlotWords<'_>,
    no_data: &[usize],
) -> Vec<Line> {
    let legends: Vec<LegendParts> = shown
        .iter()
        .map(|(i, _)| {
            let mut parts = (words.legend)(&rec.specs()[*i]);
            if log {
                parts.what = format!("log10 {}", parts.what);
            }
            parts
        })
        .collect();
    // Grouped first, so an entry without values still stands under its heading; then the
    // entry says so.
    let mut out: Vec<Line> = rows(&legends)
        .into_iter()
        .map(|mut row| {
            let series = match &mut row {
                Row::Entry { index, text, .. } => {
                    let series = (shown.get(*index).copied())
                        .map(|(i, colour)| (i, colour, patterns[*index], markers[*index]));
                    if series.is_some_and(|(i, ..)| no_data.contains(&i)) {
                        let none = if log {
                            &words.no_positive
                        } else {
                            &words.no_data
                        };
                        *text = format!("{text} — {none}");
                    }
                    series
                }
                Row::Heading(_) => None,
            };
            Line::Series(row, series)
        })
        .collect();
    let banded = shown.iter().any(|(i, _)| rec.specs()[*i].band.is_some());
    if state.show_bands && banded && !log {
        out.push(Line::Bands(words.bands.clone()));
    }
    if state.show_outages {
        for (k, o) in outages.iter().enumerate() {
            let text = words.outages.get(k).map_or(o.label, String::as_str);
            out.push(Line::Outage(k, text.to_string()));
        }
    }
    out
}

/// A legend laid out for its room: its lines, and whether it still scrolls.
pub struct Placed {
    rows: Vec<Laid>,
    scrolls: bool,
}

/// Splits `full` into the plot and its legend of `lines`: a column on the right of a wide
/// plot, a strip below a narrow one. The column's type shrinks, down to `SMALLEST` (0.7) of
/// the body's and `SMALLEST_PX` (10 CSS px), and the column widens, up to `WIDEST` (0.42)
/// of `full`, until every line fits its height (the larger type first: it is read from the
/// back of a room); a legend taller even then scrolls, its scroll bar in view.
pub fn place(ui: &Ui, full: egui::Rect, lines: &[Line]) -> (egui::Rect, egui::Rect, Placed) {
    let body = egui::TextStyle::Body.resolve(ui.style()).size;
    let gap = ui.spacing().item_spacing.y;
    let laid = |scale: f32, width: f32| layout(ui, lines, width, (body * scale, gap * scale));
    // Beside a wide plot, or a short one (a phone held sideways), below a narrow one.
    let side = full.width() >= SIDE_LEGEND_MIN_PT || full.width() >= SHORT_ASPECT * full.height();
    let room_y = if side {
        full.height()
    } else {
        // As high as the lines need at the body's type, at most a third of the plot's room.
        height(&laid(1.0, full.width()), gap).min(full.height() / 3.0)
    };
    let widths: &[f32] = if side { &[0.27, 0.34, WIDEST] } else { &[1.0] };
    let width_of = |share: f32| {
        if side {
            (full.width() * share).min(MAX_COLUMN_PT * share / 0.27)
        } else {
            full.width()
        }
    };
    // The smallest type: a share of the body's, and never under SMALLEST_PX on the screen.
    let smallest = SMALLEST
        .max(SMALLEST_PX / ui.ctx().zoom_factor() / body)
        .min(1.0);
    let scales =
        (0..=SHRINK_STEPS).map(|k| 1.0 - (1.0 - smallest) * k as f32 / SHRINK_STEPS as f32);
    let fits = scales
        .flat_map(|scale| widths.iter().map(move |w| (scale, width_of(*w))))
        .map(|(scale, width)| (width, laid(scale, width)))
        .find(|(_, rows)| height(rows, gap) <= room_y);
    let scroll_bar = egui::style::ScrollStyle::solid().allocated_width();
    let (width, placed) = match fits {
        Some((width, rows)) => (
            width,
            Placed {
                rows,
                scrolls: false,
            },
        ),
        None => {
            let width = width_of(*widths.last().unwrap_or(&1.0));
            let rows = laid(smallest, width - scroll_bar);
            (
                width,
                Placed {
                    rows,
                    scrolls: true,
                },
            )
        }
    };
    let (plot, legend) = if side {
        let plot = egui::Rect::from_min_max(full.min, full.max - egui::vec2(width + 8.0, 0.0));
        (
            plot,
            egui::Rect::from_min_max(egui::pos2(plot.max.x + 8.0, full.min.y), full.max),
        )
    } else {
        let plot = egui::Rect::from_min_max(full.min, full.max - egui::vec2(0.0, room_y + 4.0));
        (
            plot,
            egui::Rect::from_min_max(egui::pos2(full.min.x, plot.max.y + 4.0), full.max),
        )
    };
    (plot, legend, placed)
}

/// The legend as [`place`] laid it out: its [`lines`], each series in its colour and line
/// pattern.
pub fn show(ui: &mut Ui, lines: &[Line], placed: Placed) {
    let Placed { rows, scrolls } = placed;
    let gap = ui.spacing().item_spacing.y;
    let colours = palette::of(ui.visuals());
    if scrolls {
        ui.spacing_mut().scroll = egui::style::ScrollStyle::solid();
    }
    egui::ScrollArea::vertical()
        .id_salt("legend")
        .show(ui, |ui| {
            ui.spacing_mut().item_spacing.y = rows.first().map_or(gap, |r| r.gap);
            for (k, (line, row)) in lines.iter().zip(rows).enumerate() {
                let size = egui::vec2(ui.available_width(), row.galley.size().y.max(SWATCH_PT.y));
                let (rect, _) = ui.allocate_exact_size(size, egui::Sense::hover());
                let mark = egui::Rect::from_min_size(
                    egui::pos2(rect.min.x + row.indent, rect.center().y - SWATCH_PT.y / 2.0),
                    SWATCH_PT,
                );
                match line {
                    Line::Series(_, Some((_, color, pattern, marker))) => {
                        let y = mark.center().y;
                        let stroke = egui::Stroke::new(2.5, *color);
                        let pattern = *pattern;
                        let ends = vec![egui::pos2(mark.min.x, y), egui::pos2(mark.max.x, y)];
                        palette::styled_polyline(ui.painter(), ends, stroke, pattern);
                        if let Some(shape) = marker {
                            let radius = super::series_lines::MARKER_RADIUS;
                            palette::paint_marker(
                                ui.painter(),
                                mark.center(),
                                radius,
                                (*shape, *color),
                            );
                        }
                    }
                    Line::Bands(_) => {
                        let y = mark.center().y;
                        let stroke = egui::Stroke::new(2.5, Color32::GRAY);
                        let ends = vec![egui::pos2(mark.min.x, y), egui::pos2(mark.max.x, y)];
                        palette::styled_polyline(
                            ui.painter(),
                            ends,
                            stroke,
                            LineStyle::dashed_loose(),
                        );
                    }
                    Line::Outage(o, _) => {
                        let shade = mark.with_max_x(mark.min.x + OUTAGE_PT);
                        ui.painter()
                            .rect_filled(shade, 2.0, outages::color(colours, *o));
                    }
                    Line::Series(_, None) => {}
                }
                let text = egui::Rect::from_min_max(
                    egui::pos2(rect.min.x + row.lead, rect.min.y),
                    rect.max,
                );
                // In the row already allocated: a child that does not move the cursor again.
                ui.new_child(egui::UiBuilder::new().id_salt(k).max_rect(text))
                    .add(egui::Label::new(row.galley));
            }
        });
}

/// A line of the legend laid out: its words wrapped to the room beside its mark.
struct Laid {
    galley: std::sync::Arc<egui::Galley>,
    /// Where its mark starts (points from the legend's left).
    indent: f32,
    /// Where its words start.
    lead: f32,
    /// The space between lines at this size.
    gap: f32,
}

/// `lines` laid out in `width` with type of `size` points and `gap` between lines.
fn layout(ui: &Ui, lines: &[Line], width: f32, (size, gap): (f32, f32)) -> Vec<Laid> {
    let font = egui::FontId::new(size, egui::TextStyle::Body.resolve(ui.style()).family);
    let visuals = ui.visuals();
    let spacing = ui.spacing().item_spacing.x;
    lines
        .iter()
        .map(|line| {
            let (indent, mark, color) = match line {
                Line::Series(Row::Heading(_), _) => (0.0, 0.0, visuals.strong_text_color()),
                Line::Series(Row::Entry { under, .. }, _) => {
                    let indent = if *under { INDENT_PT } else { 0.0 };
                    (indent, SWATCH_PT.x, visuals.text_color())
                }
                Line::Bands(_) => (0.0, SWATCH_PT.x, visuals.text_color()),
                Line::Outage(..) => (0.0, OUTAGE_PT, visuals.text_color()),
            };
            let lead = if mark > 0.0 {
                indent + mark + spacing
            } else {
                0.0
            };
            let wrap = (width - lead - 1.0).max(size);
            let galley = ui
                .painter()
                .layout(line.text().to_owned(), font.clone(), color, wrap);
            Laid {
                galley,
                indent,
                lead,
                gap,
            }
        })
        .collect()
}

/// How tall laid-out lines stand, with the gaps between them.
fn height(rows: &[Laid], gap: f32) -> f32 {
    let lines: f32 = rows
        .iter()
        .map(|r| r.galley.size().y.max(SWATCH_PT.y))
        .sum();
    let gap = rows.first().map_or(gap, |r| r.gap);
    lines + gap * rows.len().saturating_sub(1) as f32
}

/// The smallest type a legend shrinks to, as a share of the body's: still read from the
/// back of a lecture room on a projector (presenter mode's 1.5 zoom makes it 13 px).
const SMALLEST: f32 = 0.7;

/// The smallest type a legend shrinks to on the screen (CSS pixels): without presenter
/// mode's zoom, [`SMALLEST`] of the body's would be under 9 px.
const SMALLEST_PX: f32 = 10.0;

/// The widest a legend's column grows to, as a share of the plot's room.
const WIDEST: f32 = 0.42;

/// The widest a legend's column is at its narrowest share (points); its wider shares grow
/// in proportion.
const MAX_COLUMN_PT: f32 = 380.0;

/// A plot at least this wide (points) has its legend beside it.
const SIDE_LEGEND_MIN_PT: f32 = 560.0;
/// A plot's room this many times as wide as it is tall puts its legend beside it whatever
/// its width: below, on a phone held sideways, it had left the plot 50 points tall.
const SHORT_ASPECT: f32 = 1.5;

/// The sizes tried between the body's type and [`SMALLEST`].
const SHRINK_STEPS: usize = 6;

/// A series' mark: a short stretch of its line (points).
const SWATCH_PT: egui::Vec2 = egui::vec2(30.0, 10.0);

/// An outage's mark: a patch of its shade (points wide).
const OUTAGE_PT: f32 = 18.0;

/// How far an entry under a heading is indented (points).
const INDENT_PT: f32 = 8.0;

#[cfg(test)]
#[path = "legend_tests.rs"]
mod tests;
