//! Lab tools shown only for labs that offer them: the live accuracy table, the lab's
//! diagrams and the laboratory mode that replays a recorded gyro or IMU log (the sweeps have
//! their own file).

use super::{arg, lab_word, tr, tr_with};
use crate::state::{AppState, Command, IoCommand, ViewCommand};
use attlab::i18n;
use attlab::sim::AccuracyRow;
use egui::Ui;
use egui_plot::{Line, Plot, Points};

/// The live accuracy table: each estimator's measured σ over the last window and its own
/// √max diag P beside the paper's numbers. Clicking a row shows that estimator as the ghost.
pub fn accuracy(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let colours = crate::render::palette::of(ui.visuals());
    let Some((title, window_s, rows)) = app.shown().accuracy() else {
        return;
    };
    let lang = app.view().lang();
    let cell = |x: f64| {
        if x.is_finite() {
            i18n::number(lang, &attlab::model::fmt_sig(x))
        } else {
            "—".into()
        }
    };
    let paper =
        |x: Option<f64>| x.map_or_else(|| "—".into(), |v| i18n::number(lang, &format!("{v:e}")));
    let title = lab_word(app, &i18n::accuracy_title_id(app.sim().lab().id()), title);
    super::fit::header(ui, title)
        .default_open(true)
        .show(ui, |ui| {
            let covered = app.shown().t_s().min(window_s);
            let help = tr_with(
                app,
                "accuracy-help",
                &[
                    ("covered", arg(format!("{covered:.0}"))),
                    ("window", arg(format!("{window_s:.0}"))),
                ],
            );
            ui.label(egui::RichText::new(help).small());
            let table = table_tabs(ui, app, &rows);
            egui::ScrollArea::horizontal().show(ui, |ui| {
                egui::Grid::new("accuracy_table")
                    .striped(true)
                    .num_columns(7)
                    .show(ui, |ui| {
                        header_row(ui, app);
                        for (i, r) in rows.iter().enumerate() {
                            if table.is_some() && r.paper_table != table {
                                continue;
                            }
                            let selected = app.view().ghost_index == i;
                            // Row i is estimator i (source i + 1): its colour, as in every plot.
                            ui.horizontal(|ui| {
                                ui.label(
                                    egui::RichText::new("●")
                                        .small()
                                        .color(colours.source(i + 1)),
                                );
                                let name = super::estimator_name(app, i);
                                if ui
                                    .selectable_label(selected, egui::RichText::new(name).small())
                                    .clicked()
                                {
                                    commands.push(Command::from(ViewCommand::SetGhost(i)));
                                }
                            });
                            for text in [
                                cell(r.att_sigma_deg),
                                cell(r.att_p_deg),
                                paper(r.paper[0]),
                                cell(r.rate_sigma_deg_s),
                                cell(r.rate_p_deg_s),
                                paper(r.paper[1]),
                            ] {
                                ui.label(egui::RichText::new(text).small().monospace());
                            }
                            ui.end_row();
                        }
                    });
            });
        });
}

/// The accuracy table's header.
fn header_row(ui: &mut Ui, app: &AppState) {
    for h in [
        "accuracy-filter",
        "accuracy-att",
        "accuracy-att-p",
        "accuracy-paper-att",
        "accuracy-rate",
        "accuracy-rate-p",
        "accuracy-paper-rate",
    ] {
        ui.label(egui::RichText::new(tr(app, h)).small().strong());
    }
    ui.end_row();
}

/// One tab per table of the paper the rows' values are from, and one for every row, when
/// the rows come from more than one table; returns the table shown (`None`: every row).
fn table_tabs(ui: &mut Ui, app: &AppState, rows: &[AccuracyRow]) -> Option<u8> {
    let mut tables: Vec<u8> = rows.iter().filter_map(|r| r.paper_table).collect();
    tables.sort_unstable();
    tables.dedup();
    if tables.len() < 2 {
        return None;
    }
    let id = egui::Id::unique(("accuracy_table_tab", app.sim().lab().id()));
    let mut shown: Option<u8> = ui.data(|d| d.get_temp(id)).unwrap_or(Some(tables[0]));
    ui.horizontal_wrapped(|ui| {
        for tab in tables.iter().map(|t| Some(*t)).chain([None]) {
            let name = match tab {
                Some(n) => tr_with(app, "accuracy-tab-table", &[("n", arg(n.to_string()))]),
                None => tr(app, "accuracy-tab-all"),
            };
            if ui.selectable_label(shown == tab, name).clicked() {
                shown = tab;
            }
        }
    });
    ui.data_mut(|d| d.insert_temp(id, shown));
    shown
}

