//! The run's film strip: up to six frames of the scene side by side at one
//! scale, with what a reader would otherwise miss: a body smaller than a
//! pixel is drawn at a minimum size and ringed, and each `tunnelled` or
//! `toi` event is marked (✕ where the pair met) on the frame that ends its
//! step, which the strip swaps in for the nearest of its spread.

use std::fmt::Write;

use super::chart::escape;
use crate::format::Fmt;
use crate::render::figure::{outline, Silhouette};
use crate::trace::run::{EventLine, Frame, RunTrace};
use crate::trace::Plane;

/// The events the strip marks on a frame.
pub const MARKED: [&str; 2] = ["tunnelled", "toi"];
/// At most this many of them get a frame of their own.
pub const MAX_MARKED: usize = 3;
/// A body whose outline spans less than this (px) is drawn at [`MIN_R`].
const MIN_PX: f64 = 1.0;
const MIN_R: f64 = 3.0;
/// Where the panels start (below the title and the legend).
const TOP: f64 = 90.0;

/// The frames the film strip spreads over `frames`: up to six, from the
/// first to the last, in order.
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

/// Whether the strip marks event `e` on a frame.
pub fn marked(e: &EventLine) -> bool {
    MARKED.contains(&e.kind) && e.mark.is_some()
}

/// The frames the strip draws (indices into `run.frames`, in order) and,
/// for each marked event, the frame it is marked on: the first frame at or
/// after its step that holds the bodies, swapped in for the nearest frame
/// of [`film_picks`]'s spread (never the first or the last).
pub fn strip_frames(run: &RunTrace) -> (Vec<usize>, Vec<(usize, &EventLine)>) {
    let whole = |f: &Frame| f.bodies.len() == run.names.len();
    let mut picks: Vec<usize> = film_picks(run.frames.len())
        .into_iter()
        .filter(|&i| whole(&run.frames[i]))
        .collect();
    let mut marks = vec![];
    let mut own: Vec<usize> = vec![];
    for e in run.events.iter().filter(|e| marked(e)) {
        let Some(at) = run.frames.iter().position(|f| f.step >= e.step && whole(f)) else {
            continue;
        };
        if !own.contains(&at) {
            if own.len() == MAX_MARKED {
                continue;
            }
            own.push(at);
        }
        marks.push((at, e));
    }
    for &at in &own {
        if picks.contains(&at) {
            continue;
        }
        if picks.len() < 6 {
            picks.push(at);
            picks.sort_unstable();
            continue;
        }
        let last = picks.len() - 1;
        let step = |i: usize| run.frames[i].step as i64;
        let swap = (1..last)
            .filter(|&j| !own.contains(&picks[j]))
            .min_by_key(|&j| (step(picks[j]) - step(at)).abs());
        if let Some(j) = swap {
            picks[j] = at;
            picks.sort_unstable();
        }
    }
    marks.retain(|(at, _)| picks.contains(at));
    (picks, marks)
}

