//! Renderers: each reads a [`Trace`](crate::trace::Trace) and shows it.

pub mod chart;
pub mod compare;
pub mod errata;
pub mod figure;
pub mod glossary;
pub mod impact;
pub mod json;
pub mod latex;
pub mod latex_figure;
pub mod markdown;
pub mod resolve;
pub mod run;
pub mod run_stream;
pub mod study;
pub mod svg;
pub mod text;
