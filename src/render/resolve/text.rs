//! `resolve` as plain text: the contacts before (a table), each iteration on
//! one line, the phase notes, the contacts and bodies after, the checks.

use std::fmt::Write;

use super::{action, how, phase_heading, phase_notes, updates};
use crate::format::Fmt;
use crate::physics::resolver::Phase;
use crate::trace::resolver::{ContactRow, PhaseTrace, ResolverTrace};

fn table(out: &mut String, rows: &[ContactRow], fmt: &Fmt) {
    let cells: Vec<[String; 4]> = rows
        .iter()
        .zip(super::row_numbers(rows, fmt))
        .map(|(r, [p, v, d])| [r.label.clone(), p, v, d])
        .collect();
    let head = ["contact", "penetration", "v_s", "desired Δv"];
    let width = |i: usize| {
        cells
            .iter()
            .map(|c| c[i].chars().count())
            .chain([head[i].chars().count()])
            .max()
            .unwrap_or(0)
    };
    let w = [width(0), width(1), width(2), width(3)];
    let line = |c: [&str; 4]| {
        let pad = |s: &str, n: usize| format!("{s}{}", " ".repeat(n - s.chars().count()));
        format!(
            "   {}  {}  {}  {}",
            pad(c[0], w[0]),
            pad(c[1], w[1]),
            pad(c[2], w[2]),
            c[3]
        )
    };
    let _ = writeln!(out, "{}", line(head));
    for c in &cells {
        let _ = writeln!(out, "{}", line([&c[0], &c[1], &c[2], &c[3]]));
    }
}

fn phase(out: &mut String, p: &PhaseTrace, fmt: &Fmt) {
    let _ = writeln!(out);
    let _ = writeln!(out, "{}", phase_heading(p, fmt));
    let (tag, value) = match p.phase {
        Phase::Position => ("p", "penetration"),
        Phase::Velocity => ("v", "Δv"),
    };
    for it in &p.log {
        let others = updates(it, fmt);
        let others = if others.is_empty() {
            String::new()
        } else {
            format!(" | {others}")
        };
        let _ = writeln!(
            out,
            "   {tag}{:<4} contact {}: {value} {}; {}{others}",
            it.iteration,
            it.contact,
            fmt.change(it.value, it.own_after),
            action(it, fmt)
        );
    }
    for note in phase_notes(p, fmt) {
        let _ = writeln!(out, "   · {note}");
    }
}

pub fn render(trace: &ResolverTrace, fmt: &Fmt) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}  ({})", trace.title, trace.lesson);
    if !trace.source.is_empty() {
        let _ = writeln!(out, "Source: {}", trace.source);
    }
    let _ = writeln!(out, "{}", how(trace));
    for w in &trace.warnings {
        let _ = writeln!(out, "warning: {w}");
    }
    if let Some(note) = super::elision_note(trace) {
        let _ = writeln!(out, "{note}");
    }
    let _ = writeln!(out);
    let _ = writeln!(out, "Contacts before");
    table(&mut out, &trace.before, fmt);
    phase(&mut out, &trace.position, fmt);
    phase(&mut out, &trace.velocity, fmt);
    if let Some(l) = &trace.lcp {
        super::lcp::text(&mut out, l, fmt);
    }
    let _ = writeln!(out);
    let _ = writeln!(out, "Contacts after (the resolver's bookkeeping)");
    table(&mut out, &trace.contacts_after, fmt);
    let _ = writeln!(out);
    crate::render::contact::text::after(&mut out, &trace.after, fmt);
    let _ = writeln!(out);
    let _ = writeln!(out, "Checks");
    for v in &trace.verdicts {
        let _ = writeln!(out, "   {} {}: {}", v.mark(), v.label, v.detail);
    }
    out
}
