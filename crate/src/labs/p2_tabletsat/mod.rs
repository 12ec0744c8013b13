//! Lab "p2": paper 2 — attitude determination for the TabletSat microsatellite (Ivanov,
//! Ivlev, Karpenko, Ovchinnikov, Keldysh Institute preprint 2014-64). A 20-kg satellite on a
//! circular low orbit holds the orbital frame with reaction wheels; four kinds of sensors
//! (Table 1) feed every EKF variant of Table 2 at once, beside the reduced [λ, Δω] variant,
//! the parallel disturbance filter (§3.2) and the constant-gain filter (§3.3).

mod accuracy;
mod constant_gain;
mod fig7;
mod filter_row;
mod lesson;
mod page;
mod paper_tables;
mod table4;
use page::{FIGURES, PRESETS};
mod metrics;
mod reproduce;
pub mod sensors;
pub mod sets;
mod timing;
pub mod truth;
pub mod tune;

use crate::estimators::mekf;
use crate::estimators::mekf::Retune;
use crate::estimators::{Mekf, MekfTuning, StateSet};
use crate::model::{
    Estimator, LabRun, LabSpec, ParamSpec, ParamValues, SeriesKey, Study, SweepSpec, q,
};
use crate::page::{AccuracyTable, BodyShape, Lab, Outage, Page};
use nalgebra::{Matrix3, SMatrix, UnitQuaternion, Vector3};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use sensors::{FIELD_MODELS, STAR_READINGS, Sensors};
use sets::FILTERS;
use truth::Spacecraft;

pub use accuracy::{FilterAccuracy, accuracy};

/// The paper-2 lab.
pub struct TabletSat;

/// Inertia of TabletSat-Aurora in body axes (paper 2, §1), kg·m²: the truth's and every
/// filter's dynamics model.
pub const INERTIA_KG_M2: Matrix3<f64> =
    Matrix3::new(0.519, 0.002, 0.005, 0.002, 0.579, 0.009, 0.005, 0.009, 0.71);

