//! The lab's sweeps: run/cancel with a progress bar (computed a slice per frame), then the
//! result as a plot and a table — RMS against the swept value; the lab's scores with each
//! objective's curve and argmin (paper 4's J(γ)); or, for a two-parameter grid, a heat map
//! with the lab's lines over it and the optimum marked (paper 4's Q landscape).

mod heat;
mod table;
mod words;

use super::{arg, lab_word, num_arg, tr, tr_with};
use crate::state::{AppState, Command, RunCommand};
use attlab::analysis::sweep::{Sweep, SweepPoint};
use attlab::i18n;
use attlab::i18n::errors::Worded;
use attlab::model::SweepSpec;
use egui::{RichText, Ui};
use egui_plot::{Legend, Line, Plot, Points};
use heat::heat_map;
use table::score_table;
use words::Words;

/// The lab's sweeps.
pub fn sweeps(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    if !app.sim().lab().sweeps().is_empty() {
        // A sweep can be started from here: have workers loaded before it is. At most two
        // wait idle (each holds a wasm instance); a sweep starts the rest it may use.
        crate::sweep_workers::warm(crate::sweep_workers::cores().min(2));
    }
    for (i, spec) in app.sim().lab().sweeps().iter().enumerate() {
        let title = lab_word(
            app,
            &i18n::sweep_id(app.sim().lab().id(), spec.id, "title"),
            spec.title,
        );
        super::fit::header(ui, tr_with(app, "sweep-title", &[("title", arg(title))]))
            .default_open(true)
            .show(ui, |ui| body(ui, app, (spec, i), true, commands));
    }
}

/// A lesson step's sweep `i`, in the step's card: the button or the progress, then its
/// best values and its plot (the table is in the lab's sweeps below, on a wide screen). The
/// result had been 1 600 px down the panel, and nowhere in presenter mode.
pub fn in_lesson(ui: &mut Ui, app: &AppState, i: usize, commands: &mut Vec<Command>) {
    let Some(spec) = app.sim().lab().sweeps().get(i) else {
        return;
    };
    let title = lab_word(
        app,
        &i18n::sweep_id(app.sim().lab().id(), spec.id, "title"),
        spec.title,
    );
    ui.label(RichText::new(tr_with(app, "sweep-title", &[("title", arg(title))])).strong());
    body(ui, app, (spec, i), false, commands);
}

/// Sweep `i`'s controls and, once it runs, its problems and results; `table` adds the
/// table of every value's scores.
fn body(
    ui: &mut Ui,
    app: &AppState,
    (spec, i): (&SweepSpec, usize),
    table: bool,
    commands: &mut Vec<Command>,
) {
    let running = (app.run().sweep.as_ref())
        .filter(|(j, _)| *j == i)
        .map(|(_, s)| s);
    controls(ui, app, spec, i, running, commands);
    let Some(s) = running else { return };
    problems(ui, app, s);
    match (spec.grid, s.scoring()) {
        (Some(_), Some(_)) => heat_map(ui, app, s, i),
        (None, Some(_)) => {
            argmins(ui, app, s);
            objective_plot(ui, app, s, i);
            if table {
                score_table(ui, app, s, i);
            }
        }
        _ => rms_plot(ui, app, s, i),
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
                    egui::ProgressBar::new(
                        app.sweep_progress().unwrap_or_else(|| s.progress()) as f32
                    )
                    .show_percentage()
                    .desired_width(180.0),
                );
                let workers = app.run().sweep_timing.workers;
                if workers > 0 {
                    ui.label(tr_with(app, "sweep-workers", &[("n", workers.into())]));
                }
                if ui.button(tr(app, "cancel")).clicked() {
                    commands.push(Command::from(RunCommand::CancelSweep));
                }
            });
        }
        _ => {
            let (label, hover) = if on_log {
                ("sweep-run-log", "sweep-run-log-hint")
            } else {
                ("sweep-run", "sweep-run-hint")
            };
            if ui
                .button(tr(app, label))
                .on_hover_text(tr(app, hover))
                .clicked()
            {
                commands.push(Command::from(RunCommand::RunSweep(i)));
            }
        }
    }
    let cells = spec.values.len() * spec.grid.map_or(1, |g| g.values.len());
    let seeds = if on_log { 1 } else { spec.seeds.max(1) };
    let size = tr_with(
        app,
        if spec.grid.is_some() {
            "sweep-size-grid"
        } else {
            "sweep-size"
        },
        &[("cells", cells.into()), ("seeds", seeds.into())],
    );
    let each = if on_log {
        tr(app, "sweep-on-log")
    } else {
        tr_with(
            app,
            "sweep-each",
            &[("s", arg(format!("{:.0}", spec.duration_s)))],
        )
    };
    ui.label(RichText::new(format!("{size} · {each}")).small());
    if let Some(scoring) = running.and_then(|s| s.scoring()) {
        let part = if running.is_some_and(Sweep::is_on_log) {
            "log-help"
        } else {
            "help"
        };
        let help = lab_word(
            app,
            &i18n::sweep_id(app.sim().lab().id(), spec.id, part),
            scoring.help,
        );
        ui.label(RichText::new(help).small().weak());
    }
}

