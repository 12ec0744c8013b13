//! Lab "p5": paper 5 — correcting measured angular rates from reference attitudes with the
//! sensitivity matrix (Bashniakov, Pichkur, Polishchuk, Linder). A body turns (or, in the
//! paper's case, holds still); its measured rates drive quaternion kinematics with an
//! additive correction p, which every reference attitude updates by one Gauss–Newton step
//! through U = ∂Λ/∂p. The paper's three update rules and a re-integrating variant run side by
//! side on the same measurements.

mod reproduce;

use crate::estimators::{
    Method, SensitivityCorrection, SensitivitySettings, linearised_eigenvalues,
};
use crate::math::{ANGLE_SEQUENCES, quaternion_from_sequence};
use crate::model::{
    Diagram, DiagramPoint, Estimator, Figure, Lab, LabRun, Measurements, OutputFile, ParamSpec,
    ParamValues, Preset, ReproError, Reproduction, SensorModel, SeriesGroup, SeriesSpec,
    TruthModel, TruthState,
};
use crate::sensors::WhiteNoise;
use nalgebra::{UnitQuaternion, Vector3};
use rand_chacha::ChaCha8Rng;

pub use reproduce::first_hit_s;

/// The paper-5 lab.
pub struct SensitivityLab;

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

const PARAMS: &[ParamSpec] = &[
    ParamSpec::choice("profile", "Motion", PROFILES, 0).on_reset().help("The paper's experiment holds the attitude still: the correction p steers the estimate to the reference."),
    ParamSpec::real("rate_deg_s", "Rate", "°/s", 0.0, 60.0, 10.0).on_reset().help("Size of the constant or harmonic rate (axis (1, 2, 3)/√14)."),
    ParamSpec::real("rate_freq_rad_s", "Harmonic frequency", "rad/s", 0.01, 5.0, 0.5).log().on_reset(),
    ParamSpec::choice("sequence", "Angle sequence", SEQUENCE_NAMES, 0).on_reset().help("Krylov angles are z-y′-x″ (the digest's assumption); the others for comparison."),
    ParamSpec::real("init_1_rad", "Initial angle 1", "rad", -3.0, 3.0, 0.5).on_reset().help("Paper: (0.5, 0.7, 0.2)."),
    ParamSpec::real("init_2_rad", "Initial angle 2", "rad", -1.5, 1.5, 0.7).on_reset(),
    ParamSpec::real("init_3_rad", "Initial angle 3", "rad", -3.0, 3.0, 0.2).on_reset(),
    ParamSpec::real("ref_1_rad", "Reference angle 1", "rad", -3.0, 3.0, 0.01).on_reset().help("Paper: (0.01, 0.02, 0.01): the truth's initial attitude."),
    ParamSpec::real("ref_2_rad", "Reference angle 2", "rad", -1.5, 1.5, 0.02).on_reset(),
    ParamSpec::real("ref_3_rad", "Reference angle 3", "rad", -3.0, 3.0, 0.01).on_reset(),
    ParamSpec::real("interval_s", "Reference interval Δt", "s", 0.05, 5.0, 1.0).log().help("Not given in the paper; method (9) first meets the tolerance just after 2Δt (2.36 near Δt = 1.17)."),
    ParamSpec::real("step_s", "Integration step", "s", 0.001, 0.1, 0.01).log().on_reset(),
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
    ParamSpec::choice("output_method", "Output file of", METHOD_NAMES, 0).export_only().help("Whose angles the output file (t, angle₁, angle₂, angle₃) holds."),
];

const FIGURES: &[Figure] = &[
    Figure::new(
        "Attitude error (all methods)",
        &[
            "gn9.err_deg",
            "lm10.err_deg",
            "search11.err_deg",
            "reint.err_deg",
            "raw.err_deg",
        ],
    )
    .log(),
    Figure::new(
        "Angles of method (9) and the reference",
        &[
            "gn9.angle_1_rad",
            "gn9.angle_2_rad",
            "gn9.angle_3_rad",
            "truth.angle_1_rad",
            "truth.angle_2_rad",
            "truth.angle_3_rad",
        ],
    ),
    Figure::new(
        "Correction p (9)",
        &["gn9.p_x_deg_s", "gn9.p_y_deg_s", "gn9.p_z_deg_s"],
    ),
    Figure::new(
        "Correction p (variant)",
        &["reint.p_x_deg_s", "reint.p_y_deg_s", "reint.p_z_deg_s"],
    ),
    Figure::new(
        "Condition number of UᵀQU",
        &["gn9.cond_utqu", "lm10.cond_utqu", "reint.cond_utqu"],
    )
    .log(),
    Figure::new(
        "Singular values of UᵀQU (9)",
        &["gn9.sv1", "gn9.sv2", "gn9.sv3"],
    )
    .log(),
    Figure::new("Step size s of method (11)", &["search11.step_s"]),
    Figure::new("References received", &["sensors.reference"]),
];

