//! The fixed-step loop: truth → sensors → estimators → recorder.
//!
//! One `(lab, parameters, seed)` always gives the same run; live parameter changes are kept
//! in a journal with the step they happened at, so the run can be replayed exactly (the
//! page's CSV export re-runs it and streams every sample, while the recorder only keeps what
//! its memory budget allows).

mod accuracy;
mod branch;
mod catalogue;
mod csv;
mod derived;
mod error;
mod export;
mod glance;
mod health;
mod history;
mod journal;
mod layout;
mod quantities;
mod replay;
mod rerun;
mod selection;
mod tally;

pub use accuracy::{AccuracyRow, AccuracyTracker};
pub use branch::{Branch, Difference, Seek, TravelError};
pub use csv::{CsvSink, csv_cell};
pub use error::SimError;
pub use export::write_output_file;
pub use glance::Glance;
pub use history::{HISTORY_BUDGET_BYTES, HistoryUse};
pub use journal::{Refused, ReplayError};
pub use layout::Layout;
pub use rerun::{RerunError, RerunItem, RerunJob};
pub use selection::{Selection, UnknownSeries};
pub use tally::Stretch;

use crate::model::{
    Estimate, EstimatorStatus, LabRun, ParamError, ParamValues, SceneExtras, SeriesKey, SeriesSpec,
    TruthState,
};
use crate::page::Lab;
use crate::record::{DEFAULT_BUDGET_BYTES, Recorder};
use health::Health;
use history::History;
use journal::Journal;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
pub use replay::SharedLog;
use tally::Tally;

/// What a simulation records, and in how much memory.
#[derive(Clone, Debug, PartialEq)]
pub struct SimOptions {
    /// Which series.
    pub selection: Selection,
    /// The recorder's memory budget (bytes).
    pub budget_bytes: usize,
}

impl Default for SimOptions {
    fn default() -> Self {
        Self {
            selection: Selection::Standard,
            budget_bytes: DEFAULT_BUDGET_BYTES,
        }
    }
}

impl SimOptions {
    /// What the page records for its first tab (the lab's first figure, or the errors).
    pub fn page(lab: &dyn Lab, available: &[SeriesSpec]) -> Self {
        Self {
            selection: Selection::View(crate::page::tab_series(
                lab,
                available,
                crate::page::default_tab(lab),
            )),
            budget_bytes: DEFAULT_BUDGET_BYTES,
        }
    }

    /// Records only `series` in a small recorder (analysis keeps its own traces).
    pub fn named(series: &[&str]) -> Self {
        Self {
            selection: Selection::named(series),
            budget_bytes: 1 << 16,
        }
    }
}

/// The column layout of `run` for `options.selection` (with the series `lab`'s figures
/// draw, and the sphere's where the lab has one).
fn layout_of(lab: &dyn Lab, run: &LabRun, options: &SimOptions) -> Result<Layout, UnknownSeries> {
    // The standard selection keeps what the figures draw and what the plots shade (the
    // lab's outages, a replay's gaps).
    let shaded = lab.page().outages.iter().chain([&crate::page::REPLAY_GAPS]);
    let figure_series: Vec<SeriesKey> = lab
        .page()
        .figures
        .iter()
        .flat_map(|f| f.series.iter().copied())
        .chain(shaded.map(|o| o.series))
        .collect();
    Layout::new(
        lab.id(),
        run.truth.as_ref(),
        run.sensors.as_ref(),
        &run.estimators,
        &options.selection,
        &figure_series,
        !lab.page().suspended && run.truth.state().angle_rad.is_none(),
    )
}

/// A running lab: one `(lab, parameters, seed)` always gives the same run.
pub struct Simulation {
    lab: &'static dyn Lab,
    /// What the user set: the next reset builds from these.
    params: ParamValues,
    /// What this run uses: `params`, except that a parameter marked `needs_reset` keeps the
    /// value the run was built with.
    applied: ParamValues,
    initial_params: ParamValues,
    seed: u64,
    rng: ChaCha8Rng,
    run: LabRun,
    t_s: f64,
    dt_s: f64,
    steps: u64,
    layout: Layout,
    recorder: Recorder,
    row: Vec<f64>,
    estimates: Vec<Estimate>,
    health: Health,
    options: SimOptions,
    replay: Option<SharedLog>,
    journal: Journal,
    accuracy: Option<AccuracyTracker>,
    /// Snapshots for seeking and branching (none unless [`Simulation::keep_history`]).
    history: History,
    /// Each estimator's error so far, while the run keeps a history.
    tally: Option<Tally>,
}

