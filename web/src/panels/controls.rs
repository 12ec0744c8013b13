//! The left panel: lab picker, run controls, parameter sliders generated from the lab's
//! parameter specs, export and the explanation.

use super::param_widget::in_language;
use super::slider_keys::{self, Rail};
use super::{arg, tr, tr_with};
use crate::state::{AppState, Command, IoCommand, PngTarget, RunCommand, UrlCommand, ViewCommand};
use attlab::i18n::{self, Lang};
use attlab::state::Theme;
use egui::{RichText, Ui};

/// Draws the left panel and collects commands (on a wide screen; a narrow one gets
/// `narrow`'s bar and sheet instead).
pub fn controls(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    // Presenter mode: a narrow panel, so the views keep the projector's width.
    let panel = if app.view().presenter {
        egui::Panel::left("controls_presenter").exact_size(230.0)
    } else {
        // Dragged wider, it stops at half the window: the views and the plot keep the rest
        // (it could take almost the whole width).
        let most = (0.5 * ui.ctx().content_rect().width()).max(300.0);
        egui::Panel::left("controls")
            .resizable(true)
            .default_size(300.0)
            .size_range(220.0..=most)
    };
    panel.show(ui, |ui| {
        // A lesson's way on stays in view under the panel, however long the card.
        if app.lesson().is_some() {
            egui::Panel::bottom("lesson_navigation")
                .show(ui, |ui| super::lesson::navigation_bar(ui, app, commands));
        }
        egui::ScrollArea::vertical().show(ui, |ui| {
            // A lesson under way comes first: its text and question beside the model.
            if app.lesson().is_some() {
                super::lesson::card(ui, app, commands);
                ui.separator();
            } else {
                ui.heading(tr(app, "app-title"));
            }
            super::lab_picker::lab_picker(ui, app, commands);
            ui.separator();
            run_controls(ui, app, commands);
            ui.separator();
            body(ui, app, commands);
        });
    });
}

/// Everything of the controls below the run buttons: presets, parameters, tools, outputs,
/// messages and the explanation (presenter mode: the presets, the rest behind one click).
pub(super) fn body(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    // "Start the lesson" (the card itself, once open, is at the top of the panel).
    if app.lesson().is_none() {
        super::lesson::card(ui, app, commands);
    }
    if app.view().presenter {
        // For the projector: the presets (or the lesson step's own sliders) carry the
        // lesson; the other sliders wait behind one click.
        match app.lesson_step().filter(|s| !s.highlight.is_empty()) {
            Some(step) => super::sliders::slider_rows(ui, app, commands, Some(step.highlight)),
            None => presets(ui, app, commands),
        }
        super::fit::header(ui, tr(app, "all-parameters"))
            .default_open(false)
            .show(ui, |ui| parameters(ui, app, commands));
        super::lab_tools::accuracy(ui, app, commands);
        messages(ui, app, commands);
        return;
    }
    parameters(ui, app, commands);
    ui.separator();
    super::lab_tools::accuracy(ui, app, commands);
    super::sweeps::sweeps(ui, app, commands);
    super::lab_tools::laboratory_mode(ui, app, commands);
    outputs(ui, app, commands);
    messages(ui, app, commands);
    ui.separator();
    explanation(ui, app);
}

fn run_controls(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    ui.horizontal_wrapped(|ui| {
        run_buttons(ui, app, commands);
        mode_buttons(ui, app, commands);
    });
    seed_and_speed(ui, app, commands);
}

/// Play or Pause, Step and Reset.
pub(super) fn run_buttons(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    {
        let label = tr(app, if app.run().playing { "pause" } else { "play" });
        if ui.button(label).clicked() {
            commands.push(Command::from(RunCommand::SetPlaying(!app.run().playing)));
        }
        if ui
            .add_enabled(!app.run().playing, egui::Button::new(tr(app, "step")))
            .clicked()
        {
            commands.push(Command::from(RunCommand::StepOnce));
        }
        if ui
            .button(tr(app, "reset"))
            .on_hover_text(tr(app, "reset-hint"))
            .clicked()
        {
            commands.push(Command::from(RunCommand::Reset));
        }
    }
}

