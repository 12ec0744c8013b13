//! Direct integration of the three-axis gyro in quaternions, `q̇ = ½ q ⊗ (0, ω)` (the
//! Poisson equation in quaternion form, cited by paper 3 §2), by RK4 with the rate linear
//! between samples. The reference every other attitude estimator is compared with.

use super::{ATTITUDE_AXES, GyroErrors, IntegrationErrorModel};
use crate::math::{RateSegment, step_quaternion_rk4};
use crate::model::{
    Attitude, Covariance, Estimate, Estimator, Measurements, ParamValues, StateInfo, Tuner,
};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};

/// Gyro-only quaternion integrator.
#[derive(Clone, Debug)]
pub struct QuaternionIntegration {
    q_ref_from_body: UnitQuaternion<f64>,
    last_rate_rad_s: Option<Vector3<f64>>,
    error_model: IntegrationErrorModel,
    cov: Matrix3<f64>,
    tuner: Option<Tuner<GyroErrors>>,
}

impl QuaternionIntegration {
    /// Starts at `q0_ref_from_body`; `error_model` sets the published variance.
    pub fn new(q0_ref_from_body: UnitQuaternion<f64>, error_model: IntegrationErrorModel) -> Self {
        Self {
            q_ref_from_body: q0_ref_from_body,
            last_rate_rad_s: None,
            error_model,
            cov: Matrix3::zeros(),
            tuner: None,
        }
    }

    /// Re-tunes the published variance from the lab's parameters on every change.
    #[must_use]
    pub fn tuned_by(mut self, tuner: Tuner<GyroErrors>) -> Self {
        self.tuner = Some(tuner);
        self
    }
}

impl Estimator for QuaternionIntegration {
    fn id(&self) -> &'static str {
        "quat-rk4"
    }

    fn label(&self) -> &'static str {
        "Quaternion RK4 integration"
    }

    fn covariance_states(&self) -> &'static [StateInfo] {
        ATTITUDE_AXES
    }

    fn covariance(&self) -> Option<Covariance<'_>> {
        Some(Covariance {
            states: ATTITUDE_AXES,
            matrix: self.cov.as_slice(),
        })
    }

    fn apply_params(&mut self, params: &ParamValues) {
        if let Some(f) = self.tuner {
            self.error_model.retune(f(params));
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        let Some(rate) = m.gyro_body_rad_s else {
            return;
        };
        let start = self.last_rate_rad_s.unwrap_or(rate);
        let seg = RateSegment {
            start_rad_s: start,
            end_rad_s: rate,
        };
        self.q_ref_from_body = step_quaternion_rk4(&self.q_ref_from_body, |f| seg.at(f), dt_s);
        self.last_rate_rad_s = Some(rate);
        self.error_model.step(dt_s);
        self.cov = Matrix3::identity() * self.error_model.variance_rad2();
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            attitude: Attitude::Quaternion(self.q_ref_from_body),
            rate_body_rad_s: self.last_rate_rad_s,
            ..Estimate::default()
        }
    }
}
