//! Lab "p1": paper 1 — a mock-up suspended on a thin string twists about the vertical (a
//! damped torsion pendulum); a one-axis rate gyro is the only sensor (Ivanov & Ovchinnikov,
//! "Determination of the orientation of a suspended mock-up using a one-axis gyroscope",
//! KIAM RAS preprint). Estimators: direct integration, the permanent-rotation KF and the
//! torsional KF, each with covariance matching over a window of N measurements (or none).

mod lesson;
mod params;
mod readings;
mod reproduce;
mod rocking;
mod stats;
mod truth;

use crate::estimators::covariance_matching::{AdaptMode, Adaptation};
use crate::estimators::one_axis_kf;
use crate::estimators::{AngleIntegration, OneAxisKf, OneAxisModel, OneAxisTuning};
use crate::model::{
    Estimator, ExampleLog, LabRun, LabSpec, Measurements, ParamValues, SensorModel, SeriesKey,
    Study, SweepSpec, TruthState, q,
};
use crate::page::{Figure, Lab, Page, ParamNote, SINGLE_AXIS_VIEWS};
use crate::sensors::{Averager, WhiteNoise, quantize};
use nalgebra::Vector2;
use rand_chacha::ChaCha8Rng;

pub use params::true_period_s;
use params::{PARAMS, PRESETS};
pub use reproduce::p1_noise_floor_deg;
pub use stats::{FilterStats, run_stats};
use truth::PERIOD_S;
use truth::Suspended;

/// The paper-1 lab.
pub struct SuspendedMockup;

const FIGURES: &[Figure] = &[
    Figure::new(
        "angle",
        "Angle",
        &[
            SeriesKey::truth(&q::ANGLE_DEG),
            SeriesKey::new("integration", &q::ANGLE_DEG),
            SeriesKey::new("kf-rotation", &q::ANGLE_DEG),
            SeriesKey::new("kf-torsion", &q::ANGLE_DEG),
        ],
    ),
    Figure::new(
        "rate",
        "Rate",
        &[
            SeriesKey::truth(&q::RATE_DEG_S),
            SeriesKey::new("integration", &q::RATE_DEG_S),
            SeriesKey::new("kf-rotation", &q::RATE_DEG_S),
            SeriesKey::new("kf-torsion", &q::RATE_DEG_S),
        ],
    ),
    Figure::new(
        "angle-error-vs-int",
        "Angle error vs φ_int (paper)",
        &[
            SeriesKey::new("kf-rotation", &one_axis_kf::ANGLE_MINUS_INT_DEG),
            SeriesKey::new("kf-torsion", &one_axis_kf::ANGLE_MINUS_INT_DEG),
        ],
    ),
    Figure::new(
        "angle-error",
        "Angle error vs truth",
        &[
            SeriesKey::new("kf-rotation", &q::ANGLE_ERR_DEG),
            SeriesKey::new("kf-torsion", &q::ANGLE_ERR_DEG),
            SeriesKey::new("integration", &q::ANGLE_ERR_DEG),
        ],
    ),
    Figure::new(
        "rate-error",
        "Rate error vs truth",
        &[
            SeriesKey::new("kf-rotation", &q::RATE_ERR_DEG_S),
            SeriesKey::new("kf-torsion", &q::RATE_ERR_DEG_S),
        ],
    ),
    Figure::new(
        "rate-error-vs-sensor",
        "Rate error vs sensor",
        &[
            SeriesKey::new("kf-rotation", &one_axis_kf::RATE_MINUS_SENSOR_DEG_S),
            SeriesKey::new("kf-torsion", &one_axis_kf::RATE_MINUS_SENSOR_DEG_S),
        ],
    ),
    Figure::new(
        "p-diagonal",
        "P: a = P_φφ, c = P_φ̇φ̇ (log10)",
        &[
            SeriesKey::variance("kf-rotation", &one_axis_kf::STATE_PHI),
            SeriesKey::variance("kf-rotation", &one_axis_kf::STATE_PHIDOT),
            SeriesKey::variance("kf-torsion", &one_axis_kf::STATE_PHI),
            SeriesKey::variance("kf-torsion", &one_axis_kf::STATE_PHIDOT),
        ],
    )
    .log(),
    Figure::new(
        "p-cross",
        "P: b = P_φφ̇",
        &[
            SeriesKey::covariance(
                "kf-rotation",
                &one_axis_kf::STATE_PHI,
                &one_axis_kf::STATE_PHIDOT,
            ),
            SeriesKey::covariance(
                "kf-torsion",
                &one_axis_kf::STATE_PHI,
                &one_axis_kf::STATE_PHIDOT,
            ),
        ],
    ),
];

