//! The eframe glue: each frame advances the simulation within a time budget, lets the
//! panels draw the state and collect commands, then applies the commands in one place.

use crate::export::{Capture, Regions, Step};
use crate::panels;
use crate::platform;
use crate::render::body3d;
use crate::state::{
    AppState, Command, Effect, IoCommand, Message, PngTarget, RunCommand, STEP_BUDGET,
    SWEEP_BUDGET, UrlCommand, View, ViewCommand,
};
use attlab::model::ParamValues;
use attlab::page::{Lab, ViewKind};
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
    /// The theme set on the context last.
    themed: Option<attlab::state::Theme>,
    /// A PNG capture in progress.
    capture: Option<Capture>,
    /// Where the central area drew each part in the last frame.
    regions: Regions,
    /// The last PNG saved: name, width, height, bytes (published for the page test).
    last_png: Option<(String, usize, usize, usize)>,
    /// Text for the clipboard, copied after the frame.
    clipboard: Option<String>,
    /// A PNG export asked for, started after the frame.
    png_request: Option<PngTarget>,
    /// The keyboard was used after the last click or touch: the focus ring shows.
    keyboard_nav: bool,
    /// The live description of the run for a screen reader.
    narration: panels::Narration,
    /// The language the page's `<html lang>` says.
    lang_set: Option<attlab::i18n::Lang>,
    /// The page that embeds this one, driving it by `postMessage` (docs/embed.md).
    host: crate::host::HostLink,
}

