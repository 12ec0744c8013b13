//! Recorded single-axis gyro logs (paper 1's laboratory mode): CSV lines `time, rate`,
//! parsed leniently — every good line is kept, every bad one reported with its line number.

use thiserror::Error;

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

/// A parsed gyro log.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RateLog {
    /// Sample times (s), strictly increasing.
    pub t_s: Vec<f64>,
    /// Rates (rad/s).
    pub rate_rad_s: Vec<f64>,
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

fn field(s: &str) -> Option<f64> {
    s.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

/// Parses `text`: one sample per line, `time, rate` separated by a comma, semicolon, tab or
/// spaces; blank lines and lines starting with `#` are ignored; a first line that is not
/// numeric is taken as a header. Anything else that is wrong is reported, not fatal.
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
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let parts: Vec<&str> = line
            .split([',', ';', '\t', ' '])
            .filter(|s| !s.is_empty())
            .collect();
        let err = |reason: &str| LogLineError {
            line: i + 1,
            text: line.chars().take(80).collect(),
            reason: reason.to_string(),
        };
        let (Some(t), Some(r)) = (
            parts.first().and_then(|s| field(s)),
            parts.get(1).and_then(|s| field(s)),
        ) else {
            if i == 0
                || (log.t_s.is_empty()
                    && log.errors.is_empty()
                    && parts.iter().all(|p| field(p).is_none()))
            {
                continue; // a header
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

#[cfg(test)]
mod tests {
    use super::*;

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
