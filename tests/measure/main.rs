//! Measurement reports (run with `--nocapture` for the tables): accuracy
//! against double-double, advise on every scene, the impact integration's error, energy by restitution
//! law, the 10,000-contact one-shot study, the slide angle, Hertz contacts
//! as the arbiter of sequence against simultaneous impact. Built only with
//! `--features measure`; CI runs it as its own step, in release:
//! `cargo test --locked --release --features measure --test measure`.
//! Where a test goes, and the shared helpers: tests/README.md.

#[path = "../common/mod.rs"]
mod common;
#[path = "../exact_support/mod.rs"]
mod exact_support;

mod accuracy;
mod advise_every_scene;
mod broad_phase;
mod energy_named;
mod exact_accuracy;
mod exact_energy;
mod exact_study;
mod hertz_arbiter;
mod slide_angle;
mod study_quick_full;
mod verdicts;
