//! Paper 5's parameters: the motion, the gyro's errors, the references and their
//! interval, each method's settings; the estimators the lab runs; its presets.

use crate::estimators::{Method, SensitivitySettings};
use crate::math::{ANGLE_SEQUENCES, RK_METHOD_NAMES, RK_METHODS, RK4};
use crate::model::{ParamSpec, ParamValues, Preset};

const PROFILES: &[&str] = &[
    "paper: constant attitude, ω = 0",
    "constant rate",
    "harmonic rate",
];

/// The estimators, in legend order: (id, label, method).
pub const METHODS: &[(&str, &str, Method)] = &[
    ("gn9", "Method (9): Gauss–Newton step", Method::Plain),
    ("lm10", "Method (10): regularised, ε", Method::Regularised),
    (
        "search11",
        "Method (11): step-size search",
        Method::StepSearch,
    ),
    (
        "reint",
        "Beyond the paper: re-integrate the last interval",
        Method::Reintegrate,
    ),
    ("raw", "Uncorrected integration", Method::Uncorrected),
];

const METHOD_NAMES: &[&str] = &[
    "(9) Gauss–Newton",
    "(10) regularised",
    "(11) step-size search",
    "re-integrating variant",
    "uncorrected",
];

const SEQUENCE_NAMES: &[&str] = &[
    ANGLE_SEQUENCES[0].0,
    ANGLE_SEQUENCES[1].0,
    ANGLE_SEQUENCES[2].0,
    ANGLE_SEQUENCES[3].0,
    ANGLE_SEQUENCES[4].0,
    ANGLE_SEQUENCES[5].0,
];

pub(super) const PARAMS: &[ParamSpec] = &[
    ParamSpec::choice("profile", "Motion", PROFILES, 0).on_reset().help("The paper's experiment holds the attitude still: the correction p steers the estimate to the reference."),
    ParamSpec::real("rate_deg_s", "Rate", "°/s", 0.0, 60.0, 10.0).on_reset().requires_one_of("profile", &[1.0, 2.0]).help("Size of the constant or harmonic rate (axis (1, 2, 3)/√14)."),
    ParamSpec::real("rate_freq_rad_s", "Harmonic frequency", "rad/s", 0.01, 5.0, 0.5).log().on_reset().requires_one_of("profile", &[2.0]),
    ParamSpec::choice("sequence", "Angle sequence", SEQUENCE_NAMES, 0).on_reset().help("Krylov angles are z-y′-x″ (the digest's assumption); the others for comparison."),
    ParamSpec::real("init_1_rad", "Initial angle 1", "rad", -3.0, 3.0, 0.5).on_reset().help("Paper: (0.5, 0.7, 0.2)."),
    ParamSpec::real("init_2_rad", "Initial angle 2", "rad", -1.5, 1.5, 0.7).on_reset(),
    ParamSpec::real("init_3_rad", "Initial angle 3", "rad", -3.0, 3.0, 0.2).on_reset(),
    ParamSpec::real("ref_1_rad", "Reference angle 1", "rad", -3.0, 3.0, 0.01).on_reset().help("Paper: (0.01, 0.02, 0.01): the truth's initial attitude."),
    ParamSpec::real("ref_2_rad", "Reference angle 2", "rad", -1.5, 1.5, 0.02).on_reset(),
    ParamSpec::real("ref_3_rad", "Reference angle 3", "rad", -3.0, 3.0, 0.01).on_reset(),
    ParamSpec::real("interval_s", "Reference interval Δt", "s", 0.05, 5.0, 1.0).log().help("Not given in the paper; method (9) first meets the tolerance just after 2Δt (2.36 near Δt = 1.17)."),
    ParamSpec::real("step_s", "Integration step", "s", 0.001, 0.1, 0.01).log().on_reset(),
    ParamSpec::choice("integration", "Integration method", &RK_METHOD_NAMES, 0).help("How Λ and U are integrated between gyro samples (the paper makes it a setting and does not say which it used). Euler is a quarter of RK4's work and first order: at a coarse step its drift becomes the error the references must correct."),
    ParamSpec::real("eps", "Regularisation ε", "", 0.0, 10.0, 0.1).log().help("Methods (10) and (11): (UᵀQU + εI)⁻¹. Method (9) and the re-integrating variant use ε = 0."),
    ParamSpec::real("q_weight_0", "Weight Q₀₀ (λ₀)", "", 0.01, 100.0, 1.0).log(),
    ParamSpec::real("q_weight_1", "Weight Q₁₁ (λ₁)", "", 0.01, 100.0, 1.0).log(),
    ParamSpec::real("q_weight_2", "Weight Q₂₂ (λ₂)", "", 0.01, 100.0, 1.0).log(),
    ParamSpec::real("q_weight_3", "Weight Q₃₃ (λ₃)", "", 0.01, 100.0, 1.0).log(),
    ParamSpec::real("p0_x_deg_s", "Initial p x", "°/s", -30.0, 30.0, 0.0).on_reset(),
    ParamSpec::real("p0_y_deg_s", "Initial p y", "°/s", -30.0, 30.0, 0.0).on_reset(),
    ParamSpec::real("p0_z_deg_s", "Initial p z", "°/s", -30.0, 30.0, 0.0).on_reset(),
    ParamSpec::real("tolerance_rad", "Tolerance per angle", "rad", 1e-4, 0.5, 0.01).log().help("Paper: 0.01; the output file ends at the first row within it."),
    ParamSpec::toggle("renormalise", "Renormalise Λ each step", false),
    ParamSpec::real("gyro_bias_deg_s", "Gyro bias", "°/s", 0.0, 10.0, 0.0).help("ω_meas = ω + b along (1, −1, 2)/√6: p should converge to −b."),
    ParamSpec::real("gyro_noise_deg_s", "Gyro noise σ", "°/s", 0.0, 5.0, 0.0).log(),
    ParamSpec::real("ref_noise_rad", "Reference noise σ", "rad", 0.0, 0.1, 0.0).log().help("Per axis, on each reference attitude."),
    ParamSpec::real("dropout_from_s", "Reference lost at", "s", 0.0, 600.0, 20.0).requires("dropout_s"),
    ParamSpec::real("dropout_s", "Reference lost for", "s", 0.0, 120.0, 0.0).help("No references in this window: the corrected integration runs free, then re-converges."),
    ParamSpec::choice("output_method", "Output file of", METHOD_NAMES, 0).outside_run().help("Whose angles the output file (t, angle₁, angle₂, angle₃) holds."),
];

