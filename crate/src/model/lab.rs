//! What a lab is made of: its data (`LabSpec`), a run (truth, sensors, estimators) and the
//! study that checks it against its paper. The `Lab` trait that ties them to the page is in
//! the page layer (`page`).

use super::data::LabData;
use super::estimate::{Estimator, Measurements};
use super::params::{ParamSpec, ParamValues};
#[cfg(feature = "study")]
use super::reading_error::ReadingError;
#[cfg(feature = "study")]
use super::report::{ReproError, Reproduction};
use super::scene::SceneExtras;
use super::series::{Extras, SeriesSpec};
#[cfg(feature = "study")]
use super::study::TimingItem;
use super::study::{OutputFile, SweepSpec};
use nalgebra::{UnitQuaternion, Vector3};
use rand_chacha::ChaCha8Rng;

/// The true motion at one instant.
#[derive(Clone, Debug, PartialEq)]
pub struct TruthState {
    /// Simulation time (s).
    pub t_s: f64,
    /// True attitude (NaN for a replayed or live log, which has no truth).
    pub q_ref_from_body: UnitQuaternion<f64>,
    /// True body rate (rad/s; NaN for a log).
    pub rate_body_rad_s: Vector3<f64>,
    /// True angle of a single-axis lab (rad).
    pub angle_rad: Option<f64>,
    /// The lab's own state beyond these, for its sensors (paper 2's wheels, paper 4's
    /// controller command), typed by the lab.
    pub lab: LabData,
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
            lab: LabData::default(),
        }
    }
}

/// How the body really moves.
pub trait TruthModel: Send + dyn_clone::DynClone {
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
    fn extra_values(&self, _out: &mut Extras<'_>) {}
    /// Draws the random inputs (e.g. a disturbance torque) for the next step.
    fn draw_noise(&mut self, _rng: &mut ChaCha8Rng) {}
    /// The estimators after their step, for a truth whose controller closes its loop on an
    /// estimate (paper 4's Fig. 1): what it reads acts from the next step on. None by default.
    fn feedback(&mut self, _estimators: &[Box<dyn Estimator>]) {}
    /// The heap its clone allocates beyond its own struct (bytes; a time-travel snapshot is
    /// a clone, `sim::history` counts them): only a model that keeps a growing buffer says
    /// more than 0.
    fn heap_bytes(&self) -> usize {
        0
    }
}

dyn_clone::clone_trait_object!(TruthModel);

/// The lab's sensors.
pub trait SensorModel: Send + dyn_clone::DynClone {
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
    fn extra_values(&self, _out: &mut Extras<'_>) {}
    /// What the last sample adds to the 3D view (reference directions, the orbit).
    fn scene(&self) -> SceneExtras {
        SceneExtras::default()
    }
    /// The heap its clone allocates beyond its own struct (bytes; a time-travel snapshot is
    /// a clone, `sim::history` counts them): only a model that keeps a growing buffer says
    /// more than 0.
    fn heap_bytes(&self) -> usize {
        0
    }
}

dyn_clone::clone_trait_object!(SensorModel);

/// One running instance of a lab (a clone is an exact copy: the same run from here on).
#[derive(Clone)]
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

/// A named set of parameter values (e.g. a real instrument) that the UI offers as a button
/// and the CLI as `--preset NAME`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Preset {
    /// Stable id within the lab (`gamma-small`): its messages and a lesson step name it.
    pub id: &'static str,
    /// Button label.
    pub name: &'static str,
    /// What it stands for.
    pub help: &'static str,
    /// (parameter key, value) pairs it sets.
    pub values: &'static [(&'static str, f64)],
}

/// What a lab is, as data: its name, the paper, its parameters and presets. Shown by the
/// menu, the CLI and the help; the URL and the CLI name it by `id`.
#[derive(Clone, Copy, Debug)]
pub struct LabSpec {
    /// Stable id (`free-rotation`), used by the CLI and the URL.
    pub id: &'static str,
    /// Menu title.
    pub title: &'static str,
    /// The paper it reproduces (or "foundation").
    pub paper: &'static str,
    /// The paper's full reference, as the About line, the teacher notes and CITATION.cff
    /// give it (a field the project's digest of the paper lacks is said to be missing).
    pub reference: &'static str,
    /// A paragraph for the explanation panel: what happens and what each slider does.
    pub summary: &'static str,
    /// Parameters (sliders).
    pub params: &'static [ParamSpec],
    /// Named parameter sets (instruments, scenarios).
    pub presets: &'static [Preset],
    /// Default run length for `reproduce` and the CLI (s).
    pub default_duration_s: f64,
    /// Its words in the catalogue's languages, from its folder.
    pub words: LabWords,
}

