//! The lab's sliders as the controls list them: the link's hidden controls left out, its
//! locked ones disabled, the lesson step's own outlined; and the line naming the reset-only
//! parameters that wait for Reset.

use super::param_widget::param_widget;
use super::{arg, num_arg, tr, tr_with};
use crate::state::{AppState, Command, RunCommand};
use attlab::i18n;
use attlab::page::ParamNote;
use egui::{RichText, Ui};

/// The lab's sliders (only `only`'s when given) less those the link hides; those it locks
/// are shown disabled, and those the lesson step points at are outlined.
pub(super) fn slider_rows(
    ui: &mut Ui,
    app: &AppState,
    commands: &mut Vec<Command>,
    only: Option<&[&str]>,
) {
    let highlight = app.lesson_step().map_or(&[][..], |s| s.highlight);
    let params = app.slider_params();
    let notes = app.sim().lab().param_notes(&params);
    for spec in app.sim().lab().params() {
        if app.view().hides(spec.key) || only.is_some_and(|keys| !keys.contains(&spec.key)) {
            continue;
        }
        let value = params.get(spec.key);
        let locked = app.view().locks(spec.key);
        let active = !locked && (spec.outside_run || spec.acts_in(&params));
        let row = |ui: &mut Ui| {
            let widget = |ui: &mut Ui| {
                ui.add_enabled_ui(active, |ui| param_widget(ui, app, spec, value))
                    .inner
            };
            if !locked {
                return widget(ui);
            }
            // A padlock before the greyed control: locked, not merely off.
            ui.horizontal_top(|ui| {
                let hint = tr(app, "locked-hint");
                padlock(ui, &hint).on_hover_text(hint);
                ui.vertical(widget).inner
            })
            .inner
        };
        let changed = if highlight.contains(&spec.key) {
            let stroke = egui::Stroke::new(2.0, ui.visuals().selection.stroke.color);
            egui::Frame::new()
                .stroke(stroke)
                .inner_margin(3.0)
                .corner_radius(4.0)
                .show(ui, row)
                .inner
        } else {
            row(ui)
        };
        if let Some(v) = changed {
            commands.push(Command::from(RunCommand::SetParam(spec.key, v)));
        }
        for note in notes.iter().filter(|n| n.key == spec.key) {
            note_line(ui, app, note);
        }
    }
}

/// A padlock a line of text high, painted (the page's fonts have no 🔒): the sign of a
/// control the teacher's link locks, which a screen reader reads as `words`.
fn padlock(ui: &mut Ui, words: &str) -> egui::Response {
    let h = ui.text_style_height(&egui::TextStyle::Body);
    let (rect, response) = ui.allocate_exact_size(egui::vec2(0.75 * h, h), egui::Sense::hover());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, words));
    let colour = ui.visuals().warn_fg_color;
    let painter = ui.painter_at(rect.expand(1.0));
    let body = egui::Rect::from_min_max(
        egui::pos2(rect.left(), rect.top() + 0.45 * h),
        egui::pos2(rect.right(), rect.bottom() - 0.05 * h),
    );
    painter.rect_filled(body, 0.12 * h, colour);
    // The shackle: a half ring on two short legs.
    let (cx, r) = (body.center().x, 0.26 * h);
    let top = body.top() - 0.12 * h;
    let mut points = vec![egui::pos2(cx - r, body.top())];
    points.extend((0..=12).map(|k| {
        let a = std::f32::consts::PI * (1.0 + k as f32 / 12.0);
        egui::pos2(cx + r * a.cos(), top + r * a.sin())
    }));
    points.push(egui::pos2(cx + r, body.top()));
    painter.add(egui::Shape::line(
        points,
        egui::Stroke::new(0.13 * h, colour),
    ));
    response
}

/// A note under a slider: small, in the warning colour when it is one.
fn note_line(ui: &mut Ui, app: &AppState, note: &ParamNote) {
    // Every argument of a note is a number.
    let args: Vec<(&str, _)> = note
        .args
        .iter()
        .map(|(k, v)| (*k, num_arg(app, v)))
        .collect();
    let text = RichText::new(tr_with(app, note.message, &args)).small();
    let text = if note.warning {
        text.color(ui.visuals().warn_fg_color)
    } else {
        text.weak()
    };
    ui.add(egui::Label::new(text).wrap());
}

/// A line naming the reset-only parameters that were moved and wait for Reset, with the
/// button that applies them (until then the run goes on unchanged).
pub(super) fn pending_reset(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let pending = app.sim().pending_reset();
    if pending.is_empty() {
        return;
    }
    let specs = app.sim().lab().params();
    let labels: Vec<String> = pending
        .iter()
        .filter_map(|k| specs.iter().find(|s| s.key == *k))
        .map(|s| {
            let id = i18n::param_label_id(app.sim().lab().id(), s.key);
            i18n::lab_text(app.view().lang(), &id, s.label)
        })
        .collect();
    ui.horizontal_wrapped(|ui| {
        ui.label(tr_with(
            app,
            "waiting-for-reset",
            &[("names", arg(labels.join(", ")))],
        ));
        if ui
            .small_button(tr(app, "reset-now"))
            .on_hover_text(tr(app, "reset-now-hint"))
            .clicked()
        {
            commands.push(Command::from(RunCommand::Reset));
        }
    });
}
