//! Covariance helpers shared by every Kalman filter.

use nalgebra::{SMatrix, SVector};

/// `(P + Pᵀ)/2`: removes the asymmetry that rounding adds at every step.
///
/// ```
/// # use attlab::math::symmetrize;
/// # use nalgebra::Matrix2;
/// assert_eq!(symmetrize(&Matrix2::new(1.0, 2.0, 0.0, 1.0)), Matrix2::new(1.0, 1.0, 1.0, 1.0));
/// ```
pub fn symmetrize<const N: usize>(p: &SMatrix<f64, N, N>) -> SMatrix<f64, N, N> {
    (p + p.transpose()) * 0.5
}

/// Joseph-form measurement update `P⁺ = (I − KH) P (I − KH)ᵀ + K R Kᵀ`, which stays
/// symmetric positive semi-definite for any gain K.
///
/// ```
/// # use attlab::math::joseph_update;
/// # use nalgebra::{Matrix1, Matrix1x2, Matrix2, Matrix2x1};
/// # use approx::assert_relative_eq;
/// let p = Matrix2::new(4.0, 0.0, 0.0, 1.0);
/// let h = Matrix1x2::new(1.0, 0.0);
/// let r = Matrix1::new(4.0);
/// let k = Matrix2x1::new(0.5, 0.0); // optimal gain P Hᵀ (H P Hᵀ + R)⁻¹
/// assert_relative_eq!(joseph_update(&p, &k, &h, &r), Matrix2::new(2.0, 0.0, 0.0, 1.0));
/// ```
pub fn joseph_update<const N: usize, const M: usize>(
    p: &SMatrix<f64, N, N>,
    k: &SMatrix<f64, N, M>,
    h: &SMatrix<f64, M, N>,
    r: &SMatrix<f64, M, M>,
) -> SMatrix<f64, N, N> {
    let i_kh = SMatrix::<f64, N, N>::identity() - k * h;
    symmetrize(&(i_kh * p * i_kh.transpose() + k * r * k.transpose()))
}

/// True when `p` is symmetric (to 1e-9 relative) and has a Cholesky factor.
///
/// ```
/// # use attlab::math::is_symmetric_positive_definite;
/// # use nalgebra::Matrix2;
/// assert!(is_symmetric_positive_definite(&Matrix2::new(2.0, 1.0, 1.0, 2.0)));
/// assert!(!is_symmetric_positive_definite(&Matrix2::new(1.0, 2.0, 2.0, 1.0)));
/// ```
pub fn is_symmetric_positive_definite<const N: usize>(p: &SMatrix<f64, N, N>) -> bool {
    let scale = p.amax().max(f64::MIN_POSITIVE);
    (p - p.transpose()).amax() <= 1e-9 * scale && p.cholesky().is_some()
}

/// Normalised estimation error squared `eᵀ P⁻¹ e`; `None` when P is singular.
pub fn nees<const N: usize>(error: &SVector<f64, N>, p: &SMatrix<f64, N, N>) -> Option<f64> {
    p.cholesky().map(|c| error.dot(&c.solve(error)))
}
