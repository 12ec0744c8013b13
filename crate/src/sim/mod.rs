//! The fixed-step loop: truth → sensors → estimators → recorder.
//!
//! One `(lab, parameters, seed)` always gives the same run; live parameter changes are kept
//! in a journal with the step they happened at, so the run can be replayed exactly (the
//! page's CSV export re-runs it and streams every sample, while the recorder only keeps what
//! its memory budget allows).

mod accuracy;
mod csv;
mod layout;
mod replay;

pub use accuracy::{AccuracyRow, AccuracyTracker};
pub use csv::{CsvSink, csv_cell};
pub use layout::{Layout, Selection, UnknownSeries};

use crate::model::{
    Estimate, EstimatorStatus, Lab, LabRun, ParamError, ParamValues, PlotTab, SceneExtras,
    SeriesGroup, SeriesSpec, TruthState,
};
use crate::record::{DEFAULT_BUDGET_BYTES, Recorder};
use crate::sensors::RateLog;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use replay::{LogSensor, LogTruth};
use std::sync::Arc;

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
            selection: Selection::for_tab(lab, available, default_tab(lab)),
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

/// The tab a lab opens on: its first figure, or the errors when it has none.
pub fn default_tab(lab: &dyn Lab) -> PlotTab {
    if lab.figures().is_empty() {
        PlotTab::Group(SeriesGroup::Error)
    } else {
        PlotTab::Figure(0)
    }
}

/// A parameter change during a run: applied before step `step`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct JournalEntry {
    step: u64,
    key: &'static str,
    value: f64,
}

/// A running lab: one `(lab, parameters, seed)` always gives the same run.
pub struct Simulation {
    lab: &'static dyn Lab,
    params: ParamValues,
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
    statuses: Vec<EstimatorStatus>,
    status_codes: Vec<f64>,
    options: SimOptions,
    replay: Option<Arc<RateLog>>,
    journal: Vec<JournalEntry>,
    accuracy: Option<AccuracyTracker>,
}

impl Simulation {
    /// Starts `lab` with `params` (already validated) and `seed`, recording what the page
    /// shows first ([`SimOptions::page`]) in the default memory budget.
    pub fn new(lab: &'static dyn Lab, params: ParamValues, seed: u64) -> Self {
        // Built only to learn the series the lab has: the smallest recorder will do (a
        // second full budget here would raise the page's high-water mark for good).
        let probe = SimOptions {
            budget_bytes: 0,
            ..SimOptions::default()
        };
        let standard = match Self::with_options(lab, params, seed, probe) {
            Ok(sim) => sim,
            // The standard selection names no series, so it cannot be unknown.
            Err(e) => unreachable!("{e}"),
        };
        let page = SimOptions::page(lab, standard.available_specs());
        // A view names only series the lab has, so this keeps the standard one only if
        // something is badly wrong.
        Self::with_options(lab, standard.params.clone(), seed, page).unwrap_or(standard)
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
        Self::assemble(lab, params, seed, rng, run, options, None)
    }

    /// Runs `lab`'s estimators on a recorded gyro log instead of simulated truth and sensors
    /// (paper 1's laboratory mode). The step is the log's median sample interval; each step
    /// delivers the newest logged sample not yet delivered. There is no truth, so every error
    /// series is missing.
    pub fn replay(
        lab: &'static dyn Lab,
        params: ParamValues,
        log: RateLog,
        options: SimOptions,
    ) -> Result<Self, String> {
        log.median_dt_s()
            .filter(|d| *d > 0.0)
            .ok_or("the log needs at least two samples with increasing times")?;
        let log = Arc::new(log);
        let mut rng = ChaCha8Rng::seed_from_u64(0);
        let mut run = lab.build(&params, &mut rng);
        run.truth = Box::new(LogTruth::new(log.clone()));
        run.sensors = Box::new(LogSensor::new(log.clone()));
        Self::assemble(lab, params, 0, rng, run, options, Some(log)).map_err(|e| e.to_string())
    }

