//! Paper 1's parameters as its program exposes them (P₀'s a₀, b₀, c₀; the torsion period
//! typed or from the string), the presets, and what follows from them: the pendulum, P₀ and
//! the notes under the sliders (the §3.1 string-strength check, the period the string gives,
//! a P₀ that is not positive semi-definite).

use crate::dynamics::{
    STRING_MATERIALS, StringMaterial, TorsionPendulum, min_string_diameter_m, string_safety_factor,
    string_stiffness_n_m_per_rad,
};
use crate::model::{OutputFile, ParamSpec, ParamValues, Preset, SeriesKey, TIME, fmt_sig, q};
use crate::page::ParamNote;
use nalgebra::{Matrix2, Vector2};

/// The choice between the period from the string and a typed one.
const PERIOD_FROM: &str = "period_from";
/// The typed period (s).
const TYPED_PERIOD_S: &str = "typed_period_s";
/// P₀'s elements, in the paper's units (deg², deg²/s, deg²/s²).
const P0_A: &str = "p0_a_deg2";
const P0_B: &str = "p0_b_deg2_s";
const P0_C: &str = "p0_c_deg2_s2";

/// The safety factor §3.1's text asks of the string (its stated diameters follow from 2, so
/// the paper's own 0.35-mm steel string has 1.96).
const REQUIRED_SAFETY: f64 = 1.5;

const PERIOD_SOURCES: &[&str] = &["from the string and the body", "typed"];

const MATERIALS: &[&str] = &[
    "steel (G = 80 GPa)",
    "titanium alloy (41 GPa)",
    "tungsten (161 GPa)",
    "nylon (1 GPa)",
];

const ADAPTATION_MODES: &[&str] = &[
    "saw-tooth: P := mean q qᵀ, q = (φ_int − φ̂, z − φ̇̂) (this project's reading)",
    "saw-tooth, diagonal of mean q qᵀ only (stable for small N)",
    "literal: P := mean (K r)(K r)ᵀ (collapses)",
    "rate process noise Q from the window",
];

pub(super) const PRESETS: &[Preset] = &[
    Preset {
        id: "vg-910d",
        name: "VG-910D",
        help: "Fizoptika fibre-optic gyro: ±200 °/s, 24-bit output at 300 Hz, averaged ×3 to the 100-Hz filter (R = σ²/3)",
        values: &[
            ("gyro_range_deg_s", 200.0),
            ("gyro_bits", 24.0),
            ("input_rate_hz", 300.0),
            ("filter_rate_hz", 100.0),
        ],
    },
    Preset {
        id: "adis16100",
        name: "ADIS16100",
        help: "Analog Devices MEMS gyro: ±300 °/s, 12-bit output, 1000 Hz (rate uncertain in the OCR)",
        values: &[
            ("gyro_range_deg_s", 300.0),
            ("gyro_bits", 12.0),
            ("input_rate_hz", 1000.0),
            ("filter_rate_hz", 100.0),
        ],
    },
    Preset {
        id: "period-578",
        name: "T ≈ 578 s",
        help: "String 2 m, body 0.5 kg·m²: the period the paper's rate axis (±3–4 °/s from 360°) suggests; the N = 1000 error shrinks to ~0.09°",
        values: &[("string_length_m", 2.0), ("inertia_kg_m2", 0.5)],
    },
    Preset {
        id: "earlier-setting",
        name: "earlier setting",
        help: "This project's first reading: VG-910D at 300 Hz averaged ×3 (R = σ²/3), T ≈ 578 s, ζ = 0.01, Q_N's rate element as process noise",
        values: &[
            ("input_rate_hz", 300.0),
            ("filter_rate_hz", 100.0),
            ("string_length_m", 2.0),
            ("inertia_kg_m2", 0.5),
            ("damping_ratio", 0.01),
            ("kf_adaptation", 3.0),
        ],
    },
    Preset {
        id: "rocking-body",
        name: "rocking body (5 DOF)",
        help: "The §3.2 model started 5° off the vertical, gyro aligned: the body rocks every ≈ 10 s and the swing reaches the gyro through the dynamics alone",
        values: &[("body_model", 1.0), ("swing_amp_deg", 5.0)],
    },
];

