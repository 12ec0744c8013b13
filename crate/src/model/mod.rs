//! The contracts every lab, truth model, sensor model and estimator plugs into, and the plain
//! data they exchange. A leaf: it imports nothing of this crate but [`crate::math`], so every
//! other module can depend on it and it on none of them.
//!
//! ```text
//! math → model → dynamics, sensors, estimators → record, sim → analysis → labs → state, bin
//! ```

mod cycle;
mod data;
mod estimate;
mod key;
mod lab;
mod lesson;
mod log;
mod note;
mod page;
mod param_error;
mod params;
pub mod q;
mod quantity;
mod report;
mod score_error;
mod series;
mod study;
mod trouble;

pub use cycle::{CYCLE_ROWS, CYCLE_STATES, CycleUpdate, KalmanCycle, StateMatrix, StateVector};
pub use data::LabData;
pub use estimate::{
    Attitude, Covariance, Estimate, Estimator, EstimatorStatus, Measurements, Outputs, STATUS_OK,
    Tuner,
};
pub use key::{Measure, SENSORS, SeriesKey, SeriesRef, TIME, TRUTH, names};
#[cfg(feature = "study")]
pub use lab::Chapter;
pub use lab::{
    AccuracyTable, Lab, LabRun, LabSpec, LabWords, Preset, SensorModel, Study, TruthModel,
    TruthState,
};
#[cfg(feature = "study")]
pub use lesson::ReadingError;
pub use lesson::{CycleTerm, Holds, Lesson, LessonStep, Question, Quote, QuoteSource, Reading};
pub use log::{
    ExampleLog, LineFault, LogCounts, LogFormat, LogGap, LogLineError, LogRefusal, OtherFormat,
    RateLog,
};
pub use note::ParamNote;
pub use page::{
    BodyShape, DEFAULT_VIEWS, Diagram, DiagramPoint, DiagramSetting, Figure, LOGGED_SAMPLE,
    OrbitPicture, Outage, Page, REPLAY_GAPS, SINGLE_AXIS_VIEWS, SceneExtras, SceneVector, ViewKind,
};
pub use params::{ParamError, ParamKind, ParamSpec, ParamValues, Scale};
pub use quantity::{Quantity, StateInfo, StateKind};
pub use report::{
    Calibration, Expectation, Outcome, ReproError, Reproduction, Row, RowKind, SENSITIVITY_FACTORS,
    fmt_sig,
};
pub use score_error::{ScoreError, Scored, StatsError, Unscored};
pub use series::{Extras, PlotTab, SeriesGroup, SeriesSpec, display_unit};
pub use study::{OutputFile, OverlayFn, ScoreFn, SweepAxis, SweepScoring, SweepSpec, TimingItem};
pub use trouble::Trouble;
