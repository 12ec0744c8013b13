//! The Kalman vocabulary every Kalman-type estimator shares, in the way adskalman-rs
//! separates them: a model is a **transition** Φ with its **process noise** Q, and an
//! **observation** H with its **measurement noise** R; one prediction and one Joseph-form
//! update serve every filter. A new linear filter is a model description and a few lines:
//!
//! ```
//! # use attlab::estimators::kf::{KalmanState, LinearObservation, LinearTransition};
//! # use nalgebra::{Matrix1, Matrix1x2, Matrix2, Vector1, Vector2};
//! // Constant velocity, position measured with σ = 0.1.
//! let motion = LinearTransition::new(Matrix2::new(1.0, 0.1, 0.0, 1.0), Matrix2::identity() * 1e-4);
//! let sensor = LinearObservation::new(Matrix1x2::new(1.0, 0.0), Matrix1::new(0.01));
//! let mut kf = KalmanState::new(Vector2::zeros(), Matrix2::identity());
//! for k in 1..=50 {
//!     kf.predict(&motion);
//!     kf.update(&Vector1::new(0.1 * k as f64), &sensor).unwrap();
//! }
//! assert!((kf.x[1] - 1.0).abs() < 0.05); // the velocity is found
//! ```
//!
//! Extended filters give the linearisation (Φ = ∂f/∂x over the step, H = ∂h/∂x) and their
//! own predicted state or residual to [`KalmanState::predict_with`] and
//! [`KalmanState::update_with`]; sensors whose noises are independent can be processed one
//! scalar row at a time with [`KalmanState::update_scalar`] (no matrix inverse, any number
//! of rows, no heap).

use crate::math::{all_finite, joseph_update_scalar, symmetrize};
use crate::model::Trouble;
use nalgebra::{SMatrix, SVector};
use thiserror::Error;

/// Why an update was refused (the filter keeps its prior).
#[derive(Clone, Copy, Debug, Error, PartialEq)]
pub enum KfError {
    /// The innovation covariance H P Hᵀ + R is not positive definite (a degenerate
    /// geometry, or R = 0 with P = 0).
    #[error("innovation covariance is not positive definite")]
    SingularInnovation,
    /// The measurement or the result is not finite.
    #[error("non-finite measurement or state")]
    NotFinite,
}

impl From<KfError> for Trouble {
    fn from(e: KfError) -> Self {
        match e {
            KfError::SingularInnovation => Trouble::InnovationNotPositive,
            KfError::NotFinite => Trouble::MeasurementNotFinite,
        }
    }
}

/// A linear transition: Φ and Q fixed for the step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearTransition<const N: usize> {
    /// Φ.
    pub phi: SMatrix<f64, N, N>,
    /// Q (per step).
    pub q: SMatrix<f64, N, N>,
}

impl<const N: usize> LinearTransition<N> {
    /// Φ and Q.
    pub fn new(phi: SMatrix<f64, N, N>, q: SMatrix<f64, N, N>) -> Self {
        Self { phi, q }
    }
}

/// A linear observation: z = H x + v, v ~ N(0, R).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearObservation<const N: usize, const M: usize> {
    /// H.
    pub h: SMatrix<f64, M, N>,
    /// R.
    pub r: SMatrix<f64, M, M>,
}

impl<const N: usize, const M: usize> LinearObservation<N, M> {
    /// H and R.
    pub fn new(h: SMatrix<f64, M, N>, r: SMatrix<f64, M, M>) -> Self {
        Self { h, r }
    }
}

/// What an update saw: the residual z − h(x⁻), its covariance S and the normalised
/// innovation squared rᵀ S⁻¹ r (χ² with M degrees of freedom when the filter is consistent).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Innovation<const M: usize> {
    /// z − h(x⁻).
    pub residual: SVector<f64, M>,
    /// H P⁻ Hᵀ + R.
    pub s: SMatrix<f64, M, M>,
    /// rᵀ S⁻¹ r.
    pub nis: f64,
}

/// A Gaussian state: the estimate and its covariance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KalmanState<const N: usize> {
    /// Estimate.
    pub x: SVector<f64, N>,
    /// Covariance.
    pub p: SMatrix<f64, N, N>,
}

