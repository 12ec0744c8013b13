//! Paper 4 (Pham, Shilin, Girnik, Nguyen, Inzhenernyj vestnik Dona 2025): a linear Kalman
//! filter for the roll θ of an asymmetric quadrotor, tuned by one number, γ = det Q / det R.
//!
//! * State x = [θ, ω] (and, beyond the paper, a gyro bias b); measurement
//!   z = [θ_acc, ω_gyro] with θ_acc = atan2(a_y, a_z), H = E (bias: ω_gyro = ω + b).
//! * Model (eq. 5, with the digest's discretisation): x⁺ = A x + B u, A = [[1, dt], [0, 1]],
//!   B = [dt²/2, dt], u the commanded angular acceleration. The paper feeds the zero-mean
//!   part u_v that its PD/PI split leaves; one variant feeds nothing, one (beyond the paper)
//!   the net u_v + û₀ − u₀ of a filter that knows the asymmetry's u₀.
//! * γ → Q (the paper does not say; this project's mapping): R = diag(σ_θ², σ_ω²) from the
//!   sensor's datasheet noise stays fixed, Q = q·diag(dt³/3, dt) (a white angular
//!   acceleration of density q), and q is the value with det Q = γ·det R:
//!   q = √(3γ det R)/dt². The bias state, when there is one, adds q_b·dt outside that block.
//! * Beyond the paper, for the Q landscape: Q = diag(q_θ, q_ω) set element by element, so a
//!   sweep can walk across lines of constant γ.

use super::kf::{KalmanState, LinearObservation};
use super::kf_cycle::CycleRecorder;
use crate::model::{
    Covariance, Estimate, Estimator, EstimatorStatus, Extras, KalmanCycle, Measurements,
    ParamValues, Quantity, StateInfo, StateKind, Teaching, Tuner,
};
use nalgebra::{SMatrix, SVector, Vector3};

/// The command of paper 4's roll controller as angular acceleration, split as the paper's
/// PD/PI structure splits it: a zero-mean varying part u_v and the constant part u₀ its
/// integral has absorbed (the hover asymmetry).
/// A lab whose controller is part of the plant passes it in
/// [`crate::model::Measurements::lab`]; a filter that knows the command reads it there.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ControlInput {
    /// u_v (rad/s²).
    pub varying_rad_s2: f64,
    /// u₀, the integral part (rad/s²).
    pub constant_rad_s2: f64,
    /// The constant the plant really needs to hold its angle (rad/s²): what a filter that
    /// knows the asymmetry knows.
    pub needed_rad_s2: f64,
}

// The series this estimator records besides the catalogue's (figures name them).
/// innovation of the accelerometer angle θ_acc (rad).
pub const INNOV_ANGLE_RAD: Quantity = Quantity::new(
    "innov_angle_rad",
    "innovation of the accelerometer angle θ_acc",
    "rad",
);
/// innovation of the gyro rate ω (rad/s).
pub const INNOV_RATE_RAD_S: Quantity =
    Quantity::new("innov_rate_rad_s", "innovation of the gyro rate ω", "rad/s");
/// gyro bias b (deg/s).
pub const GYRO_BIAS_DEG_S: Quantity = Quantity::new("gyro_bias_deg_s", "gyro bias b", "deg/s");

/// What the filter is fed as the model input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RollInput {
    /// The paper: u_v when the "input" switch is on, nothing when off.
    PaperSwitch,
    /// u_v + û₀ − u₀: the whole command less the constant the asymmetry really needs (beyond
    /// the paper: a filter that knows the asymmetry, so the integral's error reaches it too).
    WithConstant,
}

/// The filter's settings (a lab's [`Tuner`] gives them from its parameters).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RollTuning {
    /// γ.
    pub gamma: f64,
    /// Whether the paper's filter is fed u_v.
    pub input_on: bool,
    /// R's σ of the accelerometer angle (rad).
    pub sigma_angle_rad: f64,
    /// R's σ of the gyro (rad/s).
    pub sigma_rate_rad_s: f64,
    /// Bias random-walk density (rad/s/√s).
    pub bias_walk: f64,
    /// Q = diag(q_θ rad², q_ω (rad/s)²) per step, set element by element instead of by γ.
    pub q_elements: Option<[f64; 2]>,
}