/// Presenter mode and the light theme.
pub(super) fn mode_buttons(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    {
        if ui
            .selectable_label(app.view().presenter, tr(app, "presenter"))
            .on_hover_text(tr(app, "presenter-hint"))
            .clicked()
        {
            commands.push(Command::from(ViewCommand::SetPresenter(
                !app.view().presenter,
            )));
        }
        let light = app.view().theme() == Theme::Light;
        if ui
            .selectable_label(light, tr(app, "light"))
            .on_hover_text(tr(app, "light-hint"))
            .clicked()
        {
            let next = if light { Theme::Dark } else { Theme::Light };
            commands.push(Command::from(ViewCommand::SetTheme(Some(next))));
        }
        let lang = app.view().lang();
        egui::ComboBox::from_id_salt("language")
            .selected_text(lang.name())
            .show_ui(ui, |ui| {
                for l in Lang::ALL {
                    if ui.selectable_label(l == lang, l.name()).clicked() && l != lang {
                        commands.push(Command::from(ViewCommand::SetLang(l)));
                    }
                }
            })
            .response
            .on_hover_text(format!("{} (lang=en, lang=ru)", tr(app, "language")));
        if ui
            .button(tr(app, "keys-button"))
            .on_hover_text(tr(app, "keys-button-hint"))
            .clicked()
        {
            commands.push(Command::from(ViewCommand::SetKeysHelp(true)));
        }
    }
}

/// The seed (with New seed) and the speed slider.
pub(super) fn seed_and_speed(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    ui.horizontal(|ui| {
        let label = ui.label(tr(app, "seed"));
        let mut seed = app.run().seed;
        if ui
            .add(egui::DragValue::new(&mut seed).range(0..=u64::MAX))
            .labelled_by(label.id)
            .changed()
        {
            commands.push(Command::from(RunCommand::SetSeed(seed)));
        }
        if ui
            .button(tr(app, "new-seed"))
            .on_hover_text(tr(app, "new-seed-hint"))
            .clicked()
        {
            commands.push(Command::from(RunCommand::NewSeed));
        }
    });
    let (lo, hi) = attlab::state::SPEED_RANGE;
    let before = app.run().speed;
    let mut speed = before;
    let r = ui.add(in_language(
        egui::Slider::new(&mut speed, lo..=hi)
            .logarithmic(true)
            .text(tr(app, "speed"))
            .max_decimals(1),
        app.view().lang(),
    ));
    let rail = Rail {
        min: lo,
        max: hi,
        log: true,
        integer: false,
    };
    if let Some(keyed) = slider_keys::handle(ui, &r, rail, before) {
        speed = keyed;
    }
    if speed != before {
        commands.push(Command::from(RunCommand::SetSpeed(speed)));
    }
}

fn presets(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let presets = app.sim().lab().presets();
    if presets.is_empty() {
        return;
    }
    let lab = app.sim().lab().id();
    let names: Vec<String> = (presets.iter())
        .map(|p| i18n::lab_text(app.view().lang(), &i18n::preset_id(lab, p.id), p.name))
        .collect();
    // Wrapped into rows where every name fits a row, else one under another: in wrapped
    // rows, a preset whose name took two lines left a row as tall as its own under the
    // next one (presenter mode's narrow panel; Russian names on a laptop).
    let room = ui.available_width() - 2.0 * ui.spacing().button_padding.x;
    let wraps =
        (names.iter()).any(|n| super::fit::text_width(ui, n, egui::TextStyle::Button) > room);
    let buttons = |ui: &mut Ui| {
        ui.label(tr(app, "presets"));
        for (preset, name) in presets.iter().zip(names) {
            let help = super::lab_word(app, &i18n::preset_help_id(lab, preset.id), preset.help);
            let hint = tr_with(app, "preset-hint", &[("help", arg(help))]);
            if ui.button(name).on_hover_text(hint).clicked() {
                commands.push(Command::from(RunCommand::ApplyPreset(preset.id)));
            }
        }
    };
    if app.view().presenter || wraps {
        ui.vertical(buttons);
    } else {
        ui.horizontal_wrapped(buttons);
    }
}

