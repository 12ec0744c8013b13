//! The lab's sweeps: run/cancel with a progress bar (computed a slice per frame), then the
//! result as a plot and a table — RMS against the swept value; the lab's scores with each
//! objective's curve and argmin (paper 4's J(γ)); or, for a two-parameter grid, a heat map
//! with the lab's lines over it and the optimum marked (paper 4's Q landscape).

use crate::state::{AppState, Command, RunCommand};
use attlab::analysis::sweep::{Sweep, SweepPoint};
use attlab::model::{SweepSpec, fmt_sig};
use egui::{Color32, RichText, Ui};
use egui_plot::{Heatmap, Legend, Line, Plot, PlotPoint, Points, Text};

/// The lab's sweeps.
pub fn sweeps(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    for (i, spec) in app.sim().lab().sweeps().iter().enumerate() {
        egui::CollapsingHeader::new(format!("Sweep: {}", spec.title))
            .default_open(true)
            .show(ui, |ui| {
                let running = app
                    .run()
                    .sweep
                    .as_ref()
                    .filter(|(j, _)| *j == i)
                    .map(|(_, s)| s);
                controls(ui, app, spec, i, running, commands);
                let Some(s) = running else { return };
                problems(ui, s);
                match (spec.grid, s.scoring()) {
                    (Some(_), Some(_)) => heat_map(ui, app, s, i),
                    (None, Some(_)) => {
                        objective_plot(ui, s, i);
                        score_table(ui, s, i);
                    }
                    _ => rms_plot(ui, s, i),
                }
            });
    }
}

fn controls(
    ui: &mut Ui,
    app: &AppState,
    spec: &SweepSpec,
    i: usize,
    running: Option<&Sweep>,
    commands: &mut Vec<Command>,
) {
    let on_log = app.sim().replay_log().is_some() && spec.log_scoring.is_some();
    match running {
        Some(s) if !s.is_done() => {
            ui.horizontal(|ui| {
                ui.add(
                    egui::ProgressBar::new(s.progress() as f32)
                        .show_percentage()
                        .desired_width(180.0),
                );
                if ui.button("Cancel").clicked() {
                    commands.push(Command::from(RunCommand::CancelSweep));
                }
            });
        }
        _ => {
            let (label, hover) = if on_log {
                (
                    "Run sweep on the log",
                    "One run per value over the replayed log (no truth: the log's own scores)",
                )
            } else {
                (
                    "Run sweep",
                    "One run per value and seed with the current parameters; the page stays live",
                )
            };
            if ui.button(label).on_hover_text(hover).clicked() {
                commands.push(Command::from(RunCommand::RunSweep(i)));
            }
        }
    }
    let cells = spec.values.len() * spec.grid.map_or(1, |g| g.values.len());
    let seeds = if on_log { 1 } else { spec.seeds.max(1) };
    ui.label(
        RichText::new(format!(
            "{cells} {} × {seeds} seed{} · {}",
            if spec.grid.is_some() {
                "cells"
            } else {
                "values"
            },
            if seeds == 1 { "" } else { "s" },
            if on_log {
                "on the replayed log".to_string()
            } else {
                format!("{:.0} s each", spec.duration_s)
            },
        ))
        .small(),
    );
    if let Some(s) = running.and_then(|s| s.scoring()) {
        ui.label(RichText::new(s.help).small().weak());
    }
}

fn problems(ui: &mut Ui, s: &Sweep) {
    let spec = s.spec();
    for p in s.points.iter().filter(|p| p.missing.iter().any(|m| *m > 0)) {
        ui.colored_label(
            crate::render::palette::of(ui.visuals()).error,
            format!("{}: a filter diverged (missing samples)", at(spec, p)),
        );
    }
    for p in s.points.iter().filter(|p| !p.unscored.is_empty()) {
        ui.colored_label(
            crate::render::palette::of(ui.visuals()).error,
            format!("{}: not scored: {}", at(spec, p), p.unscored.join("; ")),
        );
    }
    for reason in &s.skipped {
        ui.colored_label(
            crate::render::palette::of(ui.visuals()).error,
            format!("skipped {reason}"),
        );
    }
}

