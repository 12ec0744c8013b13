//! The lines of a recorded log, format-blind: bytes in, numeric rows of the expected width
//! out, and every other line accounted for by its number and reason. Both importers (the
//! one-axis gyro log and the MPU-6050 IMU log) read through here, with the `csv` crate.
//!
//! * A UTF-8 byte-order mark is stripped before anything else.
//! * The delimiter (comma, semicolon, tab or spaces) is the one under which most of the
//!   first 200 lines are all numbers.
//! * Blank lines and lines starting with `#` are skipped silently; so is the header: the
//!   first line before the data whose fields are all words, as many as the columns.
//! * A line with invalid UTF-8 is a bad line, reported with its line and column; the rest
//!   of the log is read.
//! * A row of numbers of another width is reported with both widths ("two lines merged?"
//!   when it is exactly twice as wide); the widths seen are counted, so the caller can
//!   tell a log of another format from a few bad lines.

use super::row::{Row, shortened};
use super::timeline;
use crate::model::{LineFault, LogCounts, LogLineError, RateLog};
use nalgebra::Vector3;

/// Delimiters a log may use, in order of preference when several fit equally well.
const DELIMITERS: [u8; 4] = [b',', b';', b'\t', b' '];

/// What [`read_rows`] found.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Rows {
    /// Rows of the expected width, in file order.
    pub rows: Vec<Row>,
    /// Lines that are not rows (a banner, words, too few or too many columns, bad bytes).
    pub errors: Vec<LogLineError>,
    /// Lines that count: every line but blank ones, comments and the header.
    pub data_lines: usize,
    /// How many lines of numbers had each width (the expected one included), as
    /// `(width, lines)` in the order first seen.
    pub widths: Vec<(usize, usize)>,
    /// The nominal period a `# period_s=` comment states (s), if one does.
    pub period_s: Option<f64>,
}

/// A finite number, or `None`.
pub(crate) fn number(s: &str) -> Option<f64> {
    s.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

/// The fields of `line` at `delimiter`: trimmed; whitespace runs count as one delimiter;
/// one trailing empty field (a delimiter at the end of the line) is dropped.
fn fields(line: &str, delimiter: u8) -> Vec<&str> {
    let parts = line.split(char::from(delimiter)).map(str::trim);
    let mut f: Vec<&str> = if delimiter.is_ascii_whitespace() {
        parts.filter(|f| !f.is_empty()).collect()
    } else {
        parts.collect()
    };
    if f.len() > 1 && f.last() == Some(&"") {
        f.pop();
    }
    f
}

fn all_numbers(f: &[&str]) -> bool {
    f.len() >= 2 && f.iter().all(|c| number(c).is_some())
}

/// The delimiter under which most of the first lines are rows of numbers.
fn sniff_delimiter(text: &str) -> u8 {
    let sample: Vec<&str> = text.lines().take(200).collect();
    let score = |d: u8| sample.iter().filter(|l| all_numbers(&fields(l, d))).count();
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

/// `bytes` without a leading UTF-8 byte-order mark.
fn without_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes)
}

/// The comment that states a log's nominal period (a live session's record writes it, so
/// that its replay applies the clock's rules with the period the session used).
pub(crate) const PERIOD_DIRECTIVE: &str = "# period_s=";

/// Lines classified one at a time, by the module's rules: a batch read and a live stream
/// share it.
#[derive(Clone, Debug)]
pub(crate) struct LineReader {
    columns: usize,
    names: &'static str,
    /// The delimiter, once known.
    pub delimiter: Option<u8>,
    header_seen: bool,
    rows_seen: bool,
    /// What was read so far.
    pub out: Rows,
}

impl LineReader {
    /// A reader of rows of `columns` numbers (`names` says which, for the messages),
    /// split at `delimiter` (`None`: the first line of numbers fixes it).
    pub(crate) fn new(columns: usize, names: &'static str, delimiter: Option<u8>) -> Self {
        Self {
            columns,
            names,
            delimiter,
            header_seen: false,
            rows_seen: false,
            out: Rows::default(),
        }
    }

    /// Reads line number `line` (its bytes without the line break).
    pub(crate) fn line(&mut self, line: usize, raw: &[u8]) {
        let text = match std::str::from_utf8(raw) {
            Ok(text) => text.trim(),
            Err(e) => {
                self.out.data_lines += 1;
                self.out.errors.push(bad_bytes(line, raw, e.valid_up_to()));
                return;
            }
        };
        if let Some(p) = text.strip_prefix(PERIOD_DIRECTIVE).and_then(number) {
            self.out.period_s.get_or_insert(p);
        }
        if text.is_empty() || text.starts_with('#') {
            return;
        }
        let delimiter = match self.delimiter {
            Some(d) => d,
            None => {
                let d = line_delimiter(text, self.columns);
                if all_numbers(&fields(text, d)) {
                    self.delimiter = Some(d);
                }
                d
            }
        };
        self.classify(line, text, &fields(text, delimiter));
    }

