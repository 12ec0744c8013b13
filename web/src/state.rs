//! The app's state and the one place that changes it. Panels read [`AppState`] and emit
//! [`Command`]s; [`AppState::apply`] carries them out after the frame is drawn. View state
//! that only a widget cares about (camera angles, the sphere's orientation) lives in
//! [`View`] and is handed `&mut` to the widget that owns it, as egui does with a slider's
//! value.

use crate::platform;
use crate::render::{body3d, plots, riemann_sphere, single_axis};
use attlab::analysis::sweep::Sweep;
use attlab::model::PlotTab;
use attlab::model::{Lab, ParamValues};
use attlab::sensors::{ImuScales, RateUnit, TimeUnit, parse_imu_log, parse_rate_log};
use attlab::sim::{Selection, SimOptions, Simulation, default_tab};
use attlab::state::UrlState;
use web_time::{Duration, Instant};

/// The synthetic Arduino MPU-6050 log shipped with the page (paper 4): name and text.
pub const EXAMPLE_IMU_LOG: (&str, &str) = (
    "p4-arduino-mpu6050.csv",
    include_str!("../../assets/p4-arduino-mpu6050.csv"),
);

/// Time the simulation may take per frame before it falls behind real time.
pub const STEP_BUDGET: Duration = Duration::from_millis(12);

/// Wall time per frame given to a background sweep.
pub const SWEEP_BUDGET: Duration = Duration::from_millis(10);

/// A message for the user (bad URL item, export result, divergence).
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    /// Text shown.
    pub text: String,
    /// Shown in red.
    pub is_error: bool,
}

impl Message {
    /// An error message.
    pub fn error(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            is_error: true,
        }
    }

    /// An information message.
    pub fn info(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            is_error: false,
        }
    }
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

/// What a panel asks the app to do (applied after drawing, in order).
#[derive(Clone, Copy)]
pub enum Command {
    /// Switch lab (parameters to its defaults).
    SelectLab(&'static dyn Lab),
    /// Change one parameter.
    SetParam(&'static str, f64),
    /// Apply the lab's preset with this index.
    ApplyPreset(usize),
    /// All parameters back to their defaults.
    RestoreDefaults,
    /// Run or pause.
    SetPlaying(bool),
    /// Restart with the current seed.
    Reset,
    /// One step while paused.
    StepOnce,
    /// Use this seed from the next reset.
    SetSeed(u64),
    /// A fresh random seed, then reset.
    NewSeed,
    /// Simulated seconds per wall-clock second.
    SetSpeed(f64),
    /// Save every sample of the run so far as CSV.
    ExportCsv,
    /// Save the paper's own output file (labs that define one).
    ExportOutputFile,
    /// Remove message `i`.
    Dismiss(usize),
    /// Start the lab's sweep `i`.
    RunSweep(usize),
    /// Shade (or not) the lab's outages on the plots.
    SetShowOutages(bool),
    /// Stop the running sweep.
    CancelSweep,
    /// Ask for a gyro log file to replay.
    LoadLog,
    /// Leave the replay and simulate again.
    EndReplay,
    /// Units of the gyro log to load.
    SetLogUnits(RateUnit, TimeUnit),
    /// Units of the IMU log to load (paper 4).
    SetImuScales(ImuScales),
    /// Replay the IMU log shipped with the page (paper 4).
    LoadExampleLog,
    /// Which estimator the 3D ghost shows.
    SetGhost(usize),
    /// Select a plot tab.
    SelectTab(PlotTab),
    /// Draw covariance elements as log10.
    SetLogCovariance(bool),
    /// Draw ±3σ bands around errors that have one.
    SetShowBands(bool),
    /// Copy the link of the current state to the clipboard.
    CopyLink,
    /// Show the next view alone over the whole central area (then the plots, then all).
    CycleFocus,
    /// Hide (or show again) the source with this index (1 + estimator index) everywhere.
    ToggleSource(usize),
    /// Copy a pandas snippet that loads the exported CSV and draws the current plot tab.
    CopyPython,
    /// Presenter mode on or off: large type, thick lines, only the controls that matter.
    SetPresenter(bool),
    /// Save a PNG of a view or of every plot tab (taken by the app over the next frames).
    ExportPng(PngTarget),
}

/// What a PNG export shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PngTarget {
    /// The lab's view with this index (in `Lab::views()`).
    View(usize),
    /// Every plot tab, one below the other.
    Plots,
}

/// What the central area shows: everything, or one view (or the plots) at full size.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Focus {
    /// The lab's views on top, the plots below.
    #[default]
    All,
    /// The lab's view with this index alone.
    View(usize),
    /// The plots alone.
    Plots,
}

