//! House style that the compiler does not check (ARCHITECTURE.md, issue 18), as ratchets:
//! a file or function over its limit fails unless it is one of those still waiting to be
//! split, and those may not grow; hand-typed series names may only become fewer.
#![cfg(not(target_arch = "wasm32"))]

use std::path::{Path, PathBuf};

/// Longest source file (lines).
const FILE_LINES: usize = 500;
/// Longest function (lines, signature to closing brace).
const FN_LINES: usize = 80;

/// Files still over [`FILE_LINES`], each with the length it may not pass.
const LONG_FILES: &[(&str, usize)] = &[];

/// Functions still over [`FN_LINES`] (file, name, the length it may not pass).
const LONG_FNS: &[(&str, &str, usize)] = &[];

/// The workspace root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ is in the workspace")
        .to_path_buf()
}

/// Every `.rs` file under `dirs` (relative to the root), as (relative path, text).
fn sources(dirs: &[&str]) -> Vec<(String, String)> {
    let root = root();
    let mut out = Vec::new();
    let mut stack: Vec<PathBuf> = dirs.iter().map(|d| root.join(d)).collect();
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).expect("utf-8 source");
                let rel = path.strip_prefix(&root).expect("under the root");
                out.push((rel.to_string_lossy().replace('\\', "/"), text));
            }
        }
    }
    assert!(out.len() > 20, "found only {} source files", out.len());
    out
}

const CHECKED: &[&str] = &[
    "crate/src",
    "web/src",
    "web/tests",
    "tests",
    "serve/src",
    "xtask/src",
];

#[test]
fn no_source_file_passes_500_lines_but_those_waiting_to_be_split() {
    let mut over = Vec::new();
    for (path, text) in sources(CHECKED) {
        let lines = text.lines().count();
        let limit = LONG_FILES
            .iter()
            .find(|(p, _)| *p == path)
            .map_or(FILE_LINES, |(_, n)| *n);
        if lines > limit {
            over.push(format!("{path}: {lines} lines (limit {limit})"));
        }
    }
    assert!(over.is_empty(), "split these files:\n{}", over.join("\n"));
    for (path, _) in LONG_FILES {
        let text = std::fs::read_to_string(root().join(path)).unwrap_or_default();
        assert!(
            text.lines().count() > FILE_LINES,
            "{path} is no longer over {FILE_LINES} lines: remove it from LONG_FILES"
        );
    }
}

/// Every function of `text` as (name, lines): from a line `fn name` (rustfmt's layout) to
/// the closing brace at its indentation.
fn functions(text: &str) -> Vec<(String, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        let indent = &line[..line.len() - trimmed.len()];
        let rest = ["pub(crate) ", "pub(super) ", "pub ", "const ", "async "]
            .iter()
            .fold(trimmed, |t, p| t.strip_prefix(p).unwrap_or(t));
        let Some(sig) = rest.strip_prefix("fn ") else {
            continue;
        };
        if line.trim_end().ends_with(';') {
            continue;
        }
        let name: String = sig
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let close = format!("{indent}}}");
        if let Some(end) = lines[i + 1..].iter().position(|l| *l == close) {
            out.push((name, end + 2));
        }
    }
    out
}

#[test]
fn the_function_counter_counts_signature_to_closing_brace() {
    let text = "fn a() {\n    1\n}\n\nimpl X {\n    pub fn b(\n        x: u8,\n    ) -> u8 {\n        x\n    }\n    fn c();\n}\n";
    assert_eq!(functions(text), vec![("a".into(), 3), ("b".into(), 5)]);
}

#[test]
fn no_function_passes_80_lines_but_those_waiting_to_be_split() {
    let mut over = Vec::new();
    for (path, text) in sources(CHECKED) {
        for (name, lines) in functions(&text) {
            let limit = LONG_FNS
                .iter()
                .find(|(p, n, _)| *p == path && *n == name)
                .map_or(FN_LINES, |(_, _, n)| *n);
            if lines > limit {
                over.push(format!("{path}: fn {name}, {lines} lines (limit {limit})"));
            }
        }
    }
    assert!(
        over.is_empty(),
        "split these functions:\n{}",
        over.join("\n")
    );
    // An entry for a function that is now short enough (or gone) must go, so the list only
    // ever shrinks.
    let all: Vec<(String, String, usize)> = sources(CHECKED)
        .into_iter()
        .flat_map(|(path, text)| {
            functions(&text)
                .into_iter()
                .map(move |(name, n)| (path.clone(), name, n))
        })
        .collect();
    for (path, name, _) in LONG_FNS {
        assert!(
            all.iter()
                .any(|(p, n, lines)| p == path && n == name && *lines > FN_LINES),
            "{path}: fn {name} is no longer over {FN_LINES} lines: remove it from LONG_FNS"
        );
    }
}

