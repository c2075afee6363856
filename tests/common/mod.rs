//! Shared test helpers: snapshots live in the top-level `snapshots/`.
#![allow(dead_code)]

pub mod advise;
pub mod cli;
pub mod dd;
pub mod energy_scenes;
pub mod json;
pub mod pile;
pub mod random;
pub mod resolver_worlds;
pub mod src_files;
pub mod svg;
pub mod tui;

use contact_lab::lesson::{embedded, Lesson};

/// insta settings: snapshots in `snapshots/`, names without the module prefix.
pub fn snapshot_settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path(concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"));
    s.set_prepend_module_to_snapshot(false);
    s
}

/// Every embedded lesson, loaded.
pub fn all_lessons() -> Vec<Lesson> {
    embedded::ids()
        .into_iter()
        .map(|id| Lesson::load(id).expect("embedded lesson is valid"))
        .collect()
}

use contact_lab::trace::{Trace, Value};

/// A stage's scalar value; panics with the name when it is missing.
pub fn scalar(t: &Trace, stage: &str, name: &str) -> f64 {
    match t.value(stage, name) {
        Some(Value::Scalar(x)) => *x,
        other => panic!("{stage}.{name}: {other:?}"),
    }
}

/// A stage's vector value.
pub fn vector(t: &Trace, stage: &str, name: &str) -> [f64; 3] {
    match t.value(stage, name) {
        Some(Value::Vector(v)) => *v,
        other => panic!("{stage}.{name}: {other:?}"),
    }
}

/// A stage's text value.
pub fn text(t: &Trace, stage: &str, name: &str) -> String {
    match t.value(stage, name) {
        Some(Value::Text(s)) => s.clone(),
        other => panic!("{stage}.{name}: {other:?}"),
    }
}

/// A fresh scratch directory for one test (under cargo's tmp dir for tests).
pub fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("contact-lab-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

/// The lesson at `path` (a file under lessons/), with its origin relative to the crate.
pub fn lesson_file(path: &std::path::Path) -> Lesson {
    let text = std::fs::read_to_string(path).unwrap();
    let origin = path
        .strip_prefix(env!("CARGO_MANIFEST_DIR"))
        .unwrap_or(path)
        .display()
        .to_string();
    contact_lab::lesson::validate::parse(&origin, &text).expect("lesson is valid")
}

/// Calls `visit` for every contact of every embedded lesson, worked, in each
/// of the three view planes (the figure tests' loop).
pub fn each_contact_in_each_plane(
    mut visit: impl FnMut(&str, usize, &contact_lab::trace::Trace, contact_lab::trace::Plane),
) {
    use contact_lab::trace::Plane;
    for id in embedded::ids() {
        let l = Lesson::load(id).unwrap();
        for k in 0..l.contacts.len() {
            let t = contact_lab::worked_solution(&l, k);
            for plane in [Plane::Xy, Plane::Yz, Plane::Zx] {
                visit(id, k, &t, plane);
            }
        }
    }
}
