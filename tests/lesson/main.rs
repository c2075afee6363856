//! Lesson files: parsing, validation and bad files (exit codes, FILE:LINE:COLUMN),
//! the lecture's printed numbers, the extreme lessons, random valid lessons.
//! Where a test goes, and the shared helpers: tests/README.md.

#[path = "../common/mod.rs"]
mod common;

mod damaged_lessons;
mod extremes;
mod finite_outputs;
mod hulls;
mod invalid_lessons;
mod knob_twice;
mod knobs;
mod lecture_numbers;
mod load_warnings;
mod meshes;
mod narrative_units;
mod overflow_fields;
