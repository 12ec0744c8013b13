//! Paper 1's two Kalman filters for the one-axis problem (Ivanov & Ovchinnikov, KIAM
//! preprint): state (φ, φ̇), measurement the averaged rate gyro, H = (0 1), R = σ².
//!
//! * **Permanent rotation** (§4.1): φ̈ = 0, F = [[0, 1], [0, 0]] (eq. 4.1).
//! * **Torsional oscillations** (§4.2): Iφ̈ = −fφ, Ω = 2π/T (eq. 4.6); the model period T
//!   comes from the string and the body, and may be set wrong on purpose.
//!
//! Both predict with the exact transition matrix every simulation step (the models are linear
//! and time invariant, so many small steps equal one long one) and update when an averaged
//! gyro sample arrives. Adaptation is the paper's covariance matching, in
//! [`super::covariance_matching::AdaptiveKf`].

use super::covariance_matching::{
    AdaptMode, Adaptation, AdaptiveKf, rotation_transition, torsion_transition,
};
use super::kf::Innovation;
use super::kf_cycle::CycleRecorder;
use crate::model::{
    Covariance, Estimate, Estimator, EstimatorStatus, Extras, KalmanCycle, Measurements,
    ParamValues, Quantity, StateInfo, StateKind, Teaching, Trouble, Tuner,
};
use nalgebra::{Matrix1, Matrix1x2, Matrix2, Vector1, Vector2, Vector3};

// The series this estimator records besides the catalogue's (figures name them).
/// innovation z − Hx̂ (gyro rate less predicted φ̇) (rad/s).
pub const INNOV_RAD_S: Quantity = Quantity::new(
    "innov_rad_s",
    "innovation z − Hx̂ (gyro rate less predicted φ̇)",
    "rad/s",
);
/// estimated φ̇ less the gyro reading (deg/s).
pub const RATE_MINUS_SENSOR_DEG_S: Quantity = Quantity::new(
    "rate_minus_sensor_deg_s",
    "estimated φ̇ less the gyro reading",
    "deg/s",
);
/// estimated φ less the integrated φ_int (deg).
pub const ANGLE_MINUS_INT_DEG: Quantity = Quantity::new(
    "angle_minus_int_deg",
    "estimated φ less the integrated φ_int",
    "deg",
);

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

/// What a lab tunes in the one-axis filters: the adaptation, and the gyro's noise σ per
/// input sample (R = σ²/m for m averaged samples).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OneAxisTuning {
    /// How the filter adapts.
    pub adaptation: Adaptation,
    /// Gyro noise σ per input sample (rad/s).
    pub gyro_sigma_rad_s: f64,
}

/// How far (rad) the estimate may leave the integrated angle φ_int before the filter is
/// declared diverged: ten turns. No working filter on this pendulum gets near it (without
/// adaptation the torsional filter's model error reaches ~100°); an unstable adaptation runs
/// past it within seconds.
pub const RUNAWAY_RAD: f64 = 10.0 * std::f64::consts::TAU;

/// The states of both filters.
/// The covariance state phi (rad).
pub const STATE_PHI: StateInfo = StateInfo::new("phi", "rad", StateKind::Angle);
/// The covariance state phidot (rad/s).
pub const STATE_PHIDOT: StateInfo = StateInfo::new("phidot", "rad/s", StateKind::Rate);
const STATES: &[StateInfo] = &[STATE_PHI, STATE_PHIDOT];

/// One of paper 1's Kalman filters.
#[derive(Clone, Debug)]
pub struct OneAxisKf {
    model: OneAxisModel,
    kf: AdaptiveKf,
    averaging: usize,
    model_from: Option<fn(&ParamValues) -> OneAxisModel>,
    tuner: Option<Tuner<OneAxisTuning>>,
    last_z: Option<f64>,
    phi_int_rad: f64,
    rate_minus_sensor_rad_s: f64,
    innovation: [f64; 1],
    status: EstimatorStatus,
    cycle: CycleRecorder,
}

impl OneAxisKf {
    /// Starts at (φ₀, φ̇₀) with covariance `p0`; `averaging` is the number of gyro samples
    /// per measurement (it sets R = σ²/m).
    pub fn new(model: OneAxisModel, x0: Vector2<f64>, p0: Matrix2<f64>, averaging: usize) -> Self {
        let kf = AdaptiveKf::new(
            x0,
            p0,
            1e-8,
            Adaptation {
                window: 0,
                adapt_r: false,
                mode: AdaptMode::SawTooth,
            },
        );
        Self {
            model,
            kf,
            averaging: averaging.max(1),
            model_from: None,
            tuner: None,
            last_z: None,
            phi_int_rad: x0[0],
            rate_minus_sensor_rad_s: 0.0,
            innovation: [0.0],
            status: EstimatorStatus::Ok,
            cycle: CycleRecorder::new(STATES),
        }
    }

    /// Re-derives the model from the parameters whenever they change (e.g. the torsional
    /// period from the string and inertia sliders).
    pub fn with_model_from(mut self, model_from: fn(&ParamValues) -> OneAxisModel) -> Self {
        self.model_from = Some(model_from);
        self
    }

    /// Takes the adaptation and the gyro noise from the lab's parameters on every change.
    #[must_use]
    pub fn tuned_by(mut self, tuner: Tuner<OneAxisTuning>) -> Self {
        self.tuner = Some(tuner);
        self
    }

    /// The filter state.
    pub fn filter(&self) -> &AdaptiveKf {
        &self.kf
    }

