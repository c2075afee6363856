//! docs/architecture.md ("How it is built") names the folders as they are:
//! every `src/…` path it names exists, and every folder of `src/` and of
//! `src/physics/` is named there.

use std::path::Path;

fn block() -> String {
    let root = env!("CARGO_MANIFEST_DIR");
    std::fs::read_to_string(Path::new(root).join("docs/architecture.md"))
        .expect("docs/architecture.md")
}

#[test]
fn every_path_the_page_names_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = block();
    let paths: Vec<&str> = text
        .split(|c: char| c.is_whitespace() || matches!(c, '(' | ')' | ',' | ';' | ':'))
        .filter(|w| w.starts_with("src/"))
        .collect();
    assert!(paths.len() > 20, "{paths:?}");
    for p in paths {
        assert!(
            root.join(p).exists(),
            "docs/architecture.md names {p}, which does not exist"
        );
    }
}

#[test]
fn every_folder_of_src_is_named() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = block();
    for dir in ["src", "src/physics"] {
        for entry in std::fs::read_dir(root.join(dir)).unwrap() {
            let entry = entry.unwrap();
            if entry.file_type().unwrap().is_dir() {
                let name = format!("{dir}/{}/", entry.file_name().to_string_lossy());
                let short = format!(" {}/", entry.file_name().to_string_lossy());
                assert!(
                    text.contains(&name) || (dir == "src/physics" && text.contains(&short)),
                    "docs/architecture.md does not name {name}"
                );
            }
        }
    }
}

/// The page's table of twins and the twins' first lines agree: every file
/// of src/ whose first line says "Twin of" is in the table, and every file
/// the table names as a fast twin exists and says so in its first line.
#[test]
fn the_table_of_twins_names_every_twin() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = block();
    let table = text
        .split("## Twins")
        .nth(1)
        .expect("docs/architecture.md has a '## Twins' section");
    let named: Vec<&str> = table
        .lines()
        .filter_map(|l| l.strip_prefix("| `src/"))
        .map(|l| &l[..l.find('`').unwrap()])
        .collect();
    assert!(named.len() >= 5, "{named:?}");
    for file in &named {
        let first = std::fs::read_to_string(root.join("src").join(file)).unwrap();
        assert!(
            first.starts_with("//! Twin of "),
            "src/{file} is in the table of twins; its first line should say what it is a twin of"
        );
    }
    let mut stack = vec![root.join("src")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(dir).unwrap() {
            let p = entry.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if std::fs::read_to_string(&p)
                .unwrap()
                .starts_with("//! Twin of ")
            {
                let rel = p.strip_prefix(root.join("src")).unwrap();
                let rel = rel.to_string_lossy();
                assert!(
                    named.contains(&rel.as_ref()),
                    "src/{rel} says it is a twin; docs/architecture.md's table of twins does not name it"
                );
            }
        }
    }
}
