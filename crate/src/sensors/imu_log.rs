//! Recorded MPU-6050 logs from an Arduino (paper 4's rig): the usual serial-monitor CSV of
//! `time, ax, ay, az, gx, gy, gz`, in raw 16-bit counts or in scaled units.
//!
//! * The lines are read by the rules of [`super::log_lines`]: the delimiter is the one
//!   under which most lines are samples; a line of words before the first sample is the
//!   header; lines a sketch prints before the data ("Initializing I2C devices…", "MPU6050
//!   connection successful") and every later line that is not a sample are reported with
//!   their numbers and what was wrong.
//! * The clock is repaired by the rules of [`super::timeline`] (reordered, merged,
//!   glitches, gaps, a sketch's reset). Every good sample is kept.
//! * Defaults are the chip's power-on ranges (±2 g, ±250 °/s) in counts and `millis()`
//!   time, so a raw log replays with no flags.
//!
//! The roll axis is x: the rate is gx and the accelerometer angle atan2(ay, az).

use super::log_lines::{Decoded, Sample, read_log};
use super::rate_log::{TIME_UNIT_NAMES, TimeUnit, time_unit};
use crate::model::{LogFormat, LogRefusal, ParamSpec, ParamValues, RateLog};
use nalgebra::Vector3;

/// Unit of the accelerometer columns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AccelUnit {
    /// 16-bit counts of a ±`full_scale_g` range.
    Counts {
        /// Full scale (g): 2, 4, 8 or 16.
        full_scale_g: f64,
    },
    /// g.
    G,
    /// m/s².
    MetresPerS2,
}

/// Unit of the gyro columns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GyroUnit {
    /// 16-bit counts of a ±`full_scale_deg_s` range.
    Counts {
        /// Full scale (°/s): 250, 500, 1000 or 2000.
        full_scale_deg_s: f64,
    },
    /// °/s.
    DegPerS,
    /// rad/s.
    RadPerS,
}

/// How to read a log's columns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImuScales {
    /// Time column.
    pub time: TimeUnit,
    /// Accelerometer columns.
    pub accel: AccelUnit,
    /// Gyro columns.
    pub gyro: GyroUnit,
}

impl Default for ImuScales {
    /// The chip's power-on ranges in counts, Arduino `millis()`.
    fn default() -> Self {
        Self {
            time: TimeUnit::Milliseconds,
            accel: AccelUnit::Counts { full_scale_g: 2.0 },
            gyro: GyroUnit::Counts {
                full_scale_deg_s: 250.0,
            },
        }
    }
}

impl AccelUnit {
    /// Every unit with its name, for menus and the CLI.
    pub const ALL: [(AccelUnit, &'static str); 6] = [
        (Self::Counts { full_scale_g: 2.0 }, "counts2"),
        (Self::Counts { full_scale_g: 4.0 }, "counts4"),
        (Self::Counts { full_scale_g: 8.0 }, "counts8"),
        (Self::Counts { full_scale_g: 16.0 }, "counts16"),
        (Self::G, "g"),
        (Self::MetresPerS2, "mps2"),
    ];

    /// The unit called `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().find(|(_, n)| *n == name).map(|(u, _)| *u)
    }

    /// Factor to g.
    pub fn to_g(self) -> f64 {
        match self {
            Self::Counts { full_scale_g } => full_scale_g / 32768.0,
            Self::G => 1.0,
            Self::MetresPerS2 => 1.0 / 9.80665,
        }
    }
}

impl GyroUnit {
    /// Every unit with its name, for menus and the CLI.
    pub const ALL: [(GyroUnit, &'static str); 6] = [
        (
            Self::Counts {
                full_scale_deg_s: 250.0,
            },
            "counts250",
        ),
        (
            Self::Counts {
                full_scale_deg_s: 500.0,
            },
            "counts500",
        ),
        (
            Self::Counts {
                full_scale_deg_s: 1000.0,
            },
            "counts1000",
        ),
        (
            Self::Counts {
                full_scale_deg_s: 2000.0,
            },
            "counts2000",
        ),
        (Self::DegPerS, "deg_s"),
        (Self::RadPerS, "rad_s"),
    ];

    /// The unit called `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().find(|(_, n)| *n == name).map(|(u, _)| *u)
    }

