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
