//! The filter's cycle, step by step: one predict/update cycle of a small Kalman filter as
//! its equations with the filter's own numbers at this sample (paper 1's and paper 4's
//! two- and three-state filters). Pause and press s (or the button) to advance one sample;
//! the terms the lesson step talks about are highlighted.

use super::{arg, estimator_name, num_arg, tr, tr_with};
use crate::state::{AppState, Command, RunCommand, ViewCommand};
use attlab::i18n::Lang;
use attlab::model::{KalmanCycle, StateMatrix};
use attlab::page::CycleTerm;
use egui::{RichText, Ui};

/// The panel, while it is open and the run has a filter that keeps its cycle.
pub fn cycle_panel(ctx: &egui::Context, app: &AppState, commands: &mut Vec<Command>) {
    if !app.view().cycle_open {
        return;
    }
    let Some((index, cycle)) = shown_filter(app) else {
        return;
    };
    let mut open = true;
    egui::Window::new(tr(app, "cycle-title"))
        .open(&mut open)
        .default_width(360.0)
        .collapsible(true)
        .anchor(egui::Align2::RIGHT_BOTTOM, egui::vec2(-12.0, -40.0))
        .show(ctx, |ui| {
            // Small type: the window sits over the plots and carries a dozen rows.
            ui.style_mut().override_text_style = Some(egui::TextStyle::Small);
            ui.label(RichText::new(estimator_name(app, index)).strong());
            ui.label(tr_with(
                app,
                "cycle-at",
                &[
                    ("t", num_arg(app, format!("{:.3}", app.shown().t_s()))),
                    ("k", arg(app.shown().steps())),
                ],
            ));
            ui.horizontal(|ui| {
                if ui.button(tr(app, "cycle-step")).clicked() {
                    if app.run().playing {
                        commands.push(RunCommand::SetPlaying(false).into());
                    }
                    commands.push(RunCommand::StepOnce.into());
                }
                if app.run().playing && ui.button(tr(app, "cycle-pause")).clicked() {
                    commands.push(RunCommand::SetPlaying(false).into());
                }
            });
            let terms = app.lesson_step().map_or(&[][..], |s| s.terms);
            equations(ui, app, cycle, terms);
        });
    if !open {
        commands.push(ViewCommand::SetCycle(false).into());
    }
}

/// The first shown filter that keeps its cycle: (its index, its cycle).
pub fn shown_filter(app: &AppState) -> Option<(usize, &KalmanCycle)> {
    app.shown()
        .estimators()
        .iter()
        .enumerate()
        .filter(|(i, _)| !app.view().hidden.contains(&(i + 1)))
        .find_map(|(i, e)| Some((i, e.teaching()?.cycle())))
}

/// A number as the panel prints it: four significant digits, in the reader's language
/// ("0,1234" in Russian).
pub fn num(lang: Lang, v: f64) -> String {
    let text = if v == 0.0 {
        "0".into()
    } else if (1e-3..1e4).contains(&v.abs()) {
        format!("{v:.4}")
    } else {
        format!("{v:.3e}")
    };
    attlab::i18n::number(lang, &text)
}

/// What separates two numbers of a matrix's row: a comma, or where the comma is the decimal
/// separator (Russian), a wide space (the rows are separated by semicolons).
fn in_row(lang: Lang) -> &'static str {
    match lang {
        Lang::En => ", ",
        Lang::Ru => "\u{2003}",
    }
}

/// `[a, b, c]` of the first `n` entries (`[a; b; c]` in Russian).
pub fn vector(lang: Lang, v: &[f64], n: usize) -> String {
    let parts: Vec<String> = v.iter().take(n).map(|x| num(lang, *x)).collect();
    format!("[{}]", parts.join(attlab::i18n::list_separator(lang)))
}

/// `[a, b; c, d]` of the top-left `rows` × `cols` (`[a  b; c  d]` in Russian).
pub fn matrix<const C: usize>(lang: Lang, m: &[[f64; C]], rows: usize, cols: usize) -> String {
    let rows: Vec<String> = m
        .iter()
        .take(rows)
        .map(|r| {
            r.iter()
                .take(cols)
                .map(|x| num(lang, *x))
                .collect::<Vec<_>>()
                .join(in_row(lang))
        })
        .collect();
    format!("[{}]", rows.join("; "))
}

