//! What the free-rotation lab shows beside the standard tabs: its figures.

use crate::model::{SeriesKey, q};
use crate::page::Figure;

pub(super) const FIGURES: &[Figure] = &[
    Figure::new(
        "attitude",
        "Attitude (yaw, pitch, roll)",
        &[
            SeriesKey::truth(&q::YAW_DEG),
            SeriesKey::truth(&q::PITCH_DEG),
            SeriesKey::truth(&q::ROLL_DEG),
            SeriesKey::new("quat-rk4", &q::YAW_DEG),
            SeriesKey::new("quat-rk4", &q::PITCH_DEG),
            SeriesKey::new("quat-rk4", &q::ROLL_DEG),
        ],
    ),
    Figure::new(
        "errors",
        "Attitude errors (body axes)",
        &[
            SeriesKey::new("quat-rk4", &q::ERR_X_DEG),
            SeriesKey::new("quat-rk4", &q::ERR_Y_DEG),
            SeriesKey::new("quat-rk4", &q::ERR_Z_DEG),
            SeriesKey::new("uvz-rk4", &q::ERR_DEG),
            SeriesKey::new("quat-rk4", &q::ERR_DEG),
        ],
    ),
    Figure::new(
        "energy-momentum",
        "Energy and momentum (truth)",
        &[
            SeriesKey::truth(&super::truth::ENERGY_J),
            SeriesKey::truth(&super::truth::MOMENTUM_N_M_S),
        ],
    ),
];
