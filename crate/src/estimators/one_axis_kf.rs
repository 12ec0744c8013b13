//! Paper 1's two Kalman filters for the one-axis problem (Ivanov & Ovchinnikov, KIAM
//! preprint): state (φ, φ̇), measurement the averaged rate gyro, H = (0 1), R = σ².
//!
//! * **Permanent rotation** (§4.1): φ̈ = 0, F = [[0, 1], [0, 0]] (eq. 4.1).
//! * **Torsional oscillations** (§4.2): Iφ̈ = −fφ, Ω = 2π/T (eq. 4.6); the model period T
//!   comes from the string and the body, and may be set wrong on purpose.
//!
//! Both predict with the exact transition matrix every simulation step (the models are linear
//! and time invariant, so many small steps equal one long one) and update when an averaged
//! gyro sample arrives. Adaptation is the paper's covariance matching, in [`ScalarKf`].

use super::scalar_kf::{Adaptation, QUse, ScalarKf, rotation_transition, torsion_transition};
use super::{Estimate, Estimator, EstimatorStatus, Measurements};
use crate::params::ParamValues;
use nalgebra::{Matrix2, UnitQuaternion, Vector2, Vector3};

/// Which dynamic model the filter assumes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum OneAxisModel {
    /// φ̈ = 0.
    PermanentRotation,
    /// φ̈ = −Ω²φ with Ω in rad/s.
    Torsion {
        /// Model angular frequency Ω = 2π/T (rad/s).
        omega_rad_s: f64,
    },
}

/// Parameter keys the filters read.
pub mod keys {
    /// Covariance-matching window N (0 = off).
    pub const WINDOW: &str = "kf_window";
    /// Adapt R as well (toggle).
    pub const ADAPT_R: &str = "kf_adapt_r";
    /// How Q_N is used: 0 = process noise, 1 = reset P (choice).
    pub const Q_USE: &str = "kf_q_use";
    /// Gyro noise σ per input sample (°/s).
    pub const NOISE: &str = "gyro_noise_deg_s";
}

/// One of paper 1's Kalman filters.
#[derive(Clone, Debug)]
pub struct OneAxisKf {
    model: OneAxisModel,
    kf: ScalarKf,
    averaging: usize,
    model_from: Option<fn(&ParamValues) -> OneAxisModel>,
    rate_minus_sensor_rad_s: f64,
    status: EstimatorStatus,
}

impl OneAxisKf {
    /// Starts at (φ₀, φ̇₀) with covariance `p0`; `averaging` is the number of gyro samples
    /// per measurement (it sets R = σ²/m).
    pub fn new(model: OneAxisModel, x0: Vector2<f64>, p0: Matrix2<f64>, averaging: usize) -> Self {
        let kf = ScalarKf::new(
            x0,
            p0,
            1e-8,
            Adaptation {
                window: 0,
                adapt_r: false,
                q_use: QUse::ProcessNoise,
            },
        );
        Self {
            model,
            kf,
            averaging: averaging.max(1),
            model_from: None,
            rate_minus_sensor_rad_s: 0.0,
            status: EstimatorStatus::Ok,
        }
    }

    /// Re-derives the model from the parameters whenever they change (e.g. the torsional
    /// period from the string and inertia sliders).
    pub fn with_model_from(mut self, model_from: fn(&ParamValues) -> OneAxisModel) -> Self {
        self.model_from = Some(model_from);
        self
    }

    /// The filter state.
    pub fn filter(&self) -> &ScalarKf {
        &self.kf
    }

    /// Changes the model (e.g. the torsion period slider).
    pub fn set_model(&mut self, model: OneAxisModel) {
        self.model = model;
    }

    fn transition(&self, dt_s: f64) -> Matrix2<f64> {
        match self.model {
            OneAxisModel::PermanentRotation => rotation_transition(dt_s),
            OneAxisModel::Torsion { omega_rad_s } => torsion_transition(omega_rad_s, dt_s),
        }
    }
}

