//! A live IMU stream — a phone's gyro and accelerometer, or an Arduino's MPU-6050 over a
//! serial port — read as it arrives, by the same rules as a recorded log.
//!
//! * Bytes arrive in chunks ([`LiveStream::push_bytes`]: a serial port) or as whole lines
//!   ([`LiveStream::push_line`]: a phone's samples, written by [`phone_line`]). Every line
//!   goes through the importer's line reader ([`super::log_lines`]): a banner or a bad line
//!   is reported by its number and skipped, every good line is kept and **recorded** as it
//!   came.
//! * The clock is repaired by the rules of [`super::timeline`], fed a row at a time: a
//!   sample is handed on once nothing that arrives later can move it (it is more than 3
//!   periods before the latest, or its segment ended); a jumped time waits for the next
//!   three lines to tell a glitch from a gap. The nominal period P is the median step of
//!   the first [`PERIOD_ROWS`] lines (a replayed file takes the median of all its lines).
//! * [`LiveStream::record`] is a log `attlab replay` reads: the good lines as they came,
//!   after a comment that states P (`# period_s=`), so the replay applies the same rules
//!   with the same period and delivers the same samples: the same estimates.

use super::imu_log::{ImuScales, decoder};
use super::log_lines::{LineReader, PERIOD_DIRECTIVE, merge_by_line, push_sample};
use super::rate_log::TimeUnit;
use super::row::Row;
use super::timeline::{Orderer, Timeline, period_of};
use crate::model::{LogCounts, LogLineError, RateLog};
use nalgebra::{UnitQuaternion, Vector3};

/// How many lines set a live stream's nominal period (their median step).
pub const PERIOD_ROWS: usize = 16;
/// The longest line a stream takes (bytes): a device that sends no line break is a bad line
/// every this many bytes, not a growing buffer.
pub const MAX_LINE_BYTES: usize = 4096;
/// How many bad lines are kept with their text (all are counted).
const MAX_ERRORS: usize = 1000;
/// The columns of a live IMU stream, as the importer names them.
const NAMES: &str = "time, ax, ay, az, gx, gy, gz";

/// Standard gravity (m/s²): a phone reports m/s², the record is in g.
const G_MPS2: f64 = 9.80665;

/// A live IMU stream: its lines, its repaired clock and its record.
#[derive(Clone, Debug)]
pub struct LiveStream {
    scales: ImuScales,
    reader: LineReader,
    next_line: usize,
    partial: Vec<u8>,
    recorded: usize,
    /// Decoded rows before the period is known.
    startup: Vec<Row>,
    orderer: Option<Orderer>,
    timeline: Timeline,
    clock_errors: Vec<LogLineError>,
    record: String,
    /// Samples final but not yet taken.
    fresh: RateLog,
    kept: usize,
    ended: bool,
}

impl LiveStream {
    /// A stream whose columns are in `scales` (a phone's: ms, g, °/s; a sketch's: as chosen).
    pub fn new(scales: ImuScales) -> Self {
        Self {
            scales,
            reader: LineReader::new(7, NAMES, None),
            next_line: 1,
            partial: Vec::new(),
            recorded: 0,
            startup: Vec::new(),
            orderer: None,
            timeline: Timeline::default(),
            clock_errors: Vec::new(),
            record: String::new(),
            fresh: RateLog::default(),
            kept: 0,
            ended: false,
        }
    }

    /// The columns' units.
    pub fn scales(&self) -> ImuScales {
        self.scales
    }