/// A lab's own catalogue files, kept in its folder: `ru.ftl`, the Russian of every word the
/// lab says (its English is the code's own text), and `en.ftl`, the English words for what
/// its code writes as a code (a log column's unit choice `deg_s`). The page fetches the
/// Russian beside its wasm (`cargo xtask dist` joins every lab's `ru.ftl` into it), so its
/// wasm leaves `ru` empty; natively it is the file itself.
#[derive(Clone, Copy, Debug)]
pub struct LabWords {
    /// `en.ftl` ("" for a lab whose code writes only words).
    pub en: &'static str,
    /// `ru.ftl` ("" in the page's wasm).
    pub ru: &'static str,
}

/// `LabWords` of the lab whose folder calls it: `lab_words!()` reads its `ru.ftl`,
/// `lab_words!(en)` its `en.ftl` too (both beside the calling file). The page's wasm leaves
/// `ru` empty: it fetches the Russian that `cargo xtask dist` joins.
macro_rules! lab_words {
    () => {
        $crate::model::LabWords {
            en: "",
            ru: $crate::model::lab_russian!(),
        }
    };
    (en) => {
        $crate::model::LabWords {
            en: include_str!("en.ftl"),
            ru: $crate::model::lab_russian!(),
        }
    };
}
pub(crate) use lab_words;

/// The calling lab folder's `ru.ftl` (natively).
#[cfg(not(target_arch = "wasm32"))]
macro_rules! lab_russian {
    () => {
        include_str!("ru.ftl")
    };
}
/// Nothing in the page's wasm (it fetches the joined Russian).
#[cfg(target_arch = "wasm32")]
macro_rules! lab_russian {
    () => {
        ""
    };
}
pub(crate) use lab_russian;

/// The `Chapter` of the lab whose folder calls it: its `README.md`, beside the calling file.
#[cfg(feature = "study")]
macro_rules! lab_chapter {
    () => {
        $crate::model::Chapter {
            declared_in: file!(),
            text: include_str!("README.md"),
        }
    };
}
#[cfg(feature = "study")]
pub(crate) use lab_chapter;

/// A lab's chapter: `README.md` beside its code — what the paper did, what the lab shows,
/// its generated reproduction table and what differs and why.
#[cfg(feature = "study")]
#[derive(Clone, Copy, Debug)]
pub struct Chapter {
    /// The lab's source file that declares it, from the workspace root (`file!()`): the
    /// chapter sits beside it.
    pub declared_in: &'static str,
    /// The chapter's text when the crate was built (`include_str!("README.md")`).
    pub text: &'static str,
}

#[cfg(feature = "study")]
impl Chapter {
    /// Its path from the workspace root (`crate/src/labs/p4_quadrotor/README.md`).
    pub fn path(&self) -> std::path::PathBuf {
        std::path::Path::new(self.declared_in).with_file_name("README.md")
    }
}

/// What checks a lab against its paper: the reproduction, the sweeps, the timings and the
/// paper's own output file.
pub trait Study: Sync {
    /// Runs the lab's anchor scenarios and compares with the paper (with the `study`
    /// feature: the page never does, so its wasm leaves the reproductions out).
    #[cfg(feature = "study")]
    fn reproduce(&self) -> Result<Reproduction, ReproError>;
    /// The lab's chapter, `README.md` in its folder, with the reproduction's table between
    /// its markers (the `study` feature: `attlab reproduce all --readme` rewrites it and the
    /// tests compare it).
    #[cfg(feature = "study")]
    fn chapter(&self) -> Chapter;
    /// Parameter sweeps the lab offers (run in the background of the page, or by tests).
    fn sweeps(&self) -> &'static [SweepSpec] {
        &[]
    }
    /// Work whose cost the lab compares (timed by the CLI, never by tests; the `study` feature).
    #[cfg(feature = "study")]
    fn timing_items(&self) -> Vec<TimingItem> {
        Vec::new()
    }
    /// The paper's own output file, if the paper defines one (`attlab run --csv` writes it).
    fn output_file(&self, _params: &ParamValues) -> Option<OutputFile> {
        None
    }
    /// A lesson's reading of the lab's own (`page::Reading::Lab`) named `name`, on the
    /// run of `params` at `seed`: `None` for a name the lab does not know (the `study`
    /// feature: the page never reads them).
    #[cfg(feature = "study")]
    fn lesson_reading(
        &self,
        _name: &str,
        _params: &ParamValues,
        _seed: u64,
    ) -> Option<Result<f64, ReadingError>> {
        None
    }
    /// The scenario of the lab's golden trace (`golden.json` in its folder): assignments on top of its
    /// defaults that switch its sensor errors on where the defaults have none, so the noise
    /// generators are pinned too.
    fn golden_assignments(&self) -> &'static [&'static str] {
        &[]
    }
}
