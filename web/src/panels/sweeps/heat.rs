//! A grid sweep's first objective as a heat map over log10 of both parameters, with the
//! lab's lines over it and the optimum ringed (paper 4's Q landscape).

use super::super::{arg, num_arg, tr, tr_with};
use super::Words;
use crate::state::AppState;
use attlab::analysis::sweep::Sweep;
use attlab::model::fmt_sig;
use egui::{Color32, RichText, Ui};
use egui_plot::{Heatmap, Legend, Line, Plot, PlotPoint, Points, Text};

/// A colour for `x` in 0…1 (dark blue → teal → yellow), grey for NaN.
fn palette(x: f64) -> Color32 {
    const STOPS: [[f32; 3]; 5] = [
        [40.0, 20.0, 90.0],
        [40.0, 90.0, 150.0],
        [30.0, 150.0, 140.0],
        [120.0, 200.0, 80.0],
        [250.0, 230.0, 40.0],
    ];
    if !x.is_finite() {
        return Color32::from_gray(60);
    }
    let t = x.clamp(0.0, 1.0) as f32 * (STOPS.len() - 1) as f32;
    let k = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - k as f32;
    let c = |i: usize| (STOPS[k][i] + f * (STOPS[k + 1][i] - STOPS[k][i])) as u8;
    Color32::from_rgb(c(0), c(1), c(2))
}

/// The grid's first objective as a heat map over log10 of both parameters, the lab's lines
/// over it and the optimum ringed.
pub(super) fn heat_map(ui: &mut Ui, app: &AppState, s: &Sweep, i: usize) {
    let colours = crate::render::palette::of(ui.visuals());
    let (Some(scoring), Some(axis)) = (s.scoring(), s.spec().grid) else {
        return;
    };
    let spec = s.spec();
    let w = Words::of(app, s);
    let (xs, ys) = (s.values(), axis.values);
    if xs.len() < 2 || ys.len() < 2 || xs.iter().chain(ys).any(|v| *v <= 0.0) {
        ui.label(tr(app, "sweep-heat-needs"));
        return;
    }
    let grid = LogGrid::new(xs, ys);
    let values = grid_values(s, xs.len(), ys.len());
    let finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let span = if hi > lo { hi - lo } else { 1.0 };
    let name = scoring
        .objectives
        .first()
        .map_or_else(|| tr(app, "sweep-objective-axis"), |o| w.objective(0, o.0));
    let best = s.argmin(0);
    let text = match best {
        Some(b) => tr_with(
            app,
            "sweep-heat-colour",
            &[
                ("name", arg(&name)),
                ("lo", num_arg(app, fmt_sig(lo))),
                ("hi", num_arg(app, fmt_sig(hi))),
                ("at", arg(w.at(spec, b))),
                ("best", num_arg(app, fmt_sig(b.objectives[0]))),
            ],
        ),
        None => tr_with(app, "sweep-heat-filling", &[("name", arg(&name))]),
    };
    ui.label(RichText::new(text).small());
    let heat = Heatmap::new(values, xs.len())
        .at(PlotPoint::new(grid.x0, grid.y0))
        .tile_size(grid.dx as f32, grid.dy as f32)
        .show_labels(false)
        .custom_mapping(Box::new(move |v| palette((v - lo) / span)));
    let lines = scoring
        .overlay
        .map_or_else(Vec::new, |f| f(app.sim().params()));
    crate::render::ticks::in_language(Plot::new(("sweep_heat", i)), app.view().lang())
        // The wheel scrolls the panel; it had panned a plot that passed under the pointer.
        .allow_scroll(false)
        .height(260.0)
        .legend(Legend::default().text_style(egui::TextStyle::Small))
        .x_axis_label(w.log_axis(spec.key))
        .y_axis_label(w.log_axis(axis.key))
        .include_x(grid.x0)
        .include_x(grid.x1)
        .include_y(grid.y0)
        .include_y(grid.y1)
        .show(ui, |plot| {
            plot.add(heat);
            for (k, (label, pts)) in lines.iter().enumerate() {
                plot.line(
                    Line::new(w.overlay(k, label), grid.clip(pts))
                        .color(colours.source(k + 1))
                        .width(2.0),
                );
            }
            if let Some((b, g)) = best.and_then(|b| b.grid_value.map(|g| (b, g))) {
                let optimum = tr(app, "sweep-optimum");
                mark_optimum(plot, [b.value.log10(), g.log10()], grid.dy, &optimum);
            }
        });
}

/// A heat map's cells in log10 coordinates: their size and the map's edges.
struct LogGrid {
    dx: f64,
    dy: f64,
    x0: f64,
    x1: f64,
    y0: f64,
    y1: f64,
}

impl LogGrid {
    /// Cells centred on log10 of `xs` and `ys` (positive, at least two each).
    fn new(xs: &[f64], ys: &[f64]) -> Self {
        let log = |v: &[f64]| -> Vec<f64> { v.iter().map(|x| x.log10()).collect() };
        let (lx, ly) = (log(xs), log(ys));
        let dx = (lx[lx.len() - 1] - lx[0]) / (lx.len() - 1) as f64;
        let dy = (ly[ly.len() - 1] - ly[0]) / (ly.len() - 1) as f64;
        Self {
            dx,
            dy,
            x0: lx[0] - dx / 2.0,
            x1: lx[lx.len() - 1] + dx / 2.0,
            y0: ly[0] - dy / 2.0,
            y1: ly[ly.len() - 1] + dy / 2.0,
        }
    }

    /// `pts` in the map's log coordinates, clipped to it.
    fn clip(&self, pts: &[[f64; 2]]) -> Vec<[f64; 2]> {
        pts.iter()
            .filter(|p| p[0] > 0.0 && p[1] > 0.0)
            .map(|p| [p[0].log10(), p[1].log10()])
            .filter(|p| (self.x0..=self.x1).contains(&p[0]) && (self.y0..=self.y1).contains(&p[1]))
            .collect()
    }
}

/// log10 of the first objective per cell, row by row from the bottom (row = grid value,
/// column = first value); NaN where a cell is not run yet or not positive.
fn grid_values(s: &Sweep, columns: usize, rows: usize) -> Vec<f64> {
    let mut values = vec![f64::NAN; columns * rows];
    for (k, p) in s.points.iter().enumerate() {
        let (col, row) = (k / rows, k % rows);
        if let Some(j) = p.objectives.first().filter(|j| **j > 0.0) {
            values[row * columns + col] = j.log10();
        }
    }
    values
}

/// The optimum ringed and named on the map.
fn mark_optimum(plot: &mut egui_plot::PlotUi<'_>, xy: [f64; 2], dy: f64, name: &str) {
    plot.points(
        Points::new(name, vec![xy])
            .radius(8.0)
            .filled(false)
            .color(Color32::WHITE),
    );
    plot.text(Text::new("", PlotPoint::new(xy[0], xy[1] + dy * 0.6), name).color(Color32::WHITE));
}
