//! Labels in a figure never cover the drawing (issue 16, item 7): for every
//! contact of every lesson, at every stage and whole, in each plane, no
//! label's box in the SVG's drawing area meets a stroke: a body outline, an
//! arrow or its head, a spin, a surface, a dot. The strokes are read back
//! from the SVG itself (lines, polygons, circles, paths), not from the code
//! that placed the labels.

use contact_lab::physics::StageId;
use contact_lab::render::svg::render_at;

type P = [f64; 2];

/// A straight piece of a stroke and half its width.
struct Piece(P, P, f64);

use crate::common;

use common::svg::{attr, drawing, label_boxes as labels};

fn num(tag: &str, name: &str) -> f64 {
    attr(tag, name).and_then(|s| s.parse().ok()).unwrap_or(0.0)
}

fn ring(points: &[P], w: f64, out: &mut Vec<Piece>) {
    for (i, a) in points.iter().enumerate() {
        out.push(Piece(*a, points[(i + 1) % points.len()], w / 2.0));
    }
}

fn circle(c: P, r: f64, w: f64, out: &mut Vec<Piece>) {
    let pts: Vec<P> = (0..32)
        .map(|i| {
            let a = std::f64::consts::TAU * f64::from(i) / 32.0;
            [c[0] + r * a.cos(), c[1] + r * a.sin()]
        })
        .collect();
    ring(&pts, w, out);
}

/// An arrow head (SVG marker: 4.5 stroke widths, tip 0.9 widths past the end).
fn head(p: P, q: P, w: f64, out: &mut Vec<Piece>) {
    let len = (q[0] - p[0]).hypot(q[1] - p[1]);
    if len > 0.0 {
        let u = [(q[0] - p[0]) / len, (q[1] - p[1]) / len];
        let at = |a: f64, s: f64| [q[0] + a * u[0] - s * u[1], q[1] + a * u[1] + s * u[0]];
        let n = 2.25 * w;
        ring(
            &[at(0.9 * w, 0.0), at(-3.6 * w, n), at(-3.6 * w, -n)],
            1.0,
            out,
        );
    }
}

fn pair(s: &str) -> P {
    let mut it = s.split(',').map(|x| x.trim().parse::<f64>().unwrap());
    [it.next().unwrap(), it.next().unwrap()]
}

/// An SVG path: `M a L b M c L d` pieces, or `M s A r,r 0 large sweep e` (a
/// circular arc, centre found as SVG's implementation notes F.6.5 do).
fn path(d: &str, w: f64, headed: bool, out: &mut Vec<Piece>) {
    if let Some((m, a)) = d.split_once(" A") {
        let s = pair(m.trim_start_matches('M'));
        let parts: Vec<&str> = a.split_whitespace().collect();
        let r = pair(parts[0])[0];
        let (large, sweep) = (parts[2] == "1", parts[3] == "1");
        let e = pair(parts[4]);
        let h = [(s[0] - e[0]) / 2.0, (s[1] - e[1]) / 2.0];
        let hh = h[0] * h[0] + h[1] * h[1];
        let sign = if large != sweep { 1.0 } else { -1.0 };
        let k = sign * ((r * r - hh).max(0.0) / hh).sqrt();
        let c = [
            k * h[1] + (s[0] + e[0]) / 2.0,
            -k * h[0] + (s[1] + e[1]) / 2.0,
        ];
        let (t1, t2) = (
            (s[1] - c[1]).atan2(s[0] - c[0]),
            (e[1] - c[1]).atan2(e[0] - c[0]),
        );
        let tau = std::f64::consts::TAU;
        let span = if sweep {
            (t2 - t1).rem_euclid(tau)
        } else {
            -(t1 - t2).rem_euclid(tau)
        };
        let pts: Vec<P> = (0..=24)
            .map(|i| {
                let t = t1 + span * f64::from(i) / 24.0;
                [c[0] + r * t.cos(), c[1] + r * t.sin()]
            })
            .collect();
        for p in pts.windows(2) {
            out.push(Piece(p[0], p[1], w / 2.0));
        }
        if headed {
            head(pts[23], pts[24], w, out);
        }
    } else {
        for seg in d.split('M').filter(|s| !s.trim().is_empty()) {
            let (a, b) = seg.split_once('L').unwrap();
            out.push(Piece(pair(a), pair(b), w / 2.0));
        }
    }
}

/// The strokes of the drawing area (between its start and the legend).
fn strokes(drawing: &str) -> Vec<Piece> {
    let mut out = vec![];
    for t in drawing.split('<').skip(1) {
        let tag = format!(" {}", t.split('>').next().unwrap_or(""));
        let w = num(&tag, "stroke-width");
        let headed = tag.contains("marker-end");
        if t.starts_with("line ") {
            let (a, b) = (
                [num(&tag, "x1"), num(&tag, "y1")],
                [num(&tag, "x2"), num(&tag, "y2")],
            );
            out.push(Piece(a, b, w / 2.0));
            if headed {
                head(a, b, w, &mut out);
            }
        } else if t.starts_with("polygon ") && attr(&tag, "stroke").as_deref() != Some("none") {
            let pts: Vec<P> = attr(&tag, "points")
                .unwrap()
                .split_whitespace()
                .map(pair)
                .collect();
            ring(&pts, w, &mut out);
        } else if t.starts_with("circle ") {
            let (c, r) = ([num(&tag, "cx"), num(&tag, "cy")], num(&tag, "r"));
            if attr(&tag, "stroke").is_some() {
                circle(c, r, w, &mut out);
            } else {
                circle(c, r / 2.0, r, &mut out); // a filled dot
            }
        } else if t.starts_with("path ") {
            path(&attr(&tag, "d").unwrap(), w, headed, &mut out);
        }
    }
    out
}

/// Whether the segment a–b passes through the box (Liang–Barsky).
fn crosses(bx: [f64; 4], a: P, b: P) -> bool {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d[0], a[0] - bx[0]),
        (d[0], bx[2] - a[0]),
        (-d[1], a[1] - bx[1]),
        (d[1], bx[3] - a[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    t0 <= t1
}

#[test]
fn no_label_box_meets_a_stroke_in_any_lesson_stage_or_plane() {
    let (mut figures, mut labelled) = (0, 0);
    let mut stages: Vec<Option<StageId>> = StageId::ALL.iter().copied().map(Some).collect();
    stages.push(None);
    common::each_contact_in_each_plane(|id, k, t, plane| {
        for stage in &stages {
            let svg = render_at(t, plane, *stage);
            let drawing = drawing(&svg);
            let pieces = strokes(drawing);
            assert!(!pieces.is_empty());
            for (b, text) in labels(drawing) {
                // Page coordinates are written to 0.1 px.
                for Piece(a, c, h) in &pieces {
                    let grown = [
                        b[0] - h + 0.2,
                        b[1] - h + 0.2,
                        b[2] + h - 0.2,
                        b[3] + h - 0.2,
                    ];
                    assert!(
                        !crosses(grown, *a, *c),
                        "{id} #{k} {plane:?} {stage:?}: «{text}» meets the stroke {a:?}–{c:?}"
                    );
                }
                labelled += 1;
            }
            figures += 1;
        }
    });
    assert!(
        figures > 1000 && labelled > 5 * figures,
        "{figures} {labelled}"
    );
}