    /// Factor to rad/s.
    pub fn to_rad_s(self) -> f64 {
        match self {
            Self::Counts { full_scale_deg_s } => (full_scale_deg_s / 32768.0).to_radians(),
            Self::DegPerS => 1f64.to_radians(),
            Self::RadPerS => 1.0,
        }
    }
}

/// Parses an Arduino MPU-6050 log (see the module documentation).
///
/// ```
/// # use attlab::sensors::{parse_imu_log, ImuScales};
/// let text = "MPU6050 connection successful\nms,ax,ay,az,gx,gy,gz\n0,0,0,16384,131,0,0\n10,0,0,16384,bad,0,0\n20,0,16384,0,0,0,0\n";
/// let log = parse_imu_log(text, ImuScales::default());
/// assert_eq!(log.t_s, vec![0.0, 0.02]);
/// assert!((log.rate_rad_s[0] - 1f64.to_radians()).abs() < 1e-3);
/// assert_eq!(log.accel_g[1].y, 1.0);
/// assert_eq!(log.errors.iter().map(|e| e.line).collect::<Vec<_>>(), vec![1, 4]);
/// ```
pub fn parse_imu_log(bytes: impl AsRef<[u8]>, scales: ImuScales) -> RateLog {
    let time_scale = match scales.time {
        TimeUnit::Seconds => 1.0,
        TimeUnit::Milliseconds => 1e-3,
    };
    read_log(
        bytes.as_ref(),
        7,
        "time, ax, ay, az, gx, gy, gz",
        time_scale,
        decoder(scales),
    )
}

/// One row's numbers (time, ax, ay, az, gx, gy, gz in `scales`) as the roll rate gx (rad/s),
/// the acceleration (g) and the three gyro axes (rad/s): what a replay and a live stream
/// both use.
pub(crate) fn decoder(scales: ImuScales) -> impl Fn(&[f64]) -> Decoded {
    let (ka, kg) = (scales.accel.to_g(), scales.gyro.to_rad_s());
    move |v| {
        let gyro = Vector3::new(v[4], v[5], v[6]) * kg;
        Ok(Sample {
            rate_rad_s: gyro.x,
            imu: Some((Vector3::new(v[1], v[2], v[3]) * ka, gyro)),
        })
    }
}

/// Names of the accelerometer units, as [`AccelUnit::ALL`] orders them (`--accel-unit`).
const ACCEL_UNIT_NAMES: &[&str] = &["counts2", "counts4", "counts8", "counts16", "g", "mps2"];

/// Names of the gyro units, as [`GyroUnit::ALL`] orders them (`--gyro-unit`).
const GYRO_UNIT_NAMES: &[&str] = &[
    "counts250",
    "counts500",
    "counts1000",
    "counts2000",
    "deg_s",
    "rad_s",
];

/// An Arduino MPU-6050 log (paper 4's rig): `time, ax, ay, az, gx, gy, gz` lines.
pub const IMU_LOG: LogFormat = LogFormat {
    id: "mpu6050",
    name: "an MPU-6050 IMU log (time, accelerometer, gyro)",
    title: "Real data: an Arduino MPU-6050 log",
    help: "CSV lines `time, ax, ay, az, gx, gy, gz` (comma, semicolon, tab or space separated) \
           as a sketch prints them; banner lines before the header and bad lines are listed \
           with their numbers and skipped. Every good sample is replayed once: times out of \
           order are put in place, equal times merged, a glitched time rejected, and a sketch's \
           reset joined after a short gap. The roll axis is x: rate gx, angle atan2(ay, az). \
           Defaults: the chip's power-on ranges in counts, time in ms.",
    load_label: "Load MPU-6050 log…",
    columns: 7,
    units: &[
        ParamSpec::choice("accel_unit", "accel", ACCEL_UNIT_NAMES, 0).help(
            "Accelerometer columns: raw counts of a ±2/4/8/16 g range (power-on: ±2 g), g or m/s².",
        ),
        ParamSpec::choice("gyro_unit", "gyro", GYRO_UNIT_NAMES, 0).help(
            "Gyro columns: raw counts of a ±250/500/1000/2000 °/s range (power-on: ±250 °/s), °/s or rad/s.",
        ),
        ParamSpec::choice("time_unit", "time", TIME_UNIT_NAMES, 1)
            .help("Time column: seconds, or milliseconds (Arduino millis())."),
    ],
    parse: parse_imu_with,
    check: check_accel_unit,
};

