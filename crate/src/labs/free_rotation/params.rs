//! The free-rotation lab's parameters: the body's inertia and initial spin, the gyro's
//! errors and its rate.

use crate::model::ParamSpec;

const SPIN_AXES: &[&str] = &[
    "x (smallest I: stable)",
    "y (intermediate I: flips)",
    "z (largest I: stable)",
];

pub(super) const PARAMS: &[ParamSpec] = &[
    ParamSpec::real("inertia_x_kg_m2", "Inertia Ixx", "kg·m²", 0.1, 10.0, 1.0)
        .log()
        .help("Principal moment of inertia about body x."),
    ParamSpec::real("inertia_y_kg_m2", "Inertia Iyy", "kg·m²", 0.1, 10.0, 2.0)
        .log()
        .help("Principal moment of inertia about body y."),
    ParamSpec::real("inertia_z_kg_m2", "Inertia Izz", "kg·m²", 0.1, 10.0, 3.0)
        .log()
        .help("Principal moment of inertia about body z."),
    ParamSpec::real("spin_deg_s", "Initial spin", "°/s", 0.0, 360.0, 40.0)
        .on_reset()
        .help("Initial rotation rate (applies at reset)."),
    ParamSpec::choice("spin_axis", "Spin axis", SPIN_AXES, 1)
        .on_reset()
        .help("Axis of the initial spin; the intermediate axis is unstable and the body flips."),
    ParamSpec::real("tilt_deg", "Initial tilt", "°", 0.0, 180.0, 20.0)
        .on_reset()
        .help("Initial roll of the body from level (applies at reset)."),
    ParamSpec::real("gyro_noise_deg_s", "Gyro noise σ", "°/s", 0.0, 2.0, 0.02)
        .log()
        .help("White noise of each gyro sample; it accumulates as an angle random walk."),
    ParamSpec::real("gyro_bias_deg_s", "Gyro bias", "°/s", 0.0, 2.0, 0.1)
        .log()
        .help("Constant zero offset on each axis (+, −, +); integration turns it into a drift."),
    ParamSpec::real(
        "gyro_walk_deg_s_sqrt_s",
        "Bias random walk",
        "°/s/√s",
        0.0,
        0.1,
        0.0,
    )
    .log()
    .help("Bias instability: the bias itself drifts as a random walk."),
    ParamSpec::real("rate_hz", "Sample rate", "Hz", 10.0, 1000.0, 100.0)
        .log()
        .integer()
        .help("Gyro sample rate = simulation rate."),
];
