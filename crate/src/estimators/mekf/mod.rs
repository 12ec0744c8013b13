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
//!   F_g = \[η×\]J\[η×\] − \[(Jη)×\]\[η×\] (the paper's gravity-gradient block).
//! * Measurements (Table 2's H): star tracker δλ = vec(q̂⁻¹ ⊗ q_st) with H = [E 0];
//!   gyro ω̃ = ω + Δω with H = [0 E (E)]; magnetometer b = A b₀ (+ Δb) with
//!   H = [2[b̂×] 0 (E)], or with Fig. 7's bias, a small turn δ of the field, b = A b₀ + δ × A b₀
//!   with H = [2[b̂×] 0 −[b̂×]]; sun sensor s = A s₀ with H = [2[ŝ×] 0]. The 2 makes δλ
//!   half-angle consistent. Rows are processed one scalar at a time (diagonal R), so any set is the
//!   same code and the step has no heap.
//! * Q = diag(q_Λ²·E, q_ω²·E, q_bias²·E) per prediction step, the paper's tuning knobs.

use super::kf::KalmanState;
use crate::math::{all_finite, pattern_mul, propagate_first_order, symmetrize};
use crate::model::{
    Attitude, Covariance, Estimate, Estimator, EstimatorStatus, Extras, Measurements, ParamValues,
    Quantity, StateInfo, Trouble,
};
use nalgebra::{Matrix3, SMatrix, SVector, UnitQuaternion, Vector3};
pub use onboard::Onboard;
use states::states_of;
pub use states::{
    ATT_X, ATT_Y, ATT_Z, GBIAS_X, GBIAS_Y, GBIAS_Z, MBIAS_X, MBIAS_Y, MBIAS_Z, RATE_X, RATE_Y,
    RATE_Z,
};

pub use series::{
    D_X_S2, D_Y_S2, D_Z_S2, GBIAS_X_DEG_S, GBIAS_Y_DEG_S, GBIAS_Z_DEG_S, MBIAS_X_NT, MBIAS_Y_NT,
    MBIAS_Z_NT, MTURN_X_DEG, MTURN_Y_DEG, MTURN_Z_DEG, NIS, NIS_DOF,
};

mod onboard;
mod predict;
mod series;
mod states;
#[cfg(test)]
mod tests;
mod update;

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

impl SensorSet {
    /// All four: star tracker, gyro, magnetometer and sun sensors.
    pub const ALL: Self = Self {
        star: true,
        gyro: true,
        mag: true,
        sun: true,
    };
}

/// What the state holds (Table 2's x).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StateSet {
    /// [λ, ω].
    AttRate,
    /// [λ, ω, Δω]: gyro bias.
    AttRateGyroBias,
    /// [λ, ω, Δb]: magnetometer bias (nT, added to the reading).
    AttRateMagBias,
    /// [λ, ω, Δb]: magnetometer bias as a small turn of the field (rad; Fig. 7's model).
    AttRateMagTurn,
    /// [λ, Δω]: the reduced variant — ω is the gyro reading less the bias, no dynamics.
    AttGyroBias,
}

