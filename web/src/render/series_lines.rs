//! How one series of a plot is drawn: its pieces (broken at gaps, cut to the view where
//! that keeps them short, thinned to the pixels), its ±3σ band, and whether it is dense
//! enough for [`super::dense`] to paint it instead.

use attlab::i18n::LegendParts;
use attlab::model::SeriesSpec;
use attlab::record::Recorder;
use egui::Color32;
use egui_plot::{Line, LineStyle};

/// How one series is drawn.
#[derive(Clone, Copy)]
pub(super) struct LineLook {
    pub(super) color: Color32,
    pub(super) width: f32,
    /// The source's line pattern.
    pub(super) pattern: LineStyle,
    /// The marker along the line where colour and pattern do not tell it apart.
    pub(super) marker: Option<egui_plot::MarkerShape>,
    /// log10 of the values.
    pub(super) log: bool,
    /// ±3σ bands where the series has one.
    pub(super) bands: bool,
}

/// Series `i` from its plot points, broken at its missing samples, with its ±3σ band from
/// the variance series it names (never from its name). A solid line that zigzags within
/// each pixel is left for [`super::dense`] to paint over the plot: its pieces are returned
/// (the plot gets a line through its extremes, so its bounds still follow it).
pub(super) fn draw_series(
    plot: &mut egui_plot::PlotUi<'_>,
    rec: &Recorder,
    (i, mut pts): (usize, Vec<[f64; 2]>),
    look: LineLook,
    legend: &dyn Fn(&SeriesSpec) -> LegendParts,
) -> Option<Vec<Vec<[f64; 2]>>> {
    let spec = &rec.specs()[i];
    let mut label = legend(spec).joined();
    if look.log {
        for p in &mut pts {
            p[1] = if p[1] > 0.0 { p[1].log10() } else { f64::NAN };
        }
        label = format!("log10 {label}");
    }
    // An angle wraps at ±180°: break the line there rather than cross the plot.
    if spec.unit == "deg" && !look.log {
        pts = super::clip::break_at_wraps(pts);
    }
    let px = plot.transform().dvalue_dpos().map(f64::abs);
    let pieces = pieces(plot, &pts, look.pattern);
    let dense = look.pattern == LineStyle::Solid && super::dense::is_dense(&pts, px);
    for piece in &pieces {
        let line = if dense {
            extremes(piece)
        } else {
            piece.clone()
        };
        let width = if dense { 0.0 } else { look.width };
        plot.line(
            Line::new(label.clone(), line)
                .color(look.color)
                .width(width)
                .style(look.pattern),
        );
    }
    if let Some(shape) = look.marker {
        let px = plot.transform().dvalue_dpos()[0].abs();
        let along = markers_along(&pts, MARKER_EVERY_PX * px);
        let points = egui_plot::Points::new(label.clone(), along)
            .shape(shape)
            .radius(MARKER_RADIUS)
            .filled(true)
            .color(look.color);
        plot.points(points);
    }
    draw_band(plot, rec, (spec, pts.len()), look, legend);
    dense.then_some(pieces)
}

/// Pixels between two markers along a line.
const MARKER_EVERY_PX: f64 = 70.0;
/// A marker's radius (points).
pub(super) const MARKER_RADIUS: f32 = 3.5;

/// The first finite point of `pts` in each stretch `every` wide along x.
fn markers_along(pts: &[[f64; 2]], every: f64) -> Vec<[f64; 2]> {
    if !(every.is_finite() && every > 0.0) {
        return Vec::new();
    }
    let mut out: Vec<[f64; 2]> = Vec::new();
    for p in pts.iter().filter(|p| p[0].is_finite() && p[1].is_finite()) {
        if out.last().is_none_or(|last| p[0] - last[0] >= every) {
            out.push(*p);
        }
    }
    out
}

/// The first, lowest, highest and last points of `piece`: what a plot's bounds need of it.
fn extremes(piece: &[[f64; 2]]) -> Vec<[f64; 2]> {
    let by_y = |a: &&[f64; 2], b: &&[f64; 2]| a[1].total_cmp(&b[1]);
    let (lo, hi) = (piece.iter().min_by(by_y), piece.iter().max_by(by_y));
    [piece.first(), lo, hi, piece.last()]
        .into_iter()
        .flatten()
        .copied()
        .collect()
}

/// The ±3σ band of `spec` (`points` points) from the variance series it names.
fn draw_band(
    plot: &mut egui_plot::PlotUi<'_>,
    rec: &Recorder,
    (spec, points): (&SeriesSpec, usize),
    look: LineLook,
    legend: &dyn Fn(&SeriesSpec) -> LegendParts,
) {
    let band = spec.band.as_ref().filter(|_| look.bands && !look.log);
    let Some((var, scale)) = band.and_then(|(name, scale)| rec.index_of(name).map(|v| (v, *scale)))
    else {
        return;
    };
    // The band's greatest 3σ in each pixel column: between updates P grows and at each
    // update it drops, a sawtooth that, drawn whole at a steady part's scale, had shaded
    // the window four times over in vertical strokes.
    // Columns of a few pixels: a bucket's least and greatest P fall a pixel or two apart.
    let px = ENVELOPE_PX * plot.transform().dvalue_dpos()[0].abs();
    let sigma3: Vec<[f64; 2]> = (rec.plot_points(var, points.max(2)).into_iter())
        .map(|p| [p[0], 3.0 * p[1].max(0.0).sqrt() * scale])
        .collect();
    let sigma3 = super::clip::upper_envelope(&sigma3, px);
    let sigma3 =
        |sign: f64| -> Vec<[f64; 2]> { sigma3.iter().map(|p| [p[0], sign * p[1]]).collect() };
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
/// to what the plot shows (a solid one too where the value axis does not follow the data:
/// zoomed in, or a figure fitted to its steady part, whose transient had been drawn in full
/// hundreds of plot heights tall), and each thinned to the plot's pixels (see
/// [`super::clip`]).
pub fn pieces(
    plot: &egui_plot::PlotUi<'_>,
    pts: &[[f64; 2]],
    style: LineStyle,
) -> Vec<Vec<[f64; 2]>> {
    let pieces = if style == LineStyle::Solid && plot.auto_bounds().y {
        Recorder::split_at_gaps(pts)
    } else {
        super::clip::clip_to_bounds(pts, &plot.plot_bounds())
    };
    let px = plot.transform().dvalue_dpos().map(f64::abs);
    let thin = |piece| super::clip::thin_to_pixels(piece, px);
    pieces.into_iter().map(thin).collect()
}

/// The width of a band's envelope columns (pixels).
const ENVELOPE_PX: f64 = 4.0;
