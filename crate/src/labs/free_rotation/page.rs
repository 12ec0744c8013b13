//! What the free-rotation lab shows beside the standard tabs: its figures.

use crate::model::Figure;

pub(super) const FIGURES: &[Figure] = &[
    Figure::new(
        "Attitude (yaw, pitch, roll)",
        &[
            "truth.yaw_deg",
            "truth.pitch_deg",
            "truth.roll_deg",
            "quat-rk4.yaw_deg",
            "quat-rk4.pitch_deg",
            "quat-rk4.roll_deg",
        ],
    ),
    Figure::new(
        "Attitude errors (body axes)",
        &[
            "quat-rk4.err_x_deg",
            "quat-rk4.err_y_deg",
            "quat-rk4.err_z_deg",
            "uvz-rk4.err_deg",
            "quat-rk4.err_deg",
        ],
    ),
    Figure::new(
        "Energy and momentum (truth)",
        &["truth.energy_j", "truth.momentum_n_m_s"],
    ),
];
