//! Direct integration of the three-axis gyro in paper 3's (u, v, z) parameters, eq. (21)
//! (= eqs. 18–20), by RK4 with the rate linear between samples. Near w → ∞ (body upside
//! down) it switches to the flipped chart s = 1/w (digest §3) with hysteresis, so it runs
//! through any attitude.

use super::{ATTITUDE_AXES, GyroErrors, IntegrationErrorModel};
use crate::math::{RateSegment, WzAttitude, step_uvz_rk4};
use crate::model::{
    Attitude, Covariance, Estimate, Estimator, Measurements, ParamValues, StateInfo, Tuner,
};
use nalgebra::{Matrix3, Vector3};

/// Gyro-only (u, v, z) integrator with chart switching.
#[derive(Clone, Debug)]
pub struct WzIntegration {
    wz: WzAttitude,
    last_rate_rad_s: Option<Vector3<f64>>,
    error_model: IntegrationErrorModel,
    cov: Matrix3<f64>,
    chart_switches: u32,
    tuner: Option<Tuner<GyroErrors>>,
}

impl WzIntegration {
    /// Starts at `wz0`; `error_model` sets the published variance.
    pub fn new(wz0: WzAttitude, error_model: IntegrationErrorModel) -> Self {
        Self {
            wz: wz0,
            last_rate_rad_s: None,
            error_model,
            cov: Matrix3::zeros(),
            tuner: None,
            chart_switches: 0,
        }
    }

    /// Re-tunes the published variance from the lab's parameters on every change.
    #[must_use]
    pub fn tuned_by(mut self, tuner: Tuner<GyroErrors>) -> Self {
        self.tuner = Some(tuner);
        self
    }

    /// How many times the chart has switched so far.
    pub fn chart_switches(&self) -> u32 {
        self.chart_switches
    }
}

impl Estimator for WzIntegration {
    fn id(&self) -> &'static str {
        "uvz-rk4"
    }

    fn label(&self) -> &'static str {
        "(u, v, z) RK4 integration"
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
        let next = step_uvz_rk4(&self.wz, |f| seg.at(f), dt_s);
        if next.chart != self.wz.chart {
            self.chart_switches += 1;
        }
        self.wz = next;
        self.last_rate_rad_s = Some(rate);
        self.error_model.step(dt_s);
        self.cov = Matrix3::identity() * self.error_model.variance_rad2();
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            attitude: Attitude::Wz(self.wz),
            rate_body_rad_s: self.last_rate_rad_s,
            ..Estimate::default()
        }
    }
}
