//! Recorded logs that a lab's laboratory mode replays through its estimators: the parsed
//! samples with the lines that could not be used, and the formats a lab reads (each with
//! the unit choices a user makes, as parameter specs, and its parser).

use super::params::{ParamError, ParamSpec, ParamValues};
use thiserror::Error;

/// One line that could not be used.
#[derive(Clone, Debug, Error, PartialEq)]
#[error("line {line}: {reason}: `{text}`")]
pub struct LogLineError {
    /// 1-based line number.
    pub line: usize,
    /// The line as read (shortened).
    pub text: String,
    /// What was wrong (or what became of it).
    pub reason: LineFault,
}

/// What was wrong with a log line, or what the clock's repair did with it. Typed so that the
/// page can say it in the reader's language; `Display` is the English of the CLI.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum LineFault {
    /// Not as many numbers as the format has columns.
    #[error("expected {expected} columns ({names}), found {found}{}", merged_hint(*.merged))]
    Columns {
        /// The format's columns.
        expected: usize,
        /// Their names, comma separated.
        names: &'static str,
        /// The fields on the line.
        found: usize,
        /// Twice as many fields: two lines merged by a lost line break.
        merged: bool,
    },
    /// Words before the first sample that are not the header.
    #[error("before the data (a sketch's banner?)")]
    BeforeData,
    /// A field that is not a number.
    #[error("not a number: `{0}`")]
    NotANumber(String),
    /// Bytes that are not UTF-8.
    #[error("not UTF-8 text: byte 0x{byte:02X} at column {column}")]
    NotUtf8 {
        /// The first bad byte.
        byte: u8,
        /// Its 1-based column (in characters).
        column: usize,
    },
    /// A raw count outside the converter's word.
    #[error("`{raw}` is not a {bits}-bit word (0 … {max})")]
    NotAWord {
        /// The number on the line.
        raw: f64,
        /// The word's bits.
        bits: u32,
        /// The largest word.
        max: f64,
    },
    /// A time off the clock that the lines after it continue without it.
    #[error("time glitch: {t_s} s between {last_s} s and the lines after it")]
    TimeGlitch {
        /// The line's time (s).
        t_s: f64,
        /// The time before it (s).
        last_s: f64,
    },
    /// The same time and values as an earlier line: counted once.
    #[error("same time as line {line}: a duplicate of it")]
    Duplicate {
        /// The earlier line.
        line: usize,
    },
    /// The same time as an earlier line with other values: the two averaged.
    #[error("same time as line {line}: averaged with it")]
    Averaged {
        /// The earlier line.
        line: usize,
    },
    /// Earlier than a line before it: put back in its place.
    #[error("out of order: put before line {line}")]
    OutOfOrder {
        /// The line it now comes before.
        line: usize,
    },
}

/// The hint a line with twice the columns gets.
fn merged_hint(merged: bool) -> &'static str {
    if merged { " (two lines merged?)" } else { "" }
}

/// Where a log's clock jumped or restarted, and the replay joined the two segments.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogGap {
    /// The line that starts the new segment.
    pub line: usize,
    /// The joined clock's time (s, as in `RateLog::t_s`) of the last sample before.
    pub from_s: f64,
    /// The joined clock's time (s) of the first sample after: the join is shown, at most
    /// max(10 periods, 1 s) long.
    pub to_s: f64,
    /// The logged time (s) of the last sample before.
    pub logged_from_s: f64,
    /// The logged time (s) of the first sample after (below `logged_from_s` for a reset).
    pub logged_to_s: f64,
}

/// Why a whole log cannot be replayed. Typed so that the page can say it in the reader's
/// language; `Display` is the English of the CLI.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum LogRefusal {
    /// The lab reads no logs.
    #[error("lab {lab} does not replay logs; these do: {}", .replaying.join(", "))]
    NotReplayed {
        /// The lab asked.
        lab: &'static str,
        /// The labs that replay logs.
        replaying: Vec<&'static str>,
    },
    /// Most lines of numbers have another width than the format's.
    #[error(
        "{lines} lines have {width} numbers and {own} have {columns}: lab {lab} reads \
         {format}, {columns} numbers a line.{}",
        looks_like(.other)
    )]
    OtherWidth {
        /// Lines of `width` numbers.
        lines: usize,
        /// Their width.
        width: usize,
        /// Lines of the format's width.
        own: usize,
        /// The format's width.
        columns: usize,
        /// The lab asked.
        lab: &'static str,
        /// Its format's name.
        format: &'static str,
        /// The format that `width` numbers a line would be, if a lab reads one.
        other: Option<OtherFormat>,
    },
    /// Fewer than two samples with increasing times.
    #[error(
        "the log needs at least two samples with increasing times ({counts}{})",
        first_bad(.first.as_ref())
    )]
    TooFewSamples {
        /// What became of the lines.
        counts: LogCounts,
        /// The first line that could not be used.
        first: Option<LogLineError>,
    },
    /// The accelerometer's median reading is far from 1 g: its unit does not fit.
    #[error(
        "the accelerometer reads a median of {median_g:.3e} g where about 1 g is expected: \
         its unit does not fit (the unit `{unit}` gives {gives_g:.2} g)"
    )]
    AccelUnit {
        /// The median reading in the chosen unit (g).
        median_g: f64,
        /// The unit choice that comes closest to 1 g.
        unit: &'static str,
        /// The median in that unit (g).
        gives_g: f64,
    },
}

/// A log format that another lab reads, named in [`LogRefusal::OtherWidth`].
#[derive(Clone, Debug, PartialEq)]
pub struct OtherFormat {
    /// Its name.
    pub name: &'static str,
    /// The labs that read it (the first one's catalogue words name it).
    pub labs: Vec<&'static str>,
}

