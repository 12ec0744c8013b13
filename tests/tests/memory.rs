//! Nothing grows without bound: the heap, counted by this test binary's allocator
//! (`stats_alloc`), is flat after warm-up in long runs of every lab at its defaults and with
//! the fuzzer's random sets, and after paper 5's method (9) diverges (it used to grow its
//! re-integration history by ~3 kB per simulated second from then on); and the fuzzer,
//! given the count, checks each set's whole heap.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab::model::{EstimatorStatus, ParamValues};
use attlab::sim::Simulation;
use stats_alloc::{INSTRUMENTED_SYSTEM, Region, StatsAlloc};
use std::alloc::System;
use std::sync::Mutex;

#[global_allocator]
static GLOBAL: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

/// The counters are process-wide: the tests here take turns.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// Bytes allocated and not freed since `region` began.
fn grown(region: &Region<'_, System>) -> isize {
    attlab::analysis::fuzz::live_bytes(&region.change())
}

/// Bytes a run may still allocate after warm-up (a message, a status text): far below what
/// any per-step growth would add over the steps measured.
const SLACK_BYTES: isize = 16 * 1024;

#[test]
fn every_lab_at_its_defaults_holds_its_heap_flat_after_warm_up() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    for lab in labs::all() {
        let mut sim = Simulation::new(*lab, ParamValues::defaults(lab.params()), 1);
        for _ in 0..20_000 {
            sim.step();
        }
        let (region, t0) = (Region::new(GLOBAL), sim.t_s());
        for _ in 0..20_000 {
            sim.step();
        }
        let grown = grown(&region);
        assert!(
            grown <= SLACK_BYTES,
            "{}: the heap grew by {grown} B from t = {t0:.0} s to {:.0} s",
            lab.id(),
            sim.t_s()
        );
    }
}

#[test]
fn paper_5s_method_9_grows_nothing_after_it_diverges() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let lab = labs::find("p5").expect("p5");
    let mut sim = Simulation::new(lab, ParamValues::defaults(lab.params()), 1);
    let diverged = |sim: &Simulation| {
        sim.statuses()
            .iter()
            .any(|s| matches!(s, EstimatorStatus::Diverged(_)))
    };
    while !diverged(&sim) {
        assert!(
            sim.t_s() < 3600.0,
            "method (9) did not diverge within an hour"
        );
        sim.step();
    }
    let t_diverged = sim.t_s();
    sim.run_for(100.0);
    let region = Region::new(GLOBAL);
    sim.run_for(1000.0);
    let grown = grown(&region);
    assert!(
        grown <= SLACK_BYTES,
        "the heap grew by {grown} B over the 1000 s after t = {:.0} s (diverged at {t_diverged:.0} s)",
        t_diverged + 100.0
    );
}

#[test]
fn the_fuzzers_random_sets_hold_their_heap_flat_after_warm_up() {
    use rand::SeedableRng;
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(25);
    for lab in labs::all() {
        for _ in 0..2 {
            let params = attlab::analysis::fuzz::random_params(*lab, &mut rng);
            let described = format!("{params:?}");
            let mut sim = Simulation::new(*lab, params, 1);
            // Longer than the largest adaptation window (5 000 samples) fills.
            for _ in 0..20_000 {
                sim.step();
            }
            let region = Region::new(GLOBAL);
            for _ in 0..20_000 {
                sim.step();
            }
            let grown = grown(&region);
            assert!(
                grown <= SLACK_BYTES,
                "{}: the heap grew by {grown} B over 20 000 steps after warm-up with {described}",
                lab.id()
            );
        }
    }
}

#[test]
fn the_fuzzer_counts_each_sets_heap_where_the_binary_counts_it() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    fn live() -> usize {
        let s = INSTRUMENTED_SYSTEM.stats();
        (s.bytes_allocated as isize - s.bytes_deallocated as isize + s.bytes_reallocated).max(0)
            as usize
    }
    attlab::analysis::fuzz::count_heap_with(live);
    let config = attlab::analysis::fuzz::FuzzConfig {
        sets: 12,
        steps: 1000,
        seed: 3,
    };
    let report = attlab::analysis::fuzz::run(labs::all(), config, |_, _| {});
    assert!(report.failures.is_empty(), "{:?}", report.failures);
    let heap = report.max_heap_bytes.expect("the heap was counted");
    // Every set builds a recorder of the default budget: the heap grows at least by it.
    assert!(
        heap >= report.max_memory_bytes && heap <= report.max_memory_bytes + (16 << 20),
        "heap {heap} B, recorder {} B",
        report.max_memory_bytes
    );
}

/// What a time-travel snapshot holds, counted by the allocator, against what the history
/// counts it as (its budget is kept on that count): never more, and not far less.
#[test]
fn a_snapshot_holds_no_more_than_the_history_counts() {
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    let p5 = labs::find("p5").expect("p5");
    let mut cases: Vec<(&'static dyn attlab::page::Lab, ParamValues, f64)> = labs::all()
        .iter()
        .map(|lab| (*lab, ParamValues::defaults(lab.params()), 300.0))
        .collect();
    // Paper 5 inside a long reference dropout at a fine step: its re-integration history is
    // the largest state any lab keeps.
    let mut fine = ParamValues::defaults(p5.params());
    fine.set(p5.params(), "step_s", 0.001).expect("step_s");
    fine.set(p5.params(), "dropout_s", 100.0)
        .expect("dropout_s");
    cases.push((p5, fine, 0.0));
    for (lab, params, run_s) in cases {
        let mut sim = Simulation::new(lab, params, 1);
        sim.run_for(run_s);
        if lab.id() == "p5" && run_s == 0.0 {
            sim.run_for(sim.params().get("dropout_from_s") + 50.0);
        }
        let region = Region::new(GLOBAL);
        sim.keep_history(attlab::sim::HISTORY_BUDGET_BYTES);
        let held = grown(&region);
        let counted = sim.history_use().bytes as isize;
        eprintln!(
            "{}: a snapshot holds {held} B, counted {counted} B",
            lab.id()
        );
        assert!(
            held <= counted,
            "{}: {held} B held, {counted} B counted",
            lab.id()
        );
        assert!(
            counted <= 2 * held + 4096,
            "{}: {held} B held, {counted} B counted",
            lab.id()
        );
    }
}
