//! Estimators: one file each, each citing its paper and equations.
//!
//! Every estimator publishes the same [`Estimate`] shape, so plots, exports and consistency
//! checks work for all of them without knowing which one they look at.

mod accel_wz;
mod blended_wz;
mod one_axis_kf;
mod quaternion_integration;
pub mod scalar_kf;
mod wz_integration;
mod wz_kalman;

pub use accel_wz::AccelWz;
pub use blended_wz::{BLEND_TIME_CONSTANT_KEY, BlendedWz};
pub use one_axis_kf::{AngleIntegration, OneAxisKf, OneAxisModel, keys as one_axis_keys};
pub use quaternion_integration::QuaternionIntegration;
pub use wz_integration::WzIntegration;
pub use wz_kalman::{ACCEL_NOISE_KEY, KF_Q_SCALE_KEY, WzKalman};

use crate::math::WzAttitude;
use crate::params::ParamValues;
use nalgebra::{UnitQuaternion, Vector3};

/// What the sensors delivered at one step. Fields a lab's sensors don't have stay `None`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Measurements {
    /// Time of the sample (s).
    pub t_s: f64,
    /// Three-axis gyro reading in body axes (rad/s).
    pub gyro_body_rad_s: Option<Vector3<f64>>,
    /// Accelerometer specific force in body axes, in units of g.
    pub accel_body_g: Option<Vector3<f64>>,
    /// Single-axis gyro reading (rad/s).
    pub gyro_axis_rad_s: Option<f64>,
}

/// Health of an estimator, shown in the UI and recorded.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum EstimatorStatus {
    /// Running normally.
    #[default]
    Ok,
    /// The state or covariance became non-finite or lost positive definiteness.
    Diverged(String),
    /// The measurements cannot determine the state right now.
    Unobservable(String),
}

impl EstimatorStatus {
    /// 0 = ok, 1 = diverged, 2 = unobservable (the recorded value).
    pub fn code(&self) -> f64 {
        match self {
            Self::Ok => 0.0,
            Self::Diverged(_) => 1.0,
            Self::Unobservable(_) => 2.0,
        }
    }
}

/// The uniform record every estimator publishes each step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Estimate {
    /// Estimated attitude, if the estimator has a full attitude.
    pub q_ref_from_body: Option<UnitQuaternion<f64>>,
    /// The same attitude as (w, z), for estimators that work in paper 3's parameters.
    pub wz: Option<WzAttitude>,
    /// Estimated angle of a single-axis estimator (rad).
    pub angle_rad: Option<f64>,
    /// Estimated body rate (rad/s).
    pub rate_body_rad_s: Option<Vector3<f64>>,
    /// Named covariance elements, in the order of [`Estimator::covariance_names`].
    pub covariance: Vec<f64>,
    /// Innovation components, in the order of [`Estimator::innovation_names`].
    pub innovation: Vec<f64>,
    /// Estimator-specific internals worth plotting, in the order of
    /// [`Estimator::extra_names`] (e.g. the filter channels of a complementary filter).
    pub extras: Vec<f64>,
    /// Health.
    pub status: EstimatorStatus,
}

/// An attitude estimator in the simulation loop.
pub trait Estimator: Send {
    /// Short stable id used in series names, e.g. `quat-rk4`.
    fn id(&self) -> &'static str;
    /// Human label for legends.
    fn label(&self) -> &'static str;
    /// Names (with units) of the covariance elements it publishes.
    fn covariance_names(&self) -> &'static [&'static str] {
        &[]
    }
    /// Names (with units) of the innovation components it publishes.
    fn innovation_names(&self) -> &'static [&'static str] {
        &[]
    }
    /// Names (with units) of the internals it publishes in [`Estimate::extras`].
    fn extra_names(&self) -> &'static [&'static str] {
        &[]
    }
    /// Takes new parameter values (a slider moved); effective from the next step.
    fn apply_params(&mut self, params: &ParamValues);
    /// Processes the measurements of one step of length `dt_s`.
    fn step(&mut self, measurements: &Measurements, dt_s: f64);
    /// The current estimate.
    fn estimate(&self) -> Estimate;
}

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

/// Parameter keys through which a lab tells its integrators the gyro's error budget.
pub const GYRO_NOISE_KEY: &str = "gyro_noise_deg_s";
/// See [`GYRO_NOISE_KEY`].
pub const GYRO_BIAS_KEY: &str = "gyro_bias_deg_s";

fn update_error_model(model: &mut IntegrationErrorModel, params: &ParamValues) {
    let noise = params.get(GYRO_NOISE_KEY);
    let bias = params.get(GYRO_BIAS_KEY);
    if noise.is_finite() {
        model.noise_sigma_rad_s = noise.to_radians();
    }
    if bias.is_finite() {
        model.bias_sigma_rad_s = bias.to_radians();
    }
}