pub(super) const PARAMS: &[ParamSpec] = &[
    ParamSpec::choice("string_material", "String material", MATERIALS, 0).help("Sets the shear modulus G in f = G·I_p/L."),
    ParamSpec::real("string_diameter_mm", "String diameter d", "mm", 0.05, 2.0, 0.35).log().help("I_p = πd⁴/32: the stiffness goes as d⁴ (paper: steel 0.35 mm, G·I_p = 1.18e-4 N·m²)."),
    ParamSpec::real("string_length_m", "String length L", "m", 0.1, 10.0, 1.0).log().help("Stiffness f = G·I_p/L; with I = 0.48 kg·m², L = 1 m gives T ≈ 400 s (not stated in the paper)."),
    ParamSpec::real("inertia_kg_m2", "Body inertia I", "kg·m²", 0.01, 10.0, 0.48).log().help("Period T = 2π√(I/f): a shorter T means larger accelerations, which the rotation model φ̈ = 0 cannot follow between resets — watch the N = 1000 error grow."),
    ParamSpec::real("body_mass_kg", "Body mass M", "kg", 0.1, 20.0, 1.0).log().outside_run().requires("body_model").help("What the string must hold (paper: M = 1 kg); in the 5-DOF model also the weight that rights the rocking body. It does not enter the twist."),
    ParamSpec::choice("body_model", "Body model", BODY_MODELS, 0).on_reset().help("1 DOF: the twist alone, as the filters assume, with the swing a prescribed sinusoid. 5 DOF (§3.2): the suspension point slides freely, the body rocks about its centre of mass by itself, and the swing reaches the gyro through the dynamics."),
    ParamSpec::real("com_offset_mm", "Centre of mass below the string d", "mm", 0.1, 200.0, 10.0).log().requires("body_model").help("The paper's d (not given): the weight M g acts d below the suspension point, so the body rocks at √(M g d / A)."),
    ParamSpec::real("tilt_inertia_kg_m2", "Tilt inertia A = B", "kg·m²", 0.01, 10.0, 0.24).log().requires("body_model").help("The body's moments of inertia about the horizontal axes through its centre of mass (ours: half of I, a disc)."),
    ParamSpec::choice(PERIOD_FROM, "Torsion period T", PERIOD_SOURCES, 0).help("The paper's program takes T typed in; here it follows from the string and the body unless you type it."),
    ParamSpec::real(TYPED_PERIOD_S, "Typed period T", "s", 10.0, 5000.0, 400.0).log().requires(PERIOD_FROM).help("The string's stiffness becomes f = I(2π/T)²; the paper's rate axis suggests 570–750 s."),
    ParamSpec::real("damping_ratio", "Damping ratio ζ", "", 0.0, 0.5, 0.05).log().help("Air and string losses (not given in the paper); ζ = 0.05 makes the undamped torsional model drift to the ±100° of Fig. 5.3 without adaptation."),
    ParamSpec::real("initial_angle_deg", "Initial angle φ₀", "°", -720.0, 720.0, 360.0).on_reset().help("Paper: 360°."),
    ParamSpec::real("initial_rate_deg_s", "Initial rate", "°/s", -20.0, 20.0, 0.0).on_reset(),
    ParamSpec::real("init_error_deg", "Filters' initial angle error", "°", -180.0, 180.0, 0.0).on_reset().help("The paper tried ≈100°: the filters stay close to the integrated angle φ_int, which starts with the same offset."),
    ParamSpec::real(P0_A, "P₀: angle variance a₀", "deg²", 1e-8, 1e5, 1e-4).log().on_reset().help("The paper's a₀ (1e-4 deg², i.e. σ = 0.01°)."),
    ParamSpec::real(P0_B, "P₀: covariance b₀", "deg²/s", -1.0, 1.0, 1e-4).on_reset().help("The paper's b₀ (1e-4). P₀ must be positive definite: |b₀| is limited to 0.99√(a₀c₀)."),
    ParamSpec::real(P0_C, "P₀: rate variance c₀", "deg²/s²", 1e-8, 1e3, 2e-4).log().on_reset().help("The paper's GUI reads 1e-4, which with a₀ = b₀ = 1e-4 makes P₀ singular (b₀² = a₀c₀); 2e-4 (ours) keeps it positive definite."),
    ParamSpec::real("gyro_noise_deg_s", "Gyro noise σ", "°/s", 0.0, 1.0, 0.04).log().help("White noise per gyro sample (paper: 0.04)."),
    ParamSpec::real("gyro_range_deg_s", "Gyro range ±", "°/s", 1.0, 1000.0, 200.0).log().help("Readings clip here (VG-910D: 200, ADIS16100: 300)."),
    ParamSpec::real("gyro_bits", "Gyro resolution", "bit", 4.0, 24.0, 24.0).integer().help("Quantisation step = 2·range/2^bits."),
    ParamSpec::real("input_rate_hz", "Gyro output rate", "Hz", 10.0, 2000.0, 100.0).log().integer().on_reset().help("The gyro's own rate; the paper's simulation feeds the filter at 100 Hz (VG-910D: 300 Hz, see its preset)."),
    ParamSpec::real("filter_rate_hz", "Filter rate", "Hz", 1.0, 300.0, 100.0).log().integer().on_reset().help("Averaging takes the input rate down to this (paper: 100 Hz); R = σ²/m for m averaged samples."),
    ParamSpec::real("kf_window", "Adaptation window N", "", 0.0, 5000.0, 100.0).log().integer().help("Covariance matching every N measurements; 0 = off (Q = 0: P collapses). Paper: N ≈ 100 best, 1000 worse, > 2000 poor."),
    ParamSpec::choice("kf_adaptation", "Adaptation", ADAPTATION_MODES, 0).help("What the window's sum is built from and how it enters the filter (the paper is ambiguous; see the lab's help)."),
    ParamSpec::toggle("kf_adapt_r", "Adapt R as well", false),
    ParamSpec::real("kf_period_error_pct", "Torsional KF period error", "%", -50.0, 100.0, 0.0).help("Model period T = true T·(1 + e): set it wrong on purpose."),
    ParamSpec::real("impulse_time_s", "Torque impulse at", "s", 0.0, 600.0, 5.0).requires("impulse_deg_s"),
    ParamSpec::real("impulse_deg_s", "Impulse size (rate jump)", "°/s", -10.0, 10.0, 0.0).help("A kick that changes φ̇ at once."),
    ParamSpec::real("swing_amp_deg", "Pendulum swing", "°", 0.0, 20.0, 0.0).help("1 DOF: a swing about a horizontal axis at √(g/L), which leaks into the gyro through its misalignment. 5 DOF: the initial tilt (at a reset), after which the body rocks by itself."),
    ParamSpec::real("swing_misalign_deg", "Gyro misalignment", "°", 0.0, 10.0, 0.0).help("Tilt of the gyro axis towards the swing axis: the swing leaks in, and the twist rate reads cos(δ) too small."),
    ParamSpec::real("shake_torque_n_m", "Suspension shaking (torque σ)", "N·m", 0.0, 1e-3, 0.0).log().help("Random torque from a shaking suspension point."),
];

