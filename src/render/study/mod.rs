//! The study shown: a table per scene with the Pareto rows marked and one
//! sentence saying the trade ([`text`]), JSON and CSV for scripts
//! ([`json`], [`csv`]), a log–log plot of error against cost ([`svg`]) and a
//! report an instructor can hand out ([`markdown`]).

pub mod advise;
pub mod broad;
pub mod csv;
pub mod json;
pub mod markdown;
pub mod svg;
pub mod verdicts;

use crate::format::Fmt;
use crate::study::{Row, Study};

/// How each number is measured, in words (text and Markdown say it once).
pub const MEASURES: [&str; 9] = [
    "work/s: the cost, advise's: (contact visits + ccd tests + 1 for the step's own work) per step × steps per simulated second, so a smaller time step pays for its extra steps; deterministic; the front (★) is computed on it and the chart plots it",
    "µs/s: the whole step (contacts, integration, resolution, sleep) timed, × steps per simulated second: median of the timed runs with min–max (shown beside the work, not deciding the front)",
    "visits/step: contact visits of both phases per step (one deepest-first iteration or one sequential-impulse contact update is one visit), mean over the run, plus continuous detection's time-of-collision tests (`+ N ccd`: GJK calls, each counted as one visit); limit: steps where a phase used its whole budget",
    "pen. left: deepest overlap after any step (the shapes collided again, no margin), m",
    "closing left: fastest closing normal velocity after any step at the contacts it resolved, m/s",
    "energy gain: largest rise of kinetic + potential energy above the start, J",
    "drift: how far the top body (the last on ties) moved across gravity by the end (with no gravity: how far it moved), m",
    "missed: missed collisions, pairs that crossed inside a step without a contact (tunnelled events)",
    "error: RMS over the movable bodies of the distance between their final positions and the reference's, m",
];

/// A number for the tables ("—" when not a number).
pub fn num(fmt: &Fmt, x: f64) -> String {
    if x.is_finite() {
        fmt.num(x)
    } else {
        "—".into()
    }
}

/// The timed cell: median (min–max) µs per simulated second.
pub fn cost_cell(fmt: &Fmt, r: &Row) -> String {
    match r.microseconds_per_second {
        Some([m, lo, hi]) => format!("{} ({}–{})", fmt.num(m), fmt.num(lo), fmt.num(hi)),
        None => "—".into(),
    }
}

/// Work per simulated second as the verdict quotes it.
pub fn work(fmt: &Fmt, x: f64) -> String {
    crate::study::pareto::work_text(fmt, x)
}

/// The work cell: contact visits per step, and continuous detection's
/// tests beside them where it made any (`12 + 30 ccd`).
pub fn visits_cell(fmt: &Fmt, r: &Row) -> String {
    if r.ccd_tests_per_step > 0.0 {
        format!(
            "{} + {} ccd",
            fmt.num(r.visits_per_step),
            fmt.num(r.ccd_tests_per_step)
        )
    } else {
        fmt.num(r.visits_per_step)
    }
}

/// The cells of one row, in the column order of [`headers`]: the front's
/// two axes and its mark first, then the timing and the other measures.
pub fn cells(fmt: &Fmt, r: &Row, timed: bool) -> Vec<String> {
    let mut c = vec![
        r.knob.clone(),
        r.value.clone(),
        work(fmt, r.work_per_second),
        num(fmt, r.error_vs_reference),
        match (&r.failure, r.pareto) {
            (Some(_), _) => "blew up".into(),
            (None, true) => "★".into(),
            (None, false) => String::new(),
        },
    ];
    if timed {
        c.push(cost_cell(fmt, r));
    }
    c.extend([
        visits_cell(fmt, r),
        format!("{}/{}", r.limit_steps, r.steps),
        num(fmt, r.max_penetration),
        num(fmt, r.max_closing_velocity),
        num(fmt, r.energy_gain),
        num(fmt, r.drift),
        r.missed_collisions.to_string(),
    ]);
    c
}

/// Column headings (µs/s only when timed).
pub fn headers(timed: bool) -> Vec<&'static str> {
    let mut h = vec!["knob", "value", "work/s", "error", "front"];
    if timed {
        h.push("µs/s (min–max)");
    }
    h.extend([
        "visits/step",
        "limit",
        "pen. left",
        "closing left",
        "energy gain",
        "drift",
        "missed",
    ]);
    h
}

/// The text tables, folded to `width` as tables (0: never; the prose is
/// left to [`crate::render::wrap::wrap`]).
pub fn text(study: &Study, fmt: &Fmt, width: usize) -> String {
    let mut out = String::new();
    out.push_str("Speed against accuracy: each scene under one knob at a time around its default, and the iteration budget of each solver.\n");
    out.push_str("★ marks the Pareto front of work per simulated second (deterministic) against error: no other row does less work per simulated second and is more accurate; ties stay.\n");
    for m in MEASURES {
        out.push_str(&format!("   · {m}\n"));
    }
    if study.timed {
        out.push_str(&format!(
            "   · {} timed runs per configuration\n",
            study.repeats
        ));
    }
    for s in &study.scenes {
        out.push_str(&format!(
            "\n{}  ({}, {} s)\nReference: {}.\n",
            s.title,
            s.scene,
            fmt.num(s.seconds),
            s.reference
        ));
        let head: Vec<String> = headers(study.timed).iter().map(|h| h.to_string()).collect();
        let rows: Vec<Vec<String>> = s.rows.iter().map(|r| cells(fmt, r, study.timed)).collect();
        out.push_str(&crate::render::wrap::table(2, 2, &head, &rows, width));
        out.push_str(&format!("  {}\n", s.verdict));
    }
    out
}