const PRESETS: &[Preset] = &[
    Preset {
        name: "paper's case, Δt = 1.17",
        help: "The interval at which method (9) first meets 0.01 at t ≈ 2.36, the paper's number",
        values: &[("profile", 0.0), ("interval_s", 1.17)],
    },
    Preset {
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

/// The fixed rate axis of the turning profiles.
fn rate_axis() -> Vector3<f64> {
    Vector3::new(1.0, 2.0, 3.0).normalize()
}

/// The truth: the reference attitude turned by the profile's rate.
struct Turning {
    q: UnitQuaternion<f64>,
    t_s: f64,
    profile: usize,
    rate_rad_s: f64,
    freq_rad_s: f64,
    axes: [usize; 3],
}

impl Turning {
    fn rate(&self, t: f64) -> Vector3<f64> {
        match self.profile {
            0 => Vector3::zeros(),
            1 => rate_axis() * self.rate_rad_s,
            _ => rate_axis() * self.rate_rad_s * (self.freq_rad_s * t).sin(),
        }
    }
}

impl TruthModel for Turning {
    fn apply_params(&mut self, _p: &ParamValues) {}

    fn step(&mut self, dt_s: f64) {
        let t0 = self.t_s;
        self.q = crate::math::step_quaternion_rk4(&self.q, |f| self.rate(t0 + f * dt_s), dt_s);
        self.t_s += dt_s;
    }

    fn state(&self) -> TruthState {
        TruthState::new(self.t_s, self.q, self.rate(self.t_s))
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        (1..=3)
            .map(|i| {
                SeriesSpec::new(format!("truth.angle_{i}_rad"), "rad", SeriesGroup::Attitude)
                    .labelled(format!("angle {i} of the sequence"))
            })
            .collect()
    }

    fn extra_values(&self, out: &mut [f64]) {
        out.copy_from_slice(&crate::math::sequence_from_quaternion(self.axes, &self.q));
    }
}

/// The gyro and the reference attitudes (every Δt, except during a dropout).
struct Sensors {
    interval_s: f64,
    since_s: f64,
    bias: Vector3<f64>,
    noise: f64,
    ref_noise: f64,
    dropout: (f64, f64),
    delivered: bool,
}

impl SensorModel for Sensors {
    fn apply_params(&mut self, p: &ParamValues) {
        self.interval_s = p.get("interval_s");
        self.bias =
            Vector3::new(1.0, -1.0, 2.0).normalize() * p.get("gyro_bias_deg_s").to_radians();
        self.noise = p.get("gyro_noise_deg_s").to_radians();
        self.ref_noise = p.get("ref_noise_rad");
        let from = p.get("dropout_from_s");
        self.dropout = (from, from + p.get("dropout_s"));
    }

    fn sample(&mut self, truth: &TruthState, dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements {
        let noise = WhiteNoise { sigma: self.noise };
        let gyro = truth.rate_body_rad_s + self.bias + Vector3::from_fn(|_, _| noise.sample(rng));
        self.since_s += dt_s;
        // A reference every Δt (to within half a step).
        let due = self.since_s >= self.interval_s - 0.5 * dt_s;
        let lost = truth.t_s >= self.dropout.0 && truth.t_s < self.dropout.1;
        let mut reference = None;
        if due {
            self.since_s = 0.0;
            if !lost {
                let n = WhiteNoise {
                    sigma: self.ref_noise,
                };
                let err = Vector3::from_fn(|_, _| n.sample(rng));
                reference = Some(truth.q_ref_from_body * UnitQuaternion::from_scaled_axis(err));
            }
        }
        self.delivered = reference.is_some();
        Measurements {
            t_s: truth.t_s,
            gyro_body_rad_s: Some(gyro),
            star_q_ref_from_body: reference,
            ..Measurements::default()
        }
    }

    fn extra_series(&self) -> Vec<SeriesSpec> {
        vec![
            SeriesSpec::new("sensors.reference", "", SeriesGroup::Lab)
                .labelled("a reference attitude arrived (1 = yes)"),
        ]
    }

    fn extra_values(&self, out: &mut [f64]) {
        out[0] = f64::from(u8::from(self.delivered));
    }
}

fn axes_of(p: &ParamValues) -> [usize; 3] {
    ANGLE_SEQUENCES
        .get(p.index("sequence"))
        .map_or([2, 1, 0], |s| s.1)
}

impl Lab for SensitivityLab {
    fn id(&self) -> &'static str {
        "p5"
    }

    fn title(&self) -> &'static str {
        "Paper 5: correcting rates with the sensitivity matrix"
    }

    fn paper(&self) -> &'static str {
        "Bashniakov, Pichkur, Polishchuk, Linder, adaptive correction of angular velocities via the sensitivity matrix"
    }

    fn summary(&self) -> &'static str {
        "Measured rates ω drive the quaternion, 2Λ̇ = Λ ∘ (ω + p), with an additive correction p. \
         Beside Λ runs the sensitivity U = ∂Λ/∂p (4×3), reset to 0 at every reference. At each \
         reference attitude (every Δt) p takes one Gauss–Newton step h = (UᵀQU + εI)⁻¹UᵀQ(Λ_ref − Λ). \
         Method (9) continues the state and — linearised, its update has determinant 1, both \
         eigenvalues on the unit circle — oscillates for ever: it meets the tolerance for the first \
         time just after 2Δt, then leaves it again. (10) adds ε, (11) searches the step size on the \
         re-integrated interval; beyond the paper, re-integrating the last interval with the new p \
         converges in a few intervals. The diagram shows the eigenvalues for the current Δt and ε. \
         With a biased gyro p converges to −b; with the reference lost, the corrected integration \
         runs free and re-converges when it returns. The output file is the paper's: rows of \
         (t, angle₁, angle₂, angle₃) ending at the first row within tolerance."
    }

    fn params(&self) -> &'static [ParamSpec] {
        PARAMS
    }

    fn dt_s(&self, p: &ParamValues) -> f64 {
        p.get("step_s")
    }

    fn build(&self, p: &ParamValues, _rng: &mut ChaCha8Rng) -> LabRun {
        let axes = axes_of(p);
        let reference = quaternion_from_sequence(
            axes,
            [p.get("ref_1_rad"), p.get("ref_2_rad"), p.get("ref_3_rad")],
        );
        let start = quaternion_from_sequence(
            axes,
            [
                p.get("init_1_rad"),
                p.get("init_2_rad"),
                p.get("init_3_rad"),
            ],
        );
        let truth = Turning {
            q: reference,
            t_s: 0.0,
            profile: p.index("profile"),
            rate_rad_s: p.get("rate_deg_s").to_radians(),
            freq_rad_s: p.get("rate_freq_rad_s"),
            axes,
        };
        let mut sensors = Sensors {
            interval_s: 1.0,
            since_s: 0.0,
            bias: Vector3::zeros(),
            noise: 0.0,
            ref_noise: 0.0,
            dropout: (0.0, 0.0),
            delivered: false,
        };
        sensors.apply_params(p);
        let p0 = Vector3::new(
            p.get("p0_x_deg_s"),
            p.get("p0_y_deg_s"),
            p.get("p0_z_deg_s"),
        )
        .map(f64::to_radians);
        let settings = SensitivitySettings {
            eps: p.get("eps"),
            weights: [
                p.get("q_weight_0"),
                p.get("q_weight_1"),
                p.get("q_weight_2"),
                p.get("q_weight_3"),
            ],
            renormalise: p.flag("renormalise"),
            axes,
            tolerance_rad: p.get("tolerance_rad"),
        };
        let mut estimators: Vec<Box<dyn Estimator>> = METHODS
            .iter()
            .map(|(id, label, method)| -> Box<dyn Estimator> {
                Box::new(SensitivityCorrection::new(
                    id, label, *method, start, p0, settings,
                ))
            })
            .collect();
        estimators.iter_mut().for_each(|e| e.apply_params(p));
        LabRun {
            truth: Box::new(truth),
            sensors: Box::new(sensors),
            estimators,
        }
    }

    fn default_duration_s(&self) -> f64 {
        30.0
    }

    fn reproduce(&self) -> Result<Reproduction, ReproError> {
        Ok(reproduce::reproduce()?)
    }

    fn figures(&self) -> &'static [Figure] {
        FIGURES
    }

    fn presets(&self) -> &'static [Preset] {
        PRESETS
    }

    fn output_file(&self, p: &ParamValues) -> Option<OutputFile> {
        let id = METHODS.get(p.index("output_method")).map_or("gn9", |m| m.0);
        Some(OutputFile {
            columns: vec![
                "t_s".into(),
                format!("{id}.angle_1_rad"),
                format!("{id}.angle_2_rad"),
                format!("{id}.angle_3_rad"),
            ],
            headers: ["time", "angle1", "angle2", "angle3"]
                .map(String::from)
                .to_vec(),
            stop: Some(format!("{id}.within_tol")),
        })
    }

    fn diagrams(&self, p: &ParamValues) -> Vec<Diagram> {
        let (dt, eps) = (p.get("interval_s"), p.get("eps"));
        let mut points = Vec::new();
        // Each point takes the colour of the filter whose update it linearises (the
        // re-integrating variant's for "(11) and variant", Method::Reintegrate).
        for (name, method, source) in [
            ("(9)", Method::Plain, "gn9"),
            ("(10)", Method::Regularised, "lm10"),
            ("(11) and variant", Method::Reintegrate, "reint"),
        ] {
            for (k, l) in linearised_eigenvalues(method, dt, eps).iter().enumerate() {
                points.push(DiagramPoint {
                    label: format!("{name} λ{}", k + 1),
                    xy: [l.re, l.im],
                    source: Some(source),
                });
            }
        }
        vec![Diagram {
            title: format!("Eigenvalues of the linearised update (Δt = {dt} s, ε = {eps})"),
            unit_circle: true,
            points,
        }]
    }
}
