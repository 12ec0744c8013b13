//! The lab contract: truth, sensors, estimators, parameters, figures and anchors.

use super::estimate::{ControlInput, Estimator, Measurements};
use super::params::{ParamSpec, ParamValues};
use super::report::{ReproError, Reproduction};
use super::series::SeriesSpec;
use nalgebra::{UnitQuaternion, Vector3};
use rand_chacha::ChaCha8Rng;

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
    /// Reaction-wheel momentum in body axes (N·m·s), for a spacecraft with wheels.
    pub wheel_momentum_body: Option<Vector3<f64>>,
    /// Its rate ḣ (N·m).
    pub wheel_torque_body: Option<Vector3<f64>>,
    /// The command of a controller that is part of the plant (paper 4).
    pub control: Option<ControlInput>,
}

impl TruthState {
    /// A state with an attitude and a rate (no angle, no wheels).
    pub fn new(
        t_s: f64,
        q_ref_from_body: UnitQuaternion<f64>,
        rate_body_rad_s: Vector3<f64>,
    ) -> Self {
        Self {
            t_s,
            q_ref_from_body,
            rate_body_rad_s,
            angle_rad: None,
            wheel_momentum_body: None,
            wheel_torque_body: None,
            control: None,
        }
    }
}

/// How the body really moves.
pub trait TruthModel: Send {
    /// New parameter values, effective from the next step.
    fn apply_params(&mut self, params: &ParamValues);
    /// Advance by `dt_s`.
    fn step(&mut self, dt_s: f64);
    /// The current state.
    fn state(&self) -> TruthState;
    /// Extra lab-specific series (e.g. energy), whose values [`TruthModel::extra_values`]
    /// writes.
    fn extra_series(&self) -> Vec<SeriesSpec> {
        Vec::new()
    }
    /// Writes the values of [`TruthModel::extra_series`], in order, into `out` (same length).
    fn extra_values(&self, _out: &mut [f64]) {}
    /// Draws the random inputs (e.g. a disturbance torque) for the next step.
    fn draw_noise(&mut self, _rng: &mut ChaCha8Rng) {}
}

/// The lab's sensors.
pub trait SensorModel: Send {
    /// New parameter values, effective from the next sample.
    fn apply_params(&mut self, params: &ParamValues);
    /// Samples the sensors at the truth state, `dt_s` after the previous sample.
    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements;
    /// Series the sensors know the truth of (their biases, whether they see), whose values
    /// [`SensorModel::extra_values`] writes.
    fn extra_series(&self) -> Vec<SeriesSpec> {
        Vec::new()
    }
    /// Writes the values of [`SensorModel::extra_series`], in order, into `out`.
    fn extra_values(&self, _out: &mut [f64]) {}
    /// What the last sample adds to the 3D view (reference directions, the orbit).
    fn scene(&self) -> SceneExtras {
        SceneExtras::default()
    }
}

/// A reference direction drawn from the body in the 3D view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneVector {
    /// Short label at its tip.
    pub label: &'static str,
    /// Unit direction in the reference frame.
    pub dir_ref: Vector3<f64>,
    /// Colour (sRGB).
    pub rgb: [u8; 3],
}

/// Where a satellite is on its orbit, for a small picture of the Earth beside the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitPicture {
    /// Position (ECI, m).
    pub position_eci_m: Vector3<f64>,
    /// Unit orbit normal (ECI).
    pub normal_eci: Vector3<f64>,
    /// Unit sun direction (ECI).
    pub sun_eci: Vector3<f64>,
    /// In the Earth's shadow.
    pub eclipse: bool,
    /// Earth radius (m).
    pub earth_radius_m: f64,
}

/// What a lab's sensors add to the 3D view.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneExtras {
    /// Reference directions (sun, field, nadir …).
    pub vectors: Vec<SceneVector>,
    /// The orbit, if the lab flies one.
    pub orbit: Option<OrbitPicture>,
}

/// The body the 3D view draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BodyShape {
    /// A box with two panels.
    #[default]
    Box,
    /// A hexagonal prism (TabletSat).
    HexPrism,
}

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

