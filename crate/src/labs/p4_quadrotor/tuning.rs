//! Paper 4's tuning experiment as sweeps the page runs a slice per frame and `reproduce p4`
//! runs to the end: the γ sweep (Monte Carlo over seeds) scoring each run by the MSE over θ
//! and ω, the transient time and J = α·MSE + β·t_tr for the paper's three (α, β) pairs; the
//! Q landscape over the two elements of Q with R fixed; and the γ sweep on a recorded log.
//!
//! Definitions (ours where the paper is silent):
//! * MSE = mean over the run of (θ̂ − θ)² + (ω̂ − ω)², in deg² and (deg/s)² (the paper's).
//! * t_tr = time from the set-point step (at `step_period_s`) until the rig's true angle θ,
//!   averaged over ±50 ms, stays within 5 % of the step of the new set-point; the rest of
//!   the half period when it never does. That is what the paper could time on its rig: the
//!   closed-loop angle. With the loop on the truth it cannot depend on the filter.
//! * offset = |mean θ̂ − θ| over the last second before the step and before the next one,
//!   averaged; noise = RMS of the sample-to-sample differences of θ̂ − θ over the second
//!   before the step, over √2 (a slow drift does not count as noise).

use super::keys as roll_keys;
use crate::analysis::stats;
use crate::model::{
    ParamValues, ScoreError, Scored, SeriesKey, StatsError, SweepScoring, SweepSpec, q,
};

/// The series the simulated runs are scored on.
const SCORED: &[SeriesKey] = &[
    SeriesKey::truth(&q::ANGLE_DEG),
    SeriesKey::new("kf", &q::ANGLE_ERR_DEG),
    SeriesKey::new("kf", &q::RATE_ERR_DEG_S),
];

/// The scores' names, in the order [`score_run`] returns them.
pub const SCORE_NAMES: &[&str] = &[
    "MSE (deg², (deg/s)²)",
    "t_tr (s)",
    "offset (°)",
    "noise (°)",
];

/// The paper's three (α, β) pairs of eq. 6, in Table 1's order.
pub const PAIRS: [(f64, f64); 3] = [(0.3, 0.7), (0.7, 0.3), (0.5, 0.5)];

const HELP: &str = "MSE: mean of (θ̂ − θ)² + (ω̂ − ω)² over the run (the paper's). t_tr: from the set-point step until the rig's angle θ (±50 ms average) stays within 5 % of the step (ours; the paper does not define it; with the loop on the truth it does not depend on γ). Offset: |mean θ̂ − θ| in the settled seconds. Noise: sample-to-sample scatter of θ̂ − θ at rest. Medians over the seeds; J = α·MSE + β·t_tr with the paper's weights.";

/// Scoring of the γ sweep: J for the paper's three pairs, in Table 1's order.
pub const TABLE1: SweepScoring = SweepScoring {
    names: SCORE_NAMES,
    help: HELP,
    series: SCORED,
    score: score_run,
    objectives: &[
        ("J(α = 0.3, β = 0.7)", &[0.3, 0.7, 0.0, 0.0]),
        ("J(α = 0.7, β = 0.3)", &[0.7, 0.3, 0.0, 0.0]),
        ("J(α = 0.5, β = 0.5)", &[0.5, 0.5, 0.0, 0.0]),
    ],
    overlay: None,
};

/// Scoring of the Q landscape: the heat map shows the first objective, J(0.5, 0.5).
const LANDSCAPE: SweepScoring = SweepScoring {
    objectives: &[
        ("J(α = 0.5, β = 0.5)", &[0.5, 0.5, 0.0, 0.0]),
        ("MSE", &[1.0, 0.0, 0.0, 0.0]),
        ("t_tr", &[0.0, 1.0, 0.0, 0.0]),
    ],
    overlay: Some(gamma_lines),
    ..TABLE1
};

/// Scoring on a recorded log, where there is no truth: θ̂ against the accelerometer angle
/// smoothed forwards and backwards (a proxy for the truth, which lags nowhere) and θ̂'s own
/// jitter (second differences).
const ON_LOG: SweepScoring = SweepScoring {
    names: &["RMS θ̂ − smoothed θ_acc (°)", "jitter of θ̂ (°)"],
    help: "A log has no truth. The reference is the accelerometer angle low-passed at 1 Hz forwards and then backwards (zero phase): it has no lag but keeps the accelerometer's errors during fast motion, so this is a proxy for the MSE, not the MSE. Jitter: RMS of θ̂'s second differences over √6 (white noise of σ gives σ; a steady motion gives 0).",
    series: &[
        SeriesKey::new("kf", &q::ANGLE_DEG),
        SeriesKey::sensors(&super::mpu6050::ACCEL_ANGLE_DEG),
    ],
    score: score_log,
    objectives: &[("RMS against the smoothed reference", &[1.0, 0.0])],
    overlay: None,
};

