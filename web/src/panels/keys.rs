//! Keyboard: the page's shortcuts (space pause/resume, r reset, s single step, ←/→ the
//! previous/next plot tab, in a lesson PageUp/PageDown or ←/→ the previous/next step and
//! Shift+←/→ the tabs, f one view at full size, p a PNG, ? or F1 this list) and the
//! dialog that lists them with the keys of the controls (Tab, Enter, a slider's keys).
//! A letter is ignored while a text field has the keyboard; space and the arrows belong to
//! the control that has the keyboard, if any (Esc leaves it).

use super::tr;
use crate::render::plots;
use crate::state::{
    AppState, Command, Focus, IoCommand, LessonCommand, PngTarget, RunCommand, ViewCommand,
};
use attlab::model::PlotTab;
use egui::Key;

/// Turns this frame's key presses into commands.
pub fn shortcuts(ctx: &egui::Context, app: &AppState, commands: &mut Vec<Command>) {
    if ctx.text_edit_focused() {
        return;
    }
    let help = ctx.input(|i| {
        i.key_pressed(Key::F1)
            || i.events
                .iter()
                .any(|e| matches!(e, egui::Event::Text(t) if t == "?"))
    });
    if help {
        commands.push(Command::from(ViewCommand::SetKeysHelp(
            !app.view().keys_help,
        )));
        return;
    }
    if app.view().keys_help {
        // The dialog has the keyboard: Esc (or its button) closes it.
        return;
    }
    let pressed = |k: Key| ctx.input(|i| i.key_pressed(k) && i.modifiers.is_none());
    // Space presses a focused button, and the arrows move a focused slider.
    let control_has_keys = ctx.memory(|m| m.focused().is_some());
    if pressed(Key::Space) && !control_has_keys {
        commands.push(Command::from(RunCommand::SetPlaying(!app.run().playing)));
    }
    if pressed(Key::R) {
        commands.push(Command::from(RunCommand::Reset));
    }
    if pressed(Key::S) {
        if app.run().playing {
            commands.push(Command::from(RunCommand::SetPlaying(false)));
        }
        commands.push(Command::from(RunCommand::StepOnce));
    }
    if pressed(Key::F) {
        commands.push(Command::from(ViewCommand::CycleFocus));
    }
    if pressed(Key::P) {
        commands.push(Command::from(IoCommand::ExportPng(
            match app.view().focus {
                Focus::View(k) => PngTarget::View(k),
                Focus::All | Focus::Plots => PngTarget::Plots,
            },
        )));
    }
    if !control_has_keys {
        steps_and_tabs(ctx, app, commands);
    }
}

/// The arrows and the page keys: outside a lesson ←/→ move the plot tab; in a lesson the
/// keys a presenter's clicker sends walk its steps (PageDown or →, PageUp or ←), and the
/// plot tabs move with Shift+←/→.
fn steps_and_tabs(ctx: &egui::Context, app: &AppState, commands: &mut Vec<Command>) {
    let pressed = |k: Key| ctx.input(|i| i.key_pressed(k) && i.modifiers.is_none());
    let shifted = |k: Key| {
        ctx.input(|i| i.key_pressed(k) && i.modifiers.matches_exact(egui::Modifiers::SHIFT))
    };
    let lesson = app.lesson().map(|l| l.step);
    let steps = app.sim().lab().lesson().map_or(0, |l| l.steps.len());
    for ([page, arrow], delta) in [
        ([Key::PageUp, Key::ArrowLeft], -1),
        ([Key::PageDown, Key::ArrowRight], 1),
    ] {
        if let Some(n) = lesson {
            if pressed(page) || pressed(arrow) {
                let next = n
                    .checked_add_signed(delta)
                    .filter(|m| (1..=steps).contains(m));
                commands.extend(next.map(|m| Command::from(LessonCommand::Go(m))));
                continue;
            }
            if !shifted(arrow) {
                continue;
            }
        } else if !pressed(arrow) {
            continue;
        }
        if let Some(tab) = neighbour_tab(app, delta) {
            commands.push(Command::from(ViewCommand::SelectTab(tab)));
        }
    }
}

