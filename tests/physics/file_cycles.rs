//! Files of src/ (issue 41): no two files import each other, and none is
//! over 550 lines. A file imports another when one of its `use` paths or
//! `crate::`/`super::`/`self::` paths names an item that file defines, or the
//! module it is; an item re-exported by a `use` is followed to where it is
//! defined. A module's own `mod.rs` and its submodules are one unit: a
//! parent's `mod child;` and a child's `super::` item are how Rust nests
//! files, not a loop. (Unit tests, after `#[cfg(test)]`, are not counted.)

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use crate::common::src_files::{files, SRC};

/// The TUI, whose screens another change restructures (four pairs today,
/// around `tui/app.rs`): its loops are left to it; drop this after.
const LOOPS_EXEMPT: &str = "tui/";

/// `physics/contact/stages/impulse/mod.rs` → `physics/contact/stages/impulse`;
/// `lib.rs` → `` (the crate root).
fn module_of(rel: &str) -> String {
    if rel == "lib.rs" || rel == "main.rs" {
        return String::new();
    }
    let m = rel.trim_end_matches(".rs");
    m.strip_suffix("/mod").unwrap_or(m).to_string()
}

fn parent(module: &str) -> String {
    module
        .rsplit_once('/')
        .map(|(p, _)| p)
        .unwrap_or("")
        .to_string()
}

fn join(module: &str, seg: &str) -> String {
    if module.is_empty() {
        seg.to_string()
    } else {
        format!("{module}/{seg}")
    }
}

/// The code of a file, without its unit tests, comments and strings.
fn code(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    let mut out = String::new();
    for line in text.lines() {
        let mut in_str = false;
        let mut prev = ' ';
        let mut chars = line.chars().peekable();
        while let Some(ch) = chars.next() {
            if !in_str && ch == '/' && chars.peek() == Some(&'/') {
                break;
            }
            if ch == '"' && prev != '\\' && prev != '\'' {
                in_str = !in_str;
            } else if !in_str {
                out.push(ch);
            }
            prev = ch;
        }
        out.push('\n');
    }
    out
}

/// The paths of a use tree (`a::{b, c::{d as e}, self}` → `a::b`, `a::c::d`,
/// `a`), each with the name it binds.
fn expand(tree: &str, prefix: &[String], out: &mut Vec<Bound>) {
    let tree = tree.trim();
    if let Some(open) = tree.find('{') {
        let mut base = prefix.to_vec();
        base.extend(segments(&tree[..open]));
        let inner = &tree[open + 1..tree.rfind('}').unwrap()];
        let mut depth = 0;
        let mut start = 0;
        for (i, ch) in inner.char_indices() {
            match ch {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    expand(&inner[start..i], &base, out);
                    start = i + 1;
                }
                _ => {}
            }
        }
        expand(&inner[start..], &base, out);
        return;
    }
    if tree.is_empty() {
        return;
    }
    let (path, alias) = match tree.split_once(" as ") {
        Some((p, a)) => (p, Some(a.trim().to_string())),
        None => (tree, None),
    };
    let mut full = prefix.to_vec();
    full.extend(segments(path));
    if full.last().is_some_and(|s| s == "self") {
        full.pop();
    }
    let name = alias.unwrap_or_else(|| full.last().cloned().unwrap_or_default());
    out.push((full, name));
}

fn segments(path: &str) -> Vec<String> {
    path.split("::")
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .collect()
}

/// A path's segments and the name a `use` of it binds.
type Bound = (Vec<String>, String);

/// Every `use` of a file (its trees expanded) and every other path that
/// starts at `crate`, `super` or `self`.
fn paths(code: &str) -> (Vec<Bound>, Vec<Vec<String>>) {
    let mut uses = Vec::new();
    let mut rest = code;
    let mut outside = String::new();
    while let Some(i) = find_word(rest, "use") {
        outside.push_str(&rest[..i]);
        let tail = &rest[i + 3..];
        let end = tail.find(';').unwrap_or(tail.len());
        expand(&tail[..end].replace(['\n', '\r'], " "), &[], &mut uses);
        rest = &tail[(end + 1).min(tail.len())..];
    }
    outside.push_str(rest);
    let mut inline = Vec::new();
    let bytes = outside.as_bytes();
    for root in ["crate::", "super::", "self::"] {
        let mut from = 0;
        while let Some(j) = outside[from..].find(root) {
            let at = from + j;
            from = at + root.len();
            if at > 0 && (bytes[at - 1].is_ascii_alphanumeric() || bytes[at - 1] == b'_') {
                continue;
            }
            let tail = &outside[at..];
            let end = tail
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(tail.len());
            inline.push(segments(&tail[..end]));
        }
    }
    (uses, inline)
}

/// Where `word` stands as a word (not part of a longer name).
fn find_word(text: &str, word: &str) -> Option<usize> {
    let b = text.as_bytes();
    let mut from = 0;
    while let Some(j) = text[from..].find(word) {
        let at = from + j;
        let before = at == 0 || !(b[at - 1].is_ascii_alphanumeric() || b[at - 1] == b'_');
        let after = b
            .get(at + word.len())
            .is_some_and(|c| c.is_ascii_whitespace());
        if before && after {
            return Some(at);
        }
        from = at + word.len();
    }
    None
}

