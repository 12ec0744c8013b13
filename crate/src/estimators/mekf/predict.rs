//! The prediction of [`Mekf`]: the dynamics of eqs. 6–7 integrated by RK4 and the
//! covariance propagated through their Jacobian.

use super::*;

impl<const N: usize> Mekf<N> {
    /// The body rate used now: the state, or the gyro less the bias (reduced variant).
    pub(super) fn rate(&self) -> Vector3<f64> {
        match self.cfg.states.omega() {
            Some(_) => self.omega,
            None => self.last_gyro.map_or(self.omega, |g| g - self.gyro_bias),
        }
    }

    /// q̇ and ω̇ of the model at (q, ω); ω̇ is zero when `with_rate` is false (the reduced
    /// variant holds ω at the gyro reading, so its dynamics are not evaluated).
    pub(super) fn derivative(
        &self,
        q: &UnitQuaternion<f64>,
        omega: &Vector3<f64>,
        ob: &Onboard,
        with_rate: bool,
    ) -> (nalgebra::Quaternion<f64>, Vector3<f64>) {
        let w_rel = omega - q.inverse_transform_vector(&ob.frame_rate_orbit_rad_s);
        let q_dot = q.into_inner() * nalgebra::Quaternion::from_imag(w_rel) * 0.5;
        if !with_rate {
            return (q_dot, Vector3::zeros());
        }
        let eta = q.inverse_transform_vector(&Vector3::z());
        let m_gg = eta.cross(&(self.j * eta)) * ob.gravity_gradient_coeff;
        let h = ob.wheel_momentum_body;
        let d = self.dist.map_or(Vector3::zeros(), |d| d.d);
        let w_dot =
            self.j_inv * (m_gg - omega.cross(&(self.j * omega + h)) - ob.wheel_torque_body) + d;
        (q_dot, w_dot)
    }

    pub(super) fn predict(&mut self, ob: &Onboard, dt: f64) {
        let has_omega = self.cfg.states.omega().is_some();
        let (q0, w0) = (self.q, self.rate());
        // RK4 of (q, ω); the reduced variant holds ω at the gyro reading.
        let step = |q: &UnitQuaternion<f64>, w: &Vector3<f64>| self.derivative(q, w, ob, has_omega);
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
        // A constant gain propagates no covariance (§3.3); a disturbance filter behind it
        // still needs the sensitivity S, so F.
        let frozen = self.gains.is_some();
        if frozen && self.dist.is_none() {
            return;
        }
        let f = self.jacobian(&w0, ob);
        if !frozen {
            self.propagate_covariance(&f, has_omega, dt);
        }
        if self.dist.is_some() {
            // A constant d moves δω by d·dt and δλ (half angle) by d·dt²/4 per step.
            let mut gamma = SMatrix::<f64, N, 3>::zeros();
            if let Some(o) = self.cfg.states.omega() {
                for i in 0..3 {
                    gamma[(i, i)] = dt * dt / 4.0;
                    gamma[(o + i, i)] = dt;
                }
            }
            self.dist_sens += pattern_mul(&f, self.f_nonzeros(), &self.dist_sens) * dt + gamma;
        }
    }

    /// P ← Φ P Φᵀ + Q for Φ = E + F·dt.
    fn propagate_covariance(&mut self, f: &SMatrix<f64, N, N>, has_omega: bool, dt: f64) {
        let t = self.tuning;
        let mut q = SVector::<f64, N>::zeros();
        let gyro_att = if has_omega {
            0.0
        } else {
            (t.gyro_sigma_rad_s * dt / 2.0).powi(2)
        };
        for i in 0..3 {
            q[i] = t.q_att * t.q_att + gyro_att;
        }
        if let Some(o) = self.cfg.states.omega() {
            for i in 0..3 {
                q[o + i] = t.q_rate * t.q_rate;
            }
        }
        for b in [self.cfg.states.gyro_bias(), self.cfg.states.mag_bias()]
            .into_iter()
            .flatten()
        {
            for i in 0..3 {
                q[b + i] = t.q_bias * t.q_bias;
            }
        }
        // Φ P Φᵀ for Φ = E + F·dt from F's block structure, then the diagonal Q.
        self.p = propagate_first_order(&self.p, f, self.f_nonzeros(), dt);
        for i in 0..N {
            self.p[(i, i)] += q[i];
        }
    }

    /// Where [`Self::jacobian`] can be non-zero.
    pub(super) fn f_nonzeros(&self) -> &'static [(usize, usize)] {
        match self.cfg.states.omega() {
            Some(_) => &F_NONZEROS,
            None => &F_NONZEROS[..F_ATT_NONZEROS],
        }
    }

    /// F = ∂f/∂x at the estimate (see the module documentation).
    pub(super) fn jacobian(&self, w: &Vector3<f64>, ob: &Onboard) -> SMatrix<f64, N, N> {
        let mut f = SMatrix::<f64, N, N>::zeros();
        f.fixed_view_mut::<3, 3>(0, 0).copy_from(&(-skew(w)));
        match self.cfg.states.omega() {
            Some(o) => {
                f.fixed_view_mut::<3, 3>(0, o)
                    .copy_from(&(Matrix3::identity() * 0.5));
                let eta = self.q.inverse_transform_vector(&Vector3::z());
                let fg = mul_skew(&skew_mul(&eta, &self.j), &eta)
                    - skew_mul(&(self.j * eta), &skew(&eta));
                let k = 2.0 * ob.gravity_gradient_coeff;
                f.fixed_view_mut::<3, 3>(o, 0)
                    .copy_from(&(self.j_inv * fg * k));
                let h = ob.wheel_momentum_body;
                let gyro = skew(&(self.j * w + h)) - skew_mul(w, &self.j);
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
}

/// `[v×] m` with the same terms in the same order as the dense product, less the three
/// products with the zero diagonal of `[v×]` (which add an exact zero): so the same to the last
/// bit, in 18 multiplications and 9 additions instead of 27 and 18.
pub(super) fn skew_mul(v: &Vector3<f64>, m: &Matrix3<f64>) -> Matrix3<f64> {
    let s = skew(v);
    Matrix3::from_fn(|i, j| match i {
        0 => s[(0, 1)] * m[(1, j)] + s[(0, 2)] * m[(2, j)],
        1 => s[(1, 0)] * m[(0, j)] + s[(1, 2)] * m[(2, j)],
        _ => s[(2, 0)] * m[(0, j)] + s[(2, 1)] * m[(1, j)],
    })
}

/// `m [v×]`, likewise.
pub(super) fn mul_skew(m: &Matrix3<f64>, v: &Vector3<f64>) -> Matrix3<f64> {
    let s = skew(v);
    Matrix3::from_fn(|i, j| match j {
        0 => m[(i, 1)] * s[(1, 0)] + m[(i, 2)] * s[(2, 0)],
        1 => m[(i, 0)] * s[(0, 1)] + m[(i, 2)] * s[(2, 1)],
        _ => m[(i, 0)] * s[(0, 2)] + m[(i, 1)] * s[(1, 2)],
    })
}