fn parameters(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    if app.view().hides(attlab::state::ALL_CONTROLS) {
        return;
    }
    ui.horizontal(|ui| {
        ui.strong(tr(app, "parameters"));
        if ui.small_button(tr(app, "defaults")).clicked() {
            commands.push(Command::from(RunCommand::RestoreDefaults));
        }
    });
    if !app.view().presenter {
        presets(ui, app, commands);
    }
    super::sliders::slider_rows(ui, app, commands, None);
    super::sliders::pending_reset(ui, app, commands);
}

fn outputs(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    ghost_picker(ui, app, commands);
    // Wrapped: on a phone's sheet the five buttons ran past the screen's edge.
    ui.horizontal_wrapped(|ui| {
        if ui
            .button(tr(app, "export-csv"))
            .on_hover_text(tr(app, "export-csv-hint"))
            .clicked()
        {
            commands.push(Command::from(IoCommand::ExportCsv));
        }
        if ui
            .button(tr(app, "copy-link"))
            .on_hover_text(tr(app, "copy-link-hint"))
            .clicked()
        {
            commands.push(Command::from(UrlCommand::CopyLink));
        }
        if ui
            .button(tr(app, "share"))
            .on_hover_text(tr(app, "share-hint"))
            .clicked()
        {
            commands.push(Command::from(crate::state::ShareCommand::Open));
        }
        if ui
            .button(tr(app, "copy-python"))
            .on_hover_text(tr(app, "copy-python-hint"))
            .clicked()
        {
            commands.push(Command::from(IoCommand::CopyPython));
        }
        if ui
            .add_enabled(
                !app.view().capturing,
                egui::Button::new(tr(app, "png-plots")),
            )
            .on_hover_text(tr(app, "png-plots-hint"))
            .clicked()
        {
            commands.push(Command::from(IoCommand::ExportPng(PngTarget::Plots)));
        }
    });
    if app.sim().lab().output_file(app.sim().params()).is_some()
        && ui
            .button(tr(app, "export-output"))
            .on_hover_text(tr(app, "export-output-hint"))
            .clicked()
    {
        commands.push(Command::from(IoCommand::ExportOutputFile));
    }
}

/// The estimator drawn as the ghost beside the truth, of those with an attitude.
fn ghost_picker(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let with_attitude: Vec<(usize, String)> = app
        .sim()
        .estimators()
        .iter()
        .zip(app.sim().estimates())
        .enumerate()
        .filter(|(_, (_, est))| est.quaternion().is_some())
        .map(|(i, _)| (i, super::estimator_name(app, i)))
        .collect();
    if !with_attitude.is_empty() {
        let current = with_attitude
            .iter()
            .find(|(i, _)| *i == app.view().ghost_index)
            .map_or("—", |x| &x.1[..]);
        let combo = egui::ComboBox::from_id_salt("ghost").selected_text(current);
        super::fit::labelled(ui, ("ghost", tr(app, "ghost")), combo, |combo, ui| {
            combo
                .show_ui(ui, |ui| {
                    for (i, label) in &with_attitude {
                        if ui
                            .selectable_label(*i == app.view().ghost_index, &label[..])
                            .clicked()
                        {
                            commands.push(Command::from(ViewCommand::SetGhost(*i)));
                        }
                    }
                })
                .response
        });
    }
}

fn messages(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    for (i, m) in app.messages().iter().enumerate() {
        ui.horizontal_wrapped(|ui| {
            let colours = crate::render::palette::of(ui.visuals());
            let color = if m.is_error {
                colours.error
            } else {
                colours.good
            };
            if ui.small_button("✕").clicked() {
                commands.push(Command::Dismiss(i));
            }
            let text = match m.times {
                1 => m.text.clone(),
                n => format!("{} (×{n})", m.text),
            };
            ui.colored_label(color, text);
        });
    }
}

fn explanation(ui: &mut Ui, app: &AppState) {
    super::fit::header(ui, tr(app, "what-am-i-looking-at"))
        .default_open(false)
        .show(ui, |ui| {
            let lab = app.sim().lab();
            let id = i18n::lab_summary_id(lab.id());
            ui.label(i18n::lab_text(app.view().lang(), &id, lab.summary()));
            ui.add_space(4.0);
            ui.label(RichText::new(tr(app, "keys-help")).small().strong());
            ui.add_space(4.0);
            ui.label(RichText::new(tr(app, "frames-help")).small());
        });
    super::about::about(ui, app);
}
