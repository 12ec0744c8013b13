//! The quantities every source can record — the truth's and each estimator's attitude,
//! rate and errors — each with its key, the student's label in the papers' notation, its
//! unit, plot group and the covariance state that bounds it.

use crate::model::{Quantity, SeriesGroup as G, StateInfo, StateKind as K};

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
    pub(super) quantity: Quantity,
    pub(super) group: G,
    pub(super) band: Option<K>,
}

const fn qi(q: Q, key: &'static str, label: &'static str, unit: &'static str, group: G) -> QInfo {
    QInfo {
        q,
        quantity: Quantity::new(key, label, unit),
        group,
        band: None,
    }
}

const fn qb(q: Q, key: &'static str, label: &'static str, unit: &'static str, kind: K) -> QInfo {
    QInfo {
        q,
        quantity: Quantity::new(key, label, unit),
        group: G::Error,
        band: Some(kind),
    }
}

/// A three-axis source's attitude (paper 3's notation for the vertical and w).
pub(super) const ATTITUDE_3: &[QInfo] = &[
    qi(Q::Yaw, "yaw_deg", "yaw ψ", "deg", G::Attitude),
    qi(Q::Pitch, "pitch_deg", "pitch ϑ", "deg", G::Attitude),
    qi(Q::Roll, "roll_deg", "roll γ", "deg", G::Attitude),
    qi(Q::Kx, "k_x", "vertical in body axes a′", "", G::Sphere),
    qi(Q::Ky, "k_y", "vertical in body axes b′", "", G::Sphere),
    qi(Q::Kz, "k_z", "vertical in body axes c′", "", G::Sphere),
    qi(Q::U, "u", "u = Re w", "", G::Sphere),
    qi(Q::V, "v", "v = Im w", "", G::Sphere),
    qi(
        Q::Z,
        "z_deg",
        "z (turn about the vertical)",
        "deg",
        G::Sphere,
    ),
];
pub(super) const RATE_3: &[QInfo] = &[
    qi(
        Q::RateX,
        "rate_x_deg_s",
        "body rate ω about x",
        "deg/s",
        G::Rate,
    ),
    qi(
        Q::RateY,
        "rate_y_deg_s",
        "body rate ω about y",
        "deg/s",
        G::Rate,
    ),
    qi(
        Q::RateZ,
        "rate_z_deg_s",
        "body rate ω about z",
        "deg/s",
        G::Rate,
    ),
];
pub(super) const ERRORS_3: &[QInfo] = &[
    qi(
        Q::ErrDeg,
        "err_deg",
        "attitude error (whole angle)",
        "deg",
        G::Error,
    ),
    qb(
        Q::ErrX,
        "err_x_deg",
        "attitude error about x",
        "deg",
        K::AttitudeAxis(0),
    ),
    qb(
        Q::ErrY,
        "err_y_deg",
        "attitude error about y",
        "deg",
        K::AttitudeAxis(1),
    ),
    qb(
        Q::ErrZ,
        "err_z_deg",
        "attitude error about z",
        "deg",
        K::AttitudeAxis(2),
    ),
];
pub(super) const TILT_ERRORS: &[QInfo] = &[
    qi(
        Q::TiltErr,
        "tilt_err_deg",
        "tilt error (angle of the vertical)",
        "deg",
        G::Error,
    ),
    qi(Q::PitchErr, "pitch_err_deg", "pitch error", "deg", G::Error),
    qi(Q::RollErr, "roll_err_deg", "roll error", "deg", G::Error),
];
pub(super) const RATE_ERRORS_3: &[QInfo] = &[
    qb(
        Q::RateErrX,
        "rate_err_x_deg_s",
        "rate error about x",
        "deg/s",
        K::RateAxis(0),
    ),
    qb(
        Q::RateErrY,
        "rate_err_y_deg_s",
        "rate error about y",
        "deg/s",
        K::RateAxis(1),
    ),
    qb(
        Q::RateErrZ,
        "rate_err_z_deg_s",
        "rate error about z",
        "deg/s",
        K::RateAxis(2),
    ),
];
/// A single-axis source (papers 1 and 4): the angle about the axis and its rate.
pub(super) const ANGLE_1: &[QInfo] = &[qi(Q::Angle, "angle_deg", "angle", "deg", G::Attitude)];
pub(super) const RATE_1: &[QInfo] = &[qi(Q::Rate1, "rate_deg_s", "rate", "deg/s", G::Rate)];
pub(super) const ERRORS_1: &[QInfo] = &[
    qb(Q::AngleErr, "angle_err_deg", "angle error", "deg", K::Angle),
    qb(
        Q::RateErr1,
        "rate_err_deg_s",
        "rate error",
        "deg/s",
        K::Rate,
    ),
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
        K::Angle => "angle".into(),
        K::Rate => "rate".into(),
        K::WzU => "u".into(),
        K::WzV => "v".into(),
        K::Other => s.key.replace('_', " "),
    }
}
