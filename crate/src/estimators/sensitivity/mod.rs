//! Paper 5 (Bashniakov, Pichkur, Polishchuk, Linder): correcting measured angular rates from
//! reference attitudes with the sensitivity matrix.
//!
//! The measured rate ω drives the quaternion kinematics with an additive correction p,
//! 2Λ̇ = Λ ∘ (ω + p) (§2). Alongside, the sensitivity U = ∂Λ/∂p (4×3) obeys the same operator
//! plus a forcing: 2U̇ⱼ = Uⱼ ∘ (ω + p) + Λ ∘ eⱼ, with U = 0 at the start of every interval.
//! At each reference attitude Λ_ref (every Δt) the correction takes one Gauss–Newton step,
//! h = (UᵀQU + εI)⁻¹ UᵀQ (Λ_ref − Λ):
//!
//! * [`Method::Plain`] — method (9): p ← p + h with ε = 0; the state is continued, not reset.
//! * [`Method::Regularised`] — method (10): the same with ε > 0 (Levenberg–Marquardt).
//! * [`Method::StepSearch`] — method (11): p ← p + s·h with s minimising the misfit of the
//!   last interval re-integrated with p + s·h (golden section on 0 ≤ s ≤ 2). Each trial
//!   re-integrates the interval, and the run continues from the chosen trial's end state.
//! * [`Method::Reintegrate`] — beyond the paper: method (9)'s step (ε = 0), then the last
//!   interval is re-integrated with the new p and the run continues from there.
//! * [`Method::Uncorrected`] — the measured rate integrated as it is, for comparison.
//!
//! Linearised (§4 of the digest), with e the orientation error and q = pΔt, method (9/10)
//! is eₖ₊₁ = eₖ + qₖ, qₖ₊₁ = qₖ − k·eₖ₊₁ with k = (Δt²/4)/(Δt²/4 + ε): determinant 1, both
//! eigenvalues on the unit circle — it oscillates (period 6 intervals at ε = 0) and never
//! settles. Re-integrating makes it eₖ₊₁ = (1 − k)(eₖ + qₖ): at ε = 0 a dead-beat update.

use crate::math::{ExplicitRk, RK4, sequence_from_quaternion, symmetrize, wrap_pi};
use crate::model::{
    Attitude, Estimate, Estimator, EstimatorStatus, Extras, Measurements, ParamValues, Quantity,
    Trouble, Tuner,
};
use nalgebra::{
    Complex, Matrix2, Matrix3, Matrix4, Quaternion, SMatrix, UnitQuaternion, Vector3, Vector4,
};

pub use series::*;

mod series;

/// The update rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Method (9).
    Plain,
    /// Method (10).
    Regularised,
    /// Method (11).
    StepSearch,
    /// Re-integrate the last interval with the new p (beyond the paper).
    Reintegrate,
    /// No correction.
    Uncorrected,
}

/// The eigenvalues of the linearised update of `method` for interval `dt_s` and
/// regularisation `eps` (in the (e, q) variables of the module documentation).
///
/// ```
/// # use attlab::estimators::{Method, linearised_eigenvalues};
/// let [a, b] = linearised_eigenvalues(Method::Plain, 1.0, 0.0);
/// assert!((a.norm() - 1.0).abs() < 1e-12 && (b.norm() - 1.0).abs() < 1e-12);
/// let [a, b] = linearised_eigenvalues(Method::Reintegrate, 1.0, 0.0);
/// assert!(a.norm() < 1e-12 && b.norm() < 1e-12);
/// ```
pub fn linearised_eigenvalues(method: Method, dt_s: f64, eps: f64) -> [Complex<f64>; 2] {
    let a = dt_s * dt_s / 4.0;
    let eps = if matches!(method, Method::Plain | Method::Reintegrate) {
        0.0
    } else {
        eps
    };
    let k = a / (a + eps);
    let m = match method {
        // (e, q) → (e + q, q − k(e + q)).
        Method::Plain | Method::Regularised => Matrix2::new(1.0, 1.0, -k, 1.0 - k),
        // The new q is applied to the same interval again: e ← (1 − k)(e + q), q ← q − k(e + q).
        // Method (11) re-integrates too; linearised, its best s makes it the same update.
        Method::Reintegrate | Method::StepSearch => Matrix2::new(1.0 - k, 1.0 - k, -k, 1.0 - k),
        Method::Uncorrected => Matrix2::identity(),
    };
    let (tr, det) = (m.trace(), m.determinant());
    let disc = Complex::new(tr * tr / 4.0 - det, 0.0).sqrt();
    [
        Complex::new(tr / 2.0, 0.0) + disc,
        Complex::new(tr / 2.0, 0.0) - disc,
    ]
}

