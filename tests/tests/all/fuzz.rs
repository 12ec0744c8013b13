//! The registry fuzzer (see `attlab::analysis::fuzz`): random parameter sets of every lab
//! inside the declared ranges, random seeds, a live change half-way. 2 × 500 sets here (the
//! two halves run in parallel); `attlab fuzz --sets N` for longer runs.
#![cfg(not(target_arch = "wasm32"))]

use attlab::analysis::fuzz::{self, FuzzConfig};
use attlab::labs;

fn fuzz_half(seed: u64) {
    let config = FuzzConfig {
        sets: 500,
        steps: 2000,
        seed,
    };
    let report = fuzz::run(labs::all(), config, |_, _| {});
    let failures: Vec<String> = report.failures.iter().map(ToString::to_string).collect();
    assert!(
        failures.is_empty(),
        "{} of 500 sets broke a rule:\n{}",
        failures.len(),
        failures.join("\n")
    );
    for (lab, n) in &report.sets_per_lab {
        assert!(*n >= 500 / labs::all().len(), "{lab} got {n} sets");
    }
    assert!(report.max_memory_bytes <= attlab::record::DEFAULT_BUDGET_BYTES);
}

#[test]
fn random_parameter_sets_of_every_lab_keep_the_rules_first_half() {
    fuzz_half(1);
}

#[test]
fn random_parameter_sets_of_every_lab_keep_the_rules_second_half() {
    fuzz_half(2);
}
