//! `attlab reproduce p1`: the paper's setting (100 Hz, R = σ², σ = 0.04 °/s, 200-s runs for
//! the windows, 600 s for Q = 0), measured the way the paper measured — against the
//! kinematically integrated angle φ_int, which is what its error panels, its output file and
//! its laboratory runs have — beside the error against the truth, which no filter on a rate
//! gyro alone can push below the integrated gyro noise σ√(t/f).
// Only the CLI and the tests reproduce a paper (the `study` feature): without it, what only
// `reproduce` uses is left out (the page's wasm).
#![cfg_attr(not(feature = "study"), allow(dead_code, unused_imports))]

use super::stats::{FilterStats, median_stats, panel, pick, run_stats};
use super::{SuspendedMockup, true_period_s};
use crate::analysis::scenario::params_with;
use crate::analysis::stats;
use crate::analysis::{AnalysisError, StatsContext};
use crate::model::{Calibration, Expectation, Reproduction, Row};

/// The 1σ angle error of direct integration after `t_s` seconds of white rate noise σ per
/// gyro sample at `input_rate_hz`: σ·√(t/f) (each sample adds σ/f; t·f samples add up).
pub fn p1_noise_floor_deg(sigma_deg_s: f64, t_s: f64, input_rate_hz: f64) -> f64 {
    sigma_deg_s * (t_s / input_rate_hz).sqrt()
}

/// The reproduction table.
pub fn reproduce() -> Result<Reproduction, AnalysisError> {
    let runs = Windows::run()?;
    let mut rows = panel_rows(&runs)?;
    rows.extend(window_rows(&runs));
    rows.extend(truth_rows(&runs)?);
    rows.extend(finding_rows(&runs)?);
    robustness(&mut rows)?;
    rows.extend(super::readings::rows()?);
    rows.extend(super::rocking::rows()?);
    Ok(Reproduction {
        lab: super::SPEC.id.into(),
        rows,
        notes: [
            "the paper's setting: filter at 100 Hz, R = σ² (σ = 0.04 °/s), P₀ = 1e-4 (c₀ = 2e-4 so that P₀ is positive definite), 200-s runs for the windows, 600 s for Q = 0; window rows are medians over seeds 1–5",
            "unstated in the paper and chosen here: T ≈ 400 s (steel 0.35 mm, L = 1 m, I = 0.48 kg·m²) and ζ = 0.05 — the paper's rate axis (±3–4 °/s from 360°) suggests T ≈ 578 s, where the N = 1000 panel is ~0.09° (preset \"T ≈ 578 s\")",
            "adaptation: this project's reading of Table 2.3 — every N samples P := (1/N)Σ q qᵀ with q = (φ_int − φ̂⁺, z − φ̇̂⁺), then the Riccati solution with Q = 0; the literal q = K r collapses (E[Q_N,cc] = (c₀ − c_N)/N)",
            "errors against φ_int are what the paper plots; against the truth no rate-only filter beats σ√(t/f)",
            "reading × figure at the period the paper's rate axis implies (T ≈ 578 s): the saw-tooth reading, the default, passes four of five figures — Fig. 6.10's swing too, which runs away at T ≈ 400 s — tied with two others; Fig. 5.5's ±0.3–0.4° fails for every reading (0.09°), because at the longer period the accelerations the rotation model misses are smaller (∝ 1/T²)",
        ]
        .map(String::from)
        .to_vec(),
    })
}

/// The adaptation windows the paper tried (and Q = 0), each the median over the seeds.
struct Windows {
    /// N = 1, 10, 100, 1000, 3000 over 200 s.
    by_n: Vec<(usize, [FilterStats; 2])>,
    /// No adaptation, Q = 0, over 600 s.
    q0: [FilterStats; 2],
}

impl Windows {
    fn run() -> Result<Self, AnalysisError> {
        let mut by_n = Vec::new();
        for n in [1usize, 10, 100, 1000, 3000] {
            let set = format!("kf_window={n}");
            by_n.push((n, median_stats(&[&set], 200.0)?));
        }
        let q0 = median_stats(&["kf_window=0"], 600.0)?;
        Ok(Self { by_n, q0 })
    }

