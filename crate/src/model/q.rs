//! The quantities every source can record, named once: the truth's and each estimator's
//! attitude, rate and errors, with the student's label in the papers' notation and the unit.
//! A figure names a series by one of these and its source ([`super::SeriesKey`]).

use super::quantity::Quantity;

// A three-axis source's attitude (paper 3's notation for the vertical and w).
/// yaw ψ (deg).
pub const YAW_DEG: Quantity = Quantity::new("yaw_deg", "yaw ψ", "deg");
/// pitch ϑ (deg).
pub const PITCH_DEG: Quantity = Quantity::new("pitch_deg", "pitch ϑ", "deg");
/// roll γ (deg).
pub const ROLL_DEG: Quantity = Quantity::new("roll_deg", "roll γ", "deg");
/// vertical in body axes a′.
pub const K_X: Quantity = Quantity::new("k_x", "vertical in body axes a′", "");
/// vertical in body axes b′.
pub const K_Y: Quantity = Quantity::new("k_y", "vertical in body axes b′", "");
/// vertical in body axes c′.
pub const K_Z: Quantity = Quantity::new("k_z", "vertical in body axes c′", "");
/// u = Re w.
pub const U: Quantity = Quantity::new("u", "u = Re w", "");
/// v = Im w.
pub const V: Quantity = Quantity::new("v", "v = Im w", "");
/// z (turn about the vertical) (deg).
pub const Z_DEG: Quantity = Quantity::new("z_deg", "z (turn about the vertical)", "deg");
// Its body rates.
/// body rate ω about x (deg/s).
pub const RATE_X_DEG_S: Quantity = Quantity::new("rate_x_deg_s", "body rate ω about x", "deg/s");
/// body rate ω about y (deg/s).
pub const RATE_Y_DEG_S: Quantity = Quantity::new("rate_y_deg_s", "body rate ω about y", "deg/s");
/// body rate ω about z (deg/s).
pub const RATE_Z_DEG_S: Quantity = Quantity::new("rate_z_deg_s", "body rate ω about z", "deg/s");
// Its attitude errors against the truth.
/// attitude error (whole angle) (deg).
pub const ERR_DEG: Quantity = Quantity::new("err_deg", "attitude error (whole angle)", "deg");
/// attitude error about x (deg).
pub const ERR_X_DEG: Quantity = Quantity::new("err_x_deg", "attitude error about x", "deg");
/// attitude error about y (deg).
pub const ERR_Y_DEG: Quantity = Quantity::new("err_y_deg", "attitude error about y", "deg");
/// attitude error about z (deg).
pub const ERR_Z_DEG: Quantity = Quantity::new("err_z_deg", "attitude error about z", "deg");
// The errors of a source that knows only the vertical.
/// tilt error (angle of the vertical) (deg).
pub const TILT_ERR_DEG: Quantity =
    Quantity::new("tilt_err_deg", "tilt error (angle of the vertical)", "deg");
/// pitch error (deg).
pub const PITCH_ERR_DEG: Quantity = Quantity::new("pitch_err_deg", "pitch error", "deg");
/// roll error (deg).
pub const ROLL_ERR_DEG: Quantity = Quantity::new("roll_err_deg", "roll error", "deg");
// Its rate errors.
/// rate error about x (deg/s).
pub const RATE_ERR_X_DEG_S: Quantity =
    Quantity::new("rate_err_x_deg_s", "rate error about x", "deg/s");
/// rate error about y (deg/s).
pub const RATE_ERR_Y_DEG_S: Quantity =
    Quantity::new("rate_err_y_deg_s", "rate error about y", "deg/s");
/// rate error about z (deg/s).
pub const RATE_ERR_Z_DEG_S: Quantity =
    Quantity::new("rate_err_z_deg_s", "rate error about z", "deg/s");
// A single-axis source (papers 1 and 4): the angle about the axis, its rate and their errors.
/// angle (deg).
pub const ANGLE_DEG: Quantity = Quantity::new("angle_deg", "angle", "deg");
/// rate (deg/s).
pub const RATE_DEG_S: Quantity = Quantity::new("rate_deg_s", "rate", "deg/s");
/// angle error (deg).
pub const ANGLE_ERR_DEG: Quantity = Quantity::new("angle_err_deg", "angle error", "deg");
/// rate error (deg/s).
pub const RATE_ERR_DEG_S: Quantity = Quantity::new("rate_err_deg_s", "rate error", "deg/s");