impl Focus {
    /// The next focus for a lab with `views` views: each view, the plots, all.
    pub fn next(self, views: usize) -> Self {
        match self {
            Self::All if views > 0 => Self::View(0),
            Self::View(k) if k + 1 < views => Self::View(k + 1),
            Self::All | Self::View(_) => Self::Plots,
            Self::Plots => Self::All,
        }
    }
}

/// Widget-owned view state: the camera and the sphere change by dragging; the phase
/// trails remember what the views drew (never read by the simulation).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct View {
    /// 3D camera.
    pub camera: body3d::OrbitCamera,
    /// Sphere orientation.
    pub sphere: riemann_sphere::SphereView,
    /// Phase-portrait trails of a single-axis lab.
    pub trails: single_axis::PhaseTrails,
}

/// Everything the panels read.
pub struct AppState {
    /// The running simulation.
    pub sim: Simulation,
    /// Seed used at the next reset.
    pub seed: u64,
    /// Running or paused.
    pub playing: bool,
    /// Simulated seconds per wall-clock second.
    pub speed: f64,
    /// Plot tab and options.
    pub plots: plots::PlotState,
    /// One view at full size, or all.
    pub focus: Focus,
    /// Sources (1 + estimator index) hidden in every view and plot.
    pub hidden: Vec<usize>,
    /// Presenter mode: large type, thick lines, only the controls that matter.
    pub presenter: bool,
    /// Which estimator the 3D ghost shows.
    pub ghost_index: usize,
    /// Messages for the user.
    pub messages: Vec<Message>,
    /// Status line values.
    pub stats: Stats,
    /// A parameter sweep running in the background (index into the lab's sweeps, sweep).
    pub sweep: Option<(usize, Sweep)>,
    /// Units of a gyro log to load.
    pub log_units: (RateUnit, TimeUnit),
    /// Units of an IMU log to load.
    pub imu_scales: ImuScales,
    /// Name and sample count of the log being replayed.
    pub replaying: Option<(String, usize)>,
    /// Text for the clipboard, taken by the app after the frame.
    pub clipboard: Option<String>,
    /// A PNG export asked for, taken by the app after the frame.
    pub png_request: Option<PngTarget>,
    /// A PNG capture is running: the views hide their buttons and the simulation holds.
    pub capturing: bool,
    /// Where exports go without a dialog (desktop scripting and tests); `None` asks.
    pub save_dir: Option<std::path::PathBuf>,
    file_slot: platform::FileSlot,
    last_frame: Option<Instant>,
    step_debt: f64,
    last_fragment: String,
    last_seen_fragment: String,
}

impl AppState {
    /// A state for `lab` with `params`, `seed` and `speed`.
    pub fn new(lab: &'static dyn Lab, params: ParamValues, seed: u64, speed: f64) -> Self {
        let plots = plots::PlotState::for_lab(lab);
        Self {
            sim: simulation(lab, params, seed, plots.tab),
            seed,
            playing: true,
            speed,
            plots,
            focus: Focus::All,
            hidden: Vec::new(),
            presenter: false,
            ghost_index: 0,
            messages: Vec::new(),
            stats: Stats::default(),
            sweep: None,
            log_units: (RateUnit::DegPerS, TimeUnit::Seconds),
            imu_scales: ImuScales::default(),
            replaying: None,
            clipboard: None,
            png_request: None,
            capturing: false,
            save_dir: None,
            file_slot: platform::FileSlot::default(),
            last_frame: None,
            step_debt: 0.0,
            last_fragment: String::new(),
            last_seen_fragment: String::new(),
        }
    }

    /// The state a URL fragment asks for; its bad items become messages.
    pub fn from_fragment(fragment: &str) -> Self {
        let (url, errors) = UrlState::parse(fragment);
        let lab = attlab::labs::find(url.lab_id).unwrap_or(attlab::labs::all()[0]);
        let mut state = Self::new(lab, url.params, url.seed, url.speed);
        state.presenter = url.presenter;
        state.messages.extend(
            errors
                .into_iter()
                .map(|e| Message::error(format!("{e} — ignored"))),
        );
        state
    }