/// A sweep a lab offers, e.g. paper 1's adaptation window N over a log grid.
#[derive(Clone, Copy, Debug)]
pub struct SweepSpec {
    /// Title for the panel.
    pub title: &'static str,
    /// Parameter swept.
    pub key: &'static str,
    /// Values, in order.
    pub values: &'static [f64],
    /// A second parameter swept for each value of the first: the sweep becomes a grid, drawn
    /// as a heat map.
    pub grid: Option<SweepAxis>,
    /// Parameters set for every run of the sweep (e.g. a mode the sweep needs).
    pub fixed: &'static [(&'static str, f64)],
    /// Runs per value, seeds `seed`, `seed + 1`, …: a Monte Carlo over the noise.
    pub seeds: u64,
    /// Length of each run (s).
    pub duration_s: f64,
    /// Statistics are taken over t > `after_s`.
    pub after_s: f64,
    /// Series whose RMS (and maximum of |·|) is reported.
    pub series: &'static [&'static str],
    /// Scores the lab computes from each simulated run (medians over the seeds).
    pub scoring: Option<&'static SweepScoring>,
    /// Scores the lab computes from each run on a recorded log (no truth there), if the
    /// sweep can run on one.
    pub log_scoring: Option<&'static SweepScoring>,
}

impl SweepSpec {
    /// A one-parameter sweep of `key` over `values`, one seed, RMS of `series` only.
    pub const fn new(
        title: &'static str,
        key: &'static str,
        values: &'static [f64],
        duration_s: f64,
        series: &'static [&'static str],
    ) -> Self {
        Self {
            title,
            key,
            values,
            grid: None,
            fixed: &[],
            seeds: 1,
            duration_s,
            after_s: 0.0,
            series,
            scoring: None,
            log_scoring: None,
        }
    }

    /// The statistics start after `after_s`.
    pub const fn after(mut self, after_s: f64) -> Self {
        self.after_s = after_s;
        self
    }

    /// Each value runs over `seeds` seeds.
    pub const fn seeds(mut self, seeds: u64) -> Self {
        self.seeds = seeds;
        self
    }

    /// A grid: `key` is also swept over `values` for each value of the first.
    pub const fn grid(mut self, key: &'static str, values: &'static [f64]) -> Self {
        self.grid = Some(SweepAxis { key, values });
        self
    }

    /// Parameters set for every run.
    pub const fn fixed(mut self, fixed: &'static [(&'static str, f64)]) -> Self {
        self.fixed = fixed;
        self
    }

    /// The lab's scores of each simulated run.
    pub const fn scoring(mut self, scoring: &'static SweepScoring) -> Self {
        self.scoring = Some(scoring);
        self
    }

    /// The lab's scores of each run on a recorded log.
    pub const fn log_scoring(mut self, scoring: &'static SweepScoring) -> Self {
        self.log_scoring = Some(scoring);
        self
    }
}

/// The second parameter of a grid sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepAxis {
    /// Parameter swept.
    pub key: &'static str,
    /// Values, in order.
    pub values: &'static [f64],
}

/// The scores of one run: from its times and the columns of [`SweepScoring::series`], with
/// the run's parameters; an error says why the run cannot be scored.
pub type ScoreFn = fn(&ParamValues, &[f64], &[Vec<f64>]) -> Result<Vec<f64>, String>;

/// Lines drawn over a grid's heat map, in (key, grid key) coordinates, for the sweep's
/// parameters (e.g. paper 4's det Q = γ det R).
pub type OverlayFn = fn(&ParamValues) -> Vec<(String, Vec<[f64; 2]>)>;

/// What a lab scores in each run of a sweep beyond the RMS of series, e.g. paper 4's MSE
/// and transient time, and the weighted sums it minimises, e.g. J = α·MSE + β·t_tr.
#[derive(Clone, Copy, Debug)]
pub struct SweepScoring {
    /// Names of the scores, with units.
    pub names: &'static [&'static str],
    /// How each score is defined (the panel's help).
    pub help: &'static str,
    /// Series the scoring reads, in order.
    pub series: &'static [&'static str],
    /// The scoring.
    pub score: ScoreFn,
    /// Weighted sums of the scores, each with its name; the sweep marks each one's argmin.
    pub objectives: &'static [(&'static str, &'static [f64])],
    /// Lines over the heat map of a grid sweep.
    pub overlay: Option<OverlayFn>,
}

/// A lab's own output file, as its paper's program wrote it: these columns, one row per step,
/// and (if `stop` is given) ending at the first row where that series is 1.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputFile {
    /// Series written, in order (the first is usually `t_s`).
    pub columns: Vec<String>,
    /// Header cells for them (the paper's names).
    pub headers: Vec<String>,
    /// A 0/1 series: the file ends at the first row where it is 1.
    pub stop: Option<String>,
}

