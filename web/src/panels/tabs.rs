//! Above the plot: one chip per estimator (hide or show it everywhere) and the plot tabs,
//! the paper's figures first and the rest behind a "More…" menu, with the tab's options.

use super::{arg, tr, tr_with};
use crate::render::plots;
use crate::state::{AppState, Command, ViewCommand};
use attlab::i18n;
use attlab::model::SeriesGroup;
use egui::Ui;

/// One chip per estimator in its colour: a click hides it (or shows it again) in every
/// view and plot. The chips take one row; those that do not fit are behind a menu.
pub(super) fn estimator_legend(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    // The filters a lesson step discusses first: a step about sets 5 and 10 of paper 2's
    // thirty had left their chips under "+25 more…". (Not the shown ones in general: a
    // chip would jump away from the pointer that hid it.)
    let discussed = app.lesson_step().map_or(&[][..], |s| s.show);
    let estimators = app.sim().estimators();
    let (first, rest): (Vec<usize>, Vec<usize>) =
        (0..estimators.len()).partition(|i| discussed.contains(&estimators[*i].id()));
    let order: Vec<usize> = first.into_iter().chain(rest).collect();
    let mut room = ui.available_width() - 160.0;
    let fits = (order.iter())
        .take_while(|i| {
            room -= tab_width(ui, &format!("● {}", super::estimator_short(app, **i))) * 0.9;
            room >= 0.0
        })
        .count();
    ui.horizontal(|ui| {
        ui.label(egui::RichText::new(tr(app, "estimators")).small());
        for i in &order[..fits] {
            estimator_chip(ui, app, *i, commands);
        }
        if fits < order.len() {
            let label = tr_with(
                app,
                "more-estimators",
                &[("n", (order.len() - fits).into())],
            );
            ui.menu_button(egui::RichText::new(label).small(), |ui| {
                for i in &order[fits..] {
                    estimator_chip(ui, app, *i, commands);
                }
            });
        }
    });
}

/// The chip of estimator `i`: its name (cut to fit; whole on hover, with its id) in its
/// colour, grey while hidden.
fn estimator_chip(ui: &mut Ui, app: &AppState, i: usize, commands: &mut Vec<Command>) {
    let colours = crate::render::palette::of(ui.visuals());
    let Some(e) = app.sim().estimators().get(i) else {
        return;
    };
    let name = super::estimator_name(app, i);
    let source = i + 1;
    let shown = !app.view().hidden.contains(&source);
    let color = if shown {
        colours.source(source)
    } else {
        colours.ink_dim.gamma_multiply(0.6)
    };
    let text = egui::RichText::new(format!("● {}", super::estimator_short(app, i)))
        .small()
        .color(color);
    if ui
        .selectable_label(shown, text)
        .on_hover_text(tr_with(
            app,
            if shown {
                "chip-hide-hint"
            } else {
                "chip-show-hint"
            },
            &[("name", arg(format!("{name} ({})", e.id())))],
        ))
        .clicked()
    {
        commands.push(Command::from(ViewCommand::ToggleSource(source)));
    }
}

