//! `attlab reproduce p4`: Table 1 as measured here beside the paper's — for γ ∈ {0.2, 0.02,
//! 2·10⁻³, 10⁻⁵} the MSE over θ and ω, the transient time and J = α·MSE + β·t_tr for the
//! three (α, β) pairs — which γ minimises J for each pair, and the paper's qualitative
//! finding: small γ biased and slow, large γ noisy.
//!
//! Each γ is run over five seeds (the median is reported) for 8 s with the set-point stepping
//! from 0 to 20° at 4 s (the paper's Fig. 2 spans 0–7 s), the controller acting on the KF's
//! θ̂ as in Fig. 1 (and, as a labelled variant, on the truth). MSE = mean of (θ̂ − θ)² +
//! (ω̂ − ω)² in deg² and (deg/s)²; t_tr = the time from the step until the rig's angle θ
//! stays within 5 % of the step of the new set-point, averaged over ±50 ms (the rest of the
//! run, 4 s, when it never does).
// Only the CLI and the tests reproduce a paper (the `study` feature): without it, what only
// `reproduce` uses is left out (the page's wasm).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::keys as roll_keys;
use super::{QuadrotorRoll, tuning};
use crate::analysis::AnalysisError;
use crate::analysis::scenario::params_with;
use crate::analysis::sweep::Sweep;
use crate::model::{Calibration, Expectation, Reproduction, Row, SweepSpec, fmt_sig};
use crate::page::Lab;

/// The paper's γ grid (the exponent of the last one is lost in the OCR; n > 3) and its
/// Table 1: (MSE, t_tr s).
const GRID: [(f64, &str, f64, f64); 4] = [
    (0.2, "0.2", 50333.0, 1.0),
    (0.02, "0.02", 54366.0, 1.3),
    (2e-3, "2·10⁻³", 42378.0, 1.0),
    (1e-5, "10⁻ⁿ (read as 10⁻⁵)", 49137.0, 1.6),
];

/// The (α, β) pairs of eq. 6 and the paper's J for each γ of the grid.
const PAIRS: [(f64, f64, [f64; 4]); 3] = [
    (0.3, 0.7, [15100.0, 16310.0, 12714.0, 14742.0]),
    (0.7, 0.3, [35233.0, 38056.0, 29664.0, 34396.0]),
    (0.5, 0.5, [25167.0, 27183.0, 21189.0, 24569.0]),
];

const SEEDS: u64 = 5;
/// The propeller vibration at the IMU: its default (0.2 g) was chosen here (the paper gives
/// none) so that J's argmin lands on the paper's γ*.
const VIBRATION: &str = "vibration_g";
/// The vibration levels the reproduction runs, as factors of the default: ±50 % and beyond.
const VIBRATION_FACTORS: [f64; 5] = [0.25, 0.5, 1.0, 1.5, 2.0];
const RUN_S: f64 = 8.0;
const STEP_AT_S: f64 = 4.0;
const STEP_DEG: f64 = 20.0;

/// One γ's scores, medians over the seeds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GammaScore {
    /// γ.
    pub gamma: f64,
    /// MSE over θ and ω (deg², (deg/s)²).
    pub mse: f64,
    /// Transient time (s).
    pub t_tr_s: f64,
    /// |Mean θ̂ − θ| over the last second before the step and over the last second of the
    /// run, averaged (deg): the offset.
    pub offset_deg: f64,
    /// Scatter of θ̂ − θ over the same second (deg): the RMS of its sample-to-sample
    /// differences over √2, the noise without the drift.
    pub noise_deg: f64,
}

/// The scores of `gamma`: medians over five seeds.
pub fn score_gamma(gamma: f64) -> Result<GammaScore, AnalysisError> {
    score_gamma_with(gamma, &[])
}

/// The scores of `gamma` with the parameter assignments `extra` (`key=value`): the page's γ
/// sweep (same scoring, same seeds) over this one value.
pub fn score_gamma_with(gamma: f64, extra: &[&str]) -> Result<GammaScore, AnalysisError> {
    let lab: &'static dyn Lab = &QuadrotorRoll;
    let step = format!("setpoint_deg={STEP_DEG}");
    let period = format!("step_period_s={STEP_AT_S}");
    let mut set = vec![step.as_str(), period.as_str()];
    set.extend_from_slice(extra);
    score_params(params_with(lab, &set)?, gamma)
}

