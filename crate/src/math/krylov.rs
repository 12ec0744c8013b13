//! Krylov angles (paper 5): the ship-building yaw–pitch–roll sequence, taken here as
//! z, then y′, then x″ (the digest's assumption, §3): `A = R_x(α₃)·R_y(α₂)·R_z(α₁)`.

use super::rotation::{dcm_from_quaternion, quaternion_from_dcm, rot_x, rot_y, rot_z};
use nalgebra::{Matrix3, UnitQuaternion};
use serde::{Deserialize, Serialize};

/// Krylov angles (rad): α₁ about z, α₂ about the new y, α₃ about the newest x.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct KrylovAngles {
    /// First angle α₁ (about z), rad.
    pub alpha1_rad: f64,
    /// Second angle α₂ (about y′), rad, in [−π/2, π/2].
    pub alpha2_rad: f64,
    /// Third angle α₃ (about x″), rad.
    pub alpha3_rad: f64,
}

impl KrylovAngles {
    /// Angles in sequence order.
    pub fn new(alpha1_rad: f64, alpha2_rad: f64, alpha3_rad: f64) -> Self {
        Self {
            alpha1_rad,
            alpha2_rad,
            alpha3_rad,
        }
    }

    /// Matrix *A* (`v_body = A v_ref`).
    ///
    /// ```
    /// # use attlab::math::KrylovAngles;
    /// # use approx::assert_relative_eq;
    /// let a = KrylovAngles::new(0.5, 0.7, 0.2).to_dcm();
    /// assert_relative_eq!(a[(0, 2)], -0.7_f64.sin(), epsilon = 1e-15);
    /// ```
    pub fn to_dcm(&self) -> Matrix3<f64> {
        rot_x(self.alpha3_rad) * rot_y(self.alpha2_rad) * rot_z(self.alpha1_rad)
    }

    /// Angles from *A*; at α₂ = ±90° the third angle is set to 0.
    pub fn from_dcm(a: &Matrix3<f64>) -> Self {
        let alpha2_rad = (-a[(0, 2)]).clamp(-1.0, 1.0).asin();
        let cos2_sq = a[(0, 0)].powi(2) + a[(0, 1)].powi(2);
        if cos2_sq > 1e-20 {
            Self {
                alpha1_rad: a[(0, 1)].atan2(a[(0, 0)]),
                alpha2_rad,
                alpha3_rad: a[(1, 2)].atan2(a[(2, 2)]),
            }
        } else {
            // A = R_y(±90°) R_z(α₁): row 1 is (−sin α₁, cos α₁, 0).
            Self {
                alpha1_rad: (-a[(1, 0)]).atan2(a[(1, 1)]),
                alpha2_rad,
                alpha3_rad: 0.0,
            }
        }
    }

    /// `q_ref_from_body` for these angles ("standard formulas" of paper 5).
    pub fn to_quaternion(&self) -> UnitQuaternion<f64> {
        quaternion_from_dcm(&self.to_dcm())
    }

    /// Angles of `q_ref_from_body`.
    pub fn from_quaternion(q_ref_from_body: &UnitQuaternion<f64>) -> Self {
        Self::from_dcm(&dcm_from_quaternion(q_ref_from_body))
    }

    /// The angles as an array (α₁, α₂, α₃).
    pub fn to_array(&self) -> [f64; 3] {
        [self.alpha1_rad, self.alpha2_rad, self.alpha3_rad]
    }
}
