//! The live-sensors part of a lab's laboratory mode (labs that read an IMU log): this
//! phone's gyro and accelerometer, or an Arduino over Web Serial, driving the estimators as
//! the samples arrive; the rate measured, "zero", stop, and the record saved as CSV.

use super::{arg, tr, tr_with};
use crate::state::{AppState, BAUDS, Command, LiveCommand, LiveSource};
use egui::Ui;

/// The live section, for a lab whose log format is the IMU's.
pub fn live_sensors(ui: &mut Ui, app: &AppState) -> Vec<Command> {
    let mut commands = Vec::new();
    let mut push = |c: LiveCommand| commands.push(Command::from(c));
    ui.separator();
    ui.label(egui::RichText::new(tr(app, "live-title")).strong());
    let Some(live) = app.live() else {
        ui.label(egui::RichText::new(tr(app, "live-help")).small());
        ui.horizontal_wrapped(|ui| {
            if ui.button(tr(app, "live-phone")).clicked() {
                push(LiveCommand::Start(LiveSource::Phone));
            }
            let id = ui.scope_id().with("baud");
            let mut baud = ui.data_mut(|d| *d.get_temp_mut_or(id, 115_200u32));
            egui::ComboBox::new(id, tr(app, "live-baud"))
                .selected_text(baud.to_string())
                .show_ui(ui, |ui| {
                    for b in BAUDS {
                        ui.selectable_value(&mut baud, b, b.to_string());
                    }
                });
            ui.data_mut(|d| d.insert_temp(id, baud));
            if ui.button(tr(app, "live-serial")).clicked() {
                push(LiveCommand::Start(LiveSource::Serial(baud)));
            }
        });
        return commands;
    };
    let source = match live.source {
        LiveSource::Phone => tr(app, "live-phone-source"),
        LiveSource::Serial(baud) => tr_with(app, "live-serial-source", &[("baud", baud.into())]),
    };
    let state = if live.running {
        tr_with(app, "live-rate", &[("rate", live.rate_hz().into())])
    } else {
        tr(app, "live-ended")
    };
    ui.label(tr_with(
        app,
        "live-status",
        &[
            ("source", arg(source)),
            ("api", arg(&live.api)),
            ("state", arg(state)),
            ("n", live.recorded().into()),
            ("rejected", live.rejected().into()),
        ],
    ));
    ui.horizontal_wrapped(|ui| {
        if live.can_zero() && ui.button(tr(app, "live-zero")).clicked() {
            push(LiveCommand::Zero);
        }
        if live.running && ui.button(tr(app, "live-stop")).clicked() {
            push(LiveCommand::Stop);
        }
        if ui.button(tr(app, "live-save")).clicked() {
            push(LiveCommand::SaveRecord);
        }
        if ui.button(tr(app, "back-to-simulation")).clicked() {
            push(LiveCommand::Leave);
        }
    });
    commands
}
