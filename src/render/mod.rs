//! Renderers: each reads a [`Trace`](crate::trace::Trace) and shows it.

pub mod compare;
pub mod json;
pub mod text;