    /// Takes a chunk of a byte stream: complete lines are read, the rest waits for its line
    /// break (a line longer than [`MAX_LINE_BYTES`] is read as it is, and reported).
    pub fn push_bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            if b == b'\n' {
                let line = std::mem::take(&mut self.partial);
                self.read_line(&line);
            } else {
                self.partial.push(b);
                if self.partial.len() >= MAX_LINE_BYTES {
                    let line = std::mem::take(&mut self.partial);
                    self.read_line(&line);
                }
            }
        }
    }

    /// Takes one whole line (without its line break).
    pub fn push_line(&mut self, line: &str) {
        self.read_line(line.as_bytes());
    }

    fn read_line(&mut self, raw: &[u8]) {
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        let raw = if self.next_line == 1 {
            raw.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(raw)
        } else {
            raw
        };
        let errors = self.reader.out.errors.len();
        self.reader.line(self.next_line, raw);
        self.next_line += 1;
        if self.reader.out.errors.len() > MAX_ERRORS {
            self.reader.out.errors.truncate(errors);
        }
        self.process();
    }

    /// The stream ended (stopped, unplugged, the permission revoked): a last line without
    /// its break is read, and every sample becomes final.
    pub fn finish(&mut self) {
        if !self.partial.is_empty() {
            let line = std::mem::take(&mut self.partial);
            self.read_line(&line);
        }
        self.ended = true;
        self.process();
    }

    /// Whether [`LiveStream::finish`] was called.
    pub fn ended(&self) -> bool {
        self.ended
    }

    /// Moves new rows through the clock's rules; final samples go to `fresh`.
    fn process(&mut self) {
        // A row is recorded as it came, then decoded (an IMU row always decodes).
        for row in std::mem::take(&mut self.reader.out.rows) {
            let Ok(decoded) = decoder(self.scales)(&row.values) else {
                continue;
            };
            self.record.push_str(&row.text);
            self.record.push('\n');
            self.recorded += 1;
            let values = decoded.values(row.values[0]);
            self.startup.push(Row { values, ..row });
        }
        let time_scale = self.time_scale();
        if self.orderer.is_none() {
            let period = period_of(&self.startup, time_scale);
            if !self.ended && (self.startup.len() < PERIOD_ROWS || period.is_none()) {
                return;
            }
            self.timeline.period_s = period;
            self.orderer = Some(Orderer::new(time_scale, period));
        }
        let Some(orderer) = self.orderer.as_mut() else {
            return;
        };
        for row in self.startup.drain(..) {
            orderer.push(row);
            orderer.drain(&mut self.timeline, &mut self.clock_errors, false);
        }
        orderer.drain(&mut self.timeline, &mut self.clock_errors, self.ended);
        for s in self.timeline.samples.drain(..) {
            push_sample(&mut self.fresh, &s);
            self.kept += 1;
        }
    }

    fn time_scale(&self) -> f64 {
        match self.scales.time {
            TimeUnit::Seconds => 1.0,
            TimeUnit::Milliseconds => 1e-3,
        }
    }

    /// The nominal period (s), once known.
    pub fn period_s(&self) -> Option<f64> {
        self.timeline.period_s
    }

    /// Every line rejected so far (format and clock), in line order (at most the first
    /// thousand bad lines with their text; [`LiveStream::counts`] counts all).
    pub fn errors(&self) -> Vec<LogLineError> {
        merge_by_line(self.reader.out.errors.clone(), self.clock_errors.clone())
    }

    /// What became of the lines so far.
    pub fn counts(&self) -> LogCounts {
        let rejected_format = self.reader.out.data_lines - self.recorded_lines();
        LogCounts {
            data_lines: self.reader.out.data_lines,
            kept: self.kept,
            reordered: self.timeline.reordered,
            merged: self.timeline.merged,
            rejected: rejected_format + self.clock_errors.len(),
        }
    }

    /// How many good lines were recorded.
    pub fn recorded_lines(&self) -> usize {
        self.recorded
    }

    /// The samples that became final since the last call (with the stream's lines, gaps
    /// and counts as they are now), for the replay's shared log to append.
    pub fn take_new(&mut self) -> RateLog {
        let mut new = std::mem::take(&mut self.fresh);
        new.period_s = self.timeline.period_s.unwrap_or(0.0);
        new.errors = self.errors();
        new.notes.clone_from(&self.timeline.notes);
        new.gaps.clone_from(&self.timeline.gaps);
        new.counts = self.counts();
        new.widths.clone_from(&self.reader.out.widths);
        new
    }

    /// The record: a log `attlab replay --lab p4` reads to the same samples. `about` is a
    /// comment line or several (the source, the units, the command that replays it).
    pub fn record(&self, about: &str) -> String {
        let delimiter = char::from(self.reader.delimiter.unwrap_or(b','));
        let mut out = String::new();
        for line in about.lines() {
            out.push_str("# ");
            out.push_str(line);
            out.push('\n');
        }
        if let Some(p) = self.timeline.period_s {
            out.push_str(&format!("{PERIOD_DIRECTIVE}{p}\n"));
        }
        let header: Vec<&str> = NAMES.split(", ").collect();
        out.push_str(&header.join(&delimiter.to_string()));
        out.push('\n');
        out.push_str(&self.record);
        out
    }
}

/// How a phone's axes become the lab's body axes: body x is the phone's y (the top edge,
/// the "nose"), body y is minus the phone's x (its left edge), body z the phone's z (out of
/// the screen). A phone lying flat, screen up, reads +1 g on body z, as the MPU-6050 on
/// paper 4's rig does; rolling it about its long axis is the lab's roll φ about body x.
pub fn phone_to_body(v: Vector3<f64>) -> Vector3<f64> {
    Vector3::new(v.y, -v.x, v.z)
}

/// The turn that makes the body level where the accelerometer now reads `accel_body_g`:
/// applied to every later sample ("zero"), it takes that reading to +z.
pub fn zero_mount(accel_body_g: Vector3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::rotation_between(&accel_body_g, &Vector3::z()).unwrap_or_else(|| {
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
    })
}

/// One phone sample as a line of the live stream (time in ms, accelerometer in g, gyro in
/// °/s, in body axes turned by `mount`): the phone reports the accelerometer in m/s² with
/// gravity and the gyro in `gyro_deg_per_unit` °/s per unit of `gyro` (1 for the
/// `devicemotion` event's °/s, 180/π for the Gyroscope sensor's rad/s).
pub fn phone_line(
    t_ms: f64,
    accel_phone_mps2: Vector3<f64>,
    gyro_phone: Vector3<f64>,
    gyro_deg_per_unit: f64,
    mount: &UnitQuaternion<f64>,
) -> String {
    let a = mount * phone_to_body(accel_phone_mps2 / G_MPS2);
    let w = mount * phone_to_body(gyro_phone * gyro_deg_per_unit);
    format!("{t_ms},{},{},{},{},{},{}", a.x, a.y, a.z, w.x, w.y, w.z)
}

/// The units a phone's lines are in.
pub const PHONE_SCALES: ImuScales = ImuScales {
    time: TimeUnit::Milliseconds,
    accel: super::AccelUnit::G,
    gyro: super::GyroUnit::DegPerS,
};

#[cfg(test)]
#[path = "live_tests.rs"]
mod tests;
