//! A log's row of numbers, as the line reader yields it and the timeline orders it.

/// One row of numbers of the expected width, with its 1-based line number.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Row {
    /// Line number in the file.
    pub line: usize,
    /// The numbers, as many as the columns.
    pub values: Vec<f64>,
    /// The line as read (trimmed): a live session records it as it came.
    pub text: String,
}

/// A line as a message quotes it: its first 80 characters.
pub(crate) fn shortened(text: &str) -> String {
    text.chars().take(80).collect()
}
