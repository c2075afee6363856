//! The broad-phase study shown (`study --broad-phase`): a table per case
//! (tests, visits, pairs kept and, timed, µs per frame for each method at
//! each body count) with the winner by tests and by time, JSON for
//! scripts, and a log–log chart of tests (and time) against bodies.

use serde_json::json;

use crate::format::Fmt;
use crate::knobs::Choice;
use crate::physics::collide::BroadPhaseMethod;
use crate::render::chart::{Chart, Mark, Scale, Series, PALETTE};
use crate::study::broad::{BroadPoint, BroadStudy, Case, FRAMES};

/// How each number is measured, in words.
pub const MEASURES: [&str; 5] = [
    "tests: box-against-box overlap tests the method made in the last frame (deterministic; all-against-all makes n(n − 1)/2)",
    "visited: what the method walked — sweep: boxes swept (0 when the pairs of the last sweep of boxes grown by 5 % still serve); grid: cells that held a box; bvh: tree nodes the queries visited",
    "kept: pairs whose boxes overlap or touch (the same under every method)",
    "loose: boxes tested against every other box (grid: spanning more than 4 cells; bvh: not finite)",
    "µs/frame: one call's wall time, median over the frames (measured; this machine, this build)",
];

fn points(s: &BroadStudy, case: Case) -> impl Iterator<Item = &BroadPoint> {
    s.points.iter().filter(move |p| p.case == case)
}

/// The tables and the verdicts as plain text (or Markdown with `md`).
pub fn text(s: &BroadStudy, f: &Fmt, md: bool) -> String {
    let mut out = String::new();
    let title = "Broad phase: cost against the number of bodies";
    out.push_str(&if md {
        format!("# {title}\n\n")
    } else {
        format!("{title}\n\n")
    });
    out.push_str(&format!(
        "Each case: the first call, then {FRAMES} frames of small motion (each method keeps its state from frame to frame, as a run does); the counts are the last frame's.\n\n"
    ));
    for m in MEASURES.iter().filter(|m| s.timed || !m.starts_with("µs")) {
        out.push_str(&format!("- {m}\n"));
    }
    for case in Case::ALL {
        out.push_str(&if md {
            format!("\n## {} — {}\n\n", case.name(), case.words())
        } else {
            format!("\n{}: {}\n\n", case.name(), case.words())
        });
        let mut head = vec![
            "bodies".to_string(),
            "method".into(),
            "tests".into(),
            "visited".into(),
            "kept".into(),
            "loose".into(),
        ];
        if s.timed {
            head.push("µs/frame".into());
        }
        let mut rows = Vec::new();
        for p in points(s, case) {
            for r in &p.rows {
                let mut row = vec![
                    p.bodies.to_string(),
                    r.method.to_string(),
                    r.tests.to_string(),
                    r.visited.to_string(),
                    r.kept.to_string(),
                    r.loose.to_string(),
                ];
                if let Some(t) = r.microseconds {
                    row.push(f.num(t));
                }
                rows.push(row);
            }
        }
        out.push_str(&table(&head, &rows, md));
        out.push('\n');
        for p in points(s, case) {
            let mut line = format!(
                "{} bodies: fewest tests {} ({} of all-against-all's {})",
                p.bodies,
                p.fewest_tests(),
                p.rows.iter().map(|r| r.tests).min().unwrap_or(0),
                p.all_pairs
            );
            if let Some(fast) = p.fastest() {
                line.push_str(&format!("; fastest {fast}"));
            }
            out.push_str(&if md {
                format!("- {line}.\n")
            } else {
                format!("{line}.\n")
            });
        }
    }
    out
}

