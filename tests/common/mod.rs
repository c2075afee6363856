//! Shared test helpers: snapshots live in the top-level `snapshots/` (GUIDE §6).
#![allow(dead_code)]

pub mod dd;

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