const PARAMS: &[ParamSpec] = &[
    // Orbit (applies at reset).
    ParamSpec::real("altitude_km", "Orbit altitude", "km", 300.0, 800.0, 600.0).on_reset().help("Not stated in the paper: a sun-synchronous low orbit near 600 km is assumed (WMM is valid up to 850 km)."),
    ParamSpec::real("inclination_deg", "Inclination", "°", 0.0, 180.0, 97.79).on_reset().help("97.79° is sun-synchronous at 600 km."),
    ParamSpec::real("ltan_h", "Ascending node local time", "h", 0.0, 24.0, 10.5).on_reset().help("Local time at the ascending node: 6 or 18 is a dawn–dusk orbit (no eclipse), 12 a noon–midnight one (longest eclipse)."),
    ParamSpec::real("day_of_year", "Day of 2026", "", 1.0, 365.0, 170.0).integer().on_reset().help("The epoch: sets the sun's direction and the field model's date."),
    ParamSpec::real("arg_lat0_deg", "Start: argument of latitude", "°", 0.0, 360.0, 0.0).on_reset(),
    // Truth.
    ParamSpec::real("init_att_err_deg", "Initial attitude off the orbital frame", "°", 0.0, 45.0, 5.0).on_reset(),
    ParamSpec::real("init_rate_err_deg_s", "Initial rate off the orbital rate", "°/s", 0.0, 2.0, 0.05).on_reset(),
    ParamSpec::real("k_att", "Wheel gain K_λ", "N·m", 1e-5, 1e-2, 5e-4).log().help("Paper: not given; 5e-4 settles the attitude in a few minutes."),
    ParamSpec::real("k_rate", "Wheel gain K_ω", "N·m·s", 1e-4, 0.1, 0.02).log().help("Paper: not given."),
    ParamSpec::real("dist_torque_n_m", "Unmodelled torque", "N·m", 0.0, 1e-4, 8e-7).log().help("Paper: ≈ 8e-7 N·m in the tuning runs; the filters do not model it."),
    ParamSpec::real("dist_from_s", "Torque switched on at", "s", 0.0, 6000.0, 0.0).help("A step in the disturbance (§3.2): 0 = from the start."),
    // Sensors (Table 1).
    ParamSpec::real("mag_noise_nt", "Magnetometer σ", "nT", 0.0, 5000.0, 250.0).log(),
    ParamSpec::real("mag_bias_nt", "Magnetometer bias", "nT", 0.0, 5000.0, 0.0).log().help("A constant bias added to the reading, which the Δb filters in nT estimate."),
    ParamSpec::real("mag_turn_deg", "Magnetometer bias as a turn of the field", "°", 0.0, 10.0, 0.0).help("Fig. 7's model: the reading is the field turned by this angle about a fixed body axis; the Δb-as-a-turn filter estimates it in degrees."),
    ParamSpec::choice("onboard_field", "Onboard field model", FIELD_MODELS, 0).help("The truth is WMM 2025; the filters' model may be worse (the paper: errors up to 400 nT)."),
    ParamSpec::real("model_error_nt", "Model error", "nT", 10.0, 2000.0, 400.0).requires("onboard_field").help("Size of the onboard model's error when it is 'WMM + model error'."),
    ParamSpec::real("sun_noise_deg", "Sun-sensor σ", "°", 0.0, 2.0, 0.1).log(),
    ParamSpec::real("sun_fov_deg", "Sun-head field of view ±", "°", 10.0, 90.0, 45.0),
    ParamSpec::real("gyro_noise_deg_s", "Gyro σ", "°/s", 0.0, 0.5, 0.005).log(),
    ParamSpec::real("gyro_bias_deg_s", "Gyro bias", "°/s", 0.0, 1.0, 0.0).log().help("A constant bias the Δω filters estimate (Table 1 lists none; the bias rows set 0.05 °/s)."),
    ParamSpec::real("gyro_walk_deg_s_sqrt_s", "Gyro bias random walk", "°/s/√s", 0.0, 1e-2, 0.0).log(),
    ParamSpec::real("star_noise_deg", "Star-tracker σ", "°", 0.0, 0.1, 0.001).log(),
    ParamSpec::choice("star_reading", "Star-tracker σ means", STAR_READINGS, 0),
    ParamSpec::real("star_max_rate_deg_s", "Star tracker lost above", "°/s", 0.1, 10.0, 2.0).log(),
    ParamSpec::real("star_sun_exclusion_deg", "Star-tracker sun exclusion", "°", 0.0, 90.0, 30.0),
    ParamSpec::real("star_earth_exclusion_deg", "Star-tracker Earth-limb exclusion", "°", 0.0, 80.0, 20.0),
    // Rates.
    ParamSpec::real("predict_rate_hz", "EKF prediction rate", "Hz", 1.0, 50.0, 10.0).log().integer().on_reset().help("The simulation step; the filters predict (and add Q) at this rate. The paper's Q fits 10 Hz."),
    ParamSpec::real("vector_rate_hz", "Magnetometer / sun-sensor rate", "Hz", 0.1, 10.0, 1.0).log(),
    ParamSpec::real("gyro_rate_hz", "Gyro rate", "Hz", 0.1, 50.0, 1.0).log(),
    ParamSpec::real("star_rate_hz", "Star-tracker rate", "Hz", 0.1, 10.0, 1.0).log(),
    // Tuning.
    ParamSpec::real("q_scale", "Q scale (all filters)", "", 0.01, 100.0, 1.0).log().help("Multiplies every filter's q (their own values are the paper's Table 3 where readable)."),
    ParamSpec::real("alpha", "Disturbance filter fading α", "", 0.5, 1.0, 0.999).help("P_d ← P_d/α per second: smaller forgets faster (§3.2)."),
    ParamSpec::real("rd_scale", "Disturbance filter R_d scale", "", 0.1, 1000.0, 100.0).log().help("R_d as a multiple of each row's innovation variance. The innovations of a running EKF are correlated over many steps, so R_d = S (scale 1) makes the disturbance filter overconfident: it then invents a disturbance where there is none."),
    ParamSpec::real("freeze_after_s", "Constant-gain filters: gain frozen at", "s", 10.0, 6000.0, 150.0).log().help("§3.3: from the first update after this time in which every sensor of the set delivered, the filter keeps that gain and stops propagating P (the paper: once the motion is quasi-steady; the time is ours)."),
    ParamSpec::real("filter_init_err_deg", "Filters' initial attitude error", "°", 0.0, 30.0, 2.0).on_reset(),
    // "Tune this set" (issue 19): one of Table 3's sets again, its q × these sliders.
    ParamSpec::choice(tune::SET, "Set to tune", &tune::SET_CHOICES, 8).on_reset().help("Runs this set a second time as the filter 'the set being tuned', with its q multiplied by the three sliders below, beside the same set at Table 3's q. The note says the q it runs with."),
    ParamSpec::real(tune::Q_ATT, "Tuned set: q_Λ ×", "", 0.001, 1000.0, 1.0).log().help("Multiplies the tuned set's attitude process noise q_Λ (1 = Table 3's, or ours where the OCR lost it)."),
    ParamSpec::real(tune::Q_RATE, "Tuned set: q_ω ×", "", 0.001, 1000.0, 1.0).log().help("Multiplies the tuned set's rate process noise q_ω."),
    ParamSpec::real(tune::Q_BIAS, "Tuned set: q_bias ×", "", 0.001, 1000.0, 1.0).log().help("Multiplies the tuned set's bias process noise q_bias (a set without a bias state ignores it)."),
    // Failure: a degenerate geometry.
    ParamSpec::toggle("sun_along_field", "Thought experiment: sun along the field", false).help("Puts the sun (truth and ephemeris) next to the field direction: with two parallel vectors the rotation about them is not observed (H degenerate)."),
    ParamSpec::real("sun_field_angle_deg", "Sun–field angle", "°", 0.0, 90.0, 0.5).requires("sun_along_field"),
];

