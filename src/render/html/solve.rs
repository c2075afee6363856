//! A worked solution as a web page: per stage a `<section data-stage="ID">`
//! (the stage ids of the JSON contract) with its purpose, its formulas as
//! MathML (the LaTeX renderer's aligned rows, converted), its notes, and the
//! figure as that stage sees it; then the state after. Each formula with a
//! result carries the value for "predict before you look".

use std::fmt::Write;

use super::{esc, figure, mathml, page};
use crate::format::Fmt;
use crate::physics::StageId;
use crate::render::contact::latex::aligned_rows;
use crate::render::fill::Fill;
use crate::render::svg::{self, Plane};
use crate::trace::{glossary, Formula, Step, Trace, Value};

/// The id of stage `step` of contact number `n` on the page.
fn stage_id(n: usize, step: &Step) -> String {
    format!("c{n}-{}", step.id.json_name())
}

/// One formula: an aligned `<mtable>` (left side, then `= …` rows), the
/// result's cell marked for predict mode, its value in data attributes.
pub fn formula(f: &Formula, step: &Step, fmt: &Fmt) -> String {
    let rows = aligned_rows(f, step, fmt);
    let result = f.result.as_ref().and_then(|n| Some((n, step.lookup(n)?)));
    let last = rows.len().saturating_sub(1);
    let mut table = String::new();
    for (i, row) in rows.iter().enumerate() {
        let cells = mathml::cells(row);
        let (lhs, rhs) = match cells.as_slice() {
            [l, r, ..] => (l.as_str(), r.as_str()),
            [l] => (l.as_str(), ""),
            [] => ("", ""),
        };
        let hidden = if i == last && result.is_some() {
            " result"
        } else {
            ""
        };
        let _ = write!(
            table,
            "<mtr><mtd class=\"l\">{lhs}</mtd><mtd class=\"r{hidden}\">{rhs}</mtd></mtr>"
        );
    }
    let mut attrs = String::new();
    if let Some((name, value)) = result {
        let unit = glossary::unit(step, name);
        let answer = match value {
            Value::Text(word) => Some(format!(" data-word=\"{}\"", esc(word))),
            Value::List(_) => None,
            v if v.numbers().iter().all(|x| x.is_finite()) => Some(format!(
                " data-answer=\"{}\"",
                esc(&serde_json::to_string(&v.numbers()).expect("finite numbers"))
            )),
            _ => None,
        };
        if let Some(answer) = answer {
            let _ = write!(
                attrs,
                "{answer} data-name=\"{}\" data-unit=\"{}\" data-shown=\"{}\"",
                esc(&f.lhs),
                esc(unit),
                esc(&glossary::with_unit(&fmt.value(value), unit))
            );
        }
    }
    format!(
        "<div class=\"formula\"{attrs}><math display=\"block\"><mtable>{table}</mtable></math></div>\n"
    )
}

/// The figure a stage shows: the contact as the stage sees it, or the
/// impulse-space figure for the integrated impact.
fn stage_figure(trace: &Trace, step: &Step, key: &str) -> String {
    let svg = if step.id == StageId::ExactImpact {
        crate::render::contact::impact::svg(trace)
    } else {
        let mut picture = trace.clone();
        picture.impact = None;
        let stage = (step.id != StageId::Checks).then_some(step.id);
        Some(svg::render_at(&picture, Plane::Xy, stage))
    };
    match svg {
        Some(svg) => format!(
            "<figure>{}<figcaption>The figure as this stage sees it (seen along z: x to the right, y up).</figcaption></figure>\n",
            figure::inline(&svg, key)
        ),
        None => String::new(),
    }
}

fn stage(
    out: &mut String,
    trace: &Trace,
    n: usize,
    i: usize,
    step: &Step,
    fmt: &Fmt,
    figures: bool,
) {
    let id = stage_id(n, step);
    let title = format!("{}. {}", i + 1, step.title);
    let _ = writeln!(
        out,
        "<section class=\"stage\" data-stage=\"{}\" data-step data-title=\"{}\" id=\"{id}\" tabindex=\"-1\" aria-labelledby=\"{id}-h\">\n<h3 id=\"{id}-h\">{}</h3>",
        step.id.json_name(),
        esc(&title),
        esc(&title)
    );
    if let Some(why) = &step.skipped {
        let _ = writeln!(
            out,
            "<p class=\"why\"><strong>Skipped:</strong> {}</p>\n</section>",
            esc(why)
        );
        return;
    }
    let _ = writeln!(
        out,
        "<p class=\"why\"><strong>Why:</strong> {}</p>\n<div class=\"stage-body\"><div class=\"maths\">",
        esc(step.id.why())
    );
    for f in &step.formulas {
        out.push_str(&formula(f, step, fmt));
    }
    if !step.notes.is_empty() {
        out.push_str("<ul class=\"notes\">\n");
        for note in &step.notes {
            let _ = writeln!(out, "<li>{}</li>", esc(&fmt.fill_units(note, step)));
        }
        out.push_str("</ul>\n");
    }
    if step.id == StageId::Checks && !trace.verdicts.is_empty() {
        out.push_str("<ul class=\"checks\">\n");
        for v in &trace.verdicts {
            let class = match v.passed {
                Some(true) => "pass",
                Some(false) => "fail",
                None => "info",
            };
            let _ = writeln!(
                out,
                "<li class=\"{class}\"><span aria-hidden=\"true\">{}</span> <strong>{}</strong>: {}</li>",
                v.mark(),
                esc(&v.label),
                esc(&fmt.fill_units(&v.detail, step))
            );
        }
        out.push_str("</ul>\n");
    }
    out.push_str("</div>\n");
    if figures {
        out.push_str(&stage_figure(trace, step, &id));
    }
    out.push_str("</div>\n</section>\n");
}

