//! A timed filter step allocates nothing: every item `attlab bench` times (the MEKF step,
//! paper 3's integrators, …) runs 5 000 times after warm-up without one allocation or
//! reallocation, counted by this test binary's allocator (`stats_alloc`).
//!
//! It is the only test in its binary. The allocator's counters are process-wide, and in
//! `memory.rs` the test harness's thread, reporting another test that had just ended,
//! allocated during the measured steps: 16 allocations, blamed on p2's MEKF step, in one CI
//! run. Alone, nothing else in the process runs while it measures.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use stats_alloc::{INSTRUMENTED_SYSTEM, Region, StatsAlloc};
use std::alloc::System;

#[global_allocator]
static GLOBAL: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

#[test]
fn a_timed_filter_step_allocates_nothing() {
    let mut timed = 0;
    for lab in labs::all() {
        for mut item in lab.timing_items() {
            // The first repetitions may start a filter afresh (a clone, on the stack).
            for _ in 0..1000 {
                (item.run)();
            }
            let region = Region::new(GLOBAL);
            for _ in 0..5000 {
                (item.run)();
            }
            let allocations = region.change().allocations + region.change().reallocations;
            assert_eq!(
                allocations,
                0,
                "{}: {} allocated {allocations} times in 5000 steps",
                lab.id(),
                item.name
            );
            timed += 1;
        }
    }
    assert!(
        timed >= 2,
        "the MEKF step and paper 3's integrators are timed ({timed} items)"
    );
}