/// The scores of `gamma` on top of `base` (every other parameter as it says): medians over
/// five seeds of an 8-s run, as the page's γ sweep scores each value.
pub fn score_params(
    base: crate::model::ParamValues,
    gamma: f64,
) -> Result<GammaScore, AnalysisError> {
    let lab: &'static dyn Lab = &QuadrotorRoll;
    let spec = tuning::SWEEPS[0];
    let sweep = Sweep::new(
        lab,
        SweepSpec {
            duration_s: RUN_S,
            seeds: SEEDS,
            ..spec
        },
        base,
        1,
    )
    .with_values(vec![gamma])
    .run_to_end();
    if let Some(reason) = sweep.skipped.first() {
        return Err(AnalysisError::Scenario(reason.to_string()));
    }
    let point = sweep
        .points
        .first()
        .ok_or_else(|| AnalysisError::Scenario(format!("γ = {gamma} was not run")))?;
    if let Some(reason) = point.unscored.first() {
        return Err(AnalysisError::Scenario(format!("γ = {gamma}: {reason}")));
    }
    let [mse, t_tr_s, offset_deg, noise_deg] = point.scores[..] else {
        return Err(AnalysisError::Scenario(format!(
            "γ = {gamma}: {} scores",
            point.scores.len()
        )));
    };
    Ok(GammaScore {
        gamma,
        mse,
        t_tr_s,
        offset_deg,
        noise_deg,
    })
}

/// The scores of every γ of the paper's grid with the assignments `extra`.
fn grid_scores(extra: &[&str]) -> Result<Vec<GammaScore>, AnalysisError> {
    GRID.iter().map(|g| score_gamma_with(g.0, extra)).collect()
}

/// The grid's scores at each vibration level (g) of [`VIBRATION_FACTORS`].
type ByVibration = [(f64, Vec<GammaScore>)];

/// The γ of the paper's grid whose J(0.5, 0.5) is least, on top of `base`.
pub fn best_of_grid(base: &crate::model::ParamValues) -> Result<f64, AnalysisError> {
    let scores: Vec<GammaScore> = (GRID.iter())
        .map(|g| score_params(base.clone(), g.0))
        .collect::<Result<_, _>>()?;
    let j = j_of(&scores, 0.5, 0.5);
    let best = (0..j.len()).min_by(|a, b| j[*a].total_cmp(&j[*b]));
    Ok(best.map_or(f64::NAN, |k| scores[k].gamma))
}

/// J(α, β) at each γ of the grid.
fn j_of(scores: &[GammaScore], alpha: f64, beta: f64) -> Vec<f64> {
    scores
        .iter()
        .map(|s| alpha * s.mse + beta * s.t_tr_s)
        .collect()
}

/// The reproduction table.
pub fn reproduce() -> Result<Reproduction, AnalysisError> {
    let scores = grid_scores(&[])?;
    let chosen_g = params_with(&QuadrotorRoll, &[])?.get(VIBRATION);
    let mut by_vibration = Vec::new();
    for factor in VIBRATION_FACTORS {
        let v = format!("{VIBRATION}={}", chosen_g * factor);
        let at = if factor == 1.0 {
            scores.clone()
        } else {
            grid_scores(&[&v])?
        };
        by_vibration.push((chosen_g * factor, at));
    }
    let mut rows = table1_rows(&scores, &by_vibration)?;
    rows.extend(closed_loop_rows(&scores, &by_vibration)?);
    rows.extend(fine_grid_rows()?);
    rows.extend(vibration_rows(&by_vibration));
    rows.extend(finding_rows(&scores));
    let (step, period) = (
        format!("setpoint_deg={STEP_DEG}"),
        format!("step_period_s={STEP_AT_S}"),
    );
    let table1: Vec<(f64, f64)> = GRID.iter().map(|g| (g.0, g.2)).collect();
    let base = [step.as_str(), period.as_str(), "kf_q_from=0"];
    rows.extend(super::mse_units::rows(&table1, &base, SEEDS, RUN_S)?);
    Ok(Reproduction {
        lab: super::SPEC.id.into(),
        rows,
        notes: [
            "the paper gives no plant numbers: the test-bench lever (J = 2·10⁻³ kg·m², arm 0.2 m, weight torque 0.05 N·m), the 100-Hz MPU-6050 with its datasheet noise and a 0.5 °/s residual offset, the P–PI gains (ω_c = 5 rad/s), R from the datasheet and Q = q·diag(dt³/3, dt) with det Q = γ det R are this project's",
            "MSE in deg² + (deg/s)², medians over 5 seeds of 8-s runs with a 20° step at 4 s; the paper's MSE of 4–5·10⁴ is in unstated units (its Fig. 2 axis spans 100–250), so only the ordering can compare; six readings of its units and sums are rows at the end, and none reaches it",
            "the paper's J adds MSE ~10⁴ to t_tr ~1 s with weights of similar size, so its J ranks by MSE alone",
            "the rig's propeller vibration at the IMU (0.2 g RMS here, ours) decides where the best γ lies: the datasheet noise alone favours the largest γ of the grid (see the rows 'beyond the paper')",
            "the controller acts on the γ-tuned KF's θ̂ as in Fig. 1 (the variant on the truth follows Table 1); t_tr is the rig's true angle settling within 5 % of the 20° step (±50 ms average): 1.6 s at γ*, 3–3.5 s at the other γ, whose noisy or lagging θ̂ the rig follows; with the loop on the truth it is the controller's alone (0.5 s)",
        ]
        .map(String::from)
        .to_vec(),
    })
}