/// The ring around the control that has the keyboard, shown while the keyboard is in use
/// (a Tab or an arrow since the last click or touch), as a browser's `:focus-visible`.
/// `keyboard` remembers which was used last.
pub fn focus_ring(ctx: &egui::Context, keyboard: &mut bool) {
    let (keys, pointer) = ctx.input(|i| {
        let keys = i.events.iter().any(|e| {
            matches!(e, egui::Event::Key { key, pressed: true, .. }
                if matches!(key, Key::Tab | Key::ArrowLeft | Key::ArrowRight
                    | Key::ArrowUp | Key::ArrowDown | Key::Home | Key::End
                    | Key::PageUp | Key::PageDown))
        });
        let touched = i
            .events
            .iter()
            .any(|e| matches!(e, egui::Event::Touch { .. }));
        (keys, i.pointer.any_pressed() || touched)
    });
    if pointer {
        *keyboard = false;
    } else if keys {
        *keyboard = true;
    }
    let focused = ctx.memory(|m| m.focused());
    let Some(response) = focused
        .filter(|_| *keyboard)
        .and_then(|id| ctx.read_response(id))
    else {
        return;
    };
    let colour = crate::render::palette::of_ctx(ctx).focus;
    let layer = egui::LayerId::new(egui::Order::Tooltip, egui::Id::unique("focus_ring"));
    ctx.layer_painter(layer).rect_stroke(
        response.rect.expand(2.0),
        3.0,
        egui::Stroke::new(2.5, colour),
        egui::StrokeKind::Outside,
    );
}

/// The keys, as the dialog lists them: (keys, what they do), message ids of the catalogue.
pub const KEYS: [(&str, &str); 13] = [
    ("keys-tab", "keys-tab-does"),
    ("keys-activate", "keys-activate-does"),
    ("keys-slider-arrows", "keys-slider-arrows-does"),
    ("keys-slider-pages", "keys-slider-pages-does"),
    ("keys-slider-ends", "keys-slider-ends-does"),
    ("keys-escape", "keys-escape-does"),
    ("keys-space", "keys-space-does"),
    ("keys-reset", "keys-reset-does"),
    ("keys-step", "keys-step-does"),
    ("keys-tabs", "keys-tabs-does"),
    ("keys-lesson", "keys-lesson-does"),
    ("keys-full", "keys-full-does"),
    ("keys-png", "keys-png-does"),
];

/// The keyboard dialog, while open: every key of the page in a table, closed by Esc, by
/// ? or F1 again, or by its button.
pub fn help_dialog(ctx: &egui::Context, app: &AppState, commands: &mut Vec<Command>) {
    if !app.view().keys_help {
        return;
    }
    let modal = egui::Modal::new(egui::Id::unique("keys_help")).show(ctx, |ui| {
        ui.set_max_width(560.0);
        ui.heading(tr(app, "keys-title"));
        ui.label(tr(app, "keys-intro"));
        ui.add_space(6.0);
        egui::Grid::new("keys_grid")
            .num_columns(2)
            .spacing([16.0, 6.0])
            .striped(true)
            .show(ui, |ui| {
                for (keys, does) in KEYS {
                    ui.strong(tr(app, keys));
                    ui.label(tr(app, does));
                    ui.end_row();
                }
            });
        ui.add_space(6.0);
        let close = ui.button(tr(app, "close"));
        if !close.has_focus() && ui.memory(|m| m.focused().is_none()) {
            close.request_focus();
        }
        close.clicked()
    });
    if modal.inner || modal.should_close() {
        commands.push(Command::from(ViewCommand::SetKeysHelp(false)));
    }
}

/// Every tab in the order the tab row shows them: the lab's figures, then the groups.
pub fn tabs(app: &AppState) -> Vec<PlotTab> {
    let figures = (app.sim().lab().page().figures.iter()).map(|f| PlotTab::Figure(f.id));
    let groups = plots::groups(app.sim().available_specs())
        .into_iter()
        .map(PlotTab::Group);
    figures.chain(groups).collect()
}

/// The tab `delta` places from the current one, wrapping around.
fn neighbour_tab(app: &AppState, delta: isize) -> Option<PlotTab> {
    let all = tabs(app);
    let n = all.len() as isize;
    if n == 0 {
        return None;
    }
    let at = all
        .iter()
        .position(|t| *t == app.view().plots.tab)
        .unwrap_or(0) as isize;
    all.get((at + delta).rem_euclid(n) as usize).copied()
}
