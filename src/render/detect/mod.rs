//! `contact-lab detect`: a scene's detection as text, Markdown, LaTeX, JSON
//! (docs/detect.md) and an SVG figure of one pair's Minkowski difference.

mod blocks;
mod json;
mod layout;
mod svg;

pub use json::json;
pub use layout::{latex, markdown, text};
pub use svg::svg;
