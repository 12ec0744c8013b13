//! Lab tools shown only for labs that offer them: parameter sweeps (with a progress bar,
//! computed a slice per frame) and the laboratory mode that replays a recorded gyro log.

use super::Command;
use crate::app::AttLabApp;
use crate::render::plots::source_color;
use attlab::sensors::{RateUnit, TimeUnit};
use egui::Ui;
use egui_plot::{Legend, Line, Plot, Points};

/// The lab's sweeps: run/cancel, progress, and RMS against the swept value (log axis).
pub fn sweeps(ui: &mut Ui, app: &AttLabApp, commands: &mut Vec<Command>) {
    for (i, spec) in app.sim.lab().sweeps().iter().enumerate() {
        egui::CollapsingHeader::new(format!("Sweep: {}", spec.title)).default_open(true).show(ui, |ui| {
            let running = app.sweep.as_ref().filter(|(j, _)| *j == i).map(|(_, s)| s);
            match running {
                Some(s) if !s.is_done() => {
                    ui.add(egui::ProgressBar::new(s.progress() as f32).show_percentage());
                    if ui.button("Cancel").clicked() {
                        commands.push(Command::CancelSweep);
                    }
                }
                _ => {
                    if ui.button("Run sweep").on_hover_text("One run per value with the current parameters; the page stays live").clicked() {
                        commands.push(Command::RunSweep(i));
                    }
                }
            }
            let Some(s) = running else { return };
            for (k, series) in spec.series.iter().enumerate() {
                if let Some((value, rms)) = s.best(k) {
                    ui.label(format!("best for {series}: {} = {value} ({rms:.4} rms)", spec.key));
                }
            }
            Plot::new(("sweep", i)).height(170.0).legend(Legend::default().text_style(egui::TextStyle::Small)).x_axis_label(format!("log10 {}", spec.key)).show(ui, |plot| {
                for (k, series) in spec.series.iter().enumerate() {
                    let pts: Vec<[f64; 2]> = s.points.iter().filter(|p| p.value > 0.0).map(|p| [p.value.log10(), p.rms[k]]).collect();
                    let color = source_color(k + 1);
                    plot.line(Line::new(*series, pts.clone()).color(color));
                    plot.points(Points::new(*series, pts).radius(3.0).color(color));
                    if let Some((value, rms)) = s.best(k).filter(|(v, _)| *v > 0.0) {
                        plot.points(Points::new(format!("best {series}"), vec![[value.log10(), rms]]).radius(7.0).color(color).filled(false));
                    }
                }
            });
        });
    }
}

/// Loading a recorded gyro log (CSV: time, rate) for labs that accept one.
pub fn laboratory_mode(ui: &mut Ui, app: &mut AttLabApp, commands: &mut Vec<Command>) {
    if !app.sim.lab().accepts_rate_log() {
        return;
    }
    egui::CollapsingHeader::new("Laboratory mode: recorded gyro log").default_open(false).show(ui, |ui| {
        ui.label("CSV lines `time, rate` (comma, semicolon, tab or space separated). Bad lines are listed with their numbers and skipped.");
        ui.horizontal(|ui| {
            egui::ComboBox::from_label("rate").selected_text(unit_name(app.log_units.0)).show_ui(ui, |ui| {
                for (u, name) in RateUnit::ALL {
                    ui.selectable_value(&mut app.log_units.0, u, name);
                }
            });
            egui::ComboBox::from_label("time").selected_text(if app.log_units.1 == TimeUnit::Seconds { "s" } else { "ms" }).show_ui(ui, |ui| {
                ui.selectable_value(&mut app.log_units.1, TimeUnit::Seconds, "s");
                ui.selectable_value(&mut app.log_units.1, TimeUnit::Milliseconds, "ms");
            });
        });
        ui.horizontal(|ui| {
            if ui.button("Load gyro log…").clicked() {
                commands.push(Command::LoadLog);
            }
            if let Some((name, n)) = &app.replaying {
                ui.label(format!("replaying {name} ({n} samples)"));
                if ui.button("Back to simulation").clicked() {
                    commands.push(Command::EndReplay);
                }
            }
        });
    });
}

fn unit_name(u: RateUnit) -> &'static str {
    RateUnit::ALL
        .iter()
        .find(|(v, _)| *v == u)
        .map_or("?", |(_, n)| n)
}
