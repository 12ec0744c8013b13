//! Recorded single-axis gyro logs (paper 1's laboratory mode): CSV lines `time, rate`,
//! (and, read by [`super::parse_imu_log`], paper 4's IMU logs with their accelerometer),
//! parsed leniently — every good line is kept, every bad one reported with its line number.

use super::log_lines::{Sample, read_log};
use crate::model::{LineFault, LogFormat, ParamSpec, ParamValues, RateLog};

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

/// Raw counts of a gyro's digital output and the calibration coefficients that turn them
/// into a rate (paper 1's on-board program sets them in a menu; it gives no values):
/// rate = (count − zero) · scale, in the log's rate unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RawCounts {
    /// `Some(b)`: each count is a `b`-bit word in two's complement, logged unsigned
    /// (0 … 2^b − 1; words from 2^(b−1) up are negative). `None`: counts are signed.
    pub word_bits: Option<u32>,
    /// The rate of one count, in the log's rate unit.
    pub scale: f64,
    /// The signed count read at rest.
    pub zero: f64,
}

impl RawCounts {
    /// The rate (in the log's rate unit) of raw value `raw`, or why it is not a count.
    ///
    /// ```
    /// # use attlab::sensors::RawCounts;
    /// let adis = RawCounts { word_bits: Some(12), scale: 0.2439, zero: 0.0 };
    /// assert_eq!(adis.rate(4095.0), Ok(-0.2439)); // 0xFFF is −1
    /// assert!(adis.rate(4096.0).unwrap_err().to_string().contains("0 … 4095"));
    /// ```
    pub fn rate(&self, raw: f64) -> Result<f64, LineFault> {
        let signed = match self.word_bits {
            None => raw,
            Some(bits) => {
                let words = 2f64.powi(bits as i32);
                if raw.fract() != 0.0 || !(0.0..words).contains(&raw) {
                    return Err(LineFault::NotAWord {
                        raw,
                        bits,
                        max: words - 1.0,
                    });
                }
                if raw >= words / 2.0 { raw - words } else { raw }
            }
        };
        Ok((signed - self.zero) * self.scale)
    }
}

/// Parses a one-axis gyro log: one sample per line, `time, rate`, separated by a comma,
/// semicolon, tab or spaces (whichever makes most lines samples). Every line is accounted
/// for by the rules of [`super::log_lines`] (header, banner, bad bytes, wrong widths) and
/// of the clock's repair (reordered, merged, glitches, gaps and resets); every good sample
/// is kept.
///
/// ```
/// # use attlab::sensors::{parse_rate_log, RateUnit, TimeUnit};
/// let log = parse_rate_log("t,rate\n0,1.5\n0.01,junk\n0.02,1.7\n", RateUnit::DegPerS, TimeUnit::Seconds);
/// assert_eq!(log.t_s, vec![0.0, 0.02]);
/// assert_eq!(log.errors[0].line, 3);
/// assert_eq!(log.counts.data_lines, 3);
/// ```
pub fn parse_rate_log(
    bytes: impl AsRef<[u8]>,
    rate_unit: RateUnit,
    time_unit: TimeUnit,
) -> RateLog {
    parse_rate_counts(bytes, None, rate_unit, time_unit)
}

/// [`parse_rate_log`] of a log whose rate column holds raw `counts` (with `None`, a rate):
/// a count that is not a word of its width is a bad line, reported with its number.
pub fn parse_rate_counts(
    bytes: impl AsRef<[u8]>,
    counts: Option<RawCounts>,
    rate_unit: RateUnit,
    time_unit: TimeUnit,
) -> RateLog {
    let time_scale = match time_unit {
        TimeUnit::Seconds => 1.0,
        TimeUnit::Milliseconds => 1e-3,
    };
    let k = rate_unit.to_rad_s();
    read_log(bytes.as_ref(), 2, "time, rate", time_scale, |v| {
        let rate = match counts {
            Some(c) => c.rate(v[1])?,
            None => v[1],
        };
        Ok(Sample {
            rate_rad_s: rate * k,
            imu: None,
        })
    })
}

/// What the rate column holds, as the `rate_counts` choice orders it: a rate, or raw counts
/// (signed, or unsigned words of 12 or 24 bits).
const COUNT_WORDS: [Option<Option<u32>>; 4] = [None, Some(None), Some(Some(12)), Some(Some(24))];