/// One of the lab's diagrams (e.g. the eigenvalues of a linearised update on the unit
/// circle), filling `ui`, with its title above; a point of an estimator in its colour.
pub fn diagram(ui: &mut Ui, app: &AppState, d: &attlab::page::Diagram) {
    let colours = crate::render::palette::of(ui.visuals());
    ui.label(egui::RichText::new(diagram_heading(app, d)).small());
    // The legend goes below the diagram, so it covers no point.
    let row = ui.text_style_height(&egui::TextStyle::Small) + ui.spacing().item_spacing.y;
    let legend_h = row * (d.points.len() as f32 / 2.0).ceil().max(1.0);
    let height = (ui.available_height() - legend_h - 8.0).max(80.0);
    let shown = |source: Option<usize>| source.is_none_or(|s| !app.view().hidden.contains(&s));
    let source_of = |id: Option<&str>| {
        id.and_then(|id| app.sim().estimators().iter().position(|e| e.id() == id))
            .map(|i| i + 1)
    };
    crate::render::ticks::in_language(Plot::new(("diagram_plot", d.title)), app.view().lang())
        // The wheel scrolls the panel; it had panned a plot that passed under the pointer.
        .allow_scroll(false)
        .height(height)
        .data_aspect(1.0)
        .include_x(-1.2)
        .include_x(1.2)
        .include_y(-1.2)
        .include_y(1.2)
        .show(ui, |plot| {
            if d.unit_circle {
                let circle: Vec<[f64; 2]> = (0..=96)
                    .map(|k| {
                        let a = f64::from(k) * std::f64::consts::TAU / 96.0;
                        [a.cos(), a.sin()]
                    })
                    .collect();
                plot.line(Line::new("|λ| = 1", circle).color(colours.ink_dim));
            }
            for p in &d.points {
                // A point of an estimator takes its colour and hides with it.
                let source = source_of(p.source);
                if !shown(source) {
                    continue;
                }
                let color = source.map_or(colours.ink_dim, |s| colours.source(s));
                plot.points(
                    Points::new(p.label.clone(), vec![p.xy])
                        .radius(5.0)
                        .color(color),
                );
            }
        });
    ui.horizontal_wrapped(|ui| {
        for p in &d.points {
            let source = source_of(p.source);
            if shown(source) {
                let color = source.map_or(colours.ink_dim, |s| colours.source(s));
                ui.label(
                    egui::RichText::new(format!("● {}", p.label))
                        .small()
                        .color(color),
                );
            }
        }
    });
}

/// A diagram's title in the reader's language, with its detail in the paper's notation (its
/// numbers and units in the reader's words: "Δt = 1 с; ε = 0,1").
pub fn diagram_heading(app: &AppState, d: &attlab::page::Diagram) -> String {
    let title = lab_word(app, &i18n::diagram_id(app.sim().lab().id(), d.id), d.title);
    if d.detail.is_empty() {
        title
    } else {
        let detail = i18n::diagram_detail(app.view().lang(), &d.detail);
        format!("{title} ({detail})")
    }
}

/// The laboratory mode of a lab that reads a kind of recorded log: its unit choices (the
/// format's parameter specs, drawn like the lab's own), the file, the lab's example log,
/// and the way back to the simulation.
pub fn laboratory_mode(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let Some(format) = app.sim().lab().page().log_format else {
        return;
    };
    let lab = app.sim().lab().id();
    let word = |part: &str, english: &str| lab_word(app, &i18n::log_format_id(lab, part), english);
    super::fit::header(ui, word("title", format.title))
        .default_open(false)
        .show(ui, |ui| {
            ui.label(word("help", format.help));
            let units = app.io().units_for(format);
            // One under another: each takes the room its row has (`fit`), and in a wrapped
            // row the second was laid past the panel's edge.
            for spec in format.units {
                if let Some(v) =
                    super::param_widget::param_widget(ui, app, spec, units.get(spec.key))
                {
                    commands.push(Command::from(IoCommand::SetLogUnit(spec.key, v)));
                }
            }
            ui.horizontal_wrapped(|ui| {
                if ui.button(word("load", format.load_label)).clicked() {
                    commands.push(Command::from(IoCommand::LoadLog));
                }
                if let Some(example) = app.sim().lab().page().example_log
                    && ui
                        .button(tr(app, "replay-example"))
                        .on_hover_text(example.name)
                        .clicked()
                {
                    commands.push(Command::from(IoCommand::LoadExampleLog));
                }
                if let Some((name, n)) = &app.io().replaying {
                    ui.label(tr_with(
                        app,
                        "replaying",
                        &[("name", arg(name)), ("n", (*n).into())],
                    ));
                    if ui.button(tr(app, "back-to-simulation")).clicked() {
                        commands.push(Command::from(IoCommand::EndReplay));
                    }
                }
            });
            if format.id == attlab::sensors::IMU_LOG.id {
                commands.extend(super::live::live_sensors(ui, app));
            }
        });
}