/// The median magnitude of the accelerometer readings (g), if any.
fn median_accel_g(log: &RateLog) -> Option<f64> {
    let mut m: Vec<f64> = log.accel_g.iter().map(|a| a.norm()).collect();
    m.sort_by(f64::total_cmp);
    m.get(m.len() / 2).copied()
}

/// A rig that mostly holds still or swings reads about 1 g; a median outside 0.5–2 g means
/// the accelerometer unit is wrong (counts read as g, or the wrong range). The message
/// names the unit that would give the closest to 1 g.
fn check_accel_unit(log: &RateLog, units: &ParamValues) -> Result<(), LogRefusal> {
    let Some(g) = median_accel_g(log) else {
        return Ok(());
    };
    if (0.5..=2.0).contains(&g) {
        return Ok(());
    }
    let chosen = AccelUnit::ALL
        .get(units.index("accel_unit"))
        .map_or(ImuScales::default().accel, |(u, _)| *u);
    let raw = g / chosen.to_g();
    let (best, name) = AccelUnit::ALL
        .iter()
        .min_by(|a, b| {
            let off = |u: &AccelUnit| (raw * u.to_g()).ln().abs();
            off(&a.0).total_cmp(&off(&b.0))
        })
        .copied()
        .unwrap_or((chosen, "counts2"));
    Err(LogRefusal::AccelUnit {
        median_g: g,
        unit: name,
        gives_g: raw * best.to_g(),
    })
}

/// [`parse_imu_log`] with the unit choices of [`IMU_LOG`].
fn parse_imu_with(text: &[u8], units: &ParamValues) -> RateLog {
    parse_imu_log(text, imu_scales(units))
}

/// The scales the unit choices `units` of [`IMU_LOG`] name.
pub fn imu_scales(units: &ParamValues) -> ImuScales {
    let defaults = ImuScales::default();
    ImuScales {
        time: time_unit(units, "time_unit"),
        accel: AccelUnit::ALL
            .get(units.index("accel_unit"))
            .map_or(defaults.accel, |(u, _)| *u),
        gyro: GyroUnit::ALL
            .get(units.index("gyro_unit"))
            .map_or(defaults.gyro, |(u, _)| *u),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn the_formats_unit_names_follow_the_units_order() {
        for (i, (_, name)) in AccelUnit::ALL.iter().enumerate() {
            assert_eq!(ACCEL_UNIT_NAMES[i], *name);
        }
        for (i, (_, name)) in GyroUnit::ALL.iter().enumerate() {
            assert_eq!(GYRO_UNIT_NAMES[i], *name);
        }
        // The defaults are the chip's power-on ranges in counts and Arduino millis().
        let units = IMU_LOG.default_units();
        let log = (IMU_LOG.parse)(b"1000,0,0,16384,131,0,0\n1010,0,0,16384,131,0,0\n", &units);
        assert_eq!(log.t_s, vec![1.0, 1.01]);
        // ±250 °/s over 16 bits: 131 counts are 131·250/32768 ≈ 0.9995 °/s.
        let expected = (131.0 * 250.0 / 32768.0f64).to_radians();
        assert!(
            (log.rate_rad_s[0] - expected).abs() < 1e-12,
            "{}",
            log.rate_rad_s[0]
        );
        assert!((log.accel_g[0].z - 1.0).abs() < 1e-12, "16384 counts = 1 g");
    }

    #[test]
    fn scaled_units_and_semicolons_read_too() {
        let text = "t;ax;ay;az;gx;gy;gz\n0.00;0;0;9.80665;10;0;0\n0.01;0;4.903325;8.4926;10;0;0\n0.02;0;0\n";
        let scales = ImuScales {
            time: TimeUnit::Seconds,
            accel: AccelUnit::MetresPerS2,
            gyro: GyroUnit::DegPerS,
        };
        let log = parse_imu_log(text, scales);
        assert_eq!(log.t_s, vec![0.0, 0.01]);
        assert!((log.accel_g[0].z - 1.0).abs() < 1e-12);
        assert!((log.rate_rad_s[1] - 10f64.to_radians()).abs() < 1e-12);
        assert_eq!(log.errors.len(), 1);
        assert_eq!(log.errors[0].line, 4);
        assert!(
            log.errors[0]
                .reason
                .to_string()
                .contains("expected 7 columns")
        );
    }
}
