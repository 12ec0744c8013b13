//! Every lab's golden trace natively: every series at checkpoints of a short run must equal
//! the committed `golden.json` in the lab's folder, which the browser suite compares against
//! too (so native and wasm agree on every lab). After an intended change, or for a new lab,
//! write them with `ATTLAB_BLESS=1 cargo test -p attlab-tests --test all golden` and review the
//! diff.
#![cfg(not(target_arch = "wasm32"))]

use attlab::labs;
use attlab_tests::{GoldenFile, committed_golden, compare_golden, golden_trace, to_golden};
use std::collections::BTreeMap;
use std::path::Path;

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
        bless(&fresh);
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

/// Writes each lab's fresh trace into its folder, beside its chapter.
fn bless(fresh: &BTreeMap<String, attlab_tests::Golden>) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    for lab in labs::all() {
        let study = lab
            .study()
            .expect("every lab has a study, so a folder with a chapter");
        let path = root.join(study.chapter().path().with_file_name("golden.json"));
        let file = GoldenFile {
            lab: lab.id().to_string(),
            trace: fresh[lab.id()].clone(),
        };
        let text = serde_json::to_string(&file).expect("serialise");
        std::fs::write(&path, text + "\n").expect("write a golden trace");
        eprintln!("wrote {}", path.display());
    }
}