/// Names of [`COUNT_WORDS`] (`--log-set rate_counts=24-bit`).
const COUNT_WORD_NAMES: &[&str] = &[
    "no: the column is a rate",
    "signed counts",
    "12-bit words (two's complement)",
    "24-bit words (two's complement)",
];

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
           listed with their numbers and skipped. Every good sample is replayed once: times out \
           of order are put in place, equal times merged, a glitched time rejected, and a \
           restarted or stopped clock joined after a short gap.",
    load_label: "Load gyro log…",
    columns: 2,
    units: &[
        ParamSpec::choice("rate_unit", "rate", RATE_UNIT_NAMES, 0)
            .help("Unit of the rate column: °/s, m°/s (the paper's lab software) or rad/s."),
        ParamSpec::choice("time_unit", "time", TIME_UNIT_NAMES, 0)
            .help("Unit of the time column: seconds or milliseconds."),
        ParamSpec::choice("rate_counts", "raw counts", COUNT_WORD_NAMES, 0).help(
            "Whether the rate column holds the gyro's raw output, turned into the rate unit \
             by the calibration below (the paper's on-board program does this): signed \
             counts, or unsigned words in two's complement — 12 bits for the ADIS16100, 24 \
             for the VG-910D.",
        ),
        ParamSpec::real(
            "count_scale",
            "scale (rate unit per count)",
            "",
            1e-9,
            1e3,
            1.0,
        )
        .log()
        .requires("rate_counts")
        .help(
            "Calibration scale: the rate of one count. Nominal (the paper gives none): \
                 VG-910D 0.02384 m°/s (±200 °/s over 2²³ counts), ADIS16100 0.2439 °/s \
                 (its datasheet).",
        ),
        ParamSpec::real("count_zero", "zero (counts)", "", -8.4e6, 8.4e6, 0.0)
            .requires("rate_counts")
            .help("Calibration offset: the signed count the gyro reads at rest."),
    ],
    parse: parse_rate_with,
    // A rate can be anything: no unit fits better than another.
    check: |_, _| Ok(()),
};

/// [`parse_rate_counts`] with the unit choices of [`RATE_LOG`].
fn parse_rate_with(text: &[u8], units: &ParamValues) -> RateLog {
    let rate = RateUnit::ALL
        .get(units.index("rate_unit"))
        .map_or(RateUnit::DegPerS, |(u, _)| *u);
    let counts = COUNT_WORDS
        .get(units.index("rate_counts"))
        .copied()
        .flatten()
        .map(|word_bits| RawCounts {
            word_bits,
            scale: units.get("count_scale"),
            zero: units.get("count_zero"),
        });
    parse_rate_counts(text, counts, rate, time_unit(units, "time_unit"))
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
        let log = (RATE_LOG.parse)(b"0,1000\n10,2000\n", &units);
        assert_eq!(log.t_s, vec![0.0, 0.01]);
        assert!((log.rate_rad_s[1] - 2f64.to_radians()).abs() < 1e-12);
    }

    #[test]
    fn raw_words_become_rates_through_the_calibration_and_merge_as_rates() {
        let mut units = RATE_LOG.default_units();
        for (key, value) in [
            ("rate_unit", "mdeg_s"),
            ("time_unit", "ms"),
            ("rate_counts", "24-bit"),
            ("count_scale", "0.5"),
            ("count_zero", "-2"),
        ] {
            units.set_text(RATE_LOG.units, key, value).unwrap();
        }
        // 0xFFFFFF is −1; two lines at 10 ms (−1 and +1 counts) merge into their mean rate,
        // not into the mean word (8 388 608, the most negative count).
        let text = "0,8\n10,16777215\n10,1\n20,16777216\n30,2.5\n40,-3\n";
        let log = (RATE_LOG.parse)(text.as_bytes(), &units);
        let mdeg = |counts: f64| (counts + 2.0) * 0.5 * 1e-3f64.to_radians();
        assert_eq!(log.t_s, vec![0.0, 0.01]);
        assert!((log.rate_rad_s[0] - mdeg(8.0)).abs() < 1e-15);
        assert!(
            (log.rate_rad_s[1] - mdeg(0.0)).abs() < 1e-15,
            "{:?}",
            log.rate_rad_s
        );
        let lines: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
        assert_eq!(lines, vec![4, 5, 6], "{:?}", log.errors);
        assert!(
            log.errors[0]
                .reason
                .to_string()
                .contains("not a 24-bit word (0 … 16777215)")
        );
        // Signed counts take any number.
        units
            .set_text(RATE_LOG.units, "rate_counts", "signed")
            .unwrap();
        let log = (RATE_LOG.parse)(text.as_bytes(), &units);
        assert_eq!(log.counts.rejected, 0);
        assert!((log.rate_rad_s[4] - mdeg(-3.0)).abs() < 1e-15);
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
        let text = "time_ms;rate_mdeg_s\n0;1000\n10;1100\n\n# comment\n20;abc\n30\n25;1200\n40;1300;extra\n22;9\nnan;5\n50;1400\n";
        let log = parse_rate_log(text, RateUnit::MilliDegPerS, TimeUnit::Milliseconds);
        assert_eq!(log.t_s, vec![0.0, 0.01, 0.022, 0.025, 0.05]);
        assert!((log.rate_rad_s[0] - 1f64.to_radians()).abs() < 1e-15);
        let lines: Vec<usize> = log.errors.iter().map(|e| e.line).collect();
        assert_eq!(lines, vec![6, 7, 9, 11]);
        assert!(log.errors[0].to_string().contains("not a number: `abc`"));
        assert!(
            log.errors[1]
                .to_string()
                .contains("expected 2 columns (time, rate), found 1")
        );
        assert!(log.errors[2].to_string().contains("found 3"));
        // 22 ms comes after 25 ms: put in its place, and said so.
        assert_eq!(log.notes.len(), 1);
        assert!(
            log.notes[0]
                .to_string()
                .starts_with("line 10: out of order")
        );
        assert_eq!(
            (
                log.counts.data_lines,
                log.counts.kept,
                log.counts.reordered,
                log.counts.rejected
            ),
            (9, 5, 1, 4)
        );
        assert!((log.median_dt_s().unwrap() - 0.015).abs() < 1e-15);
    }
}