    fn transition(&self, dt_s: f64) -> Matrix2<f64> {
        match self.model {
            OneAxisModel::PermanentRotation => rotation_transition(dt_s),
            OneAxisModel::Torsion { omega_rad_s } => torsion_transition(omega_rad_s, dt_s),
        }
    }
}

/// What the step-through panel says when an adaptation window ends at this update.
const WINDOW_ENDED: &str =
    "the adaptation window ended: P was replaced by the window's estimate (§2.6, Table 2.3)";

impl OneAxisKf {
    /// Records the update just made (z − Hx̂⁻ with H = [0 1], R = σ²/m) in the cycle.
    fn record_update(&mut self) {
        let Some((prior, post)) = self.kf.last_update else {
            return;
        };
        let h = Matrix1x2::new(0.0, 1.0);
        let r = Matrix1::new(self.kf.r.max(1e-16));
        let innovation = Innovation {
            residual: Vector1::new(self.kf.innovation),
            s: h * prior.p * h.transpose() + r,
            nis: 0.0,
        };
        let rows = ["averaged gyro rate ω̄ (rad/s)", ""];
        self.cycle.updated(&prior, &h, &r, rows, &innovation, &post);
    }
}

impl Teaching for OneAxisKf {
    fn cycle(&self) -> &KalmanCycle {
        self.cycle.cycle()
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

    fn covariance_states(&self) -> &'static [StateInfo] {
        STATES
    }

    fn covariance(&self) -> Option<Covariance<'_>> {
        Some(Covariance {
            states: STATES,
            matrix: self.kf.p().as_slice(),
        })
    }

    fn innovation_quantities(&self) -> &'static [Quantity] {
        const QUANTITIES: &[Quantity] = &[INNOV_RAD_S];
        QUANTITIES
    }

    fn innovation(&self) -> &[f64] {
        &self.innovation
    }

    fn extra_quantities(&self) -> &'static [Quantity] {
        const QUANTITIES: &[Quantity] = &[RATE_MINUS_SENSOR_DEG_S, ANGLE_MINUS_INT_DEG];
        QUANTITIES
    }

    fn extras(&self, out: &mut Extras<'_>) {
        out.put(
            &RATE_MINUS_SENSOR_DEG_S,
            self.rate_minus_sensor_rad_s.to_degrees(),
        );
        out.put(
            &ANGLE_MINUS_INT_DEG,
            (self.kf.x()[0] - self.phi_int_rad).to_degrees(),
        );
    }

    fn status(&self) -> &EstimatorStatus {
        &self.status
    }

    fn teaching(&self) -> Option<&dyn Teaching> {
        Some(self)
    }

    fn apply_params(&mut self, p: &ParamValues) {
        if let Some(f) = self.model_from {
            self.model = f(p);
        }
        let Some(tuner) = self.tuner else {
            return;
        };
        let t = tuner(p);
        self.kf.adaptation = t.adaptation;
        let sigma = t.gyro_sigma_rad_s;
        if sigma.is_finite() && !(self.kf.adaptation.adapt_r && self.kf.resets > 0) {
            self.kf.r = (sigma * sigma / self.averaging as f64).max(1e-16);
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        if self.status != EstimatorStatus::Ok {
            return;
        }
        // The kinematically integrated angle, exactly as the direct integration computes it
        // (zero-order hold of the latest averaged rate): the saw-tooth's reference.
        if let Some(z) = m.gyro_axis_rad_s {
            self.last_z = Some(z);
        }
        self.phi_int_rad += self.last_z.unwrap_or(0.0) * dt_s;
        let phi = self.transition(dt_s);
        let before = self.kf.kf;
        self.kf.predict(&phi);
        self.cycle
            .predicted(&before, &phi, &Matrix2::zeros(), &self.kf.kf);
        let resets = self.kf.resets;
        if let Some(z) = m.gyro_axis_rad_s {
            match self.kf.update(z, self.phi_int_rad) {
                Ok(()) => {
                    self.innovation[0] = self.kf.innovation;
                    self.rate_minus_sensor_rad_s = self.kf.x()[1] - z;
                    self.record_update();
                }
                Err(e) => self.status = EstimatorStatus::Diverged(e.into()),
            }
        }
        let note = (self.kf.resets > resets).then_some(WINDOW_ENDED);
        self.cycle.finish(&self.kf.kf, note);
        if !(self
            .kf
            .x()
            .iter()
            .chain(self.kf.p().iter())
            .all(|v| v.is_finite()))
        {
            self.status = EstimatorStatus::Diverged(Trouble::NotFinite);
        } else if (self.kf.x()[0] - self.phi_int_rad).abs() > RUNAWAY_RAD {
            self.status = EstimatorStatus::Diverged(Trouble::AngleRanAway {
                deg: (self.kf.x()[0] - self.phi_int_rad).to_degrees(),
            });
        }
    }

    fn estimate(&self) -> Estimate {
        let x = self.kf.x();
        Estimate {
            angle_rad: Some(x[0]),
            rate_body_rad_s: Some(Vector3::new(0.0, 0.0, x[1])),
            ..Estimate::default()
        }
    }
}

/// Paper 1's third estimator: the angle from direct integration of the averaged gyro rate
/// (φ_int, the reference the paper's error panels compare the filters with).
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
        "Direct integration of the gyro (φ_int)"
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
            angle_rad: Some(self.angle_rad),
            rate_body_rad_s: Some(Vector3::new(0.0, 0.0, self.last_rate_rad_s.unwrap_or(0.0))),
            ..Estimate::default()
        }
    }
}
