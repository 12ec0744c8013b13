//! The series a sensitivity corrector records besides the catalogue's: its rate
//! correction p, the angles of its sequence, its tolerance flag and what the update found
//! (figures and reproductions name them).

use crate::model::Quantity;

/// rate correction p_x (deg/s).
pub const P_X_DEG_S: Quantity = Quantity::new("p_x_deg_s", "rate correction p_x", "deg/s");
/// rate correction p_y (deg/s).
pub const P_Y_DEG_S: Quantity = Quantity::new("p_y_deg_s", "rate correction p_y", "deg/s");
/// rate correction p_z (deg/s).
pub const P_Z_DEG_S: Quantity = Quantity::new("p_z_deg_s", "rate correction p_z", "deg/s");
/// angle 1 of the sequence (rad).
pub const ANGLE_1_RAD: Quantity = Quantity::new("angle_1_rad", "angle 1 of the sequence", "rad");
/// angle 2 of the sequence (rad).
pub const ANGLE_2_RAD: Quantity = Quantity::new("angle_2_rad", "angle 2 of the sequence", "rad");
/// angle 3 of the sequence (rad).
pub const ANGLE_3_RAD: Quantity = Quantity::new("angle_3_rad", "angle 3 of the sequence", "rad");
/// within tolerance of the reference (1 = yes).
pub const WITHIN_TOL: Quantity = Quantity::new(
    "within_tol",
    "within tolerance of the reference (1 = yes)",
    "",
);
/// condition number of UᵀQU.
pub const COND_UTQU: Quantity = Quantity::new("cond_utqu", "condition number of UᵀQU", "");
/// largest singular value of UᵀQU.
pub const SV1: Quantity = Quantity::new("sv1", "largest singular value of UᵀQU", "");
/// middle singular value of UᵀQU.
pub const SV2: Quantity = Quantity::new("sv2", "middle singular value of UᵀQU", "");
/// smallest singular value of UᵀQU.
pub const SV3: Quantity = Quantity::new("sv3", "smallest singular value of UᵀQU", "");
/// step size s of the correction.
pub const STEP_S: Quantity = Quantity::new("step_s", "step size s of the correction", "");
/// norm |Λ| of the integrated quaternion.
pub const NORM_LAMBDA: Quantity =
    Quantity::new("norm_lambda", "norm |Λ| of the integrated quaternion", "");
