//! The detection page laid out as plain text, Markdown and LaTeX.

use super::blocks::{page, Block};
use crate::format::Fmt;
use crate::render::tex::escape_text;
use crate::trace::detect::DetectTrace;

/// Plain text: underlined headings, tables in aligned columns folded to
/// `width` as tables (0: never; the prose is left to
/// [`crate::render::wrap::wrap`]).
pub fn text(t: &DetectTrace, f: &Fmt, width: usize) -> String {
    let mut out = String::new();
    for b in page(t, f) {
        match b {
            Block::Heading(level, s) => {
                let rule = if level == 1 {
                    '═'
                } else if level == 2 {
                    '─'
                } else {
                    '·'
                };
                // The rule as long as the heading's longest folded line.
                let lines = crate::render::wrap::wrap_line(&s, width);
                let long = lines.iter().map(|l| l.chars().count()).max().unwrap_or(0);
                out += &format!("{}\n{}\n", lines.join("\n"), rule.to_string().repeat(long));
            }
            Block::Para(s) => out += &format!("{s}\n\n"),
            Block::Table { head, rows } => {
                out += &crate::render::wrap::table(0, 1, &head, &rows, width);
                out += "\n";
            }
        }
    }
    out
}

/// Markdown: headings, paragraphs and pipe tables.
pub fn markdown(t: &DetectTrace, f: &Fmt) -> String {
    let mut out = String::new();
    for b in page(t, f) {
        match b {
            Block::Heading(level, s) => {
                out += &format!("{} {s}\n\n", "#".repeat(level as usize));
            }
            Block::Para(s) => out += &format!("{s}\n\n"),
            Block::Table { head, rows } => {
                let cell = |s: &String| s.replace('|', "\\|");
                let row = |r: &[String]| {
                    format!(
                        "| {} |\n",
                        r.iter().map(cell).collect::<Vec<_>>().join(" | ")
                    )
                };
                out += &row(&head);
                out += &format!("|{}\n", "---|".repeat(head.len()));
                for r in &rows {
                    out += &row(r);
                }
                out += "\n";
            }
        }
    }
    out
}

/// A standalone LaTeX document: sections and tabulars (small type).
pub fn latex(t: &DetectTrace, f: &Fmt) -> String {
    let mut out = String::from(
        "\\documentclass{article}\n\\usepackage[utf8]{inputenc}\n\\usepackage{amsmath}\n\\usepackage[margin=1.5cm,landscape]{geometry}\n\\begin{document}\n",
    );
    for b in page(t, f) {
        match b {
            Block::Heading(1, s) => out += &format!("\\section*{{{}}}\n", escape_text(&s)),
            Block::Heading(2, s) => out += &format!("\\subsection*{{{}}}\n", escape_text(&s)),
            Block::Heading(_, s) => out += &format!("\\subsubsection*{{{}}}\n", escape_text(&s)),
            Block::Para(s) => out += &format!("{}\n\n", escape_text(&s)),
            Block::Table { head, rows } => {
                out += &format!(
                    "{{\\small\n\\begin{{tabular}}{{{}}}\n",
                    "l".repeat(head.len())
                );
                let row = |r: &[String]| {
                    r.iter()
                        .map(|c| escape_text(c))
                        .collect::<Vec<_>>()
                        .join(" & ")
                        + " \\\\\n"
                };
                out += &row(&head);
                out += "\\hline\n";
                for r in &rows {
                    out += &row(r);
                }
                out += "\\end{tabular}}\n\n";
            }
        }
    }
    out += "\\end{document}\n";
    out
}
