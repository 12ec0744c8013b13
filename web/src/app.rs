//! The app: owns the simulation, advances it within a per-frame time budget, and lays out
//! the panels. Panels read the simulation and send commands; they never step it.

use crate::panels::{self, Command};
use crate::platform;
use crate::render::{body3d, plots, riemann_sphere};
use attlab::labs::{self, Lab};
use attlab::params::ParamValues;
use attlab::sensors::{RateUnit, TimeUnit, parse_rate_log};
use attlab::sim::Simulation;
use attlab::state::UrlState;
use attlab::sweep::Sweep;
use web_time::{Duration, Instant};

/// Time the simulation may take per frame before it falls behind real time.
const STEP_BUDGET: Duration = Duration::from_millis(12);

/// Wall time per frame given to a background sweep.
const SWEEP_BUDGET: Duration = Duration::from_millis(10);

/// A message for the user (bad URL item, export result, divergence).
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    /// Text shown.
    pub text: String,
    /// Shown in red.
    pub is_error: bool,
}

/// Smoothed frame statistics for the status line.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Simulation steps per wall-clock second.
    pub steps_per_s: f64,
    /// Frame-to-frame time (ms).
    pub frame_ms: f64,
    /// Time spent stepping in the last frame (ms).
    pub step_ms: f64,
    /// The simulation could not keep up with the requested speed.
    pub behind: bool,
}

/// Everything the UI shows and changes.
pub struct AttLabApp {
    /// The running simulation.
    pub sim: Simulation,
    /// Seed used at the next reset.
    pub seed: u64,
    /// Running or paused.
    pub playing: bool,
    /// Simulated seconds per wall-clock second.
    pub speed: f64,
    /// 3D camera.
    pub camera: body3d::OrbitCamera,
    /// Sphere orientation.
    pub sphere: riemann_sphere::SphereView,
    /// Plot tab and options.
    pub plots: plots::PlotState,
    /// Which estimator the 3D ghost shows.
    pub ghost_index: usize,
    /// Messages for the user.
    pub messages: Vec<Message>,
    /// Show the explanation panel.
    pub show_explain: bool,
    /// Status line values.
    pub stats: Stats,
    /// A parameter sweep running in the background (index into the lab's sweeps, sweep).
    pub sweep: Option<(usize, Sweep)>,
    /// Units of a gyro log to load.
    pub log_units: (RateUnit, TimeUnit),
    /// Name and sample count of the log being replayed.
    pub replaying: Option<(String, usize)>,
    file_slot: platform::FileSlot,
    gpu_ready: bool,
    app_errors: Vec<String>,
    frames: u64,
    last_frame: Option<Instant>,
    step_debt: f64,
    last_fragment: String,
}