impl StateSet {
    /// Number of states.
    pub const fn dim(self) -> usize {
        match self {
            Self::AttRate | Self::AttGyroBias => 6,
            Self::AttRateGyroBias | Self::AttRateMagBias | Self::AttRateMagTurn => 9,
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
        matches!(self, Self::AttRateMagBias | Self::AttRateMagTurn).then_some(6)
    }

    /// Whether the magnetometer bias is a turn of the field rather than an added vector.
    fn mag_turn(self) -> bool {
        self == Self::AttRateMagTurn
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
    /// Freezes the gain at [`MekfTuning::freeze_after_s`] and stops propagating P (§3.3).
    pub constant_gain: bool,
    /// The body's inertia tensor J in body axes (kg·m²), of the dynamics model (eqs. 6–7).
    pub inertia_kg_m2: Matrix3<f64>,
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
    /// When a constant-gain filter freezes its gain (s; the first update after it in which
    /// every sensor of its set delivered).
    pub freeze_after_s: f64,
}

/// One update's scalar rows: (residual at the prior, H row, R), at most [`MAX_ROWS`].
type Rows<const N: usize> = [(f64, SVector<f64, N>, f64); MAX_ROWS];

/// How a lab turns its parameters and a filter's base (q_Λ, q_ω, q_bias) into a tuning.
pub type Retune = fn(&ParamValues, [f64; 3]) -> MekfTuning;

/// Floating-point operations of one [`Mekf`] step with `n` states that processes `rows`
/// scalar measurement rows whose H rows hold `h_nonzeros` non-zero entries in all, with a
/// Jacobian F whose non-zero entries are at `f` (row, column); counted from the code (a multiply-add is
/// two; a square root or division one):
/// * prediction — RK4 of (q, ω) ≈ 840, the Jacobian ≈ 295 (its four products with a
///   `[v×]` skip their zero terms), Φ P Φᵀ by [`propagate_first_order`] (F P 2n per entry
///   of F's pattern `f`, F (F P)ᵀ on the upper triangle 2(n − i) per entry in row i, the
///   sum 5n(n + 1)/2), the diagonal Q n;
/// * each scalar row — the residual at the corrected prior 2n, v = P h 2n per non-zero of
///   h, s 2 per non-zero, k n, x 2n, the expanded Joseph form of [`crate::math::joseph_update_scalar`]
///   3n(n + 1) + n, the NIS 2: 3n² + 9n + 2 + (2n + 2) per non-zero of h;
/// * assembling the rows ≈ 200, folding the correction ≈ 55, publishing P 2n², the
///   positive-definiteness check (scaling 3n² + 2n, Cholesky ≈ n³/3).
pub const fn full_step_flops(n: u64, rows: u64, h_nonzeros: u64, f: &[(usize, usize)]) -> u64 {
    let mut fpf = 0;
    let mut e = 0;
    while e < f.len() {
        fpf += 2 * (n - f[e].0 as u64);
        e += 1;
    }
    let predict = 1135 + 2 * n * f.len() as u64 + fpf + 5 * n * (n + 1) / 2 + n;
    let updates = rows * (3 * n * n + 9 * n + 2) + (2 * n + 2) * h_nonzeros;
    let tail = 200 + 55 + 2 * n * n + 3 * n * n + 2 * n + n * n * n / 3;
    predict + updates + tail
}

/// F's structurally non-zero entries, row by row (see [`propagate_first_order`]): in the
/// attitude rows −[ω×] off its diagonal and ½E on ω (the reduced variant: −½E on the gyro
/// bias, which sits in the same columns 3–5); with ω a state, the rate rows' gravity-gradient
/// and gyroscopic blocks, dense over columns 0–5. The bias columns 6–8 are zero when ω is a
/// state; a bias row is always zero.
const F_NONZEROS: [(usize, usize); 27] = {
    let mut out = [(0, 0); 27];
    let mut n = 0;
    let mut i = 0;
    while i < 3 {
        let mut k = 0;
        while k < 3 {
            if k != i {
                out[n] = (i, k);
                n += 1;
            }
            k += 1;
        }
        out[n] = (i, 3 + i);
        n += 1;
        i += 1;
    }
    while i < 6 {
        let mut k = 0;
        while k < 6 {
            out[n] = (i, k);
            n += 1;
            k += 1;
        }
        i += 1;
    }
    out
};

/// F's pattern for [λ, ω, Δω], the full filter of [`full_step_flops`].
pub const FULL_F: &[(usize, usize)] = &F_NONZEROS;

/// How many of [`F_NONZEROS`] are in the attitude rows: the whole F of the reduced variant.
const F_ATT_NONZEROS: usize = 9;

/// Non-zero entries of F for [λ, ω, Δω] (the bias columns are zero when ω is a state):
/// −[ω×] 6, ½E 3, the gravity-gradient block 9 and the gyroscopic block 9.
pub const FULL_F_NONZEROS: u64 = F_NONZEROS.len() as u64;

/// Non-zero entries of the twelve H rows of a filter with all four sensors and a gyro bias:
/// star 1 a row, gyro 2 (ω and its bias), magnetometer and sun 2 (a row of [m×] is zero on
/// the diagonal).
pub const FULL_H_NONZEROS: u64 = 21;

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
        let j = cfg.inertia_kg_m2;
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
        let Some(&ob) = m.lab.get::<Onboard>() else {
            return;
        };
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
        let updated = self.update(m, &ob);
        self.publish();
        let finite = all_finite(self.q.coords.as_slice())
            && all_finite(self.omega.as_slice())
            && all_finite(self.p.as_slice());
        // Only an update can cost P its definiteness: a prediction adds Φ P Φᵀ and a
        // diagonal Q ≥ 0 to a P that passed, and a frozen gain leaves P as it is. (Nine steps
        // in ten are predictions; the check is a Cholesky factor.)
        let att_sigma = 2.0
            * (0..3)
                .map(|i| self.p[(i, i)])
                .fold(0.0_f64, f64::max)
                .sqrt();
        if !finite {
            self.status = EstimatorStatus::Diverged(Trouble::NotFinite);
        } else if updated && !positive_semidefinite(&self.p) {
            self.status = EstimatorStatus::Diverged(Trouble::LostDefiniteness);
        } else if att_sigma > LOST_RAD {
            self.status = EstimatorStatus::Diverged(Trouble::AttitudeLost {
                sigma_deg: att_sigma.to_degrees(),
                limit_deg: LOST_RAD.to_degrees(),
            });
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

    fn extra_quantities(&self) -> &'static [Quantity] {
        series::extra_quantities(self.cfg.states, self.dist.is_some())
    }

    fn extras(&self, out: &mut Extras<'_>) {
        self.put_extras(out);
    }
}
