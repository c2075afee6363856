//! `resolve` as a web page: the contacts before, then every iteration of
//! the position and velocity phases as one step (what it took, what it did,
//! every contact's value before and after it), the taken contact's row
//! opening its worked stages at that iteration (Enter or a click), then the
//! contacts and bodies after and the checks.

use std::fmt::Write;

use super::{esc, page, solve};
use crate::format::Fmt;
use crate::physics::resolver::Phase;
use crate::render::resolve::{action, how, phase_heading, phase_notes, row_numbers, updates};
use crate::trace::resolver::{ContactRow, PhaseTrace, ResolverTrace};
use crate::trace::Trace;

/// The worked solution of each iteration's contact, where one was made:
/// `[position, velocity]`, by iteration.
pub type Worked = [Vec<Option<Trace>>; 2];

fn contacts_table(rows: &[ContactRow], fmt: &Fmt) -> String {
    let mut out = String::from(
        "<table>\n<tr><th scope=\"col\">contact</th><th scope=\"col\">penetration (m)</th><th scope=\"col\">v_s (m/s)</th><th scope=\"col\">desired Δv (m/s)</th></tr>\n",
    );
    for (r, [p, v, d]) in rows.iter().zip(row_numbers(rows, fmt)) {
        let _ = writeln!(
            out,
            "<tr><th scope=\"row\">{}</th><td>{p}</td><td>{v}</td><td>{d}</td></tr>",
            esc(&r.label)
        );
    }
    out.push_str("</table>\n");
    out
}

fn capital(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().chain(c).collect())
        .unwrap_or_default()
}

fn step_open(out: &mut String, id: &str, title: &str) {
    let _ = writeln!(
        out,
        "<section class=\"iteration\" data-step data-title=\"{t}\" id=\"{id}\" tabindex=\"-1\" aria-labelledby=\"{id}-h\">\n<h2 id=\"{id}-h\">{t}</h2>",
        t = esc(title)
    );
}

fn phase(
    out: &mut String,
    trace: &ResolverTrace,
    p: &PhaseTrace,
    worked: &[Option<Trace>],
    fmt: &Fmt,
) {
    let (key, what, unit) = match p.phase {
        Phase::Position => ("position", "penetration", "m"),
        Phase::Velocity => ("velocity", "desired Δv", "m/s"),
    };
    // Every contact's value as the phase goes, from the table before and
    // each iteration's own value and updates.
    let mut value: Vec<Option<f64>> = trace
        .before
        .iter()
        .map(|r| {
            Some(if p.phase == Phase::Position {
                r.penetration
            } else {
                r.desired
            })
        })
        .collect();
    let head = phase_heading(p, fmt);
    if p.log.is_empty() {
        step_open(
            out,
            &format!("{key}-phase"),
            &format!("{} phase", capital(p.phase.name())),
        );
        let _ = writeln!(out, "<p>{}</p>", esc(&head));
        for note in phase_notes(p, fmt) {
            let _ = writeln!(out, "<p>{}</p>", esc(&note));
        }
        out.push_str("</section>\n");
        return;
    }
    for (n, it) in p.log.iter().enumerate() {
        let id = format!("{key}-{}", it.iteration);
        let label = trace
            .before
            .get(it.contact)
            .map_or("", |r| r.label.as_str());
        step_open(
            out,
            &id,
            &format!(
                "{} iteration {}: contact {label}",
                capital(p.phase.name()),
                it.iteration
            ),
        );
        if n == 0 {
            let _ = writeln!(out, "<p class=\"meta\">{}</p>", esc(&head));
        }
        let _ = writeln!(
            out,
            "<p>It takes contact {} at {what} {} {unit}, the largest left, and leaves it at {}: {}.</p>",
            it.contact,
            fmt.num(it.value),
            fmt.num(it.own_after),
            esc(&action(it, fmt))
        );
        let others = updates(it, fmt);
        if !others.is_empty() {
            let _ = writeln!(out, "<p>Other contacts it changed: {}.</p>", esc(&others));
        }
        if let Some(v) = value.get_mut(it.contact) {
            *v = Some(it.value);
        }
        for u in &it.updated {
            if let Some(v) = value.get_mut(u.contact) {
                *v = Some(u.from);
            }
        }
        let mut after = value.clone();
        if let Some(v) = after.get_mut(it.contact) {
            *v = Some(it.own_after);
        }
        for u in &it.updated {
            if let Some(v) = after.get_mut(u.contact) {
                *v = Some(u.to);
            }
        }
        let panel = format!("{id}-stages");
        let has_stages = worked.get(n).is_some_and(Option::is_some);
        let _ = writeln!(
            out,
            "<table>\n<caption>Every contact's {what} ({unit}) before and after this iteration{}</caption>\n<tr><th scope=\"col\">contact</th><th scope=\"col\">before</th><th scope=\"col\">after</th></tr>",
            if has_stages { "; Enter (or a click) on the taken contact opens its stages" } else { "" }
        );
        for (k, r) in trace.before.iter().enumerate() {
            let show = |v: Option<f64>| v.map_or("—".to_string(), |v| fmt.num(v));
            let taken = k == it.contact;
            let open = if taken && has_stages {
                format!(" data-open=\"{panel}\" tabindex=\"0\" aria-expanded=\"false\" aria-label=\"contact {k}: open its stages at this iteration\"")
            } else {
                String::new()
            };
            let _ = writeln!(
                out,
                "<tr{open}{}><th scope=\"row\">{}</th><td>{}</td><td>{}</td></tr>",
                if taken { " class=\"taken\"" } else { "" },
                esc(&r.label),
                show(value[k]),
                show(after[k])
            );
        }
        out.push_str("</table>\n");
        if let Some(Some(t)) = worked.get(n) {
            let _ = writeln!(
                out,
                "<div class=\"worked\" id=\"{panel}\">\n<p class=\"meta\">Contact {} alone, the bodies as this iteration finds them (<code>resolve --show {key}:{}</code>).</p>",
                it.contact, it.iteration
            );
            let mut inner = String::new();
            // The stages without a figure each (the page stays small); the
            // state after has its figure.
            let base = if p.phase == Phase::Position {
                1000
            } else {
                2000
            };
            solve::contact(&mut inner, t, base + n, fmt, false);
            // Inside an iteration the stages are not steps of their own.
            out.push_str(&inner.replace(" data-step ", " "));
            out.push_str("</div>\n");
        }
        if n + 1 == p.log.len() {
            for note in phase_notes(p, fmt) {
                let _ = writeln!(out, "<p>{}</p>", esc(&note));
            }
        }
        out.push_str("</section>\n");
        value = after;
    }
}

