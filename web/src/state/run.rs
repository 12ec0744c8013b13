//! The run part: the simulation, its clock and speed, the seed, and a sweep in the
//! background. It owns the commands that choose the lab, set parameters, reset, step and
//! sweep, and the frame loop's ticks.

use super::slicer::Slicer;
use super::{AppState, ViewState, jobs::Job};
use attlab::analysis::sweep::Sweep;
use attlab::model::{ParamValues, PlotTab, SeriesKey};
use attlab::page::Lab;
use attlab::page::default_tab;
use attlab::sim::Simulation;
use web_time::{Duration, Instant};

/// Time the simulation may take per frame before it falls behind real time.
pub const STEP_BUDGET: Duration = Duration::from_millis(12);

/// The longest frame interval the simulation advances by in full. A device that draws 4
/// frames a second or more (a phone, software GL) runs at the speed asked for; a longer gap
/// (a tab in the background, a debugger's pause) counts as this much, so the page never
/// comes back to a minute of catching up.
pub const MAX_FRAME_S: f64 = 0.25;

/// Wall time per frame given to a background sweep.
pub const SWEEP_BUDGET: Duration = Duration::from_millis(10);

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
    /// Simulated seconds per wall-clock second, as measured (smoothed).
    pub realtime: f64,
}

/// The run's clock, seed and background work.
pub struct RunState {
    /// Seed used at the next reset.
    pub seed: u64,
    /// Running or paused.
    pub playing: bool,
    /// Simulated seconds per wall-clock second.
    pub speed: f64,
    /// Status line values.
    pub stats: Stats,
    /// A parameter sweep running in the background (index into the lab's sweeps, sweep).
    pub sweep: Option<(usize, Sweep)>,
    /// How many sweep steps fit in a frame's budget, from their measured cost.
    sweep_slicer: Slicer,
    /// The Web Workers running the sweep, if they do.
    pub(super) pool: Option<super::pool::Pool>,
    /// How the last sweep ran (workers, wall time).
    pub sweep_timing: super::pool::SweepTiming,
    pub(super) sweep_started: Option<Instant>,
    /// Re-runs and exports under way, the first one advancing.
    pub(super) jobs: Vec<Job>,
    /// How many job steps fit in a frame's budget.
    pub(super) job_slicer: Slicer,
    /// The run pauses on reaching this time (s): a lesson step's picture.
    pub pause_at_s: Option<f64>,
    last_frame: Option<Instant>,
    step_debt: f64,
}

impl RunState {
    /// Playing at `speed` with `seed`.
    pub fn new(seed: u64, speed: f64) -> Self {
        Self {
            seed,
            playing: true,
            speed,
            stats: Stats::default(),
            sweep: None,
            sweep_slicer: Slicer::default(),
            pool: None,
            sweep_timing: Default::default(),
            sweep_started: None,
            jobs: Vec::new(),
            job_slicer: Slicer::default(),
            pause_at_s: None,
            last_frame: None,
            step_debt: 0.0,
        }
    }

    /// The clock starts over (a new run): no steps owed.
    pub(super) fn reset_clock(&mut self) {
        self.step_debt = 0.0;
    }

    /// The job advancing now (a re-run for a plot, an export), if any.
    pub fn job(&self) -> Option<&Job> {
        self.jobs.first()
    }

    /// A sweep is running and not finished.
    pub fn sweeping(&self) -> bool {
        self.sweep.as_ref().is_some_and(|(_, s)| !s.is_done())
    }
}

