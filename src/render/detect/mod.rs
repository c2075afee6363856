//! `contact-lab detect`: a scene's detection as text, Markdown, LaTeX, JSON
//! (docs/detect.md) and an SVG figure of one pair's Minkowski difference;
//! [`steps`] gives a pair's iterations one at a time (the TUI's screen),
//! [`minkowski`] the picture of A − B at one of them (the SVG's and the TUI's).

mod blocks;
mod json;
mod layout;
pub(crate) mod legend;
pub mod mesh_rows;
pub mod minkowski;
pub mod steps;
pub(crate) mod svg;
mod vector;

pub use json::json;
pub use layout::{latex, markdown, text};
pub use svg::{svg, svg_at};
