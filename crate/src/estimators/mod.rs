//! Estimators: one file each, each citing its paper and equations.
//!
//! Every estimator implements [`crate::model::Estimator`] and publishes the same
//! [`crate::model::Estimate`] shape plus a self-describing covariance, so plots, exports and
//! consistency checks work for all of them without knowing which one they look at. Kalman
//! filters share the vocabulary and update of [`kf`].

mod accel_wz;
pub mod blended_wz;
pub mod covariance_matching;
pub mod kf;
pub mod kf_cycle;
pub mod mekf;
pub mod one_axis_kf;
mod quaternion_integration;
pub mod roll_kf;
pub mod sensitivity;
mod wz_integration;
pub mod wz_kalman;

pub use accel_wz::AccelWz;
pub use blended_wz::BlendedWz;
pub use mekf::{
    FULL_F, FULL_F_NONZEROS, FULL_H_NONZEROS, Mekf, MekfConfig, MekfTuning, Onboard, Retune,
    SensorSet, StateSet, full_step_flops,
};
pub use one_axis_kf::{AngleIntegration, OneAxisKf, OneAxisModel, OneAxisTuning};
pub use quaternion_integration::QuaternionIntegration;
pub use roll_kf::{
    ComplementaryRoll, ControlInput, RollInput, RollKf, RollTuning, accel_angle_rad,
};
pub use sensitivity::{
    Method, SensitivityCorrection, SensitivitySettings, UpdateInfo, linearised_eigenvalues,
    sensitivity_finite_difference_check,
};
pub use wz_integration::WzIntegration;
pub use wz_kalman::{WzKalman, WzKalmanTuning};

use crate::model::{StateInfo, StateKind};

/// The states of an attitude error about the three body axes (rad): the covariance the
/// integrators publish.
pub const ATTITUDE_AXES: &[StateInfo] = &[
    StateInfo::new("att_x", "rad", StateKind::AttitudeAxis(0)),
    StateInfo::new("att_y", "rad", StateKind::AttitudeAxis(1)),
    StateInfo::new("att_z", "rad", StateKind::AttitudeAxis(2)),
];

/// The error model of pure gyro integration, shared by the integrators: white gyro noise
/// (σ per sample) accumulates as an angle random walk, an unknown constant bias of 1σ
/// `bias_sigma_rad_s` as a ramp. Gives the per-axis attitude-error variance (rad²) the
/// integrators publish, so their 3σ envelope can be plotted against the actual error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IntegrationErrorModel {
    /// Gyro white-noise σ per sample (rad/s).
    pub noise_sigma_rad_s: f64,
    /// 1σ of the unknown bias (rad/s).
    pub bias_sigma_rad_s: f64,
    /// Accumulated angle-random-walk variance (rad²).
    pub arw_variance_rad2: f64,
    /// Time integrated so far (s).
    pub elapsed_s: f64,
}

impl IntegrationErrorModel {
    /// Starts with zero uncertainty (the initial attitude is known).
    pub fn new(noise_sigma_rad_s: f64, bias_sigma_rad_s: f64) -> Self {
        Self {
            noise_sigma_rad_s,
            bias_sigma_rad_s,
            arw_variance_rad2: 0.0,
            elapsed_s: 0.0,
        }
    }

    /// Adds one step: each sample's noise enters the angle as σ·dt.
    pub fn step(&mut self, dt_s: f64) {
        self.arw_variance_rad2 += (self.noise_sigma_rad_s * dt_s).powi(2);
        self.elapsed_s += dt_s;
    }

    /// Per-axis attitude-error variance (rad²).
    pub fn variance_rad2(&self) -> f64 {
        self.arw_variance_rad2 + (self.bias_sigma_rad_s * self.elapsed_s).powi(2)
    }
}

/// The gyro's error budget an integrator publishes its covariance from (a lab's
/// [`Tuner`](crate::model::Tuner) gives it from the lab's parameters).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GyroErrors {
    /// White-noise σ per sample (rad/s).
    pub noise_sigma_rad_s: f64,
    /// 1σ of the unknown bias (rad/s).
    pub bias_sigma_rad_s: f64,
}

impl GyroErrors {
    /// From a white-noise σ and a bias 1σ in °/s, as the labs' sliders give them.
    pub fn from_deg_s(noise_sigma_deg_s: f64, bias_sigma_deg_s: f64) -> Self {
        Self {
            noise_sigma_rad_s: noise_sigma_deg_s.to_radians(),
            bias_sigma_rad_s: bias_sigma_deg_s.to_radians(),
        }
    }
}

impl IntegrationErrorModel {
    /// The same model with the gyro's new error budget (what has accumulated stays).
    fn retune(&mut self, g: GyroErrors) {
        self.noise_sigma_rad_s = g.noise_sigma_rad_s;
        self.bias_sigma_rad_s = g.bias_sigma_rad_s;
    }
}
