//! Labelled widgets fitted to the room their row has, so nothing is painted past a panel's
//! edge: the presenter's panel has a fixed width of 230 points, and the phone's sheet is the
//! screen's width. Once one row reaches past the edge, egui widens the layout to include
//! it, and every wrapped line below takes the wider width too.
//! - Given a label, egui's combo box grows to the whole row and squeezes the label: "Lab"
//!   wrapped letter by letter past the presenter panel's edge.
//! - egui's slider draws its rail, its value and then its label on one line, never wrapped:
//!   in the presenter panel every slider's label ran past the edge; a side panel grew to
//!   its longest label.

use egui::{ComboBox, Response, Slider, Ui};

/// The narrowest combo box beside its label: a word or two of its choice still shows.
const MIN_BESIDE: f32 = 100.0;

/// `combo` labelled `label` (`key` names it among its row's neighbours, whatever the
/// language): the box fills the row left of its label, or, where the label would leave it
/// less than [`MIN_BESIDE`], stands under the label (wrapped) at the row's whole width. Its text wraps rather than widening the panel. `show` adds the box (this
/// sets its width) and returns its response. Returns the box's response, labelled by the
/// label for AccessKit, and the label's (for its hover text).
pub(super) fn labelled(
    ui: &mut Ui,
    (key, label): (&str, String),
    combo: ComboBox<'_>,
    show: impl FnOnce(ComboBox<'_>, &mut Ui) -> Response,
) -> (Response, Response) {
    // The box in a scope of its own id in either layout, so it keeps its id (and its
    // open list) when the row changes layout.
    let scope = ui.scope_id().with(("fitted combo box", key));
    let beside = ui.available_width()
        - text_width(ui, &label, egui::TextStyle::Body)
        - ui.spacing().item_spacing.x;
    if beside >= MIN_BESIDE {
        return ui
            .horizontal(|ui| {
                let combo = fitted(ui, (scope, beside), combo, show);
                let label = ui.label(label);
                (combo.labelled_by(label.id), label)
            })
            .inner;
    }
    let label = ui.label(label);
    let width = ui.available_width();
    (
        fitted(ui, (scope, width), combo, show).labelled_by(label.id),
        label,
    )
}

/// The combo box `width` wide in a scope of id `scope`, its text wrapped inside.
fn fitted(
    ui: &mut Ui,
    (scope, width): (egui::Id, f32),
    combo: ComboBox<'_>,
    show: impl FnOnce(ComboBox<'_>, &mut Ui) -> Response,
) -> Response {
    let size = egui::vec2(width, ui.spacing().interact_size.y);
    ui.allocate_ui(size, |ui| {
        let scoped = egui::UiBuilder::new().scope_id(scope);
        ui.scope_builder(scoped, |ui| show(combo.width(width).wrap(), ui))
            .inner
    })
    .inner
}

/// `slider` (without a text of its own) labelled `label` (`key` names it among its row's
/// neighbours, whatever the language): the rail, its value and the label on one row, the
/// label wrapped in the room the value leaves, as long as that room is at least
/// [`MIN_LABEL`]; else the label (wrapped) above the rail and its value at the
/// row's whole width. `unit` is the value's suffix, to leave the value room before its box
/// has been drawn. Returns the slider's response, labelled by the label for AccessKit, and
/// the label's (for its hover text).
pub(super) fn slider(
    ui: &mut Ui,
    slider: Slider<'_>,
    (key, label): (&str, String),
    unit: &str,
) -> (Response, Response) {
    let spacing = ui.spacing();
    let gap = spacing.item_spacing.x;
    // The value's box: as wide as this slider's box has been drawn (egui picks the
    // decimals as it draws), up to twice the first guess, a signed number with four
    // decimals.
    let id = ui.scope_id().with(("fitted slider's value", key));
    let drawn: f32 = ui.data(|d| d.get_temp(id)).unwrap_or(0.0);
    let first_guess = (text_width(ui, &format!("−0.0000 {unit}"), egui::TextStyle::Body)
        + 2.0 * spacing.button_padding.x)
        .max(spacing.interact_size.x);
    let value = if drawn > 0.0 { drawn } else { first_guess };
    let rail = spacing.slider_width;
    // The slider in a scope of its own id in either layout, so it keeps its id (and the
    // keyboard focus) when its value's box grows and the row changes layout.
    let rail_ui = egui::UiBuilder::new().scope_id(id.with("rail"));
    let (response, label, rail) = if ui.available_width() - rail - value - 2.0 * gap >= MIN_LABEL {
        let (response, label) = ui
            .horizontal(|ui| {
                let response = ui.scope_builder(rail_ui, |ui| ui.add(slider)).inner;
                (response, ui.add(egui::Label::new(label).wrap()))
            })
            .inner;
        (response, label, rail)
    } else {
        let label = ui.add(egui::Label::new(label).wrap());
        let rail = (ui.available_width() - value - gap).max(MIN_RAIL);
        let response = ui
            .scope_builder(rail_ui, |ui| {
                ui.spacing_mut().slider_width = rail;
                ui.add(slider)
            })
            .inner;
        (response, label, rail)
    };
    // Not while the value is being typed: egui's text field grows with what is typed, and
    // a pasted line would have kept the row stacked with a short rail for the session.
    let box_width = response.rect.width() - rail - gap;
    if box_width > drawn && box_width <= 2.0 * first_guess && !response.has_focus() {
        ui.data_mut(|d| d.insert_temp(id, box_width));
    }
    (response.labelled_by(label.id), label)
}

/// The narrowest room for a slider's label beside its value: a word or two a line.
const MIN_LABEL: f32 = 72.0;

/// The shortest rail of a slider under its label.
const MIN_RAIL: f32 = 40.0;

/// The width of `text` on one line in the font of `style`.
pub(super) fn text_width(ui: &Ui, text: &str, style: egui::TextStyle) -> f32 {
    let font = style.resolve(ui.style());
    (ui.painter())
        .layout_no_wrap(text.to_owned(), font, egui::Color32::WHITE)
        .size()
        .x
}

/// A collapsing header titled `title`, wrapped within the row: egui lays a header's title
/// out on one line, and p2's "Accuracy over the last 60 s beside the paper's Tables 3–5" ran
/// past the presenter panel's edge, the text under it wrapping at the title's width.
pub(super) fn header(ui: &Ui, title: String) -> egui::CollapsingHeader {
    let spacing = ui.spacing();
    let width = ui.available_width() - spacing.indent - spacing.button_padding.x;
    let galley = egui::WidgetText::from(title).into_galley(
        ui,
        Some(egui::TextWrapMode::Wrap),
        width,
        egui::TextStyle::Button,
    );
    egui::CollapsingHeader::new(galley)
}