impl RollTuning {
    /// The [θ, ω] block of Q for a step of `dt_s`: by γ, or element by element.
    pub fn q_block(&self, dt_s: f64) -> [f64; 2] {
        match self.q_elements {
            Some(q) => q,
            None => {
                let q = self.q_density(dt_s);
                [q * dt_s.powi(3) / 3.0, q * dt_s]
            }
        }
    }

    /// q of Q = q·diag(dt³/3, dt) with det Q = γ det R.
    pub fn q_density(&self, dt_s: f64) -> f64 {
        let det_r = (self.sigma_angle_rad * self.sigma_rate_rad_s).powi(2);
        (3.0 * self.gamma * det_r).sqrt() / (dt_s * dt_s)
    }
}

/// The covariance state theta (rad).
pub const STATE_THETA: StateInfo = StateInfo::new("theta", "rad", StateKind::Angle);
/// The covariance state omega (rad/s).
pub const STATE_OMEGA: StateInfo = StateInfo::new("omega", "rad/s", StateKind::Rate);
/// The covariance state gyro_bias (rad/s).
pub const STATE_GYRO_BIAS: StateInfo = StateInfo::new("gyro_bias", "rad/s", StateKind::GyroBias(2));
const STATES_2: &[StateInfo] = &[STATE_THETA, STATE_OMEGA];
const STATES_3: &[StateInfo] = &[STATE_THETA, STATE_OMEGA, STATE_GYRO_BIAS];

/// The accelerometer angle θ_acc = atan2(a_y, a_z) of a reading (g).
pub fn accel_angle_rad(accel_g: &Vector3<f64>) -> f64 {
    accel_g.y.atan2(accel_g.z)
}

/// What the roll filter's two measurement rows are, for the step-through panel.
const CYCLE_ROWS_NAMED: [&str; 2] = ["accelerometer angle θ_acc (rad)", "gyro rate ω (rad/s)"];

/// Paper 4's roll filter with `N` = 2 ([θ, ω]) or 3 ([θ, ω, b]) states.
#[derive(Clone, Debug)]
pub struct RollKf<const N: usize> {
    id: &'static str,
    label: &'static str,
    input: RollInput,
    tuning: RollTuning,
    tuner: Option<Tuner<RollTuning>>,
    kf: KalmanState<N>,
    innovation: [f64; 2],
    status: EstimatorStatus,
    cycle: CycleRecorder,
}

impl<const N: usize> RollKf<N> {
    /// A filter starting at rest with P₀ = diag(σ_θ², σ_ω², (5 °/s)²).
    pub fn new(
        id: &'static str,
        label: &'static str,
        input: RollInput,
        tuning: RollTuning,
    ) -> Self {
        let p0 = SMatrix::<f64, N, N>::from_fn(|i, j| match (i, j) {
            (0, 0) => tuning.sigma_angle_rad.powi(2),
            (1, 1) => tuning.sigma_rate_rad_s.powi(2),
            (2, 2) => 5f64.to_radians().powi(2),
            _ => 0.0,
        });
        Self {
            id,
            label,
            input,
            tuning,
            tuner: None,
            kf: KalmanState::new(SVector::zeros(), p0),
            innovation: [0.0; 2],
            status: EstimatorStatus::Ok,
            cycle: CycleRecorder::new(if N == 3 { STATES_3 } else { STATES_2 }),
        }
    }

    /// Re-tunes the filter from the lab's parameters on every change.
    #[must_use]
    pub fn tuned_by(mut self, tuner: Tuner<RollTuning>) -> Self {
        self.tuner = Some(tuner);
        self
    }

    /// The covariance.
    pub fn p(&self) -> &SMatrix<f64, N, N> {
        &self.kf.p
    }

