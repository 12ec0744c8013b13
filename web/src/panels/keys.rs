//! Keyboard shortcuts (listed in the help): space pause/resume, r reset, s single step,
//! ←/→ the previous/next plot tab, f one view at full size (each view, the plots, all),
//! p a PNG (of the view shown alone, else of every plot tab).
//! Ignored while a text field has the keyboard.

use crate::render::plots;
use crate::state::{AppState, Command, Focus, IoCommand, PngTarget, RunCommand, ViewCommand};
use attlab::model::PlotTab;
use egui::Key;

/// Turns this frame's key presses into commands.
pub fn shortcuts(ctx: &egui::Context, app: &AppState, commands: &mut Vec<Command>) {
    if ctx.egui_wants_keyboard_input() {
        return;
    }
    let pressed = |k: Key| ctx.input(|i| i.key_pressed(k) && i.modifiers.is_none());
    if pressed(Key::Space) {
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
    for (key, delta) in [(Key::ArrowLeft, -1), (Key::ArrowRight, 1)] {
        if pressed(key)
            && let Some(tab) = neighbour_tab(app, delta)
        {
            commands.push(Command::from(ViewCommand::SelectTab(tab)));
        }
    }
}

/// Every tab in the order the tab row shows them: the lab's figures, then the groups.
pub fn tabs(app: &AppState) -> Vec<PlotTab> {
    let figures = (0..app.sim().lab().page().figures.len()).map(PlotTab::Figure);
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