/// γ values of the page's sweep: the paper's grid {0.2, 0.02, 2·10⁻³, 10⁻⁵} and values
/// between and beyond.
const GAMMAS: &[f64] = &[
    1e-7, 1e-6, 1e-5, 1e-4, 5e-4, 2e-3, 5e-3, 0.02, 0.05, 0.2, 1.0,
];

/// The lab's sweeps.
pub const SWEEPS: &[SweepSpec] = &[
    SweepSpec::new(
        "gamma",
        "γ: Table 1 (MSE, t_tr, J) over 5 seeds, 8 s with one step",
        roll_keys::GAMMA,
        GAMMAS,
        8.0,
        &[
            SeriesKey::new("kf", &q::ANGLE_ERR_DEG),
            SeriesKey::new("kf", &q::RATE_ERR_DEG_S),
        ],
    )
    .fixed(&[(roll_keys::Q_FROM, 0.0)])
    .seeds(5)
    .scoring(&TABLE1)
    .log_scoring(&ON_LOG),
    SweepSpec::new(
        "q-landscape",
        "Q landscape: J over q_θ × q_ω with R fixed, 2 seeds, 8 s",
        roll_keys::Q_ANGLE,
        &[1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2],
        8.0,
        &[SeriesKey::new("kf", &q::ANGLE_ERR_DEG)],
    )
    .grid(
        roll_keys::Q_RATE,
        &[1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0],
    )
    .fixed(&[(roll_keys::Q_FROM, 1.0)])
    .seeds(2)
    .scoring(&LANDSCAPE),
];

/// MSE, t_tr, offset and noise of one run; `columns` are those of `SCORED` (the true angle,
/// the KF's error and its rate error).
pub fn score_run(
    p: &ParamValues,
    t_s: &[f64],
    columns: &[Vec<f64>],
) -> Result<Vec<f64>, ScoreError> {
    let [angle, err_angle, err_rate] = columns else {
        return Err(ScoreError::Columns {
            expected: 3,
            got: columns.len(),
        });
    };
    let step_at = p.get("step_period_s");
    let step_deg = p.get("setpoint_deg");
    if step_deg <= 0.0 {
        return Err(ScoreError::NoStep);
    }
    let t_end = t_s.last().copied().unwrap_or(0.0);
    if t_end < step_at + 1.0 {
        return Err(ScoreError::EndsTooSoon {
            end_s: t_end,
            step_s: step_at,
        });
    }
    let dt = t_s.windows(2).next().map_or(0.01, |w| w[1] - w[0]);
    // The settled window ends at the next step (back to 0) or at the end of the run.
    let settle_end = if t_end >= 2.0 * step_at - 0.5 * dt {
        2.0 * step_at
    } else {
        t_end
    };
    let sq: Vec<f64> = err_angle
        .iter()
        .zip(err_rate)
        .map(|(a, r)| a * a + r * r)
        .collect();
    let mse = stats::mean(&sq).map_err(stat(Scored::Mse))?;
    let t_tr = transient_time(t_s, angle, step_at, step_deg, settle_end)?;
    let window = |from: f64, to: f64| -> Vec<f64> {
        t_s.iter()
            .zip(err_angle)
            .filter(|(t, _)| (from..to).contains(*t))
            .map(|(_, e)| *e)
            .collect()
    };
    let still = window(step_at - 1.0, step_at);
    let settled = window(settle_end - 1.0, settle_end);
    let before = stats::mean(&still).map_err(stat(Scored::OffsetBefore))?;
    let after = stats::mean(&settled).map_err(stat(Scored::OffsetAfter))?;
    let steps: Vec<f64> = still
        .windows(2)
        .map(|w| (w[1] - w[0]) / std::f64::consts::SQRT_2)
        .collect();
    let noise = stats::rms(&steps).map_err(stat(Scored::Noise))?;
    Ok(vec![mse, t_tr, (before.abs() + after.abs()) / 2.0, noise])
}

/// The transient time after the step at `step_at` (see the module's definitions).
fn transient_time(
    t_s: &[f64],
    angle: &[f64],
    step_at: f64,
    step_deg: f64,
    settle_end: f64,
) -> Result<f64, ScoreError> {
    let band = 0.05 * step_deg;
    let half = 5usize;
    let mut last_out = step_at;
    let mut last_t = step_at;
    for (k, t) in t_s.iter().enumerate() {
        if *t < step_at || *t >= settle_end + 1e-9 {
            continue;
        }
        last_t = *t;
        let window = &angle[k.saturating_sub(half)..(k + half + 1).min(angle.len())];
        let mean = stats::mean(window).map_err(stat(Scored::TransientTime))?;
        if (mean - step_deg).abs() >= band {
            last_out = *t;
        }
    }
    Ok(if last_out >= last_t - 0.06 {
        settle_end - step_at
    } else {
        last_out - step_at
    })
}