/// The tuning of filter row `row` with the lab's parameters.
fn tuning(p: &ParamValues, q: [f64; 3]) -> MekfTuning {
    let scale = p.get("q_scale");
    MekfTuning {
        q_att: q[0] * scale,
        q_rate: q[1] * scale,
        q_bias: q[2] * scale,
        star_sigma: {
            let s = p.get("star_noise_deg").to_radians();
            // δλ is half the rotation angle: a per-axis rotation σ is σ/2 in λ; σ on each
            // quaternion component is σ in λ.
            if p.index("star_reading") == 1 {
                s
            } else {
                s / 2.0
            }
        }
        .max(1e-9),
        gyro_sigma_rad_s: p.get("gyro_noise_deg_s").to_radians().max(1e-9),
        mag_sigma_nt: p.get("mag_noise_nt").max(1e-3),
        sun_sigma_rad: p.get("sun_noise_deg").to_radians().max(1e-9),
        alpha: p.get("alpha"),
        rd_scale: p.get("rd_scale"),
        freeze_after_s: p.get("freeze_after_s"),
    }
}

/// The initial σ of a magnetometer bias modelled as a turn of the field (rad): 3°, ours.
const MTURN_P0_RAD: f64 = 3.0 * std::f64::consts::PI / 180.0;

/// A diagonal initial covariance for `states`: attitude σ `att_rad` (rotation angle), rate
/// 0.1 °/s, gyro bias 0.05 °/s, magnetometer bias 3000 nT (the size of a bias a student
/// is likely to set; the filter does not know the truth's).
fn p0<const N: usize>(states: StateSet, att_rad: f64) -> SMatrix<f64, N, N> {
    let mut d = SMatrix::<f64, N, 1>::zeros();
    for i in 0..3 {
        d[i] = (att_rad / 2.0).powi(2);
    }
    let (rate, gbias, mbias) = (
        0.1f64.to_radians().powi(2),
        0.05f64.to_radians().powi(2),
        9e6,
    );
    match states {
        StateSet::AttRate => (3..6).for_each(|i| d[i] = rate),
        StateSet::AttRateGyroBias => {
            (3..6).for_each(|i| d[i] = rate);
            (6..9).for_each(|i| d[i] = gbias);
        }
        StateSet::AttRateMagBias => {
            (3..6).for_each(|i| d[i] = rate);
            (6..9).for_each(|i| d[i] = mbias);
        }
        StateSet::AttRateMagTurn => {
            (3..6).for_each(|i| d[i] = rate);
            (6..9).for_each(|i| d[i] = MTURN_P0_RAD.powi(2));
        }
        StateSet::AttGyroBias => (3..6).for_each(|i| d[i] = gbias),
    }
    SMatrix::<f64, N, N>::from_diagonal(&d.column(0).into_owned())
}

