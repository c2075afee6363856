//! The figure model drawn in LaTeX's own `picture` environment, so a worked
//! solution or an exercise sheet carries its figure and `pdflatex` needs
//! nothing beyond `texlive-latex-base` (no image file, no TikZ, no pict2e):
//! every line is a `\qbezier` with its control point at the middle, which
//! draws a straight line of any slope; dashes are drawn piece by piece.

use std::fmt::Write;

use crate::physics::StageId;
use crate::render::figure::{flat, ArrowKind, Figure, Silhouette, P};
use crate::render::tex::to_latex;
use crate::trace::{Plane, SceneView};

/// Width of the drawing in pt; the height follows (at most `MAX_HEIGHT`).
const WIDTH: f64 = 300.0;
const MAX_HEIGHT: f64 = 190.0;

struct Canvas {
    out: String,
    lo: P,
    scale: f64,
}

impl Canvas {
    fn at(&self, p: P) -> P {
        [
            (p[0] - self.lo[0]) * self.scale,
            (p[1] - self.lo[1]) * self.scale,
        ]
    }

    fn line(&mut self, a: P, b: P) {
        let (a, b) = (self.at(a), self.at(b));
        // A line shorter than the printed precision would be \qbezier of
        // one point, which overflows LaTeX's arithmetic.
        if (b[0] - a[0]).hypot(b[1] - a[1]) < 0.2 || !(a[0] + a[1] + b[0] + b[1]).is_finite() {
            return;
        }
        let m = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
        let _ = writeln!(
            self.out,
            "\\qbezier({:.1},{:.1})({:.1},{:.1})({:.1},{:.1})",
            a[0], a[1], m[0], m[1], b[0], b[1]
        );
    }

