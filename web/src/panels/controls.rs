//! The left panel: lab picker, run controls, parameter sliders generated from the lab's
//! parameter specs, export and the explanation.

use crate::state::{AppState, Command, IoCommand, PngTarget, RunCommand, UrlCommand, ViewCommand};
use attlab::labs;
use attlab::model::{ParamKind, ParamSpec, Scale};
use attlab::state::Theme;
use egui::{RichText, Ui};

/// Draws the left panel and collects commands (on a wide screen; a narrow one gets
/// `narrow`'s bar and sheet instead).
pub fn controls(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    // Presenter mode: a narrow panel, so the views keep the projector's width.
    let panel = if app.view().presenter {
        egui::Panel::left("controls_presenter").exact_size(230.0)
    } else {
        egui::Panel::left("controls")
            .resizable(true)
            .default_size(300.0)
    };
    panel.show(ui, |ui| {
        egui::ScrollArea::vertical().show(ui, |ui| {
            ui.heading("Attitude Lab");
            lab_picker(ui, app, commands);
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
    if app.view().presenter {
        // For the projector: the presets carry the lesson; the sliders wait behind one click.
        presets(ui, app, commands);
        egui::CollapsingHeader::new("All parameters")
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

pub(super) fn lab_picker(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let current = app.sim().lab();
    egui::ComboBox::from_label("Lab")
        .selected_text(current.title())
        .width(220.0)
        .show_ui(ui, |ui| {
            for lab in labs::all() {
                if ui
                    .selectable_label(lab.id() == current.id(), lab.title())
                    .clicked()
                    && lab.id() != current.id()
                {
                    commands.push(Command::from(RunCommand::SelectLab(*lab)));
                }
            }
        });
    ui.label(RichText::new(current.paper()).small().italics());
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
        let label = if app.run().playing {
            "Pause"
        } else {
            "▶ Play"
        };
        if ui.button(label).clicked() {
            commands.push(Command::from(RunCommand::SetPlaying(!app.run().playing)));
        }
        if ui
            .add_enabled(!app.run().playing, egui::Button::new("Step"))
            .clicked()
        {
            commands.push(Command::from(RunCommand::StepOnce));
        }
        if ui
            .button("⟲ Reset")
            .on_hover_text("Restart at t = 0 with the seed below")
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
            .selectable_label(app.view().presenter, "Presenter")
            .on_hover_text("For a projector: large type, thick lines, the presets only (also `presenter=1` in the link)")
            .clicked()
        {
            commands.push(Command::from(ViewCommand::SetPresenter(!app.view().presenter)));
        }
        let light = app.view().theme() == Theme::Light;
        if ui
            .selectable_label(light, "Light")
            .on_hover_text("Light panels in dark type, for a projector (the default in presenter mode; also `theme=light` or `theme=dark` in the link)")
            .clicked()
        {
            let next = if light { Theme::Dark } else { Theme::Light };
            commands.push(Command::from(ViewCommand::SetTheme(Some(next))));
        }
    }
}

/// The seed (with New seed) and the speed slider.
pub(super) fn seed_and_speed(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    ui.horizontal(|ui| {
        let label = ui.label("Seed");
        let mut seed = app.run().seed;
        if ui
            .add(egui::DragValue::new(&mut seed).range(0..=u64::MAX))
            .labelled_by(label.id)
            .changed()
        {
            commands.push(Command::from(RunCommand::SetSeed(seed)));
        }
        if ui
            .button("New seed")
            .on_hover_text("A random seed, then Reset")
            .clicked()
        {
            commands.push(Command::from(RunCommand::NewSeed));
        }
    });
    let (lo, hi) = attlab::state::SPEED_RANGE;
    let mut speed = app.run().speed;
    if ui
        .add(
            egui::Slider::new(&mut speed, lo..=hi)
                .logarithmic(true)
                .text("speed ×")
                .max_decimals(1),
        )
        .changed()
    {
        commands.push(Command::from(RunCommand::SetSpeed(speed)));
    }
}

fn presets(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let presets = app.sim().lab().presets();
    if !presets.is_empty() {
        ui.horizontal_wrapped(|ui| {
            ui.label("Presets:");
            for (i, preset) in presets.iter().enumerate() {
                if ui
                    .button(preset.name)
                    .on_hover_text(format!(
                        "{} — parameters marked 'applies at Reset' need Reset",
                        preset.help
                    ))
                    .clicked()
                {
                    commands.push(Command::from(RunCommand::ApplyPreset(i)));
                }
            }
        });
    }
}

fn parameters(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    ui.horizontal(|ui| {
        ui.strong("Parameters");
        if ui.small_button("defaults").clicked() {
            commands.push(Command::from(RunCommand::RestoreDefaults));
        }
    });
    if !app.view().presenter {
        presets(ui, app, commands);
    }
    for spec in app.sim().lab().params() {
        let value = app.sim().params().get(spec.key);
        let active = spec
            .requires
            .is_none_or(|k| app.sim().params().get(k) != 0.0);
        let changed = ui
            .add_enabled_ui(active, |ui| param_widget(ui, spec, value))
            .inner;
        if let Some(v) = changed {
            commands.push(Command::from(RunCommand::SetParam(spec.key, v)));
        }
    }
    pending_reset(ui, app, commands);
}

/// A line naming the reset-only parameters that were moved and wait for Reset, with the
/// button that applies them (until then the run goes on unchanged).
fn pending_reset(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let pending = app.sim().pending_reset();
    if pending.is_empty() {
        return;
    }
    let specs = app.sim().lab().params();
    let labels: Vec<&str> = pending
        .iter()
        .filter_map(|k| specs.iter().find(|s| s.key == *k).map(|s| s.label))
        .collect();
    ui.horizontal_wrapped(|ui| {
        ui.label(format!("Waiting for Reset: {}.", labels.join(", ")));
        if ui
            .small_button("Reset now")
            .on_hover_text("Restart from t = 0 with these values")
            .clicked()
        {
            commands.push(Command::from(RunCommand::Reset));
        }
    });
}

/// One widget for one parameter; returns the new value if the user changed it.
pub(super) fn param_widget(ui: &mut Ui, spec: &ParamSpec, value: f64) -> Option<f64> {
    let mut v = value;
    let hint = if spec.needs_reset {
        format!("{} (applies at Reset)", spec.help)
    } else {
        spec.help.to_string()
    };
    let response = match spec.kind {
        ParamKind::Toggle => {
            let mut on = v >= 0.5;
            let r = ui.checkbox(&mut on, spec.label);
            v = if on { 1.0 } else { 0.0 };
            r
        }
        ParamKind::Choice(options) => {
            let mut index = v.max(0.0) as usize;
            let selected = options.get(index).copied().unwrap_or("?");
            let r = egui::ComboBox::from_label(spec.label)
                .selected_text(selected)
                .show_index(ui, &mut index, options.len(), |i| options[i]);
            v = index as f64;
            r
        }
        ParamKind::Real | ParamKind::Integer => {
            let mut slider = egui::Slider::new(&mut v, spec.min..=spec.max)
                .text(spec.label)
                .logarithmic(spec.scale == Scale::Log && spec.min > 0.0);
            if spec.scale == Scale::Log && spec.min == 0.0 {
                slider = slider.logarithmic(true).smallest_positive(1e-4);
            }
            if !spec.unit.is_empty() {
                slider = slider.suffix(format!(" {}", spec.unit));
            }
            if spec.kind == ParamKind::Integer {
                slider = slider.integer();
            }
            ui.add(slider)
        }
    };
    let response = if hint.is_empty() {
        response
    } else {
        response.on_hover_text(hint)
    };
    (response.changed() && v != value).then_some(v)
}

fn outputs(ui: &mut Ui, app: &AppState, commands: &mut Vec<Command>) {
    let with_attitude: Vec<(usize, &str)> = app
        .sim()
        .estimators()
        .iter()
        .zip(app.sim().estimates())
        .enumerate()
        .filter(|(_, (_, est))| est.quaternion().is_some())
        .map(|(i, (e, _))| (i, e.label()))
        .collect();
    if !with_attitude.is_empty() {
        let current = with_attitude
            .iter()
            .find(|(i, _)| *i == app.view().ghost_index)
            .map_or("—", |x| x.1);
        egui::ComboBox::from_label("3D ghost")
            .selected_text(current)
            .show_ui(ui, |ui| {
                for (i, label) in &with_attitude {
                    if ui
                        .selectable_label(*i == app.view().ghost_index, *label)
                        .clicked()
                    {
                        commands.push(Command::from(ViewCommand::SetGhost(*i)));
                    }
                }
            });
    }
    ui.horizontal(|ui| {
        if ui
            .button("Export CSV")
            .on_hover_text("Every series at every step since t = 0 (the run is re-simulated exactly; empty cells are missing samples)")
            .clicked()
        {
            commands.push(Command::from(IoCommand::ExportCsv));
        }
        if ui.button("Copy link").on_hover_text("A link that restores lab, seed, speed and parameters").clicked() {
            commands.push(Command::from(UrlCommand::CopyLink));
        }
        if ui
            .button("Copy as Python")
            .on_hover_text("A pandas + matplotlib snippet that loads the exported CSV and draws the plot tab on screen")
            .clicked()
        {
            commands.push(Command::from(IoCommand::CopyPython));
        }
        if ui
            .add_enabled(!app.view().capturing, egui::Button::new("PNG of the plots"))
            .on_hover_text("Every plot tab at this instant, one below the other, in one PNG (key p). A view shows its own PNG button when the pointer is over it.")
            .clicked()
        {
            commands.push(Command::from(IoCommand::ExportPng(PngTarget::Plots)));
        }
    });
    if app.sim().lab().output_file(app.sim().params()).is_some()
        && ui
            .button("Export the paper's output file")
            .on_hover_text("The paper's own rows (t, angle₁, angle₂, angle₃), re-run from t = 0 with the current parameters, ending at the first row within tolerance")
            .clicked()
    {
        commands.push(Command::from(IoCommand::ExportOutputFile));
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
            ui.colored_label(color, &m.text);
        });
    }
}

fn explanation(ui: &mut Ui, app: &AppState) {
    egui::CollapsingHeader::new("What am I looking at?")
        .default_open(false)
        .show(ui, |ui| {
            ui.label(app.sim().lab().summary());
            ui.add_space(4.0);
            ui.label(RichText::new(super::keys::HELP).small().strong());
            ui.add_space(4.0);
            ui.label(RichText::new(
            "Frames: reference ζ up; body ξ′ right, η′ forward, ζ′ up. The sphere shows the \
             vertical k = (a′, b′, c′) in body axes; the ray from the pole S through k meets the \
             body plane at w = u + jv = (a′ + jb′)/(1 + c′). |w| = 1 is pitch ±90°; w → ∞ is \
             upside down, where the (u, v, z) integrator switches to s = 1/w.",
        ).small());
        });
}