fn square(lang: Lang, m: &StateMatrix, n: usize) -> String {
    matrix(lang, m, n, n)
}

/// The equations with their numbers, one per row.
fn equations(ui: &mut Ui, app: &AppState, c: &KalmanCycle, terms: &[CycleTerm]) {
    let names: Vec<String> = c
        .states
        .iter()
        .map(|s| {
            format!(
                "{} ({})",
                s.key,
                attlab::i18n::unit(app.view().lang(), s.unit)
            )
        })
        .collect();
    ui.label(
        RichText::new(tr_with(
            app,
            "cycle-states",
            &[("names", arg(names.join(", ")))],
        ))
        .small(),
    );
    let rows = rows(app.view().lang(), c);
    let accent = ui.visuals().selection.stroke.color;
    let small = ui.style().text_styles[&egui::TextStyle::Small].size;
    egui::Grid::new("cycle_rows")
        .num_columns(2)
        .striped(true)
        .show(ui, |ui| {
            for (term, lhs, value) in rows {
                let lit = term.is_some_and(|t| terms.contains(&t));
                let lhs = if lit {
                    RichText::new(lhs).strong().color(accent)
                } else {
                    RichText::new(lhs)
                };
                ui.label(lhs);
                ui.label(RichText::new(value).monospace().size(small));
                ui.end_row();
            }
        });
    if c.update.is_none() {
        ui.label(RichText::new(tr(app, "cycle-no-update")).weak());
    }
    // The one note a filter gives today is the adaptation window's (paper 1).
    if c.note.is_some() {
        ui.label(RichText::new(tr(app, "cycle-note-window")).weak());
    }
}

/// A row of the panel: the term it shows (for the highlight), the equation, its numbers.
type Row = (Option<CycleTerm>, &'static str, String);

/// The rows of the cycle: the prediction, then the update when a measurement came.
fn rows(lang: Lang, c: &KalmanCycle) -> Vec<Row> {
    let n = c.n();
    let mut rows: Vec<Row> = vec![
        (None, "x̂ =", vector(lang, &c.x_before, n)),
        (None, "Φ =", square(lang, &c.phi, n)),
        (Some(CycleTerm::ProcessNoise), "Q =", square(lang, &c.q, n)),
        (
            Some(CycleTerm::PriorState),
            "x̂⁻ = Φx̂ =",
            vector(lang, &c.x_prior, n),
        ),
        (
            Some(CycleTerm::PriorCovariance),
            "P⁻ = ΦPΦᵀ + Q =",
            square(lang, &c.p_prior, n),
        ),
    ];
    if let Some(u) = &c.update {
        let m = u.m;
        rows.extend([
            (None, "z =", vector(lang, &u.z, m)),
            (None, "H =", matrix(lang, &u.h, m, n)),
            (
                Some(CycleTerm::MeasurementNoise),
                "R =",
                matrix(lang, &u.r, m, m),
            ),
            (
                Some(CycleTerm::Innovation),
                "z − Hx̂⁻ =",
                vector(lang, &u.residual, m),
            ),
            (
                Some(CycleTerm::Innovation),
                "S = HP⁻Hᵀ + R =",
                matrix(lang, &u.s, m, m),
            ),
            (
                Some(CycleTerm::Gain),
                "K = P⁻HᵀS⁻¹ =",
                matrix(lang, &u.k, n, m),
            ),
            (
                Some(CycleTerm::PosteriorState),
                "x̂⁺ = x̂⁻ + K(z − Hx̂⁻) =",
                vector(lang, &u.x_post, n),
            ),
            (
                Some(CycleTerm::PosteriorCovariance),
                "P⁺ = (I − KH)P⁻(I − KH)ᵀ + KRKᵀ =",
                square(lang, &u.p_post, n),
            ),
        ]);
    }
    rows
}
