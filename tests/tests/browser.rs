//! Tests that run in headless Chromium (wasm-bindgen-test): the core in the browser gives
//! the golden numbers, is deterministic, reproduces its anchors and parses URL state.
#![cfg(target_arch = "wasm32")]

use attlab::labs;
use attlab::state::UrlState;
use attlab_tests::{GOLDEN_VALUES, golden_run, golden_values, max_relative_diff};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn golden_run_matches_native_values() {
    let values = golden_values(&golden_run());
    // libm in wasm may differ from the native one in the last bits.
    let d = max_relative_diff(&values, GOLDEN_VALUES);
    assert!(
        d < 1e-9,
        "wasm vs native golden values: max rel diff {d:e}: {values:?}"
    );
}

#[wasm_bindgen_test]
fn runs_are_deterministic_in_the_browser() {
    assert_eq!(golden_values(&golden_run()), golden_values(&golden_run()));
}

#[wasm_bindgen_test]
fn every_lab_reproduces_in_the_browser() {
    for lab in labs::all() {
        let rep = lab.reproduce();
        assert!(rep.all_pass(), "{}", rep.to_table());
    }
}

#[wasm_bindgen_test]
fn url_state_with_junk_keeps_the_good_items() {
    let (s, errors) =
        UrlState::parse("#lab=free-rotation&seed=9&gyro_bias_deg_s=0.4&%%%&speed=abc");
    assert_eq!(s.seed, 9);
    assert_eq!(s.params.get("gyro_bias_deg_s"), 0.4);
    assert_eq!(errors.len(), 2);
}