/// The whole page; `worked` holds the iterations' worked solutions.
pub fn document(trace: &ResolverTrace, worked: &Worked, fmt: &Fmt) -> String {
    let mut head = solve::header(
        &trace.title,
        &trace.lesson,
        &trace.source,
        &trace.summary,
        &trace.warnings,
    );
    let _ = writeln!(head, "<p>{}</p>", esc(&how(trace)));
    if let Some(note) = crate::render::resolve::elision_note(trace) {
        let _ = writeln!(head, "<p class=\"note\">{}</p>", esc(&note));
    }
    let body = format!("<main>\n{}</main>", sections(trace, worked, fmt));
    page::page(
        &format!("{} — contacts resolved together", trace.title),
        page::Steps::Iterations,
        &head,
        &body,
    )
}

/// The page's steps: the contacts before, each iteration, the state after
/// (also what `simulate`'s player opens for `--trace-step`).
pub fn sections(trace: &ResolverTrace, worked: &Worked, fmt: &Fmt) -> String {
    let mut body = String::new();
    step_open(&mut body, "before", "Contacts before");
    body.push_str(&contacts_table(&trace.before, fmt));
    body.push_str("</section>\n");
    phase(&mut body, trace, &trace.position, &worked[0], fmt);
    phase(&mut body, trace, &trace.velocity, &worked[1], fmt);
    if let Some(l) = &trace.lcp {
        // The simultaneous solve as the text gives it: A, b, each pivot.
        let mut block = String::new();
        crate::render::resolve::lcp::text(&mut block, l, fmt);
        step_open(&mut body, "lcp", "The simultaneous solve");
        let _ = writeln!(
            body,
            "<pre class=\"text\">{}</pre>\n</section>",
            esc(block.trim_end())
        );
    }
    step_open(&mut body, "after", "After");
    body.push_str("<h3>Contacts after (the resolver's bookkeeping)</h3>\n");
    body.push_str(&contacts_table(&trace.contacts_after, fmt));
    body.push_str("<h3>Bodies</h3>\n");
    body.push_str(&solve::after_table(&trace.after, fmt));
    body.push_str("<h3>Checks</h3>\n<ul class=\"checks\">\n");
    for v in &trace.verdicts {
        let _ = writeln!(
            body,
            "<li><span aria-hidden=\"true\">{}</span> <strong>{}</strong>: {}</li>",
            v.mark(),
            esc(&v.label),
            esc(&v.detail)
        );
    }
    body.push_str("</ul>\n</section>\n");
    body
}
