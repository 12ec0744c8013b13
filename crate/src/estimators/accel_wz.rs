//! Accelerometer-only (uᵃ, vᵃ), paper 3 eq. (28): `uᵃ = n_ξ/(1 + n_ζ)`, `vᵃ = n_η/(1 + n_ζ)`
//! with n = f/g. No integration, so no drift — but every bit of accelerometer noise and any
//! linear acceleration goes straight into the estimate. Gives the vertical only (pitch and
//! roll), not z. Uses the flipped chart when the body is upside down.

use crate::math::{WzAttitude, better_chart, chart_coords_of_vertical};
use crate::model::{Attitude, Estimate, Estimator, Measurements, Outputs, ParamValues};

/// Tilt from the accelerometer alone.
#[derive(Clone, Debug, Default)]
pub struct AccelWz {
    wz: Option<WzAttitude>,
}

impl AccelWz {
    /// No estimate until the first accelerometer sample.
    pub fn new() -> Self {
        Self::default()
    }
}

impl Estimator for AccelWz {
    fn id(&self) -> &'static str {
        "accel"
    }

    fn label(&self) -> &'static str {
        "Accelerometer only (uᵃ, vᵃ), eq. 28"
    }

    fn apply_params(&mut self, _params: &ParamValues) {}

    fn step(&mut self, m: &Measurements, _dt_s: f64) {
        let Some(n) = m.accel_body_g else { return };
        let chart = better_chart(&n);
        self.wz = chart_coords_of_vertical(&n, chart).map(|(u, v)| WzAttitude {
            u,
            v,
            z_rad: 0.0,
            chart,
        });
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            attitude: self.wz.map_or(Attitude::None, Attitude::Tilt),
            ..Estimate::default()
        }
    }

    fn outputs(&self) -> Outputs {
        Outputs {
            tilt: true,
            ..Outputs::default()
        }
    }
}
