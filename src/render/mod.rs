//! Renderers: each reads a [`Trace`](crate::trace::Trace) and shows it.

pub mod chart;
pub mod contact;
pub mod detect;
pub mod errata;
pub mod figure;
pub mod fill;
pub mod glossary;
pub mod html;
pub mod knobs;
pub mod previous_frame;
pub mod resolve;
pub mod run;
mod run_film;
pub mod run_stream;
pub mod run_summary;
pub mod soft_step;
pub mod study;
pub mod svg;
pub mod tex;
pub mod toi;
pub mod toi_svg;
pub mod wrap;
