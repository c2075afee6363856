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
