//! A lab as the page and the CLI meet it: its simulation (the model's contracts), what the
//! page shows of it, its lesson, its notes and its study. Registered once in `labs::all()`.

use super::{Lesson, Page, ParamNote};
use crate::model::{LabRun, LabSpec, OutputFile, ParamSpec, ParamValues, Preset, Study, SweepSpec};
#[cfg(feature = "study")]
use crate::model::{ReproError, Reproduction, TimingItem};
use rand_chacha::ChaCha8Rng;

/// A lab's live accuracy table: one row per estimator, this run's σ over the last
/// `window_s` beside the paper's values.
#[derive(Clone, Copy, Debug)]
pub struct AccuracyTable {
    /// Title (names the paper's table).
    pub title: &'static str,
    /// Window the measured σ is taken over (s).
    pub window_s: f64,
    /// The paper's (attitude σ in deg, rate σ in deg/s) for an estimator id, where given.
    pub paper: fn(&str) -> [Option<f64>; 2],
    /// The number of the paper's table an estimator id's values are from (the page shows
    /// one tab per table); `None`: in no table.
    pub paper_table: fn(&str) -> Option<u8>,
}

/// A lab's simulation: its data, its step and a fresh run, with what the page shows of it
/// and, optionally, the study that checks it against the paper. Registered once in
/// `labs::all()`; the UI, the CLI and the tests iterate that list.
pub trait Lab: Sync {
    /// What the lab is.
    fn spec(&self) -> &'static LabSpec;
    /// Simulation step for these parameters (s).
    fn dt_s(&self, params: &ParamValues) -> f64;
    /// A fresh run. Initial-condition randomness comes from `rng`.
    fn build(&self, params: &ParamValues, rng: &mut ChaCha8Rng) -> LabRun;
    /// The run whose truth and sensors a recorded or live log replaces: by default
    /// [`Lab::build`]. A log has no truth, so a lab whose estimators start from the simulated
    /// truth's attitude starts them level instead (heading 0, where the log's clock starts).
    fn build_for_log(&self, params: &ParamValues, rng: &mut ChaCha8Rng) -> LabRun {
        self.build(params, rng)
    }
    /// What the page shows (views, body, figures, outages, diagrams, log formats), as data.
    fn page(&self) -> &'static Page {
        &Page::DEFAULT
    }
    /// The reproduction of the paper, the sweeps and the timings, if the lab has them.
    fn study(&self) -> Option<&dyn Study> {
        None
    }
    /// A live table of each estimator's accuracy beside the paper's, if the paper has one.
    fn accuracy_table(&self) -> Option<AccuracyTable> {
        None
    }
    /// The lab's guided lesson (its steps are data in the lab's folder, `lesson.rs`).
    fn lesson(&self) -> Option<&'static Lesson> {
        None
    }
    /// Lines computed from `params` that sit under a slider (none by default): what a
    /// setting implies, or a warning that it is outside what the rig allows.
    fn param_notes(&self, _params: &ParamValues) -> Vec<ParamNote> {
        Vec::new()
    }
}

/// The lab's data and its study's offers, read through any lab.
impl dyn Lab + '_ {
    /// [`LabSpec::id`].
    pub fn id(&self) -> &'static str {
        self.spec().id
    }
    /// [`LabSpec::title`].
    pub fn title(&self) -> &'static str {
        self.spec().title
    }
    /// [`LabSpec::paper`].
    pub fn paper(&self) -> &'static str {
        self.spec().paper
    }
    /// [`LabSpec::reference`].
    pub fn reference(&self) -> &'static str {
        self.spec().reference
    }
    /// [`LabSpec::summary`].
    pub fn summary(&self) -> &'static str {
        self.spec().summary
    }
    /// [`LabSpec::params`].
    pub fn params(&self) -> &'static [ParamSpec] {
        self.spec().params
    }
    /// [`LabSpec::presets`].
    pub fn presets(&self) -> &'static [Preset] {
        self.spec().presets
    }
    /// The preset with id `id`.
    pub fn preset(&self, id: &str) -> Option<&'static Preset> {
        self.presets().iter().find(|p| p.id == id)
    }
    /// [`LabSpec::default_duration_s`].
    pub fn default_duration_s(&self) -> f64 {
        self.spec().default_duration_s
    }
    /// The study's reproduction; an error for a lab without a study.
    #[cfg(feature = "study")]
    pub fn reproduce(&self) -> Result<Reproduction, ReproError> {
        match self.study() {
            Some(s) => s.reproduce(),
            None => Err(ReproError(format!(
                "{} has no study of its paper",
                self.id()
            ))),
        }
    }
    /// The study's sweeps (none without a study).
    pub fn sweeps(&self) -> &'static [SweepSpec] {
        self.study().map_or(&[], |s| s.sweeps())
    }
    /// The place of the sweep with id `id` among the lab's sweeps.
    pub fn sweep_index(&self, id: &str) -> Option<usize> {
        self.sweeps().iter().position(|s| s.id == id)
    }
    /// The study's timings (none without a study).
    #[cfg(feature = "study")]
    pub fn timing_items(&self) -> Vec<TimingItem> {
        self.study().map_or_else(Vec::new, |s| s.timing_items())
    }
    /// The study's golden-trace scenario (none without a study).
    pub fn golden_assignments(&self) -> &'static [&'static str] {
        self.study().map_or(&[], |s| s.golden_assignments())
    }
    /// The paper's output file for `params`, if the study defines one.
    pub fn output_file(&self, params: &ParamValues) -> Option<OutputFile> {
        self.study()?.output_file(params)
    }
}
