//! Paper 2's attitude EKFs (Ivanov, Ivlev, Karpenko, Ovchinnikov, Keldysh preprint 2014-64)
//! as one multiplicative EKF whose state and measurement rows are assembled from data: the
//! twelve sensor sets of Table 2, the gyro-bias and magnetometer-bias augmentations, the
//! reduced [λ, Δω] variant, the parallel disturbance filter of §3.2 and the constant-gain
//! filter of §3.3 are configurations of this one file, not copies.
//!
//! * Attitude: `q_orbit_from_body` (Λ of the paper is its conjugate: orbital → body). The
//!   error state δλ is the vector part of δq = q̂⁻¹ ⊗ q (half the rotation angle, as the
//!   paper's λ); after each update the error is folded into q̂ and reset.
//! * Dynamics (eqs. 6–7): J ω̇ = M_gg − ω × (Jω + h) − ḣ (+ d), Λ̇ = ½ Λ ∘ ω_rel with
//!   ω_rel = ω − A ω_orb. The wheel momentum h and torque ḣ are known inputs (the wheels are
//!   measured), so the control law need not be modelled; d is the disturbance estimate of the
//!   parallel filter (zero otherwise). Unlike the paper's F, which carries the control gains
//!   −J⁻¹K_λ and −J⁻¹K_ω, F here carries the gyroscopic terms the wheels really apply:
//!   F = [[−[ω×], ½E], [J⁻¹ k F_g, J⁻¹([(Jω+h)×] − [ω×]J)]] with k = 6μ/r³ and
//!   F_g = [η×]J[η×] − [(Jη)×][η×] (the paper's gravity-gradient block).
//! * Measurements (Table 2's H): star tracker δλ = vec(q̂⁻¹ ⊗ q_st) with H = [E 0];
//!   gyro ω̃ = ω + Δω with H = [0 E (E)]; magnetometer b = A b₀ (+ Δb) with
//!   H = [2[b̂×] 0 (E)]; sun sensor s = A s₀ with H = [2[ŝ×] 0]. The 2 makes δλ half-angle
//!   consistent. Rows are processed one scalar at a time (diagonal R), so any set is the
//!   same code and the step has no heap.
//! * Q = diag(q_Λ²·E, q_ω²·E, q_bias²·E) per prediction step, the paper's tuning knobs.

use super::kf::KalmanState;
use crate::math::symmetrize;
use crate::model::{
    Attitude, Covariance, Estimate, Estimator, EstimatorStatus, Measurements, Onboard, ParamValues,
    StateInfo, StateKind,
};
use nalgebra::{Matrix3, SMatrix, SVector, UnitQuaternion, Vector3};

/// Which sensors a filter uses (Table 2's z).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SensorSet {
    /// Star tracker.
    pub star: bool,
    /// Gyro.
    pub gyro: bool,
    /// Magnetometer.
    pub mag: bool,
    /// Sun sensors.
    pub sun: bool,
}

/// What the state holds (Table 2's x).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StateSet {
    /// [λ, ω].
    AttRate,
    /// [λ, ω, Δω]: gyro bias.
    AttRateGyroBias,
    /// [λ, ω, Δb]: magnetometer bias.
    AttRateMagBias,
    /// [λ, Δω]: the reduced variant — ω is the gyro reading less the bias, no dynamics.
    AttGyroBias,
}

impl StateSet {
    /// Number of states.
    pub const fn dim(self) -> usize {
        match self {
            Self::AttRate | Self::AttGyroBias => 6,
            Self::AttRateGyroBias | Self::AttRateMagBias => 9,
        }
    }

    fn omega(self) -> Option<usize> {
        (self != Self::AttGyroBias).then_some(3)
    }

    fn gyro_bias(self) -> Option<usize> {
        match self {
            Self::AttRateGyroBias => Some(6),
            Self::AttGyroBias => Some(3),
            _ => None,
        }
    }

    fn mag_bias(self) -> Option<usize> {
        (self == Self::AttRateMagBias).then_some(6)
    }
}

/// One filter of the lab: its sensors, states and mode.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MekfConfig {
    /// Series id, e.g. `st-gyro`.
    pub id: &'static str,
    /// Legend label.
    pub label: &'static str,
    /// Sensors used.
    pub sensors: SensorSet,
    /// States.
    pub states: StateSet,
    /// Runs the parallel disturbance filter of §3.2.
    pub disturbance: bool,
    /// Freezes the gain at this time (s) and stops propagating P (§3.3).
    pub constant_gain_after_s: Option<f64>,
}