/// The string material chosen (steel when out of range).
fn material(p: &ParamValues) -> StringMaterial {
    STRING_MATERIALS
        .get(p.index("string_material"))
        .copied()
        .unwrap_or(STRING_MATERIALS[0])
}

/// The string's torsion stiffness f = G·I_p/L (N·m/rad).
fn string_stiffness(p: &ParamValues) -> f64 {
    string_stiffness_n_m_per_rad(
        material(p).shear_modulus_pa,
        p.get("string_diameter_mm") * 1e-3,
        p.get("string_length_m"),
    )
}

/// The period (s) the string and the body give, T = 2π√(I/f).
fn string_period_s(p: &ParamValues) -> f64 {
    std::f64::consts::TAU * (p.get("inertia_kg_m2") / string_stiffness(p)).sqrt()
}

/// True period T (s): typed, or from the string and the body.
pub fn true_period_s(p: &ParamValues) -> f64 {
    pendulum(p, Vector2::zeros()).period_s()
}

/// The torsion pendulum the parameters describe, starting at `state` (φ rad, φ̇ rad/s).
pub(super) fn pendulum(p: &ParamValues, state: Vector2<f64>) -> TorsionPendulum {
    let inertia = p.get("inertia_kg_m2");
    let stiffness = if p.index(PERIOD_FROM) == 1 {
        inertia * (std::f64::consts::TAU / p.get(TYPED_PERIOD_S)).powi(2)
    } else {
        string_stiffness(p)
    };
    TorsionPendulum {
        inertia_kg_m2: inertia,
        stiffness_n_m_per_rad: stiffness,
        damping_ratio: p.get("damping_ratio"),
        torque_n_m: 0.0,
        state,
    }
}

