//! Foundation lab "free rotation": a torque-free rigid body tumbling, a three-axis gyro, and
//! two gyro-only integrators — quaternion and paper 3's (u, v, z). It exercises every part
//! of the pipeline and shows how a gyro bias makes pure integration drift. Spun about the
//! intermediate axis the body flips over and over (Dzhanibekov effect), which sends w
//! through ∞ and exercises the chart switch of the (u, v, z) integrator.

mod lesson;
mod page;
mod params;
mod reproduce;
mod sensors;
mod truth;

use crate::estimators::{GyroErrors, IntegrationErrorModel, QuaternionIntegration, WzIntegration};
use crate::math::WzAttitude;
use crate::model::{Estimator, LabRun, LabSpec, ParamValues, SensorModel, Study, TruthModel};
use crate::page::{Lab, Page};
use crate::sensors::{Gyro3, Gyro3Config};
use rand_chacha::ChaCha8Rng;
use sensors::GyroSensors;
use truth::Tumble;

/// The free-rotation lab.
pub struct FreeRotation;

/// The gyro's error budget the integrators publish their covariance from.
fn gyro_errors(p: &ParamValues) -> GyroErrors {
    GyroErrors::from_deg_s(p.get("gyro_noise_deg_s"), p.get("gyro_bias_deg_s"))
}

const SPEC: LabSpec = LabSpec {
    id: "free-rotation",
    title: "Free rotation (gyro integration)",
    paper: "Foundation lab; kinematics of paper 3 (Matveev et al. 2025), eq. 21",
    reference: "Matveev V. V. et al. Study of new kinematic parameters for strapdown orientation systems. Devices and Methods of Measurements, 2025, vol. 16, no. 3, pp. 202–211 (in Russian): its kinematics, eq. 21.",
    summary: "A rigid body tumbles without torque (Euler's equations). A three-axis gyro measures its \
         rate with noise and bias, and two estimators integrate the gyro: quaternions \
         (q̇ = ½ q⊗ω) and paper 3's (u, v, z) (eq. 21), which switches to the flipped chart \
         s = 1/w when the body turns upside down. Without noise and bias both follow the truth; \
         the bias slider makes both drift the same way, the noise slider adds a random walk. \
         The inertia sliders change the tumbling live; spin, axis and tilt apply at reset.",
    params: params::PARAMS,
    presets: &[],
    default_duration_s: 60.0,
    words: crate::model::lab_words!(),
};

const PAGE: Page = Page {
    figures: page::FIGURES,
    ..Page::DEFAULT
};

impl Lab for FreeRotation {
    fn lesson(&self) -> Option<&'static crate::page::Lesson> {
        Some(&lesson::LESSON)
    }
    fn spec(&self) -> &'static LabSpec {
        &SPEC
    }

    fn dt_s(&self, params: &ParamValues) -> f64 {
        1.0 / params.get("rate_hz").clamp(1.0, 1e4)
    }

    fn build(&self, params: &ParamValues, _rng: &mut ChaCha8Rng) -> LabRun {
        let mut truth = Tumble::new(params);
        truth.apply_params(params);
        let state = truth.state();
        let mut sensors = GyroSensors {
            gyro: Gyro3::new(Gyro3Config::default()),
        };
        sensors.apply_params(params);
        let model = IntegrationErrorModel::new(0.0, 0.0);
        let mut estimators: Vec<Box<dyn Estimator>> = vec![
            Box::new(
                QuaternionIntegration::new(state.q_ref_from_body, model).tuned_by(gyro_errors),
            ),
            Box::new(
                WzIntegration::new(WzAttitude::from_quaternion(&state.q_ref_from_body), model)
                    .tuned_by(gyro_errors),
            ),
        ];
        estimators.iter_mut().for_each(|e| e.apply_params(params));
        LabRun {
            truth: Box::new(truth),
            sensors: Box::new(sensors),
            estimators,
        }
    }

    fn page(&self) -> &'static Page {
        &PAGE
    }

    fn study(&self) -> Option<&dyn Study> {
        Some(self)
    }
}

impl Study for FreeRotation {
    fn golden_assignments(&self) -> &'static [&'static str] {
        &[
            "gyro_noise_deg_s=0.05",
            "gyro_bias_deg_s=0.2",
            "gyro_walk_deg_s_sqrt_s=0.01",
        ]
    }

    // The page never reproduces a paper (the CLI and the tests do): the `study` feature.
    #[cfg(feature = "study")]
    fn reproduce(&self) -> Result<crate::model::Reproduction, crate::model::ReproError> {
        Ok(reproduce::reproduce()?)
    }

    #[cfg(feature = "study")]
    fn chapter(&self) -> crate::model::Chapter {
        crate::model::lab_chapter!()
    }
}
