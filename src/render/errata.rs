//! The errata findings (printed numbers against computed ones) as text (an
//! errata sheet) or JSON, for the `check` subcommand.

use crate::render::fill::Fill;
use std::fmt::Write;

use serde_json::{json, Value as J};

use crate::errata::xpbd::{self, Erratum};
use crate::errata::{Item, Status, Tally};
use crate::format::Fmt;
use crate::lesson::printed::{PrintedNum, PrintedShape};
use crate::trace::symbols::stage_words;
use crate::trace::Value;

/// The printed numbers as printed (their decimals kept), bracketed like the
/// computed value (`[…]` for a quaternion, `(…)` for a vector).
fn printed_text(p: &PrintedShape, computed: Option<&Value>, fmt: &Fmt) -> String {
    let n = |x: &PrintedNum| fmt.fixed(x.value, x.decimals);
    let list = |xs: &[PrintedNum]| xs.iter().map(n).collect::<Vec<_>>().join(", ");
    match p {
        PrintedShape::Scalar(x) => n(x),
        PrintedShape::Vector(v) if matches!(computed, Some(Value::Quaternion(_))) => {
            format!("[{}]", list(v))
        }
        PrintedShape::Vector(v) => format!("({})", list(v)),
        PrintedShape::Matrix(m) => format!(
            "[{}]",
            m.iter()
                .map(|r| format!("[{}]", list(r)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

fn printed_json(p: &PrintedShape) -> J {
    let list = |xs: &[PrintedNum]| J::Array(xs.iter().map(|x| json!(x.value)).collect());
    match p {
        PrintedShape::Scalar(x) => json!(x.value),
        PrintedShape::Vector(v) => list(v),
        PrintedShape::Matrix(m) => J::Array(m.iter().map(|r| list(r)).collect()),
    }
}

fn mark(s: Status) -> &'static str {
    match s {
        Status::Agrees => "✓",
        Status::KnownErratum => "!",
        Status::NewDisagreement | Status::NotComputed => "✗",
        Status::StaleErratum => "?",
    }
}

/// The row's name as the lecture writes it, with its stage: `Δv (stage 3,
/// desired Δv)`, `g_contact[0] (stage 4, impulse, contact 1)`. The internal
/// key (`desired_delta_velocity.desired`) stays in the JSON.
fn name(i: &Item) -> String {
    let mut s = i.label.clone();
    if let Some(c) = i.component {
        let _ = write!(s, "[{c}]");
    }
    let stage = match &i.scope {
        Some(scope) => scope.clone(),
        None => stage_words(&i.stage).unwrap_or_else(|| i.stage.clone()),
    };
    match i.contact {
        k if i.stage == "lcp" => {
            let _ = write!(s, " ({stage}, contact {k})");
        }
        0 => {
            let _ = write!(s, " ({stage})");
        }
        k => {
            let _ = write!(s, " ({stage}, contact {k})");
        }
    }
    s
}

/// "12 agree, 3 known errata", and any problem that is not zero.
fn summary(t: &Tally) -> String {
    let mut parts = vec![
        format!("{} agree", t.agrees),
        format!("{} known errata", t.known),
    ];
    for (n, what) in [
        (t.new, "new disagreements"),
        (t.stale, "stale errata"),
        (t.not_computed, "not computed"),
    ] {
        if n > 0 {
            parts.push(format!("{n} {what}"));
        }
    }
    parts.join(", ")
}

/// The errata sheet: per lesson one line per agreeing number and a block per
/// erratum or problem, then the totals. `lessons` gives each lesson's id and
/// title, in order.
pub fn text(lessons: &[(String, String)], items: &[Item], fmt: &Fmt) -> String {
    let mut out = String::new();
    let mut unprinted = Vec::new();
    for (id, title) in lessons {
        let mine: Vec<&Item> = items.iter().filter(|i| &i.lesson == id).collect();
        if mine.is_empty() {
            unprinted.push(id.as_str());
            continue;
        }
        let _ = writeln!(
            out,
            "{id} — {title}\n  {} printed numbers: {}\n",
            mine.len(),
            summary(&Tally::of(mine.iter().copied()))
        );
        for i in &mine {
            let computed = i.computed.as_ref().map_or("–".into(), |v| fmt.value(v));
            let printed = printed_text(&i.printed, i.computed.as_ref(), fmt);
            if i.status == Status::Agrees {
                let _ = writeln!(
                    out,
                    "  {} {}: printed {printed}, computed {computed} — {}",
                    mark(i.status),
                    name(i),
                    i.location
                );
                continue;
            }
            let _ = writeln!(
                out,
                "  {} {}: {}",
                mark(i.status),
                name(i),
                i.status.name().to_uppercase()
            );
            let _ = writeln!(out, "      where     {}", i.location);
            let _ = writeln!(out, "      printed   {printed}");
            let _ = writeln!(out, "      computed  {computed}");
            match (&i.erratum, i.status) {
                (Some(e), Status::StaleErratum) => {
                    let _ = writeln!(out, "      erratum   {e}\n      the number agrees: the erratum note is out of date");
                }
                (Some(e), _) => {
                    let _ = writeln!(out, "      erratum   {e}");
                }
                (None, Status::NotComputed) => {
                    let _ = writeln!(out, "      the trace has no such stage, value or component");
                }
                (None, _) => {
                    let _ = writeln!(out, "      no erratum documents this difference");
                }
            }
        }
        out.push('\n');
    }
    if !unprinted.is_empty() {
        let _ = writeln!(out, "No printed numbers: {}.\n", unprinted.join(", "));
    }
    let t = Tally::of(items);
    let _ = writeln!(
        out,
        "{} lesson(s), {} printed numbers: {}.",
        lessons.len(),
        items.len(),
        summary(&t)
    );
    if t.failures() == 0 {
        out.push_str("Every disagreement is a known erratum.\n");
    }
    out
}

/// `{"items": […]}`, and `"papers": […]` when `papers` is given (the
/// default run over every embedded lesson).
pub fn json(items: &[Item], papers: Option<&Erratum>) -> String {
    let items: Vec<J> = items
        .iter()
        .map(|i| {
            let mut item = json!({
                "lesson": i.lesson,
                "contact": i.contact,
                "stage": i.stage,
                "value": i.value,
                "label": i.label,
                "component": i.component,
                "where": i.location,
                "printed": printed_json(&i.printed),
                "computed": i.computed.as_ref().map_or(J::Null, super::contact::json::value),
                "agrees": i.agrees,
                "erratum": i.erratum,
                "status": i.status.name().replace(' ', "_"),
            });
            if let Some(scope) = &i.scope {
                item["scope"] = json!(scope);
            }
            item
        })
        .collect();
    let mut doc = json!({ "items": items });
    if let Some(e) = papers {
        doc["papers"] = json!([xpbd_json(e)]);
    }
    serde_json::to_string_pretty(&doc).expect("JSON") + "\n"
}

/// The XPBD paper's erratum beside the lecture's: both formulas and the
/// deceleration measured on a sliding box under each.
pub fn xpbd_text(e: &Erratum, fmt: &Fmt) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "Beside the lecture: Müller et al. 2020, \"Detailed rigid body simulation with \
extended position based dynamics\"\n  ! dynamic friction (eq. 30): KNOWN ERRATUM"
    );
    let _ = writeln!(out, "      printed   {}", xpbd::PRINTED);
    let _ = writeln!(out, "      corrected {} (Solver2D)", xpbd::CORRECTED);
    let _ = writeln!(out, "      erratum   {}", xpbd::WHY);
    let _ = writeln!(
        out,
        "      measured  a 1 m box sliding at 3 m/s on a floor (μ_d {}, Δt 1/60 s, 4 substeps), \
deceleration in m/s², μ_d g = {}:",
        fmt.num(xpbd::MU_D),
        fmt.num(e.mu_g())
    );
    for r in &e.rows {
        let _ = writeln!(
            out,
            "        {} kg: printed {} ({} μ_d g), corrected {} ({} μ_d g)",
            fmt.num(r.mass),
            fmt.num(r.printed),
            fmt.fixed(r.printed / e.mu_g(), 3),
            fmt.num(r.corrected),
            fmt.fixed(r.corrected / e.mu_g(), 3)
        );
    }
    if e.rows.is_empty() {
        let _ = writeln!(out, "        no run gave a figure");
    }
    let _ = writeln!(
        out,
        "      the corrected deceleration is the same at every mass; it is under μ_d g because \
one position iteration a substep supplies only part of the support λ_n that friction reads \
(docs/simulate.md)"
    );
    out
}

/// The XPBD paper's erratum as JSON (the `papers` entry of `check`'s JSON).
pub fn xpbd_json(e: &Erratum) -> J {
    json!({
        "paper": "Müller et al. 2020, Detailed rigid body simulation with extended position based dynamics",
        "where": "eq. 30, dynamic friction",
        "printed": xpbd::PRINTED,
        "corrected": xpbd::CORRECTED,
        "erratum": xpbd::WHY,
        "mu_d": xpbd::MU_D,
        "mu_d_g": e.mu_g(),
        "measured": e.rows.iter().map(|r| json!({
            "mass": r.mass,
            "printed_deceleration": r.printed,
            "corrected_deceleration": r.corrected,
        })).collect::<Vec<_>>(),
    })
}
