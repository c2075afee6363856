//! One pair's detection as an SVG figure, the lectures' picture: on the
//! left the two shapes (outlines in the view plane) with the contact normal
//! at the contact point; on the right the Minkowski difference A - B seen in
//! the same plane, the origin, GJK's last simplex (or EPA's closest face)
//! and the normal from the origin; or, at a chosen stop of GJK or EPA
//! ([`svg_at`]), that iteration's simplex or closest face, w_k, v_k and d_k.

use std::fmt::Write;

use super::legend::{diamond, legend, xml, Swatch};
use super::minkowski::{minkowski, Minkowski};
use super::steps::Stop;
use crate::render::figure::{outline, Silhouette, P};
use crate::trace::detect::{DetectTrace, PairTrace, V3};
use crate::trace::movement::Movement;

pub(crate) const W: f64 = 1000.0;
pub(crate) const H: f64 = 600.0;
pub(crate) const PANEL: f64 = 480.0;

/// The figure of pair `k` at the result (`None` when there is no such pair).
pub fn svg(t: &DetectTrace, k: usize) -> Option<String> {
    svg_at(t, k, usize::MAX)
}

/// The figure of pair `k` at `stop`, an index into the pair's
/// [`stops`](super::steps::stops) (GJK's iterations, then EPA's); past them,
/// the result (`None` when there is no such pair).
pub fn svg_at(t: &DetectTrace, k: usize, stop: usize) -> Option<String> {
    let p = t.pairs.get(k)?;
    let (u, w, _) = t.plane.axes();
    let flat = |x: &V3| -> P { [x[u], x[w]] };
    let mut out = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" font-family="sans-serif">
  <rect width="{W}" height="{H}" fill="white"/>
"#
    );
    // Left: the two shapes.
    let bodies: Vec<_> = t
        .drawn
        .iter()
        .filter(|d| d.name == p.a || d.name == p.b)
        .collect();
    let outlines: Vec<_> = bodies
        .iter()
        .filter_map(|d| {
            let o = outline(d.shape.as_ref()?, d.position, d.orientation, t.plane)?;
            Some((d.name.clone(), d.position, o))
        })
        .collect();
    let mut pts: Vec<P> = outlines
        .iter()
        .flat_map(|(_, _, o)| o.silhouette.points())
        .collect();
    let contact = p
        .contacts
        .first()
        .map(|c| (flat(&c.point), flat(&c.normal)));
    if let Some((q, _)) = contact {
        pts.push(q);
    }
    let moving = pair_movement(t, p);
    pts.extend(moving.iter().flat_map(|m| movement_extent(m, &flat)));
    let left = Fit::new(&pts, 20.0);
    movement_bounds(&mut out, &left, &moving, &flat);
    let mut left_legend = vec![];
    let _ = writeln!(
        out,
        r##"  <text x="20" y="30" font-size="18">{} and {} ({} plane)</text>"##,
        xml(&p.a),
        xml(&p.b),
        plane_name(t)
    );
    for (i, (name, at, o)) in outlines.iter().enumerate() {
        let colour = ["#1f77b4", "#d62728"][i.min(1)];
        match &o.silhouette {
            Silhouette::Polygon(poly) => {
                let _ = writeln!(
                    out,
                    r#"  <polygon points="{}" fill="{colour}" fill-opacity="0.12" stroke="none"/>"#,
                    left.points(poly)
                );
            }
            Silhouette::Circle { centre, radius } => {
                let c = left.at(*centre);
                let _ = writeln!(
                    out,
                    r#"  <circle cx="{:.1}" cy="{:.1}" r="{:.1}" fill="{colour}" fill-opacity="0.12"/>"#,
                    c[0],
                    c[1],
                    radius * left.scale
                );
            }
        }
        for e in &o.edges {
            let (a, b) = (left.at(e[0]), left.at(e[1]));
            let _ = writeln!(
                out,
                r#"  <line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{colour}" stroke-width="1.5"/>"#,
                a[0], a[1], b[0], b[1]
            );
        }
        let c = left.at(flat(at));
        let _ = writeln!(
            out,
            r#"  <text x="{:.1}" y="{:.1}" font-size="15" fill="{colour}" text-anchor="middle">{}</text>"#,
            c[0],
            c[1],
            xml(name)
        );
    }
    if let Some((q, n)) = contact {
        let size = 60.0 / left.scale;
        arrow(
            &mut out,
            &left,
            q,
            [q[0] + n[0] * size, q[1] + n[1] * size],
            "#2ca02c",
            "n",
        );
        left_legend.push((
            Swatch::Arrow("#2ca02c"),
            "n: the contact normal at the contact point (from B toward A)".to_string(),
        ));
    }
    if !moving.is_empty() {
        left_legend.extend(movement_legend());
    }
    legend(&mut out, 20.0, &left_legend);
    // Right: the Minkowski difference, the origin, the simplex, the normal
    // (the result's picture past the iterations), in view with the marks
    // of the stop.
    let m = minkowski(t.plane, p, stop);
    let right_pts: Vec<P> = if super::steps::stops(p).get(stop).is_some() {
        m.points()
    } else {
        m.hull.iter().copied().chain([[0.0, 0.0]]).collect()
    };
    let right = Fit::new(&right_pts, 20.0 + PANEL + 20.0);
    let _ = writeln!(
        out,
        r##"  <text x="{:.1}" y="30" font-size="18">A - B: {}</text>"##,
        40.0 + PANEL,
        result(p)
    );
    if !m.hull.is_empty() {
        let _ = writeln!(
            out,
            r##"  <polygon points="{}" fill="#9467bd" fill-opacity="0.15" stroke="#9467bd" stroke-width="2"/>"##,
            right.points(&m.hull)
        );
    }
    for [a, b] in m.edges() {
        let (a, b) = (right.at(a), right.at(b));
        let _ = writeln!(
            out,
            r##"  <line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="#ff7f0e" stroke-width="2"/>"##,
            a[0], a[1], b[0], b[1]
        );
    }
    for (i, a) in m.simplex.iter().enumerate() {
        let c = right.at(*a);
        // A point GJK dropped (✗) is hollow.
        let fill = if m.dropped.contains(&i) {
            r##"fill="white" stroke="#ff7f0e" stroke-width="2""##
        } else {
            r##"fill="#ff7f0e""##
        };
        let _ = writeln!(
            out,
            r#"  <circle cx="{:.1}" cy="{:.1}" r="4" {fill}/>"#,
            c[0], c[1]
        );
    }
    let o = right.at([0.0, 0.0]);
    // The result's arrow from O, on the page: its length and direction.
    let result = m.arrow.map(|(to, label)| {
        let b = right.at(to);
        let (dx, dy) = (b[0] - o[0], b[1] - o[1]);
        (to, label, dx.hypot(dy), [dx, dy])
    });
    // O's label sits up and to the right, or on the side away from the
    // result's arrow when there is one (its label is at its tip: a short
    // arrow's would land on O's).
    let at = match result {
        Some((_, _, len, [dx, dy])) if len > NEAR_O => {
            [o[0] - 16.0 * dx / len - 5.0, o[1] - 16.0 * dy / len + 5.0]
        }
        _ => [o[0] + 8.0, o[1] - 8.0],
    };
    let _ = writeln!(
        out,
        r#"  <circle cx="{:.1}" cy="{:.1}" r="5" fill="black"/>
  <text x="{:.1}" y="{:.1}" font-size="14">O</text>"#,
        o[0], o[1], at[0], at[1]
    );
    match result {
        Some((to, label, len, _)) if len > NEAR_O => {
            arrow(&mut out, &right, [0.0, 0.0], to, "#2ca02c", label);
        }
        Some((_, label, _, _)) => {
            // No arrow to draw (a depth or distance below a pixel): said
            // below O, not over it, as v_k is.
            let _ = writeln!(
                out,
                r##"  <text x="{:.1}" y="{:.1}" font-size="15" fill="#2ca02c">{} ≈ 0</text>"##,
                o[0] + 8.0,
                o[1] + 20.0,
                xml(label)
            );
        }
        None => {}
    }
    let stop = super::steps::stops(p).get(stop).copied();
    if let Some(stop) = stop {
        iteration(&mut out, &right, p, stop, &m);
    }
    legend(
        &mut out,
        40.0 + PANEL,
        &right_legend(p, stop, &m, plane_name(t)),
    );
    out += "</svg>\n";
    Some(out)
}

