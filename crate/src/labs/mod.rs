//! The labs: one file per paper (plus the foundation's free-rotation lab), all listed in
//! [`all`]. The UI's lab picker, the CLI and the conformance tests iterate that one list.

mod free_rotation;
pub mod scenario;
mod suspended_mockup;
mod wz_sphere;

pub use free_rotation::FreeRotation;
pub use suspended_mockup::{P1ErrorStats, SuspendedMockup, p1_run_stats, p1_true_period_s};
pub use wz_sphere::{WzSphere, motion_of};

use crate::estimators::{Estimator, Measurements};
use crate::params::{ParamSpec, ParamValues};
use crate::record::SeriesSpec;
use nalgebra::{UnitQuaternion, Vector3};
use rand_chacha::ChaCha8Rng;

/// Every lab, in menu order.
pub fn all() -> &'static [&'static dyn Lab] {
    &[&FreeRotation, &SuspendedMockup, &WzSphere]
}

/// The lab with this id.
pub fn find(id: &str) -> Option<&'static dyn Lab> {
    all().iter().copied().find(|l| l.id() == id)
}

/// Comma-separated ids of all labs (for error messages).
pub fn ids() -> String {
    all().iter().map(|l| l.id()).collect::<Vec<_>>().join(", ")
}

/// The true motion at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TruthState {
    /// Simulation time (s).
    pub t_s: f64,
    /// True attitude.
    pub q_ref_from_body: UnitQuaternion<f64>,
    /// True body rate (rad/s).
    pub rate_body_rad_s: Vector3<f64>,
    /// True angle of a single-axis lab (rad).
    pub angle_rad: Option<f64>,
}

/// How the body really moves.
pub trait TruthModel: Send {
    /// New parameter values, effective from the next step.
    fn apply_params(&mut self, params: &ParamValues);
    /// Advance by `dt_s`.
    fn step(&mut self, dt_s: f64);
    /// The current state.
    fn state(&self) -> TruthState;
    /// Extra lab-specific series (e.g. energy), with their current values appended by
    /// [`TruthModel::extra_values`].
    fn extra_series(&self) -> Vec<SeriesSpec> {
        Vec::new()
    }
    /// Values of [`TruthModel::extra_series`], in order.
    fn extra_values(&self, _out: &mut Vec<f64>) {}
    /// Draws the random inputs (e.g. a disturbance torque) for the next step.
    fn draw_noise(&mut self, _rng: &mut ChaCha8Rng) {}
}

/// The lab's sensors.
pub trait SensorModel: Send {
    /// New parameter values, effective from the next sample.
    fn apply_params(&mut self, params: &ParamValues);
    /// Samples the sensors at the truth state, `dt_s` after the previous sample.
    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements;
}

/// One running instance of a lab.
pub struct LabRun {
    /// The truth model.
    pub truth: Box<dyn TruthModel>,
    /// The sensors.
    pub sensors: Box<dyn SensorModel>,
    /// The estimators, in legend order.
    pub estimators: Vec<Box<dyn Estimator>>,
}

/// One line of a reproduction report: a quantity, what the paper (or theory) says, what we
/// measured, and whether it agrees.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct AnchorRow {
    /// What is compared.
    pub quantity: String,
    /// The paper's (or the analytic) value, as text.
    pub expected: String,
    /// What this simulator measured.
    pub measured: f64,
    /// Unit of `measured`.
    pub unit: &'static str,
    /// Whether the measurement meets the expectation.
    pub pass: bool,
}

/// A lab's reproduction report.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Reproduction {
    /// Lab id.
    pub lab: String,
    /// The rows.
    pub rows: Vec<AnchorRow>,
    /// Notes on deviations and unstated parameters.
    pub notes: Vec<String>,
}

impl Reproduction {
    /// All rows pass.
    pub fn all_pass(&self) -> bool {
        self.rows.iter().all(|r| r.pass)
    }