/// Settings of one corrector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensitivitySettings {
    /// ε of method (10), (11) and the re-integrating variant.
    pub eps: f64,
    /// Diagonal of the weight Q (4).
    pub weights: [f64; 4],
    /// Renormalise Λ after each step.
    pub renormalise: bool,
    /// The angle sequence of the output (see [`crate::math::ANGLE_SEQUENCES`]).
    pub axes: [usize; 3],
    /// Tolerance per angle (rad) of "within tolerance of the reference".
    pub tolerance_rad: f64,
    /// How (Λ, U) are integrated between samples (the paper makes it a setting).
    pub integrator: &'static ExplicitRk,
    /// The most steps between two references kept for the re-integration, reserved up
    /// front; a longer gap restarts the interval at the free-running estimate (so the
    /// memory is fixed when the run starts, not grown during a dropout).
    pub history_steps: usize,
}

/// What the last update found.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UpdateInfo {
    /// Singular values of UᵀQU, largest first.
    pub singular_values: [f64; 3],
    /// Their ratio, the condition number.
    pub condition: f64,
    /// Step size s used.
    pub step: f64,
}

/// Integrates (Λ, U) over `dt` with the rate `w` held constant, by `method`. The pair is
/// one 4×4 state: Λ in the first column, U in the other three.
fn integrate(
    method: &ExplicitRk,
    q: &Quaternion<f64>,
    u: &SMatrix<f64, 4, 3>,
    w: &Vector3<f64>,
    dt: f64,
) -> (Quaternion<f64>, SMatrix<f64, 4, 3>) {
    let wq = Quaternion::from_imag(*w);
    let mut x = Matrix4::zeros();
    x.set_column(0, &as_vec(q));
    x.fixed_view_mut::<4, 3>(0, 1).copy_from(u);
    let f = |x: &Matrix4<f64>| {
        let column = |j: usize| Quaternion::new(x[(0, j)], x[(1, j)], x[(2, j)], x[(3, j)]);
        let q = column(0);
        let mut d = Matrix4::zeros();
        d.set_column(0, &as_vec(&(q * wq * 0.5)));
        for j in 0..3 {
            let mut e = Vector3::zeros();
            e[j] = 1.0;
            let dj = column(j + 1) * wq * 0.5 + q * Quaternion::from_imag(e) * 0.5;
            d.set_column(j + 1, &as_vec(&dj));
        }
        d
    };
    let x = method.step(&x, dt, f);
    (
        Quaternion::new(x[(0, 0)], x[(1, 0)], x[(2, 0)], x[(3, 0)]),
        x.fixed_view::<4, 3>(0, 1).into_owned(),
    )
}

fn as_vec(q: &Quaternion<f64>) -> Vector4<f64> {
    Vector4::new(q.w, q.i, q.j, q.k)
}

/// One rate corrector of paper 5.
#[derive(Clone, Debug)]
pub struct SensitivityCorrection {
    id: &'static str,
    label: &'static str,
    method: Method,
    settings: SensitivitySettings,
    tuner: Option<Tuner<SensitivitySettings>>,
    q: Quaternion<f64>,
    u: SMatrix<f64, 4, 3>,
    p: Vector3<f64>,
    last_rate: Vector3<f64>,
    /// Λ at the start of the interval and the (rate, step) history since, to re-integrate.
    start: Quaternion<f64>,
    history: Vec<(Vector3<f64>, f64)>,
    info: UpdateInfo,
    updates: u64,
    last_reference: Option<UnitQuaternion<f64>>,
    status: EstimatorStatus,
}

impl SensitivityCorrection {
    /// A corrector using `method`, starting at `q0` with correction `p0`.
    pub fn new(
        id: &'static str,
        label: &'static str,
        method: Method,
        q0: UnitQuaternion<f64>,
        p0: Vector3<f64>,
        settings: SensitivitySettings,
    ) -> Self {
        Self {
            id,
            label,
            method,
            settings,
            tuner: None,
            q: q0.into_inner(),
            u: SMatrix::zeros(),
            p: if method == Method::Uncorrected {
                Vector3::zeros()
            } else {
                p0
            },
            last_rate: Vector3::zeros(),
            start: q0.into_inner(),
            history: Vec::with_capacity(settings.history_steps),
            info: UpdateInfo::default(),
            updates: 0,
            last_reference: None,
            status: EstimatorStatus::Ok,
        }
    }