/// "key = value" (and the grid's) of a point.
fn at(spec: &SweepSpec, p: &SweepPoint) -> String {
    match (spec.grid, p.grid_value) {
        (Some(g), Some(v)) => format!(
            "{} = {}, {} = {}",
            spec.key,
            fmt_sig(p.value),
            g.key,
            fmt_sig(v)
        ),
        _ => format!("{} = {}", spec.key, fmt_sig(p.value)),
    }
}

fn log_points(s: &Sweep, f: impl Fn(&SweepPoint) -> f64) -> Vec<[f64; 2]> {
    s.points
        .iter()
        .filter(|p| p.value > 0.0)
        .map(|p| [p.value.log10(), f(p)])
        .filter(|q| q[1].is_finite())
        .collect()
}

/// RMS (largest |value|) of each series against log10 of the value.
fn rms_plot(ui: &mut Ui, s: &Sweep, i: usize) {
    let colours = crate::render::palette::of(ui.visuals());
    let spec = s.spec();
    for k in 0..spec.series.len() {
        if let Some((value, rms)) = s.best(k) {
            ui.label(format!(
                "best for {}: {} = {value} ({rms:.4} rms)",
                s.legend(k),
                spec.key
            ));
        }
    }
    Plot::new(("sweep", i))
        .height(170.0)
        .legend(Legend::default().text_style(egui::TextStyle::Small))
        .x_axis_label(format!("log10 {}", spec.key))
        .y_axis_label("log10 max |value|")
        .show(ui, |plot| {
            for k in 0..spec.series.len() {
                let pts = log_points(s, |p| p.max_abs[k].log10());
                let color = colours.source(k + 1);
                let legend = s.legend(k);
                plot.line(Line::new(legend.clone(), pts.clone()).color(color));
                plot.points(Points::new(legend, pts).radius(3.0).color(color));
            }
        });
}

/// Each objective against log10 of the value, its argmin ringed.
fn objective_plot(ui: &mut Ui, s: &Sweep, i: usize) {
    let colours = crate::render::palette::of(ui.visuals());
    let Some(scoring) = s.scoring() else { return };
    let spec = s.spec();
    Plot::new(("sweep_objectives", i))
        .height(190.0)
        .legend(Legend::default().text_style(egui::TextStyle::Small))
        .x_axis_label(format!("log10 {}", spec.key))
        .y_axis_label("objective")
        .show(ui, |plot| {
            for (k, (name, _)) in scoring.objectives.iter().enumerate() {
                let color = colours.source(k + 1);
                let pts = log_points(s, |p| p.objectives[k]);
                plot.line(Line::new(*name, pts.clone()).color(color));
                plot.points(Points::new(*name, pts).radius(2.5).color(color));
                if let Some(best) = s.argmin(k).filter(|p| p.value > 0.0) {
                    let xy = [best.value.log10(), best.objectives[k]];
                    plot.points(
                        Points::new(format!("argmin {name}"), vec![xy])
                            .radius(7.0)
                            .filled(false)
                            .color(color),
                    );
                }
            }
        });
}