/// The pair's movement bounds (continuous detection on; none when off).
fn pair_movement(t: &DetectTrace, p: &PairTrace) -> Vec<Movement> {
    t.drawn
        .iter()
        .zip(&t.movement)
        .filter(|(d, _)| d.name == p.a || d.name == p.b)
        .filter_map(|(_, m)| *m)
        .collect()
}

/// The points a body's movement bounds reach in the view plane.
pub(crate) fn movement_extent(m: &Movement, flat: &impl Fn(&V3) -> P) -> Vec<P> {
    let (lo, hi, c) = (flat(&m.aabb[0]), flat(&m.aabb[1]), flat(&m.centre));
    vec![
        lo,
        hi,
        [c[0] - m.radius, c[1] - m.radius],
        [c[0] + m.radius, c[1] + m.radius],
    ]
}

/// The legend lines of [`movement_bounds`]' marks (the detect and the
/// time-of-collision figures).
pub(crate) fn movement_legend() -> [(Swatch, String); 2] {
    [
        (
            Swatch::Line("#7f7f7f", "8 4"),
            "the box each body sweeps over the next step (ccd)".to_string(),
        ),
        (
            Swatch::Line("#7f7f7f", "2 4"),
            "the sphere each body sweeps over the next step (ccd)".to_string(),
        ),
    ]
}