/// The tab row and the options of the selected tab: the paper's figures first, as many as
/// fit in two rows; the rest of them and the generic tabs (Attitude, Rates, Covariance, …)
/// behind one "More…" menu, which names the tab when one of those is shown.
pub(super) fn plot_tabs(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let figures = app.sim().lab().page().figures;
    let groups = plots::groups(app.sim().available_specs());
    let current = app.view().plots.tab;
    let (lang, lab) = (app.view().lang(), app.sim().lab().id());
    let mut tabs: Vec<(plots::Tab, String)> = figures
        .iter()
        .map(|f| {
            let title = i18n::lab_text(lang, &i18n::figure_id(lab, f.id), f.title);
            (plots::Tab::Figure(f.id), title)
        })
        .collect();
    tabs.extend(
        groups
            .iter()
            .map(|g| (plots::Tab::Group(*g), tr(app, g.message()))),
    );
    // The figures (or, for a lab without figures, the groups) that fit in two rows beside
    // the More menu and the options.
    let first = if figures.is_empty() {
        tabs.len()
    } else {
        figures.len()
    };
    // Two rows; one on a phone held sideways, whose height the plot needs, where the
    // estimators' chips are a menu at the row's start.
    let short = super::narrow::is_short(ui.ctx());
    let rows = if short { 1.0 } else { 2.0 };
    let chips = if short { CHIPS_MENU_PT } else { 0.0 };
    let budget = rows * ui.available_width() - OPTIONS_WIDTH_PT - chips;
    let mut used = 0.0;
    let shown = tabs[..first]
        .iter()
        .take_while(|(_, title)| {
            used += tab_width(ui, title);
            used <= budget
        })
        .count();
    let select = |commands: &mut Vec<Command>, tab| {
        commands.push(Command::from(ViewCommand::SelectTab(tab)));
    };
    ui.horizontal_wrapped(|ui| {
        if short {
            estimator_menu(ui, app, commands);
        }
        for (tab, title) in &tabs[..shown] {
            if ui
                .selectable_label(current == *tab, title.as_str())
                .clicked()
            {
                select(commands, *tab);
            }
        }
        let more = &tabs[shown..];
        if !more.is_empty() {
            let label = match more.iter().find(|(tab, _)| *tab == current) {
                Some((_, title)) if short => {
                    tr_with(app, "more-with", &[("title", arg(super::elide(title, 20)))])
                }
                Some((_, title)) => tr_with(app, "more-with", &[("title", arg(title))]),
                None => tr(app, "more"),
            };
            ui.menu_button(label, |ui| {
                for (tab, title) in more {
                    if ui
                        .selectable_label(current == *tab, title.as_str())
                        .clicked()
                    {
                        select(commands, *tab);
                        ui.close();
                    }
                }
            });
        }
        ui.separator();
        tab_options(ui, app, commands);
    });
}

/// Room the estimators' menu takes at the start of a sideways phone's tab row (points).
const CHIPS_MENU_PT: f32 = 120.0;

/// Every estimator's chip in one menu (a phone held sideways has no row to spare for them).
fn estimator_menu(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let n = app.sim().estimators().len();
    if n == 0 {
        return;
    }
    let label = egui::RichText::new(format!("● {}", tr(app, "estimators-menu"))).small();
    ui.menu_button(label, |ui| {
        for i in 0..n {
            estimator_chip(ui, app, i, commands);
        }
    });
}

/// Room the More menu and the options take at the end of the tab rows (points).
const OPTIONS_WIDTH_PT: f32 = 330.0;

/// The width a tab button with `title` takes in `ui`, spacing included (points).
fn tab_width(ui: &Ui, title: &str) -> f32 {
    let font = egui::TextStyle::Button.resolve(ui.style());
    let text = ui.ctx().fonts_mut(|f| {
        f.layout_no_wrap(title.to_string(), font, egui::Color32::WHITE)
            .size()
            .x
    });
    text + 2.0 * ui.spacing().button_padding.x + ui.spacing().item_spacing.x
}

/// The options of the selected tab: log10 for covariances, ±3σ bands otherwise, and the
/// outages' shading where the lab has outages.
fn tab_options(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    match app.view().plots.tab {
        plots::Tab::Group(SeriesGroup::Covariance) => {
            let mut on = app.view().plots.log_covariance;
            if ui.checkbox(&mut on, tr(app, "log10")).changed() {
                commands.push(Command::from(ViewCommand::SetLogCovariance(on)));
            }
        }
        _ => {
            let mut on = app.view().plots.show_bands;
            if ui.checkbox(&mut on, tr(app, "bands")).changed() {
                commands.push(Command::from(ViewCommand::SetShowBands(on)));
            }
        }
    }
    if !super::outages(app).is_empty() {
        let mut on = app.view().plots.show_outages;
        if ui
            .checkbox(&mut on, tr(app, "outages"))
            .on_hover_text(tr(app, "outages-hint"))
            .changed()
        {
            commands.push(Command::from(ViewCommand::SetShowOutages(on)));
        }
    }
}