fn problems(ui: &mut Ui, app: &AppState, s: &Sweep) {
    let spec = s.spec();
    let w = Words::of(app, s);
    let error = crate::render::palette::of(ui.visuals()).error;
    for p in s.points.iter().filter(|p| p.missing.iter().any(|m| *m > 0)) {
        let at = arg(w.at(spec, p));
        ui.colored_label(error, tr_with(app, "sweep-diverged", &[("at", at)]));
    }
    let (lang, lab) = (app.view().lang(), app.sim().lab());
    for p in s.points.iter().filter(|p| !p.unscored.is_empty()) {
        let why: Vec<String> = p.unscored.iter().map(|u| u.words(lang, lab)).collect();
        let args = [("at", arg(w.at(spec, p))), ("why", arg(why.join("; ")))];
        ui.colored_label(error, tr_with(app, "sweep-unscored", &args));
    }
    for skipped in &s.skipped {
        let why = skipped.words(lang, lab);
        ui.colored_label(error, tr_with(app, "sweep-skipped", &[("why", arg(why))]));
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
fn rms_plot(ui: &mut Ui, app: &AppState, s: &Sweep, i: usize) {
    let colours = crate::render::palette::of(ui.visuals());
    let spec = s.spec();
    let w = Words::of(app, s);
    for k in 0..spec.series.len() {
        if let Some((value, rms)) = s.best(k) {
            let args = [
                ("series", arg(w.series(s, k))),
                ("param", arg(w.param(spec.key))),
                ("value", num_arg(app, value)),
                ("rms", num_arg(app, format!("{rms:.4}"))),
            ];
            ui.label(tr_with(app, "sweep-best", &args));
        }
    }
    crate::render::ticks::in_language(Plot::new(("sweep", i)), app.view().lang())
        // The wheel scrolls the panel; it had panned a plot that passed under the pointer.
        .allow_scroll(false)
        .height(170.0)
        .legend(Legend::default().text_style(egui::TextStyle::Small))
        .x_axis_label(w.log_axis(spec.key))
        .y_axis_label(tr(app, "sweep-max-axis"))
        .show(ui, |plot| {
            for k in 0..spec.series.len() {
                let pts = log_points(s, |p| p.max_abs[k].log10());
                let color = colours.source(k + 1);
                let legend = w.series(s, k);
                plot.line(Line::new(legend.clone(), pts.clone()).color(color));
                plot.points(Points::new(legend, pts).radius(3.0).color(color));
            }
        });
}

/// Each objective against log10 of the value, its argmin ringed.
fn objective_plot(ui: &mut Ui, app: &AppState, s: &Sweep, i: usize) {
    let colours = crate::render::palette::of(ui.visuals());
    let Some(scoring) = s.scoring() else { return };
    let spec = s.spec();
    let w = Words::of(app, s);
    crate::render::ticks::in_language(Plot::new(("sweep_objectives", i)), app.view().lang())
        // The wheel scrolls the panel; it had panned a plot that passed under the pointer.
        .allow_scroll(false)
        .height(190.0)
        .legend(Legend::default().text_style(egui::TextStyle::Small))
        .x_axis_label(w.log_axis(spec.key))
        .y_axis_label(tr(app, "sweep-objective-axis"))
        .show(ui, |plot| {
            for (k, (english, _)) in scoring.objectives.iter().enumerate() {
                let name = w.objective(k, english);
                let color = colours.source(k + 1);
                let pts = log_points(s, |p| p.objectives[k]);
                plot.line(Line::new(name.clone(), pts.clone()).color(color));
                plot.points(Points::new(name.clone(), pts).radius(2.5).color(color));
                if let Some(best) = s.argmin(k).filter(|p| p.value > 0.0) {
                    let xy = [best.value.log10(), best.objectives[k]];
                    plot.points(
                        Points::new(
                            tr_with(app, "sweep-argmin-marker", &[("name", arg(&name))]),
                            vec![xy],
                        )
                        .radius(7.0)
                        .filled(false)
                        .color(color),
                    );
                }
            }
        });
}

/// Each objective's least value over the points so far, in bold.
fn argmins(ui: &mut Ui, app: &AppState, s: &Sweep) {
    let Some(scoring) = s.scoring() else { return };
    let spec = s.spec();
    let w = Words::of(app, s);
    for (k, (english, _)) in scoring.objectives.iter().enumerate() {
        if let Some(best) = s.argmin(k) {
            let args = [
                ("name", arg(w.objective(k, english))),
                ("n", s.points.len().into()),
                ("at", arg(w.at(spec, best))),
            ];
            ui.label(RichText::new(tr_with(app, "sweep-argmin", &args)).strong());
        }
    }
}