    fn u(&self, m: &Measurements) -> f64 {
        let Some(c) = m.lab.get::<ControlInput>() else {
            return 0.0;
        };
        match self.input {
            RollInput::PaperSwitch if self.tuning.input_on => c.varying_rad_s2,
            RollInput::PaperSwitch => 0.0,
            // The net angular acceleration: the whole command less what the asymmetry takes.
            RollInput::WithConstant => c.varying_rad_s2 + c.constant_rad_s2 - c.needed_rad_s2,
        }
    }
}

impl<const N: usize> Teaching for RollKf<N> {
    fn cycle(&self) -> &KalmanCycle {
        self.cycle.cycle()
    }
}

impl<const N: usize> Estimator for RollKf<N> {
    fn id(&self) -> &'static str {
        self.id
    }

    fn label(&self) -> &'static str {
        self.label
    }

    fn apply_params(&mut self, p: &ParamValues) {
        if let Some(f) = self.tuner {
            self.tuning = f(p);
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        if matches!(self.status, EstimatorStatus::Diverged(_)) {
            return;
        }
        let phi = SMatrix::<f64, N, N>::from_fn(|i, j| match (i, j) {
            (0, 1) => dt_s,
            _ if i == j => 1.0,
            _ => 0.0,
        });
        let u = self.u(m);
        let mut x = phi * self.kf.x;
        x[0] += dt_s * dt_s / 2.0 * u;
        x[1] += dt_s * u;
        let q = self.tuning.q_block(dt_s);
        let qm = SMatrix::<f64, N, N>::from_fn(|i, j| match (i, j) {
            (0, 0) => q[0],
            (1, 1) => q[1],
            (2, 2) => self.tuning.bias_walk.powi(2) * dt_s,
            _ => 0.0,
        });
        let before = self.kf;
        self.kf.predict_with(x, &phi, &qm);
        self.cycle.predicted(&before, &phi, &qm, &self.kf);
        if let (Some(a), Some(w)) = (m.accel_body_g, m.gyro_axis_rad_s) {
            let z = nalgebra::Vector2::new(accel_angle_rad(&a), w);
            let h = SMatrix::<f64, 2, N>::from_fn(|i, j| match (i, j) {
                (0, 0) | (1, 1) | (1, 2) => 1.0,
                _ => 0.0,
            });
            let r = nalgebra::Matrix2::new(
                self.tuning.sigma_angle_rad.powi(2).max(1e-18),
                0.0,
                0.0,
                self.tuning.sigma_rate_rad_s.powi(2).max(1e-18),
            );
            let prior = self.kf;
            match self.kf.update(&z, &LinearObservation::new(h, r)) {
                Ok(inn) => {
                    self.innovation = [inn.residual[0], inn.residual[1]];
                    self.cycle
                        .updated(&prior, &h, &r, CYCLE_ROWS_NAMED, &inn, &self.kf);
                }
                Err(e) => self.status = EstimatorStatus::Diverged(e.into()),
            }
        }
        self.cycle.finish(&self.kf, None);
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            angle_rad: Some(self.kf.x[0]),
            rate_body_rad_s: Some(Vector3::new(0.0, 0.0, self.kf.x[1])),
            ..Estimate::default()
        }
    }

    fn status(&self) -> &EstimatorStatus {
        &self.status
    }

    fn covariance_states(&self) -> &'static [StateInfo] {
        if N == 3 { STATES_3 } else { STATES_2 }
    }

    fn teaching(&self) -> Option<&dyn Teaching> {
        Some(self)
    }

    fn covariance(&self) -> Option<Covariance<'_>> {
        Some(Covariance {
            states: self.covariance_states(),
            matrix: self.kf.p.as_slice(),
        })
    }

    fn innovation_quantities(&self) -> &'static [Quantity] {
        const QUANTITIES: &[Quantity] = &[INNOV_ANGLE_RAD, INNOV_RATE_RAD_S];
        QUANTITIES
    }

    fn innovation(&self) -> &[f64] {
        &self.innovation
    }

    fn extra_quantities(&self) -> &'static [Quantity] {
        const BIAS: [Quantity; 1] = [GYRO_BIAS_DEG_S];
        if N == 3 { &BIAS } else { &[] }
    }

    fn extras(&self, out: &mut Extras<'_>) {
        if N == 3 {
            out.put(&GYRO_BIAS_DEG_S, self.kf.x[N - 1].to_degrees());
        }
    }
}