/// Each moving body's movement bounds over the next step, under the
/// shapes: its swept AABB dashed, its swept sphere dotted, and a legend.
pub(crate) fn movement_bounds(
    out: &mut String,
    f: &Fit,
    moving: &[Movement],
    flat: &impl Fn(&V3) -> P,
) {
    if moving.is_empty() {
        return;
    }
    for m in moving {
        let (a, b) = (f.at(flat(&m.aabb[0])), f.at(flat(&m.aabb[1])));
        let _ = writeln!(
            out,
            r##"  <rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="#7f7f7f" stroke-width="1.5" stroke-dasharray="8 4"/>"##,
            a[0].min(b[0]),
            a[1].min(b[1]),
            (b[0] - a[0]).abs(),
            (b[1] - a[1]).abs()
        );
        let c = f.at(flat(&m.centre));
        let _ = writeln!(
            out,
            r##"  <circle cx="{:.1}" cy="{:.1}" r="{:.1}" fill="none" stroke="#7f7f7f" stroke-width="1.5" stroke-dasharray="2 4"/>"##,
            c[0],
            c[1],
            m.radius * f.scale
        );
    }
}

/// A stop's marks: its title, d_k from the origin, v_k, w_k.
fn iteration(out: &mut String, f: &Fit, p: &PairTrace, stop: Stop, m: &Minkowski) {
    let title = match (stop, &p.gjk, &p.epa) {
        (Stop::Gjk(k), Some(g), _) => format!(
            "GJK iteration {} of {}: simplex (hollow: dropped), v_k, w_k, d_k",
            k + 1,
            g.iterations.len()
        ),
        (Stop::Epa(k), _, Some(e)) => format!(
            "EPA iteration {} of {}: closest face, v_k = δ_k n_k, w_k, d_k = n_k",
            k + 1,
            e.iterations.len()
        ),
        _ => return,
    };
    let _ = writeln!(
        out,
        r#"  <text x="{:.1}" y="50" font-size="14">{}</text>"#,
        f.left + 20.0,
        xml(&title)
    );
    if let Some(tip) = m.direction {
        arrow(out, f, [0.0, 0.0], tip, "#17becf", "d_k");
    }
    if let Some(v) = m.closest {
        let (o, tip) = (f.at([0.0, 0.0]), f.at(v));
        if (tip[0] - o[0]).hypot(tip[1] - o[1]) > 8.0 {
            arrow(out, f, [0.0, 0.0], v, "#2ca02c", "v_k");
        } else {
            // v_k at the origin (in this plane): said below O, not over it.
            let _ = writeln!(
                out,
                r##"  <text x="{:.1}" y="{:.1}" font-size="15" fill="#2ca02c">v_k ≈ 0</text>"##,
                o[0] + 8.0,
                o[1] + 20.0
            );
        }
    }
    if let Some(next) = m.next {
        let c = f.at(next);
        let _ = writeln!(out, "{}", diamond(c[0], c[1], "#2ca02c"));
    }
    if let Some(w) = m.support {
        let c = f.at(w);
        let _ = writeln!(
            out,
            r##"  <rect x="{:.1}" y="{:.1}" width="10" height="10" fill="#8c564b"/>
  <text x="{:.1}" y="{:.1}" font-size="15" fill="#8c564b">w_k</text>"##,
            c[0] - 5.0,
            c[1] - 5.0,
            c[0] + 8.0,
            c[1] + 16.0
        );
    }
}

