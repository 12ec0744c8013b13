//! The lab's outages on a plot: each interval shaded in its colour, its name in the reader's
//! language at the top of the band, on a backing of the panel's colour so that the lines it
//! crosses leave it readable. egui_plot's own span labels had been the lab's English words,
//! drawn straight over the lines (paper 2's "star tracker out" over the dashed ST+Gyro).

use super::palette::Palette;
use attlab::page::Outage;
use attlab::record::Recorder;
use egui::{Color32, Ui};
use egui_plot::{PlotTransform, PlotUi, Span};

/// Space between a label and the band's edges (points).
const PADDING: f32 = 4.0;

/// A label narrower than this is left out (the legend names every outage).
const MIN_LABEL_WIDTH: f32 = 24.0;

/// A label is drawn only if at least this many of its characters fit.
const LEAST_CHARS: usize = 8;

/// The points of a series read to find its intervals: four times a plotted line's, so an
/// edge lands within a quarter of the lines' point spacing.
const POINTS: usize = 6_000;

/// How opaque a label's backing is.
const BACKING_OPACITY: f32 = 0.8;

/// One shaded interval: outage `k` of the lab's list, from `t0_s` to `t1_s`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// The outage's position in the list (its colour and its words).
    pub k: usize,
    /// Start (s).
    pub t0_s: f64,
    /// End (s).
    pub t1_s: f64,
}

/// Every interval of every outage the recorder shows.
pub fn bands(rec: &Recorder, outages: &[Outage]) -> Vec<Band> {
    let mut out = Vec::new();
    for (k, o) in outages.iter().enumerate() {
        let Some(i) = rec.index_of(&o.series.name()) else {
            continue;
        };
        for [t0_s, t1_s] in intervals(rec, i, o.out_when) {
            out.push(Band { k, t0_s, t1_s });
        }
    }
    out
}

/// The intervals [t₀, t₁] where series `index` equals `out_when`, from its plotted points.
pub fn intervals(rec: &Recorder, index: usize, out_when: f64) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    let mut start: Option<f64> = None;
    let mut last_t = 0.0;
    for p in rec.plot_points(index, POINTS) {
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

/// Shades every band (unnamed: [`label`] names them once the plot is laid out).
pub fn shade(plot: &mut PlotUi<'_>, bands: &[Band], colours: &Palette) {
    for b in bands {
        plot.span(
            Span::new("", b.t0_s..=b.t1_s)
                .fill(color(colours, b.k))
                .border_width(0.0),
        );
    }
}

/// Writes each band's words (`words[k]`, the catalogue's) at its top, cut to its width with
/// "…", over a backing of the panel's colour.
pub fn label(ui: &Ui, transform: &PlotTransform, bands: &[Band], words: &[String]) {
    let frame = *transform.frame();
    let painter = ui.painter_at(frame);
    let font = egui::TextStyle::Body.resolve(ui.style());
    let text_color = ui.visuals().text_color();
    let backing = ui.visuals().panel_fill.gamma_multiply(BACKING_OPACITY);
    for b in bands {
        let Some(text) = words.get(b.k) else { continue };
        let x0 = transform.position_from_point_x(b.t0_s).max(frame.left());
        let x1 = transform.position_from_point_x(b.t1_s).min(frame.right());
        let width = x1 - x0 - 2.0 * PADDING;
        // A label cut to a few letters ("sta…", "no…" on a phone's first tenth of a
        // second) says nothing the legend does not: none unless its first eight characters
        // fit (or the whole of a shorter one).
        let head: String = text.chars().take(LEAST_CHARS).collect();
        let least = painter
            .layout_no_wrap(format!("{head}…"), font.clone(), text_color)
            .size()
            .x;
        if width < least.max(MIN_LABEL_WIDTH) {
            continue;
        }
        let galley = super::one_line(&painter, text, font.clone(), text_color, width);
        let at = egui::pos2(
            0.5 * (x0 + x1) - 0.5 * galley.size().x,
            frame.top() + PADDING,
        );
        let behind = egui::Rect::from_min_size(at, galley.size()).expand(2.0);
        painter.rect_filled(behind, 3.0, backing);
        painter.galley(at, galley, text_color);
    }
}

/// Shading colour of outage `k`.
pub fn color(colours: &Palette, k: usize) -> Color32 {
    colours.outages[k % colours.outages.len()]
}
