//! A run in time shown three ways: a text table with the events on their own
//! lines, JSON (docs/simulate.md), and an SVG film strip with charts of
//! energy, deepest penetration and awake bodies against time.

use std::fmt::Write;

use serde_json::{json, Map, Value as J};

use super::chart::{escape, Chart, Mark, Series, PALETTE};
pub use super::run_film::{film_picks, marked, MAX_MARKED};
use crate::format::Fmt;
use crate::trace::run::{EventLine, Frame, RunTrace};
use crate::trace::Plane;

/// The text table: one row per recorded frame, events between the rows.
pub fn text(run: &RunTrace, fmt: &Fmt) -> String {
    let mut out = text_header(run, fmt);
    let mut next_event = 0;
    for f in &run.frames {
        while next_event < run.events.len() && run.events[next_event].step <= f.step {
            out.push_str(&event_line(&run.events[next_event], fmt));
            next_event += 1;
        }
        out.push_str(&frame_row(f, fmt));
    }
    for e in &run.events[next_event..] {
        out.push_str(&event_line(e, fmt));
    }
    if let Some(why) = &run.stopped {
        let _ = writeln!(out, "\nstopped: {why}");
    }
    out
}

/// The text table's title, legend and column heads.
pub(super) fn text_header(run: &RunTrace, fmt: &Fmt) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{} — {}", run.lesson, run.title);
    let _ = writeln!(
        out,
        "dt = {} s, {} bodies; energy E = kinetic + potential (J), deepest penetration d (m), iterations used (position/velocity)\n",
        fmt.num(run.dt),
        run.names.len()
    );
    let header = format!(
        "{:>7} {:>9} {:>8} {:>5} {:>11} {:>11} {:>11} {:>11} {:>9}",
        "step", "t (s)", "contacts", "awake", "d (m)", "kinetic", "potential", "E", "iter p/v"
    );
    let _ = writeln!(out, "{header}");
    let _ = writeln!(out, "{}", "─".repeat(header.chars().count()));
    out
}

/// An event's line between the rows.
pub(super) fn event_line(e: &EventLine, fmt: &Fmt) -> String {
    format!(
        "        · t = {} s (step {}): {}\n",
        fmt.num(e.time),
        e.step,
        e.text
    )
}

/// A frame's row.
pub(super) fn frame_row(f: &Frame, fmt: &Fmt) -> String {
    format!(
        "{:>7} {:>9} {:>8} {:>5} {:>11} {:>11} {:>11} {:>11} {:>9}\n",
        f.step,
        fmt.num(f.time),
        f.contacts,
        f.awake,
        fmt.num(f.max_penetration),
        fmt.num(f.kinetic_energy),
        fmt.num(f.potential_energy),
        fmt.num(f.kinetic_energy + f.potential_energy),
        format!("{}/{}", f.position_iterations, f.velocity_iterations)
    )
}

fn body_json(run: &RunTrace, f: &Frame) -> J {
    let mut bodies = Map::new();
    for (i, b) in f.bodies.iter().enumerate() {
        if !run.movable[i] {
            continue;
        }
        bodies.insert(
            run.names[i].clone(),
            json!({
                "position": b.position, "orientation": b.orientation,
                "velocity": b.velocity, "angular_velocity": b.angular_velocity, "awake": b.awake
            }),
        );
    }
    J::Object(bodies)
}

/// One entry of the JSON's `steps`.
pub(super) fn frame_json(run: &RunTrace, f: &Frame) -> J {
    json!({
        "step": f.step, "time": f.time, "contacts": f.contacts, "awake": f.awake,
        "max_penetration": f.max_penetration, "kinetic_energy": f.kinetic_energy,
        "potential_energy": f.potential_energy,
        "position_iterations": f.position_iterations,
        "velocity_iterations": f.velocity_iterations,
        "bodies": body_json(run, f)
    })
}

/// The JSON's `events`.
pub(super) fn events_json(run: &RunTrace) -> J {
    J::Array(
        run.events
            .iter()
            .map(|e| json!({ "step": e.step, "time": e.time, "kind": e.kind, "text": e.text }))
            .collect(),
    )
}

/// The JSON contract: `{ lesson, dt, steps: [ … ], events: [ … ] }`.
pub fn json(run: &RunTrace) -> J {
    let steps: Vec<J> = run.frames.iter().map(|f| frame_json(run, f)).collect();
    let mut out =
        json!({ "lesson": run.lesson, "dt": run.dt, "steps": steps, "events": events_json(run) });
    if let Some(why) = &run.stopped {
        out["stopped"] = J::String(why.clone());
    }
    out
}

const WIDTH: f64 = 1280.0;
const STRIP: f64 = 250.0;

/// The film strip (up to six frames spread over the run) above three charts.
pub fn svg(run: &RunTrace, plane: Plane) -> String {
    let height = 90.0 + STRIP + 3.0 * 230.0;
    let mut out = format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height}" viewBox="0 0 {WIDTH} {height}" font-family="DejaVu Sans, Helvetica, Arial, sans-serif">
<rect width="100%" height="100%" fill="#FFFFFF"/>
<text x="24" y="36" font-size="22" font-weight="bold">{}</text>
<text x="24" y="62" font-size="14" fill="#444444">{} · dt = {} s · {} steps</text>
"##,
        escape(&run.title),
        escape(&run.lesson),
        crate::study::grid::dt_label(run.dt),
        run.frames.last().map_or(0, |f| f.step)
    );
    super::run_film::film_strip(&mut out, run, plane, (WIDTH, STRIP));
    let t = |f: &Frame| f.time;
    let series = |name: &str, i: usize, get: &dyn Fn(&Frame) -> f64, mark: Mark| Series {
        name: name.into(),
        points: run.frames.iter().map(|f| (t(f), get(f))).collect(),
        colour: PALETTE[i],
        mark,
        dashed: i == 1,
    };
    let charts = [
        Chart {
            title: "Energy".into(),
            x_label: "t (s)".into(),
            y_label: "J".into(),
            series: vec![
                series("kinetic", 0, &|f| f.kinetic_energy, Mark::Line),
                series("potential", 1, &|f| f.potential_energy, Mark::Line),
                series(
                    "total",
                    2,
                    &|f| f.kinetic_energy + f.potential_energy,
                    Mark::Line,
                ),
            ],
            ..Chart::default()
        },
        Chart {
            title: "Deepest penetration".into(),
            x_label: "t (s)".into(),
            y_label: "m".into(),
            series: vec![series(
                "before resolution",
                0,
                &|f| f.max_penetration,
                Mark::Line,
            )],
            ..Chart::default()
        },
        Chart {
            title: "Awake bodies".into(),
            x_label: "t (s)".into(),
            y_label: "bodies".into(),
            series: vec![series("awake", 0, &|f| f.awake as f64, Mark::Steps)],
            integer_y: true,
            ..Chart::default()
        },
    ];
    for (i, chart) in charts.iter().enumerate() {
        chart.draw(
            &mut out,
            (24.0, 90.0 + STRIP + 230.0 * i as f64, WIDTH - 48.0, 220.0),
        );
    }
    out.push_str("</svg>\n");
    out
}
