//! The contracts every truth model, sensor model and estimator plugs into, and the plain
//! data they exchange. A leaf: it imports nothing of this crate but [`crate::math`], so every
//! other module can depend on it and it on none of them. What the page shows of a lab (its
//! views, figures, lesson, notes) and the `Lab` trait that ties a lab together are one layer
//! up, in the page layer (`page`).
//!
//! ```text
//! math → model → page → dynamics, sensors, estimators → record, sim → analysis → labs → lessons → state, bin
//! ```

mod cycle;
mod data;
mod estimate;
mod key;
mod lab;
mod log;
mod param_error;
mod params;
pub mod q;
mod quantity;
#[cfg(feature = "study")]
mod reading_error;
mod report;
mod scene;
mod score_error;
mod series;
mod study;
mod trouble;

pub use cycle::{
    CYCLE_ROWS, CYCLE_STATES, CycleUpdate, KalmanCycle, StateMatrix, StateVector, Teaching,
};
pub use data::LabData;
pub use estimate::{
    Attitude, Covariance, Estimate, Estimator, EstimatorStatus, Measurements, Outputs, STATUS_OK,
    Tuner,
};
pub use key::{Measure, SENSORS, SeriesKey, SeriesRef, TIME, TRUTH, names};
#[cfg(feature = "study")]
pub use lab::Chapter;
#[cfg(feature = "study")]
pub(crate) use lab::lab_chapter;
pub use lab::{LabRun, LabSpec, LabWords, Preset, SensorModel, Study, TruthModel, TruthState};
pub(crate) use lab::{lab_russian, lab_words};
pub use log::{
    ExampleLog, LineFault, LogCounts, LogFormat, LogGap, LogLineError, LogRefusal, OtherFormat,
    RateLog,
};
pub(crate) use params::find_spec;
pub use params::{ParamError, ParamKind, ParamSpec, ParamValues, Scale};
pub use quantity::{Quantity, StateInfo, StateKind};
#[cfg(feature = "study")]
pub use reading_error::ReadingError;
pub use report::{
    Calibration, Expectation, Outcome, ReproError, Reproduction, Row, RowKind, SENSITIVITY_FACTORS,
    fmt_sig,
};
pub use scene::{Direction, OrbitPicture, SceneExtras, SceneVector};
pub use score_error::{ScoreError, Scored, StatsError, Unscored};
pub use series::{Extras, PlotTab, SeriesGroup, SeriesSpec, display_unit};
pub use study::{OutputFile, OverlayFn, ScoreFn, SweepAxis, SweepScoring, SweepSpec, TimingItem};
pub use trouble::Trouble;