/// Input rate (Hz) and averaging count of the selected gyro.
pub fn rates(p: &ParamValues) -> (f64, usize) {
    let input = p.get("input_rate_hz").max(1.0);
    let m = (input / p.get("filter_rate_hz").max(1.0)).round().max(1.0) as usize;
    (input, m)
}

fn torsion_model(p: &ParamValues) -> OneAxisModel {
    let t_model = true_period_s(p) * (1.0 + p.get("kf_period_error_pct") / 100.0);
    OneAxisModel::Torsion {
        omega_rad_s: std::f64::consts::TAU / t_model.max(1e-6),
    }
}

/// Both filters' adaptation (window N, R adapted or not, the reading of Table 2.3) and the
/// gyro noise their R is built from.
fn filter_tuning(p: &ParamValues) -> OneAxisTuning {
    let window = p.get("kf_window");
    OneAxisTuning {
        adaptation: Adaptation {
            window: if window.is_finite() {
                window.max(0.0) as usize
            } else {
                0
            },
            adapt_r: p.flag("kf_adapt_r"),
            mode: AdaptMode::ALL
                .get(p.index("kf_adaptation"))
                .copied()
                .unwrap_or(AdaptMode::SawTooth),
        },
        gyro_sigma_rad_s: p.get("gyro_noise_deg_s").to_radians(),
    }
}

const SPEC: LabSpec = LabSpec {
    id: "p1",
    title: "Paper 1: suspended mock-up, one-axis gyro",
    paper: "Ivanov & Ovchinnikov, one-axis gyroscope and a suspended mock-up, KIAM RAS preprint",
    reference: "Ivanov D. S., Ovchinnikov M. Yu. Determination of the orientation of a suspended mock-up using a one-axis gyroscope. Preprint of the Keldysh Institute of Applied Mathematics RAS, 32 pp. (in Russian).",
    summary: "A body hangs on a thin string and twists about the vertical: Iφ̈ = −fφ − damping, with \
         f = G·I_p/L and I_p = πd⁴/32, so T = 2π√(I/f). A one-axis gyro (noise, quantisation, range, \
         averaging to the filter rate) is the only sensor. Three estimators: direct integration \
         (φ_int); a Kalman filter assuming permanent rotation (φ̈ = 0); one assuming torsional \
         oscillation (Ω = 2π/T — set the period error to see a wrong model). With adaptation off \
         (N = 0, Q = 0) P collapses, the gain goes to zero and the filters stop listening. \
         Covariance matching puts the spread of the last N samples into P: N ≈ 100 works best in \
         the paper, N = 1000 is worse, N > 2000 poor. The paper's error panels compare the filters \
         with φ_int (its lab runs have no truth); against the true angle no filter can beat the \
         integrated gyro noise σ√(t/f), because a rate gyro alone cannot observe the angle — both \
         error plots are here. Defaults are the paper's setting: 100 Hz, R = σ², T ≈ 400 s and \
         ζ = 0.05 (the paper states neither; see the presets). Disturbances: a torque impulse, a \
         pendulum swing leaking into the gyro, suspension shaking, a wrong initial angle.",
    params: PARAMS,
    presets: PRESETS,
    default_duration_s: 600.0,
    words: crate::model::lab_words!(en),
};

const PAGE: Page = Page {
    figures: FIGURES,
    views: SINGLE_AXIS_VIEWS,
    suspended: true,
    log_format: Some(&crate::sensors::RATE_LOG),
    // Synthetic (assets/make_p1_log.py): the default twist read by a VG-910D as raw
    // 24-bit words with a zero offset, at 10 Hz for 600 s.
    example_log: Some(ExampleLog {
        name: "p1-vg910d-counts.csv",
        text: include_str!("../../../../assets/p1-vg910d-counts.csv"),
        units: &[
            ("rate_unit", "mdeg_s"),
            ("time_unit", "ms"),
            ("rate_counts", "24-bit"),
            ("count_scale", "0.0238418579"),
            ("count_zero", "1258"),
        ],
    }),
    ..Page::DEFAULT
};

