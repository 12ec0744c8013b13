//! Panels. The generic lab panel serves every lab from its parameter specs and recorded
//! series; a lab that needs its own controls gets its own file here.

mod central;
mod controls;
mod lab_tools;

pub use central::central;
pub use controls::controls;

use crate::app::AttLabApp;
use attlab::estimators::EstimatorStatus;
use attlab::labs::Lab;

/// What a panel asks the app to do (applied after drawing).
#[derive(Clone, Copy)]
pub enum Command {
    /// Switch lab (parameters to its defaults).
    SelectLab(&'static dyn Lab),
    /// Change one parameter.
    SetParam(&'static str, f64),
    /// All parameters back to their defaults.
    RestoreDefaults,
    /// Restart with the current seed.
    Reset,
    /// One step while paused.
    StepOnce,
    /// Save the recorded series as CSV.
    ExportCsv,
    /// Remove message `i`.
    Dismiss(usize),
    /// Start the lab's sweep `i`.
    RunSweep(usize),
    /// Stop the running sweep.
    CancelSweep,
    /// Ask for a gyro log file to replay.
    LoadLog,
    /// Leave the replay and simulate again.
    EndReplay,
}

/// The status line at the bottom: time, rates, frame time and estimator health.
pub fn status_line(ui: &mut egui::Ui, app: &AttLabApp) {
    egui::Panel::bottom("status").show(ui, |ui| {
        ui.horizontal_wrapped(|ui| {
            let s = &app.stats;
            ui.monospace(format!(
                "t = {:8.2} s · step {:.1} ms · {:7.0} steps/s (×{} requested) · frame {:5.1} ms · sim {:4.1} ms/frame",
                app.sim.t_s(),
                app.sim.dt_s() * 1e3,
                s.steps_per_s,
                app.speed,
                s.frame_ms,
                s.step_ms
            ));
            if s.behind {
                ui.colored_label(egui::Color32::YELLOW, "· behind real time: lower the speed");
            }
            for ((id, _, _), status) in app.sim.estimates().iter().zip(app.sim.statuses()) {
                match status {
                    EstimatorStatus::Ok => {}
                    EstimatorStatus::Diverged(why) => {
                        ui.colored_label(egui::Color32::LIGHT_RED, format!("· {id} diverged: {why} (press Reset)"));
                    }
                    EstimatorStatus::Unobservable(why) => {
                        ui.colored_label(egui::Color32::YELLOW, format!("· {id} unobservable: {why}"));
                    }
                }
            }
        });
    });
}
