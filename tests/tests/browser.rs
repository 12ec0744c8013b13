//! Tests that run in headless Chromium (wasm-bindgen-test): every lab's golden trace in the
//! browser equals the native one (≤ 1e-9 relative), runs are deterministic there, the
//! free-rotation reproduction holds, and URL state is parsed with its errors.
#![cfg(target_arch = "wasm32")]

use attlab::labs;
use attlab::state::UrlState;
use attlab_tests::{committed_golden, compare_golden, golden_trace, to_golden};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn every_lab_matches_its_native_golden_trace() {
    let committed = committed_golden();
    for lab in labs::all() {
        let (names, rows) = golden_trace(*lab);
        let fresh = to_golden(names, rows);
        let golden = committed
            .get(lab.id())
            .unwrap_or_else(|| panic!("{} has no golden trace", lab.id()));
        // libm in wasm may differ from the native one in the last bits.
        match compare_golden(&fresh, golden, 1e-9) {
            Ok(worst) => web_sys_log(&format!(
                "{}: wasm vs native, worst relative {worst:e}",
                lab.id()
            )),
            Err(e) => panic!("{}: wasm differs from native: {e}", lab.id()),
        }
    }
}

fn web_sys_log(text: &str) {
    wasm_bindgen_test::console_log!("{text}");
}

#[wasm_bindgen_test]
fn runs_are_deterministic_in_the_browser() {
    for lab in labs::all() {
        assert_eq!(golden_trace(*lab).1.len(), golden_trace(*lab).1.len());
        let (a, b) = (golden_trace(*lab), golden_trace(*lab));
        let bits = |rows: &[Vec<f64>]| -> Vec<u64> {
            rows.iter().flatten().map(|v| v.to_bits()).collect()
        };
        assert_eq!(
            bits(&a.1),
            bits(&b.1),
            "{} is not deterministic in the browser",
            lab.id()
        );
    }
}

#[wasm_bindgen_test]
fn the_free_rotation_reproduction_holds_in_the_browser() {
    let lab = labs::find("free-rotation").expect("registered");
    let rep = lab.reproduce().expect("computes");
    assert!(rep.all_as_declared(), "{}", rep.to_table());
}

#[wasm_bindgen_test]
fn url_state_with_junk_keeps_the_good_items() {
    let (s, errors) =
        UrlState::parse("#lab=free-rotation&seed=9&gyro_bias_deg_s=0.4&%%%&speed=abc");
    assert_eq!(s.seed, 9);
    assert_eq!(s.params.get("gyro_bias_deg_s"), 0.4);
    assert_eq!(errors.len(), 2);
}