const SPEC: LabSpec = LabSpec {
    id: "p2",
    title: "Paper 2: TabletSat, twelve sensor sets",
    paper: "Ivanov, Ivlev, Karpenko, Ovchinnikov, TabletSat attitude determination, Keldysh preprint 2014-64",
    reference: "Ivanov, Ivlev, Karpenko, Ovchinnikov. Attitude determination algorithms investigation for microsatellites of TabletSat series. Keldysh Institute of Applied Mathematics RAS, preprint 2014-64 (in Russian).",
    summary: "A 20-kg microsatellite on a circular orbit holds the orbital frame (e₃ up, e₂ along the \
         orbit normal) with reaction wheels against gravity gradient and an unmodelled torque. \
         Four kinds of sensors — magnetometer (the field from NOAA's WMM), five sun-sensor heads, a \
         gyro with a bias, a star tracker that is lost above 2 °/s or near the sun or the Earth — \
         feed every EKF of the paper's Table 2 at once: the same multiplicative EKF with the rows of \
         each sensor set, with gyro-bias or magnetometer-bias states, the reduced [λ, Δω] variant, a \
         parallel disturbance filter (fading α) and a constant-gain filter. The paper's accuracy is \
         √max diag P∞; beside it the measured σ over the last minute and the NEES against χ² bounds \
         show which filter believes itself too much. The paper does not give the orbit, the wheel \
         gains, the sample rates or P₀: the defaults are a 600-km sun-synchronous orbit, sensors at \
         1 Hz with the EKFs predicting at 10 Hz (the rates at which the paper's Q fits), and they are \
         sliders. Presets: model error, blinded star tracker, long eclipse, no eclipse, gyro plus \
         one vector. The 3D view draws the sun, field and nadir from the body, the ghost filter's \
         unobservable axis when it has one, and the orbit seen from its normal with the Earth's \
         shadow; the table on the left gives each filter's σ over the last minute and its own \
         √P beside the paper's Table 3 (click a row to make it the ghost).",
    params: PARAMS,
    presets: PRESETS,
    default_duration_s: 600.0,
    words: crate::model::lab_words!(),
};

const PAGE: Page = Page {
    figures: FIGURES,
    outages: &[
        Outage {
            id: "no-sun",
            series: SeriesKey::sensors(&sensors::SUN_SEEN),
            out_when: 0.0,
            label: "no sun reading (eclipse or outside the heads' fields)",
        },
        Outage {
            id: "star-tracker-out",
            series: SeriesKey::sensors(&sensors::STAR_AVAILABLE),
            out_when: 0.0,
            label: "star tracker out",
        },
    ],
    body: BodyShape::HexPrism,
    ..Page::DEFAULT
};

/// A random unit axis (x when the draw is degenerate).
fn random_axis(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    let axis = Vector3::new(
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
        rng.random_range(-1.0..1.0),
    );
    if axis.norm() > 1e-6 {
        axis.normalize()
    } else {
        Vector3::x()
    }
}