struct Crate {
    /// module → its file (relative to src/).
    files: BTreeMap<String, String>,
    /// module → (name a `use` binds there → the path it names, from that module).
    uses: BTreeMap<String, Vec<Bound>>,
    /// module → the paths outside its `use`s.
    inline: BTreeMap<String, Vec<Vec<String>>>,
}

fn read_crate() -> Crate {
    let mut all = Vec::new();
    files(Path::new(SRC), &mut all);
    let mut c = Crate {
        files: BTreeMap::new(),
        uses: BTreeMap::new(),
        inline: BTreeMap::new(),
    };
    for path in &all {
        let rel = path
            .strip_prefix(SRC)
            .unwrap()
            .to_string_lossy()
            .to_string();
        if rel == "main.rs" {
            continue;
        }
        let module = module_of(&rel);
        let (uses, inline) = paths(&code(path));
        c.files.insert(module.clone(), rel);
        c.uses.insert(module.clone(), uses);
        c.inline.insert(module, inline);
    }
    c
}

impl Crate {
    /// The file that defines what `path` names, seen from `module`; None
    /// outside the crate.
    fn resolve(&self, module: &str, path: &[String], depth: usize) -> Option<String> {
        if depth > 16 || path.is_empty() {
            return None;
        }
        let mut at = match path[0].as_str() {
            "crate" => String::new(),
            "super" => parent(module),
            "self" => module.to_string(),
            first if self.files.contains_key(&join(module, first)) => join(module, first),
            // A name a `use` binds here (`use super::rows; rows::build`).
            first => {
                let (target, _) = self.uses.get(module)?.iter().find(|(_, n)| n == first)?;
                if target.first().is_some_and(|s| s == first) && target.len() == 1 {
                    return None;
                }
                let mut full = target.clone();
                full.extend_from_slice(&path[1..]);
                return self.resolve(module, &full, depth + 1);
            }
        };
        for (i, seg) in path.iter().enumerate().skip(1) {
            match seg.as_str() {
                "super" => at = parent(&at),
                "self" => {}
                "*" => break,
                _ if self.files.contains_key(&join(&at, seg)) => at = join(&at, seg),
                // An item of `at`: defined there, or re-exported by a `use`.
                _ => {
                    if let Some((target, _)) = self
                        .uses
                        .get(&at)
                        .and_then(|u| u.iter().find(|(_, n)| n == seg))
                    {
                        let mut full = target.clone();
                        full.extend_from_slice(&path[i + 1..]);
                        return self.resolve(&at, &full, depth + 1);
                    }
                    break;
                }
            }
        }
        self.files.get(&at).cloned()
    }

    /// file → the files it imports.
    fn edges(&self) -> BTreeMap<String, BTreeSet<String>> {
        let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (module, file) in &self.files {
            let uses = self.uses[module].iter().map(|(p, _)| p);
            for path in uses.chain(self.inline[module].iter()) {
                if let Some(to) = self.resolve(module, path, 0) {
                    if &to != file {
                        edges.entry(file.clone()).or_default().insert(to);
                    }
                }
            }
        }
        edges
    }
}

/// `a` is the folder's `mod.rs` (or the file module) that declares `b`, or
/// above it.
fn nests(a: &str, b: &str) -> bool {
    let ma = module_of(a);
    let mb = module_of(b);
    ma.is_empty() || mb.starts_with(&format!("{ma}/"))
}

fn two_file_cycles() -> Vec<(String, String)> {
    let edges = read_crate().edges();
    let mut out = Vec::new();
    for (a, targets) in &edges {
        for b in targets {
            if a < b
                && edges.get(b).is_some_and(|t| t.contains(a))
                && !nests(a, b)
                && !nests(b, a)
                && !a.starts_with(LOOPS_EXEMPT)
                && !b.starts_with(LOOPS_EXEMPT)
            {
                out.push((a.clone(), b.clone()));
            }
        }
    }
    out
}

#[test]
fn no_two_files_import_each_other() {
    let cycles = two_file_cycles();
    assert!(
        cycles.is_empty(),
        "files that import each other (move the shared item to its owner or a leaf):\n{}",
        cycles
            .iter()
            .map(|(a, b)| format!("  {a} ↔ {b}"))
            .collect::<Vec<_>>()
            .join("\n")
    );
}

#[test]
fn the_reader_finds_a_known_import() {
    // The reader itself: a sibling's item through `super::`, one re-exported
    // by the parent, and one through `crate::`.
    let edges = read_crate().edges();
    let of = |f: &str| edges.get(f).cloned().unwrap_or_default();
    assert!(of("physics/resolver/lean_prepare.rs").contains("physics/resolver/prepare.rs"));
    assert!(of("physics/resolver/lean_prepare.rs").contains("physics/resolver/sequential/lean.rs"));
    assert!(of("format.rs").is_empty(), "{:?}", of("format.rs"));
}

#[test]
fn no_file_over_550_lines() {
    let mut all = Vec::new();
    files(Path::new(SRC), &mut all);
    for path in all {
        let rel = path
            .strip_prefix(SRC)
            .unwrap()
            .to_string_lossy()
            .to_string();
        let lines = std::fs::read_to_string(&path).unwrap().lines().count();
        assert!(lines <= 550, "src/{rel} has {lines} lines (at most 550)");
    }
}