    fn classify(&mut self, line: usize, text: &str, f: &[&str]) {
        let (columns, out) = (self.columns, &mut self.out);
        let words = f.iter().all(|c| !c.is_empty() && number(c).is_none());
        let before_data = !self.rows_seen && !self.header_seen;
        if before_data && words && f.len() == columns {
            self.header_seen = true;
            return;
        }
        out.data_lines += 1;
        let names = self.names;
        if all_numbers(f) {
            match out.widths.iter_mut().find(|(w, _)| *w == f.len()) {
                Some((_, n)) => *n += 1,
                None => out.widths.push((f.len(), 1)),
            }
            if f.len() == columns {
                let values = f.iter().filter_map(|c| number(c)).collect();
                let text = text.to_string();
                out.rows.push(Row { line, values, text });
                self.rows_seen = true;
                return;
            }
            let reason = LineFault::Columns {
                expected: columns,
                names,
                found: f.len(),
                merged: f.len() == 2 * columns,
            };
            let text = shortened(text);
            out.errors.push(LogLineError { line, text, reason });
            return;
        }
        let reason = if before_data {
            LineFault::BeforeData
        } else if f.len() != columns {
            LineFault::Columns {
                expected: columns,
                names,
                found: f.len(),
                merged: false,
            }
        } else {
            let bad = f.iter().find(|c| number(c).is_none()).unwrap_or(&"");
            LineFault::NotANumber((*bad).to_string())
        };
        let text = shortened(text);
        out.errors.push(LogLineError { line, text, reason });
    }
}

/// The delimiter of a single line: the first under which it is `columns` numbers, else
/// `columns` words (a header), else any numbers; a comma when none fits.
fn line_delimiter(text: &str, columns: usize) -> u8 {
    let fits = |test: &dyn Fn(&[&str]) -> bool| {
        DELIMITERS.iter().copied().find(|d| test(&fields(text, *d)))
    };
    fits(&|f| f.len() == columns && all_numbers(f))
        .or_else(|| fits(&|f| f.len() == columns && f.iter().all(|c| number(c).is_none())))
        .or_else(|| fits(&|f| all_numbers(f)))
        .unwrap_or(b',')
}

/// Reads `bytes` as rows of `columns` numbers (`names` says which, for the messages: "time,
/// rate"). See the module documentation for the rules.
pub(crate) fn read_rows(bytes: &[u8], columns: usize, names: &'static str) -> Rows {
    let bytes = without_bom(bytes);
    let delimiter = sniff_delimiter(&String::from_utf8_lossy(&bytes[..bytes.len().min(1 << 16)]));
    // One record per line: no quoting (a stray quote must not swallow the lines after it),
    // only '\n' ends a record (so the line numbers are the editor's).
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .quoting(false)
        .delimiter(delimiter)
        .terminator(csv::Terminator::Any(b'\n'))
        .from_reader(bytes);
    let mut lines = LineReader::new(columns, names, Some(delimiter));
    for record in reader.byte_records().filter_map(Result::ok) {
        let Some(position) = record.position() else {
            continue;
        };
        let start = (position.byte() as usize).min(bytes.len());
        let raw = bytes[start..].split(|b| *b == b'\n').next().unwrap_or(&[]);
        lines.line(position.line() as usize, raw);
    }
    lines.out
}

/// What one row of a log holds once decoded: the rate about the lab's axis (rad/s) and, for
/// an IMU log, the acceleration (g) and the three gyro axes (rad/s, body axes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Sample {
    /// The rate about the lab's axis (rad/s): a rate log's column, an IMU's gx.
    pub rate_rad_s: f64,
    /// An IMU's accelerometer (g) and gyro (rad/s), in body axes.
    pub imu: Option<(Vector3<f64>, Vector3<f64>)>,
}

impl Sample {
    /// The row's values once decoded, time first: `[t, rate]` or
    /// `[t, rate, ax, ay, az, gx, gy, gz]` (what the clock's rules merge and order).
    pub(crate) fn values(&self, t: f64) -> Vec<f64> {
        let mut v = vec![t, self.rate_rad_s];
        if let Some((a, g)) = self.imu {
            v.extend(a.iter().chain(g.iter()).copied());
        }
        v
    }
}

/// A decoded row, or why the row cannot be used.
pub(crate) type Decoded = Result<Sample, LineFault>;

