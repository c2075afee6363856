//! One contact's worked solution shown: as text, JSON, Markdown and LaTeX
//! (with its LaTeX figure), the friction models side by side, and the
//! impulse-space figure of the exact impact.

pub mod compare;
pub mod impact;
pub mod json;
pub mod latex;
pub mod latex_figure;
pub mod markdown;
pub mod text;
