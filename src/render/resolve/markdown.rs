//! `resolve` as Markdown: the same content as the text, with a heading per
//! part and tables for the contacts and the iterations.

use std::fmt::Write;

use super::{action, how, phase_heading, phase_notes, updates};
use crate::format::Fmt;
use crate::render::contact::markdown::{cell, escape};
use crate::trace::resolver::{ContactRow, PhaseTrace, ResolverTrace};

fn table(out: &mut String, rows: &[ContactRow], fmt: &Fmt) {
    let _ = writeln!(out, "| contact | penetration | v_s | desired Δv |");
    let _ = writeln!(out, "|---|---|---|---|");
    for (r, [p, v, d]) in rows.iter().zip(super::row_numbers(rows, fmt)) {
        let _ = writeln!(out, "| {} | {p} | {v} | {d} |", cell(&r.label));
    }
}

fn phase(out: &mut String, p: &PhaseTrace, fmt: &Fmt) {
    let _ = writeln!(out, "\n## {}\n", escape(&phase_heading(p, fmt)));
    if !p.log.is_empty() {
        let _ = writeln!(
            out,
            "| iteration | contact | value → after | moves or impulse | others changed |"
        );
        let _ = writeln!(out, "|---|---|---|---|---|");
        for it in &p.log {
            let _ = writeln!(
                out,
                "| {} | {} | {} | {} | {} |",
                it.iteration,
                it.contact,
                fmt.change(it.value, it.own_after),
                cell(&action(it, fmt)),
                cell(&updates(it, fmt))
            );
        }
        let _ = writeln!(out);
    }
    for note in phase_notes(p, fmt) {
        let _ = writeln!(out, "- {}", escape(&note));
    }
}

pub fn render(trace: &ResolverTrace, fmt: &Fmt) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# {} (`{}`)\n", escape(&trace.title), trace.lesson);
    if !trace.source.is_empty() {
        let _ = writeln!(out, "*Source:* {}\n", escape(&trace.source));
    }
    if !trace.summary.is_empty() {
        let _ = writeln!(out, "{}\n", escape(&trace.summary));
    }
    let _ = writeln!(out, "{}\n", escape(&how(trace)));
    for w in &trace.warnings {
        let _ = writeln!(out, "> warning: {}\n", escape(w));
    }
    if let Some(note) = super::elision_note(trace) {
        let _ = writeln!(out, "> {}\n", escape(&note));
    }
    let _ = writeln!(out, "## Contacts before\n");
    table(&mut out, &trace.before, fmt);
    phase(&mut out, &trace.position, fmt);
    phase(&mut out, &trace.velocity, fmt);
    if let Some(l) = &trace.lcp {
        // The simultaneous solve as the text gives it: A, b, each pivot.
        let mut block = String::new();
        super::lcp::text(&mut block, l, fmt);
        let _ = writeln!(
            out,
            "\n## The simultaneous solve\n\n```text\n{}\n```",
            block.trim_end()
        );
    }
    let _ = writeln!(out, "\n## Contacts after (the resolver's bookkeeping)\n");
    table(&mut out, &trace.contacts_after, fmt);
    let _ = writeln!(out, "\n## After\n");
    out.push_str(&crate::render::contact::markdown::after_table(
        &trace.after,
        fmt,
    ));
    let _ = writeln!(out, "\n## Checks\n");
    for v in &trace.verdicts {
        let _ = writeln!(
            out,
            "- {} **{}**: {}",
            v.mark(),
            escape(&v.label),
            escape(&v.detail)
        );
    }
    out
}