/// The right panel's legend: every mark it draws at `stop` (the result
/// when `None`), arrows included.
fn right_legend(
    p: &PairTrace,
    stop: Option<Stop>,
    m: &Minkowski,
    plane: &str,
) -> Vec<(Swatch, String)> {
    let mut out = vec![];
    if !m.hull.is_empty() {
        out.push((
            Swatch::Line("#9467bd", ""),
            format!("A - B seen in the {plane} plane (its outline); O: the origin"),
        ));
    }
    let s = |t: &str| t.to_string();
    match stop {
        Some(Stop::Node(_) | Stop::Triangle(_)) => {}
        Some(Stop::Gjk(_)) => {
            out.push((
                Swatch::Dot("#ff7f0e", true),
                s("the simplex with w_k added (hollow: dropped)"),
            ));
            out.push((
                Swatch::Square("#8c564b"),
                s("w_k = s_A(d_k) - s_B(-d_k), the support point"),
            ));
            out.push((
                Swatch::Arrow("#2ca02c"),
                s("v_k: the closest point the iteration starts from"),
            ));
            out.push((
                Swatch::Arrow("#17becf"),
                s("d_k = -v_k: the search direction (its length is not to scale)"),
            ));
            if m.next.is_some() {
                out.push((
                    Swatch::Diamond("#2ca02c"),
                    s("v_k+1: the kept simplex's closest point (the next v_k)"),
                ));
            }
        }
        Some(Stop::Epa(_)) => {
            out.push((
                Swatch::Dot("#ff7f0e", false),
                s("the polytope's face closest to the origin"),
            ));
            out.push((
                Swatch::Square("#8c564b"),
                s("w_k: the support point along n_k"),
            ));
            out.push((
                Swatch::Arrow("#2ca02c"),
                s("v_k = δ_k n_k: the face's point closest to O"),
            ));
            out.push((
                Swatch::Arrow("#17becf"),
                s("d_k = n_k: the face's outward normal (length not to scale)"),
            ));
        }
        None => {
            if !m.simplex.is_empty() {
                let what = match &p.epa {
                    Some(e) if !e.iterations.is_empty() => "EPA's last closest face",
                    _ => "GJK's last simplex",
                };
                out.push((Swatch::Dot("#ff7f0e", false), s(what)));
            }
            match m.arrow {
                Some((_, "-δn")) => out.push((
                    Swatch::Arrow("#2ca02c"),
                    s("-δn: the penetration vector (depth δ along the normal n)"),
                )),
                Some(_) => out.push((
                    Swatch::Arrow("#2ca02c"),
                    s("v: from O to A - B's closest point (its length: the distance)"),
                )),
                None => {}
            }
        }
    }
    out
}

