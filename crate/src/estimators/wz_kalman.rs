//! Beyond paper 3: a Kalman filter in (u, v). The process is the Riccati kinematics
//! (eqs. 18–19) driven by the gyro; the measurement is the accelerometer's (uᵃ, vᵃ)
//! (eq. 28). Extended form: the state is propagated by RK4, the covariance by the Jacobian
//! `F = ∂(u̇, v̇)/∂(u, v)`; gyro noise enters through `G = ∂(u̇, v̇)/∂ω`, accelerometer noise
//! through `J = ∂(uᵃ, vᵃ)/∂n`, so `R = σₐ² J Jᵀ`. Joseph-form update. A 2×2 covariance, drawn
//! as a 3σ ellipse around the estimate. When the body turns upside down the state moves to
//! the flipped chart s = 1/w and the covariance with it (`P ← M P Mᵀ`, M the Jacobian of
//! 1/w, i.e. multiplication by −1/w²).
//!
//! A constant gyro bias is not in the state: it is modelled as extra rate noise of spectral
//! density b²·τ (b = the bias slider, τ = 1 s), which keeps the filter listening to the
//! accelerometer; its covariance is then only approximately consistent. With b = 0 the model
//! is exact (the NEES test). `kf_q_scale` scales the process noise.

use super::kf::KalmanState;
use crate::math::{
    RateSegment, WzAttitude, WzChart, chart_coords_of_vertical, step_uvz_rk4, symmetrize,
};
use crate::model::{
    Attitude, Covariance, Estimate, Estimator, EstimatorStatus, Measurements, ParamValues,
    Quantity, StateInfo, StateKind, Tuner,
};
use nalgebra::{Matrix2, Matrix2x3, Vector2, Vector3};

// The series this estimator records besides the catalogue's (figures name them).
/// innovation of u (uᵃ − û).
pub const INNOV_U: Quantity = Quantity::new("innov_u", "innovation of u (uᵃ − û)", "");
/// innovation of v (vᵃ − v̂).
pub const INNOV_V: Quantity = Quantity::new("innov_v", "innovation of v (vᵃ − v̂)", "");

/// The noise the (u, v) filter assumes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WzKalmanTuning {
    /// Gyro white-noise σ per sample (rad/s).
    pub gyro_sigma_rad_s: f64,
    /// 1σ of an unmodelled constant gyro bias (rad/s), turned into process noise.
    pub bias_sigma_rad_s: f64,
    /// Accelerometer noise σ per axis (g).
    pub accel_sigma_g: f64,
    /// Scale of the process noise.
    pub q_scale: f64,
}

impl Default for WzKalmanTuning {
    /// A noiseless gyro and a 0.01-g accelerometer.
    fn default() -> Self {
        Self {
            gyro_sigma_rad_s: 0.0,
            bias_sigma_rad_s: 0.0,
            accel_sigma_g: 0.01,
            q_scale: 1.0,
        }
    }
}

/// Correlation time (s) with which an unmodelled constant gyro bias is turned into process
/// noise.
pub const BIAS_CORRELATION_S: f64 = 1.0;

/// The (u, v) Kalman filter.
#[derive(Clone, Debug)]
pub struct WzKalman {
    wz: WzAttitude,
    /// (u, v) and their covariance, in the current chart.
    kf: KalmanState<2>,
    last_rate_rad_s: Option<Vector3<f64>>,
    tuning: WzKalmanTuning,
    tuner: Option<Tuner<WzKalmanTuning>>,
    innovation: [f64; 2],
    status: EstimatorStatus,
}

/// The filter's states.
/// The covariance state u.
pub const STATE_U: StateInfo = StateInfo::new("u", "", StateKind::WzU);
/// The covariance state v.
pub const STATE_V: StateInfo = StateInfo::new("v", "", StateKind::WzV);
const STATES: &[StateInfo] = &[STATE_U, STATE_V];

/// `F = ∂(u̇, v̇)/∂(u, v)` of eqs. (18–19).
fn jacobian_state(u: f64, v: f64, w: &Vector3<f64>) -> Matrix2<f64> {
    let (wx, wy, wz) = (w.x, w.y, w.z);
    Matrix2::new(
        v * wx - u * wy,
        wz + u * wx + v * wy,
        -wz - v * wy - u * wx,
        v * wx - u * wy,
    )
}

/// `G = ∂(u̇, v̇)/∂ω` of eqs. (18–19).
fn jacobian_rate(u: f64, v: f64) -> Matrix2x3<f64> {
    Matrix2x3::new(
        u * v,
        -0.5 * (1.0 + u * u - v * v),
        v,
        0.5 * (1.0 - u * u + v * v),
        -u * v,
        -u,
    )
}

/// `J = ∂(uᵃ, vᵃ)/∂n` of eq. (28) at the unit vertical `k` (chart coordinates).
fn jacobian_accel(k: &Vector3<f64>) -> Matrix2x3<f64> {
    let d = 1.0 + k.z;
    Matrix2x3::new(1.0 / d, 0.0, -k.x / (d * d), 0.0, 1.0 / d, -k.y / (d * d))
}

impl WzKalman {
    /// Starts at `wz0` with covariance `p0` (in `wz0`'s chart).
    pub fn new(wz0: WzAttitude, p0: Matrix2<f64>) -> Self {
        Self {
            wz: wz0,
            kf: KalmanState::new(Vector2::new(wz0.u, wz0.v), p0),
            last_rate_rad_s: None,
            tuning: WzKalmanTuning::default(),
            tuner: None,
            innovation: [0.0; 2],
            status: EstimatorStatus::Ok,
        }
    }

