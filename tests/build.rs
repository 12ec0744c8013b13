//! Finds every lab's golden trace (`crate/src/labs/<lab>/golden.json`) so that the test
//! library embeds them all, natively and in wasm, without a list of labs of its own: a new
//! lab's trace is found when it is blessed into its folder.

use std::fmt::Write as _;
use std::path::Path;

fn main() {
    let labs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../crate/src/labs");
    println!("cargo:rerun-if-changed={}", labs.display());
    let mut files: Vec<_> = std::fs::read_dir(&labs)
        .map(|dir| {
            dir.filter_map(Result::ok)
                .map(|e| e.path().join("golden.json"))
                .filter(|p| p.is_file())
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    let mut code = String::from("/// Every lab's committed golden trace file: (path, text).\n");
    code.push_str("pub const GOLDEN_FILES: &[(&str, &str)] = &[\n");
    for path in &files {
        println!("cargo:rerun-if-changed={}", path.display());
        let shown = path
            .strip_prefix(labs.parent().and_then(Path::parent).unwrap_or(&labs))
            .unwrap_or(path)
            .display()
            .to_string();
        let _ = writeln!(
            code,
            "    ({shown:?}, include_str!({:?})),",
            path.display().to_string()
        );
    }
    code.push_str("];\n");
    let out =
        Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("golden_files.rs");
    std::fs::write(out, code).expect("write the golden file list");
}