/// One row per value: the median scores (with their range over the seeds) and objectives;
/// each objective's argmin in bold.
fn score_table(ui: &mut Ui, s: &Sweep, i: usize) {
    let colours = crate::render::palette::of(ui.visuals());
    let Some(scoring) = s.scoring() else { return };
    let spec = s.spec();
    for (k, (name, _)) in scoring.objectives.iter().enumerate() {
        if let Some(best) = s.argmin(k) {
            ui.label(
                RichText::new(format!(
                    "argmin of {name}: {} = {}",
                    spec.key,
                    fmt_sig(best.value)
                ))
                .strong(),
            );
        }
    }
    let cell = |x: f64| {
        if x.is_finite() {
            fmt_sig(x)
        } else {
            "—".into()
        }
    };
    egui::ScrollArea::horizontal()
        .id_salt(("sweep_table_scroll", i))
        .show(ui, |ui| {
            egui::Grid::new(("sweep_table", i))
                .striped(true)
                .show(ui, |ui| {
                    ui.label(RichText::new(spec.key).small().strong());
                    for n in scoring.names {
                        ui.label(RichText::new(*n).small().strong());
                    }
                    for (n, _) in scoring.objectives {
                        ui.label(RichText::new(*n).small().strong());
                    }
                    ui.end_row();
                    for p in &s.points {
                        ui.label(RichText::new(fmt_sig(p.value)).small().monospace());
                        for (v, r) in p.scores.iter().zip(&p.score_range) {
                            let text = if p.runs > 1 && r[0].is_finite() {
                                format!("{} [{}–{}]", cell(*v), cell(r[0]), cell(r[1]))
                            } else {
                                cell(*v)
                            };
                            ui.label(RichText::new(text).small().monospace());
                        }
                        for (k, j) in p.objectives.iter().enumerate() {
                            let best = s.argmin(k).is_some_and(|b| std::ptr::eq(b, p));
                            let text = RichText::new(cell(*j)).small().monospace();
                            ui.label(if best {
                                text.strong().color(colours.source(k + 1))
                            } else {
                                text
                            });
                        }
                        ui.end_row();
                    }
                });
        });
}

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
fn heat_map(ui: &mut Ui, app: &AppState, s: &Sweep, i: usize) {
    let colours = crate::render::palette::of(ui.visuals());
    let (Some(scoring), Some(axis)) = (s.scoring(), s.spec().grid) else {
        return;
    };
    let spec = s.spec();
    let (xs, ys) = (s.values(), axis.values);
    if xs.len() < 2 || ys.len() < 2 || xs.iter().chain(ys).any(|v| *v <= 0.0) {
        ui.label("A heat map needs at least two positive values on each axis.");
        return;
    }
    let grid = LogGrid::new(xs, ys);
    let values = grid_values(s, xs.len(), ys.len());
    let finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let span = if hi > lo { hi - lo } else { 1.0 };
    let name = scoring.objectives.first().map_or("objective", |o| o.0);
    let best = s.argmin(0);
    ui.label(
        RichText::new(match best {
            Some(b) => format!(
                "colour: log10 {name}, from {} (dark) to {} (bright). Optimum: {} ({name} = {}).",
                fmt_sig(lo),
                fmt_sig(hi),
                at(spec, b),
                fmt_sig(b.objectives[0])
            ),
            None => format!("colour: log10 {name}; cells fill in as the sweep runs."),
        })
        .small(),
    );
    let heat = Heatmap::new(values, xs.len())
        .at(PlotPoint::new(grid.x0, grid.y0))
        .tile_size(grid.dx as f32, grid.dy as f32)
        .show_labels(false)
        .custom_mapping(Box::new(move |v| palette((v - lo) / span)));
    let lines = scoring
        .overlay
        .map_or_else(Vec::new, |f| f(app.sim().params()));
    Plot::new(("sweep_heat", i))
        .height(260.0)
        .legend(Legend::default().text_style(egui::TextStyle::Small))
        .x_axis_label(format!("log10 {}", spec.key))
        .y_axis_label(format!("log10 {}", axis.key))
        .include_x(grid.x0)
        .include_x(grid.x1)
        .include_y(grid.y0)
        .include_y(grid.y1)
        .show(ui, |plot| {
            plot.add(heat);
            for (k, (label, pts)) in lines.iter().enumerate() {
                plot.line(
                    Line::new(label.clone(), grid.clip(pts))
                        .color(colours.source(k + 1))
                        .width(2.0),
                );
            }
            if let Some((b, g)) = best.and_then(|b| b.grid_value.map(|g| (b, g))) {
                mark_optimum(plot, [b.value.log10(), g.log10()], grid.dy);
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
fn mark_optimum(plot: &mut egui_plot::PlotUi<'_>, xy: [f64; 2], dy: f64) {
    plot.points(
        Points::new("optimum", vec![xy])
            .radius(8.0)
            .filled(false)
            .color(Color32::WHITE),
    );
    plot.text(
        Text::new("", PlotPoint::new(xy[0], xy[1] + dy * 0.6), "optimum").color(Color32::WHITE),
    );
}
