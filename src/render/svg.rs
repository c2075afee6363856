//! A figure of one contact as SVG, written by hand: the bodies (and where
//! projection moves them), the contact point, the normal, the arms, the
//! velocities before and after, the spin, the impulse, labels and a legend.
//! 1280 × 720, for a slide. Everything drawn comes from the trace's scene.

pub mod geom;

use std::fmt::Write;

pub use geom::Plane;
use geom::{outline, size, surface_distance, Outline};

use crate::format::Fmt;
use crate::trace::{BodyView, ShapeView, Trace};

const WIDTH: f64 = 1280.0;
const HEIGHT: f64 = 720.0;
/// The drawing area (left, top, right, bottom); the legend is to its right.
const AREA: (f64, f64, f64, f64) = (24.0, 96.0, 880.0, 700.0);
const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";

const INK: &str = "#222222";
const BEFORE: &str = "#0072B2";
const AFTER: &str = "#009E73";
const IMPULSE: &str = "#D55E00";
const NORMAL: &str = "#CC79A7";
const ARM: &str = "#6E6E6E";
const MOVED: &str = "#E69F00";
const FILL: [&str; 3] = ["#EEEEEE", "#DCE9F5", "#F5E6CC"];

/// Maps view-plane coordinates to the page.
struct View {
    scale: f64,
    centre: (f64, f64),
}

impl View {
    fn fit(points: &[(f64, f64)]) -> View {
        let (mut lo, mut hi) = (
            (f64::INFINITY, f64::INFINITY),
            (f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for p in points.iter().filter(|p| p.0.is_finite() && p.1.is_finite()) {
            lo = (lo.0.min(p.0), lo.1.min(p.1));
            hi = (hi.0.max(p.0), hi.1.max(p.1));
        }
        if !lo.0.is_finite() {
            (lo, hi) = ((-1.0, -1.0), (1.0, 1.0));
        }
        let span = ((hi.0 - lo.0).max(1e-9), (hi.1 - lo.1).max(1e-9));
        let (w, h) = (AREA.2 - AREA.0, AREA.3 - AREA.1);
        let scale = (0.86 * w / span.0).min(0.86 * h / span.1);
        View {
            scale,
            centre: ((lo.0 + hi.0) / 2.0, (lo.1 + hi.1) / 2.0),
        }
    }

    fn page(&self, p: (f64, f64)) -> (f64, f64) {
        (
            (AREA.0 + AREA.2) / 2.0 + (p.0 - self.centre.0) * self.scale,
            (AREA.1 + AREA.3) / 2.0 - (p.1 - self.centre.1) * self.scale,
        )
    }
}

/// A page coordinate: one decimal, never `-0.0`.
fn c(x: f64) -> String {
    let s = format!("{x:.1}");
    if s == "-0.0" {
        "0.0".into()
    } else {
        s
    }
}

fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn sub(n: usize) -> &'static str {
    ["", "₁", "₂"][n.min(2)]
}

fn scaled(p: [f64; 3], v: [f64; 3], k: f64) -> [f64; 3] {
    [p[0] + k * v[0], p[1] + k * v[1], p[2] + k * v[2]]
}

fn norm(v: [f64; 3]) -> f64 {
    crate::physics::scale::stable_norm_of(&v)
}

/// Where an arrow's label goes.
#[derive(Clone, Copy, PartialEq)]
enum Label {
    /// Beyond the head.
    Tip,
    /// Before the tail (for an arrow that ends on the contact point).
    Tail,
    /// Beside the middle.
    Middle,
}

/// An arrow from `a` to `b` (world), or a ⊙ / ⊗ when it points along the view axis.
struct Arrow {
    from: [f64; 3],
    to: [f64; 3],
    colour: &'static str,
    width: f64,
    dashed: bool,
    label: String,
    at: Label,
    head: bool,
}

struct Figure<'a> {
    trace: &'a Trace,
    plane: Plane,
    fmt: Fmt,
    out: String,
}