    /// Re-tunes ε, Q, the tolerance and the renormalisation from the lab's parameters on
    /// every change.
    #[must_use]
    pub fn tuned_by(mut self, tuner: Tuner<SensitivitySettings>) -> Self {
        self.tuner = Some(tuner);
        self
    }

    /// The correction p (rad/s).
    pub fn correction(&self) -> Vector3<f64> {
        self.p
    }

    /// The sensitivity U = ∂Λ/∂p accumulated since the last reference.
    pub fn sensitivity(&self) -> &SMatrix<f64, 4, 3> {
        &self.u
    }

    /// The quaternion Λ (not normalised unless the setting says so).
    pub fn quaternion(&self) -> Quaternion<f64> {
        self.q
    }

    /// What the last update found.
    pub fn last_update(&self) -> UpdateInfo {
        self.info
    }

    /// Λ at the end of the last interval when re-integrated from its start with `p`.
    fn reintegrated(&self, p: &Vector3<f64>) -> Quaternion<f64> {
        let mut q = self.start;
        let u = SMatrix::<f64, 4, 3>::zeros();
        for (w, dt) in &self.history {
            q = integrate(self.settings.integrator, &q, &u, &(w + p), *dt).0;
            if self.settings.renormalise {
                q = q.normalize();
            }
        }
        q
    }

    fn misfit(&self, q: &Quaternion<f64>, target: &Vector4<f64>) -> f64 {
        let d = target - as_vec(q);
        (0..4).map(|i| self.settings.weights[i] * d[i] * d[i]).sum()
    }

    /// One reference attitude: the Gauss–Newton step of the method.
    fn update(&mut self, reference: &UnitQuaternion<f64>) {
        let mut target = as_vec(reference.quaternion());
        // Λ and −Λ are one attitude: aim at the one nearer the estimate.
        if target.dot(&as_vec(&self.q)) < 0.0 {
            target = -target;
        }
        let w = Matrix4::from_diagonal(&Vector4::from(self.settings.weights));
        let a = symmetrize(&(self.u.transpose() * w * self.u));
        let b = self.u.transpose() * w * (target - as_vec(&self.q));
        let eps = if matches!(self.method, Method::Plain | Method::Reintegrate) {
            0.0
        } else {
            self.settings.eps
        };
        let sv = a.symmetric_eigenvalues();
        let mut sv = [sv[0].abs(), sv[1].abs(), sv[2].abs()];
        sv.sort_by(|x, y| y.total_cmp(x));
        let condition = if sv[2] > 0.0 {
            sv[0] / sv[2]
        } else {
            f64::INFINITY
        };
        let Some(h) = (a + Matrix3::identity() * eps).lu().solve(&b) else {
            self.status = EstimatorStatus::Unobservable(Trouble::SingularSensitivity);
            self.info = UpdateInfo {
                singular_values: sv,
                condition,
                step: 0.0,
            };
            return;
        };
        self.status = EstimatorStatus::Ok;
        let step = match self.method {
            Method::StepSearch => golden_section(
                |s| self.misfit(&self.reintegrated(&(self.p + h * s)), &target),
                0.0,
                2.0,
            ),
            _ => 1.0,
        };
        self.p += h * step;
        if matches!(self.method, Method::Reintegrate | Method::StepSearch) {
            self.q = self.reintegrated(&self.p);
        }
        self.info = UpdateInfo {
            singular_values: sv,
            condition,
            step,
        };
        self.updates += 1;
    }

    fn restart_interval(&mut self) {
        self.u = SMatrix::zeros();
        self.start = self.q;
        self.history.clear();
    }
}

