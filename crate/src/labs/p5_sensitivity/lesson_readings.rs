//! The numbers paper 5's lesson quotes that are not one series at one time: a method's
//! largest angle error at its k-th update (`gn9-update-3`), its largest error over the
//! updates after the tenth (`search11-after-10`), how far its p is from −b after 30 s
//! (`reint-p-plus-b`), and the angle of its linearised update's eigenvalues
//! (`gn9-eigen-angle`, degrees).

use super::METHODS;
use super::reproduce::{errors_at_updates, run_params};
use crate::analysis::{StatsContext, stats};
use crate::estimators::{linearised_eigenvalues, sensitivity};
use crate::model::{ParamValues, ReadingError, SeriesKey};

/// The run every reading looks at (s): the lesson's steps pause at 30 s at most.
const RUN_S: f64 = 30.0;

/// Reading `name` of the run of `params` (`None` for a name this lab does not know).
pub(super) fn reading(name: &str, params: &ParamValues) -> Option<Result<f64, ReadingError>> {
    let (id, what) = name.split_once('-')?;
    let (id, _, method) = METHODS.iter().find(|m| m.0 == id)?;
    let updates = || -> Result<Vec<f64>, ReadingError> {
        let trace = run_params(params.clone(), RUN_S, &[])?;
        errors_at_updates(&trace, id).map_err(ReadingError::from)
    };
    Some(if let Some(k) = what.strip_prefix("update-") {
        let k: usize = k.parse().ok()?;
        updates().and_then(|e| {
            (e.get(k.wrapping_sub(1)).copied()).ok_or(ReadingError::NoUpdate { method: id, k })
        })
    } else if let Some(k) = what.strip_prefix("after-") {
        let k: usize = k.parse().ok()?;
        updates().and_then(|e| {
            let late = e.get(k..).unwrap_or_default();
            stats::max(late)
                .of("late updates")
                .map_err(ReadingError::from)
        })
    } else if what == "p-plus-b" {
        p_plus_b(id, params)
    } else if what == "eigen-angle" {
        let [l, _] = linearised_eigenvalues(*method, params.get("interval_s"), params.get("eps"));
        Ok(l.arg().abs().to_degrees())
    } else {
        return None;
    })
}

/// |p + b| / |b| of method `id` after [`RUN_S`]: how far its correction is from cancelling
/// the gyro's bias b, along (1, −1, 2)/√6.
fn p_plus_b(id: &'static str, params: &ParamValues) -> Result<f64, ReadingError> {
    let keys = [
        &sensitivity::P_X_DEG_S,
        &sensitivity::P_Y_DEG_S,
        &sensitivity::P_Z_DEG_S,
    ]
    .map(|q| SeriesKey::new(id, q));
    let trace = run_params(params.clone(), RUN_S, &keys)?;
    let p: Vec<f64> = (keys.iter())
        .map(|k| trace.last(*k))
        .collect::<Result<_, _>>()?;
    let b = nalgebra::Vector3::new(1.0, -1.0, 2.0).normalize() * params.get("gyro_bias_deg_s");
    Ok((nalgebra::Vector3::new(p[0], p[1], p[2]) + b).norm() / b.norm())
}