/// The paper's output file, in its column order (ω, φ_int, φ̂₁, φ̇̂₁, φ̂₂, φ̇̂₂, t): the rate
/// the filters read (averaged to the filter rate), the integrated angle, each filter's angle
/// and rate, and the time — no truth column, as on the rig. Degrees, °/s and seconds (the
/// paper does not state the file's units).
pub(super) fn output_file() -> OutputFile {
    let columns = [
        SeriesKey::new("integration", &q::RATE_DEG_S),
        SeriesKey::new("integration", &q::ANGLE_DEG),
        SeriesKey::new("kf-rotation", &q::ANGLE_DEG),
        SeriesKey::new("kf-rotation", &q::RATE_DEG_S),
        SeriesKey::new("kf-torsion", &q::ANGLE_DEG),
        SeriesKey::new("kf-torsion", &q::RATE_DEG_S),
    ];
    OutputFile {
        columns: columns
            .iter()
            .map(SeriesKey::name)
            .chain(std::iter::once(TIME.to_string()))
            .collect(),
        headers: [
            "omega", "phi_int", "phi1", "phi1_dot", "phi2", "phi2_dot", "t",
        ]
        .map(String::from)
        .to_vec(),
        stop: None,
    }
}

/// The largest correlation b₀/√(a₀c₀) the filters take: at 1 P₀ is singular, and rounding
/// in the first propagation can leave it indefinite (the fuzzer found it).
const MAX_CORRELATION: f64 = 0.99;

/// The largest |b₀| (deg²/s) the filters take with these a₀, c₀.
fn b0_limit(p: &ParamValues) -> f64 {
    MAX_CORRELATION * (p.get(P0_A) * p.get(P0_C)).sqrt()
}

/// P₀ of both filters (rad², rad²/s, rad²/s²) from a₀, b₀, c₀, with |b₀| limited to
/// 0.99√(a₀c₀) so that it is positive definite.
pub(super) fn p0(p: &ParamValues) -> Matrix2<f64> {
    let (a, c) = (p.get(P0_A), p.get(P0_C));
    let limit = b0_limit(p);
    let b = p.get(P0_B).clamp(-limit, limit);
    Matrix2::new(a, b, b, c) * 1f64.to_radians().powi(2)
}

/// The notes under the sliders: the thinnest string that holds the body (a warning when the
/// chosen one is thinner), the period the string gives when T is typed, and a b₀ that had
/// to be limited.
pub(super) fn notes(p: &ParamValues) -> Vec<ParamNote> {
    let m = material(p);
    let mass = p.get("body_mass_kg");
    let d_mm = p.get("string_diameter_mm");
    let factor = string_safety_factor(mass, m.tensile_strength_pa, d_mm * 1e-3);
    let d_min_mm = min_string_diameter_m(mass, m.tensile_strength_pa, REQUIRED_SAFETY) * 1e3;
    let args = vec![
        ("mass", fmt_sig(mass)),
        ("factor", fmt_sig(factor)),
        ("required", fmt_sig(REQUIRED_SAFETY)),
        ("dmin", fmt_sig(d_min_mm)),
    ];
    let mut notes = vec![if factor < REQUIRED_SAFETY {
        ParamNote::warning("string_diameter_mm", "note-string-too-thin", args)
    } else {
        ParamNote::info("string_diameter_mm", "note-string-holds", args)
    }];
    let period_args = vec![("period", fmt_sig(string_period_s(p)))];
    notes.push(ParamNote::info(
        PERIOD_FROM,
        "note-string-period",
        period_args,
    ));
    if p.get(P0_B).abs() > b0_limit(p) {
        let limit = vec![("limit", fmt_sig(b0_limit(p)))];
        notes.push(ParamNote::warning(P0_B, "note-p0-limited", limit));
    }
    notes
}

