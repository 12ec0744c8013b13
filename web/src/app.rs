//! The eframe glue: each frame advances the simulation within a time budget, lets the
//! panels draw the state and collect commands, then applies the commands in one place.

use crate::panels;
use crate::platform;
use crate::render::body3d;
use crate::state::{AppState, Command, SWEEP_BUDGET, View};
use attlab::model::{Lab, ParamValues};
use web_time::Instant;

/// The app: the state, the widgets' view, and what only the frame loop needs.
pub struct AttLabApp {
    /// Everything the panels read.
    pub state: AppState,
    /// Widget-owned view (camera, sphere).
    pub view: View,
    gpu_ready: bool,
    app_errors: Vec<String>,
    frames: u64,
    zoomed_for: Option<bool>,
}

impl AttLabApp {
    /// Creates the app, restoring lab, seed, speed and parameters from the URL fragment.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        crate::render::fonts::install(&cc.egui_ctx);
        // The 3D view and the sphere are drawn on dark panels, and the truth is drawn in
        // white: the whole app is dark.
        cc.egui_ctx.set_theme(egui::Theme::Dark);
        let gpu_ready = cc.wgpu_render_state.as_ref().map(body3d::init).is_some();
        let mut app = Self::headless(AppState::from_fragment(&platform::initial_fragment()));
        app.gpu_ready = gpu_ready;
        if !gpu_ready {
            app.app_errors
                .push("no wgpu render state: the 3D view is disabled".into());
        }
        app
    }

    /// An app around `state` without a GPU (tests, headless use).
    pub fn headless(state: AppState) -> Self {
        Self {
            state,
            view: View::default(),
            gpu_ready: false,
            app_errors: Vec::new(),
            frames: 0,
            zoomed_for: None,
        }
    }

    /// An app for `lab` with `params`, `seed` and `speed`, without a GPU.
    pub fn with_state(lab: &'static dyn Lab, params: ParamValues, seed: u64, speed: f64) -> Self {
        Self::headless(AppState::new(lab, params, seed, speed))
    }

    /// Whether the 3D renderer is available.
    pub fn gpu_ready(&self) -> bool {
        self.gpu_ready
    }

    /// Frames drawn.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// One frame of UI: draw, collect commands, apply them.
    pub fn frame(&mut self, ui: &mut egui::Ui) {
        self.state.advance(Instant::now());
        self.state.advance_sweep(SWEEP_BUDGET);
        self.state.take_picked_log();
        let mut commands: Vec<Command> = Vec::new();
        // Presenter mode: everything larger (set on a change only, so the reader's own zoom
        // keys keep working in between).
        if self.zoomed_for != Some(self.state.presenter) {
            ui.ctx()
                .set_zoom_factor(if self.state.presenter { 1.5 } else { 1.0 });
            self.zoomed_for = Some(self.state.presenter);
        }
        panels::shortcuts(ui.ctx(), &self.state, &mut commands);
        panels::status_line(ui, &self.state);
        panels::controls(ui, &self.state, &mut commands);
        panels::central(
            ui,
            &self.state,
            &mut self.view,
            self.gpu_ready,
            &mut commands,
        );
        for c in commands {
            self.state.apply(c);
        }
        if let Some(text) = self.state.clipboard.take() {
            ui.ctx().copy_text(text);
        }
        self.state.sync_url();
        self.frames += 1;
        platform::publish_status(&platform::Status {
            frames: self.frames,
            lab: self.state.sim.lab().id(),
            sim_steps: self.state.sim.steps(),
            recorder_bytes: self.state.sim.recorder().memory_bytes(),
            errors: &self.app_errors,
        });
    }
}

impl eframe::App for AttLabApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.frame(ui);
        let sweeping = self.state.sweep.as_ref().is_some_and(|(_, s)| !s.is_done());
        if self.state.playing || sweeping {
            ui.ctx().request_repaint();
        }
    }
}