/// Noise levels and tuning, from the lab's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MekfTuning {
    /// q_Λ per prediction step (λ units).
    pub q_att: f64,
    /// q_ω per prediction step (rad/s).
    pub q_rate: f64,
    /// q of a bias state per step (rad/s or nT).
    pub q_bias: f64,
    /// σ of one star-tracker quaternion vector component (δλ units).
    pub star_sigma: f64,
    /// Gyro σ per sample (rad/s).
    pub gyro_sigma_rad_s: f64,
    /// Magnetometer σ per axis (nT).
    pub mag_sigma_nt: f64,
    /// Sun-sensor σ per axis of the unit vector (rad).
    pub sun_sigma_rad: f64,
    /// Fading factor α of the disturbance filter (P_d ← P_d/α per update).
    pub alpha: f64,
    /// R_d as a multiple of the innovation variance of each row.
    pub rd_scale: f64,
}

/// One update's scalar rows: (residual at the prior, H row, R), at most [`MAX_ROWS`].
type Rows<const N: usize> = [(f64, SVector<f64, N>, f64); MAX_ROWS];

/// How a lab turns its parameters and a filter's base (q_Λ, q_ω, q_bias) into a tuning.
pub type Retune = fn(&ParamValues, [f64; 3]) -> MekfTuning;

/// Floating-point operations of one [`Mekf`] step with `n` states that processes `rows`
/// scalar measurement rows, counted from the code (a multiply-add is two; a square root or
/// division one):
/// * prediction — RK4 of (q, ω) ≈ 840, the Jacobian ≈ 367, Φ = E + F·dt 2n², ΦPΦᵀ
///   2(2n³ − n²), + Q and symmetrise 3n²: 1207 + 4n³ + 3n²;
/// * each scalar row — the gain and innovation variance in the filter (4n² + 3n) and the
///   Joseph update of [`KalmanState::update_scalar`] (PHᵀ 2n² − n, S and K 4n, x 2n,
///   E − KH 2n², (E − KH)P(E − KH)ᵀ 2(2n³ − n²), KRKᵀ + add 2n² + n, symmetrise 2n²):
///   4n³ + 10n² + 9n + 2;
/// * assembling the rows ≈ 200, folding the correction ≈ 55, publishing P 2n², the
///   positive-definiteness check (scaling 3n² + 2n, Cholesky ≈ n³/3).
pub const fn full_step_flops(n: u64, rows: u64) -> u64 {
    let predict = 1207 + 4 * n * n * n + 3 * n * n;
    let row = 4 * n * n * n + 10 * n * n + 9 * n + 2;
    let tail = 200 + 55 + 2 * n * n + 3 * n * n + 2 * n + n * n * n / 3;
    predict + rows * row + tail
}

/// Inertia of TabletSat-Aurora (paper 2, §1), kg·m².
pub fn tabletsat_inertia() -> Matrix3<f64> {
    Matrix3::new(0.519, 0.002, 0.005, 0.002, 0.579, 0.009, 0.005, 0.009, 0.71)
}

const STATES_6: [StateInfo; 6] = [
    StateInfo::new("att_x", "rad", StateKind::AttitudeAxis(0)),
    StateInfo::new("att_y", "rad", StateKind::AttitudeAxis(1)),
    StateInfo::new("att_z", "rad", StateKind::AttitudeAxis(2)),
    StateInfo::new("rate_x", "rad/s", StateKind::RateAxis(0)),
    StateInfo::new("rate_y", "rad/s", StateKind::RateAxis(1)),
    StateInfo::new("rate_z", "rad/s", StateKind::RateAxis(2)),
];
const STATES_GYRO_BIAS: [StateInfo; 9] = [
    STATES_6[0],
    STATES_6[1],
    STATES_6[2],
    STATES_6[3],
    STATES_6[4],
    STATES_6[5],
    StateInfo::new("gbias_x", "rad/s", StateKind::GyroBias(0)),
    StateInfo::new("gbias_y", "rad/s", StateKind::GyroBias(1)),
    StateInfo::new("gbias_z", "rad/s", StateKind::GyroBias(2)),
];
const STATES_MAG_BIAS: [StateInfo; 9] = [
    STATES_6[0],
    STATES_6[1],
    STATES_6[2],
    STATES_6[3],
    STATES_6[4],
    STATES_6[5],
    StateInfo::new("mbias_x", "nT", StateKind::Other),
    StateInfo::new("mbias_y", "nT", StateKind::Other),
    StateInfo::new("mbias_z", "nT", StateKind::Other),
];
const STATES_REDUCED: [StateInfo; 6] = [
    STATES_6[0],
    STATES_6[1],
    STATES_6[2],
    StateInfo::new("gbias_x", "rad/s", StateKind::GyroBias(0)),
    StateInfo::new("gbias_y", "rad/s", StateKind::GyroBias(1)),
    StateInfo::new("gbias_z", "rad/s", StateKind::GyroBias(2)),
];