impl<const N: usize> KalmanState<N> {
    /// Starts at `x0` with covariance `p0`.
    pub fn new(x0: SVector<f64, N>, p0: SMatrix<f64, N, N>) -> Self {
        Self { x: x0, p: p0 }
    }

    /// x⁻ = Φ x, P⁻ = Φ P Φᵀ + Q.
    pub fn predict(&mut self, model: &LinearTransition<N>) {
        let x = model.phi * self.x;
        self.predict_with(x, &model.phi, &model.q);
    }

    /// An extended prediction: the propagated state `x_predicted` (e.g. integrated through
    /// the nonlinear dynamics) and the linearised Φ and Q.
    pub fn predict_with(
        &mut self,
        x_predicted: SVector<f64, N>,
        phi: &SMatrix<f64, N, N>,
        q: &SMatrix<f64, N, N>,
    ) {
        self.x = x_predicted;
        self.p = symmetrize(&(phi * self.p * phi.transpose() + q));
    }

    /// The update with a measurement of a linear observation.
    pub fn update<const M: usize>(
        &mut self,
        z: &SVector<f64, M>,
        model: &LinearObservation<N, M>,
    ) -> Result<Innovation<M>, KfError> {
        let residual = z - model.h * self.x;
        self.update_with(residual, &model.h, &model.r)
    }

    /// The Joseph-form update with a residual computed by the caller (z − h(x⁻) of a
    /// nonlinear h) and the linearised H:
    /// K = P⁻Hᵀ S⁻¹, x⁺ = x⁻ + K r, P⁺ = (I − KH) P⁻ (I − KH)ᵀ + K R Kᵀ. Returns the
    /// correction made, K r, too (adaptive filters use it). On error nothing changes.
    pub fn update_with<const M: usize>(
        &mut self,
        residual: SVector<f64, M>,
        h: &SMatrix<f64, M, N>,
        r: &SMatrix<f64, M, M>,
    ) -> Result<Innovation<M>, KfError> {
        if !residual.iter().all(|v| v.is_finite()) {
            return Err(KfError::NotFinite);
        }
        let pht = self.p * h.transpose();
        let s = symmetrize(&(h * pht + r));
        let chol = s.cholesky().ok_or(KfError::SingularInnovation)?;
        let k = chol.solve(&pht.transpose()).transpose();
        let nis = residual.dot(&chol.solve(&residual));
        let x = self.x + k * residual;
        let i_kh = SMatrix::<f64, N, N>::identity() - k * h;
        let p = symmetrize(&(i_kh * self.p * i_kh.transpose() + k * r * k.transpose()));
        if !(all_finite(x.as_slice()) && all_finite(p.as_slice())) {
            return Err(KfError::NotFinite);
        }
        self.x = x;
        self.p = p;
        Ok(Innovation { residual, s, nis })
    }

    /// One scalar measurement row (independent noise of variance `r`), in O(n²): v = P⁻h
    /// from h's non-zero entries, s = hᵀv + r, k = v/s, x⁺ = x⁻ + k·residual and the
    /// expanded scalar Joseph form of [`joseph_update_scalar`] (no matrix inverse, no heap).
    /// On error nothing changes.
    pub fn update_scalar(
        &mut self,
        residual: f64,
        h: &SVector<f64, N>,
        r: f64,
    ) -> Result<ScalarInnovation<N>, KfError> {
        if !residual.is_finite() {
            return Err(KfError::NotFinite);
        }
        let mut v = SVector::<f64, N>::zeros();
        let mut s = r;
        for (k, hk) in h.iter().enumerate() {
            if *hk != 0.0 {
                v.axpy(*hk, &self.p.column(k), 1.0);
            }
        }
        for (k, hk) in h.iter().enumerate() {
            if *hk != 0.0 {
                s += hk * v[k];
            }
        }
        if !(s > 0.0 && s.is_finite()) {
            return Err(KfError::SingularInnovation);
        }
        let gain = v / s;
        let x = self.x + gain * residual;
        let p = joseph_update_scalar(&self.p, &gain, &v, s);
        if !(all_finite(x.as_slice()) && all_finite(p.as_slice())) {
            return Err(KfError::NotFinite);
        }
        self.x = x;
        self.p = p;
        Ok(ScalarInnovation {
            s,
            gain,
            nis: residual * residual / s,
        })
    }
}

