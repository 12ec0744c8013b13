//! What each state of [`super::Mekf`] is, for every [`StateSet`].

use super::StateSet;
use crate::model::{StateInfo, StateKind};

const STATES_6: [StateInfo; 6] = [
    StateInfo::new("att_x", "rad", StateKind::AttitudeAxis(0)),
    StateInfo::new("att_y", "rad", StateKind::AttitudeAxis(1)),
    StateInfo::new("att_z", "rad", StateKind::AttitudeAxis(2)),
    StateInfo::new("rate_x", "rad/s", StateKind::RateAxis(0)),
    StateInfo::new("rate_y", "rad/s", StateKind::RateAxis(1)),
    StateInfo::new("rate_z", "rad/s", StateKind::RateAxis(2)),
];
const STATES_GYRO_BIAS: [StateInfo; 9] = [
    STATES_6[0],
    STATES_6[1],
    STATES_6[2],
    STATES_6[3],
    STATES_6[4],
    STATES_6[5],
    StateInfo::new("gbias_x", "rad/s", StateKind::GyroBias(0)),
    StateInfo::new("gbias_y", "rad/s", StateKind::GyroBias(1)),
    StateInfo::new("gbias_z", "rad/s", StateKind::GyroBias(2)),
];
const STATES_MAG_BIAS: [StateInfo; 9] = [
    STATES_6[0],
    STATES_6[1],
    STATES_6[2],
    STATES_6[3],
    STATES_6[4],
    STATES_6[5],
    StateInfo::new("mbias_x", "nT", StateKind::MagBias(0)),
    StateInfo::new("mbias_y", "nT", StateKind::MagBias(1)),
    StateInfo::new("mbias_z", "nT", StateKind::MagBias(2)),
];
const STATES_REDUCED: [StateInfo; 6] = [
    STATES_6[0],
    STATES_6[1],
    STATES_6[2],
    StateInfo::new("gbias_x", "rad/s", StateKind::GyroBias(0)),
    StateInfo::new("gbias_y", "rad/s", StateKind::GyroBias(1)),
    StateInfo::new("gbias_z", "rad/s", StateKind::GyroBias(2)),
];

pub(super) fn states_of(s: StateSet) -> &'static [StateInfo] {
    match s {
        StateSet::AttRate => &STATES_6,
        StateSet::AttRateGyroBias => &STATES_GYRO_BIAS,
        StateSet::AttRateMagBias => &STATES_MAG_BIAS,
        StateSet::AttGyroBias => &STATES_REDUCED,
    }
}