    /// A dashed line: 4 pt dashes, 3 pt gaps.
    fn dashed(&mut self, a: P, b: P) {
        let (pa, pb) = (self.at(a), self.at(b));
        let len = ((pb[0] - pa[0]).powi(2) + (pb[1] - pa[1]).powi(2)).sqrt();
        if len < 1e-9 {
            return;
        }
        let n = (len / 7.0).ceil().max(1.0) as usize;
        for i in 0..n {
            let t0 = i as f64 / n as f64;
            let t1 = t0 + (4.0 / 7.0) / n as f64;
            let p = |t: f64| [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
            self.line(p(t0), p(t1.min(1.0)));
        }
    }

    /// A head at `to` pointing away from `from`.
    fn head(&mut self, from: P, to: P) {
        let (f, t) = (self.at(from), self.at(to));
        let (dx, dy) = (t[0] - f[0], t[1] - f[1]);
        let len = (dx * dx + dy * dy).sqrt();
        if len < 1e-9 {
            return;
        }
        let (ux, uy) = (dx / len, dy / len);
        for side in [1.0f64, -1.0] {
            let (c, s) = (0.93f64, 0.36 * side);
            let back = [
                t[0] - 6.0 * (ux * c - uy * s),
                t[1] - 6.0 * (uy * c + ux * s),
            ];
            let _ = writeln!(
                self.out,
                "\\qbezier({:.1},{:.1})({:.1},{:.1})({:.1},{:.1})",
                t[0],
                t[1],
                (t[0] + back[0]) / 2.0,
                (t[1] + back[1]) / 2.0,
                back[0],
                back[1]
            );
        }
    }

    fn label(&mut self, at: P, text: &str) {
        let p = self.at(at);
        let _ = writeln!(
            self.out,
            "\\put({:.1},{:.1}){{\\makebox(0,0)[bl]{{\\scriptsize ${}$}}}}",
            p[0] + 2.0,
            p[1] + 2.0,
            to_latex(text)
        );
    }

    fn polygon(&mut self, points: &[P], dashed: bool) {
        for i in 0..points.len() {
            let (a, b) = (points[i], points[(i + 1) % points.len()]);
            if dashed {
                self.dashed(a, b);
            } else {
                self.line(a, b);
            }
        }
    }
}

/// A point of a fixed surface's section: `u` along it from where it meets
/// the view plane, `v` toward its solid side.
fn along(s: &crate::render::figure::Section, u: f64, v: f64) -> P {
    let (q, t, d) = (s.at, s.along, s.solid_side);
    [q[0] + u * t[0] + v * d[0], q[1] + u * t[1] + v * d[1]]
}

/// The key under the picture, naming only what is drawn: a set-up figure
/// has no velocity after, no impulse and no outline after the projection.
fn caption(kinds: &[ArrowKind], outline_after: bool, surface: bool) -> String {
    let has = |k: ArrowKind| kinds.contains(&k);
    let mut dashed = vec![];
    if has(ArrowKind::Arm) {
        dashed.push("arms $r$");
    }
    if has(ArrowKind::Velocity) {
        dashed.push("velocities before $v$");
    }
    if outline_after {
        dashed.push("each body's outline after the projection");
    }
    let mut solid = vec![];
    if has(ArrowKind::VelocityAfter) {
        solid.push("velocities after $v'$");
    }
    if has(ArrowKind::Normal) {
        solid.push("the normal $\\hat{d}$");
    }
    if has(ArrowKind::Impulse) {
        solid.push("the impulse $g$ on body 1");
    }
    let list = |items: &[&str]| match items {
        [] => String::new(),
        [one] => one.to_string(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    };
    let mut parts = vec![];
    if !dashed.is_empty() {
        parts.push(format!("Dashed: {}", list(&dashed)));
    }
    if !solid.is_empty() {
        parts.push(format!("solid: {}", list(&solid)));
    }
    if surface {
        parts.push("ticks: the solid side of a fixed surface".to_string());
    }
    let scales = match (
        has(ArrowKind::Velocity) || has(ArrowKind::VelocityAfter),
        has(ArrowKind::Impulse),
    ) {
        (true, true) => "velocities and the impulse to scales of their own; ",
        (true, false) => "velocities to a scale of their own; ",
        _ => "",
    };
    let mut text = parts.join("; ");
    if let Some(first) = text.get(..1) {
        text = first.to_uppercase() + &text[1..];
    }
    format!("{text} ({scales}the xy plane).")
}

/// The outline to draw: a polygon's corners, a circle's 24 rim points.
fn ring(s: &Silhouette) -> Vec<P> {
    match s {
        Silhouette::Polygon(p) => p.clone(),
        Silhouette::Circle { centre, radius } => (0..24)
            .map(|i| {
                let a = std::f64::consts::TAU * f64::from(i) / 24.0;
                [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
            })
            .collect(),
    }
}

/// The figure of a contact (xy plane) as `stage` sees it (every mark when
/// `None`), in a `picture` environment with a one-line key under it; `None`
/// when there is nothing to draw.
pub fn picture(scene: &SceneView, stage: Option<StageId>) -> Option<String> {
    let whole = Figure::of_contact(scene, Plane::Xy);
    let fig = match stage {
        Some(s) => whole.at_stage(s),
        None => whole,
    };
    let reach = fig.scene_length;
    let v_scale = if fig.top_speed > 0.0 {
        0.9 * reach / fig.top_speed
    } else {
        0.0
    };
    // Arrows as (from, to, dashed, head) in view coordinates.
    let mut arrows = Vec::new();
    for a in &fig.arrows {
        let (from, to, dashed) = match a.kind {
            ArrowKind::Arm => (a.at, a.tip(1.0), true),
            ArrowKind::Normal => (a.at, a.tip(0.45 * reach), false),
            ArrowKind::Impulse => {
                let size = a.contact.map_or(0.0, |k| fig.contacts[k].impulse_size);
                let g = if size > 0.0 { 0.8 * reach / size } else { 0.0 };
                (a.tip(-g), a.at, false)
            }
            ArrowKind::Reaction => continue,
            ArrowKind::Velocity => (a.at, a.tip(v_scale), true),
            ArrowKind::VelocityAfter => (a.at, a.tip(v_scale), false),
        };
        let (from, to) = (flat(from), flat(to));
        // A zero velocity is no arrow (and its label would sit on p).
        if (to[0] - from[0]).hypot(to[1] - from[1]) <= 1e-9 * reach {
            continue;
        }
        arrows.push((from, to, dashed, a.kind, a.label.clone()));
    }
    let mut points: Vec<P> = arrows.iter().flat_map(|a| [a.0, a.1]).collect();
    // A fixed surface a scene length each way of where it meets the view
    // plane, its ticks on the solid side: inside the picture, never over
    // the caption under it.
    for s in fig.surfaces.iter().filter_map(|s| s.section.as_ref()) {
        for (u, v) in [(-1.12, 0.12), (1.0, 0.0), (-1.0, 0.0), (0.88, 0.12)] {
            points.push(along(s, u * reach, v * reach));
        }
    }
    let mut shapes: Vec<(Vec<P>, bool)> = Vec::new();
    for b in &fig.bodies {
        points.push(flat(b.centre));
        if let Some(o) = &b.outline {
            shapes.push((ring(&o.silhouette), false));
        }
        if let Some(o) = b.outline_after.as_ref().filter(|_| !fig.beyond(b)) {
            shapes.push((ring(&o.silhouette), true));
        }
    }
    for (s, _) in &shapes {
        points.extend(s.iter().copied());
    }
    for c in &fig.contacts {
        points.push(flat(c.point));
    }
    let finite: Vec<P> = points
        .into_iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .collect();
    if finite.is_empty() {
        return None;
    }
    let lo = [
        finite.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min),
        finite.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min),
    ];
    let hi = [
        finite
            .iter()
            .map(|p| p[0])
            .fold(f64::NEG_INFINITY, f64::max),
        finite
            .iter()
            .map(|p| p[1])
            .fold(f64::NEG_INFINITY, f64::max),
    ];
    let span = [(hi[0] - lo[0]).max(1e-12), (hi[1] - lo[1]).max(1e-12)];
    let scale = (WIDTH / span[0]).min(MAX_HEIGHT / span[1]);
    let size = [span[0] * scale, span[1] * scale];
    let mut c = Canvas {
        out: String::new(),
        lo,
        scale,
    };
    let _ = writeln!(
        c.out,
        "\\begin{{center}}\n\\setlength{{\\unitlength}}{{1pt}}\n\\begin{{picture}}({:.1},{:.1})",
        size[0] + 20.0,
        size[1] + 12.0
    );
    for (s, dashed) in &shapes {
        c.polygon(s, *dashed);
    }
    // The world's surface (and any half-space) where it meets the view
    // plane, a scene length each way, with ticks on the solid side; none
    // when it faces the viewer.
    for s in fig.surfaces.iter().filter_map(|s| s.section.as_ref()) {
        let at = |u: f64, v: f64| along(s, u, v);
        c.line(at(-reach, 0.0), at(reach, 0.0));
        for i in -4..=4 {
            let u = 0.25 * reach * f64::from(i);
            c.line(at(u, 0.0), at(u - 0.12 * reach, 0.12 * reach));
        }
    }
    for (from, to, dashed, kind, label) in &arrows {
        let head = *kind != ArrowKind::Arm;
        if *dashed {
            c.dashed(*from, *to);
        } else {
            c.line(*from, *to);
        }
        if head {
            c.head(*from, *to);
        }
        // As the SVG does: an arm's label at its middle, the impulse's at
        // its tail (its tip is q, which has a label of its own).
        let at = if !head {
            [(from[0] + to[0]) / 2.0, (from[1] + to[1]) / 2.0]
        } else if label.starts_with('g') {
            *from
        } else {
            *to
        };
        c.label(at, label);
    }
    for p in &fig.points {
        c.label(flat(p.at), &p.label);
    }
    c.out.push_str("\\end{picture}\n\n");
    let kinds: Vec<ArrowKind> = arrows.iter().map(|a| a.3).collect();
    let outline_after = shapes.iter().any(|(_, dashed)| *dashed);
    let surface = fig.surfaces.iter().any(|s| s.section.is_some());
    c.out.push_str("{\\footnotesize ");
    c.out.push_str(&caption(&kinds, outline_after, surface));
    if let Some(note) = &fig.corrected {
        c.out.push(' ');
        c.out.push_str(&crate::render::tex::prose(note));
    }
    c.out.push_str("}\n\\end{center}\n");
    Some(c.out)
}