/// What the run part does.
#[derive(Clone, Copy)]
pub enum RunCommand {
    /// Switch lab (parameters to its defaults).
    SelectLab(&'static dyn Lab),
    /// Change one parameter.
    SetParam(&'static str, f64),
    /// Apply the lab's preset with this id.
    ApplyPreset(&'static str),
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
    /// Start the lab's sweep `i`.
    RunSweep(usize),
    /// Stop the running sweep.
    CancelSweep,
    /// Stop the re-run or export under way.
    CancelJob,
    /// A frame at `now`: step by the wall time since the last one × speed, within
    /// [`STEP_BUDGET`].
    Advance(Instant),
    /// A frame at `now` that leaves the simulation where it is (a PNG capture in progress):
    /// the next advance does not catch up on the time spent.
    Hold(Instant),
    /// Give the background sweep this much wall time.
    AdvanceSweep(Duration),
    /// Move the job under way on for this much wall time without stepping the run (a PNG
    /// capture waits for the re-run of each tab it shows).
    AdvanceJob(Duration),
}

impl AppState {
    pub(super) fn apply_run(&mut self, command: RunCommand) {
        match command {
            RunCommand::SelectLab(lab) => self.select_lab(lab),
            // A control the teacher's link locks keeps its value, whoever asks (the
            // screen reader's mirror, a preset).
            RunCommand::SetParam(key, _) if self.view.locks(key) => self.say_locked(&[key]),
            RunCommand::SetParam(key, value) if self.change_at_cursor(key, value) => {}
            RunCommand::SetParam(key, value) => {
                if let Err(e) = self.sim.set_param(key, value) {
                    let lab = self.sim.lab();
                    let lang = self.view.lang();
                    self.error(super::link_words::param_problem(
                        lang,
                        lab,
                        lab.params(),
                        &e,
                    ));
                }
            }
            RunCommand::ApplyPreset(i) => self.apply_preset(i),
            RunCommand::RestoreDefaults => {
                let lab = self.sim.lab();
                let mut params = ParamValues::defaults(lab.params());
                let held = self.hold_locked(&mut params);
                self.say_locked(&held);
                self.restart(lab, params);
            }
            RunCommand::SetPlaying(on) => self.run.playing = on,
            RunCommand::Reset => {
                self.drop_jobs();
                self.end_travel();
                self.sim.reset(self.run.seed);
                self.run.step_debt = 0.0;
                // A re-run for the tab stopped by the reset: at t = 0 it is done at once.
                self.apply_view(super::ViewCommand::SelectTab(self.view.plots.tab));
            }
            // The run holds while a job brings a re-run up to it.
            // A live run steps only onto samples that have arrived.
            RunCommand::StepOnce if self.run.jobs.is_empty() && self.sim.can_step() => {
                self.sim.step()
            }
            RunCommand::StepOnce => {}
            RunCommand::SetSeed(seed) => self.run.seed = seed,
            RunCommand::NewSeed => {
                self.run.seed = fresh_seed();
                self.apply_run(RunCommand::Reset);
            }
            RunCommand::SetSpeed(speed) => {
                let (lo, hi) = attlab::state::SPEED_RANGE;
                self.run.speed = speed.clamp(lo, hi);
            }
            RunCommand::RunSweep(i) => self.start_sweep(i),
            RunCommand::CancelSweep => self.run.sweep = None,
            RunCommand::CancelJob => self.cancel_job(),
            RunCommand::Advance(now) => self.advance(now),
            RunCommand::Hold(now) => self.run.last_frame = Some(now),
            RunCommand::AdvanceSweep(budget) => self.advance_sweep(budget),
            RunCommand::AdvanceJob(budget) => self.advance_job(budget),
        }
    }

    fn select_lab(&mut self, lab: &'static dyn Lab) {
        self.lesson = None;
        self.run.pause_at_s = None;
        self.view = ViewState {
            hide: std::mem::take(&mut self.view.hide),
            lock: std::mem::take(&mut self.view.lock),
            origins: std::mem::take(&mut self.view.origins),
            embed: self.view.embed,
            presenter: self.view.presenter,
            theme: self.view.theme,
            lang: self.view.lang,
            browser_lang: self.view.browser_lang,
            capturing: self.view.capturing,
            ..ViewState::for_lab(lab)
        };
        self.run.sweep = None;
        self.restart(lab, ParamValues::defaults(lab.params()));
        self.run.step_debt = 0.0;
    }

    /// A fresh run of `lab` with `params`, recording the tab shown and the lesson step's
    /// tiles; the jobs under way and a replayed log end with the old run. In the same lab,
    /// the controls the link locks keep their values whatever `params` says.
    pub(super) fn restart(&mut self, lab: &'static dyn Lab, mut params: ParamValues) {
        if lab.id() == self.sim.lab().id() {
            self.hold_locked(&mut params);
        }
        if self.live.take().is_some() {
            crate::live_io::stop();
        }
        self.drop_jobs();
        self.end_travel();
        self.sim.release_recorder();
        let tab = self.view.plots.tab;
        self.sim = simulation(lab, params, self.run.seed, tab, self.tiles());
        self.io.replaying = None;
    }

    /// Sets the locked controls of `params` back to the values they hold in the run, and
    /// returns those `params` had asked to change.
    pub(super) fn hold_locked(&self, params: &mut ParamValues) -> Vec<&'static str> {
        let now = self.sim.params();
        let specs = self.sim.lab().params();
        let mut held = Vec::new();
        for spec in specs.iter().filter(|s| self.view.locks(s.key)) {
            let (asked, kept) = (params.get(spec.key), now.get(spec.key));
            if asked != kept && params.set(specs, spec.key, kept).is_ok() {
                held.push(spec.key);
            }
        }
        held
    }

    /// Says that the controls `keys` are locked by the teacher's link and kept (nothing
    /// for none).
    pub(super) fn say_locked(&mut self, keys: &[&'static str]) {
        if keys.is_empty() {
            return;
        }
        let lab = self.sim.lab();
        let lang = self.view.lang();
        let names: Vec<String> = (keys.iter())
            .filter_map(|k| lab.params().iter().find(|p| p.key == *k))
            .map(|p| {
                let id = attlab::i18n::param_label_id(lab.id(), p.key);
                attlab::i18n::lab_text(lang, &id, p.label)
            })
            .collect();
        self.say("msg-locked-kept", &[("names", names.join(", ").into())]);
    }

    fn apply_preset(&mut self, id: &str) {
        let lab = self.sim.lab();
        let Some(preset) = lab.preset(id) else {
            return;
        };
        let (locked, free): (Vec<_>, Vec<_>) =
            preset.values.iter().partition(|(k, _)| self.view.locks(k));
        for (k, v) in free {
            self.apply_run(RunCommand::SetParam(k, v));
        }
        let held: Vec<&'static str> = (locked.iter())
            .filter(|(k, v)| self.sim.params().get(k) != *v)
            .map(|(k, _)| *k)
            .collect();
        let waiting = self.sim.pending_reset();
        let id = attlab::i18n::preset_id(lab.id(), preset.id);
        let name = attlab::i18n::lab_text(self.view.lang(), &id, preset.name);
        let message = if waiting.is_empty() {
            "msg-preset-applied"
        } else {
            "msg-preset-waits"
        };
        self.say(message, &[("name", name.into())]);
        self.say_locked(&held);
    }

    fn start_sweep(&mut self, i: usize) {
        let lab = self.sim.lab();
        let Some(spec) = lab.sweeps().get(i) else {
            return;
        };
        let params = self.sim.params().clone();
        let fresh = || Sweep::new(lab, *spec, params.clone(), self.run.seed);
        // While a log is replayed, a sweep that can run on it does.
        let sweep = match self.sim.replay_log() {
            Some(log) if spec.log_scoring.is_some() => {
                fresh().on_log(log.clone()).unwrap_or_else(fresh)
            }
            _ => fresh(),
        };
        self.run.sweep = Some((i, sweep));
        self.start_pool();
    }

    /// Runs the background sweep for at most `budget` of wall time.
    fn advance_sweep(&mut self, budget: Duration) {
        if self.advance_pool() {
            return;
        }
        let Some((_, sweep)) = self.run.sweep.as_mut() else {
            return;
        };
        let slicer = &mut self.run.sweep_slicer;
        let start = Instant::now();
        while let Some(left) = budget.checked_sub(start.elapsed()) {
            let steps = slicer.chunk(left);
            let t0 = Instant::now();
            let done = sweep.advance(steps);
            slicer.measured(steps, t0.elapsed());
            if done {
                let timing = &mut self.run.sweep_timing;
                if timing.wall_s.is_none() {
                    timing.wall_s = self.run.sweep_started.map(|t| t.elapsed().as_secs_f64());
                }
                break;
            }
        }
    }

    /// Advances the simulation by the wall-clock time since the last frame × speed, within
    /// [`STEP_BUDGET`]; if it cannot keep up it drops the backlog instead of freezing.
    fn advance(&mut self, now: Instant) {
        if !self.run.jobs.is_empty() {
            // The simulation holds while a job runs (and does not catch up afterwards).
            self.run.last_frame = Some(now);
            self.advance_job(STEP_BUDGET);
            return;
        }
        if self.follow_plan(STEP_BUDGET) {
            // A link's cursor and branches: the run goes there first, as fast as it can.
            self.run.last_frame = Some(now);
            return;
        }
        if self.live.is_some() {
            // A live run goes at the pace its samples arrive.
            self.run.last_frame = Some(now);
            return self.advance_live(now);
        }
        let run = &mut self.run;
        // The stats report the interval as it was; the stepping takes at most
        // `MAX_FRAME_S` of it.
        let wall_s = run
            .last_frame
            .map_or(0.0, |t| now.duration_since(t).as_secs_f64());
        let frame_s = wall_s.min(MAX_FRAME_S);
        run.last_frame = Some(now);
        run.stats.frame_ms = 0.9 * run.stats.frame_ms + 0.1 * wall_s * 1e3;
        if !run.playing {
            run.stats.steps_per_s *= 0.9;
            run.stats.realtime *= 0.9;
            return self.advance_travel(STEP_BUDGET);
        }
        run.step_debt += run.speed * frame_s / self.sim.dt_s();
        let mut steps = 0u32;
        run.stats.behind = false;
        while run.step_debt >= 1.0 {
            if run
                .pause_at_s
                .is_some_and(|t| self.sim.t_s() >= t - 0.5 * self.sim.dt_s())
            {
                run.pause_at_s = None;
                run.playing = false;
                run.step_debt = 0.0;
                // On a phone the answered step's why is in the controls' sheet, which the
                // answer closed to show the run: open it now the run has shown it.
                if self
                    .lesson
                    .as_ref()
                    .is_some_and(|l| l.answer(l.step).is_some())
                {
                    self.view.sheet_open = true;
                }
                break;
            }
            self.sim.step();
            run.step_debt -= 1.0;
            steps += 1;
            if steps.is_multiple_of(16) && now.elapsed() > STEP_BUDGET {
                run.stats.behind = true;
                run.step_debt = 0.0;
            }
        }
        run.stats.step_ms = now.elapsed().as_secs_f64() * 1e3;
        self.advance_travel(STEP_BUDGET.saturating_sub(now.elapsed()));
        let run = &mut self.run;
        if wall_s > 0.0 {
            let rate = f64::from(steps) / wall_s;
            run.stats.steps_per_s = 0.9 * run.stats.steps_per_s + 0.1 * rate;
            run.stats.realtime = 0.9 * run.stats.realtime + 0.1 * rate * self.sim.dt_s();
        }
    }
}

/// A simulation recording what `tab` shows and the lesson step's `tiles`.
pub(super) fn simulation(
    lab: &'static dyn Lab,
    params: ParamValues,
    seed: u64,
    tab: PlotTab,
    tiles: &[SeriesKey],
) -> Simulation {
    let mut sim = Simulation::new(lab, params, seed);
    sim.keep_history(attlab::sim::HISTORY_BUDGET_BYTES);
    let has_tiles = tiles
        .iter()
        .all(|t| sim.specs().iter().any(|s| t.is(&s.name)));
    if tab == default_tab(lab) && has_tiles {
        return sim;
    }
    // At t = 0 the re-run is immediate; on an error the run records the default tab's series.
    let selection = super::view_selection(&sim, tab, tiles);
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