impl Simulation {
    /// Starts `lab` with `params` (already validated) and `seed`, recording what the page
    /// shows first ([`SimOptions::page`]) in the default memory budget. The lab is built once.
    pub fn new(lab: &'static dyn Lab, params: ParamValues, seed: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let run = lab.build(&params, &mut rng);
        let standard = SimOptions::default();
        let layout = |options: &SimOptions| layout_of(lab, &run, options);
        // The standard selection names no series, so it cannot be unknown; a view names only
        // series the lab has, so the standard one is kept only if something is badly wrong.
        let (options, layout) = match layout(&standard) {
            Ok(all) => {
                let page = SimOptions::page(lab, all.available());
                match layout(&page) {
                    Ok(l) => (page, l),
                    Err(_) => (standard, all),
                }
            }
            Err(e) => unreachable!("{e}"),
        };
        Self::assemble(lab, params, seed, rng, run, options, layout, None)
    }

    /// Starts `lab` recording `options.selection` within `options.budget_bytes`.
    pub fn with_options(
        lab: &'static dyn Lab,
        params: ParamValues,
        seed: u64,
        options: SimOptions,
    ) -> Result<Self, UnknownSeries> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let run = lab.build(&params, &mut rng);
        let layout = layout_of(lab, &run, &options)?;
        Ok(Self::assemble(
            lab, params, seed, rng, run, options, layout, None,
        ))
    }

    #[allow(clippy::too_many_arguments)]
    fn assemble(
        lab: &'static dyn Lab,
        params: ParamValues,
        seed: u64,
        rng: ChaCha8Rng,
        run: LabRun,
        options: SimOptions,
        layout: Layout,
        replay: Option<SharedLog>,
    ) -> Self {
        let recorder = Recorder::with_budget(layout.specs().to_vec(), options.budget_bytes);
        let n = run.estimators.len();
        let dt_s = match replay.as_ref().and_then(|l| l.read().median_dt_s()) {
            Some(dt) => dt,
            None => lab.dt_s(&params),
        };
        let mut sim = Self {
            lab,
            initial_params: params.clone(),
            applied: params.clone(),
            params,
            seed,
            rng,
            run,
            t_s: 0.0,
            dt_s,
            steps: 0,
            layout,
            recorder,
            row: Vec::new(),
            estimates: Vec::with_capacity(n),
            health: Health::new(n),
            options,
            accuracy: lab.accuracy_table().map(|t| AccuracyTracker::new(t, n)),
            replay,
            journal: Journal::default(),
            history: History::default(),
            tally: None,
        };
        let truth = sim.run.truth.state();
        sim.t_s = truth.t_s;
        sim.record(&truth);
        sim
    }

    /// Gives the recorder's memory back (an empty recorder of the same series): for a
    /// simulation about to be replaced, so the old and the new budget are never held at once.
    pub fn release_recorder(&mut self) {
        self.recorder = Recorder::with_window(Vec::new(), 2);
    }

    /// The lab.
    pub fn lab(&self) -> &'static dyn Lab {
        self.lab
    }

    /// Current parameter values.
    pub fn params(&self) -> &ParamValues {
        &self.params
    }

    /// The seed of this run.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Simulation time (s).
    pub fn t_s(&self) -> f64 {
        self.t_s
    }

    /// Steps taken since the last reset.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// Current step length (s): the lab's, or a replayed log's median sample interval.
    pub fn dt_s(&self) -> f64 {
        self.dt_s
    }

    /// What is recorded and in how much memory.
    pub fn options(&self) -> &SimOptions {
        &self.options
    }

    /// The recorded series.
    pub fn recorder(&self) -> &Recorder {
        &self.recorder
    }

    /// The recorded series' specs (same order as [`Simulation::last_row`]).
    pub fn specs(&self) -> &[SeriesSpec] {
        self.layout.specs()
    }

    /// Every series the lab has, recorded or not (see [`Simulation::reselected`]).
    pub fn available_specs(&self) -> &[SeriesSpec] {
        self.layout.available()
    }

    /// The row recorded last.
    pub fn last_row(&self) -> &[f64] {
        &self.row
    }

    /// Index of the recorded series `name`.
    pub fn series_index(&self, name: &str) -> Result<usize, UnknownSeries> {
        self.recorder.index_of(name).ok_or_else(|| UnknownSeries {
            name: name.to_string(),
            lab: self.lab.id().to_string(),
            known: self
                .specs()
                .iter()
                .map(|s| s.name.as_str())
                .collect::<Vec<_>>()
                .join(", "),
        })
    }

    /// The latest value of the recorded series `name`.
    pub fn value(&self, name: &str) -> Result<f64, UnknownSeries> {
        self.series_index(name).map(|i| self.row[i])
    }

    /// The true state now.
    pub fn truth(&self) -> TruthState {
        self.run.truth.state()
    }

    /// The estimators (read only).
    pub fn estimators(&self) -> &[Box<dyn crate::model::Estimator>] {
        &self.run.estimators
    }

    /// Every estimator's current estimate, in order.
    pub fn estimates(&self) -> &[Estimate] {
        &self.estimates
    }

    /// Health of every estimator (by position).
    pub fn statuses(&self) -> &[EstimatorStatus] {
        self.health.statuses()
    }

    /// Sets one parameter. A live parameter takes effect on the next step without a restart;
    /// one marked `needs_reset` changes nothing in this run (not even its step length) and
    /// takes effect at the next reset.
    pub fn set_param(&mut self, key: &str, value: f64) -> Result<(), ParamError> {
        let specs = self.lab.params();
        self.params.set(specs, key, value)?;
        let Some(spec) = specs.iter().find(|s| s.key == key) else {
            return Ok(());
        };
        self.journal.push(self.steps, spec.key, value);
        if !spec.needs_reset {
            self.applied.set(specs, key, value)?;
            self.apply_params();
        }
        Ok(())
    }

    /// The parameters this run uses: [`Simulation::params`] less the reset-only changes
    /// that wait for the next reset.
    pub fn applied_params(&self) -> &ParamValues {
        &self.applied
    }

    /// Keys of reset-only parameters whose value was changed since this run was built (they
    /// take effect at the next reset).
    pub fn pending_reset(&self) -> Vec<&'static str> {
        self.lab
            .params()
            .iter()
            .filter(|s| s.needs_reset && self.params.get(s.key) != self.applied.get(s.key))
            .map(|s| s.key)
            .collect()
    }

    fn apply_params(&mut self) {
        self.run.truth.apply_params(&self.applied);
        self.run.sensors.apply_params(&self.applied);
        for e in &mut self.run.estimators {
            e.apply_params(&self.applied);
        }
        if self.replay.is_none() {
            self.dt_s = self.lab.dt_s(&self.applied);
        }
    }

    /// Restarts from t = 0 with `seed` and the current parameters (reseeds the RNG, rebuilds
    /// truth and estimators); a replay restarts from the start of its log.
    pub fn reset(&mut self, seed: u64) {
        let options = self.options.clone();
        let history_bytes = self.history.budget_bytes();
        let fresh = match self.replay.take() {
            Some(log) => Self::live(self.lab, self.params.clone(), log, options),
            None => Self::with_options(self.lab, self.params.clone(), seed, options)
                .map_err(SimError::from),
        };
        if let Ok(fresh) = fresh {
            *self = fresh;
            if history_bytes > 0 {
                self.keep_history(history_bytes);
            }
        }
    }

    /// One step: the lab's fixed one, or a replay's to its next sample.
    pub fn step(&mut self) {
        let dt_s = match &self.replay {
            Some(log) => log.read().step_after(self.t_s),
            None => self.dt_s,
        };
        self.run.truth.draw_noise(&mut self.rng);
        self.run.truth.step(dt_s);
        let truth = self.run.truth.state();
        let measurements = self.run.sensors.sample(&truth, dt_s, &mut self.rng);
        for e in &mut self.run.estimators {
            e.step(&measurements, dt_s);
        }
        self.run.truth.feedback(&self.run.estimators);
        self.t_s = truth.t_s;
        self.steps += 1;
        self.record(&truth);
        self.take_snapshot();
    }

    /// What the sensors' last sample adds to the 3D view.
    pub fn scene(&self) -> SceneExtras {
        self.run.sensors.scene()
    }

    /// The lab's live accuracy table (each estimator over the last window), if it has one.
    pub fn accuracy(&self) -> Option<(&'static str, f64, Vec<AccuracyRow>)> {
        self.accuracy.as_ref().map(|a| {
            (
                a.table().title,
                a.table().window_s,
                a.rows(&self.run.estimators),
            )
        })
    }

    /// Steps until `duration_s` more simulated time has passed.
    pub fn run_for(&mut self, duration_s: f64) {
        let end = self.t_s + duration_s;
        while self.t_s < end - 1e-9 * self.dt_s {
            self.step();
        }
    }

    fn record(&mut self, truth: &TruthState) {
        self.estimates.clear();
        for (i, e) in self.run.estimators.iter().enumerate() {
            let est = e.estimate();
            self.health.update(i, e.as_ref(), &est);
            self.estimates.push(est);
        }
        self.count_errors(truth);
        self.fill_row(truth);
        self.recorder.push(&self.row);
        if let Some(a) = &mut self.accuracy {
            a.push(truth, &self.estimates);
        }
    }

    /// The row of this instant, from the state as it is (no estimator is asked again).
    fn fill_row(&mut self, truth: &TruthState) {
        self.layout.fill(
            &mut self.row,
            self.run.truth.as_ref(),
            self.run.sensors.as_ref(),
            truth,
            &self.run.estimators,
            &self.estimates,
            self.health.codes(),
        );
    }

    /// The row of this instant again (a run restored from a snapshot) into a fresh recorder.
    fn refill_row(&mut self) {
        let truth = self.run.truth.state();
        self.fill_row(&truth);
        self.recorder.push(&self.row);
    }
}
