//! The lab picker: the list of labs by their titles in the reader's language, with the
//! paper under it (the side panel), or alone in a phone's bar held sideways.

use super::tr;
use crate::state::{AppState, Command, RunCommand};
use attlab::i18n;
use attlab::labs;
use egui::{RichText, Ui};

/// The picker, labelled, with the current lab's paper under it.
pub(super) fn lab_picker(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let combo = lab_list(app);
    super::fit::labelled(ui, ("lab-picker", tr(app, "lab")), combo, |combo, ui| {
        choose_lab(combo, ui, app, commands)
    });
    let lab = app.sim().lab();
    let paper = i18n::lab_text(
        app.view().lang(),
        &i18n::lab_paper_id(lab.id()),
        lab.paper(),
    );
    ui.label(RichText::new(paper).small().italics());
}

/// The lab picker alone, a fifth of the row wide (a phone held sideways, in its bar).
pub(super) fn lab_combo(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let width = ui.available_width() / 5.0;
    let response = choose_lab(lab_list(app).width(width).truncate(), ui, app, commands);
    response.on_hover_text(tr(app, "lab"));
}

/// The closed list of labs, showing the current one's title.
fn lab_list(app: &AppState) -> egui::ComboBox<'static> {
    let title = lab_title(app, app.sim().lab());
    egui::ComboBox::from_id_salt("lab-picker").selected_text(title)
}

/// A lab's title in the reader's language.
fn lab_title(app: &AppState, lab: &dyn attlab::page::Lab) -> String {
    i18n::lab_text(
        app.view().lang(),
        &i18n::lab_title_id(lab.id()),
        lab.title(),
    )
}

/// `combo` opened to every lab; choosing another switches to it.
fn choose_lab(
    combo: egui::ComboBox<'_>,
    ui: &mut Ui,
    app: &AppState,
    commands: &mut Vec<Command>,
) -> egui::Response {
    let current = app.sim().lab();
    combo
        .show_ui(ui, |ui| {
            for lab in labs::all() {
                let chosen = lab.id() == current.id();
                if ui.selectable_label(chosen, lab_title(app, *lab)).clicked() && !chosen {
                    commands.push(Command::from(RunCommand::SelectLab(*lab)));
                }
            }
        })
        .response
}
