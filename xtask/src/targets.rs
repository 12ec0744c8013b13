//! Which targets a step of `cargo xtask test` builds: the integration test targets it runs in
//! the browser (those with wasm tests), and the targets `cargo doc` documents.

use crate::cmd::Result;
use serde_json::Value;
use std::path::Path;

/// The integration test targets in `dir` (a `name.rs`, or a folder `name/` with `main.rs`,
/// as cargo finds them) whose sources mention `wasm_bindgen_test`, sorted; an error when
/// there is none, so the step cannot pass on no test.
pub fn wasm_test_targets(dir: &Path) -> Result<Vec<String>> {
    let entries =
        std::fs::read_dir(dir).map_err(|e| format!("cannot list {}: {e}", dir.display()))?;
    let mut targets = Vec::new();
    for entry in entries {
        let path = entry?.path();
        let name = if path.is_dir() && path.join("main.rs").is_file() {
            path.file_name()
        } else if path.is_file() && path.extension().is_some_and(|e| e == "rs") {
            path.file_stem()
        } else {
            continue;
        };
        let Some(name) = name.and_then(|n| n.to_str()) else {
            return Err(format!("{} is not a target name", path.display()).into());
        };
        if mentions(&path, "wasm_bindgen_test")? {
            targets.push(name.to_string());
        }
    }
    targets.sort();
    if targets.is_empty() {
        return Err(format!("no test in {} runs in wasm", dir.display()).into());
    }
    Ok(targets)
}

/// `cargo doc`'s target selection: what it documents by default (every library, and every
/// binary not named as its package's library, whose page would overwrite the library's),
/// named explicitly, with `--examples`. Selecting examples makes cargo resolve features with
/// the dev-dependencies, as clippy's `--all-targets` does, so the doc reuses clippy's checks
/// of the dependencies instead of checking 24 of them again with other features (the
/// dev-dependencies add serde's `alloc`, approx's `default`, eframe's `accesskit`, …).
/// `metadata` is `cargo metadata --no-deps --format-version 1`'s output. Named explicitly, a
/// library with `doc = false` would be documented and a binary whose `required-features`
/// are off would fail the step; the workspace has neither.
pub fn doc_target_args(metadata: &str) -> Result<Vec<String>> {
    let metadata: Value =
        serde_json::from_str(metadata).map_err(|e| format!("cargo metadata's output: {e}"))?;
    let packages = metadata["packages"]
        .as_array()
        .ok_or("cargo metadata's output has no packages")?;
    let mut args = vec!["--lib".to_string(), "--examples".to_string()];
    for package in packages {
        let targets = package["targets"].as_array().ok_or_else(|| {
            format!(
                "package {} has no targets in cargo metadata's output",
                package["name"]
            )
        })?;
        let lib = targets
            .iter()
            .find(|t| has_kind(t, &LIB_KINDS))
            .and_then(crate_name);
        for bin in targets.iter().filter(|t| has_kind(t, &["bin"])) {
            let Some(name) = bin["name"].as_str() else {
                return Err(format!("a binary without a name in {}", package["name"]).into());
            };
            if bin["doc"] != false && crate_name(bin) != lib {
                args.extend(["--bin".to_string(), name.to_string()]);
            }
        }
    }
    Ok(args)
}

/// The kinds of target cargo documents as a package's library (its `crate-type`s).
const LIB_KINDS: [&str; 6] = ["lib", "rlib", "dylib", "cdylib", "staticlib", "proc-macro"];

/// Whether the target `t` (of `cargo metadata`) is of one of `kinds`.
fn has_kind(t: &Value, kinds: &[&str]) -> bool {
    t["kind"]
        .as_array()
        .is_some_and(|k| k.iter().any(|k| kinds.iter().any(|kind| k == kind)))
}

/// The target `t`'s crate name, the name its documentation's folder takes.
fn crate_name(t: &Value) -> Option<String> {
    t["name"].as_str().map(|n| n.replace('-', "_"))
}

/// Whether the Rust source `path` (a file, or every `.rs` file in a folder and its
/// subfolders) contains `needle`.
fn mentions(path: &Path, needle: &str) -> Result<bool> {
    if path.is_dir() {
        let entries =
            std::fs::read_dir(path).map_err(|e| format!("cannot list {}: {e}", path.display()))?;
        for entry in entries {
            let inner = entry?.path();
            let source = inner.is_dir() || inner.extension().is_some_and(|e| e == "rs");
            if source && mentions(&inner, needle)? {
                return Ok(true);
            }
        }
        return Ok(false);
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    Ok(text.contains(needle))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cmd;

    #[test]
    fn the_wasm_test_targets_are_those_whose_sources_mention_wasm_bindgen_test() {
        let dir = std::env::temp_dir().join(format!("xtask-wasm-targets-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        for folder in ["page", "common", "deep/inner"] {
            std::fs::create_dir_all(dir.join(folder)).expect("temp dir");
        }
        let write = |name: &str, text: &str| std::fs::write(dir.join(name), text).expect("write");
        write(
            "browser.rs",
            "wasm_bindgen_test_configure!(run_in_browser);",
        );
        write("p1.rs", "#[test] fn native() {}");
        write("page/main.rs", "mod x;");
        write("page/x.rs", "#[wasm_bindgen_test] fn in_a_module() {}");
        // Helpers shared by test files: a folder without main.rs is no target.
        write("common/mod.rs", "wasm_bindgen_test");
        write("deep/main.rs", "mod inner;");
        write("deep/inner/mod.rs", "use wasm_bindgen_test::*;");
        write("notes.txt", "wasm_bindgen_test");
        let found = wasm_test_targets(&dir).expect("targets");
        assert_eq!(found, ["browser", "deep", "page"]);
        for gone in ["browser.rs", "page/x.rs", "deep/inner/mod.rs"] {
            std::fs::remove_file(dir.join(gone)).expect("remove");
        }
        assert!(
            wasm_test_targets(&dir).is_err(),
            "no wasm test must be an error"
        );
        let _ = std::fs::remove_dir_all(&dir);
        // The repository's own: the browser suite.
        let real = wasm_test_targets(&cmd::root().join("tests/tests")).expect("real targets");
        assert_eq!(real, ["browser"]);
    }

    #[test]
    fn the_doc_names_the_binaries_it_documents_by_default() {
        let target = |name: &str, kind: &str| format!(r#"{{"name":"{name}","kind":["{kind}"]}}"#);
        let package = |name: &str, targets: &[String]| {
            format!(r#"{{"name":"{name}","targets":[{}]}}"#, targets.join(","))
        };
        let metadata = format!(
            r#"{{"packages":[{},{},{},{}]}}"#,
            package(
                "app",
                &[target("app-web", "cdylib"), target("app-web", "bin")]
            ),
            package("tool", &[target("tool", "bin"), target("other", "bin")]),
            package("core", &[target("core", "lib"), target("test", "test")]),
            package(
                "quiet",
                &[r#"{"name":"quiet","kind":["bin"],"doc":false}"#.into()]
            ),
        );
        let args = doc_target_args(&metadata).expect("args");
        assert_eq!(
            args,
            ["--lib", "--examples", "--bin", "tool", "--bin", "other"]
        );
        assert!(
            doc_target_args("{}").is_err(),
            "no packages must be an error"
        );
        // The repository's own: the libraries and xtask.
        let real =
            cmd::probe(cmd::cargo().args(["metadata", "--no-deps", "--format-version", "1"]))
                .expect("cargo metadata");
        let args = doc_target_args(&real).expect("real args");
        assert_eq!(args, ["--lib", "--examples", "--bin", "xtask"]);
    }
}