impl Lab for TabletSat {
    fn lesson(&self) -> Option<&'static crate::page::Lesson> {
        Some(&lesson::LESSON)
    }
    fn spec(&self) -> &'static LabSpec {
        &SPEC
    }

    fn dt_s(&self, p: &ParamValues) -> f64 {
        1.0 / p.get("predict_rate_hz").max(1.0)
    }

    fn build(&self, p: &ParamValues, rng: &mut ChaCha8Rng) -> LabRun {
        let truth = Spacecraft::new(p, rng);
        let sensors = Sensors::new(p, self.dt_s(p));
        let state = crate::model::TruthModel::state(&truth);
        let err = p.get("filter_init_err_deg").to_radians();
        let mut estimators: Vec<Box<dyn Estimator>> = Vec::with_capacity(FILTERS.len());
        let mut axes: Vec<(&str, Vector3<f64>)> = Vec::with_capacity(FILTERS.len());
        let tuned = tune::tuned_row(p);
        let rows = FILTERS
            .iter()
            .map(|row| (row, tuning as Retune))
            .chain([(&tuned, tune::tuned_tuning as Retune)]);
        for (row, retune) in rows {
            // Each filter starts off the truth by the same angle about its own random axis;
            // a constant-gain variant about its EKF's (drawing nothing, so adding one
            // changes no other filter's run).
            let earlier = row
                .starts_as
                .and_then(|id| axes.iter().find(|(a, _)| *a == id).map(|(_, v)| *v));
            let axis = earlier.unwrap_or_else(|| random_axis(rng));
            axes.push((row.config.id, axis));
            let q0 = state.q_ref_from_body * UnitQuaternion::from_scaled_axis(axis * err);
            let t = retune(p, row.q);
            let sigma = err.max(0.5f64.to_radians());
            let w0 = state.rate_body_rad_s;
            let e: Box<dyn Estimator> = match row.config.states.dim() {
                9 => Box::new(
                    Mekf::<9>::new(row.config, t, q0, w0, p0(row.config.states, sigma))
                        .with_retune(retune, row.q),
                ),
                _ => Box::new(
                    Mekf::<6>::new(row.config, t, q0, w0, p0(row.config.states, sigma))
                        .with_retune(retune, row.q),
                ),
            };
            estimators.push(e);
        }
        LabRun {
            truth: Box::new(truth),
            sensors: Box::new(sensors),
            estimators,
        }
    }

    fn page(&self) -> &'static Page {
        &PAGE
    }

    fn param_notes(&self, params: &ParamValues) -> Vec<crate::page::ParamNote> {
        tune::notes(params)
    }

    fn study(&self) -> Option<&dyn Study> {
        Some(self)
    }

    fn accuracy_table(&self) -> Option<AccuracyTable> {
        Some(AccuracyTable {
            title: "Accuracy over the last 60 s beside the paper's Tables 3–5",
            window_s: 60.0,
            paper: |id| {
                sets::filter(id).map_or([None, None], |f| [f.paper_att_deg, f.paper_rate_deg_s])
            },
            paper_table: |id| sets::filter(id).and_then(|f| f.table()),
        })
    }
}

impl Study for TabletSat {
    // The page never reproduces a paper (the CLI and the tests do): the `study` feature.
    #[cfg(feature = "study")]
    fn reproduce(&self) -> Result<crate::model::Reproduction, crate::model::ReproError> {
        Ok(reproduce::reproduce()?)
    }

    #[cfg(feature = "study")]
    fn chapter(&self) -> crate::model::Chapter {
        crate::model::lab_chapter!()
    }

    fn sweeps(&self) -> &'static [SweepSpec] {
        const SWEEPS: &[SweepSpec] = &[
            SweepSpec::new(
                "tune-q",
                "Tune Q under the unmodelled torque (attitude error, 200 s each)",
                "q_scale",
                &[0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0],
                200.0,
                &[
                    SeriesKey::new("st-gyro", &q::ERR_DEG),
                    SeriesKey::new("mag-sun-gyro", &q::ERR_DEG),
                    SeriesKey::new("mag-sun", &q::ERR_DEG),
                ],
            )
            .after(140.0),
            tune::SWEEP,
        ];
        SWEEPS
    }

    #[cfg(feature = "study")]
    fn timing_items(&self) -> Vec<crate::model::TimingItem> {
        timing::timing_items()
    }
}