fn table(head: &[String], rows: &[Vec<String>], md: bool) -> String {
    let mut out = String::new();
    if md {
        out.push_str(&format!("| {} |\n", head.join(" | ")));
        out.push_str(&format!("|{}\n", "---|".repeat(head.len())));
        for r in rows {
            out.push_str(&format!("| {} |\n", r.join(" | ")));
        }
        return out;
    }
    let widths: Vec<usize> = (0..head.len())
        .map(|k| {
            rows.iter()
                .map(|r| r[k].chars().count())
                .chain([head[k].chars().count()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let line = |r: &[String]| {
        let cells: Vec<String> = r
            .iter()
            .zip(&widths)
            .enumerate()
            .map(|(k, (c, w))| {
                if k < 2 {
                    format!("{c:<w$}")
                } else {
                    format!("{c:>w$}")
                }
            })
            .collect();
        cells.join("  ").trim_end().to_string() + "\n"
    };
    out.push_str(&line(head));
    for r in rows {
        out.push_str(&line(r));
    }
    out
}

/// The study as JSON.
pub fn json(s: &BroadStudy) -> String {
    let v = json!({
        "frames": FRAMES,
        "timed": s.timed,
        "cases": Case::ALL.iter().map(|&case| json!({
            "case": case.name(),
            "description": case.words(),
            "points": points(s, case).map(|p| json!({
                "bodies": p.bodies,
                "all_pairs": p.all_pairs,
                "fewest_tests": p.fewest_tests(),
                "fastest": p.fastest(),
                "methods": p.rows.iter().map(|r| json!({
                    "method": r.method,
                    "tests": r.tests,
                    "visited": r.visited,
                    "kept": r.kept,
                    "loose": r.loose,
                    "microseconds_per_frame": r.microseconds,
                })).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
    });
    serde_json::to_string_pretty(&v).expect("finite JSON") + "\n"
}

/// One row per case, body count and method.
pub fn csv(s: &BroadStudy) -> String {
    let mut out = String::from(
        "case,bodies,all_pairs,method,tests,visited,kept,loose,microseconds_per_frame\n",
    );
    for p in &s.points {
        for r in &p.rows {
            out.push_str(&format!(
                "{},{},{},{},{},{},{},{},{}\n",
                p.case.name(),
                p.bodies,
                p.all_pairs,
                r.method,
                r.tests,
                r.visited,
                r.kept,
                r.loose,
                r.microseconds.map_or(String::new(), |t| t.to_string())
            ));
        }
    }
    out
}

/// Log–log charts: tests against bodies per case (and µs per frame when timed).
pub fn svg(s: &BroadStudy) -> String {
    let mut charts = Vec::new();
    for case in Case::ALL {
        let series = |value: &dyn Fn(usize, &BroadPoint) -> Option<f64>| -> Vec<Series> {
            let mut out: Vec<Series> = BroadPhaseMethod::NAMES
                .iter()
                .enumerate()
                .map(|(k, name)| Series {
                    name: name.to_string(),
                    points: points(s, case)
                        .filter_map(|p| Some((p.bodies as f64, value(k, p)?)))
                        .collect(),
                    colour: PALETTE[k],
                    mark: [Mark::Squares, Mark::Triangles, Mark::Diamonds][k],
                    dashed: false,
                })
                .collect();
            out.retain(|s| !s.points.is_empty());
            out
        };
        let mut tests = series(&|k, p| p.rows.get(k).map(|r| r.tests.max(1) as f64));
        tests.push(Series {
            name: "all against all".into(),
            points: points(s, case)
                .map(|p| (p.bodies as f64, p.all_pairs.max(1) as f64))
                .collect(),
            colour: PALETTE[7],
            mark: Mark::Line,
            dashed: true,
        });
        charts.push(Chart {
            title: format!("{}: box tests per frame", case.name()),
            x_label: "bodies".into(),
            y_label: "tests".into(),
            x_scale: Scale::Log,
            y_scale: Scale::Log,
            series: tests,
            ..Chart::default()
        });
        if s.timed {
            charts.push(Chart {
                title: format!("{}: time per frame (measured)", case.name()),
                x_label: "bodies".into(),
                y_label: "µs".into(),
                x_scale: Scale::Log,
                y_scale: Scale::Log,
                series: series(&|k, p| p.rows.get(k).and_then(|r| r.microseconds)),
                ..Chart::default()
            });
        }
    }
    let (w, h) = (640.0, 300.0);
    let height = h * charts.len() as f64;
    let mut out = format!(
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{height}" viewBox="0 0 {w} {height}" font-family="DejaVu Sans, Helvetica, Arial, sans-serif">
<rect width="100%" height="100%" fill="white"/>
"##
    );
    for (k, chart) in charts.iter().enumerate() {
        chart.draw(&mut out, (24.0, k as f64 * h + 16.0, w - 48.0, h - 36.0));
    }
    out.push_str("</svg>\n");
    out
}
