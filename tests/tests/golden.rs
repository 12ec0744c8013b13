//! The golden scenario natively: its values must equal the committed golden values, which
//! the browser test compares against too (so native and wasm agree).
#![cfg(not(target_arch = "wasm32"))]

use attlab_tests::{GOLDEN_SERIES, GOLDEN_VALUES, golden_run, golden_values, max_relative_diff};

#[test]
fn native_run_matches_the_golden_values() {
    let values = golden_values(&golden_run());
    let listing: Vec<String> = GOLDEN_SERIES
        .iter()
        .zip(&values)
        .map(|(n, v)| format!("{n} = {v:?}"))
        .collect();
    let d = max_relative_diff(&values, GOLDEN_VALUES);
    assert!(
        d < 1e-12,
        "golden values changed (max rel diff {d:e}):\n{}",
        listing.join("\n")
    );
}