    /// Plain-text table.
    pub fn to_table(&self) -> String {
        let w = self
            .rows
            .iter()
            .map(|r| r.quantity.chars().count())
            .max()
            .unwrap_or(8)
            .max(8);
        let mut s = format!(
            "== {} ==\n{:<w$}  {:>24}  {:>14}  {:<8} ok\n",
            self.lab, "quantity", "expected", "measured", "unit"
        );
        for r in &self.rows {
            s += &format!(
                "{:<w$}  {:>24}  {:>14.6e}  {:<8} {}\n",
                r.quantity,
                r.expected,
                r.measured,
                r.unit,
                if r.pass { "yes" } else { "NO" }
            );
        }
        for n in &self.notes {
            s += &format!("note: {n}\n");
        }
        s
    }
}

/// A named set of series plotted together, e.g. a figure of the paper.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Figure {
    /// Tab title, e.g. "Fig. 8: v and vᵃ".
    pub title: &'static str,
    /// Series names (as recorded) drawn in it.
    pub series: &'static [&'static str],
    /// Draw log10 of the values (covariance elements spanning decades).
    pub log: bool,
}

impl Figure {
    /// A figure on a linear axis.
    pub const fn new(title: &'static str, series: &'static [&'static str]) -> Self {
        Self {
            title,
            series,
            log: false,
        }
    }

    /// The same on a log10 axis.
    pub const fn log(self) -> Self {
        Self { log: true, ..self }
    }
}

/// A named set of parameter values (e.g. a real instrument) that the UI offers as a button
/// and the CLI as `--preset NAME`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Preset {
    /// Button label.
    pub name: &'static str,
    /// What it stands for.
    pub help: &'static str,
    /// (parameter key, value) pairs it sets.
    pub values: &'static [(&'static str, f64)],
}

/// A piece of work whose cost a lab wants measured (`attlab bench`, `attlab reproduce`).
pub struct TimingItem {
    /// What is timed.
    pub name: &'static str,
    /// One repetition.
    pub run: Box<dyn FnMut()>,
}

/// A lab: truth, sensors, estimators, parameters and the paper's anchors.
pub trait Lab: Sync {
    /// Stable id (`free-rotation`), used by the CLI and the URL.
    fn id(&self) -> &'static str;
    /// Menu title.
    fn title(&self) -> &'static str;
    /// The paper it reproduces (or "foundation").
    fn paper(&self) -> &'static str;
    /// A paragraph for the explanation panel: what happens and what each slider does.
    fn summary(&self) -> &'static str;
    /// Parameters (sliders).
    fn params(&self) -> &'static [ParamSpec];
    /// Simulation step for these parameters (s).
    fn dt_s(&self, params: &ParamValues) -> f64;
    /// A fresh run. Initial-condition randomness comes from `rng`.
    fn build(&self, params: &ParamValues, rng: &mut ChaCha8Rng) -> LabRun;
    /// Default run length for `reproduce` and the CLI (s).
    fn default_duration_s(&self) -> f64;
    /// Runs the lab's anchor scenarios and compares with the paper.
    fn reproduce(&self) -> Reproduction;
    /// The paper's figures as plot tabs.
    fn figures(&self) -> &'static [Figure] {
        &[]
    }
    /// Parameter sweeps the lab offers (run in the background of the page, or by tests).
    fn sweeps(&self) -> &'static [crate::sweep::SweepSpec] {
        &[]
    }
    /// True when the body hangs on a string (the 3D view draws it).
    fn suspended(&self) -> bool {
        false
    }
    /// True when the lab's estimators can run on a recorded single-axis gyro log.
    fn accepts_rate_log(&self) -> bool {
        false
    }
    /// Named parameter sets (instruments, scenarios).
    fn presets(&self) -> &'static [Preset] {
        &[]
    }
    /// Work whose cost the lab compares (timed by the CLI, never by tests).
    fn timing_items(&self) -> Vec<TimingItem> {
        Vec::new()
    }
}

impl LabRun {
    /// Steps truth and sensors only, `steps` times, and returns the measurements: the input
    /// for timing or replaying the estimators on their own.
    pub fn measurement_trace(
        &mut self,
        dt_s: f64,
        steps: usize,
        rng: &mut ChaCha8Rng,
    ) -> Vec<Measurements> {
        (0..steps)
            .map(|_| {
                self.truth.draw_noise(rng);
                self.truth.step(dt_s);
                let truth = self.truth.state();
                self.sensors.sample(&truth, dt_s, rng)
            })
            .collect()
    }
}
