//! The floors of src/: physics < lesson < trace < render < tui / commands.
//! An import only points down: no loop between files of different folders,
//! no `crate::trace` in lesson/ or the number formatter, no `crate::commands`
//! below commands/. (Unit tests, after `#[cfg(test)]`, are not counted.)

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use crate::common::src_files::{files, SRC};

/// `physics/contact/stages/impulse.rs` → module `physics/contact/stages/impulse`.
fn module_of(rel: &str) -> String {
    let m = rel.trim_end_matches(".rs");
    m.strip_suffix("/mod").unwrap_or(m).to_string()
}

/// The folder a module belongs to: itself when it has one, else its parent.
fn folder_of(module: &str) -> String {
    if Path::new(SRC).join(module).is_dir() {
        module.to_string()
    } else {
        Path::new(module)
            .parent()
            .map(|p| p.to_string_lossy().to_string())
            .unwrap_or_default()
    }
}

/// The code of a file, without its unit tests and comments.
fn code(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    text.split("#[cfg(test)]")
        .next()
        .unwrap_or("")
        .lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Every `crate::a::b::c` path in `text`.
fn crate_paths(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("crate::") {
        let tail = &rest[i + 7..];
        let end = tail
            .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
            .unwrap_or(tail.len());
        out.push(tail[..end].trim_end_matches(':').replace("::", "/"));
        rest = &tail[end..];
    }
    out
}

struct Graph {
    /// folder → folders it imports, with one file that does.
    edges: BTreeMap<String, BTreeMap<String, String>>,
    /// file (relative) → its code.
    code: BTreeMap<String, String>,
}

fn graph() -> Graph {
    let mut all = Vec::new();
    files(Path::new(SRC), &mut all);
    let rels: Vec<String> = all
        .iter()
        .map(|p| p.strip_prefix(SRC).unwrap().to_string_lossy().to_string())
        .collect();
    let modules: BTreeSet<String> = rels.iter().map(|r| module_of(r)).collect();
    let mut g = Graph {
        edges: BTreeMap::new(),
        code: BTreeMap::new(),
    };
    for (path, rel) in all.iter().zip(&rels) {
        if rel == "lib.rs" || rel == "main.rs" {
            continue;
        }
        let text = code(path);
        let mine = folder_of(&module_of(rel));
        for target in crate_paths(&text) {
            // The longest prefix of the path that is a module.
            let parts: Vec<&str> = target.split('/').collect();
            let Some(module) = (1..=parts.len())
                .rev()
                .map(|n| parts[..n].join("/"))
                .find(|m| modules.contains(m))
            else {
                continue;
            };
            let theirs = folder_of(&module);
            if theirs != mine {
                g.edges
                    .entry(mine.clone())
                    .or_default()
                    .entry(theirs)
                    .or_insert_with(|| rel.clone());
            }
        }
        g.code.insert(rel.clone(), text);
    }
    g
}

/// A path of folders from `from` back to `to`, if the imports have one.
fn path_back(g: &Graph, from: &str, to: &str) -> Option<Vec<String>> {
    let mut seen = BTreeSet::new();
    let mut stack = vec![vec![from.to_string()]];
    while let Some(path) = stack.pop() {
        let last = path.last().unwrap().clone();
        if last == to && path.len() > 1 {
            return Some(path);
        }
        if !seen.insert(last.clone()) {
            continue;
        }
        for next in g.edges.get(&last).into_iter().flat_map(|m| m.keys()) {
            let mut p = path.clone();
            p.push(next.clone());
            stack.push(p);
        }
    }
    None
}

#[test]
fn no_loop_between_folders() {
    let g = graph();
    for (from, targets) in &g.edges {
        for (to, file) in targets {
            if let Some(back) = path_back(&g, to, from) {
                panic!("a loop: {from} → {to} ({file}), and back: {back:?}");
            }
        }
    }
}

#[test]
fn lower_floors_do_not_import_upper_ones() {
    let g = graph();
    for (file, text) in &g.code {
        let paths = crate_paths(text);
        let imports = |top: &str| {
            paths
                .iter()
                .any(|p| p == top || p.starts_with(&format!("{top}/")))
        };
        if file.starts_with("lesson/") || file == "format.rs" || file.starts_with("physics/") {
            for up in [
                "trace", "render", "tui", "commands", "session", "study", "exercise",
            ] {
                assert!(!imports(up), "{file} imports crate::{up}");
            }
        }
        if file == "format.rs" || file == "printable.rs" {
            assert!(paths.is_empty(), "{file} is a leaf: {paths:?}");
        }
        if file.starts_with("physics/") {
            assert!(!imports("lesson") && !imports("format"), "{file}");
        }
        if file.starts_with("trace/") {
            for up in ["render", "tui", "commands", "session", "study", "exercise"] {
                assert!(!imports(up), "{file} imports crate::{up}");
            }
        }
        if !file.starts_with("commands/") {
            assert!(!imports("commands"), "{file} imports crate::commands");
        }
    }
}
