//! Lines computed from a lab's current parameter values and shown under one slider: what a
//! setting implies (the period the string gives) or why it is out of bounds (a string too
//! thin to hold the body). The text is a message of the page catalogue with its arguments,
//! so it is translated like every other string.

/// One line under a slider.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamNote {
    /// The parameter it sits under.
    pub key: &'static str,
    /// The message id in the page catalogue (`crate/locales/*/page.ftl`).
    pub message: &'static str,
    /// The message's arguments, already formatted: each a number with its digits chosen, as
    /// Rust writes it (the page writes its decimal separator in the reader's language).
    pub args: Vec<(&'static str, String)>,
    /// A warning (the setting is outside what the paper's rig allows) rather than a fact.
    pub warning: bool,
}

impl ParamNote {
    /// A note of fact under `key`.
    pub fn info(
        key: &'static str,
        message: &'static str,
        args: Vec<(&'static str, String)>,
    ) -> Self {
        Self {
            key,
            message,
            args,
            warning: false,
        }
    }

    /// A warning under `key`.
    pub fn warning(
        key: &'static str,
        message: &'static str,
        args: Vec<(&'static str, String)>,
    ) -> Self {
        Self {
            warning: true,
            ..Self::info(key, message, args)
        }
    }
}
