//! The binary through assert_cmd: subcommands, flags, exit codes, JSON/CSV
//! contracts, files written.
//! Where a test goes, and the shared helpers: tests/README.md.

#[path = "../common/mod.rs"]
mod common;

mod advise;
mod advise_agrees;
mod advise_per_step;
mod ccd_simulate;
mod check_resolved;
mod check_rows;
mod detect_cli;
mod detect_iteration;
mod detect_toi;
mod exercise_asks;
mod exercise_figures;
mod grading;
mod html_cli;
mod instructor;
mod interrupt_at_once;
mod io_cli;
mod io_exercise;
mod io_simulate;
mod output_files;
mod readme;
mod resolve_cli;
mod resolve_lcp;
mod round_off;
mod simulate_interrupt;
mod slide_ready;
mod study;
mod study_broad;
mod substepped;
mod tunnelled;
mod xpbd_erratum;