impl AttLabApp {
    /// Creates the app, restoring lab, seed, speed and parameters from the URL fragment.
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let gpu_ready = cc.wgpu_render_state.as_ref().map(body3d::init).is_some();
        let (state, errors) = UrlState::parse(&platform::initial_fragment());
        let lab = labs::find(state.lab_id).unwrap_or(labs::all()[0]);
        let mut app = Self::with_state(lab, state.params, state.seed, state.speed);
        app.gpu_ready = gpu_ready;
        if !gpu_ready {
            app.app_errors
                .push("no wgpu render state: the 3D view is disabled".into());
        }
        app.messages.extend(errors.into_iter().map(|e| Message {
            text: format!("{e} — ignored"),
            is_error: true,
        }));
        app
    }

    /// An app without a window (tests, headless use).
    pub fn with_state(lab: &'static dyn Lab, params: ParamValues, seed: u64, speed: f64) -> Self {
        Self {
            sim: Simulation::new(lab, params, seed),
            seed,
            playing: true,
            speed,
            camera: body3d::OrbitCamera::default(),
            sphere: riemann_sphere::SphereView::default(),
            plots: plots::PlotState {
                tab: default_tab(lab),
                ..plots::PlotState::default()
            },
            ghost_index: 0,
            messages: Vec::new(),
            show_explain: false,
            stats: Stats::default(),
            sweep: None,
            log_units: (RateUnit::DegPerS, TimeUnit::Seconds),
            replaying: None,
            file_slot: platform::FileSlot::default(),
            gpu_ready: false,
            app_errors: Vec::new(),
            frames: 0,
            last_frame: None,
            step_debt: 0.0,
            last_fragment: String::new(),
        }
    }

    /// Applies one UI command.
    pub fn apply(&mut self, command: Command) {
        match command {
            Command::SelectLab(lab) => {
                self.sim = Simulation::new(lab, ParamValues::defaults(lab.params()), self.seed);
                self.sweep = None;
                self.replaying = None;
                self.plots.tab = default_tab(lab);
                self.ghost_index = 0;
                self.step_debt = 0.0;
            }
            Command::SetParam(key, value) => {
                if let Err(e) = self.sim.set_param(key, value) {
                    self.messages.push(Message {
                        text: e.to_string(),
                        is_error: true,
                    });
                }
            }
            Command::RestoreDefaults => {
                let lab = self.sim.lab();
                self.sim = Simulation::new(lab, ParamValues::defaults(lab.params()), self.seed);
            }
            Command::Reset => {
                self.sim.reset(self.seed);
                self.step_debt = 0.0;
            }
            Command::StepOnce => self.sim.step(),
            Command::ExportCsv => self.export_csv(),
            Command::RunSweep(i) => {
                if let Some(spec) = self.sim.lab().sweeps().get(i) {
                    self.sweep = Some((
                        i,
                        Sweep::new(self.sim.lab(), *spec, self.sim.params().clone(), self.seed),
                    ));
                }
            }
            Command::CancelSweep => self.sweep = None,
            Command::LoadLog => platform::pick_text_file(&self.file_slot),
            Command::EndReplay => {
                self.replaying = None;
                self.sim = Simulation::new(self.sim.lab(), self.sim.params().clone(), self.seed);
            }
            Command::Dismiss(i) => {
                if i < self.messages.len() {
                    self.messages.remove(i);
                }
            }
        }
    }

    /// Takes a picked gyro log, if one arrived, and starts replaying it (bad lines are
    /// listed as messages with their line numbers; the good ones are used).
    fn take_picked_log(&mut self) {
        let Some(picked) = self.file_slot.borrow_mut().take() else {
            return;
        };
        let (name, text) = match picked {
            Ok(x) => x,
            Err(e) => {
                return self.messages.push(Message {
                    text: e,
                    is_error: true,
                });
            }
        };
        let log = parse_rate_log(&text, self.log_units.0, self.log_units.1);
        const SHOWN: usize = 12;
        for e in log.errors.iter().take(SHOWN) {
            self.messages.push(Message {
                text: format!("{name}: skipped {e}"),
                is_error: true,
            });
        }
        if log.errors.len() > SHOWN {
            self.messages.push(Message {
                text: format!("{name}: … and {} more bad lines", log.errors.len() - SHOWN),
                is_error: true,
            });
        }
        let samples = log.t_s.len();
        match Simulation::replay(
            self.sim.lab(),
            self.sim.params().clone(),
            log,
            attlab::sim::DEFAULT_HISTORY_ROWS,
        ) {
            Ok(sim) => {
                self.sim = sim;
                self.sweep = None;
                self.messages.push(Message {
                    text: format!("{name}: replaying {samples} samples"),
                    is_error: false,
                });
                self.replaying = Some((name, samples));
            }
            Err(e) => self.messages.push(Message {
                text: format!("{name}: {e}"),
                is_error: true,
            }),
        }
    }

    /// Runs the background sweep for at most `budget` of wall time.
    fn advance_sweep(&mut self, budget: Duration) {
        let Some((_, sweep)) = self.sweep.as_mut() else {
            return;
        };
        let start = Instant::now();
        while start.elapsed() < budget {
            if sweep.advance(1000) {
                break;
            }
        }
    }

    fn export_csv(&mut self) {
        let mut buf = Vec::new();
        let result = self
            .sim
            .recorder()
            .write_csv(&mut buf)
            .map_err(|e| e.to_string());
        let name = format!("attlab-{}-seed{}.csv", self.sim.lab().id(), self.sim.seed());
        let result = result.and_then(|()| platform::save_file(&name, "text/csv", &buf));
        let (text, is_error) = match result {
            Ok(t) => (t, false),
            Err(e) => (format!("export failed: {e}"), true),
        };
        self.messages.push(Message { text, is_error });
    }

    /// Advances the simulation by the wall-clock time since the last frame × speed, within
    /// [`STEP_BUDGET`]; if it cannot keep up it drops the backlog instead of freezing.
    pub fn advance(&mut self, now: Instant) {
        let frame_s = self
            .last_frame
            .map_or(0.0, |t| now.duration_since(t).as_secs_f64())
            .min(0.1);
        self.last_frame = Some(now);
        self.stats.frame_ms = 0.9 * self.stats.frame_ms + 0.1 * frame_s * 1e3;
        if !self.playing {
            self.stats.steps_per_s *= 0.9;
            return;
        }
        self.step_debt += self.speed * frame_s / self.sim.dt_s();
        let mut steps = 0u32;
        self.stats.behind = false;
        while self.step_debt >= 1.0 {
            self.sim.step();
            self.step_debt -= 1.0;
            steps += 1;
            if steps.is_multiple_of(16) && now.elapsed() > STEP_BUDGET {
                self.stats.behind = true;
                self.step_debt = 0.0;
            }
        }
        self.stats.step_ms = now.elapsed().as_secs_f64() * 1e3;
        if frame_s > 0.0 {
            self.stats.steps_per_s =
                0.9 * self.stats.steps_per_s + 0.1 * f64::from(steps) / frame_s;
        }
    }

    fn sync_url(&mut self) {
        let state = UrlState {
            lab_id: self.sim.lab().id(),
            seed: self.seed,
            speed: self.speed,
            params: self.sim.params().clone(),
        };
        let fragment = state.encode();
        if fragment != self.last_fragment {
            platform::set_fragment(&fragment);
            self.last_fragment = fragment;
        }
    }

    /// The shareable link fragment of the current state.
    pub fn fragment(&self) -> &str {
        &self.last_fragment
    }

    /// Whether the 3D renderer is available.
    pub fn gpu_ready(&self) -> bool {
        self.gpu_ready
    }
}

/// A lab with figures opens on its first figure, others on the error plot.
fn default_tab(lab: &'static dyn Lab) -> plots::Tab {
    if lab.figures().is_empty() {
        plots::Tab::Group(attlab::record::SeriesGroup::Error)
    } else {
        plots::Tab::Figure(0)
    }
}

impl eframe::App for AttLabApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.advance(Instant::now());
        self.advance_sweep(SWEEP_BUDGET);
        self.take_picked_log();
        let mut commands = Vec::new();
        panels::status_line(ui, self);
        panels::controls(ui, self, &mut commands);
        panels::central(ui, self);
        for c in commands {
            self.apply(c);
        }
        self.sync_url();
        self.frames += 1;
        platform::publish_status(&platform::Status {
            frames: self.frames,
            lab: self.sim.lab().id(),
            sim_steps: self.sim.steps(),
            errors: &self.app_errors,
        });
        ui.ctx().request_repaint();
    }
}