/// A sensor outage a lab's plots shade: the intervals where a recorded 0/1 series equals
/// `out_when` (e.g. paper 2's eclipse, or the star tracker unavailable).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outage {
    /// The 0/1 series.
    pub series: &'static str,
    /// Its value during the outage.
    pub out_when: f64,
    /// What the shading is called in the legend.
    pub label: &'static str,
}

/// A view the page's top row shows, left to right, as the lab declares (each lab shows what
/// explains it: a body turning about one axis has no use for the Riemann sphere).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewKind {
    /// The body in 3D with the estimate as a ghost.
    Body3d,
    /// The Riemann sphere: the vertical in body axes.
    Sphere,
    /// The complex plane of w (or the lab's diagram, when it has one).
    WPlane,
    /// A single-axis angle on a dial, a needle per source.
    Dial,
    /// Rate against angle, a trail per source.
    PhasePortrait,
}

impl ViewKind {
    /// A short lower-case name (file names, test output).
    pub fn slug(self) -> &'static str {
        match self {
            Self::Body3d => "body3d",
            Self::Sphere => "sphere",
            Self::WPlane => "wplane",
            Self::Dial => "dial",
            Self::PhasePortrait => "phase-portrait",
        }
    }
}

/// The views of a lab that does not say otherwise.
pub const DEFAULT_VIEWS: &[ViewKind] = &[ViewKind::Body3d, ViewKind::Sphere, ViewKind::WPlane];

/// The views of a lab whose body turns about one axis.
pub const SINGLE_AXIS_VIEWS: &[ViewKind] =
    &[ViewKind::Body3d, ViewKind::Dial, ViewKind::PhasePortrait];

/// A small x–y diagram a lab draws beside its plots (e.g. eigenvalues on the unit circle).
#[derive(Clone, Debug, PartialEq)]
pub struct Diagram {
    /// Title.
    pub title: String,
    /// Draw the unit circle.
    pub unit_circle: bool,
    /// Labelled points.
    pub points: Vec<DiagramPoint>,
}

/// One labelled point of a [`Diagram`].
#[derive(Clone, Debug, PartialEq)]
pub struct DiagramPoint {
    /// Legend text.
    pub label: String,
    /// Position (x, y).
    pub xy: [f64; 2],
    /// Id of the estimator the point belongs to (it takes that estimator's colour and hides
    /// with it), if any.
    pub source: Option<&'static str>,
}

/// A piece of work whose cost a lab wants measured (`attlab bench`, `attlab reproduce`).
pub struct TimingItem {
    /// What is timed.
    pub name: &'static str,
    /// Floating-point operations of one repetition, where counted (printed beside the time).
    pub flops: Option<u64>,
    /// One repetition.
    pub run: Box<dyn FnMut()>,
}

/// A lab: truth, sensors, estimators, parameters and the paper's anchors. Registered once in
/// `labs::all()`; the UI, the CLI and the tests iterate that list.
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
    fn reproduce(&self) -> Result<Reproduction, ReproError>;
    /// The paper's figures as plot tabs.
    fn figures(&self) -> &'static [Figure] {
        &[]
    }
    /// Outages the plots shade (every plot, every tab).
    fn outages(&self) -> &'static [Outage] {
        &[]
    }
    /// Parameter sweeps the lab offers (run in the background of the page, or by tests).
    fn sweeps(&self) -> &'static [SweepSpec] {
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
    /// True when the lab's estimators can run on a recorded IMU log (time, accelerometer,
    /// gyro; paper 4's Arduino and MPU-6050).
    fn accepts_imu_log(&self) -> bool {
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
    /// The paper's own output file, if the paper defines one (`attlab run --csv` writes it).
    fn output_file(&self, _params: &ParamValues) -> Option<OutputFile> {
        None
    }
    /// The views of the page's top row, left to right.
    fn views(&self) -> &'static [ViewKind] {
        DEFAULT_VIEWS
    }
    /// Diagrams that explain the current parameters (drawn beside the plots).
    fn diagrams(&self, _params: &ParamValues) -> Vec<Diagram> {
        Vec::new()
    }
    /// The body the 3D view draws.
    fn body_shape(&self) -> BodyShape {
        BodyShape::Box
    }
    /// A live table of each estimator's accuracy beside the paper's, if the paper has one.
    fn accuracy_table(&self) -> Option<AccuracyTable> {
        None
    }
}
