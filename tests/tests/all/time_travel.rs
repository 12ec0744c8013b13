//! Time travel (issue 58): a branch with no change is the original run bit for bit, every
//! lab, from three moments; a branch that changes a filter's tuning reads the same sensor
//! noise as the original; a seek shows exactly the row the original recorded there; the
//! filter's cycle at a seeked moment is the filter's own there; the snapshots stay within
//! their budget in a long run.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::model::{ParamValues, SeriesGroup};
use attlab::page::Lab;
use attlab::sim::{HISTORY_BUDGET_BYTES, Selection, SimOptions, Simulation, TravelError};

/// Steps of each original run.
const STEPS: usize = 2500;

/// Every series, each run's rows at full rate.
fn all() -> SimOptions {
    SimOptions {
        selection: Selection::All,
        budget_bytes: 1 << 20,
    }
}

/// A run of `lab` keeping every series and snapshots, and each of its rows, by step.
fn original(lab: &'static dyn Lab, settings: &[&str]) -> (Simulation, Vec<Vec<f64>>) {
    let mut params = ParamValues::defaults(lab.params());
    let errors = params.apply_assignments(lab.params(), settings.iter().copied());
    assert!(errors.is_empty(), "{errors:?}");
    let mut sim = Simulation::with_options(lab, params, 7, all()).unwrap();
    sim.keep_history(HISTORY_BUDGET_BYTES);
    let mut rows = vec![sim.last_row().to_vec()];
    for _ in 0..STEPS {
        sim.step();
        rows.push(sim.last_row().to_vec());
    }
    (sim, rows)
}

