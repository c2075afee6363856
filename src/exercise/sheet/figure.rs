//! The figure of an exercise in a Markdown sheet: the set-up as the
//! question sees it, embedded as a `data:` URI image on stdout (one line of
//! HTML, no file needed; it renders in VS Code, Typora, Obsidian, pandoc and
//! browsers, where an inline `<svg>` is often stripped or broken by the
//! Markdown parser) or linked to an SVG written beside the sheet.

use std::fmt::Write;

use super::Exercise;

/// How a Markdown sheet shows each exercise's figure.
#[derive(Debug, Clone, PartialEq)]
pub enum MdFigures {
    /// Embedded as `<img src="data:image/svg+xml;base64,…">`: one line of
    /// HTML that needs no file beside the sheet.
    Inline,
    /// Linked: the path of each exercise's SVG (written beside the sheet).
    Files(Vec<String>),
}

/// The figure of exercise `i` as the question sees it: the set-up, no
/// impulse, nothing after (as the LaTeX sheet draws it).
pub fn figure_svg(e: &Exercise) -> String {
    crate::render::svg::render_at(
        &e.trace,
        crate::trace::Plane::Xy,
        Some(crate::physics::StageId::ContactFrame),
    )
}

pub(super) fn md_figure(out: &mut String, e: &Exercise, i: usize, figures: &MdFigures) {
    let alt = format!(
        "Exercise {}: the bodies, the contact point, the normal and the arms",
        i + 1
    );
    match figures {
        MdFigures::Inline => {
            use base64::Engine;
            let data = base64::engine::general_purpose::STANDARD.encode(figure_svg(e));
            let _ = writeln!(
                out,
                "<img alt=\"{alt}\" width=\"640\" src=\"data:image/svg+xml;base64,{data}\">\n"
            );
        }
        MdFigures::Files(paths) => {
            if let Some(path) = paths.get(i) {
                let _ = writeln!(out, "![{alt}]({path})\n");
            }
        }
    }
}
