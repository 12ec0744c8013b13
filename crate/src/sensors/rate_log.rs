//! Recorded single-axis gyro logs (paper 1's laboratory mode): CSV lines `time, rate`,
//! (and, read by [`super::parse_imu_log`], paper 4's IMU logs with their accelerometer),
//! parsed leniently — every good line is kept, every bad one reported with its line number.

use crate::model::{LogFormat, LogLineError, ParamSpec, ParamValues, RateLog};

/// Unit of the rate column.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RateUnit {
    /// Degrees per second.
    DegPerS,
    /// Millidegrees per second (the paper's lab software).
    MilliDegPerS,
    /// Radians per second.
    RadPerS,
}

impl RateUnit {
    /// All units with their names, for menus and the CLI.
    pub const ALL: [(RateUnit, &'static str); 3] = [
        (Self::DegPerS, "deg_s"),
        (Self::MilliDegPerS, "mdeg_s"),
        (Self::RadPerS, "rad_s"),
    ];

    /// Factor to rad/s.
    pub fn to_rad_s(self) -> f64 {
        match self {
            Self::DegPerS => 1f64.to_radians(),
            Self::MilliDegPerS => 1e-3f64.to_radians(),
            Self::RadPerS => 1.0,
        }
    }

    /// The unit called `name` (`deg_s`, `mdeg_s`, `rad_s`).
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().find(|(_, n)| *n == name).map(|(u, _)| *u)
    }
}

/// Unit of the time column.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TimeUnit {
    /// Seconds.
    Seconds,
    /// Milliseconds (the paper's lab software).
    Milliseconds,
}