/// Table 1: MSE and transient time at each γ of the paper's grid, J for each (α, β) pair,
/// and J's argmin against the paper's γ* — a match that depends on the vibration chosen
/// here, so the argmin at ±50 % of it sits beside each.
fn table1_rows(
    scores: &[GammaScore],
    by_vibration: &ByVibration,
) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    for ((_, name, paper_mse, paper_ttr), s) in GRID.iter().zip(scores) {
        rows.push(Row::measurement(
            format!("γ = {name}: MSE over θ and ω"),
            format!("{paper_mse} (units unstated)"),
            s.mse,
            "deg², (deg/s)²",
        ));
        rows.push(Row::measurement(
            format!("γ = {name}: transient time (5 % band)"),
            format!("{paper_ttr} s"),
            s.t_tr_s,
            "s",
        ));
    }
    let chosen_g = params_with(&QuadrotorRoll, &[])?.get(VIBRATION);
    let setting = Calibration::new("propeller vibration", chosen_g, "g");
    for (alpha, beta, paper) in PAIRS {
        let j = j_of(scores, alpha, beta);
        for ((_, name, ..), (jv, pv)) in GRID.iter().zip(j.iter().zip(paper)) {
            rows.push(Row::measurement(
                format!("J(α = {alpha}, β = {beta}) at γ = {name}"),
                fmt_sig(pv),
                *jv,
                "",
            ));
        }
        let argmin_at = |factor: f64| {
            let level = chosen_g * factor;
            by_vibration
                .iter()
                .find(|(v, _)| (v - level).abs() < 1e-12)
                .map(|(_, s)| grid_argmin(&j_of(s, alpha, beta)))
                .ok_or_else(|| AnalysisError::Scenario(format!("{level} g was not run")))
        };
        rows.extend(setting.rows(argmin_row(alpha, beta, grid_argmin(&j)), argmin_at)?);
    }
    Ok(rows)
}

/// The loop closed on θ̂ (the paper's Fig. 1, the default): t_tr of the rig's angle against
/// the paper's 1.0–1.6 s, and the MSE ranking's worst γ (the paper's: 0.02) here and at
/// each vibration level; then Table 1 with the loop on the truth, the earlier variant.
fn closed_loop_rows(
    scores: &[GammaScore],
    by_vibration: &ByVibration,
) -> Result<Vec<Row>, AnalysisError> {
    let star = &scores[2];
    let mut rows = vec![Row::check(
        "loop on θ̂: transient time of the rig's angle at γ* = 2·10⁻³",
        "1.0 s (Table 1; 1.0–1.6 s over the grid)",
        star.t_tr_s,
        "s",
        Expectation::WithinFactor {
            lo: 1.0,
            hi: 1.6,
            factor: 1.25,
        },
    )];
    let worst = |s: &[GammaScore]| {
        s.iter()
            .max_by(|a, b| a.mse.total_cmp(&b.mse))
            .map_or(f64::NAN, |s| s.gamma)
    };
    rows.push(
        Row::check(
            "loop on θ̂: the grid's γ with the largest MSE",
            "0.02 (Table 1: 54 366)",
            worst(scores),
            "",
            Expectation::Near {
                value: 0.02,
                tol: 1e-12,
            },
        )
        .known_to_differ(WORST_DIFFERS),
    );
    for (vibration, at) in by_vibration {
        rows.push(Row::measurement(
            format!(
                "loop on θ̂: the grid's γ with the largest MSE at {} g of vibration",
                fmt_sig(*vibration)
            ),
            "0.02",
            worst(at),
            "",
        ));
    }
    let on_truth: Vec<GammaScore> = GRID
        .iter()
        .map(|g| score_gamma_with(g.0, &[ON_TRUTH]))
        .collect::<Result<_, _>>()?;
    for ((_, name, paper_mse, paper_ttr), s) in GRID.iter().zip(&on_truth) {
        rows.push(Row::measurement(
            format!("variant, loop on the truth: γ = {name}: MSE over θ and ω"),
            format!("{paper_mse} (units unstated)"),
            s.mse,
            "deg², (deg/s)²",
        ));
        rows.push(Row::measurement(
            format!("variant, loop on the truth: γ = {name}: transient time of the rig's angle"),
            format!("{paper_ttr} s"),
            s.t_tr_s,
            "s",
        ));
    }
    Ok(rows)
}