impl Figure<'_> {
    fn text(&mut self, at: (f64, f64), size: f64, anchor: &str, weight: &str, fill: &str, s: &str) {
        let _ = writeln!(
            self.out,
            r#"  <text x="{}" y="{}" font-size="{size}" text-anchor="{anchor}" font-weight="{weight}" fill="{fill}" stroke="white" stroke-width="4" stroke-linejoin="round" paint-order="stroke">{}</text>"#,
            c(at.0),
            c(at.1),
            xml(s)
        );
    }

    fn shape(&mut self, view: &View, o: &Outline, fill: &str, stroke: &str, dashed: bool) {
        let dash = if dashed {
            r#" stroke-dasharray="10 6""#
        } else {
            ""
        };
        match o {
            Outline::Circle { centre, radius } => {
                let p = view.page(*centre);
                let _ = writeln!(
                    self.out,
                    r#"  <circle cx="{}" cy="{}" r="{}" fill="{fill}" stroke="{stroke}" stroke-width="2.5"{dash}/>"#,
                    c(p.0),
                    c(p.1),
                    c(radius * view.scale)
                );
            }
            Outline::Polygon(points) => {
                let pts: Vec<String> = points
                    .iter()
                    .map(|p| {
                        let p = view.page(*p);
                        format!("{},{}", c(p.0), c(p.1))
                    })
                    .collect();
                let _ = writeln!(
                    self.out,
                    r#"  <polygon points="{}" fill="{fill}" stroke="{stroke}" stroke-width="2.5" stroke-linejoin="round"{dash}/>"#,
                    pts.join(" ")
                );
            }
        }
    }

    fn arrow(&mut self, view: &View, a: &Arrow) {
        let p = view.page(self.plane.project(a.from));
        let q = view.page(self.plane.project(a.to));
        let along = [
            a.to[0] - a.from[0],
            a.to[1] - a.from[1],
            a.to[2] - a.from[2],
        ];
        let page_len = ((q.0 - p.0).powi(2) + (q.1 - p.1).powi(2)).sqrt();
        let dash = if a.dashed {
            r#" stroke-dasharray="9 6""#
        } else {
            ""
        };
        if page_len < 6.0 {
            if norm(along) * view.scale < 6.0 {
                return;
            }
            // Along the view axis: ⊙ toward the viewer, ⊗ away.
            let toward = self.plane.depth(along) > 0.0;
            let _ = writeln!(
                self.out,
                r#"  <circle cx="{}" cy="{}" r="11" fill="white" stroke="{}" stroke-width="{}"/>"#,
                c(q.0),
                c(q.1),
                a.colour,
                a.width
            );
            if toward {
                let _ = writeln!(
                    self.out,
                    r#"  <circle cx="{}" cy="{}" r="3.5" fill="{}"/>"#,
                    c(q.0),
                    c(q.1),
                    a.colour
                );
            } else {
                let _ = writeln!(
                    self.out,
                    r#"  <path d="M{},{} L{},{} M{},{} L{},{}" stroke="{}" stroke-width="{}"/>"#,
                    c(q.0 - 7.0),
                    c(q.1 - 7.0),
                    c(q.0 + 7.0),
                    c(q.1 + 7.0),
                    c(q.0 - 7.0),
                    c(q.1 + 7.0),
                    c(q.0 + 7.0),
                    c(q.1 - 7.0),
                    a.colour,
                    a.width
                );
            }
            self.text(
                (q.0 + 16.0, q.1 - 12.0),
                20.0,
                "start",
                "bold",
                a.colour,
                &a.label,
            );
            return;
        }
        let head = if a.head {
            format!(r#" marker-end="url(#head-{})""#, &a.colour[1..])
        } else {
            String::new()
        };
        let _ = writeln!(
            self.out,
            r#"  <line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{}" stroke-width="{}" stroke-linecap="round"{dash}{head}/>"#,
            c(p.0),
            c(p.1),
            c(q.0),
            c(q.1),
            a.colour,
            a.width,
        );
        let dir = ((q.0 - p.0) / page_len, (q.1 - p.1) / page_len);
        let at = match a.at {
            Label::Tip => (q.0 + 22.0 * dir.0, q.1 + 22.0 * dir.1 + 7.0),
            Label::Tail => (p.0 - 22.0 * dir.0, p.1 - 22.0 * dir.1 + 7.0),
            Label::Middle => (
                (p.0 + q.0) / 2.0 + 16.0 * dir.1,
                (p.1 + q.1) / 2.0 - 16.0 * dir.0 + 7.0,
            ),
        };
        self.text(at, 20.0, "middle", "bold", a.colour, &a.label);
    }

    /// A spin arrow about the view axis around `centre`.
    fn spin(
        &mut self,
        view: &View,
        centre: [f64; 3],
        rate: f64,
        radius: f64,
        colour: &str,
        dashed: bool,
    ) {
        let p = view.page(self.plane.project(centre));
        let r = radius;
        let ccw = rate > 0.0;
        let a0: f64 = 20f64.to_radians();
        let a1 = if ccw {
            a0 + 250f64.to_radians()
        } else {
            a0 - 250f64.to_radians()
        };
        let at = |a: f64| (p.0 + r * a.cos(), p.1 - r * a.sin());
        let (s, e) = (at(a0), at(a1));
        let dash = if dashed {
            r#" stroke-dasharray="8 5""#
        } else {
            ""
        };
        let _ = writeln!(
            self.out,
            r#"  <path d="M{},{} A{},{} 0 1 {} {},{}" fill="none" stroke="{colour}" stroke-width="2.5"{dash} marker-end="url(#head-{})"/>"#,
            c(s.0),
            c(s.1),
            c(r),
            c(r),
            if ccw { 0 } else { 1 },
            c(e.0),
            c(e.1),
            &colour[1..]
        );
    }

    /// The plane through q perpendicular to d̂, hatched on the side of the
    /// body in `slot` (body 2 lies on the −d̂ side, body 1 on the +d̂ side).
    fn half_space(&mut self, view: &View, slot: usize, name: &str, reach: f64) {
        let s = &self.trace.scene;
        // Body 2 lies on the −d̂ side of the plane, body 1 on the +d̂ side.
        let side = if slot == 1 { 1.0 } else { -1.0 };
        let d = self.plane.project(s.normal);
        let len = (d.0 * d.0 + d.1 * d.1).sqrt();
        if len < 0.2 {
            return;
        }
        let d = (d.0 / len * side, d.1 / len * side);
        let t = (-d.1, d.0);
        let q = self.plane.project(s.point);
        let far = 10.0 * reach;
        let corners = [
            (q.0 + far * t.0, q.1 + far * t.1),
            (q.0 - far * t.0, q.1 - far * t.1),
            (q.0 - far * t.0 + far * d.0, q.1 - far * t.1 + far * d.1),
            (q.0 + far * t.0 + far * d.0, q.1 + far * t.1 + far * d.1),
        ];
        let pts: Vec<String> = corners
            .iter()
            .map(|p| {
                let p = view.page(*p);
                format!("{},{}", c(p.0), c(p.1))
            })
            .collect();
        let (a, b) = (view.page(corners[0]), view.page(corners[1]));
        let _ = writeln!(
            self.out,
            r#"  <g clip-path="url(#area)">
    <polygon points="{}" fill="url(#hatch)" stroke="none"/>
    <line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{INK}" stroke-width="3"/>
  </g>"#,
            pts.join(" "),
            c(a.0),
            c(a.1),
            c(b.0),
            c(b.1)
        );
        let label = view.page((
            q.0 + 0.9 * reach * t.0 + 0.25 * reach * d.0,
            q.1 + 0.9 * reach * t.1 + 0.25 * reach * d.1,
        ));
        let name = format!("{name} (m = ∞)");
        self.text(label, 20.0, "middle", "normal", INK, &name);
    }
}

