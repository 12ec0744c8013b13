//! The page embedded in another (`embed=1`: a slide, a course page): no side panel, no
//! status line, no sheet — a thin bar with the run buttons, the time and a link that opens
//! the same state in Attitude Lab itself, then (with a lesson) the step's card, and the
//! views and the plot below, sized to the frame.

use super::{arg, lab_word, num_arg, tr, tr_with};
use crate::state::{AppState, Command};
use egui::Ui;

/// The largest share of the frame's height the lesson card takes (it scrolls beyond).
const CARD_SHARE: f32 = 0.4;

/// The bar and, with a lesson open, its card.
pub fn embed_bar(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    egui::Panel::top("embed_bar").show(ui, |ui| {
        ui.horizontal(|ui| {
            super::controls::run_buttons(ui, app, commands);
            let lab = app.sim().lab();
            let title = lab_word(app, &attlab::i18n::lab_title_id(lab.id()), lab.title());
            let t = num_arg(app, format!("{:.1}", app.sim().t_s()));
            ui.label(tr_with(app, "embed-time", &[("t", t)]));
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                if let Some(url) = open_url(app) {
                    ui.hyperlink_to(tr(app, "embed-open"), url)
                        .on_hover_text(tr_with(app, "embed-open-hint", &[("lab", arg(title))]));
                }
            });
        });
    });
    if app.lesson().is_none() {
        return;
    }
    let most = CARD_SHARE * ui.ctx().content_rect().height();
    egui::Panel::top("embed_lesson")
        .resizable(false)
        .max_size(most)
        .show(ui, |ui| {
            super::lesson::navigation_bar(ui, app, commands);
            egui::ScrollArea::vertical()
                .max_height(most)
                .show(ui, |ui| super::lesson::card(ui, app, commands));
        });
}

/// The link to this state in the page itself, in a new tab: the same address and
/// fragment without `embed` and `origin` (none on the desktop).
pub fn open_url(app: &AppState) -> Option<String> {
    let page = crate::platform::page_address()?;
    let fragment = app.fragment();
    let kept: Vec<&str> = (fragment.split('&'))
        .filter(|item| !item.starts_with("embed=") && !item.starts_with("origin="))
        .collect();
    Some(format!("{page}#{}", kept.join("&")))
}