    /// Loads lab, seed, speed, presenter mode and parameters from a link's fragment; its
    /// bad items become messages, the messages already shown stay.
    pub fn load_fragment(&mut self, fragment: &str) {
        self.sim.release_recorder();
        self.sweep = None;
        let mut next = Self::from_fragment(fragment);
        let mut kept = std::mem::take(&mut self.messages);
        kept.append(&mut next.messages);
        next.messages = kept;
        next.save_dir = self.save_dir.take();
        next.file_slot = std::mem::take(&mut self.file_slot);
        *self = next;
    }

    /// Carries out one command: the only place the app's state changes.
    pub fn apply(&mut self, command: Command) {
        match command {
            Command::SelectLab(lab) => {
                self.plots = plots::PlotState::for_lab(lab);
                self.focus = Focus::All;
                self.hidden.clear();
                self.sim.release_recorder();
                self.sweep = None;
                self.sim = simulation(
                    lab,
                    ParamValues::defaults(lab.params()),
                    self.seed,
                    self.plots.tab,
                );
                self.sweep = None;
                self.replaying = None;
                self.ghost_index = 0;
                self.step_debt = 0.0;
            }
            Command::SetParam(key, value) => {
                if let Err(e) = self.sim.set_param(key, value) {
                    self.messages.push(Message::error(e.to_string()));
                }
            }
            Command::ApplyPreset(i) => {
                let lab = self.sim.lab();
                if let Some(preset) = lab.presets().get(i) {
                    for (k, v) in preset.values {
                        self.apply(Command::SetParam(k, *v));
                    }
                    let resets = preset
                        .values
                        .iter()
                        .any(|(k, _)| lab.params().iter().any(|s| s.key == *k && s.needs_reset));
                    self.messages.push(Message::info(if resets {
                        format!("preset {}: some values apply at Reset", preset.name)
                    } else {
                        format!("preset {} applied", preset.name)
                    }));
                }
            }
            Command::RestoreDefaults => {
                let lab = self.sim.lab();
                self.sim = simulation(
                    lab,
                    ParamValues::defaults(lab.params()),
                    self.seed,
                    self.plots.tab,
                );
                self.replaying = None;
            }
            Command::SetPlaying(on) => self.playing = on,
            Command::Reset => {
                self.sim.reset(self.seed);
                self.step_debt = 0.0;
            }
            Command::StepOnce => self.sim.step(),
            Command::SetSeed(seed) => self.seed = seed,
            Command::NewSeed => {
                self.seed = fresh_seed();
                self.apply(Command::Reset);
            }
            Command::SetSpeed(speed) => {
                let (lo, hi) = attlab::state::SPEED_RANGE;
                self.speed = speed.clamp(lo, hi);
            }
            Command::ExportCsv => self.export_csv(),
            Command::ExportOutputFile => self.export_output_file(),
            Command::Dismiss(i) => {
                if i < self.messages.len() {
                    self.messages.remove(i);
                }
            }
            Command::RunSweep(i) => {
                if let Some(spec) = self.sim.lab().sweeps().get(i) {
                    let sweep =
                        Sweep::new(self.sim.lab(), *spec, self.sim.params().clone(), self.seed);
                    // While a log is replayed, a sweep that can run on it does.
                    let sweep = match self.sim.replay_log() {
                        Some(log) if spec.log_scoring.is_some() => {
                            sweep.on_log(log.clone()).unwrap_or_else(|| {
                                Sweep::new(
                                    self.sim.lab(),
                                    *spec,
                                    self.sim.params().clone(),
                                    self.seed,
                                )
                            })
                        }
                        _ => sweep,
                    };
                    self.sweep = Some((i, sweep));
                }
            }
            Command::CancelSweep => self.sweep = None,
            Command::LoadLog => platform::pick_text_file(&self.file_slot),
            Command::EndReplay => {
                self.replaying = None;
                self.sim = simulation(
                    self.sim.lab(),
                    self.sim.params().clone(),
                    self.seed,
                    self.plots.tab,
                );
            }
            Command::SetLogUnits(rate, time) => self.log_units = (rate, time),
            Command::SetImuScales(scales) => self.imu_scales = scales,
            Command::LoadExampleLog => {
                self.start_replay(EXAMPLE_IMU_LOG.0.into(), EXAMPLE_IMU_LOG.1)
            }
            Command::SetGhost(i) => self.ghost_index = i,
            Command::SelectTab(tab) => self.select_tab(tab),
            Command::SetLogCovariance(on) => self.plots.log_covariance = on,
            Command::SetShowBands(on) => self.plots.show_bands = on,
            Command::SetShowOutages(on) => self.plots.show_outages = on,
            Command::CopyLink => self.clipboard = Some(format!("#{}", self.fragment())),
            Command::CycleFocus => self.focus = self.focus.next(self.sim.lab().views().len()),
            Command::ToggleSource(i) => match self.hidden.iter().position(|h| *h == i) {
                Some(k) => {
                    self.hidden.remove(k);
                }
                None => self.hidden.push(i),
            },
            Command::CopyPython => {
                self.clipboard = Some(self.python_snippet());
                self.messages.push(Message::info(
                    "copied: a Python snippet that loads the exported CSV and draws this plot",
                ));
            }
            Command::SetPresenter(on) => self.presenter = on,
            Command::ExportPng(target) => self.png_request = Some(target),
        }
    }

