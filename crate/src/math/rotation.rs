//! Quaternion ↔ DCM and elementary rotations (see the module docs for conventions).

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

/// Passive rotation by `angle_rad` about x (paper 3's Θ).
///
/// ```
/// # use attlab::math::rot_x;
/// # use approx::assert_relative_eq;
/// let m = rot_x(0.3);
/// assert_relative_eq!(m[(1, 2)], 0.3_f64.sin());
/// ```
pub fn rot_x(angle_rad: f64) -> Matrix3<f64> {
    let (s, c) = angle_rad.sin_cos();
    Matrix3::new(1.0, 0.0, 0.0, 0.0, c, s, 0.0, -s, c)
}

/// Passive rotation by `angle_rad` about y (paper 3's Γ).
///
/// ```
/// # use attlab::math::rot_y;
/// # use approx::assert_relative_eq;
/// assert_relative_eq!(rot_y(0.3)[(0, 2)], -0.3_f64.sin());
/// ```
pub fn rot_y(angle_rad: f64) -> Matrix3<f64> {
    let (s, c) = angle_rad.sin_cos();
    Matrix3::new(c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c)
}

/// Passive rotation by `angle_rad` about z (paper 3's eq. 1, Ψ).
///
/// ```
/// # use attlab::math::rot_z;
/// # use approx::assert_relative_eq;
/// assert_relative_eq!(rot_z(0.3)[(0, 1)], 0.3_f64.sin());
/// ```
pub fn rot_z(angle_rad: f64) -> Matrix3<f64> {
    let (s, c) = angle_rad.sin_cos();
    Matrix3::new(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0)
}

/// Paper 3's matrix *A* (`v_body = A v_ref`) from `q_ref_from_body`.
///
/// ```
/// # use attlab::math::dcm_from_quaternion;
/// # use nalgebra::{UnitQuaternion, Vector3};
/// # use approx::assert_relative_eq;
/// let q = UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3);
/// let v_ref = Vector3::new(1.0, 2.0, 3.0);
/// assert_relative_eq!(dcm_from_quaternion(&q) * v_ref, q.inverse() * v_ref, epsilon = 1e-12);
/// ```
pub fn dcm_from_quaternion(q_ref_from_body: &UnitQuaternion<f64>) -> Matrix3<f64> {
    q_ref_from_body.to_rotation_matrix().matrix().transpose()
}

/// `q_ref_from_body` from paper 3's matrix *A*, in closed form (Shepperd's method) and
/// renormalised, so a slightly non-orthogonal DCM (e.g. from integration) is accepted and a
/// matrix with a non-finite element gives a quaternion of NaNs (which the loop reports as a
/// diverged estimate) — never an open-ended iteration.
///
/// ```
/// # use attlab::math::{dcm_from_quaternion, quaternion_from_dcm};
/// # use nalgebra::UnitQuaternion;
/// # use approx::assert_relative_eq;
/// let q = UnitQuaternion::from_euler_angles(0.4, -0.2, 2.0);
/// let back = quaternion_from_dcm(&dcm_from_quaternion(&q));
/// assert_relative_eq!(back.angle_to(&q), 0.0, epsilon = 1e-12);
/// let nan = nalgebra::Matrix3::repeat(f64::NAN);
/// assert!(quaternion_from_dcm(&nan).coords.iter().all(|c| c.is_nan()));
/// ```
pub fn quaternion_from_dcm(a_body_from_ref: &Matrix3<f64>) -> UnitQuaternion<f64> {
    if !a_body_from_ref.iter().all(|v| v.is_finite()) {
        return UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(
            f64::NAN,
            f64::NAN,
            f64::NAN,
            f64::NAN,
        ));
    }
    let r_ref_from_body = Rotation3::from_matrix_unchecked(a_body_from_ref.transpose());
    UnitQuaternion::new_normalize(
        UnitQuaternion::from_rotation_matrix(&r_ref_from_body).into_inner(),
    )
}

