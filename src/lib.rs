//! contact-lab: a step-by-step calculator for rigid-body contact resolution
//! (Millington's impulse-based resolver).
//!
//! Physics computes ([`physics`]), the trace describes ([`trace`]), renderers
//! show ([`render`], [`tui`]). [`knobs`] declares every tunable once;
//! [`lesson`] reads scenes; [`commands`] wires
//! the CLI; [`errata`] compares the lectures' printed numbers with the
//! computed ones; [`exercise`] draws exercises. One contact lives in
//! `physics::contact` and is described stage by stage in `trace::contact`;
//! sets of contacts and time steps go beside them. The JSON contract and the
//! exit codes are in `docs/`.

pub mod cli;
pub mod commands;
pub mod errata;
pub mod error;
pub mod exercise;
pub mod format;
pub mod knobs;
pub mod lesson;
pub mod output_file;
pub mod physics;
pub mod printable;
pub mod render;
pub mod session;
pub mod study;
pub mod trace;
pub mod tui;

/// Solves contact `k` of `lesson` in f64 and describes it.
pub fn worked_solution(lesson: &lesson::Lesson, k: usize) -> trace::Trace {
    let problem = lesson.problem::<f64>(k);
    let solution = physics::solve(&problem);
    let mut trace = trace::build_of(lesson, k, &problem, &solution);
    trace::note_planar_acceleration(&mut trace, &solution);
    trace
}