fn states_of(s: StateSet) -> &'static [StateInfo] {
    match s {
        StateSet::AttRate => &STATES_6,
        StateSet::AttRateGyroBias => &STATES_GYRO_BIAS,
        StateSet::AttRateMagBias => &STATES_MAG_BIAS,
        StateSet::AttGyroBias => &STATES_REDUCED,
    }
}

/// `[v×]`.
fn skew(v: &Vector3<f64>) -> Matrix3<f64> {
    v.cross_matrix()
}

/// The parallel disturbance filter (§3.2): d̂ (1/s²) with covariance P_d.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Disturbance {
    d: Vector3<f64>,
    p: Matrix3<f64>,
}

/// Initial variance of the disturbance estimate (1/s⁴): σ 1e-5 s⁻², several times the
/// paper's d ≈ 1e-6 s⁻².
const DIST_P0: f64 = 1e-10;

/// Largest variance of the disturbance estimate (1/s⁴): σ 1e-3 s⁻², far above any torque a
/// microsatellite meets.
const DIST_P_MAX: f64 = 1e-6;

/// Whether `p` is positive semi-definite to rounding in its own units: the correlation
/// matrix D^-½ P D^-½ plus 1e-9·E has a Cholesky factor. (Its smallest eigenvalue is then
/// above −1e-9 of the largest variance.)
fn positive_semidefinite<const N: usize>(p: &SMatrix<f64, N, N>) -> bool {
    let d = p.diagonal();
    if d.iter().any(|v| *v < 0.0) {
        return false;
    }
    let inv = d.map(|v| if v > 0.0 { 1.0 / v.sqrt() } else { 0.0 });
    let c = SMatrix::<f64, N, N>::from_fn(|i, j| p[(i, j)] * inv[i] * inv[j])
        + SMatrix::<f64, N, N>::identity() * 1e-9;
    c.cholesky().is_some()
}

/// Sun–field angle (deg) below which a vector-only set is flagged unobservable.
const DEGENERATE_DEG: f64 = 2.0;

/// Attitude σ (rotation, rad) above which a filter has lost the attitude: diverged.
const LOST_RAD: f64 = std::f64::consts::FRAC_PI_4;

/// Measurement rows per update, at most: star 3, gyro 3, magnetometer 3, sun 3.
const MAX_ROWS: usize = 12;

/// Paper 2's multiplicative EKF with `N` states.
#[derive(Clone, Debug)]
pub struct Mekf<const N: usize> {
    cfg: MekfConfig,
    tuning: MekfTuning,
    j: Matrix3<f64>,
    j_inv: Matrix3<f64>,
    q: UnitQuaternion<f64>,
    omega: Vector3<f64>,
    gyro_bias: Vector3<f64>,
    mag_bias: Vector3<f64>,
    p: SMatrix<f64, N, N>,
    published: SMatrix<f64, N, N>,
    dist: Option<Disturbance>,
    /// ∂(x − x̂)/∂d: how a constant error in d̂ shows in the prior error, through the model
    /// and this filter's own corrections (the disturbance filter's H_d = H·S).
    dist_sens: SMatrix<f64, N, 3>,
    gains: Option<[Option<SVector<f64, N>>; MAX_ROWS]>,
    last_gyro: Option<Vector3<f64>>,
    retune: Option<(Retune, [f64; 3])>,
    unobservable_axis: Option<Vector3<f64>>,
    t_s: f64,
    nis: [f64; 2],
    status: EstimatorStatus,
}

impl<const N: usize> Mekf<N> {
    /// A filter of `cfg` starting at `q0` with rate `omega0` and covariance `p0`; `N` must
    /// be `cfg.states.dim()`.
    pub fn new(
        cfg: MekfConfig,
        tuning: MekfTuning,
        q0: UnitQuaternion<f64>,
        omega0: Vector3<f64>,
        p0: SMatrix<f64, N, N>,
    ) -> Self {
        debug_assert_eq!(N, cfg.states.dim(), "{}", cfg.id);
        let j = tabletsat_inertia();
        let mut f = Self {
            cfg,
            tuning,
            j,
            j_inv: j.try_inverse().unwrap_or_else(Matrix3::identity),
            q: q0,
            omega: omega0,
            gyro_bias: Vector3::zeros(),
            mag_bias: Vector3::zeros(),
            p: p0,
            published: p0,
            dist: cfg.disturbance.then_some(Disturbance {
                d: Vector3::zeros(),
                p: Matrix3::identity() * DIST_P0,
            }),
            dist_sens: SMatrix::zeros(),
            gains: None,
            last_gyro: None,
            retune: None,
            unobservable_axis: None,
            t_s: 0.0,
            nis: [0.0; 2],
            status: EstimatorStatus::Ok,
        };
        f.publish();
        f
    }