/// The complementary filter the paper names as its baseline (this project's form):
/// θ ← a(θ + ω_gyro·dt) + (1 − a)·θ_acc, ω = ω_gyro; a = 0.98 at 100 Hz is τ ≈ 0.5 s.
#[derive(Clone, Debug)]
pub struct ComplementaryRoll {
    gain: f64,
    tuner: Option<Tuner<f64>>,
    angle_rad: f64,
    rate_rad_s: f64,
    started: bool,
}

impl ComplementaryRoll {
    /// A filter of gain `a` (0 < a < 1).
    pub fn new(gain: f64) -> Self {
        Self {
            gain,
            tuner: None,
            angle_rad: 0.0,
            rate_rad_s: 0.0,
            started: false,
        }
    }

    /// Takes the gain a from the lab's parameters on every change.
    #[must_use]
    pub fn tuned_by(mut self, tuner: Tuner<f64>) -> Self {
        self.tuner = Some(tuner);
        self
    }
}

impl Estimator for ComplementaryRoll {
    fn id(&self) -> &'static str {
        "cf"
    }

    fn label(&self) -> &'static str {
        "Complementary filter (the paper's baseline)"
    }

    fn apply_params(&mut self, p: &ParamValues) {
        if let Some(f) = self.tuner {
            self.gain = f(p);
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        let (Some(a), Some(w)) = (m.accel_body_g, m.gyro_axis_rad_s) else {
            self.angle_rad += self.rate_rad_s * dt_s;
            return;
        };
        let acc = accel_angle_rad(&a);
        self.angle_rad = if self.started {
            self.gain * (self.angle_rad + w * dt_s) + (1.0 - self.gain) * acc
        } else {
            acc
        };
        self.started = true;
        self.rate_rad_s = w;
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            angle_rad: Some(self.angle_rad),
            rate_body_rad_s: Some(Vector3::new(0.0, 0.0, self.rate_rad_s)),
            ..Estimate::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tuning(gamma: f64) -> RollTuning {
        RollTuning {
            gamma,
            input_on: true,
            sigma_angle_rad: 0.2f64.to_radians(),
            sigma_rate_rad_s: 0.05f64.to_radians(),
            bias_walk: 0.0,
            q_elements: None,
        }
    }

    #[test]
    fn the_q_of_gamma_has_that_determinant_ratio() {
        for gamma in [1e-5, 2e-3, 0.02, 0.2] {
            let t = tuning(gamma);
            let dt = 0.01;
            let q = t.q_density(dt);
            let det_q = (q * dt.powi(3) / 3.0) * (q * dt);
            let det_r = (t.sigma_angle_rad * t.sigma_rate_rad_s).powi(2);
            assert!((det_q / det_r / gamma - 1.0).abs() < 1e-12, "{gamma}");
        }
    }

    #[test]
    fn with_exact_measurements_the_filter_converges_to_them() {
        let mut f = RollKf::<2>::new("kf", "kf", RollInput::PaperSwitch, tuning(2e-3));
        let theta: f64 = 0.3;
        let m = Measurements {
            accel_body_g: Some(Vector3::new(0.0, theta.sin(), theta.cos())),
            gyro_axis_rad_s: Some(0.0),
            ..Measurements::default()
        };
        for _ in 0..2000 {
            f.step(&m, 0.01);
        }
        let e = f.estimate();
        assert!(
            (e.angle_rad.unwrap() - theta).abs() < 1e-6,
            "{:?}",
            e.angle_rad
        );
    }
}
