//! Sensor models. All randomness comes in through the caller's seeded RNG.

mod gyro;
mod imu_log;
pub mod live;
pub mod log_lines;
mod noise;
mod rate_log;
mod row;
pub mod timeline;

pub use crate::model::{LogCounts, LogFormat, LogGap, LogLineError, RateLog};
pub use gyro::{Gyro3, Gyro3Config};
pub use imu_log::{AccelUnit, GyroUnit, IMU_LOG, ImuScales, imu_scales, parse_imu_log};
pub use noise::{Averager, RandomWalk, WhiteNoise, quantize};
pub use rate_log::{RATE_LOG, RateUnit, RawCounts, TimeUnit, parse_rate_counts, parse_rate_log};