    /// Re-derives the tuning from the lab's parameters on every live change: `f(params, q)`
    /// with this filter's base `q` = (q_Λ, q_ω, q_bias).
    #[must_use]
    pub fn with_retune(mut self, f: Retune, q: [f64; 3]) -> Self {
        self.retune = Some((f, q));
        self
    }

    /// The configuration.
    pub fn config(&self) -> &MekfConfig {
        &self.cfg
    }

    /// The covariance (δλ units for the attitude).
    pub fn p(&self) -> &SMatrix<f64, N, N> {
        &self.p
    }

    /// The disturbance estimate (1/s²), if the filter runs one.
    pub fn disturbance(&self) -> Option<Vector3<f64>> {
        self.dist.map(|d| d.d)
    }

    /// The body rate used now: the state, or the gyro less the bias (reduced variant).
    fn rate(&self) -> Vector3<f64> {
        match self.cfg.states.omega() {
            Some(_) => self.omega,
            None => self.last_gyro.map_or(self.omega, |g| g - self.gyro_bias),
        }
    }

    /// q̇ and ω̇ of the model at (q, ω).
    fn derivative(
        &self,
        q: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
        ob: &Onboard,
    ) -> (nalgebra::Quaternion<f64>, Vector3<f64>) {
        let w_rel = omega - q.inverse_transform_vector(&ob.frame_rate_orbit_rad_s);
        let q_dot = q.into_inner() * nalgebra::Quaternion::from_imag(w_rel) * 0.5;
        let eta = q.inverse_transform_vector(&Vector3::z());
        let m_gg = eta.cross(&(self.j * eta)) * ob.gravity_gradient_coeff;
        let h = ob.wheel_momentum_body;
        let d = self.dist.map_or(Vector3::zeros(), |d| d.d);
        let w_dot =
            self.j_inv * (m_gg - omega.cross(&(self.j * omega + h)) - ob.wheel_torque_body) + d;
        (q_dot, w_dot)
    }

    fn predict(&mut self, ob: &Onboard, dt: f64) {
        let has_omega = self.cfg.states.omega().is_some();
        let (q0, w0) = (self.q, self.rate());
        // RK4 of (q, ω); the reduced variant holds ω at the gyro reading.
        let step = |q: &UnitQuaternion<f64>, w: &Vector3<f64>| {
            let (qd, wd) = self.derivative(q, w, ob);
            (qd, if has_omega { wd } else { Vector3::zeros() })
        };
        let add = |q: &UnitQuaternion<f64>, dq: &nalgebra::Quaternion<f64>, h: f64| {
            UnitQuaternion::new_normalize(q.into_inner() + dq * h)
        };
        let (k1q, k1w) = step(&q0, &w0);
        let (k2q, k2w) = step(&add(&q0, &k1q, dt / 2.0), &(w0 + k1w * dt / 2.0));
        let (k3q, k3w) = step(&add(&q0, &k2q, dt / 2.0), &(w0 + k2w * dt / 2.0));
        let (k4q, k4w) = step(&add(&q0, &k3q, dt), &(w0 + k3w * dt));
        self.q = add(&q0, &((k1q + k2q * 2.0 + k3q * 2.0 + k4q) / 6.0), dt);
        if has_omega {
            self.omega = w0 + (k1w + k2w * 2.0 + k3w * 2.0 + k4w) * (dt / 6.0);
        }
        if self.gains.is_some() {
            return; // constant gain: no covariance propagation (§3.3)
        }
        let f = self.jacobian(&w0, ob);
        let phi = SMatrix::<f64, N, N>::identity() + f * dt;
        let t = self.tuning;
        let mut q = SMatrix::<f64, N, N>::zeros();
        let gyro_att = if has_omega {
            0.0
        } else {
            (t.gyro_sigma_rad_s * dt / 2.0).powi(2)
        };
        for i in 0..3 {
            q[(i, i)] = t.q_att * t.q_att + gyro_att;
        }
        if let Some(o) = self.cfg.states.omega() {
            for i in 0..3 {
                q[(o + i, o + i)] = t.q_rate * t.q_rate;
            }
        }
        for b in [self.cfg.states.gyro_bias(), self.cfg.states.mag_bias()]
            .into_iter()
            .flatten()
        {
            for i in 0..3 {
                q[(b + i, b + i)] = t.q_bias * t.q_bias;
            }
        }
        self.p = symmetrize(&(phi * self.p * phi.transpose() + q));
        if self.dist.is_some() {
            // A constant d moves δω by d·dt and δλ (half angle) by d·dt²/4 per step.
            let mut gamma = SMatrix::<f64, N, 3>::zeros();
            if let Some(o) = self.cfg.states.omega() {
                for i in 0..3 {
                    gamma[(i, i)] = dt * dt / 4.0;
                    gamma[(o + i, i)] = dt;
                }
            }
            self.dist_sens = phi * self.dist_sens + gamma;
        }
    }