/// The strip and its legend into `out`; `(width, strip)`: the page's width
/// and the strip's height.
pub fn film_strip(out: &mut String, run: &RunTrace, plane: Plane, (width, strip): (f64, f64)) {
    let (picks, marks) = strip_frames(run);
    if picks.is_empty() {
        film_legend(out, width, false, false);
        return;
    }
    let n = picks.len();
    // One scale for all panels: the bounds of every finite body in every pick.
    let (lo, hi) = frames_bounds(run, picks.iter().copied(), plane);
    let w = (width - 48.0) / n as f64;
    let span = ((hi.0 - lo.0).max(1e-9), (hi.1 - lo.1).max(1e-9));
    let scale = ((w - 16.0) / span.0).min((strip - 40.0) / span.1);
    let fmt = Fmt::new(3);
    let (mut tiny_any, mut marks_any) = (false, false);
    for (slot, &k) in picks.iter().enumerate() {
        let f = &run.frames[k];
        let x0 = 24.0 + w * slot as f64;
        let y0 = TOP;
        let cx = x0 + w / 2.0;
        let cy = y0 + (strip - 20.0) / 2.0;
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
            strip - 20.0,
            cx,
            y0 + strip - 4.0,
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
                    r##"<clipPath id="c{slot}"><rect x="{:.1}" y="{y0:.1}" width="{:.1}" height="{:.1}"/></clipPath><line clip-path="url(#c{slot})" x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="#555555" stroke-width="2"/>"##,
                    x0 + 4.0,
                    w - 8.0,
                    strip - 20.0,
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
            let pts: Vec<(f64, f64)> = o
                .silhouette
                .points()
                .iter()
                .map(|q| page((q[0], q[1])))
                .collect();
            let (plo, phi) = extent(&pts);
            if (phi.0 - plo.0).max(phi.1 - plo.1) < MIN_PX {
                // Below a pixel: a dot of MIN_R, ringed and named.
                tiny_any = true;
                let (x, y) = ((plo.0 + phi.0) / 2.0, (plo.1 + phi.1) / 2.0);
                let _ = writeln!(
                    out,
                    r##"<g class="tiny"><circle cx="{x:.1}" cy="{y:.1}" r="{MIN_R}" fill="{fill}" stroke="#222222"{dash}/><circle cx="{x:.1}" cy="{y:.1}" r="8" fill="none" stroke="#D55E00" stroke-width="1.5"/><text x="{x:.1}" y="{:.1}" font-size="11" text-anchor="middle">{}</text></g>"##,
                    y - 11.0,
                    escape(&run.names[i])
                );
                continue;
            }
            match &o.silhouette {
                Silhouette::Polygon(_) => {
                    let pts: Vec<String> =
                        pts.iter().map(|(x, y)| format!("{x:.1},{y:.1}")).collect();
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
        // The events of this frame's step: ✕ where the pair met.
        for (row, (_, e)) in marks.iter().filter(|(at, _)| *at == k).enumerate() {
            let Some((point, time)) = e.mark else {
                continue;
            };
            marks_any = true;
            let (x, y) = page(plane.project(point));
            let what = if e.kind == "toi" {
                "toi: collided"
            } else {
                "tunnelled"
            };
            let label = format!("{what} at t = {} s", fmt.num(time));
            // The label along the panel's top, clear of the frame's edges
            // (centred where it is wider than the panel).
            let half = 3.1 * label.chars().count() as f64;
            let (from, to) = (x0 + 8.0 + half, x0 + w - 8.0 - half);
            let lx = if from <= to { x.clamp(from, to) } else { cx };
            let _ = writeln!(
                out,
                r##"<g class="event-mark"><path d="M{:.1},{:.1} L{:.1},{:.1} M{:.1},{:.1} L{:.1},{:.1}" stroke="#CC0000" stroke-width="2.5"/><text x="{lx:.1}" y="{:.1}" font-size="11" fill="#CC0000" text-anchor="middle">{}</text></g>"##,
                x - 6.0,
                y - 6.0,
                x + 6.0,
                y + 6.0,
                x - 6.0,
                y + 6.0,
                x + 6.0,
                y - 6.0,
                y0 + 14.0 + 13.0 * row as f64,
                escape(&label)
            );
        }
    }
    film_legend(out, width, tiny_any, marks_any);
}

/// The smallest and largest corner of `pts`.
fn extent(pts: &[(f64, f64)]) -> ((f64, f64), (f64, f64)) {
    pts.iter().fold(
        (
            (f64::INFINITY, f64::INFINITY),
            (f64::NEG_INFINITY, f64::NEG_INFINITY),
        ),
        |(lo, hi), p| {
            (
                (lo.0.min(p.0), lo.1.min(p.1)),
                (hi.0.max(p.0), hi.1.max(p.1)),
            )
        },
    )
}

/// What the film strip's outlines mean, at the right under the title: a
/// filled box per kind of body (awake, asleep with a dashed outline,
/// immovable) and the contact point's dot; on a second line, when the strip
/// draws them, the ring of a body below a pixel and the event's ✕.
fn film_legend(out: &mut String, width: f64, tiny: bool, marks: bool) {
    let entries = [
        ("#DCE9F5", "", "awake"),
        ("#EEEEEE", r#" stroke-dasharray="4 3""#, "asleep (dashed)"),
        ("#DDDDDD", "", "immovable"),
    ];
    let y = 44.0;
    let mut x = width - 560.0;
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
    let (y, mut x) = (y + 18.0, width - 840.0);
    if tiny {
        let _ = writeln!(
            out,
            r##"<circle cx="{:.1}" cy="{:.1}" r="3" fill="#DCE9F5" stroke="#222222"/><circle cx="{:.1}" cy="{:.1}" r="8" fill="none" stroke="#D55E00" stroke-width="1.5"/><text x="{:.1}" y="{:.1}">smaller than a pixel: drawn at 3 px, ringed</text>"##,
            x + 9.0,
            y + 7.0,
            x + 9.0,
            y + 7.0,
            x + 24.0,
            y + 12.0
        );
        x += 330.0;
    }
    if marks {
        let _ = writeln!(
            out,
            r##"<path d="M{:.1},{:.1} L{:.1},{:.1} M{:.1},{:.1} L{:.1},{:.1}" stroke="#CC0000" stroke-width="2.5"/><text x="{:.1}" y="{:.1}">where a pair met (tunnelled, time of collision)</text>"##,
            x + 3.0,
            y + 1.0,
            x + 15.0,
            y + 13.0,
            x + 3.0,
            y + 13.0,
            x + 15.0,
            y + 1.0,
            x + 24.0,
            y + 12.0
        );
    }
    out.push_str("</g>\n");
}

/// The bounds, in the figure's plane, of every body's outline in the frames
/// `frames` (finite points only; a unit square about the origin when there
/// is none): one scale for a film strip or a player.
pub fn frames_bounds(
    run: &RunTrace,
    frames: impl Iterator<Item = usize>,
    plane: Plane,
) -> ((f64, f64), (f64, f64)) {
    let (mut lo, mut hi) = (
        (f64::INFINITY, f64::INFINITY),
        (f64::NEG_INFINITY, f64::NEG_INFINITY),
    );
    for k in frames {
        for (i, b) in run.frames[k].bodies.iter().enumerate() {
            let Some(o) = run.shapes[i]
                .as_ref()
                .and_then(|s| outline(s, b.position, b.orientation, plane))
            else {
                continue;
            };
            for p in o.silhouette.points() {
                if p[0].is_finite() && p[1].is_finite() {
                    lo = (lo.0.min(p[0]), lo.1.min(p[1]));
                    hi = (hi.0.max(p[0]), hi.1.max(p[1]));
                }
            }
        }
    }
    if lo.0.is_finite() {
        (lo, hi)
    } else {
        ((-1.0, -1.0), (1.0, 1.0))
    }
}
