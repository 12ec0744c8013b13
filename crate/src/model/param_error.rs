//! What was wrong with a parameter a reader gave: a slider's typed value, a CLI's `--set`,
//! a link's item.

use thiserror::Error;

/// What was wrong with a parameter given by a user (slider, `--set`, URL).
#[derive(Clone, Debug, Error, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum ParamError {
    /// No parameter of that name in this lab.
    #[error("unknown parameter `{key}` (this lab has: {known})")]
    Unknown {
        /// The key given.
        key: String,
        /// The lab's keys, comma separated.
        known: String,
    },
    /// The text is not a number.
    #[error("parameter `{key}`: `{text}` is not a number")]
    NotANumber {
        /// Parameter key.
        key: String,
        /// Text given.
        text: String,
    },
    /// NaN or infinite.
    #[error("parameter `{key}` must be a finite number")]
    NotFinite {
        /// Parameter key.
        key: String,
    },
    /// Outside the allowed range.
    #[error("parameter `{key}` = {value} is outside {min} … {max} {unit}")]
    OutOfRange {
        /// Parameter key.
        key: String,
        /// Value given.
        value: f64,
        /// Smallest allowed.
        min: f64,
        /// Largest allowed.
        max: f64,
        /// Unit of the range.
        unit: String,
    },
    /// A fractional value for an integer, toggle or choice.
    #[error("parameter `{key}` must be a whole number, got {value}")]
    NotInteger {
        /// Parameter key.
        key: String,
        /// Value given.
        value: f64,
    },
    /// A choice given by a name that matches no option, or several.
    #[error("parameter `{key}`: `{text}` names no single option (options: {options})")]
    NoSuchOption {
        /// Parameter key.
        key: String,
        /// Text given.
        text: String,
        /// The options with their indexes.
        options: String,
    },
    /// `key=value` expected.
    #[error("`{text}` is not of the form key=value")]
    Malformed {
        /// Text given.
        text: String,
    },
}
