//! A glance at the run, for a screen reader's live description ("ST+Gyro: attitude error
//! 0.0008°, within its 3σ band"): each estimator's attitude (or angle) error against the
//! truth now, and the 3σ its own covariance gives.

use super::Simulation;
use crate::math::small_angle_error_body;
use crate::model::{Estimator, StateKind};

/// One estimator at this instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Glance {
    /// The estimator's position in the lab's list.
    pub estimator: usize,
    /// The largest attitude error about a body axis (or the angle error of a single-axis
    /// estimator) against the truth (deg); NaN without a truth (a replayed log) or for an
    /// estimator that has no whole attitude (a tilt-only one).
    pub error_deg: f64,
    /// 3·√(largest attitude or angle variance) of its covariance (deg); NaN without one.
    pub three_sigma_deg: f64,
}

/// An attitude error this small is rounding, not estimation (deg).
const ROUNDING_DEG: f64 = 1e-9;

impl Glance {
    /// Whether the error is inside the estimator's own ±3σ; `None` when either is unknown.
    /// An error at rounding level (10⁻⁹°) is inside a band that has not opened yet (an
    /// integrator's zero covariance at t = 0).
    pub fn within(&self) -> Option<bool> {
        (self.error_deg.is_finite() && self.three_sigma_deg.is_finite())
            .then_some(self.error_deg <= self.three_sigma_deg.max(ROUNDING_DEG))
    }
}

impl Simulation {
    /// Estimator `i` at this instant, if there is one.
    pub fn glance(&self, i: usize) -> Option<Glance> {
        let estimator = self.estimators().get(i)?;
        let error_deg = self.error_deg(i, &self.truth())?;
        Some(Glance {
            estimator: i,
            error_deg,
            three_sigma_deg: 3.0 * attitude_sigma_deg(estimator.as_ref()),
        })
    }
}

impl Simulation {
    /// Estimator `i`'s largest attitude error about a body axis (or its angle error)
    /// against `truth` (deg), as [`Glance::error_deg`]; None when there is no estimator `i`.
    pub(super) fn error_deg(&self, i: usize, truth: &crate::model::TruthState) -> Option<f64> {
        let outputs = self.estimators().get(i)?.outputs();
        let estimate = self.estimates().get(i)?;
        Some(if self.has_truth() {
            error_deg(outputs, estimate, truth)
        } else {
            f64::NAN
        })
    }
}

/// The largest attitude error about a body axis of `estimate` (or its angle error, for an
/// estimator whose `outputs` are an angle) against `truth` (deg); NaN for neither.
pub(super) fn error_deg(
    outputs: crate::model::Outputs,
    estimate: &crate::model::Estimate,
    truth: &crate::model::TruthState,
) -> f64 {
    {
        if outputs.attitude {
            estimate.quaternion().map_or(f64::NAN, |q| {
                let e = small_angle_error_body(&truth.q_ref_from_body, &q);
                e.amax().to_degrees()
            })
        } else if outputs.angle {
            match (estimate.angle_rad, truth.angle_rad) {
                (Some(est), Some(t)) => wrapped(est - t).abs().to_degrees(),
                _ => f64::NAN,
            }
        } else {
            f64::NAN
        }
    }
}

/// An angle difference brought into (−π, π].
fn wrapped(a: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    let w = a.rem_euclid(tau);
    if w > std::f64::consts::PI { w - tau } else { w }
}

/// √ of the largest attitude (or angle) variance of `e`'s covariance (deg); NaN without one.
fn attitude_sigma_deg(e: &dyn Estimator) -> f64 {
    let Some(c) = e.covariance() else {
        return f64::NAN;
    };
    let variances = (0..c.dim())
        .filter(|&k| {
            matches!(
                c.states[k].kind,
                StateKind::AttitudeAxis(_) | StateKind::Angle
            )
        })
        .map(|k| c.get(k, k));
    // A variance that is not a number makes the whole answer NaN, never a smaller one.
    let largest = variances.fold(None, |acc: Option<f64>, v| match acc {
        Some(a) if a.is_nan() || v.is_nan() => Some(f64::NAN),
        Some(a) => Some(a.max(v)),
        None => Some(v),
    });
    largest.map_or(f64::NAN, |v| v.sqrt().to_degrees())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::labs;
    use crate::model::ParamValues;

    fn sim(lab_id: &str, params: &[(&str, f64)]) -> Simulation {
        let lab = labs::find(lab_id).expect("registered");
        let mut values = ParamValues::defaults(lab.params());
        for (k, v) in params {
            values.set(lab.params(), k, *v).expect("valid");
        }
        Simulation::new(lab, values, 3)
    }

    /// Without noise or bias, gyro integration follows the truth: the glance says the error
    /// is (nearly) zero; with a bias it grows like bias × t.
    #[test]
    fn the_error_is_the_truths_and_grows_with_a_bias() {
        let zero = [("gyro_noise_deg_s", 0.0), ("gyro_bias_deg_s", 0.0)];
        let mut clean = sim("free-rotation", &zero);
        clean.run_for(5.0);
        let g = clean.glance(0).expect("an estimator");
        assert!(g.error_deg < 1e-3, "{g:?}");
        let mut biased = sim(
            "free-rotation",
            &[("gyro_noise_deg_s", 0.0), ("gyro_bias_deg_s", 0.5)],
        );
        biased.run_for(5.0);
        let g = biased.glance(0).expect("an estimator");
        // 0.5 °/s for 5 s on each axis, seen about the body axes of a tumbling body.
        assert!(g.error_deg > 0.5 && g.error_deg < 2.5 * 5.0 * 0.5, "{g:?}");
        assert!(biased.glance(99).is_none());
    }

    /// A Kalman filter's glance has its own 3σ, and a consistent filter is inside it; the
    /// single-axis labs give the angle error.
    #[test]
    fn a_filter_has_its_band_and_a_single_axis_lab_its_angle() {
        let mut s = sim("p4", &[]);
        s.run_for(3.0);
        let glances: Vec<Glance> = (0..s.estimators().len())
            .filter_map(|i| s.glance(i))
            .collect();
        assert!(
            glances.iter().all(|g| g.error_deg.is_finite()),
            "{glances:?}"
        );
        let with_band: Vec<&Glance> = glances
            .iter()
            .filter(|g| g.three_sigma_deg.is_finite())
            .collect();
        assert!(!with_band.is_empty(), "{glances:?}");
        assert!(with_band.iter().all(|g| g.three_sigma_deg > 0.0));
    }

    #[test]
    fn within_needs_both_numbers() {
        let g = |e, s| Glance {
            estimator: 0,
            error_deg: e,
            three_sigma_deg: s,
        };
        assert_eq!(g(0.1, 0.3).within(), Some(true));
        assert_eq!(g(0.4, 0.3).within(), Some(false));
        assert_eq!(g(f64::NAN, 0.3).within(), None);
        assert_eq!(g(0.1, f64::NAN).within(), None);
        assert_eq!(g(3.2e-15, 0.0).within(), Some(true), "rounding at t = 0");
        approx::assert_relative_eq!(wrapped(3.0 * std::f64::consts::PI), std::f64::consts::PI);
        approx::assert_relative_eq!(wrapped(-0.1), -0.1, epsilon = 1e-15);
    }
}