    /// Re-tunes the filter from the lab's parameters on every change.
    #[must_use]
    pub fn tuned_by(mut self, tuner: Tuner<WzKalmanTuning>) -> Self {
        self.tuner = Some(tuner);
        self
    }

    fn rates_in_chart(&self, rate: &Vector3<f64>) -> Vector3<f64> {
        match self.wz.chart {
            WzChart::North => *rate,
            WzChart::Flipped => Vector3::new(rate.x, -rate.y, -rate.z),
        }
    }

    fn predict(&mut self, rate: Vector3<f64>, dt_s: f64) {
        let seg = RateSegment {
            start_rad_s: self.last_rate_rad_s.unwrap_or(rate),
            end_rad_s: rate,
        };
        let mid = self.rates_in_chart(&seg.at(0.5));
        let (u, v) = (self.wz.u, self.wz.v);
        let phi = Matrix2::identity() + jacobian_state(u, v, &mid) * dt_s;
        let g = jacobian_rate(u, v);
        // White gyro noise: σ² per sample enters as σ² dt². The unmodelled bias b enters as
        // rate noise of spectral density b²·τ (τ = BIAS_CORRELATION_S), so the predicted
        // error from it after τ seconds is b·τ, what a constant bias really does by then.
        let angle_var = (self.tuning.gyro_sigma_rad_s * dt_s).powi(2)
            + self.tuning.bias_sigma_rad_s.powi(2) * BIAS_CORRELATION_S * dt_s;
        let q = g * g.transpose() * (angle_var * self.tuning.q_scale);
        let before = self.wz;
        self.wz = step_uvz_rk4(&self.wz, |f| seg.at(f), dt_s);
        self.kf
            .predict_with(Vector2::new(self.wz.u, self.wz.v), &phi, &q);
        if self.wz.chart != before.chart {
            self.kf.p = chart_change(&self.kf.p, &self.wz);
        }
        self.last_rate_rad_s = Some(rate);
    }

    fn update(&mut self, n: &Vector3<f64>) {
        let Some((ua, va)) =
            chart_coords_of_vertical(n, self.wz.chart).filter(|(u, v)| u.hypot(*v) < 10.0)
        else {
            return;
        };
        let k_body = n.normalize();
        let k_chart = match self.wz.chart {
            WzChart::North => k_body,
            WzChart::Flipped => Vector3::new(k_body.x, -k_body.y, -k_body.z),
        };
        // (uᵃ, vᵃ) are computed from the normalised reading, so only noise across k matters.
        let j = jacobian_accel(&k_chart)
            * (nalgebra::Matrix3::identity() - k_chart * k_chart.transpose());
        let r = symmetrize(&(j * j.transpose() * self.tuning.accel_sigma_g.powi(2)));
        let y = Vector2::new(ua - self.wz.u, va - self.wz.v);
        match self.kf.update_with(y, &Matrix2::identity(), &r) {
            Ok(_) => {
                self.wz.u = self.kf.x[0];
                self.wz.v = self.kf.x[1];
                self.innovation = [y.x, y.y];
            }
            Err(e) => self.status = EstimatorStatus::Diverged(e.into()),
        }
    }

    /// The current (u, v) covariance, in the current chart.
    pub fn uv_covariance(&self) -> Matrix2<f64> {
        self.kf.p
    }
}

/// P carried into the chart of `new` (the point just converted): new = 1/old as complex
/// numbers, so d(new)/d(old) = −1/old² = −new², a rotation-scaling matrix.
fn chart_change(p: &Matrix2<f64>, new: &WzAttitude) -> Matrix2<f64> {
    let (u, v) = (new.u, new.v);
    let (re, im) = (-(u * u - v * v), -2.0 * u * v);
    let m = Matrix2::new(re, -im, im, re);
    symmetrize(&(m * p * m.transpose()))
}

impl Estimator for WzKalman {
    fn id(&self) -> &'static str {
        "kf-uv"
    }

    fn label(&self) -> &'static str {
        "Kalman filter in (u, v)"
    }

    fn covariance_states(&self) -> &'static [StateInfo] {
        STATES
    }

    fn covariance(&self) -> Option<Covariance<'_>> {
        Some(Covariance {
            states: STATES,
            matrix: self.kf.p.as_slice(),
        })
    }

    fn innovation_quantities(&self) -> &'static [Quantity] {
        const QUANTITIES: &[Quantity] = &[INNOV_U, INNOV_V];
        QUANTITIES
    }

    fn innovation(&self) -> &[f64] {
        &self.innovation
    }

    fn status(&self) -> &EstimatorStatus {
        &self.status
    }

    fn apply_params(&mut self, params: &ParamValues) {
        if let Some(f) = self.tuner {
            let t = f(params);
            self.tuning = WzKalmanTuning {
                accel_sigma_g: t.accel_sigma_g.max(1e-6),
                ..t
            };
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        if self.status != EstimatorStatus::Ok {
            return;
        }
        if let Some(rate) = m.gyro_body_rad_s {
            self.predict(rate, dt_s);
        }
        if let Some(n) = m.accel_body_g {
            self.update(&n);
        }
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            attitude: Attitude::Wz(self.wz),
            rate_body_rad_s: self.last_rate_rad_s,
            ..Estimate::default()
        }
    }
}