impl AttLabApp {
    /// Creates the app, restoring lab, seed, speed and parameters from the URL fragment.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        setup_context(&cc.egui_ctx);
        // In the page, the controls are mirrored into the DOM for screen readers (the
        // desktop window has no mirror: eframe there would need its own AccessKit adapter).
        #[cfg(target_arch = "wasm32")]
        crate::a11y::Mirror::install(&cc.egui_ctx);
        // Back and Forward change the fragment with no input on the canvas: draw a frame to
        // read it.
        platform::repaint_on_history_moves(&cc.egui_ctx);
        let gpu_ready = cc.wgpu_render_state.as_ref().map(body3d::init).is_some();
        let mut app = Self::headless(AppState::from_fragment(&platform::initial_fragment()));
        app.gpu_ready = gpu_ready;
        app.host = crate::host::HostLink::install(&cc.egui_ctx);
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
            themed: None,
            capture: None,
            regions: Regions::default(),
            last_png: None,
            clipboard: None,
            png_request: None,
            keyboard_nav: false,
            narration: panels::Narration::default(),
            lang_set: None,
            host: crate::host::HostLink::default(),
        }
    }

    /// An app for `lab` with `params`, `seed` and `speed`, without a GPU.
    pub fn with_state(lab: &'static dyn Lab, params: ParamValues, seed: u64, speed: f64) -> Self {
        Self::headless(AppState::new(lab, params, seed, speed))
    }

    /// Applies `command` to the state and keeps what it asks of the app (a clipboard text,
    /// a PNG) for the end of the frame.
    pub fn apply(&mut self, command: Command) {
        match self.state.apply(command) {
            Some(Effect::Clipboard(text)) => self.clipboard = Some(text),
            Some(Effect::Png(target)) => self.png_request = Some(target),
            None => {}
        }
    }

    /// The text the last command put on the clipboard, if any (for tests: the page copies
    /// it at the end of the frame).
    pub fn clipboard(&self) -> Option<&str> {
        self.clipboard.as_deref()
    }

    /// Whether the 3D renderer is available.
    pub fn gpu_ready(&self) -> bool {
        self.gpu_ready
    }

    /// Frames drawn.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// The PNG capture in progress, for a test standing in for the renderer
    /// ([`Capture::deliver`]).
    pub fn capture_mut(&mut self) -> Option<&mut Capture> {
        self.capture.as_mut()
    }

    /// Where the last frame drew the views and the plot (for tests of the layout).
    pub fn regions(&self) -> &Regions {
        &self.regions
    }

    /// The last PNG saved: name, width, height and size in bytes.
    pub fn last_png(&self) -> Option<&(String, usize, usize, usize)> {
        self.last_png.as_ref()
    }

    /// One frame of UI: draw, collect commands, apply them.
    pub fn frame(&mut self, ui: &mut egui::Ui) {
        // A lab switched (or a link loaded) during a capture: its tabs are gone.
        if self
            .capture
            .as_ref()
            .is_some_and(|c| panels::tabs(&self.state) != c.lab_tabs())
        {
            self.capture = None;
            let stopped = Message::error(panels::tr_page(&self.state, "msg-png-lab-changed"));
            self.apply(Command::Notify(stopped));
        }
        let now = Instant::now();
        // The capture flag first: a tab the capture selects knows it is being captured.
        self.apply(ViewCommand::SetCapturing(self.capture.is_some()).into());
        let mut commands: Vec<Command> = match &self.capture {
            // Every part of a capture shows the same instant.
            Some(capture) if self.state.view().plots.tab != capture.tab() => vec![
                RunCommand::Hold(now).into(),
                ViewCommand::SelectTab(capture.tab()).into(),
            ],
            // A tab's re-run goes on while the capture waits for it.
            Some(_) => vec![
                RunCommand::Hold(now).into(),
                RunCommand::AdvanceJob(STEP_BUDGET).into(),
            ],
            None => vec![RunCommand::Advance(now).into()],
        };
        commands.extend([
            RunCommand::AdvanceSweep(SWEEP_BUDGET).into(),
            IoCommand::TakePickedLog.into(),
        ]);
        for c in commands.drain(..) {
            self.apply(c);
        }
        self.host.serve(&mut self.state);
        self.set_zoom_and_theme(ui.ctx());
        // A phone (upright or sideways) or an upright tablet: the phone's bar, one view
        // and the plot, the controls in a sheet.
        let narrow = panels::is_phone(ui.ctx());
        if narrow {
            panels::touch_style(ui);
        }
        panels::shortcuts(ui.ctx(), &self.state, &mut commands);
        panels::help_dialog(ui.ctx(), &self.state, &mut commands);
        panels::share_dialog(ui.ctx(), &self.state, &mut commands);
        panels::cycle_panel(ui.ctx(), &self.state, &mut commands);
        panels::link_problems(ui, &self.state, &mut commands);
        if self.state.view().embed {
            panels::embed_bar(ui, &self.state, &mut commands);
        } else {
            panels::status_line(ui, &self.state, &mut commands);
            panels::controls_for_the_screen(ui, &self.state, &mut commands);
        }
        panels::tiles(ui, &self.state);
        self.regions = Regions::default();
        panels::central(
            ui,
            &self.state,
            &mut self.view,
            &mut self.regions,
            self.gpu_ready,
            &mut commands,
        );
        for c in commands {
            self.apply(c);
        }
        panels::focus_ring(ui.ctx(), &mut self.keyboard_nav);
        self.run_capture(ui.ctx());
        if let Some(text) = self.clipboard.take() {
            ui.ctx().copy_text(text);
        }
        self.apply(UrlCommand::Sync.into());
        if let Some(text) = self.narration.due(&self.state, now) {
            crate::a11y::describe(&text);
        }
        self.host.report(&self.state, now, ui.ctx());
        self.frames += 1;
        self.publish(ui.ctx());
    }

    /// Presenter mode makes everything larger, and the theme follows the state (each set on
    /// a change only, so the reader's own zoom keys keep working in between).
    fn set_zoom_and_theme(&mut self, ctx: &egui::Context) {
        if self.zoomed_for != Some(self.state.view().presenter) {
            ctx.set_zoom_factor(if self.state.view().presenter {
                1.5
            } else {
                1.0
            });
            self.zoomed_for = Some(self.state.view().presenter);
        }
        let lang = self.state.view().lang();
        if self.lang_set != Some(lang) {
            // A screen reader picks its voice by the page's language, and hears the
            // mirror's words in it.
            platform::set_document_lang(lang.code());
            let word = |id: &str| attlab::i18n::t(lang, id);
            crate::a11y::Words::set(
                ctx,
                crate::a11y::Words {
                    dot: word("a11y-dot"),
                    double_dot: word("a11y-double-dot"),
                    resize_panel: word("a11y-resize-panel"),
                },
            );
            self.lang_set = Some(lang);
        }
        let theme = self.state.view().theme();
        if self.themed != Some(theme) {
            ctx.set_theme(match theme {
                attlab::state::Theme::Light => egui::Theme::Light,
                attlab::state::Theme::Dark => egui::Theme::Dark,
            });
            self.themed = Some(theme);
            crate::render::palette::panels_on_the_clear(ctx);
        }
    }

    /// What the page test reads (`window.attlabStatus`).
    fn publish(&self, ctx: &egui::Context) {
        platform::publish_status(&platform::Status {
            frames: self.frames,
            lab: self.state.sim().lab().id(),
            sim_steps: self.state.sim().steps(),
            recorder_bytes: self.state.sim().recorder().memory_bytes(),
            errors: &self.app_errors,
            last_png: self.last_png.as_ref(),
            lesson_step: self.state.lesson().map(|l| l.step),
            playing: self.state.run().playing,
            t_s: self.state.sim().t_s(),
            sweep_progress: self.state.sweep_progress(),
            sweep_timing: {
                let t = self.state.run().sweep_timing;
                (t.workers, t.wall_s)
            },
            sweep_values: (self.state.run().sweep.iter())
                .flat_map(|(_, s)| s.points.iter())
                .map(|p| {
                    p.objectives
                        .first()
                        .or(p.rms.first())
                        .copied()
                        .unwrap_or(f64::NAN)
                })
                .collect(),
            angles_rad: (self.state.sim().estimates().iter())
                .map(|e| e.angle_rad.unwrap_or(f64::NAN))
                .collect(),
            views: self
                .regions
                .views
                .iter()
                .map(|(k, r)| [*k as f32, r.min.x, r.min.y, r.width(), r.height()])
                .collect(),
            layout: self.regions.plot_area.map(|plot| {
                let xywh = |r: egui::Rect| [r.min.x, r.min.y, r.width(), r.height()];
                (xywh(ctx.content_rect()), xywh(plot), ctx.zoom_factor())
            }),
        });
    }

    /// Starts a PNG capture the panels asked for, or moves the running one on; a finished
    /// picture is saved like the CSV (a download in the page, a file on the desktop).
    fn run_capture(&mut self, ctx: &egui::Context) {
        if let Some(target) = self.png_request.take() {
            if self.capture.is_some() {
                let busy = Message::info(panels::tr_page(&self.state, "msg-png-busy"));
                self.apply(Command::Notify(busy));
            } else {
                let tabs = panels::tabs(&self.state);
                self.capture = Some(Capture::new(target, tabs, self.state.view().plots.tab));
            }
        }
        let Some(capture) = self.capture.as_mut() else {
            return;
        };
        if self.state.run().job().is_some() {
            // The tab shown is being re-run for its series: picture it when it has them.
            ctx.request_repaint();
            return;
        }
        let Step::Done(result) = capture.after_frame(ctx, &self.regions) else {
            return;
        };
        let target = capture.target();
        let restore = capture.restore_tab();
        self.capture = None;
        self.apply(ViewCommand::SetCapturing(false).into());
        if self.state.view().plots.tab != restore {
            self.apply(ViewCommand::SelectTab(restore).into());
        }
        let name = self.png_name(target);
        let lang = self.state.view().lang();
        let message = result.map_err(|e| e.message(lang)).and_then(|png| {
            let (w, h, n) = (png.width, png.height, png.bytes.len());
            let dir = self.state.io().save_dir.as_deref();
            let saved = platform::save_file(&name, "image/png", png.bytes, dir, lang)
                .map_err(|e| e.words(lang))?;
            self.last_png = Some((name.clone(), w, h, n));
            let args = [("saved", saved.into()), ("w", w.into()), ("h", h.into())];
            Ok(attlab::i18n::t_with(lang, "msg-png-saved", &args))
        });
        let message = match message {
            Ok(m) => Message::info(m),
            Err(e) => Message::error(attlab::i18n::t_with(
                lang,
                "msg-png-failed",
                &[("why", e.into())],
            )),
        };
        self.apply(Command::Notify(message));
    }

    /// `attlab-<lab>-seed<seed>-t<time>s-<what>.png`.
    fn png_name(&self, target: PngTarget) -> String {
        let lab = self.state.sim().lab();
        let what = match target {
            // A lab with a diagram of its own draws it where the w plane would be.
            PngTarget::View(k) => match lab.page().views.get(k) {
                Some(ViewKind::WPlane)
                    if !lab.page().diagrams(self.state.sim().params()).is_empty() =>
                {
                    "diagram".to_string()
                }
                Some(v) => v.slug().to_string(),
                None => format!("view{k}"),
            },
            PngTarget::Plots => "plots".to_string(),
        };
        format!(
            "attlab-{}-seed{}-t{:.0}s-{what}.png",
            lab.id(),
            self.state.sim().seed(),
            self.state.sim().t_s()
        )
    }
}

/// The page's fonts, and a press that counts as a click however long it is held: egui
/// takes a press over 0.8 s for a long touch (a context menu, which the page has none of),
/// and a lecturer's slow finger on a button had done nothing.
pub fn setup_context(ctx: &egui::Context) {
    crate::render::fonts::install(ctx);
    ctx.options_mut(|o| o.input_options.max_click_duration = f64::INFINITY);
}

impl eframe::App for AttLabApp {
    fn clear_color(&self, visuals: &egui::Visuals) -> [f32; 4] {
        crate::render::palette::clear_colour(visuals).to_normalized_gamma_f32()
    }

    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.frame(ui);
        let run = self.state.run();
        if run.playing || run.sweeping() || run.job().is_some() || self.state.travel_busy() {
            ui.ctx().request_repaint();
        }
    }
}
