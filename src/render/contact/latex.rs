//! A worked solution as LaTeX: a standalone `article` with `amsmath`, or the
//! body alone (`--fragment`). Stage formulas go in one `align*` each; notes,
//! titles and summaries are prose with their maths set inline.

use crate::render::fill::Fill;
use std::fmt::Write;

use crate::format::Fmt;
use crate::physics::StageId;
use crate::render::tex::{escape_text, prose};
use crate::trace::{glossary, Formula, Step, Trace};

/// Packages a fragment needs; the standalone document loads them.
pub const PACKAGES: &str = "\\usepackage{amsmath}\n\\usepackage{amssymb}";

/// The formula as rows of an aligned block: `lhs &= rhs`, `&= numbers`,
/// `&= result` (a row that repeats the previous one is left out).
pub fn aligned_rows(f: &Formula, step: &Step, fmt: &Fmt) -> Vec<String> {
    let latex = crate::render::tex::formula(f);
    let (lhs, rhs) = latex.split_once(" = ").unwrap_or((&latex, ""));
    let mut right: Vec<String> = Vec::new();
    if !rhs.trim().is_empty() {
        right.push(rhs.trim().to_string());
    }
    if let Some(s) = crate::render::tex::substituted(f) {
        right.push(fmt.fill(&s, step, true));
    }
    if let Some((name, r)) = f.result.as_ref().and_then(|n| Some((n, step.lookup(n)?))) {
        let unit = glossary::unit(step, name);
        let r = degrees_apart(fmt.value_latex(r), unit);
        if right.last() != Some(&r) {
            right.push(r);
        }
        // The result carries its unit.
        if let Some(last) = right.last_mut() {
            last.push_str(&glossary::unit_latex(unit));
        }
    }
    let mut rows = Vec::new();
    for (i, r) in right.iter().enumerate() {
        if i == 0 {
            rows.push(format!("{lhs} &= {r}"));
        } else {
            rows.push(format!("&= {r}"));
        }
    }
    if rows.is_empty() {
        rows.push(format!("{lhs} &"));
    }
    rows
}

/// Sectioning command for a depth: 0 section, 1 subsection, 2 subsubsection,
/// deeper a run-in paragraph. Unnumbered: the text carries its own number.
pub fn heading(depth: usize, text: &str) -> String {
    let cmd = ["section", "subsection", "subsubsection", "paragraph"][depth.min(3)];
    format!("\\{cmd}*{{{text}}}\n")
}

/// A number in degrees written in powers of ten in parentheses,
/// `(5.9 \times 10^{-5})^{\circ}`: the degree sign after a bare exponent
/// reads as part of it.
fn degrees_apart(number: String, unit: &str) -> String {
    if unit == "°" && number.contains("\\times 10^") && !number.starts_with('(') {
        format!("({number})")
    } else {
        number
    }
}

fn note(text: &str, step: &Step, fmt: &Fmt) -> String {
    fmt.fill_named(text, step, &prose, &|name, v| {
        format!(
            "${}{}$",
            degrees_apart(fmt.value_latex(v), glossary::unit(step, name)),
            glossary::unit_latex(glossary::unit_to_add(
                text,
                name,
                glossary::unit(step, name)
            ))
        )
    })
}

fn stage(out: &mut String, n: usize, step: &Step, fmt: &Fmt, depth: usize) {
    out.push('\n');
    out.push_str(&heading(depth, &format!("{n}. {}", prose(step.title))));
    if let Some(why) = &step.skipped {
        let _ = writeln!(out, "\\emph{{Skipped:}} {}", prose(why));
        return;
    }
    let _ = writeln!(out, "\\emph{{Why:}} {}\n", prose(step.id.why()));
    let rows: Vec<String> = step
        .formulas
        .iter()
        .map(|f| aligned_rows(f, step, fmt).join(" \\\\\n"))
        .collect();
    if !rows.is_empty() {
        let _ = writeln!(
            out,
            "\\begin{{align*}}\n{}\n\\end{{align*}}",
            rows.join(" \\\\[4pt]\n")
        );
    }
    if !step.notes.is_empty() {
        out.push_str("\\begin{itemize}\n");
        for text in &step.notes {
            let _ = writeln!(out, "\\item {}", note(text, step, fmt));
        }
        out.push_str("\\end{itemize}\n");
    }
}

