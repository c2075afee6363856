//! A run in time shown three ways: a text table with the events on their own
//! lines, JSON (docs/simulate.md), and an SVG film strip with charts of
//! energy, deepest penetration and awake bodies against time.

use std::fmt::Write;

use serde_json::{json, Map, Value as J};

use super::chart::{escape, Chart, Mark, Series, PALETTE};
use crate::format::Fmt;
use crate::render::figure::{outline, Silhouette};
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
        Fmt::new(4).num(run.dt),
        run.frames.last().map_or(0, |f| f.step)
    );
    film_strip(&mut out, run, plane);
    film_legend(&mut out);
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

/// The frames the film strip draws, of `frames`: up to six, spread over
/// the run from the first to the last, in order.
pub fn film_picks(frames: usize) -> Vec<usize> {
    let n = frames.min(6);
    (0..n)
        .map(|i| {
            if n == 1 {
                0
            } else {
                i * (frames - 1) / (n - 1)
            }
        })
        .collect()
}

/// What the film strip's outlines mean, on the title's line at the right:
/// a filled box per kind of body (awake, asleep with a dashed outline,
/// immovable) and the contact point's dot.
fn film_legend(out: &mut String) {
    let entries = [
        ("#DCE9F5", "", "awake"),
        ("#EEEEEE", r#" stroke-dasharray="4 3""#, "asleep (dashed)"),
        ("#DDDDDD", "", "immovable"),
    ];
    let y = 50.0;
    let mut x = WIDTH - 560.0;
    let _ = writeln!(out, r#"<g class="legend" font-size="13">"#);
    for (fill, dash, label) in entries {
        let _ = writeln!(
            out,
            r##"<rect x="{x:.1}" y="{y:.1}" width="18" height="14" fill="{fill}" stroke="#222222"{dash}/><text x="{:.1}" y="{:.1}">{label}</text>"##,
            x + 24.0,
            y + 12.0
        );
        x += 24.0 + 8.0 * label.len() as f64 + 20.0;
    }
    let _ = writeln!(
        out,
        r##"<circle cx="{:.1}" cy="{:.1}" r="4" fill="#D55E00"/><text x="{:.1}" y="{:.1}">contact point</text>"##,
        x + 6.0,
        y + 7.0,
        x + 16.0,
        y + 12.0
    );
    out.push_str("</g>\n");
}

/// Six panels of the scene, the same scale in each.
fn film_strip(out: &mut String, run: &RunTrace, plane: Plane) {
    if run.frames.is_empty() {
        return;
    }
    let n = run.frames.len().min(6);
    let picks: Vec<&Frame> = film_picks(run.frames.len())
        .into_iter()
        .map(|i| &run.frames[i])
        .collect();
    // One scale for all panels: the bounds of every finite body in every pick.
    let (mut lo, mut hi) = (
        (f64::INFINITY, f64::INFINITY),
        (f64::NEG_INFINITY, f64::NEG_INFINITY),
    );
    for f in &picks {
        for (i, b) in f.bodies.iter().enumerate() {
            let Some(o) = run.shapes[i]
                .as_ref()
                .and_then(|s| outline(s, b.position, b.orientation, plane))
            else {
                continue;
            };
            for p in o.silhouette.points() {
                lo = (lo.0.min(p[0]), lo.1.min(p[1]));
                hi = (hi.0.max(p[0]), hi.1.max(p[1]));
            }
        }
    }
    if !lo.0.is_finite() {
        (lo, hi) = ((-1.0, -1.0), (1.0, 1.0));
    }
    let w = (WIDTH - 48.0) / n as f64;
    let span = ((hi.0 - lo.0).max(1e-9), (hi.1 - lo.1).max(1e-9));
    let scale = ((w - 16.0) / span.0).min((STRIP - 40.0) / span.1);
    let fmt = Fmt::new(3);
    for (k, f) in picks.iter().enumerate() {
        let x0 = 24.0 + w * k as f64;
        let y0 = 80.0;
        let cx = x0 + w / 2.0;
        let cy = y0 + (STRIP - 20.0) / 2.0;
        let page = |p: (f64, f64)| {
            (
                cx + (p.0 - (lo.0 + hi.0) / 2.0) * scale,
                cy - (p.1 - (lo.1 + hi.1) / 2.0) * scale,
            )
        };
        let _ = writeln!(
            out,
            r##"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="#CCCCCC"/><text x="{:.1}" y="{:.1}" font-size="13" text-anchor="middle">t = {} s</text>"##,
            x0 + 4.0,
            y0,
            w - 8.0,
            STRIP - 20.0,
            cx,
            y0 + STRIP - 4.0,
            fmt.num(f.time)
        );
        // A half-space: a line across the panel through its point.
        for (i, b) in f.bodies.iter().enumerate() {
            if let Some(crate::physics::Shape::HalfSpace { normal }) = run.shapes[i] {
                let (u, v) = plane.project(normal);
                let along = (-v, u);
                let p = plane.project(b.position);
                let reach = span.0.max(span.1) * 2.0;
                let a = page((p.0 - along.0 * reach, p.1 - along.1 * reach));
                let z = page((p.0 + along.0 * reach, p.1 + along.1 * reach));
                let _ = writeln!(
                    out,
                    r##"<clipPath id="c{k}"><rect x="{:.1}" y="{y0:.1}" width="{:.1}" height="{:.1}"/></clipPath><line clip-path="url(#c{k})" x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="#555555" stroke-width="2"/>"##,
                    x0 + 4.0,
                    w - 8.0,
                    STRIP - 20.0,
                    a.0,
                    a.1,
                    z.0,
                    z.1
                );
            }
        }
        for (i, b) in f.bodies.iter().enumerate() {
            let Some(o) = run.shapes[i]
                .as_ref()
                .and_then(|s| outline(s, b.position, b.orientation, plane))
            else {
                continue;
            };
            let fill = if !run.movable[i] {
                "#DDDDDD"
            } else if b.awake {
                "#DCE9F5"
            } else {
                "#EEEEEE"
            };
            let dash = if run.movable[i] && !b.awake {
                r#" stroke-dasharray="4 3""#
            } else {
                ""
            };
            match &o.silhouette {
                Silhouette::Polygon(p) => {
                    let pts: Vec<String> = p
                        .iter()
                        .map(|q| {
                            let (x, y) = page((q[0], q[1]));
                            format!("{x:.1},{y:.1}")
                        })
                        .collect();
                    let _ = writeln!(
                        out,
                        r##"<polygon points="{}" fill="{fill}" stroke="#222222"{dash}/>"##,
                        pts.join(" ")
                    );
                }
                Silhouette::Circle { centre, radius } => {
                    let (x, y) = page((centre[0], centre[1]));
                    let _ = writeln!(
                        out,
                        r##"<circle cx="{x:.1}" cy="{y:.1}" r="{:.1}" fill="{fill}" stroke="#222222"{dash}/>"##,
                        radius * scale
                    );
                }
            }
        }
        for (q, _) in &f.contact_points {
            let (x, y) = page(plane.project(*q));
            let _ = writeln!(
                out,
                r##"<circle cx="{x:.1}" cy="{y:.1}" r="2.5" fill="#D55E00"/>"##
            );
        }
    }
}
