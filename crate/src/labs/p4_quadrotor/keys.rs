//! The keys of p4's filter parameters (only this lab reads them: the filters get their
//! tuning from [`super::tuning_of`]).

/// γ = det Q / det R.
pub const GAMMA: &str = "gamma";
/// Feed the controller's u_v to the paper's filter (toggle).
pub const INPUT: &str = "kf_input";
/// The filter's assumed accelerometer-angle σ (deg).
pub const SIGMA_ANGLE: &str = "kf_sigma_angle_deg";
/// The filter's assumed gyro σ (deg/s).
pub const SIGMA_RATE: &str = "kf_sigma_rate_deg_s";
/// Random-walk density of the bias state (deg/s/√s).
pub const BIAS_WALK: &str = "kf_bias_walk";
/// Complementary-filter gain a.
pub const CF_GAIN: &str = "cf_gain";
/// Where Q comes from: 0 = γ (the paper), 1 = two elements.
pub const Q_FROM: &str = "kf_q_from";
/// Q's angle element per step (deg²), when Q is set element by element.
pub const Q_ANGLE: &str = "kf_q_angle_deg2";
/// Q's rate element per step ((deg/s)²), when Q is set element by element.
pub const Q_RATE: &str = "kf_q_rate_deg2_s2";
