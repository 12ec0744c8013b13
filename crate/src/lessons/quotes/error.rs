//! Why a quoted number does not hold for its run, and the analysis' errors as readings'.

use crate::analysis::AnalysisError;
use crate::model::{ParamError, ReadingError};

/// Why a [`crate::page::Quote`] does not hold for the run its step opens. Worded in English
/// only because only the CLI and the tests meet it: a page reader never checks quotes.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum QuoteError {
    /// The quote's words are not a number [`super::shown_number`] reads.
    #[error("not a number")]
    NotANumber {
        /// The words, as the English writes them.
        shown: &'static str,
    },
    /// The quote is the step's pause, but the step has none.
    #[error("the step has no pause")]
    NoPause,
    /// The run's reading is not the number written, within its tolerance.
    #[error("the run gives {got:.6e}, not {value} ± {tolerance:.1e}")]
    Off {
        /// What the run gives.
        got: f64,
        /// The number written.
        value: f64,
        /// How far the reading may be from it.
        tolerance: f64,
    },
    /// The run's reading is over the number the words say it stays under.
    #[error("the run gives {got:.6e}, over {value}")]
    Over {
        /// What the run gives.
        got: f64,
        /// The number written.
        value: f64,
    },
    /// The reading could not be taken.
    #[error(transparent)]
    Reading(#[from] ReadingError),
    /// A parameter the quote reads or sets is refused.
    #[error(transparent)]
    Param(#[from] ParamError),
}

/// The analysis' error as a reading's: its text (the model, below the analysis, cannot name
/// it).
impl From<AnalysisError> for ReadingError {
    fn from(e: AnalysisError) -> Self {
        ReadingError::Run(e.to_string())
    }
}
