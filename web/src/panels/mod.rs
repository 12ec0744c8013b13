//! Panels: they read [`AppState`] and emit [`Command`](crate::state::Command)s, never changing the state
//! themselves. The generic lab panel serves every lab from its parameter specs and recorded
//! series; a lab that needs its own controls gets its own file here.

mod central;
mod controls;
mod keys;
mod lab_tools;
mod sweeps;

pub use central::central;
pub use controls::controls;
pub use keys::{shortcuts, tabs};

use crate::state::AppState;
use attlab::model::EstimatorStatus;

/// The status line at the bottom: time, rates, frame time, recorder memory and estimator
/// health.
pub fn status_line(ui: &mut egui::Ui, app: &AppState) {
    egui::Panel::bottom("status").show(ui, |ui| {
        ui.horizontal_wrapped(|ui| {
            let s = &app.run().stats;
            let rec = app.sim().recorder();
            ui.monospace(format!(
                "t = {:8.2} s · step {:.1} ms · {:7.0} steps/s (×{} requested) · frame {:5.1} ms · sim {:4.1} ms/frame · recorder {:.1} MiB ({} series, whole run)",
                app.sim().t_s(),
                app.sim().dt_s() * 1e3,
                s.steps_per_s,
                app.run().speed,
                s.frame_ms,
                s.step_ms,
                rec.memory_bytes() as f64 / f64::from(1 << 20),
                rec.specs().len(),
            ));
            if s.behind {
                ui.colored_label(egui::Color32::YELLOW, "· behind real time: lower the speed");
            }
            for (e, status) in app.sim().estimators().iter().zip(app.sim().statuses()) {
                match status {
                    EstimatorStatus::Ok => {}
                    EstimatorStatus::Diverged(why) => {
                        ui.colored_label(egui::Color32::LIGHT_RED, format!("· {} diverged: {why} (press Reset)", e.id()));
                    }
                    EstimatorStatus::Unobservable(why) => {
                        ui.colored_label(egui::Color32::YELLOW, format!("· {} unobservable: {why}", e.id()));
                    }
                }
            }
        });
    });
}
