//! Plain text, laid out like the lecture's worked examples: per stage the
//! formula, the numbers put into it, the result.

use crate::render::fill::Fill;
use std::fmt::Write;

use crate::format::Fmt;
use crate::physics::StageId;
use crate::trace::{glossary, Formula, Step, Trace};

/// `lhs = rhs`, `= numbers`, `= result`, aligned under the `=`.
pub fn formula_lines(f: &Formula, step: &Step, fmt: &Fmt) -> Vec<String> {
    let mut rhs = Vec::new();
    if !f.rhs.is_empty() {
        rhs.push(f.rhs.to_string());
    }
    if let Some(s) = &f.substituted {
        rhs.push(fmt.fill(s, step, false));
    }
    if let Some((name, r)) = f.result.as_ref().and_then(|n| Some((n, step.lookup(n)?))) {
        let r = fmt.value(r);
        if rhs.last() != Some(&r) {
            rhs.push(r);
        }
        // The result carries its unit (the substituted numbers do not: the
        // glossary gives every symbol's unit).
        if let Some(last) = rhs.last_mut() {
            *last = glossary::with_unit(last, glossary::unit(step, name));
        }
    }
    let pad = " ".repeat(f.lhs.chars().count());
    rhs.iter()
        .enumerate()
        .map(|(i, r)| {
            if i == 0 {
                format!("{} = {r}", f.lhs)
            } else {
                format!("{pad} = {r}")
            }
        })
        .collect()
}

pub fn render(trace: &Trace, fmt: &Fmt) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}  ({})", trace.title, trace.lesson);
    if !trace.source.is_empty() {
        let _ = writeln!(out, "Source: {}", trace.source);
    }
    let _ = writeln!(out, "Contact {}", trace.contact_label);
    for w in &trace.warnings {
        let _ = writeln!(out, "warning: {w}");
    }
    for (i, step) in trace.stages.iter().enumerate() {
        let _ = writeln!(out);
        match &step.skipped {
            Some(why) => {
                let _ = writeln!(
                    out,
                    "{}. {} [{}] — skipped: {why}",
                    i + 1,
                    step.title,
                    step.id.json_name()
                );
            }
            None => {
                let _ = writeln!(out, "{}. {} [{}]", i + 1, step.title, step.id.json_name());
                let _ = writeln!(out, "   Why: {}", step.id.why());
                for f in &step.formulas {
                    for line in formula_lines(f, step, fmt) {
                        let _ = writeln!(out, "   {line}");
                    }
                }
                for note in &step.notes {
                    let _ = writeln!(out, "   · {}", fmt.fill_units(note, step));
                }
                // The checks stage shows its verdicts, not only its formulas.
                if step.id == StageId::Checks {
                    for v in &trace.verdicts {
                        let _ = writeln!(
                            out,
                            "   {} {}: {}",
                            v.mark(),
                            v.label,
                            fmt.fill_units(&v.detail, step)
                        );
                    }
                }
            }
        }
    }
    let _ = writeln!(out);
    after(&mut out, &trace.after, fmt);
    out
}

/// "After", then each body's position, orientation and velocities, two lines a body.
pub(crate) fn after(out: &mut String, bodies: &[(String, crate::trace::AfterState)], fmt: &Fmt) {
    let _ = writeln!(out, "After");
    for (name, a) in bodies {
        let v = |x: &[f64]| format!("({})", fmt.list(x));
        let _ = writeln!(
            out,
            "   {name}: position {} m, orientation [{}]",
            v(&a.position),
            fmt.list(&a.orientation)
        );
        let _ = writeln!(
            out,
            "   {}  velocity {} m/s, angular velocity {} rad/s",
            " ".repeat(name.chars().count()),
            v(&a.velocity),
            v(&a.angular_velocity)
        );
    }
}