/// What one scalar row did: its innovation variance, the gain it applied and the NIS.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScalarInnovation<const N: usize> {
    /// s = hᵀ P⁻ h + r.
    pub s: f64,
    /// k = P⁻ h / s.
    pub gain: SVector<f64, N>,
    /// residual² / s.
    pub nis: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix1, Matrix1x2, Matrix2, Vector1, Vector2};

    #[test]
    fn joseph_update_matches_the_textbook_form_for_the_optimal_gain() {
        let mut kf = KalmanState::new(Vector2::new(1.0, 2.0), Matrix2::new(4.0, 1.0, 1.0, 3.0));
        let obs = LinearObservation::new(Matrix1x2::new(0.0, 1.0), Matrix1::new(0.5));
        let p0 = kf.p;
        let inn = kf.update(&Vector1::new(2.5), &obs).unwrap();
        // (I − KH)P with K = P Hᵀ / (H P Hᵀ + R).
        let s = p0[(1, 1)] + 0.5;
        let k = p0.column(1) / s;
        let expected = p0 - k * p0.row(1);
        assert!((kf.p - expected).amax() < 1e-12, "{} vs {expected}", kf.p);
        assert!((inn.nis - 0.25 / s).abs() < 1e-12);
    }

    #[test]
    fn the_scalar_update_equals_the_dense_joseph_update() {
        use nalgebra::{Matrix4, RowVector4, Vector4};
        let a = Matrix4::new(
            2.0, 0.3, -0.1, 0.0, 0.1, 1.5, 0.2, -0.4, 0.0, 0.7, 1.1, 0.3, -0.2, 0.0, 0.5, 0.9,
        );
        let p0 = a * a.transpose();
        let h = Vector4::new(0.0, 2.0, -1.0, 0.0);
        let (mut scalar, mut dense) = (
            KalmanState::new(Vector4::new(1.0, -1.0, 0.5, 2.0), p0),
            KalmanState::new(Vector4::new(1.0, -1.0, 0.5, 2.0), p0),
        );
        let inn = scalar.update_scalar(0.8, &h, 0.3).unwrap();
        let full = dense
            .update_with(
                Vector1::new(0.8),
                &RowVector4::from(h.transpose()),
                &Matrix1::new(0.3),
            )
            .unwrap();
        assert!(
            (scalar.p - dense.p).amax() < 1e-13 * p0.amax(),
            "{} vs {}",
            scalar.p,
            dense.p
        );
        assert!((scalar.x - dense.x).amax() < 1e-13);
        assert!((inn.nis - full.nis).abs() < 1e-13 && (inn.s - full.s[(0, 0)]).abs() < 1e-13);
        assert_eq!(scalar.p, scalar.p.transpose(), "exactly symmetric");
        let mut degenerate = KalmanState::new(Vector4::zeros(), Matrix4::zeros());
        let before = degenerate;
        assert_eq!(
            degenerate.update_scalar(1.0, &h, 0.0),
            Err(KfError::SingularInnovation)
        );
        assert_eq!(
            degenerate.update_scalar(f64::NAN, &h, 1.0),
            Err(KfError::NotFinite)
        );
        assert_eq!(degenerate, before);
    }

    #[test]
    fn a_degenerate_update_is_refused_and_changes_nothing() {
        let mut kf = KalmanState::new(Vector2::new(1.0, 2.0), Matrix2::zeros());
        let obs = LinearObservation::new(Matrix1x2::new(0.0, 1.0), Matrix1::new(0.0));
        let before = kf;
        assert_eq!(
            kf.update(&Vector1::new(2.5), &obs),
            Err(KfError::SingularInnovation)
        );
        assert_eq!(kf, before);
        assert_eq!(
            kf.update(&Vector1::new(f64::NAN), &obs),
            Err(KfError::NotFinite)
        );
    }
}