/// The `body_model` choice's options.
pub(super) const BODY_MODELS: &[&str] = &[
    "1 DOF: the twist alone, the swing prescribed (§3.3, the filters' model)",
    "5 DOF: the body rocks on a free suspension point (§3.2, eq. 3.2)",
];

#[cfg(test)]
mod tests {
    use super::*;

    fn with(assignments: &[&str]) -> ParamValues {
        let mut p = ParamValues::defaults(PARAMS);
        for a in assignments {
            let (k, v) = a.split_once('=').unwrap();
            p.set(PARAMS, k, v.parse().unwrap()).unwrap();
        }
        p
    }

    #[test]
    fn the_paper_s_string_holds_the_body_and_a_thinner_one_is_a_warning() {
        // The paper's 0.35-mm steel string under 1 kg: safety factor 1.96.
        let string = notes_of(&[], "string_diameter_mm");
        assert!(!string.warning, "{string:?}");
        assert!(
            string.args.contains(&("factor", "1.96".to_string())),
            "{string:?}"
        );
        assert!(
            string.args.contains(&("dmin", "0.306".to_string())),
            "{string:?}"
        );
        let thin = notes_of(&["string_diameter_mm=0.3"], "string_diameter_mm");
        assert!(thin.warning && thin.message == "note-string-too-thin");
        // Titanium alloy holds the kilogram at 0.2 mm (paper: d > 0.17 mm); steel does not.
        let titanium = ["string_material=1", "string_diameter_mm=0.2"];
        assert!(!notes_of(&titanium, "string_diameter_mm").warning);
        assert!(notes_of(&["string_diameter_mm=0.2"], "string_diameter_mm").warning);
        // Four times the mass needs twice the diameter.
        let heavy = notes_of(&["body_mass_kg=4"], "string_diameter_mm");
        assert!(heavy.warning, "{heavy:?}");
        assert!(
            heavy.args.contains(&("dmin", "0.612".to_string())),
            "{heavy:?}"
        );
    }

    fn notes_of(assignments: &[&str], key: &str) -> ParamNote {
        notes(&with(assignments))
            .into_iter()
            .find(|n| n.key == key)
            .unwrap()
    }

    #[test]
    fn a_typed_period_is_the_pendulum_s_and_the_string_s_period_is_still_shown() {
        let typed = with(&["period_from=1", "typed_period_s=578"]);
        assert!((true_period_s(&typed) - 578.0).abs() < 1e-9);
        assert!((true_period_s(&with(&[])) - 401.0).abs() < 1.0);
        let note = notes_of(&["period_from=1", "typed_period_s=578"], "period_from");
        assert_eq!(note.args, vec![("period", "401".to_string())]);
    }

    #[test]
    fn p0_is_the_paper_s_elements_and_an_indefinite_one_is_limited_and_said() {
        let deg2 = 1f64.to_radians().powi(2);
        let p = p0(&with(&[]));
        assert_eq!(p, Matrix2::new(1e-4, 1e-4, 1e-4, 2e-4) * deg2);
        assert!(notes(&with(&[])).iter().all(|n| n.key != P0_B));
        let limited = with(&["p0_b_deg2_s=-0.5"]);
        let b = p0(&limited)[(0, 1)] / deg2;
        assert!((b + 0.99 * (1e-4f64 * 2e-4).sqrt()).abs() < 1e-15, "{b}");
        assert!(p0(&limited).determinant() > 0.0);
        // The paper's literal GUI values (all 1e-4) are singular: b₀ is limited and said.
        let literal = with(&["p0_c_deg2_s2=1e-4"]);
        assert!(p0(&literal).determinant() > 0.0);
        assert!(notes(&literal).iter().any(|n| n.key == P0_B && n.warning));
        assert!(notes_of(&["p0_b_deg2_s=-0.5"], P0_B).warning);
    }
}
