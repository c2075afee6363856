//! `resolve --compare A,B`: a lesson's contacts resolved by two solvers,
//! the bodies after side by side (text), or both answers in one JSON object
//! (`{ "lesson", "compare": [ { "solver", "after", "lcp"? } ] }`).

use std::fmt::Write;

use serde_json::{json, Map, Value as J};

use crate::cli::ResolveFormat;
use crate::error::AppError;
use crate::format::Fmt;
use crate::knobs::Choice;
use crate::physics::resolver::Implementation;
use crate::physics::{ResolverParams, Solver};
use crate::render::resolve::lcp;
use crate::trace::resolver::{describe, ResolverTrace};

fn traces(
    lesson: &crate::lesson::Lesson,
    params: &ResolverParams,
    implementation: Implementation,
    pair: [Solver; 2],
) -> [ResolverTrace; 2] {
    pair.map(|solver| {
        let p = ResolverParams { solver, ..*params };
        describe(lesson, &p, implementation, true)
    })
}

fn text(pair: [Solver; 2], t: &[ResolverTrace; 2], fmt: &Fmt) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}  ({})", t[0].title, t[0].lesson);
    let _ = writeln!(
        out,
        "{} contacts resolved by {} and by {}: the bodies after, side by side.",
        t[0].before.len(),
        pair[0].name(),
        pair[1].name()
    );
    let _ = writeln!(out);
    let head = ["body", "", pair[0].name(), pair[1].name()];
    let mut rows: Vec<[String; 4]> = Vec::new();
    for (k, (name, a)) in t[0].after.iter().enumerate() {
        let b = &t[1].after[k].1;
        rows.push([
            name.clone(),
            "velocity".into(),
            fmt.list(&a.velocity),
            fmt.list(&b.velocity),
        ]);
        rows.push([
            String::new(),
            "angular velocity".into(),
            fmt.list(&a.angular_velocity),
            fmt.list(&b.angular_velocity),
        ]);
    }
    let width = |i: usize| {
        rows.iter()
            .map(|r| r[i].chars().count())
            .chain([head[i].chars().count()])
            .max()
            .unwrap_or(0)
    };
    let w = [width(0), width(1), width(2)];
    let pad = |s: &str, n: usize| format!("{s}{}", " ".repeat(n - s.chars().count()));
    let _ = writeln!(
        out,
        "   {}  {}  {}  {}",
        pad(head[0], w[0]),
        pad(head[1], w[1]),
        pad(head[2], w[2]),
        head[3]
    );
    for r in &rows {
        let _ = writeln!(
            out,
            "   {}  {}  {}  {}",
            pad(&r[0], w[0]),
            pad(&r[1], w[1]),
            pad(&r[2], w[2]),
            r[3]
        );
    }
    for (solver, trace) in pair.iter().zip(t) {
        if let Some(l) = &trace.lcp {
            let _ = writeln!(out);
            let _ = writeln!(out, "{}:", solver.name());
            lcp::text(&mut out, l, fmt);
        }
    }
    out
}

fn json(pair: [Solver; 2], t: &[ResolverTrace; 2]) -> String {
    let answers: Vec<J> = pair
        .iter()
        .zip(t)
        .map(|(solver, trace)| {
            let after: Map<String, J> = trace
                .after
                .iter()
                .map(|(name, a)| {
                    (
                        name.clone(),
                        json!({ "position": a.position, "orientation": a.orientation,
                                "velocity": a.velocity, "angular_velocity": a.angular_velocity }),
                    )
                })
                .collect();
            let mut m = Map::new();
            m.insert(crate::knobs::SOLVER.name.into(), json!(solver.name()));
            m.insert("after".into(), J::Object(after));
            if let Some(l) = &trace.lcp {
                m.insert("lcp".into(), lcp::json(l));
            }
            J::Object(m)
        })
        .collect();
    let v = json!({ "lesson": t[0].lesson, "contacts": t[0].before.len(), "compare": answers });
    serde_json::to_string_pretty(&v).expect("JSON of a comparison") + "\n"
}

/// The comparison in `format` (text or JSON; the others are refused).
pub fn render(
    lesson: &crate::lesson::Lesson,
    params: &ResolverParams,
    implementation: Implementation,
    pair: [Solver; 2],
    format: ResolveFormat,
    fmt: &Fmt,
) -> Result<String, AppError> {
    let t = traces(lesson, params, implementation, pair);
    match format {
        ResolveFormat::Text => Ok(text(pair, &t, fmt)),
        ResolveFormat::Json => Ok(json(pair, &t)),
        _ => Err(AppError::Usage(
            "--compare prints text or json only (-f text or -f json)".into(),
        )),
    }
}