    /// Shows `tab`; when it draws series not recorded so far, the run is re-simulated from
    /// its start recording them (same seed, same parameter changes), so the new plot covers
    /// the whole run too.
    fn select_tab(&mut self, tab: PlotTab) {
        self.plots.tab = tab;
        let selection = view_selection(&self.sim, tab);
        let Selection::View(wanted) = &selection else {
            return;
        };
        let recorded = self.sim.specs();
        if wanted.iter().all(|w| recorded.iter().any(|s| &s.name == w)) {
            return;
        }
        let started = Instant::now();
        match self.sim.reselect(selection) {
            Ok(()) => {
                let ms = started.elapsed().as_secs_f64() * 1e3;
                if ms > 200.0 {
                    self.messages.push(Message::info(format!(
                        "re-ran {:.0} s of simulation for this plot in {ms:.0} ms",
                        self.sim.t_s()
                    )));
                }
            }
            Err(e) => self
                .messages
                .push(Message::error(format!("cannot show this plot: {e}"))),
        }
    }

    /// Takes a picked log, if one arrived, and starts replaying it (bad lines are listed as
    /// messages with their line numbers; the good ones are used).
    pub fn take_picked_log(&mut self) {
        let Some(picked) = self.file_slot.borrow_mut().take() else {
            return;
        };
        match picked {
            Ok((name, text)) => self.start_replay(name, &text),
            Err(e) => self.messages.push(Message::error(e)),
        }
    }

    /// Parses `text` as the lab's kind of log and replays it.
    fn start_replay(&mut self, name: String, text: &str) {
        let log = if self.sim.lab().accepts_imu_log() {
            parse_imu_log(text, self.imu_scales)
        } else {
            parse_rate_log(text, self.log_units.0, self.log_units.1)
        };
        const SHOWN: usize = 12;
        for e in log.errors.iter().take(SHOWN) {
            self.messages
                .push(Message::error(format!("{name}: skipped {e}")));
        }
        if log.errors.len() > SHOWN {
            self.messages.push(Message::error(format!(
                "{name}: … and {} more bad lines",
                log.errors.len() - SHOWN
            )));
        }
        let samples = log.t_s.len();
        match Simulation::replay(
            self.sim.lab(),
            self.sim.params().clone(),
            log,
            SimOptions::default(),
        ) {
            Ok(sim) => {
                self.sim = sim;
                self.sweep = None;
                self.messages.push(Message::info(format!(
                    "{name}: replaying {samples} samples"
                )));
                self.replaying = Some((name, samples));
            }
            Err(e) => self.messages.push(Message::error(format!("{name}: {e}"))),
        }
    }

    /// Runs the background sweep for at most `budget` of wall time.
    pub fn advance_sweep(&mut self, budget: Duration) {
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
        let result = self.sim.export_csv(&mut buf);
        let name = self.csv_name();
        let message = result
            .and_then(|rows| {
                platform::save_file(&name, "text/csv", buf, self.save_dir.as_deref())
                    .map(|m| format!("{m} ({rows} rows, every sample, re-run from t = 0)"))
            })
            .map_or_else(
                |e| Message::error(format!("export failed: {e}")),
                Message::info,
            );
        self.messages.push(message);
    }

