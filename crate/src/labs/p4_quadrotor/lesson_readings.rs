//! The numbers paper 4's lesson quotes that are the γ sweep's scores, read as the page's
//! sweep scores each γ (medians over five seeds of an 8-s run; see `reproduce`): the offset,
//! the rig's settling time, the scatter of θ̂ − θ at rest, the MSE, and which γ of the
//! paper's grid is best.

use super::reproduce::{best_of_grid, score_params};
use super::{QuadrotorRoll, keys, tuning};
use crate::analysis::sweep::Sweep;
use crate::model::{ParamValues, ReadingError};
use crate::page::Lab;

/// Reading `name` of the run of `params` (`None` for a name this lab does not know).
pub(super) fn reading(name: &str, params: &ParamValues) -> Option<Result<f64, ReadingError>> {
    let score =
        || score_params(params.clone(), params.get(keys::GAMMA)).map_err(ReadingError::from);
    Some(match name {
        // |mean θ̂ − θ| over the settled seconds (deg).
        "offset" => score().map(|s| s.offset_deg),
        // The rig's true angle within 5 % of the step (s).
        "settling" => score().map(|s| s.t_tr_s),
        // θ̂ − θ's sample-to-sample scatter at rest (deg), without its slow wander.
        "scatter" => score().map(|s| s.noise_deg),
        // MSE over θ and ω (deg² + (deg/s)²).
        "mse" => score().map(|s| s.mse),
        // The γ of the paper's four with the least J(0.5, 0.5).
        "best-of-grid" => best_of_grid(params).map_err(ReadingError::from),
        // The γ of the page's finer sweep with the least J(0.5, 0.5).
        "best-of-sweep" => Ok(best_of_sweep(params)),
        _ => return None,
    })
}

/// The argmin of J(0.5, 0.5) over the page's γ sweep from `params`.
fn best_of_sweep(params: &ParamValues) -> f64 {
    let lab: &'static dyn Lab = &QuadrotorRoll;
    let sweep = Sweep::new(lab, tuning::SWEEPS[0], params.clone(), 1).run_to_end();
    let half =
        (tuning::TABLE1.objectives.iter()).position(|(name, _)| name.contains("0.5, β = 0.5"));
    half.and_then(|k| sweep.argmin(k))
        .map_or(f64::NAN, |p| p.value)
}
