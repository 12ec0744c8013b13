//! The share dialog: the teacher's link for the state or the lesson step, with presenter
//! mode, the answers, and controls hidden or locked, shown as text to copy and as a QR code
//! the class scans from the projector.

use super::{lab_word, tr};
use crate::state::{AppState, Command, QrModules, ShareCommand, ShareOptions, qr};
use attlab::i18n;
use attlab::state::ALL_CONTROLS;
use egui::{Color32, Ui};

/// The dialog, while it is open.
pub fn share_dialog(ctx: &egui::Context, app: &AppState, commands: &mut Vec<Command>) {
    let Some(options) = app.share() else {
        return;
    };
    let link = app.share_link(options);
    let modal = egui::Modal::new(egui::Id::unique("share_dialog")).show(ctx, |ui| {
        ui.set_max_width(640.0);
        ui.heading(tr(app, "share-title"));
        ui.horizontal_top(|ui| {
            ui.vertical(|ui| {
                ui.set_max_width(340.0);
                choices(ui, app, options, commands);
                controls(ui, app, options, commands);
            });
            ui.vertical(|ui| {
                match qr(&link) {
                    Ok(code) => draw_qr(ui, &code, 240.0),
                    Err(why) => {
                        ui.colored_label(ui.visuals().error_fg_color, why.words(app.view().lang()));
                    }
                }
                ui.label(egui::RichText::new(tr(app, "share-scan")).small().weak());
            });
        });
        whole_link(ui, &link);
        embed(ui, app, options);
        ui.horizontal(|ui| {
            if ui.button(tr(app, "share-copy")).clicked() {
                commands.push(ShareCommand::Copy.into());
            }
            if ui
                .button(tr(app, "share-copy-embed"))
                .on_hover_text(tr(app, "share-embed-hint"))
                .clicked()
            {
                commands.push(ShareCommand::CopyEmbed.into());
            }
            ui.button(tr(app, "close")).clicked()
        })
        .inner
    });
    if modal.inner || modal.should_close() {
        commands.push(ShareCommand::Close.into());
    }
}

/// The `<iframe>` snippet for a slide or a course page, folded (the class needs the link).
fn embed(ui: &mut Ui, app: &AppState, options: &ShareOptions) {
    egui::CollapsingHeader::new(tr(app, "share-embed"))
        .default_open(false)
        .show(ui, |ui| {
            ui.label(egui::RichText::new(tr(app, "share-embed-hint")).small());
            whole_link(ui, &app.share_embed(options));
        });
}

/// The link, whole: wrapped anywhere (it has no spaces) in the dialog's width, and
/// selectable; a one-line field had cut it at the dialog's edge.
fn whole_link(ui: &mut Ui, link: &str) {
    let font = egui::TextStyle::Monospace.resolve(ui.style());
    let mut job = egui::text::LayoutJob::single_section(
        link.to_string(),
        egui::TextFormat::simple(font, ui.visuals().text_color()),
    );
    job.wrap = egui::text::TextWrapping {
        max_width: ui.available_width(),
        break_anywhere: true,
        ..Default::default()
    };
    egui::Frame::group(ui.style()).show(ui, |ui| {
        ui.add(egui::Label::new(job).selectable(true));
    });
}

/// What the link opens: the step or the state, presenter mode, the answers.
fn choices(ui: &mut Ui, app: &AppState, o: &ShareOptions, commands: &mut Vec<Command>) {
    if let Some(lesson) = app.lesson() {
        if ui.radio(o.from_step, tr(app, "share-from-step")).clicked() {
            commands.push(ShareCommand::FromStep(true).into());
        }
        if ui.radio(!o.from_step, tr(app, "share-as-is")).clicked() {
            commands.push(ShareCommand::FromStep(false).into());
        }
        let mut answers = o.answers;
        if !lesson.answers.is_empty()
            && ui
                .checkbox(&mut answers, tr(app, "share-answers"))
                .changed()
        {
            commands.push(ShareCommand::Answers(answers).into());
        }
    }
    let mut presenter = o.presenter;
    if ui
        .checkbox(&mut presenter, tr(app, "share-presenter"))
        .changed()
    {
        commands.push(ShareCommand::Presenter(presenter).into());
    }
}

/// Hide and lock: every control at once, or one by one.
fn controls(ui: &mut Ui, app: &AppState, o: &ShareOptions, commands: &mut Vec<Command>) {
    super::fit::header(ui, tr(app, "share-controls"))
        .default_open(!o.hide.is_empty() || !o.lock.is_empty())
        .show(ui, |ui| {
            egui::ScrollArea::vertical()
                .max_height(220.0)
                .show(ui, |ui| {
                    egui::Grid::new("share_controls")
                        .num_columns(3)
                        .striped(true)
                        .show(ui, |ui| {
                            ui.strong(tr(app, "share-control"));
                            ui.strong(tr(app, "share-hide"));
                            ui.strong(tr(app, "share-lock"));
                            ui.end_row();
                            let heads = [tr(app, "share-hide"), tr(app, "share-lock")];
                            row(
                                ui,
                                o,
                                (ALL_CONTROLS, &tr(app, "share-all")),
                                &heads,
                                commands,
                            );
                            let lab = app.sim().lab();
                            for spec in lab.params() {
                                let id = i18n::param_label_id(lab.id(), spec.key);
                                let label = lab_word(app, &id, spec.label);
                                row(ui, o, (spec.key, &label), &heads, commands);
                            }
                        });
                });
        });
}

/// One control's row: its name, hide, lock. The boxes have no text of their own (the
/// columns' heads say what they do), so a screen reader is told "Hide: Gyro σ".
fn row(
    ui: &mut Ui,
    o: &ShareOptions,
    (key, label): (&'static str, &str),
    [hide_word, lock_word]: &[String; 2],
    commands: &mut Vec<Command>,
) {
    ui.label(super::elide(label, 32)).on_hover_text(label);
    let boxed = |ui: &mut Ui, on: bool, word: &str| {
        let mut value = on;
        let response = ui.checkbox(&mut value, "");
        let name = format!("{word}: {label}");
        response
            .widget_info(|| egui::WidgetInfo::selected(egui::Role::CheckBox, true, value, &name));
        response.changed().then_some(value)
    };
    if let Some(hide) = boxed(ui, o.hide.contains(&key), hide_word) {
        commands.push(ShareCommand::Hide(key, hide).into());
    }
    if let Some(lock) = boxed(ui, o.lock.contains(&key), lock_word) {
        commands.push(ShareCommand::Lock(key, lock).into());
    }
    ui.end_row();
}

/// Draws `code` `side` points wide, dark on white with the quiet zone of 4 modules the
/// standard asks for (a phone reads it off a dark theme too).
fn draw_qr(ui: &mut Ui, code: &QrModules, side: f32) {
    let quiet = 4;
    let modules = code.width + 2 * quiet;
    let (rect, _) = ui.allocate_exact_size(egui::vec2(side, side), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, Color32::WHITE);
    let m = side / modules as f32;
    for (i, dark) in code.dark.iter().enumerate() {
        if !dark {
            continue;
        }
        let (x, y) = (
            (i % code.width + quiet) as f32,
            (i / code.width + quiet) as f32,
        );
        let min = rect.min + egui::vec2(x * m, y * m);
        painter.rect_filled(
            egui::Rect::from_min_size(min, egui::vec2(m + 0.3, m + 0.3)),
            0.0,
            Color32::BLACK,
        );
    }
}
