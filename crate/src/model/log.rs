//! Recorded logs that a lab's laboratory mode replays through its estimators: the parsed
//! samples with the lines that could not be used, and the formats a lab reads (each with
//! the unit choices a user makes, as parameter specs, and its parser).

use super::params::{ParamSpec, ParamValues};
use thiserror::Error;

/// One line that could not be used.
#[derive(Clone, Debug, Error, PartialEq)]
#[error("line {line}: {reason}: `{text}`")]
pub struct LogLineError {
    /// 1-based line number.
    pub line: usize,
    /// The line as read (shortened).
    pub text: String,
    /// What was wrong.
    pub reason: String,
}

/// A parsed log: a gyro's rate, and an accelerometer's reading for an IMU log.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RateLog {
    /// Sample times (s), strictly increasing.
    pub t_s: Vec<f64>,
    /// Rates (rad/s).
    pub rate_rad_s: Vec<f64>,
    /// Accelerometer readings (g), one per sample for an IMU log, empty for a rate log.
    pub accel_g: Vec<nalgebra::Vector3<f64>>,
    /// Lines that were skipped, with the reason.
    pub errors: Vec<LogLineError>,
}

impl RateLog {
    /// Median sample interval (s), if there are at least two samples.
    pub fn median_dt_s(&self) -> Option<f64> {
        let mut d: Vec<f64> = self.t_s.windows(2).map(|w| w[1] - w[0]).collect();
        if d.is_empty() {
            return None;
        }
        d.sort_by(f64::total_cmp);
        let n = d.len();
        Some(if n % 2 == 1 {
            d[n / 2]
        } else {
            0.5 * (d[n / 2 - 1] + d[n / 2])
        })
    }
}

/// A kind of recorded log a lab reads: what it is, the unit choices of its columns (choice
/// parameters, named as the CLI's `--<name>` flags: `rate_unit` is `--rate-unit`), and its
/// parser. Formats live beside their parsers (`sensors/`); a lab names the one it reads in
/// [`super::Page::log_format`].
#[derive(Clone, Copy, Debug)]
pub struct LogFormat {
    /// Stable id.
    pub id: &'static str,
    /// What it is, in a sentence's words ("a one-axis gyro log").
    pub name: &'static str,
    /// Heading of the page's laboratory-mode panel.
    pub title: &'static str,
    /// What its lines look like and how bad lines are treated (the panel's help).
    pub help: &'static str,
    /// The load button's text.
    pub load_label: &'static str,
    /// Unit choices of the columns.
    pub units: &'static [ParamSpec],
    /// Reads a log's text with unit choices `units` (validated against [`Self::units`]).
    pub parse: fn(&str, &ParamValues) -> RateLog,
}

impl LogFormat {
    /// The default unit choices.
    pub fn default_units(&self) -> ParamValues {
        ParamValues::defaults(self.units)
    }
}
