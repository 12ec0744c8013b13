//! A three-axis rate gyro: constant bias + random-walk bias + white noise + quantisation.

use super::noise::{RandomWalk, WhiteNoise, quantize};
use nalgebra::Vector3;
use rand::Rng;

/// Error budget of a three-axis gyro (all rad, rad/s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gyro3Config {
    /// Constant bias per axis (rad/s).
    pub bias_rad_s: Vector3<f64>,
    /// White noise σ of one sample (rad/s).
    pub noise_sigma_rad_s: f64,
    /// Bias random-walk intensity (rad/s per √s).
    pub bias_walk_rad_s_per_sqrt_s: f64,
    /// Quantisation step (rad/s); 0 = none.
    pub lsb_rad_s: f64,
    /// Measurement range ± (rad/s); 0 = unlimited.
    pub range_rad_s: f64,
}

impl Default for Gyro3Config {
    fn default() -> Self {
        Self {
            bias_rad_s: Vector3::zeros(),
            noise_sigma_rad_s: 0.0,
            bias_walk_rad_s_per_sqrt_s: 0.0,
            lsb_rad_s: 0.0,
            range_rad_s: 0.0,
        }
    }
}

/// The gyro's state (its drifting bias) and configuration.
#[derive(Clone, Debug, PartialEq)]
pub struct Gyro3 {
    /// Error budget; may change between samples (a slider moved).
    pub config: Gyro3Config,
    walk: [RandomWalk; 3],
}

impl Gyro3 {
    /// A gyro whose random-walk bias starts at zero.
    pub fn new(config: Gyro3Config) -> Self {
        let walk = [RandomWalk {
            value: 0.0,
            sigma_per_sqrt_s: 0.0,
        }; 3];
        Self { config, walk }
    }

    /// The current total bias (constant + walk), rad/s.
    pub fn bias_rad_s(&self) -> Vector3<f64> {
        self.config.bias_rad_s
            + Vector3::new(self.walk[0].value, self.walk[1].value, self.walk[2].value)
    }

    /// One reading of the true body rate `rate_body_rad_s`, after `dt_s` since the last one.
    pub fn sample(
        &mut self,
        rate_body_rad_s: &Vector3<f64>,
        dt_s: f64,
        rng: &mut impl Rng,
    ) -> Vector3<f64> {
        let c = self.config;
        let white = WhiteNoise {
            sigma: c.noise_sigma_rad_s,
        };
        Vector3::from_fn(|i, _| {
            self.walk[i].sigma_per_sqrt_s = c.bias_walk_rad_s_per_sqrt_s;
            let walk = self.walk[i].step(dt_s, rng);
            let raw = rate_body_rad_s[i] + c.bias_rad_s[i] + walk + white.sample(rng);
            quantize(raw, c.lsb_rad_s, c.range_rad_s)
        })
    }
}
