//! Sensor models. All randomness comes in through the caller's seeded RNG.

mod gyro;
mod noise;

pub use gyro::{Gyro3, Gyro3Config};
pub use noise::{Averager, RandomWalk, WhiteNoise, quantize};
