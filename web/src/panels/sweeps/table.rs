//! A sweep's scores as tables that fit the panel: one of the scores and one of the
//! objectives, each row a swept value, each cell the median over the seeds with its range
//! on hover, the headers wrapped to the column (paper 4's eight columns with their ranges
//! had run 700 points wide, past a 300-point panel's edge).

use super::words::Words;
use super::{num_arg, tr_with};
use crate::state::AppState;
use attlab::analysis::sweep::{Sweep, SweepPoint};
use attlab::i18n;
use attlab::model::fmt_sig;
use egui::{Color32, RichText, Ui};

/// A header's widest line (points): a name wraps to it.
const HEADER_WIDTH: f32 = 64.0;

/// One cell: its text, what hovering it says, and its colour when it is an argmin.
struct Cell {
    text: String,
    hover: Option<String>,
    best: Option<Color32>,
}

/// The scores' table, then the objectives' (each objective's argmin in its colour).
pub(super) fn score_table(ui: &mut Ui, app: &AppState, s: &Sweep, i: usize) {
    let Some(scoring) = s.scoring() else { return };
    let w = Words::of(app, s);
    let param = w.param(s.spec().key);
    let colours = crate::render::palette::of(ui.visuals());
    let lang = app.view().lang();
    let number = |x: f64| {
        if x.is_finite() {
            i18n::number(lang, &fmt_sig(x))
        } else {
            "—".into()
        }
    };
    let value = |p: &SweepPoint| Cell {
        text: number(p.value),
        hover: None,
        best: None,
    };
    let mut header = vec![param.clone()];
    header.extend(scoring.names.iter().enumerate().map(|(j, n)| w.score(j, n)));
    let rows = s.points.iter().map(|p| {
        let mut row = vec![value(p)];
        row.extend(p.scores.iter().zip(&p.score_range).map(|(v, r)| {
            let hover = (p.runs > 1 && r[0].is_finite()).then(|| {
                let args = [
                    ("value", num_arg(app, number(*v))),
                    ("n", num_arg(app, p.runs.to_string())),
                    ("lo", num_arg(app, number(r[0]))),
                    ("hi", num_arg(app, number(r[1]))),
                ];
                tr_with(app, "sweep-cell-range", &args)
            });
            Cell {
                text: number(*v),
                hover,
                best: None,
            }
        }));
        row
    });
    grid(ui, ("sweep_scores", i), &header, rows.collect());
    let mut header = vec![param];
    header.extend(
        scoring
            .objectives
            .iter()
            .enumerate()
            .map(|(j, (n, _))| w.objective(j, n)),
    );
    let rows = s.points.iter().map(|p| {
        let mut row = vec![value(p)];
        row.extend(p.objectives.iter().enumerate().map(|(k, j)| {
            Cell {
                text: number(*j),
                hover: None,
                best: s
                    .argmin(k)
                    .is_some_and(|b| std::ptr::eq(b, p))
                    .then(|| colours.source(k + 1)),
            }
        }));
        row
    });
    ui.add_space(6.0);
    grid(ui, ("sweep_objectives_table", i), &header, rows.collect());
}

/// A striped grid of `rows` under `header`, scrolled sideways (with its bar shown) only
/// where even wrapped headers do not fit.
fn grid(ui: &mut Ui, id: (&str, usize), header: &[String], rows: Vec<Vec<Cell>>) {
    egui::ScrollArea::horizontal()
        .id_salt(("scroll", id))
        .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::VisibleWhenNeeded)
        .show(ui, |ui| {
            egui::Grid::new(id).striped(true).show(ui, |ui| {
                for name in header {
                    ui.scope(|ui| {
                        ui.set_max_width(HEADER_WIDTH);
                        ui.add(egui::Label::new(RichText::new(name).small().strong()).wrap());
                    });
                }
                ui.end_row();
                for row in rows {
                    for cell in row {
                        let text = RichText::new(cell.text).small().monospace();
                        let text = match cell.best {
                            Some(c) => text.strong().color(c),
                            None => text,
                        };
                        let label = ui.label(text);
                        if let Some(h) = cell.hover {
                            label.on_hover_text(h);
                        }
                    }
                    ui.end_row();
                }
            });
        });
}