/// The bodies after the contact, as a table.
pub fn after_table(bodies: &[(String, crate::trace::AfterState)], fmt: &Fmt) -> String {
    let v = |x: &[f64]| format!("({})", fmt.list(x));
    let mut out = String::from(
        "<table>\n<tr><th scope=\"col\">body</th><th scope=\"col\">position (m)</th><th scope=\"col\">orientation</th><th scope=\"col\">velocity (m/s)</th><th scope=\"col\">angular velocity (rad/s)</th></tr>\n",
    );
    for (name, a) in bodies {
        let _ = writeln!(
            out,
            "<tr><th scope=\"row\">{}</th><td>{}</td><td>[{}]</td><td>{}</td><td>{}</td></tr>",
            esc(name),
            v(&a.position),
            fmt.list(&a.orientation),
            v(&a.velocity),
            v(&a.angular_velocity)
        );
    }
    out.push_str("</table>\n");
    out
}

/// One contact's stages and the state after: an `<article>`; each stage's
/// figure when `figures` (the state after has its figure always).
pub fn contact(out: &mut String, trace: &Trace, n: usize, fmt: &Fmt, figures: bool) {
    let _ = writeln!(
        out,
        "<article class=\"contact\" aria-labelledby=\"c{n}\">\n<h2 id=\"c{n}\">Contact {}</h2>",
        esc(&trace.contact_label)
    );
    for (i, step) in trace.stages.iter().enumerate() {
        stage(out, trace, n, i, step, fmt, figures);
    }
    let id = format!("c{n}-after");
    let _ = writeln!(
        out,
        "<section class=\"after\" data-step data-title=\"After\" id=\"{id}\" tabindex=\"-1\" aria-labelledby=\"{id}-h\">\n<h3 id=\"{id}-h\">After</h3>"
    );
    out.push_str(&after_table(&trace.after, fmt));
    let mut picture = trace.clone();
    picture.impact = None;
    let _ = writeln!(
        out,
        "<figure>{}<figcaption>Every mark: before and after, the impulse, the projection's move.</figcaption></figure>\n</section>\n</article>",
        figure::inline(&svg::render(&picture, Plane::Xy), &id)
    );
}

/// The list of stages to jump to (a table of contents without the script).
fn stage_list(traces: &[Trace]) -> String {
    let mut out = String::from("<nav class=\"steps\" aria-label=\"stages\">\n");
    for (n, t) in traces.iter().enumerate() {
        if traces.len() > 1 {
            let _ = writeln!(out, "<p>Contact {}</p>", esc(&t.contact_label));
        }
        out.push_str("<ol>\n");
        for step in &t.stages {
            let class = if step.skipped.is_some() {
                " class=\"skipped\""
            } else {
                ""
            };
            let _ = writeln!(
                out,
                "<li{class}><a href=\"#{}\">{}</a></li>",
                stage_id(n, step),
                esc(step.title)
            );
        }
        let _ = writeln!(out, "<li><a href=\"#c{n}-after\">After</a></li>\n</ol>");
    }
    out.push_str("</nav>\n");
    out
}

/// The lesson's heading, source, summary and warnings.
pub fn header(
    title: &str,
    lesson: &str,
    source: &str,
    summary: &str,
    warnings: &[String],
) -> String {
    let mut out = format!(
        "<h1>{}</h1>\n<p class=\"meta\">Lesson <code>{}</code>",
        esc(title),
        esc(lesson)
    );
    if !source.is_empty() {
        let _ = write!(out, " — {}", esc(source));
    }
    out.push_str("</p>\n");
    if !summary.trim().is_empty() {
        let _ = writeln!(out, "<p>{}</p>", esc(summary.trim()));
    }
    for w in warnings {
        let _ = writeln!(
            out,
            "<p class=\"warning\"><strong>Warning:</strong> {}</p>",
            esc(w)
        );
    }
    out
}

/// Every trace given (one per contact) as one page; `note` (when given)
/// opens it.
pub fn document(traces: &[Trace], fmt: &Fmt, note: Option<&str>) -> String {
    let Some(first) = traces.first() else {
        return String::new();
    };
    let mut head = header(
        &first.title,
        &first.lesson,
        &first.source,
        &first.summary,
        &first.warnings,
    );
    if let Some(note) = note {
        let _ = writeln!(head, "<p class=\"note\"><em>{}</em></p>", esc(note));
    }
    let mut body = String::from("<div class=\"layout\">\n");
    body.push_str(&stage_list(traces));
    body.push_str("<main>\n");
    for (n, t) in traces.iter().enumerate() {
        contact(&mut body, t, n, fmt, true);
    }
    body.push_str("</main>\n</div>");
    page::page(
        &format!("{} — worked solution", first.title),
        page::Steps::Stages,
        &head,
        &body,
    )
}
