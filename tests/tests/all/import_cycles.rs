//! No import circle among the files of a folder: when `a.rs` uses `b.rs`, `b.rs` must not use
//! `a.rs` back, directly or round a longer loop. A circle is a file cut in two that still
//! works as one, or a concern that sits in the wrong file; `module_cycles.py` checks the
//! folders, this checks the files inside each. Paths are read from the source text
//! (`super::`, `crate::`, `self::` and `use` trees, through the parent's re-exports);
//! comments, strings and unit-test modules are left out.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module's path from the crate root (`["model", "estimate"]`).
type ModPath = Vec<String>;

/// `text` with comments and the insides of string and char literals blanked.
fn code_only(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < b.len() {
        if text[i..].starts_with("//") {
            let end = text[i..].find('\n').map_or(b.len(), |k| i + k);
            i = end;
        } else if text[i..].starts_with("/*") {
            let end = text[i..].find("*/").map_or(b.len(), |k| i + k + 2);
            i = end;
        } else if text[i..].starts_with("r#\"") {
            let end = text[i + 3..].find("\"#").map_or(b.len(), |k| i + 3 + k + 2);
            out.push_str("\"\"");
            i = end;
        } else if b[i] == b'\'' && b.get(i + 1) == Some(&b'\\') {
            let end = text[i + 2..].find('\'').map_or(b.len(), |k| i + 2 + k + 1);
            out.push_str("' '");
            i = end;
        } else if b[i] == b'\'' && text[i + 1..].chars().nth(1) == Some('\'') {
            let c = text[i + 1..].chars().next().expect("in bounds");
            out.push_str("' '");
            i += 2 + c.len_utf8();
        } else if b[i] == b'"' {
            let mut j = i + 1;
            while j < b.len() && b[j] != b'"' {
                j += if b[j] == b'\\' { 2 } else { 1 };
            }
            out.push_str("\"\"");
            i = j + 1;
        } else {
            let c = text[i..].chars().next().expect("in bounds");
            out.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// The file's code without its unit tests (`#[cfg(test)] mod …` to the end, as they sit).
fn without_tests(code: &str) -> &str {
    let mut at = 0;
    while let Some(k) = code[at..].find("#[cfg(test)]") {
        let start = at + k;
        if code[start + 12..].trim_start().starts_with("mod ") {
            return &code[..start];
        }
        at = start + 12;
    }
    code
}

/// The module path of source file `rel` (from the crate's `src/`), or `None` for a test file.
fn module_of(rel: &str) -> Option<ModPath> {
    let stem = rel.strip_suffix(".rs")?;
    let mut parts: Vec<String> = stem.split('/').map(String::from).collect();
    let last = parts.last()?.clone();
    if last == "tests" || last.ends_with("_tests") || parts.iter().any(|p| p == "tests") {
        return None;
    }
    if ["mod", "lib", "main"].contains(&last.as_str()) {
        parts.pop();
    }
    Some(parts)
}

/// Expands the use tree or path starting at `text` into full paths (`a::{b, c::D}` → `a::b`,
/// `a::c::D`), `self` inside a group naming the group's own path.
fn expand(text: &str) -> Vec<Vec<String>> {
    fn parse(chars: &[char], i: &mut usize, prefix: Vec<String>, out: &mut Vec<Vec<String>>) {
        let mut path = prefix;
        loop {
            while *i < chars.len() && chars[*i].is_whitespace() {
                *i += 1;
            }
            if *i < chars.len() && chars[*i] == '{' {
                *i += 1;
                loop {
                    parse(chars, i, path.clone(), out);
                    while *i < chars.len() && chars[*i].is_whitespace() {
                        *i += 1;
                    }
                    match chars.get(*i) {
                        Some(',') => *i += 1,
                        Some('}') => {
                            *i += 1;
                            return;
                        }
                        _ => return,
                    }
                    while *i < chars.len() && chars[*i].is_whitespace() {
                        *i += 1;
                    }
                    if chars.get(*i) == Some(&'}') {
                        *i += 1;
                        return;
                    }
                }
            }
            let start = *i;
            while *i < chars.len() && (chars[*i].is_alphanumeric() || chars[*i] == '_') {
                *i += 1;
            }
            let word: String = chars[start..*i].iter().collect();
            if word.is_empty() {
                out.push(path);
                return;
            }
            if word != "self" {
                path.push(word);
            }
            if chars.get(*i) == Some(&':') && chars.get(*i + 1) == Some(&':') {
                *i += 2;
            } else {
                out.push(path);
                // `name as alias`: the alias is not a path.
                let ahead: String = chars[*i..].iter().take(4).collect();
                if ahead.trim_start().starts_with("as ") {
                    while chars.get(*i).is_some_and(|c| c.is_whitespace()) {
                        *i += 1;
                    }
                    *i += 2;
                    while chars.get(*i).is_some_and(|c| c.is_whitespace()) {
                        *i += 1;
                    }
                    while chars
                        .get(*i)
                        .is_some_and(|c| c.is_alphanumeric() || *c == '_')
                    {
                        *i += 1;
                    }
                }
                return;
            }
        }
    }
    let chars: Vec<char> = text.chars().take(2000).collect();
    let mut out = Vec::new();
    parse(&chars, &mut 0, Vec::new(), &mut out);
    out
}

/// Every path file `module` names, made absolute (from the crate root).
fn named_paths(module: &[String], code: &str) -> Vec<ModPath> {
    // `super::` from `a/b.rs` (module a::b) is `a`; from `a/b/mod.rs` (a::b) also `a`.
    let parent: ModPath = module[..module.len().saturating_sub(1)].to_vec();
    let mut out = Vec::new();
    for (prefix, base) in [
        ("crate::", Vec::new()),
        ("super::", parent),
        ("self::", module.to_vec()),
    ] {
        let mut at = 0;
        while let Some(k) = code[at..].find(prefix) {
            let start = at + k;
            at = start + prefix.len();
            let before = code[..start].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                continue;
            }
            let mut base = base.clone();
            let mut rest = &code[at..];
            while let Some(r) = rest.strip_prefix("super::") {
                base.pop();
                rest = r;
            }
            for tail in expand(rest) {
                let mut path = base.clone();
                path.extend(tail);
                out.push(path);
            }
        }
    }
    out
}

/// One crate's source: module → (its code, whether it is a folder's `mod.rs`).
struct Crate {
    modules: BTreeMap<ModPath, String>,
}

impl Crate {
    fn read(src: &Path) -> Crate {
        let mut modules = BTreeMap::new();
        let mut stack = vec![src.to_path_buf()];
        while let Some(dir) = stack.pop() {
            for entry in
                std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            {
                let path = entry.expect("a directory entry").path();
                if path.is_dir() {
                    stack.push(path);
                    continue;
                }
                let rel = path
                    .strip_prefix(src)
                    .expect("under src")
                    .to_string_lossy()
                    .replace('\\', "/");
                let Some(module) = module_of(&rel) else {
                    continue;
                };
                let text = std::fs::read_to_string(&path).expect("utf-8 source");
                let code = code_only(&text);
                modules.insert(module, without_tests(&code).to_string());
            }
        }
        Crate { modules }
    }

    /// Which child of `parent` the item `name` of `parent` lives in: a child module of that
    /// name, or one the parent re-exports the name from.
    fn child_of(&self, parent: &[String], name: &str) -> Option<String> {
        if self.is_child(parent, name) {
            return Some(name.to_string());
        }
        let code = self.modules.get(parent)?;
        named_paths(parent, code)
            .into_iter()
            .chain(bare_uses(parent, code))
            .find(|p| {
                p.len() > parent.len() + 1
                    && p.starts_with(parent)
                    && p.last().is_some_and(|l| l == name)
                    && self.is_child(parent, &p[parent.len()])
            })
            .map(|p| p[parent.len()].clone())
    }

    /// Whether `parent` has a child module `name`.
    fn is_child(&self, parent: &[String], name: &str) -> bool {
        let mut child = parent.to_vec();
        child.push(name.to_string());
        self.modules.keys().any(|m| m.starts_with(&child))
    }

    /// Edges between siblings: (folder, from child, to child) with an example path.
    fn sibling_edges(&self) -> BTreeMap<ModPath, BTreeSet<(String, String)>> {
        let mut edges: BTreeMap<ModPath, BTreeSet<(String, String)>> = BTreeMap::new();
        for (module, code) in &self.modules {
            let Some((name, parent)) = module.split_last() else {
                continue;
            };
            for path in named_paths(module, code)
                .into_iter()
                .chain(bare_uses(module, code))
            {
                if path.len() <= parent.len() || !path.starts_with(parent) {
                    continue;
                }
                let Some(to) = self.child_of(parent, &path[parent.len()]) else {
                    continue;
                };
                if &to != name {
                    edges
                        .entry(parent.to_vec())
                        .or_default()
                        .insert((name.clone(), to));
                }
            }
        }
        edges
    }
}

/// `use child::…;` in `module` (a path relative to the module itself, edition 2018+).
fn bare_uses(module: &[String], code: &str) -> Vec<ModPath> {
    let mut out = Vec::new();
    for line in code.lines() {
        let t = line.trim_start();
        let t = t.strip_prefix("pub ").unwrap_or(t);
        let t = t.strip_prefix("pub(crate) ").unwrap_or(t);
        let Some(rest) = t.strip_prefix("use ") else {
            continue;
        };
        if ["crate::", "super::", "self::", "std::", "core::", "alloc::"]
            .iter()
            .any(|p| rest.starts_with(p))
        {
            continue;
        }
        for tail in expand(rest) {
            let mut path = module.to_vec();
            path.extend(tail);
            out.push(path);
        }
    }
    out
}

/// The circles among each folder's children: "folder: a → b → a".
fn circles(edges: &BTreeMap<ModPath, BTreeSet<(String, String)>>) -> Vec<String> {
    let mut out = Vec::new();
    for (folder, pairs) in edges {
        let nodes: BTreeSet<&String> = pairs.iter().flat_map(|(a, b)| [a, b]).collect();
        let mut reported: BTreeSet<BTreeSet<String>> = BTreeSet::new();
        for start in nodes {
            // Breadth-first from `start`'s successors back to `start`: the shortest circle.
            let mut previous: BTreeMap<&String, &String> = BTreeMap::new();
            let mut queue: Vec<&String> = vec![start];
            let mut found = None;
            while let Some(at) = (!queue.is_empty()).then(|| queue.remove(0)) {
                for (_, to) in pairs.iter().filter(|(a, _)| a == at) {
                    if to == start {
                        found = Some(at);
                        break;
                    }
                    if !previous.contains_key(to) {
                        previous.insert(to, at);
                        queue.push(to);
                    }
                }
                if found.is_some() {
                    break;
                }
            }
            let Some(mut at) = found else { continue };
            let mut ring = vec![start.clone()];
            while at != start {
                ring.push(at.clone());
                at = previous[at];
            }
            ring.reverse();
            ring.rotate_right(1);
            let set: BTreeSet<String> = ring.iter().cloned().collect();
            if reported.insert(set) {
                let shown = if folder.is_empty() {
                    "(root)".to_string()
                } else {
                    folder.join("/")
                };
                out.push(format!("{shown}: {} → {}", ring.join(" → "), ring[0]));
            }
        }
    }
    out
}

#[test]
fn a_circle_through_a_reexport_or_a_use_group_is_found() {
    let files = [
        (
            "m/mod.rs",
            "mod a;\nmod b;\nmod c;\npub use b::{Other as O, Thing};",
        ),
        (
            "m/a.rs",
            "use super::Thing; // super::c::X in a comment\nfn f() { \"super::c\"; }",
        ),
        ("m/b.rs", "use crate::m::{c::Y, self as me};"),
        (
            "m/c.rs",
            "pub struct Y; fn g() { super::a::f(); }\n#[cfg(test)]\nmod tests { use super::super::b::Thing; }",
        ),
        ("m/d_tests.rs", "use super::a::f;"),
    ];
    let modules = files
        .iter()
        .filter_map(|(rel, text)| {
            Some((module_of(rel)?, without_tests(&code_only(text)).to_string()))
        })
        .collect();
    let krate = Crate { modules };
    let found = circles(&krate.sibling_edges());
    assert_eq!(found, ["m: a → b → c → a"], "{found:?}");
    let mut broken = krate;
    broken
        .modules
        .insert(vec!["m".into(), "c".into()], "pub struct Y;".into());
    assert!(circles(&broken.sibling_edges()).is_empty());
}

#[test]
fn no_file_uses_a_sibling_that_uses_it_back() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut found = Vec::new();
    let mut modules = 0;
    for src in [
        "crate/src",
        "web/src",
        "tests/src",
        "serve/src",
        "xtask/src",
    ] {
        let krate = Crate::read(&root.join(src));
        modules += krate.modules.len();
        found.extend(
            circles(&krate.sibling_edges())
                .into_iter()
                .map(|c| format!("{src}/{c}")),
        );
    }
    assert!(modules > 200, "found only {modules} modules");
    assert!(
        found.is_empty(),
        "import circles among a folder's files (move what both use into a file of its own):\n{}",
        found.join("\n")
    );
}