/// One contact: a heading at `depth`, every stage one deeper, the state
/// after and the checks.
pub fn contact(trace: &Trace, fmt: &Fmt, depth: usize) -> String {
    let mut out = heading(depth, &format!("Contact {}", prose(&trace.contact_label)));
    // The figure with every mark: before and after, the projection's move.
    if let Some(fig) = super::latex_figure::picture(&trace.scene, None) {
        out.push_str(&fig);
    }
    for (i, step) in trace.stages.iter().enumerate() {
        stage(&mut out, i + 1, step, fmt, depth + 1);
        // The checks stage shows its verdicts; a separating contact has none
        // (and an empty itemize does not compile).
        if step.id == StageId::Checks && step.skipped.is_none() && !trace.verdicts.is_empty() {
            out.push_str("\\begin{itemize}\n");
            for v in &trace.verdicts {
                let mark = match v.passed {
                    Some(true) => "$\\checkmark$",
                    Some(false) => "$\\times$",
                    None => "$\\cdot$",
                };
                let _ = writeln!(
                    out,
                    "\\item[{mark}] {}: {}",
                    prose(&v.label),
                    note(&v.detail, step, fmt)
                );
            }
            out.push_str("\\end{itemize}\n");
        }
    }
    out.push('\n');
    out.push_str(&heading(depth + 1, "After"));
    out.push_str("\\begin{description}\n");
    for (name, a) in &trace.after {
        let v = |x: &[f64]| {
            format!(
                "({})",
                x.iter()
                    .map(|x| fmt.num_latex(*x))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        let q = a
            .orientation
            .iter()
            .map(|x| fmt.num_latex(*x))
            .collect::<Vec<_>>()
            .join(", ");
        let _ = writeln!(
            out,
            "\\item[{}] position ${}\\,\\mathrm{{m}}$, orientation $[{q}]$,\\\\\n velocity ${}\\,\\mathrm{{m/s}}$, angular velocity ${}\\,\\mathrm{{rad/s}}$.",
            prose(name),
            v(&a.position),
            v(&a.velocity),
            v(&a.angular_velocity)
        );
    }
    out.push_str("\\end{description}\n");
    out
}

/// The lesson's heading, source, summary and warnings.
pub fn preamble(trace: &Trace, depth: usize) -> String {
    let mut out = heading(depth, &prose(&trace.title));
    let _ = write!(out, "Lesson \\texttt{{{}}}", escape_text(&trace.lesson));
    if !trace.source.is_empty() {
        let _ = write!(out, " --- {}", prose(&trace.source));
    }
    out.push_str(".\n");
    if !trace.summary.trim().is_empty() {
        let _ = writeln!(out, "\n{}", prose(trace.summary.trim()));
    }
    for w in &trace.warnings {
        let _ = writeln!(out, "\n\\textbf{{Warning:}} {}", prose(w));
    }
    out
}

/// Wraps a body in a standalone article.
pub fn standalone(body: &str) -> String {
    format!(
        "\\documentclass[11pt]{{article}}\n\\usepackage[a4paper,margin=2.2cm]{{geometry}}\n{PACKAGES}\n\\allowdisplaybreaks\n\\begin{{document}}\n{body}\\end{{document}}\n"
    )
}

/// Every trace given (one per contact) after the lesson's preamble; a
/// standalone document unless `fragment`.
pub fn document(traces: &[Trace], fmt: &Fmt, fragment: bool) -> String {
    let Some(first) = traces.first() else {
        return String::new();
    };
    let mut body = preamble(first, 0);
    for t in traces {
        body.push('\n');
        body.push_str(&contact(t, fmt, 1));
    }
    if fragment {
        format!(
            "% contact-lab worked solution; needs {}\n{body}",
            PACKAGES.replace('\n', " ")
        )
    } else {
        standalone(&body)
    }
}