/// `"word.word"` string literals — series names such as `"kf.angle_deg"` and name builders
/// such as `"{id}.status"` — in `text`, file names and numbers aside.
fn series_literals(text: &str) -> Vec<&str> {
    let word = |s: &str| {
        s.starts_with(|c: char| c.is_ascii_lowercase() || c == '{')
            && s.chars()
                .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || "_-{}".contains(c))
    };
    let files = [
        "csv", "png", "json", "md", "rs", "txt", "html", "js", "wasm", "wgsl", "ftl",
    ];
    text.split('"')
        .skip(1)
        .step_by(2)
        .filter(|lit| match lit.split_once('.') {
            Some((a, b)) => word(a) && word(b) && !b.contains('-') && !files.contains(&b),
            None => false,
        })
        .collect()
}

#[test]
fn the_series_counter_finds_names_and_name_builders() {
    let text = r#"x("kf.angle_deg", "a.csv", "b", "0.2", "p1-x.rate_deg_s", "{id}.{q}", "{v:.2}")"#;
    assert_eq!(
        series_literals(text),
        ["kf.angle_deg", "p1-x.rate_deg_s", "{id}.{q}"]
    );
}

/// Series are named by their key (`SeriesKey`), from which the catalogue derives the name:
/// no lab and nothing in the page writes a series name by hand.
#[test]
fn no_series_name_is_typed_by_hand() {
    let found: Vec<String> = sources(&["crate/src/labs", "web/src"])
        .iter()
        .flat_map(|(path, text)| {
            series_literals(text)
                .into_iter()
                .map(move |lit| format!("{path}: \"{lit}\""))
        })
        .collect();
    assert!(
        found.is_empty(),
        "series names typed by hand (name them by a SeriesKey):\n{}",
        found.join("\n")
    );
}

/// The error types of `Result<…>`s in `text` that are a bare `String` (whitespace ignored):
/// `Result<T, String>` and `Ok::<T, String>`.
fn string_errors(text: &str) -> usize {
    let flat: String = text.chars().filter(|c| !c.is_whitespace()).collect();
    let mut found = 0;
    for opener in ["Result<", "Ok::<", "Err::<"] {
        let mut at = 0;
        while let Some(k) = flat[at..].find(opener) {
            let start = at + k + opener.len();
            at = start;
            let (mut depth, mut last_comma) = (1usize, None);
            for (i, c) in flat[start..].char_indices() {
                match c {
                    '<' | '(' | '[' => depth += 1,
                    '>' | ')' | ']' => {
                        depth -= 1;
                        if depth == 0 {
                            let error = last_comma.map(|j| &flat[start + j + 1..start + i]);
                            found += usize::from(error == Some("String"));
                            break;
                        }
                    }
                    ',' if depth == 1 => last_comma = Some(i),
                    _ => {}
                }
            }
        }
    }
    found
}

#[test]
fn the_string_error_counter_finds_them_across_lines() {
    let text = "fn a() -> Result<Vec<(u8, f64)>,\n    String> {}\nOk::<(), String>(())\nResult<String, E> Result<u8, Box<String>>";
    assert_eq!(string_errors(text), 2);
}

/// Failures are typed per layer and worded by the catalogue: no `Result<_, String>` outside
/// the CLI's top level (`crate/src/bin/`).
#[test]
fn no_error_is_a_bare_string() {
    let found: Vec<String> = sources(&["crate/src", "web/src"])
        .iter()
        .filter(|(path, _)| !path.starts_with("crate/src/bin/"))
        .filter_map(|(path, text)| {
            let n = string_errors(text);
            (n > 0).then(|| format!("{path}: {n}"))
        })
        .collect();
    assert!(
        found.is_empty(),
        "Result<_, String> (type the error and word it in the catalogue):\n{}",
        found.join("\n")
    );
}