fn result(p: &PairTrace) -> String {
    match (&p.gjk, &p.epa) {
        (Some(g), _) if g.result == "separated" => {
            format!("separated, {} GJK iterations", g.iterations.len())
        }
        (Some(g), Some(e)) => format!(
            "intersecting, {} GJK + {} EPA iterations",
            g.iterations.len(),
            e.iterations.len()
        ),
        _ => "no support mapping (a half-space)".into(),
    }
}

fn plane_name(t: &DetectTrace) -> &'static str {
    match t.plane.axes().0 {
        0 => "xy",
        1 => "yz",
        _ => "zx",
    }
}

pub(crate) fn arrow(out: &mut String, f: &Fit, from: P, to: P, colour: &str, label: &str) {
    let (a, b) = (f.at(from), f.at(to));
    let _ = writeln!(
        out,
        r#"  <line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{colour}" stroke-width="3"/>"#,
        a[0], a[1], b[0], b[1]
    );
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len = dx.hypot(dy);
    if len > 1e-9 {
        let (ux, uy) = (dx / len, dy / len);
        let base = [b[0] - 12.0 * ux, b[1] - 12.0 * uy];
        let _ = writeln!(
            out,
            r#"  <polygon points="{:.1},{:.1} {:.1},{:.1} {:.1},{:.1}" fill="{colour}"/>"#,
            b[0],
            b[1],
            base[0] - 5.0 * uy,
            base[1] + 5.0 * ux,
            base[0] + 5.0 * uy,
            base[1] - 5.0 * ux
        );
    }
    let _ = writeln!(
        out,
        r#"  <text x="{:.1}" y="{:.1}" font-size="15" fill="{colour}">{}</text>"#,
        b[0] + 6.0,
        b[1] - 6.0,
        xml(label)
    );
}

/// The result's arrow from O shorter than this (page units, a pixel) has
/// no direction to draw: its value is said below O instead.
const NEAR_O: f64 = 1.0;

/// A panel's mapping from the view plane to the page (y up).
pub(crate) struct Fit {
    pub(crate) scale: f64,
    lo: P,
    hi: P,
    pub(crate) left: f64,
}

impl Fit {
    pub(crate) fn new(pts: &[P], left: f64) -> Fit {
        let finite = pts.iter().filter(|p| p[0].is_finite() && p[1].is_finite());
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in finite {
            lo = [lo[0].min(p[0]), lo[1].min(p[1])];
            hi = [hi[0].max(p[0]), hi[1].max(p[1])];
        }
        if !lo[0].is_finite() {
            (lo, hi) = ([-1.0, -1.0], [1.0, 1.0]);
        }
        let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-9);
        Fit {
            scale: 0.85 * PANEL / span,
            lo,
            hi,
            left,
        }
    }

    pub(crate) fn at(&self, p: P) -> P {
        let cx = (self.lo[0] + self.hi[0]) / 2.0;
        let cy = (self.lo[1] + self.hi[1]) / 2.0;
        [
            self.left + PANEL / 2.0 + (p[0] - cx) * self.scale,
            50.0 + PANEL / 2.0 - 20.0 - (p[1] - cy) * self.scale,
        ]
    }

    pub(crate) fn points(&self, poly: &[P]) -> String {
        poly.iter()
            .map(|p| {
                let q = self.at(*p);
                format!("{:.1},{:.1}", q[0], q[1])
            })
            .collect::<Vec<_>>()
            .join(" ")
    }
}
