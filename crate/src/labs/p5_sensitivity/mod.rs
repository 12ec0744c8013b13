//! Lab "p5": paper 5 — correcting measured angular rates from reference attitudes with the
//! sensitivity matrix (Bashniakov, Pichkur, Polishchuk, Linder). A body turns (or, in the
//! paper's case, holds still); its measured rates drive quaternion kinematics with an
//! additive correction p, which every reference attitude updates by one Gauss–Newton step
//! through U = ∂Λ/∂p. The paper's three update rules and a re-integrating variant run side by
//! side on the same measurements.

mod lesson;
#[cfg(feature = "study")]
mod lesson_readings;
mod page;
mod params;
mod reproduce;
mod sensors;
mod truth;

use crate::estimators::SensitivityCorrection;
use crate::math::quaternion_from_sequence;
use crate::model::{Estimator, LabRun, LabSpec, OutputFile, ParamValues, Study};
use crate::page::{Lab, Page};
use nalgebra::Vector3;
use rand_chacha::ChaCha8Rng;
use sensors::Sensors;
use truth::Turning;

pub use params::METHODS;
pub use reproduce::first_hit_s;

/// The paper-5 lab.
pub struct SensitivityLab;

const SPEC: LabSpec = LabSpec {
    id: "p5",
    title: "Paper 5: correcting rates with the sensitivity matrix",
    paper: "Bashniakov, Pichkur, Polishchuk, Linder, adaptive correction of angular velocities via the sensitivity matrix",
    reference: "Bashniakov A., Pichkur V., Polishchuk A., Linder Y. (Taras Shevchenko National University of Kyiv). On correcting a rigid body's angular velocities from reference attitudes by the sensitivity matrix (title as the project's digest describes it; the paper's own title, venue and year are not recorded). UDC 519.688.",
    summary: "Measured rates ω drive the quaternion, 2Λ̇ = Λ ∘ (ω + p), with an additive correction p. \
         Beside Λ runs the sensitivity U = ∂Λ/∂p (4×3), reset to 0 at every reference. At each \
         reference attitude (every Δt) p takes one Gauss–Newton step h = (UᵀQU + εI)⁻¹UᵀQ(Λ_ref − Λ). \
         Method (9) continues the state and — linearised, its update has determinant 1, both \
         eigenvalues on the unit circle — oscillates for ever: it meets the tolerance for the first \
         time just after 2Δt, then leaves it again. (10) adds ε, (11) searches the step size on the \
         re-integrated interval; beyond the paper, re-integrating the last interval with the new p \
         converges in a few intervals. The diagram shows the eigenvalues for the current Δt and ε. \
         With a biased gyro p converges to −b; with the reference lost, the corrected integration \
         runs free and re-converges when it returns. The output file is the paper's: rows of \
         (t, angle₁, angle₂, angle₃) ending at the first row within tolerance.",
    params: params::PARAMS,
    presets: params::PRESETS,
    default_duration_s: 30.0,
    words: crate::model::lab_words!(),
};

const PAGE: Page = Page {
    figures: page::FIGURES,
    diagrams: Some(page::diagrams),
    ..Page::DEFAULT
};

impl Lab for SensitivityLab {
    fn lesson(&self) -> Option<&'static crate::page::Lesson> {
        Some(&lesson::LESSON)
    }
    fn spec(&self) -> &'static LabSpec {
        &SPEC
    }

    fn dt_s(&self, p: &ParamValues) -> f64 {
        p.get("step_s")
    }

    fn build(&self, p: &ParamValues, _rng: &mut ChaCha8Rng) -> LabRun {
        let axes = params::axes_of(p);
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
        let truth = Turning::new(p, reference, axes);
        let sensors = Sensors::new(p);
        let p0 = Vector3::new(
            p.get("p0_x_deg_s"),
            p.get("p0_y_deg_s"),
            p.get("p0_z_deg_s"),
        )
        .map(f64::to_radians);
        let settings = params::settings_of(p);
        let mut estimators: Vec<Box<dyn Estimator>> = METHODS
            .iter()
            .map(|(id, label, method)| -> Box<dyn Estimator> {
                Box::new(
                    SensitivityCorrection::new(id, label, *method, start, p0, settings)
                        .tuned_by(params::settings_of),
                )
            })
            .collect();
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

    fn study(&self) -> Option<&dyn Study> {
        Some(self)
    }
}

impl Study for SensitivityLab {
    // The page never reproduces a paper (the CLI and the tests do): the `study` feature.
    #[cfg(feature = "study")]
    fn reproduce(&self) -> Result<crate::model::Reproduction, crate::model::ReproError> {
        Ok(reproduce::reproduce()?)
    }

    #[cfg(feature = "study")]
    fn chapter(&self) -> crate::model::Chapter {
        crate::model::lab_chapter!()
    }

    fn output_file(&self, p: &ParamValues) -> Option<OutputFile> {
        Some(page::output_file(p))
    }

    #[cfg(feature = "study")]
    fn lesson_reading(
        &self,
        name: &str,
        params: &ParamValues,
        _seed: u64,
    ) -> Option<Result<f64, crate::model::ReadingError>> {
        lesson_readings::reading(name, params)
    }
}