fn number(s: &str) -> Option<f64> {
    s.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

/// Delimiters a log may use, in order of preference when several fit equally well.
const DELIMITERS: [u8; 4] = [b',', b';', b'\t', b' '];

/// The trimmed fields of one line split at `delimiter` (whitespace runs count as one
/// delimiter).
fn fields(line: &str, delimiter: u8) -> Vec<&str> {
    let parts = line.split(char::from(delimiter)).map(str::trim);
    if delimiter.is_ascii_whitespace() {
        parts.filter(|f| !f.is_empty()).collect()
    } else {
        parts.collect()
    }
}

/// The delimiter under which most of the first lines read as samples (two numbers).
fn sniff_delimiter(text: &str) -> u8 {
    let sample: Vec<&str> = text.lines().take(200).collect();
    let score = |d: u8| {
        sample
            .iter()
            .filter(|l| {
                let f = fields(l, d);
                f.len() >= 2 && number(f[0]).is_some() && number(f[1]).is_some()
            })
            .count()
    };
    DELIMITERS
        .iter()
        .copied()
        .max_by_key(|d| {
            (
                score(*d),
                std::cmp::Reverse(DELIMITERS.iter().position(|x| x == d)),
            )
        })
        .unwrap_or(b',')
}

/// Parses `text` with the `csv` crate: one sample per line, `time, rate` separated by a
/// comma, semicolon, tab or spaces (whichever makes most lines samples); blank lines and
/// lines starting with `#` are ignored; the first line before the data whose fields are all
/// words is the header. Every other line that is not a sample is reported with its line
/// number and reason, and every sample is kept.
///
/// ```
/// # use attlab::sensors::{parse_rate_log, RateUnit, TimeUnit};
/// let log = parse_rate_log("t,rate\n0,1.5\n0.01,junk\n0.02,1.7\n", RateUnit::DegPerS, TimeUnit::Seconds);
/// assert_eq!(log.t_s, vec![0.0, 0.02]);
/// assert_eq!(log.errors[0].line, 3);
/// ```
pub fn parse_rate_log(text: &str, rate_unit: RateUnit, time_unit: TimeUnit) -> RateLog {
    let mut log = RateLog::default();
    let time_scale = match time_unit {
        TimeUnit::Seconds => 1.0,
        TimeUnit::Milliseconds => 1e-3,
    };
    let delimiter = sniff_delimiter(text);
    // One record per line: no quoting (a stray quote must not swallow the lines after it),
    // only '\n' ends a record (so the line numbers are the editor's).
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .quoting(false)
        .delimiter(delimiter)
        .terminator(csv::Terminator::Any(b'\n'))
        .from_reader(text.as_bytes());
    let mut header_seen = false;
    for record in reader.byte_records().filter_map(Result::ok) {
        let line = record.position().map_or(0, |p| p.line() as usize);
        let cells: Vec<String> = record
            .iter()
            .map(|f| {
                String::from_utf8_lossy(f)
                    .trim_matches(|c: char| c.is_whitespace())
                    .to_string()
            })
            .collect();
        let blank = cells.iter().all(String::is_empty)
            && (cells.len() == 1 || delimiter.is_ascii_whitespace());
        if blank || cells.first().is_some_and(|c| c.starts_with('#')) {
            continue;
        }
        let parts: Vec<&str> = cells
            .iter()
            .map(String::as_str)
            .filter(|c| !(delimiter.is_ascii_whitespace() && c.is_empty()))
            .collect();
        let trimmed = cells.join(&char::from(delimiter).to_string());
        let err = |reason: &str| LogLineError {
            line,
            text: trimmed.chars().take(80).collect(),
            reason: reason.to_string(),
        };
        let (Some(t), Some(r)) = (
            parts.first().and_then(|s| number(s)),
            parts.get(1).and_then(|s| number(s)),
        ) else {
            let words =
                parts.len() >= 2 && parts.iter().all(|p| !p.is_empty() && number(p).is_none());
            if log.t_s.is_empty() && !header_seen && words {
                header_seen = true; // the header
                continue;
            }
            log.errors.push(err(if parts.len() < 2 {
                "expected two columns: time, rate"
            } else {
                "not a number"
            }));
            continue;
        };
        let t = t * time_scale;
        if log.t_s.last().is_some_and(|last| t <= *last) {
            log.errors.push(err("time does not increase"));
            continue;
        }
        log.t_s.push(t);
        log.rate_rad_s.push(r * rate_unit.to_rad_s());
    }
    log
}

/// Names of the rate units, as [`RateUnit::ALL`] orders them (the CLI's `--rate-unit`).
const RATE_UNIT_NAMES: &[&str] = &["deg_s", "mdeg_s", "rad_s"];

/// Names of the time units (the CLI's `--time-unit`).
pub(super) const TIME_UNIT_NAMES: &[&str] = &["s", "ms"];

/// The time unit chosen as `key` in `units` (seconds if out of range).
pub(super) fn time_unit(units: &ParamValues, key: &str) -> TimeUnit {
    if units.index(key) == 1 {
        TimeUnit::Milliseconds
    } else {
        TimeUnit::Seconds
    }
}

/// A one-axis gyro log (paper 1's laboratory software): `time, rate` lines.
pub const RATE_LOG: LogFormat = LogFormat {
    id: "gyro-rate",
    name: "a one-axis gyro log (time, rate)",
    title: "Laboratory mode: recorded gyro log",
    help: "CSV lines `time, rate` (comma, semicolon, tab or space separated). Bad lines are \
           listed with their numbers and skipped.",
    load_label: "Load gyro log…",
    units: &[
        ParamSpec::choice("rate_unit", "rate", RATE_UNIT_NAMES, 0)
            .help("Unit of the rate column: °/s, m°/s (the paper's lab software) or rad/s."),
        ParamSpec::choice("time_unit", "time", TIME_UNIT_NAMES, 0)
            .help("Unit of the time column: seconds or milliseconds."),
    ],
    parse: parse_rate_with,
};

/// [`parse_rate_log`] with the unit choices of [`RATE_LOG`].
fn parse_rate_with(text: &str, units: &ParamValues) -> RateLog {
    let rate = RateUnit::ALL
        .get(units.index("rate_unit"))
        .map_or(RateUnit::DegPerS, |(u, _)| *u);
    parse_rate_log(text, rate, time_unit(units, "time_unit"))
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn the_formats_unit_names_follow_the_units_order() {
        for (i, (_, name)) in RateUnit::ALL.iter().enumerate() {
            assert_eq!(RATE_UNIT_NAMES[i], *name);
        }
        let mut units = RATE_LOG.default_units();
        units
            .set_text(RATE_LOG.units, "rate_unit", "mdeg_s")
            .unwrap();
        units.set_text(RATE_LOG.units, "time_unit", "ms").unwrap();
        let log = (RATE_LOG.parse)("0,1000\n10,2000\n", &units);
        assert_eq!(log.t_s, vec![0.0, 0.01]);
        assert!((log.rate_rad_s[1] - 2f64.to_radians()).abs() < 1e-12);
    }

    #[test]
    fn a_banner_before_the_header_is_reported_and_a_stray_quote_swallows_nothing() {
        let text = "MPU connection successful\ntime,rate\n0,1\n\"oops\n0.01,2\n";
        let log = parse_rate_log(text, RateUnit::DegPerS, TimeUnit::Seconds);
        assert_eq!(log.t_s, vec![0.0, 0.01]);
        let lines: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
        assert_eq!(lines, vec![1, 4], "{:?}", log.errors);
    }

    #[test]
    fn junk_lines_are_reported_with_line_numbers_and_good_ones_kept() {
        let text = "time_ms;rate_mdeg_s\n0;1000\n10;1100\n\n# comment\n20;abc\n30\n25;1200\n40;1300;extra\n35;9\nnan;5\n50;1400\n";
        let log = parse_rate_log(text, RateUnit::MilliDegPerS, TimeUnit::Milliseconds);
        assert_eq!(log.t_s, vec![0.0, 0.01, 0.025, 0.04, 0.05]);
        assert!((log.rate_rad_s[0] - 1f64.to_radians()).abs() < 1e-15);
        let lines: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
        assert_eq!(lines, vec![6, 7, 10, 11]);
        assert!(log.errors[0].to_string().contains("not a number"));
        assert!(log.errors[1].to_string().contains("two columns"));
        assert!(log.errors[2].to_string().contains("time does not increase"));
        assert!((log.median_dt_s().unwrap() - 0.0125).abs() < 1e-15);
    }
}