    fn assemble(
        lab: &'static dyn Lab,
        params: ParamValues,
        seed: u64,
        rng: ChaCha8Rng,
        run: LabRun,
        options: SimOptions,
        replay: Option<Arc<RateLog>>,
    ) -> Result<Self, UnknownSeries> {
        let figure_series: Vec<&str> = lab
            .figures()
            .iter()
            .flat_map(|f| f.series.iter().copied())
            .collect();
        let layout = Layout::new(
            lab.id(),
            run.truth.as_ref(),
            run.sensors.as_ref(),
            &run.estimators,
            &options.selection,
            &figure_series,
            !lab.suspended() && run.truth.state().angle_rad.is_none(),
        )?;
        let recorder = Recorder::with_budget(layout.specs().to_vec(), options.budget_bytes);
        let n = run.estimators.len();
        let dt_s = match replay.as_ref().and_then(|l| l.median_dt_s()) {
            Some(dt) => dt,
            None => lab.dt_s(&params),
        };
        let mut sim = Self {
            lab,
            initial_params: params.clone(),
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
            statuses: vec![EstimatorStatus::Ok; n],
            status_codes: vec![0.0; n],
            options,
            accuracy: lab.accuracy_table().map(|t| AccuracyTracker::new(t, n)),
            replay,
            journal: Vec::new(),
        };
        let truth = sim.run.truth.state();
        sim.record(&truth);
        Ok(sim)
    }

    /// Gives the recorder's memory back (an empty recorder of the same series): for a
    /// simulation about to be replaced, so the old and the new budget are never held at once.
    pub fn release_recorder(&mut self) {
        self.recorder = Recorder::with_window(Vec::new(), 2);
    }

    /// The log being replayed, if this is a replay.
    pub fn replay_log(&self) -> Option<&RateLog> {
        self.replay.as_deref()
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
        &self.statuses
    }

    /// Sets one parameter; takes effect on the next step without a restart (parameters
    /// marked `needs_reset` take effect at the next reset).
    pub fn set_param(&mut self, key: &str, value: f64) -> Result<(), ParamError> {
        let specs = self.lab.params();
        self.params.set(specs, key, value)?;
        if let Some(spec) = specs.iter().find(|s| s.key == key) {
            self.journal.push(JournalEntry {
                step: self.steps,
                key: spec.key,
                value,
            });
        }
        self.apply_params();
        Ok(())
    }

    fn apply_params(&mut self) {
        self.run.truth.apply_params(&self.params);
        self.run.sensors.apply_params(&self.params);
        for e in &mut self.run.estimators {
            e.apply_params(&self.params);
        }
        if self.replay.is_none() {
            self.dt_s = self.lab.dt_s(&self.params);
        }
    }

    /// Restarts from t = 0 with `seed` and the current parameters (reseeds the RNG, rebuilds
    /// truth and estimators); a replay restarts from the start of its log.
    pub fn reset(&mut self, seed: u64) {
        let options = self.options.clone();
        let fresh = match self.replay.take() {
            Some(log) => Self::replay(self.lab, self.params.clone(), (*log).clone(), options),
            None => Self::with_options(self.lab, self.params.clone(), seed, options)
                .map_err(|e| e.to_string()),
        };
        if let Ok(fresh) = fresh {
            *self = fresh;
        }
    }

