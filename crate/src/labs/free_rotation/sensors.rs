//! The sensors: a three-axis gyro with noise, a constant bias and a bias random walk.

use crate::model::{Measurements, ParamValues, SensorModel, TruthState};
use crate::sensors::{Gyro3, Gyro3Config};
use nalgebra::Vector3;
use rand_chacha::ChaCha8Rng;

/// Which sign the gyro bias has on each body axis (the bias slider sets its size).
pub(super) const BIAS_PATTERN: Vector3<f64> = Vector3::new(1.0, -1.0, 1.0);

#[derive(Clone)]
pub(super) struct GyroSensors {
    pub(super) gyro: Gyro3,
}

impl SensorModel for GyroSensors {
    fn apply_params(&mut self, params: &ParamValues) {
        let b = params.get("gyro_bias_deg_s").to_radians();
        self.gyro.config = Gyro3Config {
            bias_rad_s: BIAS_PATTERN * b,
            noise_sigma_rad_s: params.get("gyro_noise_deg_s").to_radians(),
            bias_walk_rad_s_per_sqrt_s: params.get("gyro_walk_deg_s_sqrt_s").to_radians(),
            ..Gyro3Config::default()
        };
    }

    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements {
        let rate = self.gyro.sample(&truth.rate_body_rad_s, dt_s, rng);
        Measurements {
            t_s: truth.t_s,
            gyro_body_rad_s: Some(rate),
            ..Measurements::default()
        }
    }
}
