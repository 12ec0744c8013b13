//! The documents hold where their readers look: every relative link in the Markdown resolves
//! (to a file, and to a heading where it names one), the README stays short, every lab's
//! folder has its words and its chapter, and ARCHITECTURE.md names every top-level folder.
#![cfg(not(target_arch = "wasm32"))]

use std::path::{Path, PathBuf};

/// The workspace root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the workspace root")
        .to_path_buf()
}

/// Folders that are built or installed, never written by hand.
const BUILT: &[&str] = &["target", "dist", ".tools", ".git", "node_modules"];

/// Every Markdown file of the repository (built folders aside), from the root.
fn markdown_files() -> Vec<PathBuf> {
    let root = root();
    let mut out = Vec::new();
    let mut stack = vec![root.clone()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
            let path = entry.expect("a directory entry").path();
            let name = path.file_name().unwrap_or_default().to_string_lossy();
            if path.is_dir() && !BUILT.contains(&name.as_ref()) {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    out
}

/// The targets of `[text](target)` links in `markdown`, code spans and blocks aside.
fn link_targets(markdown: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut fenced = false;
    for line in markdown.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        // Code spans are the odd pieces between backticks.
        for (k, piece) in line.split('`').enumerate() {
            if k % 2 == 1 {
                continue;
            }
            let mut rest = piece;
            while let Some(at) = rest.find("](") {
                let after = &rest[at + 2..];
                let Some(end) = after.find(')') else { break };
                out.push(after[..end].trim().to_string());
                rest = &after[end..];
            }
        }
    }
    out
}

/// GitHub's anchor of a heading: lower case, punctuation dropped, spaces as hyphens.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of every heading in `markdown`.
fn anchors(markdown: &str) -> Vec<String> {
    markdown
        .lines()
        .filter(|l| l.starts_with('#'))
        .map(|l| anchor(l.trim_start_matches('#')))
        .collect()
}

/// What is wrong with link `target` written in `file`, if anything.
fn broken(file: &Path, target: &str) -> Option<String> {
    let external = ["http://", "https://", "mailto:"];
    if external.iter().any(|p| target.starts_with(p)) {
        return None;
    }
    let (path_part, fragment) = match target.split_once('#') {
        Some((p, f)) => (p, Some(f)),
        None => (target, None),
    };
    let resolved = if path_part.is_empty() {
        file.to_path_buf()
    } else {
        file.parent().expect("a file's folder").join(path_part)
    };
    if !resolved.exists() {
        return Some(format!("{target}: no such file"));
    }
    let fragment = fragment?;
    if resolved.extension().is_none_or(|e| e != "md") {
        return None;
    }
    let text = std::fs::read_to_string(&resolved).expect("utf-8 Markdown");
    (!anchors(&text).iter().any(|a| a == fragment))
        .then(|| format!("{target}: no heading #{fragment} in {}", resolved.display()))
}

#[test]
fn the_link_reader_finds_links_and_skips_code() {
    let text = "see [a](a.md) and `[b](b.md)`\n```\n[c](c.md)\n```\n![d](d.png#x) [e](https://e)";
    assert_eq!(link_targets(text), ["a.md", "d.png#x", "https://e"]);
    assert_eq!(anchor("The two commands"), "the-two-commands");
    assert_eq!(anchor("What a frame draws (p2)"), "what-a-frame-draws-p2");
}

#[test]
fn a_missing_file_or_heading_is_caught() {
    let readme = root().join("README.md");
    assert!(broken(&readme, "no/such/file.md").is_some());
    assert!(broken(&readme, "ARCHITECTURE.md#no-such-heading").is_some());
    assert_eq!(broken(&readme, "ARCHITECTURE.md#the-tests"), None);
}

#[test]
fn every_relative_link_in_the_markdown_resolves() {
    let files = markdown_files();
    assert!(
        files.len() >= 10,
        "found only {} Markdown files",
        files.len()
    );
    let root = root();
    let problems: Vec<String> = files
        .iter()
        .flat_map(|file| {
            let text = std::fs::read_to_string(file).expect("utf-8 Markdown");
            let shown = file
                .strip_prefix(&root)
                .unwrap_or(file)
                .display()
                .to_string();
            link_targets(&text)
                .into_iter()
                .filter_map(|t| broken(file, &t))
                .map(move |p| format!("{shown}: {p}"))
                .collect::<Vec<_>>()
        })
        .collect();
    assert!(
        problems.is_empty(),
        "broken links:\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_readme_is_read_in_two_minutes() {
    let text = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let lines = text.lines().count();
    assert!(lines <= 250, "README.md has {lines} lines (at most 250)");
}

#[test]
fn every_lab_folder_has_its_words_and_its_chapter() {
    let labs = root().join("crate/src/labs");
    let mut folders = 0;
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(&labs).expect("crate/src/labs") {
        let path = entry.expect("a directory entry").path();
        if !path.is_dir() {
            continue;
        }
        folders += 1;
        for file in ["ru.ftl", "README.md", "mod.rs", "lesson.rs"] {
            if !path.join(file).exists() {
                missing.push(format!("{}/{file}", path.display()));
            }
        }
    }
    assert_eq!(
        folders,
        attlab::labs::all().len(),
        "one folder per registered lab"
    );
    assert!(missing.is_empty(), "missing:\n{}", missing.join("\n"));
}

#[test]
fn the_architecture_names_every_top_level_folder() {
    let root = root();
    let text = std::fs::read_to_string(root.join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let unnamed: Vec<String> = std::fs::read_dir(&root)
        .expect("the root")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.is_dir())
        .map(|p| {
            p.file_name()
                .unwrap_or_default()
                .to_string_lossy()
                .into_owned()
        })
        .filter(|name| name != ".git" && !text.contains(&format!("{name}/")))
        .collect();
    assert!(
        unnamed.is_empty(),
        "ARCHITECTURE.md does not name: {unnamed:?}"
    );
}