    /// F = ∂f/∂x at the estimate (see the module documentation).
    fn jacobian(&self, w: &Vector3<f64>, ob: &Onboard) -> SMatrix<f64, N, N> {
        let mut f = SMatrix::<f64, N, N>::zeros();
        f.fixed_view_mut::<3, 3>(0, 0).copy_from(&(-skew(w)));
        match self.cfg.states.omega() {
            Some(o) => {
                f.fixed_view_mut::<3, 3>(0, o)
                    .copy_from(&(Matrix3::identity() * 0.5));
                let eta = self.q.inverse_transform_vector(&Vector3::z());
                let (se, sje) = (skew(&eta), skew(&(self.j * eta)));
                let fg = se * self.j * se - sje * se;
                let k = 2.0 * ob.gravity_gradient_coeff;
                f.fixed_view_mut::<3, 3>(o, 0)
                    .copy_from(&(self.j_inv * fg * k));
                let h = ob.wheel_momentum_body;
                let gyro = skew(&(self.j * w + h)) - skew(w) * self.j;
                f.fixed_view_mut::<3, 3>(o, o)
                    .copy_from(&(self.j_inv * gyro));
            }
            None => {
                if let Some(b) = self.cfg.states.gyro_bias() {
                    f.fixed_view_mut::<3, 3>(0, b)
                        .copy_from(&(Matrix3::identity() * -0.5));
                }
            }
        }
        f
    }

    /// Assembles this step's measurement rows: (residual at the prior, H row, R).
    fn rows(&self, m: &Measurements, ob: &Onboard) -> (Rows<N>, [bool; MAX_ROWS]) {
        let mut rows = [(0.0, SVector::<f64, N>::zeros(), 0.0); MAX_ROWS];
        let mut present = [false; MAX_ROWS];
        let s = self.cfg.sensors;
        let t = self.tuning;
        let st = self.cfg.states;
        if let (true, Some(q_st)) = (s.star, m.star_q_ref_from_body) {
            let mut dq = (self.q.inverse() * q_st).into_inner();
            if dq.w < 0.0 {
                dq = -dq;
            }
            for i in 0..3 {
                let mut h = SVector::<f64, N>::zeros();
                h[i] = 1.0;
                rows[i] = (dq.imag()[i], h, t.star_sigma * t.star_sigma);
                present[i] = true;
            }
        }
        if let (true, Some(g), Some(o)) = (s.gyro, m.gyro_body_rad_s, st.omega()) {
            let predicted = self.omega
                + if st.gyro_bias().is_some() {
                    self.gyro_bias
                } else {
                    Vector3::zeros()
                };
            for i in 0..3 {
                let mut h = SVector::<f64, N>::zeros();
                h[o + i] = 1.0;
                if let Some(b) = st.gyro_bias() {
                    h[b + i] = 1.0;
                }
                rows[3 + i] = (
                    g[i] - predicted[i],
                    h,
                    t.gyro_sigma_rad_s * t.gyro_sigma_rad_s,
                );
                present[3 + i] = true;
            }
        }
        let mut vector = |base: usize,
                          z: Option<Vector3<f64>>,
                          reference: &Vector3<f64>,
                          bias: Option<usize>,
                          sigma: f64| {
            let Some(z) = z else { return };
            let model = self.q.inverse_transform_vector(reference);
            let predicted = model
                + if bias.is_some() {
                    self.mag_bias
                } else {
                    Vector3::zeros()
                };
            let h_att = skew(&model) * 2.0;
            for i in 0..3 {
                let mut h = SVector::<f64, N>::zeros();
                for k in 0..3 {
                    h[k] = h_att[(i, k)];
                }
                if let Some(b) = bias {
                    h[b + i] = 1.0;
                }
                rows[base + i] = (z[i] - predicted[i], h, sigma * sigma);
                present[base + i] = true;
            }
        };
        if s.mag {
            vector(
                6,
                m.mag_body_nt,
                &ob.mag_ref_orbit_nt,
                st.mag_bias(),
                t.mag_sigma_nt,
            );
        }
        if s.sun {
            vector(9, m.sun_body, &ob.sun_ref_orbit, None, t.sun_sigma_rad);
        }
        (rows, present)
    }