/// RMS of θ̂ against the zero-phase-smoothed accelerometer angle, and θ̂'s jitter.
fn score_log(_p: &ParamValues, t_s: &[f64], columns: &[Vec<f64>]) -> Result<Vec<f64>, ScoreError> {
    let [angle, accel] = columns else {
        return Err(ScoreError::Columns {
            expected: 2,
            got: columns.len(),
        });
    };
    // Samples where both are known (a log's first step may deliver nothing yet).
    let (mut a, mut r, mut t) = (Vec::new(), Vec::new(), Vec::new());
    for ((x, y), ti) in angle.iter().zip(accel).zip(t_s) {
        if x.is_finite() && y.is_finite() {
            a.push(*x);
            r.push(*y);
            t.push(*ti);
        }
    }
    if a.len() < 20 {
        return Err(ScoreError::FewSamples { n: a.len() });
    }
    let dt = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
    let reference = zero_phase_low_pass(&r, dt, 1.0);
    let diff: Vec<f64> = a.iter().zip(&reference).map(|(x, y)| x - y).collect();
    // Second differences: a steady motion does not count, white noise of σ gives σ·√6.
    let jitter: Vec<f64> = a
        .windows(3)
        .map(|w| (w[2] - 2.0 * w[1] + w[0]) / 6f64.sqrt())
        .collect();
    Ok(vec![
        stats::rms(&diff).map_err(stat(Scored::Rms))?,
        stats::rms(&jitter).map_err(stat(Scored::Jitter))?,
    ])
}

/// A failed statistic of `of` as a scoring error.
fn stat(of: Scored) -> impl Fn(StatsError) -> ScoreError {
    move |source| ScoreError::Stat { of, source }
}

/// A first-order low-pass at `cutoff_hz` run forwards and then backwards (no lag).
fn zero_phase_low_pass(x: &[f64], dt_s: f64, cutoff_hz: f64) -> Vec<f64> {
    let tau = 1.0 / (std::f64::consts::TAU * cutoff_hz);
    let k = dt_s / (tau + dt_s);
    let pass = |v: &mut dyn Iterator<Item = f64>| -> Vec<f64> {
        let mut out = Vec::with_capacity(x.len());
        let mut y = f64::NAN;
        for s in v {
            y = if y.is_nan() { s } else { y + k * (s - y) };
            out.push(y);
        }
        out
    };
    let forward = pass(&mut x.iter().copied());
    let mut back = pass(&mut forward.iter().rev().copied());
    back.reverse();
    back
}

/// Lines of constant γ on the Q landscape (q_θ·q_ω = γ·det R, R fixed at the sliders'
/// σ) for γ* = 2·10⁻³ and the paper's other grid values, and the γ mapping's ray
/// q_θ/q_ω = dt²/3.
fn gamma_lines(p: &ParamValues) -> Vec<(&'static str, Vec<[f64; 2]>)> {
    let det_r = (p.get(roll_keys::SIGMA_ANGLE) * p.get(roll_keys::SIGMA_RATE)).powi(2);
    let dt = 1.0 / p.get("sample_hz");
    let qa: Vec<f64> = (0..=40)
        .map(|k| 10f64.powf(-10.0 + 8.0 * f64::from(k) / 40.0))
        .collect();
    let mut lines: Vec<(&'static str, Vec<[f64; 2]>)> =
        [(2e-3, "γ* = 2·10⁻³"), (0.2, "γ = 0.2"), (1e-5, "γ = 10⁻⁵")]
            .iter()
            .map(|(g, name)| {
                let pts = qa.iter().map(|a| [*a, g * det_r / a]).collect();
                (*name, pts)
            })
            .collect();
    let ray = qa.iter().map(|a| [*a, a * 3.0 / (dt * dt)]).collect();
    lines.push(("the γ mapping: q_θ/q_ω = dt²/3", ray));
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_zero_phase_low_pass_does_not_lag_a_ramp() {
        let x: Vec<f64> = (0..400).map(|k| f64::from(k) * 0.01).collect();
        let y = zero_phase_low_pass(&x, 0.01, 1.0);
        // Away from the ends, a ramp passes unchanged (a one-way low-pass would lag by τ).
        assert!((y[200] - x[200]).abs() < 1e-3, "{} vs {}", y[200], x[200]);
    }
}