impl Estimator for OneAxisKf {
    fn id(&self) -> &'static str {
        match self.model {
            OneAxisModel::PermanentRotation => "kf-rotation",
            OneAxisModel::Torsion { .. } => "kf-torsion",
        }
    }

    fn label(&self) -> &'static str {
        match self.model {
            OneAxisModel::PermanentRotation => "KF permanent rotation (φ̈ = 0)",
            OneAxisModel::Torsion { .. } => "KF torsional oscillations (Iφ̈ = −fφ)",
        }
    }

    fn covariance_names(&self) -> &'static [&'static str] {
        &["a_rad2", "b_rad2_s", "c_rad2_s2"]
    }

    fn innovation_names(&self) -> &'static [&'static str] {
        &["innov_rad_s"]
    }

    fn extra_names(&self) -> &'static [&'static str] {
        &["rate_minus_sensor_deg_s"]
    }

    fn apply_params(&mut self, p: &ParamValues) {
        if let Some(f) = self.model_from {
            self.model = f(p);
        }
        let window = p.get(keys::WINDOW);
        let q_use = if p.index(keys::Q_USE) == 1 {
            QUse::ResetP
        } else {
            QUse::ProcessNoise
        };
        self.kf.adaptation = Adaptation {
            window: if window.is_finite() {
                window.max(0.0) as usize
            } else {
                0
            },
            adapt_r: p.flag(keys::ADAPT_R),
            q_use,
        };
        let sigma = p.get(keys::NOISE).to_radians();
        if sigma.is_finite() && !(self.kf.adaptation.adapt_r && self.kf.resets > 0) {
            self.kf.r = (sigma * sigma / self.averaging as f64).max(1e-16);
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        if self.status != EstimatorStatus::Ok {
            return;
        }
        let phi = self.transition(dt_s);
        self.kf.predict(&phi);
        if let Some(z) = m.gyro_axis_rad_s {
            self.kf.update(z);
            self.rate_minus_sensor_rad_s = self.kf.x[1] - z;
        }
        if !(self
            .kf
            .x
            .iter()
            .chain(self.kf.p.iter())
            .all(|v| v.is_finite()))
        {
            self.status = EstimatorStatus::Diverged("state or covariance is not finite".into());
        }
    }

    fn estimate(&self) -> Estimate {
        let [a, b, c] = self.kf.abc();
        Estimate {
            q_ref_from_body: Some(UnitQuaternion::from_axis_angle(
                &Vector3::z_axis(),
                self.kf.x[0],
            )),
            angle_rad: Some(self.kf.x[0]),
            rate_body_rad_s: Some(Vector3::new(0.0, 0.0, self.kf.x[1])),
            covariance: vec![a, b, c],
            innovation: vec![self.kf.innovation],
            extras: vec![self.rate_minus_sensor_rad_s.to_degrees()],
            status: self.status.clone(),
            ..Estimate::default()
        }
    }
}

/// Paper 1's third estimator: the angle from direct integration of the averaged gyro rate.
#[derive(Clone, Debug)]
pub struct AngleIntegration {
    angle_rad: f64,
    last_rate_rad_s: Option<f64>,
}

impl AngleIntegration {
    /// Starts at `angle0_rad`.
    pub fn new(angle0_rad: f64) -> Self {
        Self {
            angle_rad: angle0_rad,
            last_rate_rad_s: None,
        }
    }
}

impl Estimator for AngleIntegration {
    fn id(&self) -> &'static str {
        "integration"
    }

    fn label(&self) -> &'static str {
        "Direct integration of the gyro"
    }

    fn apply_params(&mut self, _params: &ParamValues) {}

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        // Zero-order hold of the latest averaged rate between measurements.
        if let Some(z) = m.gyro_axis_rad_s {
            self.last_rate_rad_s = Some(z);
        }
        self.angle_rad += self.last_rate_rad_s.unwrap_or(0.0) * dt_s;
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            q_ref_from_body: Some(UnitQuaternion::from_axis_angle(
                &Vector3::z_axis(),
                self.angle_rad,
            )),
            angle_rad: Some(self.angle_rad),
            rate_body_rad_s: self.last_rate_rad_s.map(|r| Vector3::new(0.0, 0.0, r)),
            ..Estimate::default()
        }
    }
}