    fn update(&mut self, m: &Measurements, ob: &Onboard) {
        let (rows, present) = self.rows(m, ob);
        if !present.iter().any(|p| *p) {
            return;
        }
        self.check_geometry(&present, ob);
        // One reference vector and no star tracker: the turn about that vector is not seen.
        let (star, mag, sun) = (present[0], present[6], present[9]);
        self.unobservable_axis = if !star && (mag != sun) {
            let r = if mag {
                ob.mag_ref_orbit_nt
            } else {
                ob.sun_ref_orbit
            };
            self.q.inverse_transform_vector(&r).try_normalize(1e-12)
        } else {
            None
        };
        let mut err = KalmanState::new(SVector::<f64, N>::zeros(), self.p);
        let (mut nis, mut dof) = (0.0, 0.0);
        // §3.3: the gain is frozen at the first update after the freeze time in which every
        // sensor of the set delivered, so it holds a gain for each of the set's rows.
        let expected = self.expected_rows();
        let freeze = self.gains.is_none()
            && self
                .cfg
                .constant_gain_after_s
                .is_some_and(|t| self.t_s >= t)
            && expected.iter().zip(&present).all(|(e, p)| !e || *p);
        let mut new_gains = [None; MAX_ROWS];
        for (k, ((r, h, var), here)) in rows.iter().zip(present).enumerate() {
            if !here {
                continue;
            }
            let residual = r - h.dot(&err.x);
            if let Some(gains) = &self.gains {
                if let Some(g) = gains[k] {
                    err.x += g * residual;
                }
                continue;
            }
            let s = (h.transpose() * err.p * h)[(0, 0)] + var;
            let gain = err.p * h / s;
            if let Some(d) = &mut self.dist {
                let hd = self.dist_sens.transpose() * h;
                disturbance_update(d, residual, &hd, s * self.tuning.rd_scale);
                self.dist_sens -= gain * hd.transpose();
            }
            match err.update_scalar(residual, &h.transpose(), *var) {
                Ok(n) => {
                    nis += n;
                    dof += 1.0;
                    new_gains[k] = Some(gain);
                }
                Err(e) => {
                    self.status = EstimatorStatus::Diverged(format!(
                        "update refused: {e} (degenerate geometry?)"
                    ));
                    return;
                }
            }
        }
        if freeze {
            self.gains = Some(new_gains);
        }
        self.nis = [nis, dof];
        if self.gains.is_none() || freeze {
            self.p = err.p;
        }
        self.apply_correction(&err.x);
    }

    /// Two parallel reference vectors and no star tracker: the rotation about them is not
    /// observed this update (H is degenerate). Said, not hidden; cleared when it passes.
    fn check_geometry(&mut self, present: &[bool; MAX_ROWS], ob: &Onboard) {
        if matches!(self.status, EstimatorStatus::Diverged(_)) {
            return;
        }
        let (star, mag, sun) = (present[0], present[6], present[9]);
        let degenerate = !star && mag && sun && {
            let angle = ob.mag_ref_orbit_nt.angle(&ob.sun_ref_orbit).to_degrees();
            !(DEGENERATE_DEG..=180.0 - DEGENERATE_DEG).contains(&angle)
        };
        self.status = if degenerate {
            EstimatorStatus::Unobservable(format!(
                "sun and field within {DEGENERATE_DEG}°: the rotation about them is not observed"
            ))
        } else {
            EstimatorStatus::Ok
        };
    }

    /// The rows the filter's sensors give when all of them deliver.
    fn expected_rows(&self) -> [bool; MAX_ROWS] {
        let s = self.cfg.sensors;
        let gyro = s.gyro && self.cfg.states.omega().is_some();
        std::array::from_fn(|k| match k / 3 {
            0 => s.star,
            1 => gyro,
            2 => s.mag,
            _ => s.sun,
        })
    }

    fn apply_correction(&mut self, dx: &SVector<f64, N>) {
        let dl = Vector3::new(dx[0], dx[1], dx[2]);
        let w = (1.0 - dl.norm_squared()).max(0.0).sqrt();
        self.q = UnitQuaternion::new_normalize(
            self.q.into_inner() * nalgebra::Quaternion::from_parts(w, dl),
        );
        if let Some(o) = self.cfg.states.omega() {
            self.omega += Vector3::new(dx[o], dx[o + 1], dx[o + 2]);
        }
        if let Some(b) = self.cfg.states.gyro_bias() {
            self.gyro_bias += Vector3::new(dx[b], dx[b + 1], dx[b + 2]);
        }
        if let Some(b) = self.cfg.states.mag_bias() {
            self.mag_bias += Vector3::new(dx[b], dx[b + 1], dx[b + 2]);
        }
    }

    /// P with the attitude block as rotation angle (2δλ), what the loop and the plots read.
    fn publish(&mut self) {
        let mut t = SVector::<f64, N>::repeat(1.0);
        for i in 0..3 {
            t[i] = 2.0;
        }
        self.published = SMatrix::<f64, N, N>::from_fn(|i, j| self.p[(i, j)] * t[i] * t[j]);
    }
}