/// Reads `bytes` as a log of `columns` numbers per line (`names` says which), time first
/// in units of `time_scale` s, its clock repaired ([`timeline`]); `sample` turns one row's
/// numbers (time first) into a rate (rad/s) and, for an IMU log, an acceleration (g), or
/// rejects the row with a reason (a raw word out of its range). Rows are decoded before
/// lines at one time are merged, so that merging averages rates, not raw words.
pub(crate) fn read_log(
    bytes: &[u8],
    columns: usize,
    names: &'static str,
    time_scale: f64,
    sample: impl Fn(&[f64]) -> Decoded,
) -> RateLog {
    let Rows {
        rows,
        errors,
        data_lines,
        widths,
        period_s,
    } = read_rows(bytes, columns, names);
    let (rows, undecodable) = decode_rows(rows, sample);
    let errors = merge_by_line(errors, undecodable);
    let mut glitches = Vec::new();
    let timeline = timeline::order(rows, time_scale, period_s, &mut glitches);
    let errors = merge_by_line(errors, glitches);
    let mut log = RateLog {
        period_s: timeline.period_s.unwrap_or(0.0),
        gaps: timeline.gaps,
        notes: timeline.notes,
        widths,
        ..RateLog::default()
    };
    for s in &timeline.samples {
        push_sample(&mut log, s);
    }
    log.counts = LogCounts {
        data_lines,
        kept: log.t_s.len(),
        reordered: timeline.reordered,
        merged: timeline.merged,
        rejected: errors.len(),
    };
    log.errors = errors;
    log
}

/// Appends a kept sample (its row decoded: [`Sample::values`]) to `log`.
pub(crate) fn push_sample(log: &mut RateLog, s: &timeline::Timed) {
    let v = &s.row.values;
    log.t_s.push(s.t_s);
    log.rate_rad_s.push(v[1]);
    if let [_, _, ax, ay, az, gx, gy, gz] = v[..] {
        log.accel_g.push(Vector3::new(ax, ay, az));
        log.gyro_body_rad_s.push(Vector3::new(gx, gy, gz));
    }
}

/// Each row decoded by `sample` ([`Sample::values`]), and the
/// rows `sample` rejects as line errors, both in line order.
fn decode_rows(
    rows: Vec<Row>,
    sample: impl Fn(&[f64]) -> Decoded,
) -> (Vec<Row>, Vec<LogLineError>) {
    let mut errors = Vec::new();
    let rows = rows
        .into_iter()
        .filter_map(|row| match sample(&row.values) {
            Ok(decoded) => {
                let values = decoded.values(row.values[0]);
                Some(Row { values, ..row })
            }
            Err(reason) => {
                errors.push(LogLineError {
                    line: row.line,
                    text: shortened(&row.text),
                    reason,
                });
                None
            }
        })
        .collect();
    (rows, errors)
}

/// Two lists of line errors, each in line order, as one in line order.
pub(crate) fn merge_by_line(a: Vec<LogLineError>, b: Vec<LogLineError>) -> Vec<LogLineError> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut a, mut b) = (a.into_iter().peekable(), b.into_iter().peekable());
    loop {
        let take_a = match (a.peek(), b.peek()) {
            (Some(x), Some(y)) => x.line <= y.line,
            (Some(_), None) => true,
            (None, Some(_)) => false,
            (None, None) => return out,
        };
        out.extend(if take_a { a.next() } else { b.next() });
    }
}

/// The error for line `line` whose bytes `raw` are valid UTF-8 up to `valid`.
fn bad_bytes(line: usize, raw: &[u8], valid: usize) -> LogLineError {
    let good = String::from_utf8_lossy(&raw[..valid]);
    let byte = raw.get(valid).copied().unwrap_or(0);
    LogLineError {
        line,
        text: String::from_utf8_lossy(raw).chars().take(80).collect(),
        reason: LineFault::NotUtf8 {
            byte,
            column: good.chars().count() + 1,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bom_a_bad_byte_and_merged_lines_are_each_one_line_of_their_own() {
        let mut bytes = b"\xEF\xBB\xBF0,1\n0.1,2\n0.2,\xFF3\n0.3,4,0.4,5\n0.5,6,\n".to_vec();
        bytes.extend_from_slice(b"\n# note\n0.6;7\n");
        let r = read_rows(&bytes, 2, "time, rate");
        let lines: Vec<usize> = r.rows.iter().map(|r| r.line).collect();
        assert_eq!(
            lines,
            vec![1, 2, 5],
            "the BOM line is data; a trailing comma is fine"
        );
        let bad: Vec<(usize, String)> = r
            .errors
            .iter()
            .map(|e| (e.line, e.reason.to_string()))
            .collect();
        assert_eq!(
            bad,
            vec![
                (3, "not UTF-8 text: byte 0xFF at column 5".to_string()),
                (
                    4,
                    "expected 2 columns (time, rate), found 4 (two lines merged?)".to_string()
                ),
                (8, "expected 2 columns (time, rate), found 1".to_string()),
            ]
        );
        assert_eq!(r.data_lines, 6);
        assert_eq!(r.widths, vec![(2, 3), (4, 1)]);
    }
}