    fn export_output_file(&mut self) {
        let lab = self.sim.lab();
        let Some(file) = lab.output_file(self.sim.params()) else {
            return self
                .messages
                .push(Message::error("this lab has no output file of its paper"));
        };
        let mut buf = Vec::new();
        let duration = self.sim.t_s().max(lab.default_duration_s());
        let name = format!("attlab-{}-output-seed{}.csv", lab.id(), self.seed);
        let message = attlab::sim::write_output_file(
            lab,
            self.sim.params().clone(),
            self.seed,
            duration,
            &file,
            &mut buf,
        )
        .and_then(|(rows, stopped)| {
            platform::save_file(&name, "text/csv", buf, self.save_dir.as_deref()).map(|m| {
                format!(
                    "{m} ({rows} rows{})",
                    if stopped {
                        ", to the first row within tolerance"
                    } else {
                        ""
                    }
                )
            })
        })
        .map_or_else(
            |e| Message::error(format!("export failed: {e}")),
            Message::info,
        );
        self.messages.push(message);
    }

    /// A frame that leaves the simulation where it is (a PNG capture in progress): the
    /// next [`Self::advance`] does not catch up on the time spent.
    pub fn hold(&mut self, now: Instant) {
        self.last_frame = Some(now);
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

    /// The CSV file name "Export CSV" saves under.
    pub fn csv_name(&self) -> String {
        format!("attlab-{}-seed{}.csv", self.sim.lab().id(), self.sim.seed())
    }

    /// "Copy as Python" for the plot tab on screen.
    pub fn python_snippet(&self) -> String {
        let lab = self.sim.lab();
        let available = self.sim.available_specs();
        let header = |name: &str| {
            available
                .iter()
                .find(|s| s.name == name)
                .map(|s| s.header())
        };
        let (title, columns, log) = match self.plots.tab {
            PlotTab::Figure(f) if f < lab.figures().len() => {
                let fig = &lab.figures()[f];
                let cols = fig.series.iter().filter_map(|n| header(n)).collect();
                (fig.title.to_string(), cols, fig.log)
            }
            PlotTab::Figure(_) => (String::new(), Vec::new(), false),
            PlotTab::Group(g) => (
                g.title().to_string(),
                available
                    .iter()
                    .filter(|s| s.group == g)
                    .map(|s| s.header())
                    .collect(),
                self.plots.log_covariance && g == attlab::model::SeriesGroup::Covariance,
            ),
        };
        crate::python::snippet(&self.csv_name(), &title, &columns, log)
    }

    /// The shareable link fragment of the current state.
    pub fn fragment(&self) -> String {
        UrlState {
            lab_id: self.sim.lab().id(),
            seed: self.seed,
            speed: self.speed,
            params: self.sim.params().clone(),
            presenter: self.presenter,
        }
        .encode()
    }

    /// Writes the current state into the URL when it changed — or, when the reader changed
    /// the URL (a link pasted into the open tab), loads what it asks for.
    pub fn sync_url(&mut self) {
        // Compared with what the address bar said right after our own last write, so a
        // browser that spells our fragment differently cannot make us reload every frame.
        if let Some(now) = platform::current_fragment()
            && !self.last_fragment.is_empty()
            && now != self.last_seen_fragment
        {
            self.load_fragment(&now);
        }
        let fragment = self.fragment();
        if fragment != self.last_fragment {
            platform::set_fragment(&fragment);
            self.last_seen_fragment = platform::current_fragment().unwrap_or_default();
            self.last_fragment = fragment;
        }
    }
}

/// What the page records while `tab` is shown (see [`Selection::for_tab`]).
pub fn view_selection(sim: &Simulation, tab: PlotTab) -> Selection {
    Selection::for_tab(sim.lab(), sim.available_specs(), tab)
}

/// A simulation recording what `tab` shows.
fn simulation(lab: &'static dyn Lab, params: ParamValues, seed: u64, tab: PlotTab) -> Simulation {
    let mut sim = Simulation::new(lab, params, seed);
    if tab == default_tab(lab) {
        return sim;
    }
    // At t = 0 the re-run is immediate; on an error the run records the default tab's series.
    let selection = view_selection(&sim, tab);
    let _ = sim.reselect(selection);
    sim
}

/// A new random seed from the operating system (the browser's crypto in the page).
fn fresh_seed() -> u64 {
    let mut bytes = [0u8; 8];
    match getrandom::fill(&mut bytes) {
        Ok(()) => u64::from_le_bytes(bytes) >> 16,
        // No entropy source: fall back to the clock, still a new seed each time.
        Err(_) => web_time::SystemTime::now()
            .duration_since(web_time::UNIX_EPOCH)
            .map_or(1, |d| d.as_nanos() as u64 >> 16),
    }
}
