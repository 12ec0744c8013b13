//! The measurement update of [`Mekf`]: Table 2's rows assembled from the sensors present,
//! processed one scalar at a time in Joseph form, the geometry check, the correction folded
//! into the quaternion, and the parallel disturbance filter's update (§3.2).

use super::*;

impl<const N: usize> Mekf<N> {
    /// Assembles this step's measurement rows: (residual at the prior, H row, R).
    pub(super) fn rows(&self, m: &Measurements, ob: &Onboard) -> (Rows<N>, [bool; MAX_ROWS]) {
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
        let mut out = (rows, present);
        if let (true, Some(z)) = (s.mag, m.mag_body_nt) {
            let bias = st.mag_bias();
            self.vector_rows(&mut out, 6, z, &ob.mag_ref_orbit_nt, bias, t.mag_sigma_nt);
        }
        if let (true, Some(z)) = (s.sun, m.sun_body) {
            self.vector_rows(&mut out, 9, z, &ob.sun_ref_orbit, None, t.sun_sigma_rad);
        }
        out
    }

    /// A reference vector's three rows from `base`: reading `z` of `reference` (orbital
    /// axes), with the magnetometer's bias state at `bias` if the filter has one.
    fn vector_rows(
        &self,
        (rows, present): &mut (Rows<N>, [bool; MAX_ROWS]),
        base: usize,
        z: Vector3<f64>,
        reference: &Vector3<f64>,
        bias: Option<usize>,
        sigma: f64,
    ) {
        let model = self.q.inverse_transform_vector(reference);
        // The bias: added (nT), or a small turn δ of the field, b ≈ b₀ + δ × b₀ (Fig. 7),
        // whose rows are ∂(δ × b₀)/∂δ = −[b₀×].
        let (predicted, h_bias) = match bias {
            None => (model, Matrix3::zeros()),
            Some(_) if self.cfg.states.mag_turn() => {
                (model + self.mag_bias.cross(&model), -skew(&model))
            }
            Some(_) => (model + self.mag_bias, Matrix3::identity()),
        };
        let h_att = skew(&model) * 2.0;
        for i in 0..3 {
            let mut h = SVector::<f64, N>::zeros();
            for k in 0..3 {
                h[k] = h_att[(i, k)];
                if let Some(b) = bias {
                    h[b + k] = h_bias[(i, k)];
                }
            }
            rows[base + i] = (z[i] - predicted[i], h, sigma * sigma);
            present[base + i] = true;
        }
    }

    /// Whether any of this filter's sensors delivered this step (what [`Self::rows`] turns
    /// into rows): most steps none did, and the rows need not be assembled.
    fn delivered(&self, m: &Measurements) -> bool {
        let s = self.cfg.sensors;
        (s.star && m.star_q_ref_from_body.is_some())
            || (s.gyro && m.gyro_body_rad_s.is_some() && self.cfg.states.omega().is_some())
            || (s.mag && m.mag_body_nt.is_some())
            || (s.sun && m.sun_body.is_some())
    }

    /// The measurement update; whether it changed P.
    pub(super) fn update(&mut self, m: &Measurements, ob: &Onboard) -> bool {
        if !self.delivered(m) {
            return false;
        }
        let (rows, present) = self.rows(m, ob);
        if !present.iter().any(|p| *p) {
            return false;
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
            && self.cfg.constant_gain
            && self.t_s >= self.tuning.freeze_after_s
            && expected.iter().zip(&present).all(|(e, p)| !e || *p);
        let mut new_gains = [None; MAX_ROWS];
        for (k, ((r, h, var), here)) in rows.iter().zip(present).enumerate() {
            if !here {
                continue;
            }
            let residual = r - h.dot(&err.x);
            if let Some(gains) = &self.gains {
                if let Some(g) = gains[k] {
                    // Table 5's (λ, ω, d) rows: the disturbance filter keeps running behind
                    // the frozen gain, its innovation variance from the frozen P.
                    if let Some(d) = &mut self.dist {
                        let hd = self.dist_sens.transpose() * h;
                        let s = h.dot(&(self.p * h)) + *var;
                        disturbance_update(d, residual, &hd, s * self.tuning.rd_scale);
                        self.dist_sens -= g * hd.transpose();
                    }
                    err.x += g * residual;
                }
                continue;
            }
            match err.update_scalar(residual, h, *var) {
                Ok(inn) => {
                    if let Some(d) = &mut self.dist {
                        let hd = self.dist_sens.transpose() * h;
                        disturbance_update(d, residual, &hd, inn.s * self.tuning.rd_scale);
                        self.dist_sens -= inn.gain * hd.transpose();
                    }
                    nis += inn.nis;
                    dof += 1.0;
                    new_gains[k] = Some(inn.gain);
                }
                Err(e) => {
                    self.status = EstimatorStatus::Diverged(e.into());
                    return false;
                }
            }
        }
        if freeze {
            self.gains = Some(new_gains);
        }
        self.nis = [nis, dof];
        let p_changed = self.gains.is_none() || freeze;
        if p_changed {
            self.p = err.p;
        }
        self.apply_correction(&err.x);
        p_changed
    }

    /// Two parallel reference vectors and no star tracker: the rotation about them is not
    /// observed this update (H is degenerate). Said, not hidden; cleared when it passes.
    pub(super) fn check_geometry(&mut self, present: &[bool; MAX_ROWS], ob: &Onboard) {
        if matches!(self.status, EstimatorStatus::Diverged(_)) {
            return;
        }
        let (star, mag, sun) = (present[0], present[6], present[9]);
        let degenerate = !star && mag && sun && {
            let angle = ob.mag_ref_orbit_nt.angle(&ob.sun_ref_orbit).to_degrees();
            !(DEGENERATE_DEG..=180.0 - DEGENERATE_DEG).contains(&angle)
        };
        self.status = if degenerate {
            EstimatorStatus::Unobservable(Trouble::SunAlongField {
                within_deg: DEGENERATE_DEG,
            })
        } else {
            EstimatorStatus::Ok
        };
    }

    /// The rows the filter's sensors give when all of them deliver.
    pub(super) fn expected_rows(&self) -> [bool; MAX_ROWS] {
        let s = self.cfg.sensors;
        let gyro = s.gyro && self.cfg.states.omega().is_some();
        std::array::from_fn(|k| match k / 3 {
            0 => s.star,
            1 => gyro,
            2 => s.mag,
            _ => s.sun,
        })
    }

    pub(super) fn apply_correction(&mut self, dx: &SVector<f64, N>) {
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
    pub(super) fn publish(&mut self) {
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
pub(super) fn disturbance_update(d: &mut Disturbance, residual: f64, hd: &Vector3<f64>, r_d: f64) {
    let s = hd.dot(&(d.p * hd)) + r_d;
    if s <= 0.0 || !s.is_finite() {
        return;
    }
    let k = d.p * hd / s;
    d.d += k * residual;
    d.p = symmetrize(&((Matrix3::identity() - k * hd.transpose()) * d.p));
}
