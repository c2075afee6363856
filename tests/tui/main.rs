//! The TUI: scripted keys into a TestBackend (helpers in common/tui.rs), and
//! a real pseudo-terminal restored after panics and signals.
//! Where a test goes, and the shared helpers: tests/README.md.

#[path = "../common/mod.rs"]
mod common;

mod ccd_events;
mod io_tui_edits;
mod io_tui_responsive;
mod movement_bounds;
mod previous_frame;
mod progress_terminal;
mod tui;
mod tui_detect;
mod tui_detect_stages;
mod tui_detect_worker;
mod tui_huge_step;
mod tui_labels;
mod tui_lcp;
mod tui_lesson_picker;
mod tui_reading;
mod tui_router;
mod tui_scenes;
mod tui_substeps;
mod tui_teaching;
mod tui_terminal;
mod tui_write_context;
