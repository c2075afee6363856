//! Trace and render: what a solution says (values, notes, checks' labels and
//! causes, glossary, docs/json.md) and how each output shows it (text, JSON,
//! Markdown, LaTeX, SVG figures), with the insta snapshots of snapshots/.
//! Where a test goes, and the shared helpers: tests/README.md.

#[path = "../common/mod.rs"]
mod common;

mod architecture_layout;
mod check_causes;
mod detect_broad;
mod detect_mesh;
mod detect_rows;
mod detect_snapshots;
mod docs;
mod every_number_substituted;
mod exact_stage;
mod figure_corrected;
mod figure_labels;
mod figure_stages;
mod figure_strokes;
mod film_strip;
mod glossary;
mod html_pages;
mod html_scenes;
mod huge_step;
mod instructor_snapshots;
mod latex_compiles;
mod movement_bounds;
mod one_minus_sign;
mod previous_frame;
mod resolve_snapshots;
mod scene_snapshots;
mod solve_snapshots;
mod solver_glossary;
mod trace_step;
mod verdict_labels;
mod verdict_matrix;
