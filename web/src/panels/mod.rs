//! Panels: they read [`AppState`] and emit [`Command`]s, never changing the state
//! themselves. The generic lab panel serves every lab from its parameter specs and recorded
//! series; a lab that needs its own controls gets its own file here.

mod central;
mod controls;
mod keys;
mod lab_tools;
mod narrow;
mod sweeps;
mod tabs;

pub use central::central;
pub use controls::controls;
pub use keys::{shortcuts, tabs};
pub use narrow::{bar as narrow_bar, is_narrow, sheet as narrow_sheet, touch_style};

use crate::state::{AppState, Command, RunCommand};
use attlab::model::EstimatorStatus;

/// The status line at the bottom: a re-run or export under way (with its progress and a
/// button that stops it), time, rates, frame time, recorder memory and estimator health.
pub fn status_line(ui: &mut egui::Ui, app: &AppState, commands: &mut Vec<Command>) {
    egui::Panel::bottom("status").show(ui, |ui| {
        if let Some(job) = app.run().job() {
            ui.horizontal(|ui| {
                let done = job.progress();
                ui.add(
                    egui::ProgressBar::new(done as f32)
                        .desired_width(220.0)
                        .text(format!("{} · {:.0} %", job.title(), 100.0 * done)),
                );
                ui.label("the simulation holds meanwhile");
                if ui.small_button("Stop").clicked() {
                    commands.push(Command::from(RunCommand::CancelJob));
                }
            });
        }
        let colours = crate::render::palette::of(ui.visuals());
        ui.horizontal_wrapped(|ui| {
            let s = &app.run().stats;
            let rec = app.sim().recorder();
            if app.view().presenter || is_narrow(ui.ctx()) {
                // A room (or a phone) reads the time and the pace; the rest is for the engineer.
                ui.monospace(format!(
                    "t = {:7.2} s · ×{:.2} real time (×{} asked)",
                    app.sim().t_s(),
                    s.realtime,
                    app.run().speed
                ));
            } else {
                ui.monospace(format!(
                "t = {:8.2} s · step {:.1} ms · {:7.0} steps/s · ×{:.2} real time (×{} asked) · frame every {:5.1} ms · sim {:4.1} ms/frame · recorder {:.1} MiB ({} series, whole run)",
                app.sim().t_s(),
                app.sim().dt_s() * 1e3,
                s.steps_per_s,
                s.realtime,
                app.run().speed,
                s.frame_ms,
                s.step_ms,
                rec.memory_bytes() as f64 / f64::from(1 << 20),
                rec.specs().len(),
            ));
            }
            if s.behind {
                ui.colored_label(colours.warn, "· behind real time: lower the speed");
            }
            for (e, status) in app.sim().estimators().iter().zip(app.sim().statuses()) {
                match status {
                    EstimatorStatus::Ok => {}
                    EstimatorStatus::Diverged(why) => {
                        ui.colored_label(colours.error, format!("· {} diverged: {why} (press Reset)", e.id()));
                    }
                    EstimatorStatus::Unobservable(why) => {
                        ui.colored_label(colours.warn, format!("· {} unobservable: {why}", e.id()));
                    }
                }
            }
        });
    });
}
