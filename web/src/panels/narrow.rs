//! A narrow screen (a phone, a tablet held upright): one view and the plot get the page,
//! a bar on top holds the lab, the run buttons and a switcher between the views, and the
//! controls open as a sheet from the bottom.

use super::{controls, tr};
use crate::state::{AppState, Command, ViewCommand};
use attlab::page::ViewKind;
use egui::Ui;

/// Below this width in CSS pixels the page stacks (a phone is 360–430 px wide).
pub const NARROW_PX: f32 = 800.0;

/// The least height of a control a finger must hit (CSS pixels).
pub const TOUCH_TARGET_PX: f32 = 32.0;

/// Whether the page is laid out for a narrow screen.
pub fn is_narrow(ctx: &egui::Context) -> bool {
    ctx.content_rect().width() * ctx.zoom_factor() < NARROW_PX
}

/// Below this height in CSS pixels a wide screen is a phone held sideways (844×390): the
/// desktop's side panel and row of views had left its plot 55 px tall.
pub const SHORT_PX: f32 = 500.0;

/// Whether the page is a wide but short screen: a phone held sideways gets the phone's
/// bar and a sheet from the side, and one view beside the plot.
pub fn is_short(ctx: &egui::Context) -> bool {
    !is_narrow(ctx) && ctx.content_rect().height() * ctx.zoom_factor() < SHORT_PX
}

/// A phone, upright or sideways: the bar and the sheet instead of the side panel.
pub fn is_phone(ctx: &egui::Context) -> bool {
    is_narrow(ctx) || is_short(ctx)
}

/// The controls as the screen holds them: the side panel on a wide screen; on a phone the
/// bar and the sheet (sideways, the bar spans the screen and the sheet opens below it, at
/// the left; upright, the sheet rises from the bottom under the bar).
pub fn controls_for_the_screen(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    if is_short(ui.ctx()) {
        bar(ui, app, commands);
        sheet(ui, app, commands);
    } else if is_narrow(ui.ctx()) {
        sheet(ui, app, commands);
        bar(ui, app, commands);
    } else {
        controls::controls(ui, app, commands);
    }
}

/// The bar on top: the lab picker, Play/Pause, Reset, the controls' sheet, and one button
/// per view of the lab.
pub fn bar(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let short = is_short(ui.ctx());
    egui::Panel::top("narrow_bar").show(ui, |ui| {
        // Sideways there is width to spare and no height: the picker beside the buttons.
        if !short {
            super::lab_picker::lab_picker(ui, app, commands);
        }
        ui.horizontal_wrapped(|ui| {
            if short {
                super::lab_picker::lab_combo(ui, app, commands);
            }
            controls::run_buttons(ui, app, commands);
            let open = app.view().sheet_open;
            if ui
                .selectable_label(open, tr(app, "controls"))
                .on_hover_text(tr(app, "controls-hint"))
                .clicked()
            {
                commands.push(Command::from(ViewCommand::SetSheet(!open)));
            }
            lesson_button(ui, app, commands);
            if short {
                view_combo(ui, app, commands);
            }
        });
        if short {
            return;
        }
        ui.horizontal_wrapped(|ui| {
            ui.label(tr(app, "view"));
            for (k, kind) in app.sim().lab().page().views.iter().enumerate() {
                let chosen = app.view().narrow_view == k;
                if ui
                    .selectable_label(chosen, view_title(app, *kind))
                    .clicked()
                {
                    commands.push(Command::from(ViewCommand::ShowNarrowView(k)));
                }
            }
        });
    });
}

/// With a lesson open, "Lesson · step k of n": the card is at the top of the sheet it opens
/// (a question step opens the sheet by itself; see `AppState::show_step`).
fn lesson_button(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let Some(all) = app.sim().lab().lesson() else {
        return;
    };
    let Some(lesson) = app.lesson() else {
        // On the bar, not down in the controls' sheet where a phone's reader never looked.
        if ui.button(tr(app, "lesson-start")).clicked() {
            commands.push(Command::from(crate::state::LessonCommand::Start));
            commands.push(Command::from(ViewCommand::SetSheet(true)));
        }
        return;
    };
    let text = super::tr_with(
        app,
        "lesson-bar",
        &[
            ("n", super::arg(lesson.step)),
            ("count", super::arg(all.steps.len())),
        ],
    );
    if ui.button(egui::RichText::new(text).strong()).clicked() {
        commands.push(Command::from(ViewCommand::SetSheet(true)));
    }
}

/// The views as one list (a phone held sideways has room for one row of buttons).
fn view_combo(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let views = app.sim().lab().page().views;
    let chosen = app.view().narrow_view.min(views.len().saturating_sub(1));
    let Some(current) = views.get(chosen) else {
        return;
    };
    egui::ComboBox::from_id_salt("narrow-view")
        .selected_text(view_title(app, *current))
        .show_ui(ui, |ui| {
            for (k, kind) in views.iter().enumerate() {
                if ui
                    .selectable_label(k == chosen, view_title(app, *kind))
                    .clicked()
                {
                    commands.push(Command::from(ViewCommand::ShowNarrowView(k)));
                }
            }
        })
        .response
        .on_hover_text(tr(app, "view"));
}

/// What the switcher calls a view: a lab with a diagram of its own shows it where the w plane
/// would be.
fn view_title(app: &AppState, kind: ViewKind) -> String {
    if kind == ViewKind::WPlane
        && let Some(d) = app.sim().lab().page().diagrams(app.sim().params()).first()
    {
        return super::lab_tools::diagram_heading(app, d);
    }
    tr(app, kind.message())
}

/// The controls' sheet over the lower half of the page, when open: seed and speed, then
/// everything the wide page's left panel holds below its run buttons.
pub fn sheet(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    if !app.view().sheet_open {
        return;
    }
    let room = ui.ctx().content_rect();
    // Sideways, from the left (a sheet from the bottom would leave nothing above it).
    let panel = if is_short(ui.ctx()) {
        let w = room.width();
        egui::Panel::left("narrow_sheet")
            .resizable(true)
            .default_size(0.45 * w)
            .size_range(0.3 * w..=0.7 * w)
    } else {
        let h = room.height();
        egui::Panel::bottom("narrow_sheet")
            .resizable(true)
            .default_size(0.5 * h)
            .size_range(0.2 * h..=0.85 * h)
    };
    panel.show(ui, |ui| {
        ui.horizontal(|ui| {
            ui.strong(tr(app, "controls"));
            if ui.button(tr(app, "close")).clicked() {
                commands.push(Command::from(ViewCommand::SetSheet(false)));
            }
        });
        if app.lesson().is_some() {
            egui::Panel::bottom("narrow_lesson_navigation")
                .show(ui, |ui| super::lesson::navigation_bar(ui, app, commands));
        }
        egui::ScrollArea::vertical().show(ui, |ui| {
            if app.lesson().is_some() {
                super::lesson::card(ui, app, commands);
            }
            ui.horizontal_wrapped(|ui| controls::mode_buttons(ui, app, commands));
            controls::seed_and_speed(ui, app, commands);
            ui.separator();
            controls::body(ui, app, commands);
        });
    });
}

/// Styles `ui` for fingers: every button, slider and chip at least `TOUCH_TARGET_PX` high.
pub fn touch_style(ui: &mut Ui) {
    let zoom = ui.ctx().zoom_factor();
    let spacing = ui.spacing_mut();
    spacing.interact_size.y = TOUCH_TARGET_PX / zoom;
    spacing.button_padding = egui::vec2(8.0, 7.0);
    spacing.item_spacing = egui::vec2(8.0, 6.0);
}
