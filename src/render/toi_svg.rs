//! `detect --toi --figure F.svg`: one pair's time-of-collision search as a
//! picture, drawn as `detect --figure` draws a pair (the same outlines,
//! movement bounds and page layout): on the left the two bodies at the
//! step's start with their movement bounds over the step (swept AABB
//! dashed, swept sphere dotted), on the right the two bodies at the time of
//! collision found, at the same scale. A half-space is its plane's trace.

use std::fmt::Write;

use super::detect::legend::{legend, xml};
use super::detect::svg::{movement_bounds, movement_extent, movement_legend, Fit, H, PANEL, W};
use crate::format::Fmt;
use crate::physics::Shape;
use crate::render::figure::{outline, Outline, Silhouette, P};
use crate::trace::toi::{end_text, PictureBody, ToiPicture};
use crate::trace::Plane;

const COLOURS: [&str; 2] = ["#1f77b4", "#d62728"];

/// The figure of `p` in `plane`.
pub fn svg(p: &ToiPicture, plane: Plane) -> String {
    let (u, w, _) = plane.axes();
    let flat = |x: &[f64; 3]| -> P { [x[u], x[w]] };
    let f = Fmt::new(4);
    let at = |b: &PictureBody, pose: ([f64; 3], [f64; 4])| {
        b.shape
            .as_ref()
            .and_then(|s| outline(s, pose.0, pose.1, plane))
    };
    let start: Vec<Option<Outline>> = p.bodies.iter().map(|b| at(b, b.start)).collect();
    let found: Vec<Option<Outline>> = p
        .bodies
        .iter()
        .map(|b| b.found.and_then(|pose| at(b, pose)))
        .collect();
    let moving: Vec<_> = p.bodies.iter().filter_map(|b| b.movement).collect();
    // One scale for both panels: every outline and bound, and the bodies'
    // positions (a half-space's point among them).
    let mut pts: Vec<P> = start
        .iter()
        .chain(&found)
        .flatten()
        .flat_map(|o| o.silhouette.points())
        .collect();
    pts.extend(moving.iter().flat_map(|m| movement_extent(m, &flat)));
    pts.extend(
        p.bodies
            .iter()
            .filter(|b| !matches!(b.shape, Some(Shape::HalfSpace { .. })))
            .map(|b| flat(&b.start.0)),
    );
    let left = Fit::new(&pts, 20.0);
    let right = Fit::new(&pts, 20.0 + PANEL + 20.0);
    let mut out = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" font-family="sans-serif">
  <rect width="{W}" height="{H}" fill="white"/>
"#
    );
    let _ = writeln!(
        out,
        r##"  <text x="20" y="30" font-size="18">{} and {}: t = 0 (step {} starts)</text>"##,
        xml(&p.bodies[0].name),
        xml(&p.bodies[1].name),
        p.step
    );
    let title = match p.time {
        Some(t) => format!(
            "t = {} s: time of collision ({})",
            f.num(t),
            crate::knobs::toi_method_name(p.method)
        ),
        None => format!("no time of collision: {}", end_text(p.end)),
    };
    let _ = writeln!(
        out,
        r##"  <text x="{:.1}" y="30" font-size="18">{}</text>"##,
        40.0 + PANEL,
        xml(&title)
    );
    // Each panel clips what reaches past it (a half-space's plane).
    let _ = writeln!(out, "  <defs>");
    for (id, fit) in [("left", &left), ("right", &right)] {
        let _ = writeln!(
            out,
            r#"    <clipPath id="{id}"><rect x="{:.1}" y="40" width="{PANEL}" height="{:.1}"/></clipPath>"#,
            fit.left,
            H - 60.0
        );
    }
    let _ = writeln!(out, "  </defs>");
    movement_bounds(&mut out, &left, &moving, &flat);
    movement_bounds(&mut out, &right, &moving, &flat);
    if !moving.is_empty() {
        legend(&mut out, 20.0, &movement_legend());
    }
    for (k, b) in p.bodies.iter().enumerate() {
        let colour = COLOURS[k];
        let start_pose = start[k].as_ref();
        draw(
            &mut out,
            &left,
            b,
            start_pose,
            b.start.0,
            (colour, "left"),
            &flat,
        );
        if let Some(pose) = b.found {
            let o = found[k].as_ref();
            draw(&mut out, &right, b, o, pose.0, (colour, "right"), &flat);
        }
    }
    out += "</svg>\n";
    out
}

/// One body in a panel: its outline (or a half-space's plane) and its name.
fn draw(
    out: &mut String,
    fit: &Fit,
    b: &PictureBody,
    o: Option<&Outline>,
    position: [f64; 3],
    (colour, clip): (&str, &str),
    flat: &impl Fn(&[f64; 3]) -> P,
) {
    if let Some(Shape::HalfSpace { normal }) = b.shape {
        // The plane's trace across the panel, the solid side shaded.
        let (q, n) = (flat(&position), flat(&normal));
        let len = n[0].hypot(n[1]);
        if len < 1e-12 {
            return; // The plane is the view plane: no trace.
        }
        let (n, d) = ([n[0] / len, n[1] / len], [-n[1] / len, n[0] / len]);
        let far = 2.0 * PANEL / fit.scale;
        let a = [q[0] - d[0] * far, q[1] - d[1] * far];
        let z = [q[0] + d[0] * far, q[1] + d[1] * far];
        let below = |x: P| [x[0] - n[0] * far, x[1] - n[1] * far];
        let _ = writeln!(
            out,
            r#"  <polygon points="{}" fill="{colour}" fill-opacity="0.08" stroke="none" clip-path="url(#{clip})"/>
  <line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{colour}" stroke-width="1.5" clip-path="url(#{clip})"/>"#,
            fit.points(&[a, z, below(z), below(a)]),
            fit.at(a)[0],
            fit.at(a)[1],
            fit.at(z)[0],
            fit.at(z)[1],
        );
        return;
    }
    let Some(o) = o else {
        return;
    };
    match &o.silhouette {
        Silhouette::Polygon(poly) => {
            let _ = writeln!(
                out,
                r#"  <polygon points="{}" fill="{colour}" fill-opacity="0.12" stroke="none"/>"#,
                fit.points(poly)
            );
        }
        Silhouette::Circle { centre, radius } => {
            let c = fit.at(*centre);
            let _ = writeln!(
                out,
                r#"  <circle cx="{:.1}" cy="{:.1}" r="{:.1}" fill="{colour}" fill-opacity="0.12"/>"#,
                c[0],
                c[1],
                radius * fit.scale
            );
        }
    }
    for e in &o.edges {
        let (a, z) = (fit.at(e[0]), fit.at(e[1]));
        let _ = writeln!(
            out,
            r#"  <line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{colour}" stroke-width="1.5"/>"#,
            a[0], a[1], z[0], z[1]
        );
    }
    let c = fit.at(flat(&position));
    let _ = writeln!(
        out,
        r#"  <text x="{:.1}" y="{:.1}" font-size="15" fill="{colour}" text-anchor="middle">{}</text>"#,
        c[0],
        c[1],
        xml(&b.name)
    );
}