    /// Window `n`'s statistics (NaN rows if it was not run).
    fn at(&self, n: usize) -> [FilterStats; 2] {
        pick(&self.by_n, n).unwrap_or(
            [FilterStats {
                max_vs_int_deg: f64::NAN,
                max_vs_truth_deg: f64::NAN,
                rms_vs_truth_deg: f64::NAN,
                rate_rms_deg_s: f64::NAN,
                rate_inside_band: f64::NAN,
                diverged: f64::NAN,
            }; 2],
        )
    }
}

/// Figs. 5.3, 5.5, 5.7: the panels for N = 100 and N = 1000 (and at the longer period the
/// paper's axis suggests), and Q = 0.
fn panel_rows(r: &Windows) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    rows.push(Row::check(
        "N = 100: angle-error panel vs φ_int (larger KF max |φ̂ − φ_int|, 200 s, median of 5 seeds)",
        "±0.01–0.015° (Fig. 5.7)",
        panel(&r.at(100)),
        "deg",
        Expectation::WithinFactor {
            lo: 0.01,
            hi: 0.015,
            factor: 2.0,
        },
    ));
    let defaults = params_with(&SuspendedMockup, &[])?;
    let inertia = defaults.get("inertia_kg_m2");
    let period = Calibration {
        how: "through the body's inertia (T ∝ √I; string 1 m × 0.35 mm)",
        ..Calibration::new("torsion period T", true_period_s(&defaults).round(), "s")
    };
    let n1000 = Row::check(
        "N = 1000: angle-error panel vs φ_int (larger KF max |φ̂ − φ_int|, 200 s)",
        "±0.3–0.4° (Fig. 5.5)",
        panel(&r.at(1000)),
        "deg",
        Expectation::WithinFactor {
            lo: 0.3,
            hi: 0.4,
            factor: 2.0,
        },
    );
    rows.extend(period.rows(n1000, |factor| {
        let set = format!("inertia_kg_m2={}", inertia * factor * factor);
        Ok::<_, AnalysisError>(panel(&median_stats(&["kf_window=1000", &set], 200.0)?))
    })?);
    let long = median_stats(
        &["kf_window=1000", "string_length_m=2", "inertia_kg_m2=0.5"],
        200.0,
    )?;
    rows.push(
        Row::check(
            "N = 1000 at T ≈ 578 s (string 2 m, body 0.5 kg·m²): angle-error panel vs φ_int",
            "±0.3–0.4° (Fig. 5.5)",
            panel(&long),
            "deg",
            Expectation::WithinFactor { lo: 0.3, hi: 0.4, factor: 2.0 },
        )
        .known_to_differ(
            "the period the paper's rate axis suggests: the rotation model lags less behind the smaller accelerations (∝ 1/T²); the default T ≈ 400 s matches",
        ),
    );
    let zeta = defaults.get("damping_ratio");
    let damping = Calibration::new("damping ratio ζ", zeta, "");
    let q0 = Row::check(
        "Q = 0: torsional KF max |φ̂ − φ_int| (600 s)",
        "angle-error axis of the order of ±100° (Fig. 5.3)",
        r.q0[1].max_vs_int_deg,
        "deg",
        Expectation::within_factor_of(100.0, 2.0),
    );
    rows.extend(damping.rows(q0, |factor| {
        let set = format!("damping_ratio={}", zeta * factor);
        Ok::<_, AnalysisError>(median_stats(&["kf_window=0", &set], 600.0)?[1].max_vs_int_deg)
    })?);
    rows.push(Row::measurement(
        "Q = 0: rotation KF max |φ̂ − φ_int| (600 s)",
        "\"fairly good\" (Fig. 5.3)",
        r.q0[0].max_vs_int_deg,
        "deg",
    ));
    Ok(rows)
}