/// Whether a spin is worth drawing: its speed at the body's size is at
/// least 2 % of the fastest velocity (round-off leaves tiny spins behind).
fn spins(rate: f64, reach: f64, v_max: f64) -> bool {
    if v_max > 0.0 {
        rate.abs() * reach >= 0.02 * v_max
    } else {
        rate.abs() > 1e-9
    }
}

/// Whether projection moves the body further than three times the scene's size.
fn far(b: &BodyView, reach: f64) -> bool {
    norm(scaled(b.position_after, b.position, -1.0)) > 3.0 * reach
}

fn moved(b: &BodyView) -> bool {
    let dp = (0..3)
        .map(|i| (b.position_after[i] - b.position[i]).abs())
        .fold(0.0, f64::max);
    let dq = (0..4)
        .map(|i| (b.orientation_after[i] - b.orientation[i]).abs())
        .fold(0.0, f64::max);
    dp > 1e-9 || dq > 1e-9
}

/// The figure of `trace`'s contact seen in `plane`.
pub fn render(trace: &Trace, plane: Plane) -> String {
    let s = &trace.scene;
    let fmt = Fmt::new(4);
    let in_contact: Vec<&BodyView> = s.bodies.iter().filter(|b| b.slot > 0).collect();
    // A length for the scene: the largest body, else the longest arm, else 1.
    let reach = {
        let shapes = in_contact
            .iter()
            .map(|b| size(&b.shape))
            .fold(0.0, f64::max);
        let arms = in_contact
            .iter()
            .filter(|b| b.movable)
            .map(|b| norm(scaled(s.point, b.position, -1.0)))
            .fold(0.0, f64::max);
        [shapes, arms, 1.0]
            .into_iter()
            .find(|x| *x > 1e-9)
            .unwrap_or(1.0)
    };
    let v_max = in_contact
        .iter()
        .flat_map(|b| [norm(b.velocity), norm(b.velocity_after)])
        .fold(0.0, f64::max);
    let v_scale = if v_max > 0.0 {
        0.9 * reach / v_max
    } else {
        0.0
    };
    let g_scale = s.impulse.map_or(0.0, |g| {
        if norm(g) > 0.0 {
            0.8 * reach / norm(g)
        } else {
            0.0
        }
    });

    let mut arrows: Vec<Arrow> = Vec::new();
    let normal_tip = scaled(s.point, s.normal, 0.45 * reach);
    let arrow = |from, to, colour, width, dashed, label: &str, at| Arrow {
        from,
        to,
        colour,
        width,
        dashed,
        label: label.to_string(),
        at,
        head: colour != ARM,
    };
    for b in in_contact.iter().filter(|b| b.movable) {
        let n = sub(b.slot);
        arrows.push(arrow(
            b.position,
            s.point,
            ARM,
            2.0,
            true,
            &format!("r{n}"),
            Label::Middle,
        ));
    }
    arrows.push(arrow(
        s.point,
        normal_tip,
        NORMAL,
        3.0,
        false,
        "d̂",
        Label::Tip,
    ));
    if let Some(g) = s.impulse {
        arrows.push(arrow(
            scaled(s.point, g, -g_scale),
            s.point,
            IMPULSE,
            5.0,
            false,
            "g",
            Label::Tail,
        ));
    }
    for b in in_contact.iter().filter(|b| b.movable) {
        let n = sub(b.slot);
        let tip = |v| scaled(b.position, v, v_scale);
        arrows.push(arrow(
            b.position,
            tip(b.velocity),
            BEFORE,
            3.5,
            true,
            &format!("v{n}"),
            Label::Tip,
        ));
        arrows.push(arrow(
            b.position,
            tip(b.velocity_after),
            AFTER,
            3.5,
            false,
            &format!("v{n}′"),
            Label::Tip,
        ));
    }

    // Fit the view to the bodies, the arrows and a little of any half-space.
    let mut points = vec![
        plane.project(s.point),
        plane.project(scaled(s.point, s.normal, -0.4 * reach)),
    ];
    for b in &in_contact {
        points.push(plane.project(b.position));
        let mut poses = vec![(b.position, b.orientation)];
        // A projection that moves a body far off is noted, not fitted.
        if !far(b, reach) {
            poses.push((b.position_after, b.orientation_after));
        }
        for (p, q) in poses {
            if let Some(o) = outline(&b.shape, p, q, plane) {
                points.extend(o.points());
            }
        }
    }
    for a in &arrows {
        points.push(plane.project(a.from));
        points.push(plane.project(a.to));
    }
    let view = View::fit(&points);
    // The normal is a direction: at least 60 px long whatever the scale.
    let normal_len = (0.45 * reach).max(60.0 / view.scale);
    if let Some(a) = arrows.iter_mut().find(|a| a.colour == NORMAL) {
        a.to = scaled(s.point, s.normal, normal_len);
    }

    let mut f = Figure {
        trace,
        plane,
        fmt,
        out: String::new(),
    };
    let _ = writeln!(
        f.out,
        r##"<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}" font-family="{FONT}">
  <title>{}</title>
  <defs>
    <clipPath id="area"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>
    <pattern id="hatch" width="14" height="14" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">
      <rect width="14" height="14" fill="#E4E4E4"/>
      <line x1="0" y1="0" x2="0" y2="14" stroke="#9A9A9A" stroke-width="3"/>
    </pattern>"##,
        xml(&format!(
            "{} — contact {}",
            trace.title, trace.contact_label
        )),
        c(AREA.0),
        c(AREA.1),
        c(AREA.2 - AREA.0),
        c(AREA.3 - AREA.1)
    );
    for colour in [BEFORE, AFTER, IMPULSE, NORMAL, ARM, MOVED] {
        let _ = writeln!(
            f.out,
            r#"    <marker id="head-{}" viewBox="0 0 10 10" refX="8" refY="5" markerWidth="4.5" markerHeight="4.5" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="{colour}"/></marker>"#,
            &colour[1..]
        );
    }
    f.out
        .push_str("  </defs>\n  <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
    f.text((AREA.0, 40.0), 28.0, "start", "bold", INK, &trace.title);
    let subtitle = format!(
        "{} · contact {} · {} plane, {} toward the viewer",
        trace.lesson,
        trace.contact_label,
        plane.name(),
        ["x", "y", "z"][plane.axes().2]
    );
    f.text(
        (AREA.0, 72.0),
        18.0,
        "start",
        "normal",
        "#555555",
        &subtitle,
    );

    // Everything drawn stays in the drawing area, however far a value reaches.
    f.out.push_str("  <g clip-path=\"url(#area)\">\n");
    // Bodies: half-spaces first, then shapes; where projection moves them, a dashed outline.
    for b in &in_contact {
        if b.shape == ShapeView::HalfSpace {
            f.half_space(&view, b.slot, &b.name, reach);
        }
    }
    // A contact against the world: its surface is drawn like a half-space.
    if !in_contact.iter().any(|b| b.slot == 2) {
        f.half_space(&view, 2, "the world", reach);
    }
    for b in &in_contact {
        let fill = if b.movable {
            FILL[b.slot.min(2)]
        } else {
            "url(#hatch)"
        };
        if let Some(o) = outline(&b.shape, b.position, b.orientation, plane) {
            f.shape(&view, &o, fill, INK, false);
        } else if b.shape == ShapeView::Marker {
            let o = Outline::Circle {
                centre: plane.project(b.position),
                radius: 0.15 * reach,
            };
            f.shape(&view, &o, fill, INK, true);
        }
    }
    for b in in_contact.iter().filter(|b| moved(b)) {
        if let Some(o) = outline(&b.shape, b.position_after, b.orientation_after, plane) {
            f.shape(&view, &o, "none", MOVED, true);
        }
        let (from, to) = (
            view.page(plane.project(b.position)),
            view.page(plane.project(b.position_after)),
        );
        if ((to.0 - from.0).powi(2) + (to.1 - from.1).powi(2)).sqrt() > 6.0 {
            let _ = writeln!(
                f.out,
                r#"  <line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{MOVED}" stroke-width="2.5" marker-end="url(#head-{})"/>"#,
                c(from.0),
                c(from.1),
                c(to.0),
                c(to.1),
                &MOVED[1..]
            );
        }
    }
    // Spin about the view axis, before (dashed) and after.
    for b in in_contact.iter().filter(|b| b.movable) {
        for (w, colour, dashed, radius) in [
            (b.angular_velocity, BEFORE, true, 30.0),
            (b.angular_velocity_after, AFTER, false, 42.0),
        ] {
            let rate = plane.depth(w);
            if spins(rate, reach, v_max) {
                f.spin(&view, b.position, rate, radius, colour, dashed);
            }
        }
    }
    for a in &arrows {
        f.arrow(&view, a);
    }
    // Centres and the contact point, with their names.
    for b in in_contact
        .iter()
        .filter(|b| b.movable || b.shape != ShapeView::HalfSpace)
    {
        let p = view.page(plane.project(b.position));
        let _ = writeln!(
            f.out,
            r#"  <circle cx="{}" cy="{}" r="5" fill="{INK}"/>"#,
            c(p.0),
            c(p.1)
        );
        let label = if b.movable {
            format!("p{} {}", sub(b.slot), b.name)
        } else {
            format!("{} (m = ∞)", b.name)
        };
        f.text((p.0 - 50.0, p.1 + 7.0), 20.0, "end", "normal", INK, &label);
    }
    let q = view.page(plane.project(s.point));
    let _ = writeln!(
        f.out,
        r#"  <circle cx="{}" cy="{}" r="7" fill="{IMPULSE}" stroke="white" stroke-width="2"/>"#,
        c(q.0),
        c(q.1)
    );
    // The q label sits along the contact plane, away from the normal and the impulse.
    let d = plane.project(s.normal);
    let len = (d.0 * d.0 + d.1 * d.1).sqrt();
    let t = if len > 0.2 {
        (d.1 / len, d.0 / len)
    } else {
        (-0.7, 0.7)
    };
    f.text(
        (q.0 - 26.0 * t.0.abs(), q.1 + 26.0 * t.1.abs() + 8.0),
        22.0,
        "end",
        "bold",
        INK,
        "q",
    );

    f.out.push_str("  </g>\n");
    legend(&mut f, &in_contact, reach, v_max);
    f.out.push_str("</svg>\n");
    f.out
}

fn legend(f: &mut Figure, bodies: &[&BodyView], reach: f64, v_max: f64) {
    let s = &f.trace.scene;
    let fmt = f.fmt;
    let v = |x: [f64; 3]| format!("({})", fmt.list(&x));
    let x0 = AREA.2 + 20.0;
    let mut y = AREA.1 + 8.0;
    let _ = writeln!(
        f.out,
        r##"  <rect x="{}" y="{}" width="{}" height="{}" rx="10" fill="#FAFAFA" stroke="#CCCCCC"/>"##,
        c(x0 - 12.0),
        c(y - 30.0),
        c(WIDTH - x0 - 8.0),
        c(AREA.3 - y + 30.0)
    );
    let line = |f: &mut Figure, sample: Option<(&str, bool, f64)>, text: &str, y: &mut f64| {
        if let Some((colour, dashed, width)) = sample {
            let dash = if dashed {
                r#" stroke-dasharray="9 6""#
            } else {
                ""
            };
            let _ = writeln!(
                f.out,
                r#"  <line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{colour}" stroke-width="{width}"{dash}/>"#,
                c(x0),
                c(*y - 6.0),
                c(x0 + 34.0),
                c(*y - 6.0)
            );
        }
        let _ = writeln!(
            f.out,
            r#"  <text x="{}" y="{}" font-size="16" fill="{INK}">{}</text>"#,
            c(x0 + if sample.is_some() { 44.0 } else { 0.0 }),
            c(*y),
            xml(text)
        );
        *y += 25.0;
    };
    let _ = writeln!(
        f.out,
        r#"  <text x="{}" y="{}" font-size="18" font-weight="bold" fill="{INK}">Legend</text>"#,
        c(x0),
        c(y)
    );
    y += 27.0;
    for b in bodies {
        let what = if b.movable {
            format!("body {}: {}", b.slot, b.name)
        } else {
            format!("body {}: {} (immovable)", b.slot, b.name)
        };
        line(f, None, &what, &mut y);
    }
    line(f, None, &format!("q contact point {}", v(s.point)), &mut y);
    line(
        f,
        Some((NORMAL, false, 3.0)),
        &format!("d̂ normal {}", v(s.normal)),
        &mut y,
    );
    if let Some(g) = s.impulse {
        line(
            f,
            Some((IMPULSE, false, 5.0)),
            &format!("g on body 1 {}", v(g)),
            &mut y,
        );
        if bodies.iter().filter(|b| b.movable).count() == 2 {
            line(f, None, "(body 2 receives −g)", &mut y);
        }
    }
    for b in bodies.iter().filter(|b| b.movable) {
        let n = sub(b.slot);
        line(
            f,
            Some((ARM, true, 2.0)),
            &format!("r{n} = q − p{n} {}", v(scaled(s.point, b.position, -1.0))),
            &mut y,
        );
        if norm(b.velocity) > 0.0 || norm(b.velocity_after) > 0.0 {
            line(
                f,
                Some((BEFORE, true, 3.5)),
                &format!("v{n} before {}", v(b.velocity)),
                &mut y,
            );
            line(
                f,
                Some((AFTER, false, 3.5)),
                &format!("v{n}′ after {}", v(b.velocity_after)),
                &mut y,
            );
        }
        if [b.angular_velocity, b.angular_velocity_after]
            .iter()
            .any(|w| spins(norm(*w), reach, v_max))
        {
            line(
                f,
                None,
                &format!(
                    "ω{n} {} → {}",
                    v(b.angular_velocity),
                    v(b.angular_velocity_after)
                ),
                &mut y,
            );
        }
    }
    for b in bodies.iter().filter(|b| far(b, reach)) {
        let d = norm(scaled(b.position_after, b.position, -1.0));
        line(
            f,
            None,
            &format!("projection moves {} by {}", b.name, fmt.num(d)),
            &mut y,
        );
        line(f, None, "(beyond the figure)", &mut y);
    }
    if bodies.iter().any(|b| moved(b)) {
        line(f, Some((MOVED, true, 2.5)), "after projection", &mut y);
    }
    y += 6.0;
    line(f, None, "Velocities to one scale, the impulse", &mut y);
    line(f, None, "to another; ⊙ toward you, ⊗ away.", &mut y);
    // Where the contact point is not on a body as drawn, say so.
    for b in bodies {
        let Some(dist) = surface_distance(&b.shape, b.position, b.orientation, s.point) else {
            continue;
        };
        if dist.abs() > s.penetration.max(0.0) + 0.02 * reach {
            let side = if dist > 0.0 { "outside" } else { "inside" };
            line(
                f,
                None,
                &format!("⚠ q is {} {side} {}", fmt.num(dist.abs()), b.name),
                &mut y,
            );
            line(f, None, "as drawn (shape or orientation", &mut y);
            line(f, None, "in the lesson do not fit q).", &mut y);
        }
    }
}
