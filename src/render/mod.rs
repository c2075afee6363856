//! Renderers: each reads a [`Trace`](crate::trace::Trace) and shows it.

pub mod check;
pub mod compare;
pub mod json;
pub mod latex;
pub mod markdown;
pub mod resolve;
pub mod svg;
pub mod text;