/// One scalar row of the disturbance filter: `residual` is the row's innovation (the
/// model already carries d̂, so its expected value is H_d (d − d̂)) and `hd` = H·S its
/// sensitivity to an error in d̂.
fn disturbance_update(d: &mut Disturbance, residual: f64, hd: &Vector3<f64>, r_d: f64) {
    let s = hd.dot(&(d.p * hd)) + r_d;
    if s <= 0.0 || !s.is_finite() {
        return;
    }
    let k = d.p * hd / s;
    d.d += k * residual;
    d.p = symmetrize(&((Matrix3::identity() - k * hd.transpose()) * d.p));
}

impl<const N: usize> Estimator for Mekf<N> {
    fn id(&self) -> &'static str {
        self.cfg.id
    }

    fn label(&self) -> &'static str {
        self.cfg.label
    }

    fn unobservable_axis_body(&self) -> Option<Vector3<f64>> {
        self.unobservable_axis
    }

    fn apply_params(&mut self, params: &ParamValues) {
        if let Some((f, q)) = self.retune {
            self.tuning = f(params, q);
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        if matches!(self.status, EstimatorStatus::Diverged(_)) {
            return;
        }
        let Some(ob) = m.onboard else { return };
        if let Some(g) = m.gyro_body_rad_s {
            self.last_gyro = Some(g);
        }
        self.t_s += dt_s;
        self.predict(&ob, dt_s);
        if let Some(d) = &mut self.dist {
            d.p /= self.tuning.alpha.clamp(1e-3, 1.0).powf(dt_s);
            // Fading without information (a sensor out) would grow P_d without bound.
            let peak = d.p.diagonal().max();
            if peak > DIST_P_MAX {
                d.p *= DIST_P_MAX / peak;
            }
        }
        self.update(m, &ob);
        self.publish();
        let finite = self
            .q
            .coords
            .iter()
            .chain(self.omega.iter())
            .chain(self.p.iter())
            .all(|v| v.is_finite());
        let att_sigma = 2.0
            * (0..3)
                .map(|i| self.p[(i, i)])
                .fold(0.0_f64, f64::max)
                .sqrt();
        if !finite {
            self.status = EstimatorStatus::Diverged("state or covariance is not finite".into());
        } else if !positive_semidefinite(&self.p) {
            self.status = EstimatorStatus::Diverged(
                "the covariance lost positive definiteness: R is too small beside P for double precision".into(),
            );
        } else if att_sigma > LOST_RAD {
            self.status = EstimatorStatus::Diverged(format!(
                "attitude σ {:.0}° (over {:.0}°): the filter has lost the attitude",
                att_sigma.to_degrees(),
                LOST_RAD.to_degrees()
            ));
        }
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            attitude: Attitude::Quaternion(self.q),
            rate_body_rad_s: Some(self.rate()),
            angle_rad: None,
        }
    }

    fn status(&self) -> &EstimatorStatus {
        &self.status
    }

    fn covariance_states(&self) -> &'static [StateInfo] {
        states_of(self.cfg.states)
    }

    fn covariance(&self) -> Option<Covariance<'_>> {
        Some(Covariance {
            states: states_of(self.cfg.states),
            matrix: self.published.as_slice(),
        })
    }

    fn extra_names(&self) -> &'static [&'static str] {
        const NIS: [&str; 2] = ["nis", "nis_dof"];
        const GB: [&str; 5] = [
            "nis",
            "nis_dof",
            "gbias_x_deg_s",
            "gbias_y_deg_s",
            "gbias_z_deg_s",
        ];
        const MB: [&str; 5] = ["nis", "nis_dof", "mbias_x_nt", "mbias_y_nt", "mbias_z_nt"];
        const D: [&str; 5] = ["nis", "nis_dof", "d_x_s2", "d_y_s2", "d_z_s2"];
        const GB_D: [&str; 8] = [
            "nis",
            "nis_dof",
            "gbias_x_deg_s",
            "gbias_y_deg_s",
            "gbias_z_deg_s",
            "d_x_s2",
            "d_y_s2",
            "d_z_s2",
        ];
        const MB_D: [&str; 8] = [
            "nis",
            "nis_dof",
            "mbias_x_nt",
            "mbias_y_nt",
            "mbias_z_nt",
            "d_x_s2",
            "d_y_s2",
            "d_z_s2",
        ];
        let st = self.cfg.states;
        match (
            st.gyro_bias().is_some(),
            st.mag_bias().is_some(),
            self.dist.is_some(),
        ) {
            (true, _, false) => &GB,
            (_, true, false) => &MB,
            (true, _, true) => &GB_D,
            (_, true, true) => &MB_D,
            (false, false, true) => &D,
            (false, false, false) => &NIS,
        }
    }

    fn extras(&self, out: &mut [f64]) {
        out[0] = self.nis[0];
        out[1] = self.nis[1];
        let mut k = 2;
        let mut put = |v: Vector3<f64>| {
            out[k..k + 3].copy_from_slice(v.as_slice());
            k += 3;
        };
        if self.cfg.states.gyro_bias().is_some() {
            put(self.gyro_bias.map(f64::to_degrees));
        }
        if self.cfg.states.mag_bias().is_some() {
            put(self.mag_bias);
        }
        if let Some(d) = self.dist {
            put(d.d);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn onboard() -> Onboard {
        Onboard {
            frame_rate_orbit_rad_s: Vector3::new(0.0, 1.08e-3, 0.0),
            gravity_gradient_coeff: 3.0 * 1.17e-6,
            mag_ref_orbit_nt: Vector3::new(2e4, -5e3, 3e4),
            sun_ref_orbit: Vector3::new(0.3, 0.4, 0.866).normalize(),
            wheel_momentum_body: Vector3::new(1e-3, -2e-3, 5e-4),
            wheel_torque_body: Vector3::new(1e-6, 0.0, -2e-6),
        }
    }

    fn filter() -> Mekf<6> {
        let cfg = MekfConfig {
            id: "t",
            label: "t",
            sensors: SensorSet {
                star: true,
                gyro: true,
                mag: false,
                sun: false,
            },
            states: StateSet::AttRate,
            disturbance: false,
            constant_gain_after_s: None,
        };
        let tuning = MekfTuning {
            q_att: 1e-6,
            q_rate: 1e-6,
            q_bias: 0.0,
            star_sigma: 1e-5,
            gyro_sigma_rad_s: 1e-4,
            mag_sigma_nt: 250.0,
            sun_sigma_rad: 1e-3,
            alpha: 1.0,
            rd_scale: 1.0,
        };
        let q = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
        Mekf::new(
            cfg,
            tuning,
            q,
            Vector3::new(0.01, -0.02, 0.015),
            SMatrix::identity() * 1e-6,
        )
    }

    /// The error state after propagating a perturbed and the nominal estimate for `dt`.
    fn error_after(f: &Mekf<6>, dx: &SVector<f64, 6>, dt: f64, ob: &Onboard) -> SVector<f64, 6> {
        let mut a = f.clone();
        let mut b = f.clone();
        b.apply_correction(dx);
        a.predict(ob, dt);
        b.predict(ob, dt);
        let mut dq = (a.q.inverse() * b.q).into_inner();
        if dq.w < 0.0 {
            dq = -dq;
        }
        let dw = b.omega - a.omega;
        SVector::<f64, 6>::from_iterator(dq.imag().iter().chain(dw.iter()).copied())
    }

    #[test]
    fn the_jacobian_matches_finite_differences_of_the_propagation() {
        let f = filter();
        let ob = onboard();
        let dt = 0.1;
        let jac = f.jacobian(&f.omega, &ob);
        for k in 0..6 {
            let mut dx = SVector::<f64, 6>::zeros();
            let h = if k < 3 { 1e-6 } else { 1e-7 };
            dx[k] = h;
            let numeric =
                (error_after(&f, &dx, dt, &ob) - error_after(&f, &(-dx), dt, &ob)) / (2.0 * h);
            // The exact Φ = exp(F dt) to second order; the filter's I + F dt drops the
            // (F dt)²/2 term (≈ 3e-5 here), which this test keeps so it checks F itself.
            let fdt = jac * dt;
            let analytic = (SMatrix::<f64, 6, 6>::identity() + fdt + fdt * fdt / 2.0)
                .column(k)
                .into_owned();
            let diff = (numeric - analytic).amax();
            assert!(
                diff < 2e-6,
                "column {k}: numeric {numeric} vs exp(F dt) {analytic}"
            );
        }
    }

    #[test]
    fn a_degenerate_geometry_is_said_not_hidden() {
        let mut f = filter();
        f.cfg.sensors = SensorSet {
            star: false,
            gyro: false,
            mag: true,
            sun: true,
        };
        let mut ob = onboard();
        ob.sun_ref_orbit = ob.mag_ref_orbit_nt.normalize();
        let m = Measurements {
            mag_body_nt: Some(f.q.inverse_transform_vector(&ob.mag_ref_orbit_nt)),
            sun_body: Some(f.q.inverse_transform_vector(&ob.sun_ref_orbit)),
            onboard: Some(ob),
            ..Measurements::default()
        };
        f.step(&m, 0.1);
        assert!(
            matches!(f.status(), EstimatorStatus::Unobservable(_)),
            "{:?}",
            f.status()
        );
        assert!(f.estimate().is_finite());
    }
}