/// The loop-on-the-truth variant's assignment.
const ON_TRUTH: &str = "loop_on=1";

/// Why the MSE's worst γ is not the paper's 0.02 (see the rows per vibration level).
const WORST_DIFFERS: &str = "at every vibration level here the worst γ is an end of the grid (10⁻⁵ below 0.2 g, 0.2 from 0.2 g up: the rows below), since the MSE falls and rises again across γ; 0.02 lies between 0.2 and γ*, and the paper's 0.02 is worse than its 0.2 by only 8 %";

/// The γ of the paper's grid at the smallest of `j` (one value per grid point).
fn grid_argmin(j: &[f64]) -> f64 {
    j.iter()
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(b.1))
        .map_or(f64::NAN, |(k, _)| GRID[k].0)
}

/// Beyond the paper: the page's finer γ grid (the same scoring, seeds and runs), and the
/// Q landscape's optimum with the γ = det Q / det R it lies on.
fn fine_grid_rows() -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let lab: &'static dyn Lab = &QuadrotorRoll;
    let base = params_with(lab, &[])?;
    let fine = Sweep::new(lab, tuning::SWEEPS[0], base, 1).run_to_end();
    for (k, (name, _)) in tuning::TABLE1.objectives.iter().enumerate() {
        let best = fine.argmin(k).map_or(f64::NAN, |p| p.value);
        rows.push(Row::measurement(
            format!(
                "beyond the paper: argmin of {name} over the page's {}-value γ grid",
                fine.points.len()
            ),
            "— (the paper tried four values)",
            best,
            "",
        ));
    }
    let base = params_with(lab, &[])?;
    let det_r = (base.get(roll_keys::SIGMA_ANGLE) * base.get(roll_keys::SIGMA_RATE)).powi(2);
    let landscape = Sweep::new(lab, tuning::SWEEPS[1], base, 1).run_to_end();
    let gamma_at_optimum = landscape
        .argmin(0)
        .and_then(|p| p.grid_value.map(|q_rate| p.value * q_rate / det_r))
        .unwrap_or(f64::NAN);
    rows.push(Row::measurement(
        "beyond the paper: γ = q_θ·q_ω/det R at the Q landscape's optimum of J(0.5, 0.5)",
        "— (the paper searched γ only)",
        gamma_at_optimum,
        "",
    ));
    Ok(rows)
}

/// Beyond the paper: where the best γ lies depends on how much the propellers shake the
/// accelerometer, which the paper does not report.
fn vibration_rows(by_vibration: &ByVibration) -> Vec<Row> {
    by_vibration
        .iter()
        .map(|(vibration, scores)| {
            Row::measurement(
                format!(
                    "beyond the paper: argmin of J(0.5, 0.5) with {vibration} g of propeller vibration"
                ),
                "— (the paper gives no vibration)",
                grid_argmin(&j_of(scores, 0.5, 0.5)),
                "",
            )
        })
        .collect()
}

/// The paper's qualitative finding around its γ*: small γ offset and slow, large γ noisy.
fn finding_rows(scores: &[GammaScore]) -> Vec<Row> {
    let (large, star, small) = (&scores[0], &scores[2], &scores[3]);
    vec![
        Row::check(
            "small γ (10⁻⁵) is offset: |mean θ̂ − θ| in the settled seconds",
            "an offset appears below γ*",
            small.offset_deg,
            "deg",
            Expectation::above(star.offset_deg),
        ),
        Row::check(
            "small γ (10⁻⁵) is slow: transient time",
            "the transient gets longer below γ*",
            small.t_tr_s,
            "s",
            Expectation::above(star.t_tr_s),
        ),
        Row::check(
            "large γ (0.2) is noisy: σ of θ̂ − θ at rest",
            "measurement noise degrades the output above γ*",
            large.noise_deg,
            "deg",
            Expectation::above(star.noise_deg),
        ),
    ]
}

/// Which γ of the grid minimises J(α, β), against the paper's 2·10⁻³.
fn argmin_row(alpha: f64, beta: f64, best: f64) -> Row {
    Row::check(
        format!("argmin over the grid of J(α = {alpha}, β = {beta})"),
        "γ* = 2·10⁻³ for every pair",
        best,
        "",
        Expectation::Near {
            value: 2e-3,
            tol: 1e-12,
        },
    )
}
