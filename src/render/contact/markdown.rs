//! A worked solution as Markdown: a heading per stage, each stage's formulas
//! as one display-math block (`$$…$$`, symbols, numbers, result), notes as a
//! list, skipped stages named with their reason.

use crate::render::fill::Fill;
use std::fmt::Write;

use super::latex::aligned_rows;
use crate::format::Fmt;
use crate::physics::StageId;
use crate::trace::{glossary, Step, Trace};

/// Escapes what Markdown would read as markup in running text, and no more,
/// so the source stays readable: `\\`, `*` and `$` (which starts math)
/// always (backticks are left alone: lesson texts write `code` spans); `_` at a word boundary; `<` before a tag-like character;
/// `]` before `(`, `[` or `:`; `#` and `>` at the start of a line.
pub fn escape(s: &str) -> String {
    let chars: Vec<char> = s.chars().collect();
    let mut out = String::with_capacity(s.len());
    let mut line_start = true;
    for (i, &c) in chars.iter().enumerate() {
        let prev = i.checked_sub(1).map(|j| chars[j]);
        let next = chars.get(i + 1).copied();
        // Letters, digits and combining accents (q̇) make up words.
        let word = |x: Option<char>| {
            x.is_some_and(|x| x.is_alphanumeric() || ('\u{300}'..='\u{36f}').contains(&x))
        };
        let escape = match c {
            '\\' | '*' | '$' => true,
            '_' => !(word(prev) && word(next)),
            '<' => next.is_some_and(|n| n.is_ascii_alphabetic() || "/!?".contains(n)),
            ']' => next.is_some_and(|n| "([:".contains(n)),
            '#' | '>' => line_start,
            _ => false,
        };
        if escape {
            out.push('\\');
        }
        out.push(c);
        if c == '\n' {
            line_start = true;
        } else if !c.is_whitespace() {
            line_start = false;
        }
    }
    out
}

/// Escapes a table cell: as [`escape`], and `|`.
pub fn cell(s: &str) -> String {
    escape(s).replace('|', "\\|")
}

fn heading(level: usize, text: &str) -> String {
    format!("{} {text}\n\n", "#".repeat(level.clamp(1, 6)))
}

/// The stage's formulas as one `aligned` display block.
pub fn formulas(step: &Step, fmt: &Fmt) -> String {
    let rows: Vec<String> = step
        .formulas
        .iter()
        .map(|f| aligned_rows(f, step, fmt).join(" \\\\\n"))
        .collect();
    if rows.is_empty() {
        return String::new();
    }
    format!(
        "$$\n\\begin{{aligned}}\n{}\n\\end{{aligned}}\n$$\n\n",
        rows.join(" \\\\[4pt]\n")
    )
}

fn note(text: &str, step: &Step, fmt: &Fmt) -> String {
    fmt.fill_named(text, step, &escape, &|name, v| {
        let u = glossary::unit_to_add(text, name, glossary::unit(step, name));
        escape(&glossary::with_unit(&fmt.value(v), u))
    })
}

fn stage(out: &mut String, n: usize, step: &Step, fmt: &Fmt, level: usize) {
    match &step.skipped {
        Some(why) => {
            out.push_str(&heading(level, &format!("{n}. {} — skipped", step.title)));
            let _ = writeln!(out, "*Skipped:* {}\n", escape(why));
        }
        None => {
            out.push_str(&heading(level, &format!("{n}. {}", step.title)));
            let _ = writeln!(out, "*Why:* {}\n", escape(step.id.why()));
            out.push_str(&formulas(step, fmt));
            for text in &step.notes {
                let _ = writeln!(out, "- {}", note(text, step, fmt));
            }
            if !step.notes.is_empty() {
                out.push('\n');
            }
        }
    }
}

/// One contact: a heading at `level`, the figure when given, every stage one
/// level deeper, the state after and the checks.
pub fn contact(trace: &Trace, fmt: &Fmt, level: usize, figure: Option<&str>) -> String {
    let figures = Figures {
        contact: figure.map(str::to_string),
        impulse: None,
    };
    contact_with(trace, fmt, level, &figures)
}

