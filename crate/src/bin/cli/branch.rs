//! `attlab run … --branch-at T --what-if KEY=VALUE`: the run, and a second run from its
//! moment T with the changes (the same random numbers from there on), each written as CSV —
//! the page's "What if…" from the command line.

use super::run::{all_series, params_from, stream_csv};
use attlab::model::ParamValues;
use attlab::page::Lab;
use attlab::sim::{CsvSink, HISTORY_BUDGET_BYTES, Simulation};
use std::path::Path;

/// What a branched run is asked for.
pub(super) struct BranchRun<'a> {
    pub lab: &'a str,
    pub seed: u64,
    pub duration_s: Option<f64>,
    pub csv: &'a Path,
    pub preset: Option<&'a str>,
    pub set: &'a [String],
    pub at_s: f64,
    pub what_if: &'a [String],
}

/// The changes `KEY=VALUE` for `lab`, checked against its ranges.
fn changes(lab: &dyn Lab, what_if: &[String]) -> Result<Vec<(&'static str, f64)>, String> {
    let specs = lab.params();
    let mut check = ParamValues::defaults(specs);
    let mut out = Vec::new();
    for item in what_if {
        let (key, value) = item
            .split_once('=')
            .ok_or_else(|| format!("--what-if {item}: expected KEY=VALUE"))?;
        let spec = (specs.iter().find(|s| s.key == key))
            .ok_or_else(|| format!("--what-if {item}: {} has no parameter {key}", lab.id()))?;
        check
            .set_text(specs, spec.key, value)
            .map_err(|e| format!("--what-if {item}: {e}"))?;
        out.push((spec.key, check.get(spec.key)));
    }
    Ok(out)
}

/// Runs, branches and writes both CSV files (the branch's beside the run's, `.whatif.csv`).
pub(super) fn run(ask: BranchRun<'_>) -> Result<(), String> {
    let BranchRun { seed, csv, .. } = ask;
    let lab = super::find_lab(ask.lab)?;
    let duration_s = ask.duration_s.unwrap_or(lab.default_duration_s());
    if !(ask.at_s.is_finite() && ask.at_s >= 0.0 && ask.at_s < duration_s) {
        return Err(format!(
            "--branch-at must be a time in [0, {duration_s}) s, got {}",
            ask.at_s
        ));
    }
    let changes = changes(lab, ask.what_if)?;
    let params = params_from(lab, ask.preset, ask.set)?;
    let mut sim =
        Simulation::with_options(lab, params, seed, all_series()).map_err(|e| e.to_string())?;
    sim.keep_history(HISTORY_BUDGET_BYTES);
    let rows = stream_csv(&mut sim, duration_s, csv)?;
    let mut branch = sim
        .branch(ask.at_s, &changes, all_series())
        .map_err(|e| format!("--branch-at {}: {e}", ask.at_s))?;
    let path = csv.with_extension("whatif.csv");
    let file = std::fs::File::create(&path)
        .map_err(|e| format!("cannot create {}: {e}", path.display()))?;
    let io = |e: csv::Error| format!("writing {}: {e}", path.display());
    let mut out = CsvSink::new(std::io::BufWriter::new(file), branch.sim().specs()).map_err(io)?;
    out.row(branch.sim().last_row()).map_err(io)?;
    while branch.sim().steps() < sim.steps() {
        branch.advance(&sim, 1);
        out.row(branch.sim().last_row()).map_err(io)?;
    }
    let branch_rows = out.finish().map_err(io)?;
    println!(
        "wrote {rows} rows to {} and the what-if from t = {} s, {branch_rows} rows, to {}",
        csv.display(),
        branch.from_s(),
        path.display()
    );
    for d in branch.differences(&sim).unwrap_or_default() {
        let id = sim.estimators()[d.estimator].id();
        println!(
            "  {id}: attitude error RMS over the {:.1} s after the branch {:.6}° → {:.6}°",
            d.over_s, d.original.rms_deg, d.branch.rms_deg
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With no change the what-if's CSV is the tail of the run's, line for line.
    #[test]
    fn a_what_if_with_no_change_writes_the_tail_of_the_run() {
        let dir = std::env::temp_dir().join(format!("attlab-branch-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let csv = dir.join("p3.csv");
        run(BranchRun {
            lab: "p3",
            seed: 4,
            duration_s: Some(20.0),
            csv: &csv,
            preset: None,
            set: &[],
            at_s: 7.3,
            what_if: &[],
        })
        .unwrap();
        let main = std::fs::read_to_string(&csv).unwrap();
        let branch = std::fs::read_to_string(dir.join("p3.whatif.csv")).unwrap();
        let (main, branch): (Vec<&str>, Vec<&str>) =
            (main.lines().collect(), branch.lines().collect());
        assert_eq!(main[0], branch[0], "the same columns");
        assert!(branch.len() > 2 && branch.len() < main.len());
        assert_eq!(branch[1..], main[main.len() - (branch.len() - 1)..]);
        let bad = run(BranchRun {
            lab: "p3",
            seed: 4,
            duration_s: Some(20.0),
            csv: &csv,
            preset: None,
            set: &[],
            at_s: 25.0,
            what_if: &[],
        });
        assert!(bad.unwrap_err().contains("--branch-at"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