/// The minimiser of `f` on [lo, hi] by golden-section search (40 iterations: 1e-8 of the
/// bracket).
fn golden_section(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (lo, hi);
    let (mut c, mut d) = (b - g * (b - a), a + g * (b - a));
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..40 {
        if fc < fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    (a + b) / 2.0
}

impl Estimator for SensitivityCorrection {
    fn heap_bytes(&self) -> usize {
        // A clone holds the history's samples (its capacity is their number).
        self.history.len() * std::mem::size_of::<(Vector3<f64>, f64)>()
    }

    fn id(&self) -> &'static str {
        self.id
    }

    fn label(&self) -> &'static str {
        self.label
    }

    fn apply_params(&mut self, p: &ParamValues) {
        if let Some(f) = self.tuner {
            self.settings = f(p);
            let wanted = self.settings.history_steps;
            self.history
                .reserve_exact(wanted.saturating_sub(self.history.len()));
        }
    }

    fn step(&mut self, m: &Measurements, dt_s: f64) {
        // Diverged: frozen, as flagged. Stepping on would only grow the re-integration
        // history, which no reference clears any more (it leaked ~3 kB per simulated second).
        if matches!(self.status, EstimatorStatus::Diverged(_)) {
            return;
        }
        if let Some(w) = m.gyro_body_rad_s {
            self.last_rate = w;
        }
        let (q, u) = integrate(
            self.settings.integrator,
            &self.q,
            &self.u,
            &(self.last_rate + self.p),
            dt_s,
        );
        self.q = if self.settings.renormalise {
            q.normalize()
        } else {
            q
        };
        self.u = u;
        if self.history.len() >= self.settings.history_steps {
            self.restart_interval();
        }
        self.history.push((self.last_rate, dt_s));
        if !(self
            .q
            .coords
            .iter()
            .chain(self.u.iter())
            .chain(self.p.iter())
            .all(|v| v.is_finite()))
        {
            self.status = EstimatorStatus::Diverged(Trouble::SensitivityNotFinite);
            return;
        }
        if let Some(reference) = m.star_q_ref_from_body {
            if self.method != Method::Uncorrected {
                self.update(&reference);
            }
            self.last_reference = Some(reference);
            self.restart_interval();
        }
    }

    fn estimate(&self) -> Estimate {
        Estimate {
            attitude: Attitude::Quaternion(UnitQuaternion::new_normalize(self.q)),
            rate_body_rad_s: Some(self.last_rate + self.p),
            angle_rad: None,
        }
    }

    fn status(&self) -> &EstimatorStatus {
        &self.status
    }

    fn extra_quantities(&self) -> &'static [Quantity] {
        const QUANTITIES: &[Quantity] = &[
            P_X_DEG_S,
            P_Y_DEG_S,
            P_Z_DEG_S,
            ANGLE_1_RAD,
            ANGLE_2_RAD,
            ANGLE_3_RAD,
            WITHIN_TOL,
            COND_UTQU,
            SV1,
            SV2,
            SV3,
            STEP_S,
            NORM_LAMBDA,
        ];
        QUANTITIES
    }

    fn extras(&self, out: &mut Extras<'_>) {
        let axes = self.settings.axes;
        let k = sequence_from_quaternion(axes, &UnitQuaternion::new_normalize(self.q));
        // Within tolerance of the last reference on every angle (the paper's stop rule).
        let within = self.last_reference.is_some_and(|r| {
            let kr = sequence_from_quaternion(axes, &r);
            k.iter()
                .zip(kr)
                .all(|(a, b)| wrap_pi(a - b).abs() <= self.settings.tolerance_rad)
        });
        let i = self.info;
        out.put_all(
            [&P_X_DEG_S, &P_Y_DEG_S, &P_Z_DEG_S],
            self.p.iter().map(|v| v.to_degrees()),
        );
        out.put_all([&ANGLE_1_RAD, &ANGLE_2_RAD, &ANGLE_3_RAD], k);
        out.put(&WITHIN_TOL, f64::from(u8::from(within)));
        out.put(&COND_UTQU, i.condition);
        out.put_all([&SV1, &SV2, &SV3], i.singular_values);
        out.put(&STEP_S, i.step);
        out.put(&NORM_LAMBDA, self.q.norm());
    }
}

/// The largest difference between U integrated by the sensitivity equations over 1.2 s of
/// a varying rate and central finite differences (h = 1e-6) of the integrated Λ: an
/// independent check of the equations (NaN propagates).
pub fn sensitivity_finite_difference_check() -> f64 {
    let q0 = UnitQuaternion::from_euler_angles(0.5, 0.7, 0.2).into_inner();
    let rate = |k: usize| Vector3::new(0.1 * (k as f64 * 0.01).sin(), -0.05, 0.2);
    let p = Vector3::new(0.01, -0.02, 0.03);
    let run = |p: &Vector3<f64>| {
        let (mut q, mut u) = (q0, SMatrix::<f64, 4, 3>::zeros());
        for k in 0..120 {
            (q, u) = integrate(&RK4, &q, &u, &(rate(k) + p), 0.01);
        }
        (q, u)
    };
    let (_, u) = run(&p);
    let h = 1e-6;
    let mut worst = 0.0_f64;
    for j in 0..3 {
        let mut dp = Vector3::zeros();
        dp[j] = h;
        let fd = (as_vec(&run(&(p + dp)).0) - as_vec(&run(&(p - dp)).0)) / (2.0 * h);
        let d = (fd - u.column(j)).amax();
        worst = if d.is_nan() || worst.is_nan() {
            f64::NAN
        } else {
            worst.max(d)
        };
    }
    worst
}

#[cfg(test)]
mod tests;
