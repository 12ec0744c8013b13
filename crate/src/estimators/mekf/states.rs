//! What each state of [`super::Mekf`] is, for every [`StateSet`].

use super::StateSet;
use crate::model::{StateInfo, StateKind};

/// Attitude error about body x (rad).
pub const ATT_X: StateInfo = StateInfo::new("att_x", "rad", StateKind::AttitudeAxis(0));
/// Attitude error about body y (rad).
pub const ATT_Y: StateInfo = StateInfo::new("att_y", "rad", StateKind::AttitudeAxis(1));
/// Attitude error about body z (rad).
pub const ATT_Z: StateInfo = StateInfo::new("att_z", "rad", StateKind::AttitudeAxis(2));
/// Body rate about x (rad/s).
pub const RATE_X: StateInfo = StateInfo::new("rate_x", "rad/s", StateKind::RateAxis(0));
/// Body rate about y (rad/s).
pub const RATE_Y: StateInfo = StateInfo::new("rate_y", "rad/s", StateKind::RateAxis(1));
/// Body rate about z (rad/s).
pub const RATE_Z: StateInfo = StateInfo::new("rate_z", "rad/s", StateKind::RateAxis(2));
/// Gyro bias about x (rad/s).
pub const GBIAS_X: StateInfo = StateInfo::new("gbias_x", "rad/s", StateKind::GyroBias(0));
/// Gyro bias about y (rad/s).
pub const GBIAS_Y: StateInfo = StateInfo::new("gbias_y", "rad/s", StateKind::GyroBias(1));
/// Gyro bias about z (rad/s).
pub const GBIAS_Z: StateInfo = StateInfo::new("gbias_z", "rad/s", StateKind::GyroBias(2));
/// Magnetometer bias along x (nT).
pub const MBIAS_X: StateInfo = StateInfo::new("mbias_x", "nT", StateKind::MagBias(0));
/// Magnetometer bias along y (nT).
pub const MBIAS_Y: StateInfo = StateInfo::new("mbias_y", "nT", StateKind::MagBias(1));
/// Magnetometer bias along z (nT).
pub const MBIAS_Z: StateInfo = StateInfo::new("mbias_z", "nT", StateKind::MagBias(2));

/// Magnetometer bias: turn of the field about x (rad).
pub const MTURN_X: StateInfo = StateInfo::new("mturn_x", "rad", StateKind::MagTurn(0));
/// Magnetometer bias: turn of the field about y (rad).
pub const MTURN_Y: StateInfo = StateInfo::new("mturn_y", "rad", StateKind::MagTurn(1));
/// Magnetometer bias: turn of the field about z (rad).
pub const MTURN_Z: StateInfo = StateInfo::new("mturn_z", "rad", StateKind::MagTurn(2));

const STATES_6: [StateInfo; 6] = [ATT_X, ATT_Y, ATT_Z, RATE_X, RATE_Y, RATE_Z];
const STATES_GYRO_BIAS: [StateInfo; 9] = [
    ATT_X, ATT_Y, ATT_Z, RATE_X, RATE_Y, RATE_Z, GBIAS_X, GBIAS_Y, GBIAS_Z,
];
const STATES_MAG_BIAS: [StateInfo; 9] = [
    ATT_X, ATT_Y, ATT_Z, RATE_X, RATE_Y, RATE_Z, MBIAS_X, MBIAS_Y, MBIAS_Z,
];
const STATES_MAG_TURN: [StateInfo; 9] = [
    ATT_X, ATT_Y, ATT_Z, RATE_X, RATE_Y, RATE_Z, MTURN_X, MTURN_Y, MTURN_Z,
];
const STATES_REDUCED: [StateInfo; 6] = [ATT_X, ATT_Y, ATT_Z, GBIAS_X, GBIAS_Y, GBIAS_Z];

pub(super) fn states_of(s: StateSet) -> &'static [StateInfo] {
    match s {
        StateSet::AttRate => &STATES_6,
        StateSet::AttRateGyroBias => &STATES_GYRO_BIAS,
        StateSet::AttRateMagBias => &STATES_MAG_BIAS,
        StateSet::AttRateMagTurn => &STATES_MAG_TURN,
        StateSet::AttGyroBias => &STATES_REDUCED,
    }
}
