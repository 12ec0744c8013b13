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

/// The structurally non-zero entries of a Jacobian F as `(row, column)`, row by row and
/// ascending in column within a row. An entry outside the list must be zero; one inside may
/// happen to be zero. Multiplying by the list's entries alone adds, for every product entry,
/// the same terms in the same order as a dense product that skips zeros, so the result is the
/// same to the last bit.
pub type NonZeros = [(usize, usize)];

/// `A B` from the entries `nonzero` of `a` alone: 2·C FLOPs per entry.
///
/// ```
/// # use attlab::math::pattern_mul;
/// # use nalgebra::{Matrix3, Matrix3x2};
/// let a = Matrix3::new(0.0, 2.0, 0.0, -1.0, 0.0, 3.0, 0.0, 0.0, 0.0);
/// let b = Matrix3x2::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0);
/// assert_eq!(pattern_mul(&a, &[(0, 1), (1, 0), (1, 2)], &b), a * b);
/// ```
pub fn pattern_mul<const N: usize, const C: usize>(
    a: &SMatrix<f64, N, N>,
    nonzero: &NonZeros,
    b: &SMatrix<f64, N, C>,
) -> SMatrix<f64, N, C> {
    let mut out = SMatrix::<f64, N, C>::zeros();
    for &(i, k) in nonzero {
        let aik = a[(i, k)];
        for j in 0..C {
            out[(i, j)] += aik * b[(k, j)];
        }
    }
    out
}

/// `Φ P Φᵀ` for the first-order transition `Φ = E + F·dt` of a symmetric P, from F's
/// non-zero entries `nonzero` and P's symmetry: `P + dt (FP + (FP)ᵀ) + dt² F (FP)ᵀ`, formed
/// on the upper triangle and mirrored. `G = (FP)ᵀ` is built column by column from P's
/// columns (row k of a symmetric P is its column k), so the inner loops run over contiguous
/// memory. Cost: 2n FLOPs per entry for FP, at most 2n per entry for the triangle of
/// F (FP)ᵀ, and 5n(n + 1)/2 (against 2n² + 4n³ − 2n² for Φ and the two dense products).
///
/// ```
/// # use attlab::math::propagate_first_order;
/// # use nalgebra::Matrix3;
/// # use approx::assert_relative_eq;
/// let p = Matrix3::new(4.0, 1.0, 0.5, 1.0, 3.0, 0.2, 0.5, 0.2, 2.0);
/// let f = Matrix3::new(0.0, 0.5, 0.0, -0.2, 0.0, 0.0, 0.0, 0.0, 0.0);
/// let phi = Matrix3::identity() + f * 0.1;
/// let nonzero = [(0, 1), (1, 0)];
/// assert_relative_eq!(propagate_first_order(&p, &f, &nonzero, 0.1), phi * p * phi.transpose(), max_relative = 1e-14);
/// ```
pub fn propagate_first_order<const N: usize>(
    p: &SMatrix<f64, N, N>,
    f: &SMatrix<f64, N, N>,
    nonzero: &NonZeros,
    dt: f64,
) -> SMatrix<f64, N, N> {
    // G = (FP)ᵀ: its column i is row i of FP, Σₖ f_ik · (column k of P).
    let mut g = SMatrix::<f64, N, N>::zeros();
    for &(i, k) in nonzero {
        let fik = f[(i, k)];
        for (o, pk) in g.column_mut(i).iter_mut().zip(p.column(k).iter()) {
            *o += fik * pk;
        }
    }
    // F (FP)ᵀ on the upper triangle: (i, j) = Σₖ f_ik G_kj for j ≥ i.
    let mut fpf = SMatrix::<f64, N, N>::zeros();
    for &(i, k) in nonzero {
        let fik = f[(i, k)];
        for j in i..N {
            fpf[(i, j)] += fik * g[(k, j)];
        }
    }
    let dt2 = dt * dt;
    let mut out = *p;
    for j in 0..N {
        for i in 0..=j {
            // (FP)_ij = G_ji and (FP)_ji = G_ij.
            let u = p[(i, j)] + dt * (g[(j, i)] + g[(i, j)]) + dt2 * fpf[(i, j)];
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
    // A value is finite unless its exponent bits are all ones (infinity or NaN); then, and
    // only then, adding one to the exponent carries into the top bit. Integer OR has no
    // order to keep, so the pass vectorises (a floating-point sum does not).
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    const ONE: u64 = 0x0010_0000_0000_0000;
    let carried = values
        .iter()
        .fold(0u64, |acc, v| acc | ((v.to_bits() & EXPONENT) + ONE));
    carried >> 63 == 0
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