/// Whether two rows are the same bits (NaN included).
fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// The series where two rows differ, with both values.
fn differing(sim: &Simulation, a: &[f64], b: &[f64]) -> String {
    if a.len() != b.len() {
        return format!("{} columns against {}", a.len(), b.len());
    }
    let names = sim.specs().iter().map(|s| s.name.as_str());
    (names.zip(a.iter().zip(b)))
        .filter(|(_, (x, y))| x.to_bits() != y.to_bits())
        .map(|(n, (x, y))| format!("{n}: {x} vs {y}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Three moments of a run that are not on a snapshot's step.
fn moments(sim: &Simulation) -> [f64; 3] {
    let t = sim.t_s();
    [0.213 * t, 0.5 * t + 0.37 * sim.dt_s(), 0.871 * t]
}

/// Every row a branch records, by step from its first; the branch is brought level with
/// `original` a few steps at a time, as the page does.
fn branch_rows(original: &Simulation, t_s: f64, changes: &[(&str, f64)]) -> (u64, Vec<Vec<f64>>) {
    let mut branch = original.branch(t_s, changes, all()).unwrap();
    let mut rows = vec![branch.sim().last_row().to_vec()];
    while branch.sim().steps() < original.steps() {
        branch.advance(original, 1);
        rows.push(branch.sim().last_row().to_vec());
    }
    assert!(!branch.advance(original, 1) || branch.sim().steps() == original.steps());
    (branch.from_step(), rows)
}

#[test]
fn a_branch_with_no_change_is_the_original_bit_for_bit_in_every_lab() {
    for lab in labs::all() {
        let (sim, rows) = original(*lab, &[]);
        for t in moments(&sim) {
            let (from, branch) = branch_rows(&sim, t, &[]);
            assert!(
                from > 0 && (from as usize) < STEPS,
                "{}: from {from}",
                lab.id()
            );
            assert_eq!(branch.len(), STEPS + 1 - from as usize, "{}", lab.id());
            for (k, row) in branch.iter().enumerate() {
                let step = from as usize + k;
                assert!(
                    same_bits(row, &rows[step]),
                    "{} branched at {t} s: step {step} differs: {}",
                    lab.id(),
                    differing(&sim, row, &rows[step])
                );
            }
        }
    }
}

#[test]
fn a_branch_follows_the_originals_later_changes_and_keeps_its_own() {
    let lab = labs::find("p4").unwrap();
    let mut params = ParamValues::defaults(lab.params());
    params.set(lab.params(), "gamma", 1.0).unwrap();
    let mut sim = Simulation::with_options(lab, params, 7, all()).unwrap();
    sim.keep_history(HISTORY_BUDGET_BYTES);
    sim.run_for(2.0);
    let branch_t = sim.t_s();
    sim.run_for(1.0);
    // A change after the branch's moment: the branch must take it too.
    sim.set_param("gamma", 3.0).unwrap();
    sim.run_for(1.0);
    let mut same = sim.branch(branch_t, &[], all()).unwrap();
    while !same.advance(&sim, 100) {}
    assert!(same_bits(same.sim().last_row(), sim.last_row()));
    assert_eq!(same.sim().params().get("gamma"), 3.0);
    // Its summary compares the original with itself: the same numbers, over samples.
    let differences = same.differences(&sim).unwrap();
    assert!(differences.iter().any(|d| d.original.counted > 100));
    for d in &differences {
        assert_eq!(d.original.rms_deg.to_bits(), d.branch.rms_deg.to_bits());
        assert!((d.over_s - 2.0).abs() < 0.01, "{}", d.over_s);
    }
    // A branch that sets gamma keeps its value through the original's later change.
    let mut own = sim.branch(branch_t, &[("gamma", 10.0)], all()).unwrap();
    while !own.advance(&sim, 100) {}
    assert_eq!(own.sim().params().get("gamma"), 10.0);
    assert!(!same_bits(own.sim().last_row(), sim.last_row()));
    let differences = own.differences(&sim).unwrap();
    assert!(
        differences
            .iter()
            .any(|d| d.original.rms_deg != d.branch.rms_deg)
    );
    // The original's side is the same as in the no-change branch: it is the original.
    let plain = same.differences(&sim).unwrap();
    for (a, b) in differences.iter().zip(&plain) {
        assert_eq!(a.original, b.original);
    }
}

/// The columns of the truth and the sensors (source 0): the world, not the filters.
fn world_columns(sim: &Simulation) -> Vec<usize> {
    sim.specs()
        .iter()
        .enumerate()
        .filter(|(_, s)| s.group != SeriesGroup::Time && s.source == 0)
        .map(|(i, _)| i)
        .collect()
}

#[test]
fn a_branch_that_retunes_a_filter_reads_the_same_sensor_noise() {
    // Paper 2: the filters' process noise scale changes the estimates, not the readings.
    let lab = labs::find("p2").unwrap();
    let (sim, rows) = original(lab, &[]);
    let readings = world_columns(&sim);
    assert!(!readings.is_empty(), "p2 records its truth and readings");
    let t = moments(&sim)[1];
    let scale = sim.params().get("q_scale");
    let (from, branch) = branch_rows(&sim, t, &[("q_scale", scale * 100.0)]);
    let mut estimates_differ = false;
    for (k, row) in branch.iter().enumerate().skip(1) {
        let step = from as usize + k;
        for &c in &readings {
            assert_eq!(
                row[c].to_bits(),
                rows[step][c].to_bits(),
                "step {step}: reading {} differs",
                sim.specs()[c].name
            );
        }
        estimates_differ |= !same_bits(row, &rows[step]);
    }
    assert!(estimates_differ, "the retuned filters estimate the same");
}

#[test]
fn a_seek_shows_the_row_the_original_recorded_and_the_filters_own_cycle() {
    for lab in labs::all() {
        let (sim, rows) = original(*lab, &[]);
        for t in moments(&sim) {
            let mut seek = sim.seek(t).unwrap();
            while !seek.advance(&sim, 7) {}
            assert!(seek.done());
            let at = seek.sim();
            let step = at.steps() as usize;
            assert!(
                at.t_s() <= t && t - at.t_s() < at.dt_s() * 1.000_001,
                "{}",
                lab.id()
            );
            assert!(
                same_bits(at.last_row(), &rows[step]),
                "{} seek to {t}: the row at step {step} differs",
                lab.id()
            );
            // The filter's cycle there is the one of a fresh run stepped to that step.
            let mut fresh = Simulation::new(*lab, sim.applied_params().clone(), 7);
            for _ in 0..step {
                fresh.step();
            }
            for (a, b) in at.estimators().iter().zip(fresh.estimators()) {
                let cycle = |e: &dyn attlab::model::Estimator| e.teaching().map(|t| *t.cycle());
                assert_eq!(
                    cycle(a.as_ref()),
                    cycle(b.as_ref()),
                    "{} {}",
                    lab.id(),
                    a.id()
                );
            }
            // Compared as text: a NaN (a variance a filter does not have) equals itself there.
            let rows = |s: &Simulation| format!("{:?}", s.accuracy());
            assert_eq!(rows(at), rows(&fresh), "{}", lab.id());
        }
    }
}

#[test]
fn a_seek_before_the_history_or_in_a_run_without_one_is_refused() {
    let lab = labs::find("p3").unwrap();
    let mut sim = Simulation::new(lab, ParamValues::defaults(lab.params()), 1);
    sim.run_for(1.0);
    assert_eq!(sim.seek(0.5).err(), Some(TravelError::NoHistory));
    sim.keep_history(HISTORY_BUDGET_BYTES);
    let first = sim.history_start_s().unwrap();
    assert!(matches!(
        sim.seek(first - 0.5).err(),
        Some(TravelError::Before { .. })
    ));
    let err = sim.branch(first, &[("no_such_key", 1.0)], all()).err();
    assert!(matches!(err, Some(TravelError::Param(_))), "{err:?}");
}

#[test]
fn snapshots_stay_within_their_budget_in_a_long_run() {
    for lab in labs::all() {
        let mut sim = Simulation::new(*lab, ParamValues::defaults(lab.params()), 1);
        let budget = 256 * 1024;
        sim.keep_history(budget);
        let mut most = 0;
        for _ in 0..40_000 {
            sim.step();
            most = most.max(sim.history_use().bytes);
        }
        let used = sim.history_use();
        assert!(most <= budget, "{}: {most} B", lab.id());
        assert!(used.snapshots >= 2, "{}: {used:?}", lab.id());
        // Thinned evenly: at most one interval between snapshots, so a seek anywhere costs
        // at most that many steps.
        assert!(
            (40_000 / used.interval_steps) as usize <= used.snapshots,
            "{}: {used:?}",
            lab.id()
        );
    }
}
