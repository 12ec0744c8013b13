//! Direct integration of the three-axis gyro in quaternions, `q̇ = ½ q ⊗ (0, ω)` (the
//! Poisson equation in quaternion form, cited by paper 3 §2), by RK4 with the rate linear
//! between samples. The reference every other attitude estimator is compared with.

use super::{Estimate, Estimator, IntegrationErrorModel, Measurements};
use crate::math::{RateSegment, step_quaternion_rk4};
use crate::params::ParamValues;
use nalgebra::{UnitQuaternion, Vector3};

/// Gyro-only quaternion integrator.
#[derive(Clone, Debug)]
pub struct QuaternionIntegration {
    q_ref_from_body: UnitQuaternion<f64>,
    last_rate_rad_s: Option<Vector3<f64>>,
    error_model: IntegrationErrorModel,
}

impl QuaternionIntegration {
    /// Starts at `q0_ref_from_body`; `error_model` sets the published variance.
    pub fn new(q0_ref_from_body: UnitQuaternion<f64>, error_model: IntegrationErrorModel) -> Self {
        Self {
            q_ref_from_body: q0_ref_from_body,
            last_rate_rad_s: None,
            error_model,
        }
    }
}

impl Estimator for QuaternionIntegration {
    fn id(&self) -> &'static str {
        "quat-rk4"
    }

    fn label(&self) -> &'static str {
        "Quaternion RK4 integration"
    }

    fn covariance_names(&self) -> &'static [&'static str] {
        &["P_axis_rad2"]
    }

    fn apply_params(&mut self, params: &ParamValues) {
        super::update_error_model(&mut self.error_model, params);
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
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            q_ref_from_body: Some(self.q_ref_from_body),
            rate_body_rad_s: self.last_rate_rad_s,
            covariance: vec![self.error_model.variance_rad2()],
            ..Estimate::default()
        }
    }
}
