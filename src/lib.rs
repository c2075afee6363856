//! contact-lab: a step-by-step calculator for rigid-body contact resolution
//! (Millington's impulse-based resolver).
//!
//! Physics computes ([`physics`]), the trace describes ([`trace`]), renderers
//! show ([`render`]). [`lesson`] reads scenes; [`commands`] wires the CLI.

pub mod check;
pub mod cli;
pub mod commands;
pub mod error;
pub mod exercise;
pub mod format;
pub mod lesson;
pub mod output_file;
pub mod physics;
pub mod render;
pub mod trace;
pub mod tui;

/// Solves contact `k` of `lesson` in f64 and describes it.
pub fn worked_solution(lesson: &lesson::Lesson, k: usize) -> trace::Trace {
    let solution = physics::solve(&lesson.problem::<f64>(k));
    trace::build(lesson, k, &solution)
}