/// Every window's max |φ̂ − φ_int| for both filters.
fn window_rows(r: &Windows) -> Vec<Row> {
    let mut rows = Vec::new();
    for (n, s) in &r.by_n {
        for (k, name) in ["rotation", "torsional"].iter().enumerate() {
            let diverged = if s[k].diverged > 0.5 {
                " (diverged: stopped at 10 turns)"
            } else {
                ""
            };
            rows.push(Row::measurement(
                format!("N = {n}: {name} KF max |φ̂ − φ_int|{diverged}"),
                if *n == 1 { "\"no smoothing\"" } else { "—" },
                s[k].max_vs_int_deg,
                "deg",
            ));
        }
    }
    rows
}

/// Against the truth, bounded below by the integrated gyro noise σ√(t/f).
fn truth_rows(r: &Windows) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    let p = params_with(&SuspendedMockup, &[])?;
    let floor = |t: f64| p1_noise_floor_deg(p.get("gyro_noise_deg_s"), t, p.get("input_rate_hz"));
    rows.push(Row::measurement(
        "noise floor of any rate-only estimate: σ√(t/f) at t = 200 s (closed form)",
        "—",
        floor(200.0),
        "deg",
    ));
    for n in [100, 1000] {
        for (k, name) in ["rotation", "torsional"].iter().enumerate() {
            rows.push(Row::measurement(
                format!("N = {n}: {name} KF max |φ̂ − φ| against the truth"),
                "— (no truth in the paper's panels)",
                r.at(n)[k].max_vs_truth_deg,
                "deg",
            ));
        }
    }
    rows.push(Row::measurement(
        "noise floor σ√(t/f) at t = 600 s (closed form)",
        "—",
        floor(600.0),
        "deg",
    ));
    rows.push(Row::measurement(
        "Q = 0: rotation KF max |φ̂ − φ| against the truth (600 s)",
        "—",
        r.q0[0].max_vs_truth_deg,
        "deg",
    ));
    Ok(rows)
}

/// The paper's findings: N = 100 beats N = 1000 beats Q = 0 (on both references), large
/// windows are unsatisfactory, N ≈ 100 is near the best, and the torsional KF's rate stays
/// in the noise band.
fn finding_rows(r: &Windows) -> Result<Vec<Row>, AnalysisError> {
    let mut rows = Vec::new();
    for (reference, f) in [
        (
            "φ_int",
            (|s: &FilterStats| s.max_vs_int_deg) as fn(&FilterStats) -> f64,
        ),
        ("truth", |s: &FilterStats| s.max_vs_truth_deg),
    ] {
        let (r100, r1000, r0) = (f(&r.at(100)[0]), f(&r.at(1000)[0]), f(&r.q0[0]));
        rows.push(Row::check(
            format!("finding: rotation KF vs {reference}, N = 100 below N = 1000"),
            "N = 100 better (Figs. 5.5, 5.7)",
            r100,
            "deg",
            Expectation::below(r1000),
        ));
        rows.push(Row::check(
            format!("finding: rotation KF vs {reference}, N = 1000 below Q = 0"),
            "adaptation much better (Figs. 5.3, 5.5)",
            r1000,
            "deg",
            Expectation::below(r0),
        ));
    }
    rows.push(Row::check(
        "finding: N = 3000 worse than N = 1000 (panel vs φ_int)",
        "N > 2000 unsatisfactory",
        panel(&r.at(3000)),
        "deg",
        Expectation::above(panel(&r.at(1000))),
    ));
    let best =
        stats::min(&r.by_n.iter().map(|(_, s)| panel(s)).collect::<Vec<_>>()).of("panel over N")?;
    rows.push(Row::check(
        "finding: N = 100 within 2× of the best window (panel vs φ_int)",
        "N ≈ 100 optimal",
        panel(&r.at(100)) / best,
        "×best",
        Expectation::below(2.0),
    ));
    let [rot, tor] = r.at(1000);
    rows.push(Row::check(
        "finding: N = 1000, torsional KF rate inside the 1σ noise band more often than the rotation KF",
        "torsional fully, rotation partly (Fig. 5.8)",
        tor.rate_inside_band,
        "fraction",
        Expectation::above(rot.rate_inside_band),
    ));
    rows.push(Row::measurement(
        "N = 1000: rotation KF rate inside the 1σ noise band",
        "partly (Fig. 5.8)",
        rot.rate_inside_band,
        "fraction",
    ));
    Ok(rows)
}

