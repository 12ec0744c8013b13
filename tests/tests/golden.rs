//! Every lab's golden trace natively: every series at checkpoints of a short run must equal
//! the committed `tests/golden/traces.json`, which the browser suite compares against too
//! (so native and wasm agree on every lab). After an intended change, regenerate it with
//! `ATTLAB_BLESS=1 cargo test -p attlab-tests --test golden` and review the diff.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab_tests::{committed_golden, compare_golden, golden_trace, to_golden};
use std::collections::BTreeMap;

#[test]
fn native_traces_match_the_committed_golden_traces() {
    let fresh: BTreeMap<String, _> = labs::all()
        .iter()
        .map(|lab| {
            let (names, rows) = golden_trace(*lab);
            (lab.id().to_string(), to_golden(names, rows))
        })
        .collect();
    if std::env::var_os("ATTLAB_BLESS").is_some() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/golden/traces.json");
        let text = serde_json::to_string(&fresh).expect("serialise");
        std::fs::write(path, text + "\n").expect("write golden traces");
        eprintln!("wrote {path}");
        return;
    }
    let committed = committed_golden();
    assert_eq!(
        fresh.keys().collect::<Vec<_>>(),
        committed.keys().collect::<Vec<_>>(),
        "every registered lab has a golden trace (bless with ATTLAB_BLESS=1)"
    );
    for (id, trace) in &fresh {
        if let Err(e) = compare_golden(trace, &committed[id], 1e-12) {
            panic!("{id}: golden trace changed: {e} (if intended, bless with ATTLAB_BLESS=1)");
        }
    }
}