pub(super) const PRESETS: &[Preset] = &[
    Preset {
        id: "paper-case",
        name: "paper's case, Δt = 1.17",
        help: "The interval at which method (9) first meets 0.01 at t ≈ 2.36, the paper's number",
        values: &[("profile", 0.0), ("interval_s", 1.17)],
    },
    Preset {
        id: "gyro-bias",
        name: "gyro bias 2 °/s",
        help: "A turning body, a biased gyro: p converges to −b",
        values: &[
            ("profile", 1.0),
            ("gyro_bias_deg_s", 2.0),
            ("eps", 0.01),
            ("init_1_rad", 0.01),
            ("init_2_rad", 0.02),
            ("init_3_rad", 0.01),
        ],
    },
    Preset {
        id: "reference-lost",
        name: "reference lost 20–50 s",
        help: "The reference drops out for 30 s: free-running drift, then re-convergence",
        values: &[
            ("profile", 1.0),
            ("gyro_bias_deg_s", 2.0),
            ("init_1_rad", 0.01),
            ("init_2_rad", 0.02),
            ("init_3_rad", 0.01),
            ("dropout_from_s", 20.0),
            ("dropout_s", 30.0),
        ],
    },
];

/// The angle sequence the parameters choose (Krylov z-y′-x″ when out of range).
pub(super) fn axes_of(p: &ParamValues) -> [usize; 3] {
    ANGLE_SEQUENCES
        .get(p.index("sequence"))
        .map_or([2, 1, 0], |s| s.1)
}

/// Every method's settings in `p`: ε, the weights of Q, the renormalisation, the angle
/// sequence and the tolerance.
pub(super) fn settings_of(p: &ParamValues) -> SensitivitySettings {
    SensitivitySettings {
        eps: p.get("eps"),
        weights: [
            p.get("q_weight_0"),
            p.get("q_weight_1"),
            p.get("q_weight_2"),
            p.get("q_weight_3"),
        ],
        renormalise: p.flag("renormalise"),
        axes: axes_of(p),
        tolerance_rad: p.get("tolerance_rad"),
        integrator: RK_METHODS
            .get(p.index("integration"))
            .copied()
            .unwrap_or(&RK4),
        history_steps: history_steps(p),
    }
}

/// The longest gap between references a run can have, in integration steps: a dropout and
/// the intervals either side of it (at most ≈ 1.3·10⁵ steps at 1 ms).
fn history_steps(p: &ParamValues) -> usize {
    let gap_s = p.get("dropout_s") + 2.0 * p.get("interval_s");
    let steps = (gap_s / p.get("step_s").max(1e-6)).ceil() + 2.0;
    steps.clamp(16.0, f64::from(1u32 << 20)) as usize
}
