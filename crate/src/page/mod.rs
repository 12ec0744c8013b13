//! The page layer: what a lab shows and teaches, above the model's contracts and below the
//! simulation — the `Lab` trait (a lab's simulation with its page, lesson, notes and study),
//! what the page shows as data (views, figures, outages, diagrams), the lessons' steps, the
//! notes under a slider, and the page's policy (which tab a lab opens on, which series a tab
//! records, the speeds the page offers). Nothing here draws: the web crate does.
//!
//! ```text
//! math → model → page → dynamics, sensors, estimators → record, sim → analysis → labs → lessons → state, bin
//! ```

mod lab;
mod lesson;
mod note;
mod policy;
mod screen;

pub use lab::{AccuracyTable, Lab};
pub use lesson::{CycleTerm, Holds, Lesson, LessonStep, Question, Quote, QuoteSource, Reading};
pub use note::ParamNote;
pub use policy::{SPEED_RANGE, default_tab, tab_series};
pub use screen::{
    BodyShape, DEFAULT_VIEWS, Diagram, DiagramPoint, DiagramSetting, Figure, LOGGED_SAMPLE, Outage,
    Page, REPLAY_GAPS, SINGLE_AXIS_VIEWS, ViewKind,
};
