//! The integration test targets `cargo xtask test` runs in the browser: those with wasm tests.

use crate::cmd::Result;
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
}
