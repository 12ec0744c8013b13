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

/// The scalar Joseph update in O(n²): for one measurement row h with noise variance r and
/// **any** gain k,
/// `(E − k hᵀ) P (E − k hᵀ)ᵀ + k r kᵀ = P − k vᵀ − v kᵀ + s k kᵀ` with `v = P h` and
/// `s = hᵀ v + r`. It is the Joseph form expanded, not the short form `P − k vᵀ`: the same
/// polynomial in k, so an error in the gain still changes P only at second order. Formed on
/// the upper triangle and mirrored, so P stays exactly symmetric. Cost: 3n(n + 1) + n FLOPs
/// (against 4n³ + 6n² for the matrix products of [`joseph_update`]).
///
/// ```
/// # use attlab::math::{joseph_update, joseph_update_scalar};
/// # use nalgebra::{Matrix1, Matrix3, RowVector3, Vector3};
/// # use approx::assert_relative_eq;
/// let p = Matrix3::new(4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0);
/// let (h, r) = (Vector3::new(0.0, 1.0, -2.0), 0.7);
/// let v = p * h;
/// let s = h.dot(&v) + r;
/// let k = Vector3::new(0.3, -0.1, 0.05); // not the optimal gain: Joseph holds for any
/// let dense = joseph_update(&p, &k, &h.transpose(), &Matrix1::new(r));
/// assert_relative_eq!(joseph_update_scalar(&p, &k, &v, s), dense, max_relative = 1e-14);
/// ```
pub fn joseph_update_scalar<const N: usize>(
    p: &SMatrix<f64, N, N>,
    k: &SVector<f64, N>,
    v: &SVector<f64, N>,
    s: f64,
) -> SMatrix<f64, N, N> {
    let sk = k * s;
    let mut out = *p;
    for j in 0..N {
        for i in 0..=j {
            let u = p[(i, j)] - k[i] * v[j] - v[i] * k[j] + sk[i] * k[j];
            out[(i, j)] = u;
            out[(j, i)] = u;
        }
    }
    out
}

/// `A B` using only the non-zero entries of `a` (a Jacobian's block structure): 2·C FLOPs per
/// non-zero entry of `a`.
pub fn sparse_mul<const N: usize, const C: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SMatrix<f64, N, C>,
) -> SMatrix<f64, N, C> {
    let mut out = SMatrix::<f64, N, C>::zeros();
    for k in 0..N {
        for i in 0..N {
            let aik = a[(i, k)];
            if aik != 0.0 {
                for (o, bkj) in out.row_mut(i).iter_mut().zip(b.row(k).iter()) {
                    *o += aik * bkj;
                }
            }
        }
    }
    out
}

/// `Φ P Φᵀ` for the first-order transition `Φ = E + F·dt` of a symmetric P, from F's non-zero
/// entries and P's symmetry: `P + dt (FP + (FP)ᵀ) + dt² F (FP)ᵀ`, formed on the upper
/// triangle and mirrored. Cost: 4n FLOPs per non-zero entry of F and 5n(n + 1)/2 (against
/// 2n² + 4n³ − 2n² for Φ and the two dense products).
///
/// ```
/// # use attlab::math::propagate_first_order;
/// # use nalgebra::Matrix3;
/// # use approx::assert_relative_eq;
/// let p = Matrix3::new(4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0);
/// let f = Matrix3::new(0.0, 0.5, 0.0, -0.2, 0.0, 0.0, 0.0, 0.0, 0.0);
/// let phi = Matrix3::identity() + f * 0.1;
/// assert_relative_eq!(propagate_first_order(&p, &f, 0.1), phi * p * phi.transpose(), max_relative = 1e-14);
/// ```
pub fn propagate_first_order<const N: usize>(
    p: &SMatrix<f64, N, N>,
    f: &SMatrix<f64, N, N>,
    dt: f64,
) -> SMatrix<f64, N, N> {
    let fp = sparse_mul(f, p);
    let fpf = sparse_mul(f, &fp.transpose());
    let dt2 = dt * dt;
    let mut out = *p;
    for j in 0..N {
        for i in 0..=j {
            let u = p[(i, j)] + dt * (fp[(i, j)] + fp[(j, i)]) + dt2 * fpf[(i, j)];
            out[(i, j)] = u;
            out[(j, i)] = u;
        }
    }
    out
}

/// Whether every value is finite, over a contiguous slice (a matrix's `as_slice()`): one
/// branch-free pass, for the checks every filter step makes on its covariance.
///
/// ```
/// # use attlab::math::all_finite;
/// assert!(all_finite(&[1.0, -2.0, 1e300]));
/// assert!(!all_finite(&[1.0, f64::NAN]) && !all_finite(&[f64::INFINITY, 0.0]));
/// ```
pub fn all_finite(values: &[f64]) -> bool {
    // x·0 is ±0 for a finite x and NaN for an infinite or NaN one.
    values.iter().fold(0.0, |acc, v| acc + v * 0.0) == 0.0
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