impl Lab for SuspendedMockup {
    fn lesson(&self) -> Option<&'static crate::page::Lesson> {
        Some(&lesson::LESSON)
    }
    fn spec(&self) -> &'static LabSpec {
        &SPEC
    }

    fn dt_s(&self, params: &ParamValues) -> f64 {
        1.0 / rates(params).0
    }

    fn build(&self, p: &ParamValues, _rng: &mut ChaCha8Rng) -> LabRun {
        let x0 = Vector2::new(
            p.get("initial_angle_deg").to_radians(),
            p.get("initial_rate_deg_s").to_radians(),
        );
        let truth = Suspended::new(p, x0);
        let (_, m) = rates(p);
        let mut sensors = OneAxisGyro {
            averager: Averager::new(m),
            sigma_rad_s: 0.0,
            lsb_rad_s: 0.0,
            range_rad_s: 0.0,
            misalign_rad: 0.0,
        };
        sensors.apply_params(p);
        let xe = Vector2::new(x0[0] + p.get("init_error_deg").to_radians(), x0[1]);
        let p0 = params::p0(p);
        let mut estimators: Vec<Box<dyn Estimator>> = vec![
            Box::new(AngleIntegration::new(xe[0])),
            Box::new(
                OneAxisKf::new(OneAxisModel::PermanentRotation, xe, p0, m).tuned_by(filter_tuning),
            ),
            Box::new(
                OneAxisKf::new(torsion_model(p), xe, p0, m)
                    .with_model_from(torsion_model)
                    .tuned_by(filter_tuning),
            ),
        ];
        estimators.iter_mut().for_each(|e| e.apply_params(p));
        LabRun {
            truth: Box::new(truth),
            sensors: Box::new(sensors),
            estimators,
        }
    }

    fn page(&self) -> &'static Page {
        &PAGE
    }

    fn param_notes(&self, params: &ParamValues) -> Vec<ParamNote> {
        params::notes(params)
    }

    fn study(&self) -> Option<&dyn Study> {
        Some(self)
    }
}

impl Study for SuspendedMockup {
    // The page never reproduces a paper (the CLI and the tests do): the `study` feature.
    #[cfg(feature = "study")]
    fn reproduce(&self) -> Result<crate::model::Reproduction, crate::model::ReproError> {
        Ok(reproduce::reproduce()?)
    }

    #[cfg(feature = "study")]
    fn chapter(&self) -> crate::model::Chapter {
        crate::model::lab_chapter!()
    }

    fn output_file(&self, _params: &ParamValues) -> Option<crate::model::OutputFile> {
        Some(params::output_file())
    }

    fn sweeps(&self) -> &'static [SweepSpec] {
        const SWEEPS: &[SweepSpec] = &[SweepSpec::new(
            "window",
            "Adaptation window N (angle error, 200 s each)",
            "kf_window",
            &[1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0, 5000.0],
            200.0,
            &[
                SeriesKey::new("kf-rotation", &one_axis_kf::ANGLE_MINUS_INT_DEG),
                SeriesKey::new("kf-torsion", &one_axis_kf::ANGLE_MINUS_INT_DEG),
                SeriesKey::new("kf-rotation", &q::ANGLE_ERR_DEG),
                SeriesKey::new("kf-torsion", &q::ANGLE_ERR_DEG),
            ],
        )];
        SWEEPS
    }
}

/// The one-axis gyro: white noise, quantisation and range at the input rate, then block
/// averaging down to the filter rate. Its axis is tilted by `misalign` towards the swing axis.
#[derive(Clone)]
struct OneAxisGyro {
    averager: Averager,
    sigma_rad_s: f64,
    lsb_rad_s: f64,
    range_rad_s: f64,
    misalign_rad: f64,
}

impl SensorModel for OneAxisGyro {
    fn apply_params(&mut self, p: &ParamValues) {
        let (range_deg_s, bits) = (p.get("gyro_range_deg_s"), p.get("gyro_bits"));
        self.range_rad_s = range_deg_s.to_radians();
        self.lsb_rad_s = 2.0 * self.range_rad_s / 2f64.powf(bits);
        self.sigma_rad_s = p.get("gyro_noise_deg_s").to_radians();
        self.misalign_rad = p.get("swing_misalign_deg").to_radians();
    }

    fn sample(&mut self, truth: &TruthState, _dt_s: f64, rng: &mut ChaCha8Rng) -> Measurements {
        let w = truth.rate_body_rad_s;
        let along_axis = w.z * self.misalign_rad.cos() + w.x * self.misalign_rad.sin();
        let raw = along_axis
            + WhiteNoise {
                sigma: self.sigma_rad_s,
            }
            .sample(rng);
        let reading = quantize(raw, self.lsb_rad_s, self.range_rad_s);
        Measurements {
            t_s: truth.t_s,
            gyro_axis_rad_s: self.averager.push(reading),
            ..Measurements::default()
        }
    }
}
