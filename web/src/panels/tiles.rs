//! Big numbers for the back row: in presenter mode, the values a lesson step names (the
//! current error, a covariance element) as large tiles above the views.

use super::{series_legend, tr};
use crate::state::AppState;
use egui::{RichText, Ui};

/// The strip of tiles, when presenter mode is on and the lesson step names values.
pub fn tiles(ui: &mut Ui, app: &AppState) {
    let Some(step) = app.lesson_step().filter(|s| !s.tiles.is_empty()) else {
        return;
    };
    if !app.view().presenter {
        return;
    }
    egui::Panel::top("lesson_tiles").show(ui, |ui| {
        ui.horizontal(|ui| {
            for key in step.tiles {
                let name = key.name();
                let spec = app.sim().specs().iter().find(|s| s.name == name);
                let value = app.sim().value(&name).ok().filter(|v| v.is_finite());
                egui::Frame::group(ui.style()).show(ui, |ui| {
                    ui.vertical(|ui| {
                        let label = spec.map_or(name.clone(), |s| series_legend(app, s));
                        ui.label(RichText::new(super::elide(&label, 44)).small())
                            .on_hover_text(label);
                        let text = value.map_or_else(|| tr(app, "tile-none"), super::cycle_num);
                        ui.label(RichText::new(text).size(34.0).strong());
                    });
                });
            }
        });
    });
}
