//! The quantities every source can record — the truth's and each estimator's attitude,
//! rate and errors — each with its key, the student's label in the papers' notation, its
//! unit, plot group and the covariance state that bounds it.

use crate::model::{Quantity, SeriesGroup as G, StateInfo, StateKind as K, q};

/// A quantity of the truth or of an estimate, derived from its attitude, rate or angle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Q {
    Yaw,
    Pitch,
    Roll,
    Kx,
    Ky,
    Kz,
    U,
    V,
    Z,
    RateX,
    RateY,
    RateZ,
    Angle,
    Rate1,
    ErrDeg,
    TiltErr,
    PitchErr,
    RollErr,
    ErrX,
    ErrY,
    ErrZ,
    RateErrX,
    RateErrY,
    RateErrZ,
    AngleErr,
    RateErr1,
}

pub(super) const N_Q: usize = Q::RateErr1 as usize + 1;

/// What each quantity is called (its key, the student's label, its unit), its plot, and the
/// covariance state bounding it.
pub(super) struct QInfo {
    pub(super) q: Q,
    pub(super) quantity: &'static Quantity,
    pub(super) group: G,
    pub(super) band: Option<K>,
}

const fn qi(q: Q, quantity: &'static Quantity, group: G) -> QInfo {
    QInfo {
        q,
        quantity,
        group,
        band: None,
    }
}

const fn qb(q: Q, quantity: &'static Quantity, kind: K) -> QInfo {
    QInfo {
        q,
        quantity,
        group: G::Error,
        band: Some(kind),
    }
}

/// A three-axis source's attitude (paper 3's notation for the vertical and w).
pub(super) const ATTITUDE_3: &[QInfo] = &[
    qi(Q::Yaw, &q::YAW_DEG, G::Attitude),
    qi(Q::Pitch, &q::PITCH_DEG, G::Attitude),
    qi(Q::Roll, &q::ROLL_DEG, G::Attitude),
    qi(Q::Kx, &q::K_X, G::Sphere),
    qi(Q::Ky, &q::K_Y, G::Sphere),
    qi(Q::Kz, &q::K_Z, G::Sphere),
    qi(Q::U, &q::U, G::Sphere),
    qi(Q::V, &q::V, G::Sphere),
    qi(Q::Z, &q::Z_DEG, G::Sphere),
];
pub(super) const RATE_3: &[QInfo] = &[
    qi(Q::RateX, &q::RATE_X_DEG_S, G::Rate),
    qi(Q::RateY, &q::RATE_Y_DEG_S, G::Rate),
    qi(Q::RateZ, &q::RATE_Z_DEG_S, G::Rate),
];
pub(super) const ERRORS_3: &[QInfo] = &[
    qi(Q::ErrDeg, &q::ERR_DEG, G::Error),
    qb(Q::ErrX, &q::ERR_X_DEG, K::AttitudeAxis(0)),
    qb(Q::ErrY, &q::ERR_Y_DEG, K::AttitudeAxis(1)),
    qb(Q::ErrZ, &q::ERR_Z_DEG, K::AttitudeAxis(2)),
];
pub(super) const TILT_ERRORS: &[QInfo] = &[
    qi(Q::TiltErr, &q::TILT_ERR_DEG, G::Error),
    qi(Q::PitchErr, &q::PITCH_ERR_DEG, G::Error),
    qi(Q::RollErr, &q::ROLL_ERR_DEG, G::Error),
];
pub(super) const RATE_ERRORS_3: &[QInfo] = &[
    qb(Q::RateErrX, &q::RATE_ERR_X_DEG_S, K::RateAxis(0)),
    qb(Q::RateErrY, &q::RATE_ERR_Y_DEG_S, K::RateAxis(1)),
    qb(Q::RateErrZ, &q::RATE_ERR_Z_DEG_S, K::RateAxis(2)),
];
/// A single-axis source (papers 1 and 4): the angle about the axis and its rate.
pub(super) const ANGLE_1: &[QInfo] = &[qi(Q::Angle, &q::ANGLE_DEG, G::Attitude)];
pub(super) const RATE_1: &[QInfo] = &[qi(Q::Rate1, &q::RATE_DEG_S, G::Rate)];
pub(super) const ERRORS_1: &[QInfo] = &[
    qb(Q::AngleErr, &q::ANGLE_ERR_DEG, K::Angle),
    qb(Q::RateErr1, &q::RATE_ERR_DEG_S, K::Rate),
];

/// What a covariance state is, in words.
pub(super) fn state_label(s: &StateInfo) -> String {
    const AXES: [&str; 3] = ["x", "y", "z"];
    let axis = |a: u8| AXES.get(usize::from(a)).copied().unwrap_or("?");
    match s.kind {
        K::AttitudeAxis(a) => format!("attitude about {}", axis(a)),
        K::RateAxis(a) => format!("rate about {}", axis(a)),
        K::GyroBias(a) => format!("gyro bias about {}", axis(a)),
        K::MagBias(a) => format!("magnetometer bias along {}", axis(a)),
        K::MagTurn(a) => format!("magnetometer bias: turn of the field about {}", axis(a)),
        K::Angle => "angle".into(),
        K::Rate => "rate".into(),
        K::WzU => "u".into(),
        K::WzV => "v".into(),
        K::Other => s.key.replace('_', " "),
    }
}
