//! `attlab run … --branch-at T --what-if KEY=VALUE`: the run, and a second run from its
//! moment T with the changes (the same random numbers from there on), each written as CSV —
//! the page's "What if…" from the command line.

use super::run::{all_series, params_from, stream_csv};
use attlab::model::{ParamError, ParamValues};
use attlab::page::Lab;
use attlab::sim::{CsvSink, HISTORY_BUDGET_BYTES, Simulation, TravelError};
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

/// Why a what-if run stopped (English: the CLI's own words, as its other commands).
#[derive(Debug, thiserror::Error)]
pub(super) enum WhatIfError {
    /// A `--what-if` item is not `KEY=VALUE`.
    #[error("--what-if {0}: expected KEY=VALUE")]
    NotKeyValue(String),
    /// A `--what-if` key the lab has no parameter for.
    #[error("--what-if {item}: {lab} has no parameter {key}")]
    NoParameter {
        /// The item as given.
        item: String,
        /// The lab's id.
        lab: &'static str,
        /// The key.
        key: String,
    },
    /// A `--what-if` value the parameter refuses.
    #[error("--what-if {item}: {why}")]
    Value {
        /// The item as given.
        item: String,
        /// Why.
        why: ParamError,
    },
    /// `--branch-at` outside the run.
    #[error("--branch-at must be a time in [0, {duration_s}) s, got {at_s}")]
    At {
        /// The moment asked for (s).
        at_s: f64,
        /// The run's length (s).
        duration_s: f64,
    },
    /// The run cannot be branched there.
    #[error("--branch-at {at_s}: {why}")]
    Travel {
        /// The moment asked for (s).
        at_s: f64,
        /// Why.
        why: TravelError,
    },
    /// The run could not be built.
    #[error(transparent)]
    Series(#[from] attlab::sim::UnknownSeries),
    /// The what-if's CSV could not be written.
    #[error("writing {path}: {why}")]
    Write {
        /// The file.
        path: String,
        /// Why.
        why: String,
    },
    /// What the CLI's shared steps (the lab, the parameters, the run's CSV) said.
    #[error("{0}")]
    Run(String),
}

/// The changes `KEY=VALUE` for `lab`, checked against its ranges.
fn changes(lab: &dyn Lab, what_if: &[String]) -> Result<Vec<(&'static str, f64)>, WhatIfError> {
    let specs = lab.params();
    let mut check = ParamValues::defaults(specs);
    let mut out = Vec::new();
    for item in what_if {
        let (key, value) =
            (item.split_once('=')).ok_or_else(|| WhatIfError::NotKeyValue(item.clone()))?;
        let spec =
            (specs.iter().find(|s| s.key == key)).ok_or_else(|| WhatIfError::NoParameter {
                item: item.clone(),
                lab: lab.id(),
                key: key.to_string(),
            })?;
        (check.set_text(specs, spec.key, value)).map_err(|why| WhatIfError::Value {
            item: item.clone(),
            why,
        })?;
        out.push((spec.key, check.get(spec.key)));
    }
    Ok(out)
}

/// Runs, branches and writes both CSV files (the branch's beside the run's, `.whatif.csv`).
pub(super) fn run(ask: BranchRun<'_>) -> Result<(), WhatIfError> {
    let BranchRun { seed, csv, .. } = ask;
    let lab = super::find_lab(ask.lab).map_err(WhatIfError::Run)?;
    let duration_s = ask.duration_s.unwrap_or(lab.default_duration_s());
    if !(ask.at_s.is_finite() && ask.at_s >= 0.0 && ask.at_s < duration_s) {
        return Err(WhatIfError::At {
            at_s: ask.at_s,
            duration_s,
        });
    }
    let changes = changes(lab, ask.what_if)?;
    let params = params_from(lab, ask.preset, ask.set).map_err(WhatIfError::Run)?;
    let mut sim = Simulation::with_options(lab, params, seed, all_series())?;
    sim.keep_history(HISTORY_BUDGET_BYTES);
    let rows = stream_csv(&mut sim, duration_s, csv).map_err(WhatIfError::Run)?;
    let mut branch =
        (sim.branch(ask.at_s, &changes, all_series())).map_err(|why| WhatIfError::Travel {
            at_s: ask.at_s,
            why,
        })?;
    let path = csv.with_extension("whatif.csv");
    let write = |why: String| WhatIfError::Write {
        path: path.display().to_string(),
        why,
    };
    let file = std::fs::File::create(&path).map_err(|e| write(e.to_string()))?;
    let io = |e: csv::Error| write(e.to_string());
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
        let at = |at_s: f64| {
            run(BranchRun {
                lab: "p3",
                seed: 4,
                duration_s: Some(20.0),
                csv: &csv,
                preset: None,
                set: &[],
                at_s,
                what_if: &[],
            })
        };
        at(7.3).unwrap();
        let main = std::fs::read_to_string(&csv).unwrap();
        let branch = std::fs::read_to_string(dir.join("p3.whatif.csv")).unwrap();
        let (main, branch): (Vec<&str>, Vec<&str>) =
            (main.lines().collect(), branch.lines().collect());
        assert_eq!(main[0], branch[0], "the same columns");
        assert!(branch.len() > 2 && branch.len() < main.len());
        assert_eq!(branch[1..], main[main.len() - (branch.len() - 1)..]);
        assert!(matches!(at(25.0), Err(WhatIfError::At { .. })));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