/// " It looks like … (read by lab …)." or nothing.
fn looks_like(other: &Option<OtherFormat>) -> String {
    other.as_ref().map_or(String::new(), |o| {
        let s = if o.labs.len() == 1 { "" } else { "s" };
        format!(
            " It looks like {} (read by lab{s} {}).",
            o.name,
            o.labs.join(", ")
        )
    })
}

/// "; first bad line: …" or nothing.
fn first_bad(first: Option<&LogLineError>) -> String {
    first.map_or(String::new(), |e| format!("; first bad line: {e}"))
}

/// What became of every line of a log that counts (not blank, a comment or the header).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LogCounts {
    /// Lines that count.
    pub data_lines: usize,
    /// Samples kept (each delivered once by a replay).
    pub kept: usize,
    /// Of those, how many were out of order and put in their place.
    pub reordered: usize,
    /// Lines merged into a sample at the same time.
    pub merged: usize,
    /// Lines rejected (each with its reason in [`RateLog::errors`]).
    pub rejected: usize,
}

impl std::fmt::Display for LogCounts {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} samples kept of {} lines ({} reordered), {} merged, {} rejected",
            self.kept, self.data_lines, self.reordered, self.merged, self.rejected
        )
    }
}

/// A parsed log: a gyro's rate, and an accelerometer's reading for an IMU log.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RateLog {
    /// Sample times (s), strictly increasing: the logged clock, with the segments after a
    /// reset or a long gap joined (see [`RateLog::gaps`]).
    pub t_s: Vec<f64>,
    /// Rates (rad/s).
    pub rate_rad_s: Vec<f64>,
    /// Accelerometer readings (g), one per sample for an IMU log, empty for a rate log.
    pub accel_g: Vec<nalgebra::Vector3<f64>>,
    /// Three-axis gyro readings (rad/s, body axes), one per sample for an IMU log, empty
    /// for a rate log (whose one axis is [`RateLog::rate_rad_s`]; an IMU's x is too).
    pub gyro_body_rad_s: Vec<nalgebra::Vector3<f64>>,
    /// Lines that were rejected, with the reason.
    pub errors: Vec<LogLineError>,
    /// Lines kept but moved or merged, with what was done.
    pub notes: Vec<LogLineError>,
    /// Where the clock jumped or restarted.
    pub gaps: Vec<LogGap>,
    /// The nominal sample period (s): the median positive step between lines; 0 with
    /// fewer than two increasing times.
    pub period_s: f64,
    /// What became of every line.
    pub counts: LogCounts,
    /// How many lines of numbers had each column count (the format's own included), as
    /// `(columns, lines)`.
    pub widths: Vec<(usize, usize)>,
}

impl RateLog {
    /// The nominal sample period (s), if there are two samples with increasing times.
    pub fn median_dt_s(&self) -> Option<f64> {
        (self.t_s.len() >= 2 && self.period_s > 0.0).then_some(self.period_s)
    }

    /// The time (s) of sample `k` on a replay's clock: the log's, less its first time.
    /// A replay starts one period earlier, at −P, so that its first step delivers sample 0.
    pub fn replay_time_s(&self, k: usize) -> Option<f64> {
        Some(self.t_s.get(k)? - self.t_s.first()?)
    }

    /// The replay's clock from its start to its last sample (s).
    pub fn span_s(&self) -> f64 {
        self.t_s
            .last()
            .zip(self.t_s.first())
            .map_or(0.0, |(b, a)| b - a)
    }

    /// The length of a replay's step from time `now_s`: to the next sample, or one period
    /// when the next sample is more than 1.5 periods away (a gap is stepped through
    /// without samples, so it shows) or there is none.
    pub fn step_after(&self, now_s: f64) -> f64 {
        let p = self.period_s.max(f64::MIN_POSITIVE);
        let t0 = self.t_s.first().copied().unwrap_or(0.0);
        let next = self.t_s.partition_point(|t| t - t0 <= now_s + 1e-6 * p);
        match self.replay_time_s(next) {
            Some(t) if t - now_s <= 1.5 * p => t - now_s,
            _ => p,
        }
    }
}

/// A kind of recorded log a lab reads: what it is, the unit choices of its columns (choice
/// parameters, named as the CLI's `--<name>` flags: `rate_unit` is `--rate-unit`), and its
/// parser. Formats live beside their parsers (`sensors/`); a lab names the one it reads in
/// `page::Page::log_format`.
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
    /// Numbers per line.
    pub columns: usize,
    /// Reads a log's bytes with unit choices `units` (validated against [`Self::units`]).
    pub parse: fn(&[u8], &ParamValues) -> RateLog,
    /// Whether a parsed log fits the unit choices (e.g. an accelerometer near 1 g); the
    /// message says which choice would fit.
    pub check: fn(&RateLog, &ParamValues) -> Result<(), LogRefusal>,
}

impl LogFormat {
    /// The default unit choices.
    pub fn default_units(&self) -> ParamValues {
        ParamValues::defaults(self.units)
    }
}

/// A recorded log a lab ships for its laboratory mode (the page's "Replay the example log").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExampleLog {
    /// File name shown.
    pub name: &'static str,
    /// Its text, in the lab's log format.
    pub text: &'static str,
    /// The unit choices it is written in, as (`key`, option name or value) of the format's
    /// units; loading it sets them, so that the panel shows what it is read with.
    pub units: &'static [(&'static str, &'static str)],
}

impl ExampleLog {
    /// The format's default unit choices with this log's own set.
    pub fn unit_values(&self, format: &LogFormat) -> Result<ParamValues, ParamError> {
        let mut values = format.default_units();
        for (key, value) in self.units {
            values.set_text(format.units, key, value)?;
        }
        Ok(values)
    }
}