    /// One fixed step.
    pub fn step(&mut self) {
        let dt_s = self.dt_s;
        self.run.truth.draw_noise(&mut self.rng);
        self.run.truth.step(dt_s);
        let truth = self.run.truth.state();
        let measurements = self.run.sensors.sample(&truth, dt_s, &mut self.rng);
        for e in &mut self.run.estimators {
            e.step(&measurements, dt_s);
        }
        self.t_s = truth.t_s;
        self.steps += 1;
        self.record(&truth);
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
            self.estimates.push(est);
            let status = e.status();
            let healthy = status.is_ok() && finite(&est, e.as_ref());
            let code = if healthy { 0.0 } else { status.code().max(1.0) };
            if code != self.status_codes[i] || (!status.is_ok() && self.statuses[i] != *status) {
                self.statuses[i] = match (healthy, status) {
                    (true, _) => EstimatorStatus::Ok,
                    (false, EstimatorStatus::Ok) => {
                        EstimatorStatus::Diverged("state or covariance is not finite".into())
                    }
                    (false, s) => s.clone(),
                };
                self.status_codes[i] = self.statuses[i].code();
            }
        }
        self.layout.fill(
            &mut self.row,
            self.run.truth.as_ref(),
            self.run.sensors.as_ref(),
            truth,
            &self.run.estimators,
            &self.estimates,
            &self.status_codes,
        );
        self.recorder.push(&self.row);
        if let Some(a) = &mut self.accuracy {
            a.push(truth, &self.estimates);
        }
    }

    /// Re-runs this run from its start — same lab, initial parameters, seed (or log) and the
    /// same parameter changes at the same steps — up to the current step, recording
    /// `selection`, and hands every row to `sink` (the specs first). Used to export every
    /// sample of a run whose recorder kept only a summary.
    pub fn rerun<E>(
        &self,
        selection: Selection,
        mut sink: impl FnMut(RerunItem<'_>) -> Result<(), E>,
    ) -> Result<u64, RerunError<E>> {
        let options = SimOptions {
            selection,
            budget_bytes: 1 << 16,
        };
        let mut sim = match &self.replay {
            Some(log) => Self::replay(
                self.lab,
                self.initial_params.clone(),
                (**log).clone(),
                options,
            )
            .map_err(RerunError::Setup)?,
            None => Self::with_options(self.lab, self.initial_params.clone(), self.seed, options)
                .map_err(|e| RerunError::Setup(e.to_string()))?,
        };
        sink(RerunItem::Specs(sim.specs())).map_err(RerunError::Sink)?;
        sink(RerunItem::Row(&sim.row)).map_err(RerunError::Sink)?;
        let mut next = 0;
        while sim.steps < self.steps {
            while let Some(entry) = self.journal.get(next).filter(|e| e.step == sim.steps) {
                // The journal holds values that were valid when set.
                let _ = sim.set_param(entry.key, entry.value);
                next += 1;
            }
            sim.step();
            sink(RerunItem::Row(&sim.row)).map_err(RerunError::Sink)?;
        }
        Ok(sim.steps + 1)
    }

    /// The same run recording `selection` instead: re-run from the start (same seed or log,
    /// same parameter changes at the same steps) up to this step, so the new series have
    /// their whole history. Its cost is the run so far at the new selection's speed.
    pub fn reselected(&self, selection: Selection) -> Result<Simulation, String> {
        let options = SimOptions {
            selection,
            budget_bytes: self.options.budget_bytes,
        };
        let mut sim = match &self.replay {
            Some(log) => Self::replay(
                self.lab,
                self.initial_params.clone(),
                (**log).clone(),
                options,
            )?,
            None => Self::with_options(self.lab, self.initial_params.clone(), self.seed, options)
                .map_err(|e| e.to_string())?,
        };
        let mut next = 0;
        while sim.steps < self.steps {
            while let Some(entry) = self.journal.get(next).filter(|e| e.step == sim.steps) {
                let _ = sim.set_param(entry.key, entry.value);
                next += 1;
            }
            sim.step();
        }
        // Changes made after the last step (none stepped since) still apply.
        for entry in &self.journal[next..] {
            let _ = sim.set_param(entry.key, entry.value);
        }
        Ok(sim)
    }

    /// [`Self::reselected`] in place, holding one recorder's memory at a time: this run's
    /// recorder goes first (the re-run rebuilds every series), which keeps the page's
    /// high-water mark down on a lab with many series. On an error the run goes on recording
    /// what it did (re-run again, or from now on if that fails too) and the error is returned.
    pub fn reselect(&mut self, selection: Selection) -> Result<(), String> {
        let specs = self.recorder.specs().to_vec();
        self.release_recorder();
        match self.reselected(selection) {
            Ok(sim) => {
                *self = sim;
                Ok(())
            }
            Err(e) => {
                match self.reselected(self.options.selection.clone()) {
                    Ok(sim) => *self = sim,
                    Err(_) => {
                        self.recorder = Recorder::with_budget(specs, self.options.budget_bytes);
                    }
                }
                Err(e)
            }
        }
    }

    /// Writes every sample of every series of the run so far as CSV (see
    /// [`Simulation::rerun`]); returns the number of rows.
    pub fn export_csv<W: std::io::Write>(&self, out: W) -> Result<u64, String> {
        let mut sink: Option<CsvSink<W>> = None;
        let mut out = Some(out);
        self.rerun(Selection::All, |item| match item {
            RerunItem::Specs(specs) => {
                let w = out.take().ok_or_else(|| "writer used twice".to_string())?;
                sink = Some(CsvSink::new(w, specs).map_err(|e| e.to_string())?);
                Ok(())
            }
            RerunItem::Row(row) => sink
                .as_mut()
                .ok_or_else(|| "row before header".to_string())?
                .row(row)
                .map_err(|e| e.to_string()),
        })
        .map_err(|e| e.to_string())?;
        sink.ok_or_else(|| "no header written".to_string())?
            .finish()
            .map_err(|e| e.to_string())
    }
}

