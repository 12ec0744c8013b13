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

/// The Tait–Bryan sequences a lab offers for Krylov-type angles: (name, body axes turned
/// about first, second, third; 0 = x, 1 = y, 2 = z).
pub const ANGLE_SEQUENCES: [(&str, [usize; 3]); 6] = [
    ("z-y-x (Krylov, ship: yaw, pitch, roll)", [2, 1, 0]),
    ("x-y-z", [0, 1, 2]),
    ("y-x-z", [1, 0, 2]),
    ("z-x-y", [2, 0, 1]),
    ("x-z-y", [0, 2, 1]),
    ("y-z-x", [1, 2, 0]),
];

/// `q_ref_from_body` of the intrinsic rotation about body axis `axes[0]` by `angles[0]`,
/// then `axes[1]` by `angles[1]`, then `axes[2]` by `angles[2]` (three distinct axes). With
/// `[2, 1, 0]` these are [`KrylovAngles`].
///
/// ```
/// # use attlab::math::{KrylovAngles, quaternion_from_sequence};
/// let k = KrylovAngles::new(0.5, 0.7, 0.2);
/// let q = quaternion_from_sequence([2, 1, 0], k.to_array());
/// assert!(q.angle_to(&k.to_quaternion()) < 1e-12);
/// ```
pub fn quaternion_from_sequence(axes: [usize; 3], angles: [f64; 3]) -> UnitQuaternion<f64> {
    let about = |axis: usize, angle: f64| {
        let mut v = nalgebra::Vector3::zeros();
        v[axis] = 1.0;
        UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_unchecked(v), angle)
    };
    about(axes[0], angles[0]) * about(axes[1], angles[1]) * about(axes[2], angles[2])
}

/// The angles of `q_ref_from_body` in the sequence `axes` (inverse of
/// [`quaternion_from_sequence`]; the middle angle in [−π/2, π/2]).
///
/// ```
/// # use attlab::math::{ANGLE_SEQUENCES, quaternion_from_sequence, sequence_from_quaternion};
/// for (_, axes) in ANGLE_SEQUENCES {
///     let a = [0.4, -0.3, 1.1];
///     let back = sequence_from_quaternion(axes, &quaternion_from_sequence(axes, a));
///     assert!(a.iter().zip(back).all(|(x, y)| (x - y).abs() < 1e-12), "{axes:?}: {back:?}");
/// }
/// ```
pub fn sequence_from_quaternion(
    axes: [usize; 3],
    q_ref_from_body: &UnitQuaternion<f64>,
) -> [f64; 3] {
    let r = q_ref_from_body.to_rotation_matrix().into_inner();
    let [i, j, k] = axes;
    // +1 for a cyclic (even) order of the axes, −1 otherwise.
    let eps = if (j + 3 - i) % 3 == 1 { 1.0 } else { -1.0 };
    let a2 = (eps * r[(i, k)]).clamp(-1.0, 1.0).asin();
    let a1 = (-eps * r[(j, k)]).atan2(r[(k, k)]);
    let a3 = (-eps * r[(i, j)]).atan2(r[(i, i)]);
    [a1, a2, a3]
}