/// The paper's robustness cases, judged against φ_int like its laboratory runs.
fn robustness(rows: &mut Vec<Row>) -> Result<(), AnalysisError> {
    let plain = run_stats(&["kf_window=100"], 1, 200.0, 0.0)?;
    let cases: [(&str, &[&str], &str); 2] = [
        (
            "torque impulse 2 °/s at 100 s",
            &["impulse_time_s=100", "impulse_deg_s=2"],
            "estimates stay accurate (Fig. 6.9)",
        ),
        (
            "suspension shaking, torque σ 1e-5 N·m",
            &["shake_torque_n_m=1e-5"],
            "the KFs still track (Fig. 6.8)",
        ),
    ];
    for (name, extra, paper) in cases {
        let mut a: Vec<&str> = extra.to_vec();
        a.push("kf_window=100");
        let [rot, tor] = run_stats(&a, 1, 200.0, 0.0)?;
        rows.push(Row::check(
            format!("robustness, {name}: larger KF max |φ̂ − φ_int|"),
            format!("{paper}; Fig. 6.8's error axis ≈ 1°"),
            rot.max_vs_int_deg.max(tor.max_vs_int_deg),
            "deg",
            Expectation::below(1.0),
        ));
    }
    let swing = ["swing_amp_deg=5", "swing_misalign_deg=3", "kf_window=100"];
    let [rot, tor] = run_stats(&swing, 1, 200.0, 0.0)?;
    rows.push(
        Row::check(
            "robustness, pendulum swing 5°, gyro misaligned 3°: larger KF max |φ̂ − φ_int|",
            "estimates remain good (Fig. 6.10); Fig. 6.8's error axis ≈ 1°",
            rot.max_vs_int_deg.max(tor.max_vs_int_deg),
            "deg",
            Expectation::below(1.0),
        )
        .known_to_differ(
            "with the saw-tooth reading the swing's 2-s rate oscillation feeds the reset P and the torsional KF runs away; the paper gives neither the swing's period nor d — on the 5-DOF body rocking at 9.8 s (d = 10 mm) the same case holds, at 2.2 s (d = 200 mm) it runs away too (the rows at the end)",
        ),
    );
    for (mode, name) in [(1, "saw-tooth, diagonal"), (3, "rate process noise")] {
        let set = format!("kf_adaptation={mode}");
        let [rot, tor] = run_stats(&[swing[0], swing[1], swing[2], &set], 1, 200.0, 0.0)?;
        for (s, filter) in [(rot, "rotation"), (tor, "torsional")] {
            let diverged = if s.diverged > 0.5 { " (diverged)" } else { "" };
            rows.push(Row::measurement(
                format!("robustness, swing, adaptation \"{name}\": {filter} KF max |φ̂ − φ_int|{diverged}"),
                "—",
                s.max_vs_int_deg,
                "deg",
            ));
        }
    }
    let [rot, tor] = run_stats(&["init_error_deg=100", "kf_window=100"], 1, 200.0, 0.0)?;
    rows.push(Row::check(
        "robustness, initial angle error 100°: torsional KF max |φ̂ − φ_int|",
        "\"the torsional KF stayed accurate\" (§7); within 2× of the run without the error",
        tor.max_vs_int_deg,
        "deg",
        Expectation::below(2.0 * plain[1].max_vs_int_deg.max(1e-9)),
    ));
    rows.push(Row::measurement(
        "robustness, initial angle error 100°: rotation KF max |φ̂ − φ_int|",
        "—",
        rot.max_vs_int_deg,
        "deg",
    ));
    rows.push(Row::measurement(
        "robustness, initial angle error 100°: torsional KF max |φ̂ − φ| against the truth",
        "— (the paper does not say the offset is corrected; φ_int carries it too)",
        tor.max_vs_truth_deg,
        "deg",
    ));
    Ok(())
}