/// What [`Simulation::rerun`] hands out: the specs once, then each row.
pub enum RerunItem<'a> {
    /// The series, before any row.
    Specs(&'a [SeriesSpec]),
    /// One row, in spec order.
    Row(&'a [f64]),
}

/// Why a re-run stopped.
#[derive(Debug, thiserror::Error)]
pub enum RerunError<E> {
    /// The run could not be rebuilt.
    #[error("cannot rebuild the run: {0}")]
    Setup(String),
    /// The sink refused a row.
    #[error("export failed: {0}")]
    Sink(E),
}

/// State, rate and covariance are all finite.
fn finite(est: &Estimate, e: &dyn crate::model::Estimator) -> bool {
    est.is_finite()
        && e.covariance()
            .is_none_or(|c| c.matrix.iter().all(|v| v.is_finite()))
}

/// Runs `lab` from its start for at most `duration_s` and writes the paper's output file
/// `file` (its columns under its headers, one row per step), ending at the first row where
/// `file.stop` is 1. Returns the rows written and whether the stop row was reached.
pub fn write_output_file<W: std::io::Write>(
    lab: &'static dyn Lab,
    params: ParamValues,
    seed: u64,
    duration_s: f64,
    file: &crate::model::OutputFile,
    out: W,
) -> Result<(u64, bool), String> {
    let mut names: Vec<&str> = file.columns.iter().map(String::as_str).collect();
    if let Some(stop) = &file.stop {
        names.push(stop);
    }
    let mut sim = Simulation::with_options(lab, params, seed, SimOptions::named(&names))
        .map_err(|e| e.to_string())?;
    let cols: Vec<usize> = file
        .columns
        .iter()
        .map(|c| sim.series_index(c))
        .collect::<Result<_, _>>()
        .map_err(|e| e.to_string())?;
    let stop = file
        .stop
        .as_deref()
        .map(|s| sim.series_index(s))
        .transpose()
        .map_err(|e| e.to_string())?;
    let mut writer = ::csv::Writer::from_writer(out);
    let io = |e: ::csv::Error| e.to_string();
    writer.write_record(&file.headers).map_err(io)?;
    let mut rows = 0;
    let end = duration_s - 1e-9 * sim.dt_s();
    loop {
        let row = sim.last_row();
        writer
            .write_record(cols.iter().map(|c| csv_cell(row[*c])))
            .map_err(io)?;
        rows += 1;
        if stop.is_some_and(|s| row[s] > 0.5) {
            writer.flush().map_err(|e| e.to_string())?;
            return Ok((rows, true));
        }
        if sim.t_s() >= end {
            break;
        }
        sim.step();
    }
    writer.flush().map_err(|e| e.to_string())?;
    Ok((rows, false))
}
