//! Rotations, attitude parameterisations and integrators.
//!
//! # Conventions (stated once, used everywhere)
//!
//! * **Reference frame** `ref`: the fixed frame Oξηζ of paper 3, ζ pointing **up**.
//! * **Body frame** `body`: ξ' right, η' forward, ζ' up (paper 3, §1).
//! * **Quaternion**: Hamilton product, scalar first (`nalgebra::Quaternion::new(w, i, j, k)`).
//!   The attitude quaternion is always named `q_ref_from_body`: it maps body-frame
//!   coordinates into the reference frame, `v_ref = q_ref_from_body * v_body`.
//! * **DCM**: `a_body_from_ref` is paper 3's matrix *A* (`v_body = A v_ref`, rows are the body
//!   axes), so `a_body_from_ref = R(q_ref_from_body)ᵀ`.
//! * **Elementary rotations** [`rot_x`], [`rot_y`], [`rot_z`] are *passive* (frame) rotations,
//!   exactly paper 3's eq. (1): `rot_z(z) = [[cz, sz, 0], [−sz, cz, 0], [0, 0, 1]]`.
//! * Angles are radians and rates rad/s everywhere inside; degrees only in labels.
//!
//! Papers that use another convention are converted at the edges, in their lab.

mod covariance;
mod euler;
mod integrate;
mod krylov;
mod rotation;
mod runge_kutta;
mod wz;

pub use covariance::{
    NonZeros, all_finite, is_symmetric_positive_definite, joseph_update, joseph_update_scalar,
    nees, pattern_mul, propagate_first_order, symmetrize,
};
pub use euler::EulerYpr;
pub use integrate::{
    RateSegment, quaternion_derivative, rk4_step, step_quaternion_rk4, step_uvz_rk4, uv_derivative,
    uvz_derivative,
};
pub use krylov::{
    ANGLE_SEQUENCES, KrylovAngles, quaternion_from_sequence, sequence_from_quaternion,
};
pub use rotation::{
    dcm_from_quaternion, pitch_roll_of_vertical, quaternion_from_dcm, rot_x, rot_y, rot_z,
    rotation_angle_between, small_angle_error_body, vertical_in_body, wrap_pi,
};
pub use runge_kutta::{EULER, ExplicitRk, MIDPOINT, RK_METHOD_NAMES, RK_METHODS, RK4};
pub use wz::{
    CHART_SWITCH_MODULUS, WzAttitude, WzChart, a_of_w, better_chart, chart_coords_of_vertical,
    other_chart,
};