/// The reference vertical ζ expressed in body axes: the third column (a′, b′, c′) of *A*.
///
/// ```
/// # use attlab::math::vertical_in_body;
/// # use nalgebra::{UnitQuaternion, Vector3};
/// # use approx::assert_relative_eq;
/// assert_relative_eq!(vertical_in_body(&UnitQuaternion::identity()), Vector3::z());
/// ```
pub fn vertical_in_body(q_ref_from_body: &UnitQuaternion<f64>) -> Vector3<f64> {
    q_ref_from_body.inverse_transform_vector(&Vector3::z())
}

/// Angle (rad, in [0, π]) of the rotation that takes one attitude to the other.
///
/// ```
/// # use attlab::math::rotation_angle_between;
/// # use nalgebra::{UnitQuaternion, Vector3};
/// # use approx::assert_relative_eq;
/// let a = UnitQuaternion::identity();
/// let b = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.25);
/// assert_relative_eq!(rotation_angle_between(&a, &b), 0.25, epsilon = 1e-12);
/// ```
pub fn rotation_angle_between(a: &UnitQuaternion<f64>, b: &UnitQuaternion<f64>) -> f64 {
    a.angle_to(b)
}

/// Small-angle attitude error in body axes (rad): the rotation vector of
/// `q_true⁻¹ ⊗ q_estimate`, i.e. how far the estimate is turned, seen from the true body.
/// NaN when either attitude is not finite (a log's unknown truth, a filter gone to NaN):
/// nalgebra's rotation vector of a NaN quaternion is zero, which would read as no error.
///
/// ```
/// # use attlab::math::small_angle_error_body;
/// # use nalgebra::{Quaternion, UnitQuaternion, Vector3};
/// # use approx::assert_relative_eq;
/// let truth = UnitQuaternion::from_euler_angles(0.3, 0.1, -0.5);
/// let est = truth * UnitQuaternion::from_scaled_axis(Vector3::new(0.01, -0.02, 0.0));
/// let e = small_angle_error_body(&truth, &est);
/// assert_relative_eq!(e, Vector3::new(0.01, -0.02, 0.0), epsilon = 1e-12);
/// let unknown = UnitQuaternion::new_unchecked(Quaternion::new(f64::NAN, 0.0, 0.0, 0.0));
/// assert!(small_angle_error_body(&unknown, &est).iter().all(|c| c.is_nan()));
/// ```
pub fn small_angle_error_body(
    q_true_ref_from_body: &UnitQuaternion<f64>,
    q_est_ref_from_body: &UnitQuaternion<f64>,
) -> Vector3<f64> {
    let finite = |q: &UnitQuaternion<f64>| q.coords.iter().all(|c| c.is_finite());
    if !(finite(q_true_ref_from_body) && finite(q_est_ref_from_body)) {
        return Vector3::repeat(f64::NAN);
    }
    (q_true_ref_from_body.inverse() * q_est_ref_from_body).scaled_axis()
}

/// Pitch ϑ and roll γ of paper 3 from the vertical in body axes (eqs. 24–25 solved).
///
/// ```
/// # use attlab::math::pitch_roll_of_vertical;
/// # use nalgebra::Vector3;
/// let (pitch, roll) = pitch_roll_of_vertical(&Vector3::z());
/// assert_eq!((pitch, roll), (0.0, 0.0));
/// ```
pub fn pitch_roll_of_vertical(k_body: &Vector3<f64>) -> (f64, f64) {
    (
        k_body.y.clamp(-1.0, 1.0).asin(),
        (-k_body.x).atan2(k_body.z),
    )
}

/// `a` wrapped to (−π, π].
///
/// ```
/// # use attlab::math::wrap_pi;
/// assert!((wrap_pi(3.0 * std::f64::consts::PI) - std::f64::consts::PI).abs() < 1e-12);
/// assert!((wrap_pi(-0.5) + 0.5).abs() < 1e-15);
/// ```
pub fn wrap_pi(a: f64) -> f64 {
    let t = a.rem_euclid(std::f64::consts::TAU);
    if t > std::f64::consts::PI {
        t - std::f64::consts::TAU
    } else {
        t
    }
}
