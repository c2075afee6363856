//! One pair's detection as an SVG figure, the lectures' picture: on the
//! left the two shapes (outlines in the view plane) with the contact normal
//! at the contact point; on the right the Minkowski difference A - B seen in
//! the same plane, the origin, GJK's last simplex (or EPA's closest face)
//! and the normal from the origin, or a chosen iteration ([`Shown`]).

use std::fmt::Write;

use crate::render::figure::{outline, Silhouette, P};
use crate::trace::detect::{DetectTrace, PairTrace, V3};

const W: f64 = 1000.0;
const H: f64 = 520.0;
const PANEL: f64 = 480.0;

mod iteration;
pub use iteration::Shown;

/// The figure of pair `k` at its last iteration (`None` when there is no
/// such pair).
pub fn svg(t: &DetectTrace, k: usize) -> Option<String> {
    svg_at(t, k, Shown::Last)
}

/// The figure of pair `k` drawing the iteration `shown` (`None` when there
/// is no such pair or iteration).
pub fn svg_at(t: &DetectTrace, k: usize, shown: Shown) -> Option<String> {
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
    let left = Fit::new(&pts, 20.0);
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
            "d",
        );
    }
    // Right: the Minkowski difference, the origin, the simplex, the normal.
    let mut right_pts: Vec<P> = p.minkowski.iter().map(flat).chain([[0.0, 0.0]]).collect();
    // The chosen iteration's marks are in view too.
    let d_length = iteration::d_length(&right_pts);
    right_pts.extend(iteration::reach(p, shown, &flat, d_length));
    let right = Fit::new(&right_pts, 20.0 + PANEL + 20.0);
    let _ = writeln!(
        out,
        r##"  <text x="{:.1}" y="30" font-size="18">A - B: {}</text>"##,
        40.0 + PANEL,
        result(p)
    );
    if !p.minkowski.is_empty() {
        let hull = crate::render::figure::hull(p.minkowski.iter().map(flat).collect());
        let _ = writeln!(
            out,
            r##"  <polygon points="{}" fill="#9467bd" fill-opacity="0.15" stroke="#9467bd" stroke-width="2"/>"##,
            right.points(&hull)
        );
    }
    iteration::draw(&mut out, &right, p, shown, &flat, d_length)?;
    out += "</svg>\n";
    Some(out)
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

fn arrow(out: &mut String, f: &Fit, from: P, to: P, colour: &str, label: &str) {
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

/// A panel's mapping from the view plane to the page (y up).
struct Fit {
    scale: f64,
    lo: P,
    hi: P,
    left: f64,
}

impl Fit {
    fn new(pts: &[P], left: f64) -> Fit {
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

    fn at(&self, p: P) -> P {
        let cx = (self.lo[0] + self.hi[0]) / 2.0;
        let cy = (self.lo[1] + self.hi[1]) / 2.0;
        [
            self.left + PANEL / 2.0 + (p[0] - cx) * self.scale,
            50.0 + PANEL / 2.0 - 20.0 - (p[1] - cy) * self.scale,
        ]
    }

    fn points(&self, poly: &[P]) -> String {
        poly.iter()
            .map(|p| {
                let q = self.at(*p);
                format!("{:.1},{:.1}", q[0], q[1])
            })
            .collect::<Vec<_>>()
            .join(" ")
    }
}

fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
