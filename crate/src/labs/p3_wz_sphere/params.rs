//! Paper 3's parameters: the truth's motion (the paper's, a coning, a slow tumble, a free
//! body) and its sliders, each acting in the motions that use it; the gyro, the
//! accelerometers, the blend and the Kalman filter.

use crate::model::ParamSpec;

const PROFILES: &[&str] = &[
    "paper 3: yaw ramp, harmonic pitch & roll",
    "coning (pitch/roll 90° apart)",
    "slow tumble (turns upside down)",
    "free rotation (torque free)",
];

const BIAS_AXES: &[&str] = &[
    "all three axes (+, +, +)",
    "ξ only",
    "η only",
    "ζ only",
    "alternating (+, −, +)",
];

/// The motions (`profile`) each slider of the motion acts in (see [`super::motion_of`]): the
/// paper's alone, every prescribed one (pitch acts in the coning and the tumble too), those
/// that turn in yaw, the tumble alone.
const PAPER_MOTION: &[f64] = &[0.0];
const PRESCRIBED: &[f64] = &[0.0, 1.0, 2.0];
const TURNING_IN_YAW: &[f64] = &[0.0, 2.0];
const TUMBLE: &[f64] = &[2.0];

pub(super) const PARAMS: &[ParamSpec] = &[
    ParamSpec::choice("profile", "Motion", PROFILES, 0)
        .on_reset()
        .help("Which truth motion (applies at Reset)."),
    ParamSpec::real("roll_amp_deg", "Roll amplitude A_γ", "°", 0.0, 90.0, 25.0)
        .on_reset()
        .requires_one_of("profile", PAPER_MOTION)
        .help("Paper: 25°."),
    ParamSpec::real("pitch_amp_deg", "Pitch amplitude A_ϑ", "°", 0.0, 89.0, 30.0)
        .on_reset()
        .requires_one_of("profile", PRESCRIBED)
        .help("Paper: 30°; also the cone half-angle of the coning motion."),
    ParamSpec::real("yaw_rate_deg_s", "Yaw rate ω_ψ", "°/s", -20.0, 20.0, 1.0)
        .on_reset()
        .requires_one_of("profile", TURNING_IN_YAW)
        .help("Paper: 1 °/s."),
    ParamSpec::real(
        "pitch_freq_rad_s",
        "Pitch frequency ω_ϑ",
        "rad/s",
        0.001,
        2.0,
        0.05,
    )
    .log()
    .on_reset()
    .requires_one_of("profile", PRESCRIBED)
    .help("Paper: 0.05 rad/s."),
    ParamSpec::real(
        "roll_freq_rad_s",
        "Roll frequency ω_γ",
        "rad/s",
        0.001,
        2.0,
        0.05,
    )
    .log()
    .on_reset()
    .requires_one_of("profile", PAPER_MOTION)
    .help("Paper: 0.05 rad/s."),
    ParamSpec::real(
        "tumble_rate_deg_s",
        "Tumble roll rate",
        "°/s",
        0.5,
        90.0,
        6.0,
    )
    .log()
    .on_reset()
    .requires_one_of("profile", TUMBLE)
    .help("Roll rate of the slow tumble."),
    ParamSpec::real("gyro_bias_deg_s", "Gyro bias", "°/s", 0.0, 2.0, 0.1)
        .log()
        .help("Zero offset on all three axes (paper: 0.1 °/s); gyro-only integration drifts."),
    ParamSpec::choice("bias_axes", "Bias on", BIAS_AXES, 0)
        .help("Which gyro axes carry the bias (the paper: presumably all three)."),
    ParamSpec::real("gyro_noise_deg_s", "Gyro noise σ", "°/s", 0.0, 1.0, 0.0)
        .log()
        .help("White noise per sample (the paper has none)."),
    ParamSpec::real(
        "accel_noise_g",
        "Accelerometer noise σ",
        "g",
        0.0,
        0.2,
        0.01,
    )
    .log()
    .help("White noise per axis (paper: 0.01 g); accelerometer-only (uᵃ, vᵃ) is noisy."),
    ParamSpec::real("bump_g", "Lateral bump", "g", 0.0, 2.0, 0.0)
        .help("A 2-s horizontal acceleration pulse: accelerometers cannot tell it from tilt."),
    ParamSpec::real("bump_time_s", "Bump time", "s", 0.0, 100.0, 50.0)
        .requires("bump_g")
        .help("When the bump peaks."),
    ParamSpec::real(
        "blend_time_const_s",
        "Blend time constant T",
        "s",
        0.01,
        100.0,
        1.0,
    )
    .log()
    .help("T of HPF = Ts/(Ts+1) and LPF = 1/(Ts+1) (paper: 1 s)."),
    ParamSpec::real("kf_q_scale", "KF process-noise scale", "", 0.01, 100.0, 1.0)
        .log()
        .help("Scales the Kalman filter's process noise: larger trusts the accelerometer more."),
    ParamSpec::real("rate_hz", "Sample rate", "Hz", 10.0, 1000.0, 100.0)
        .log()
        .integer()
        .help("Gyro and accelerometer rate = simulation rate."),
];