/// Links to the SVG figures of one contact, written beside the document.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Figures {
    /// The contact's picture, shown under its heading.
    pub contact: Option<String>,
    /// The impulse-space figure, shown in the `exact_impact` stage.
    pub impulse: Option<String>,
}

/// [`contact`] with every figure link.
pub fn contact_with(trace: &Trace, fmt: &Fmt, level: usize, figures: &Figures) -> String {
    let mut out = heading(level, &format!("Contact {}", escape(&trace.contact_label)));
    if let Some(path) = &figures.contact {
        let _ = writeln!(
            out,
            "![Contact {}: bodies, normal, arms, velocities and impulse]({path})\n",
            escape(&trace.contact_label)
        );
    }
    for (i, step) in trace.stages.iter().enumerate() {
        stage(&mut out, i + 1, step, fmt, level + 1);
        // The checks stage shows its verdicts (a separating contact has none).
        if step.id == StageId::Checks && step.skipped.is_none() && !trace.verdicts.is_empty() {
            for v in &trace.verdicts {
                let _ = writeln!(
                    out,
                    "- {} {}: {}",
                    v.mark(),
                    escape(&v.label),
                    note(&v.detail, step, fmt)
                );
            }
            out.push('\n');
        }
        let impulse = figures.impulse.as_ref();
        if let Some(path) = impulse.filter(|_| step.id == StageId::ExactImpact) {
            let _ = writeln!(
                out,
                "![Impulse space: u_n and u_t against P_n, the phase changes marked]({path})\n"
            );
        }
    }
    out.push_str(&heading(level + 1, "After"));
    out.push_str(&after_table(&trace.after, fmt));
    out.push('\n');
    out
}

/// The bodies after, one row a body, units in the header: the one "After"
/// table of `solve` and `resolve` in Markdown.
pub(crate) fn after_table(bodies: &[(String, crate::trace::AfterState)], fmt: &Fmt) -> String {
    let mut out = String::from(
        "| body | position (m) | orientation | velocity (m/s) | angular velocity (rad/s) |\n|---|---|---|---|---|\n",
    );
    for (name, a) in bodies {
        let v = |x: &[f64]| format!("({})", fmt.list(x));
        let _ = writeln!(
            out,
            "| {} | {} | [{}] | {} | {} |",
            cell(name),
            v(&a.position),
            fmt.list(&a.orientation),
            v(&a.velocity),
            v(&a.angular_velocity)
        );
    }
    out
}

/// The lesson's heading, source, summary and warnings.
pub fn preamble(trace: &Trace, level: usize) -> String {
    let mut out = heading(level, &escape(&trace.title));
    let _ = write!(out, "Lesson `{}`", trace.lesson);
    if !trace.source.is_empty() {
        let _ = write!(out, " — {}", escape(&trace.source));
    }
    out.push_str("\n\n");
    if !trace.summary.trim().is_empty() {
        let _ = writeln!(out, "{}\n", escape(trace.summary.trim()));
    }
    for w in &trace.warnings {
        let _ = writeln!(out, "> **Warning:** {}\n", escape(w));
    }
    out
}

/// A whole document: the lesson's preamble, then every trace given (one per
/// contact), each with its figure link when `figures[k]` is set.
pub fn document(traces: &[Trace], fmt: &Fmt, figures: &[Figures]) -> String {
    let Some(first) = traces.first() else {
        return String::new();
    };
    let mut out = preamble(first, 1);
    for (k, t) in traces.iter().enumerate() {
        let none = Figures::default();
        out.push_str(&contact_with(t, fmt, 2, figures.get(k).unwrap_or(&none)));
    }
    out.truncate(out.trim_end().len());
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::{cell, escape};

    #[test]
    fn escapes_only_what_would_be_markup() {
        assert_eq!(
            escape("v_s < 0 and |d.x| ≤ |d.y|"),
            "v_s < 0 and |d.x| ≤ |d.y|"
        );
        assert_eq!(
            escape("_x_ *y* $z$ <b> [a](b)"),
            "\\_x\\_ \\*y\\* \\$z\\$ \\<b> [a\\](b)"
        );
        assert_eq!(escape("# one\n> two #3"), "\\# one\n\\> two #3");
        assert_eq!(cell("|g|"), "\\|g\\|");
    }
}
