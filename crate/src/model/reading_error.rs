//! Why a lesson's reading could not be taken from its run (the `study` feature: only the
//! tests check a lesson's quotes against its run).

/// Why a reading (`page::Reading`) could not be taken off a run. Worded in English only because only the
/// CLI and the tests meet it: a page reader never takes a lesson's readings.
#[cfg(feature = "study")]
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum ReadingError {
    /// A `Reading::Lab` whose name the lab's study does not know.
    #[error("{lab} has no reading `{name}`")]
    NoSuchReading {
        /// The lab's id.
        lab: &'static str,
        /// The reading's name.
        name: &'static str,
    },
    /// A series with no values, or a value that is not finite, in the span read.
    #[error("{series} has no finite values in {from_s}…{to_s} s")]
    NoFiniteValues {
        /// The series' name.
        series: String,
        /// The span's start (s).
        from_s: f64,
        /// The span's end (s).
        to_s: f64,
    },
    /// A series with no finite value at or before the time read.
    #[error("no finite value")]
    NoFiniteValue,
    /// What a "first time" reading looks for never happens in the run.
    #[error("never, in the run")]
    Never,
    /// A method's update that its run does not reach.
    #[error("{method} has no update {k}")]
    NoUpdate {
        /// The method's id.
        method: &'static str,
        /// The update's number, from 1.
        k: usize,
    },
    /// A reading of the lab's own (`Reading::Lab`) handed to the statistics of a run's
    /// trace: the lab's study takes those, so this is a bug of the reader.
    #[error("not a reading over a span")]
    NotOverASpan,
    /// The run, or a statistic of it, could not be made: the analysis' error, as its text
    /// (this layer does not name the analysis; `From<AnalysisError>` sits in
    /// `lessons::quotes`).
    #[error("{0}")]
    Run(String),
}
