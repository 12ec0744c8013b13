//! Yaw–pitch–roll Euler angles of paper 3, eq. (22): `A = Γ(γ)·Θ(ϑ)·Ψ(ψ)` — yaw ψ about ζ,
//! then pitch ϑ about ξ, then roll γ about η.

use super::rotation::{dcm_from_quaternion, rot_x, rot_y, rot_z};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

/// Paper 3's Euler angles (rad). Pitch ϑ ∈ [−π/2, π/2], yaw ψ and roll γ ∈ (−π, π].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct EulerYpr {
    /// Yaw ψ about the vertical ζ (rad).
    pub yaw_rad: f64,
    /// Pitch ϑ about ξ (rad).
    pub pitch_rad: f64,
    /// Roll γ about η (rad).
    pub roll_rad: f64,
}

impl EulerYpr {
    /// Angles in paper order (yaw, pitch, roll).
    pub fn new(yaw_rad: f64, pitch_rad: f64, roll_rad: f64) -> Self {
        Self {
            yaw_rad,
            pitch_rad,
            roll_rad,
        }
    }

    /// Paper 3's eq. (22) matrix *A*.
    ///
    /// ```
    /// # use attlab::math::EulerYpr;
    /// # use approx::assert_relative_eq;
    /// let (psi, th, ga) = (0.3_f64, 0.4_f64, -0.2_f64);
    /// let a = EulerYpr::new(psi, th, ga).to_dcm();
    /// // third column = (−sinγ cosϑ, sinϑ, cosγ cosϑ), eq. (27)
    /// assert_relative_eq!(a[(0, 2)], -ga.sin() * th.cos(), epsilon = 1e-15);
    /// assert_relative_eq!(a[(1, 2)], th.sin(), epsilon = 1e-15);
    /// ```
    pub fn to_dcm(&self) -> Matrix3<f64> {
        rot_y(self.roll_rad) * rot_x(self.pitch_rad) * rot_z(self.yaw_rad)
    }

    /// Angles from *A*. At the gimbal lock (ϑ = ±90°) roll is set to 0 and yaw takes the
    /// whole rotation about the vertical.
    pub fn from_dcm(a: &Matrix3<f64>) -> Self {
        let pitch_rad = a[(1, 2)].clamp(-1.0, 1.0).asin();
        let cos_pitch_sq = a[(0, 2)].powi(2) + a[(2, 2)].powi(2);
        if cos_pitch_sq > 1e-20 {
            Self {
                yaw_rad: (-a[(1, 0)]).atan2(a[(1, 1)]),
                pitch_rad,
                roll_rad: (-a[(0, 2)]).atan2(a[(2, 2)]),
            }
        } else {
            Self {
                yaw_rad: a[(0, 1)].atan2(a[(0, 0)]),
                pitch_rad,
                roll_rad: 0.0,
            }
        }
    }

    /// `q_ref_from_body` for these angles.
    pub fn to_quaternion(&self) -> UnitQuaternion<f64> {
        // A = Γ(γ)·Θ(ϑ)·Ψ(ψ) of passive rotations, so q_ref_from_body = R_ζ(ψ)·R_ξ(ϑ)·R_η(γ)
        // of active ones: three half-angle sin/cos and two products, no matrix.
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), self.yaw_rad)
            * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), self.pitch_rad)
            * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), self.roll_rad)
    }

    /// The yaw ψ alone of `q_ref_from_body` (one atan2, no matrix): what a yaw plot needs.
    ///
    /// ```
    /// # use attlab::math::EulerYpr;
    /// let e = EulerYpr::new(0.7, -0.3, 1.1);
    /// assert!((EulerYpr::yaw_of(&e.to_quaternion()) - 0.7).abs() < 1e-12);
    /// ```
    pub fn yaw_of(q_ref_from_body: &UnitQuaternion<f64>) -> f64 {
        // a = A = R(q)ᵀ, so a[(1, 0)] = R[(0, 1)] and a[(1, 1)] = R[(1, 1)].
        let (w, x, y, z) = (
            q_ref_from_body.w,
            q_ref_from_body.i,
            q_ref_from_body.j,
            q_ref_from_body.k,
        );
        let r01 = 2.0 * (x * y - w * z);
        let r11 = 1.0 - 2.0 * (x * x + z * z);
        let cos_pitch_sq = {
            let r20 = 2.0 * (x * z - w * y);
            let r22 = 1.0 - 2.0 * (x * x + y * y);
            r20 * r20 + r22 * r22
        };
        if cos_pitch_sq > 1e-20 {
            (-r01).atan2(r11)
        } else {
            Self::from_quaternion(q_ref_from_body).yaw_rad
        }
    }

    /// Angles of `q_ref_from_body`.
    pub fn from_quaternion(q_ref_from_body: &UnitQuaternion<f64>) -> Self {
        Self::from_dcm(&dcm_from_quaternion(q_ref_from_body))
    }
}
