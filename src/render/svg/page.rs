//! The SVG page: 1280 × 720, the drawing area and its fitting to the
//! figure's view-plane coordinates, the colours of the figure's inks, and the
//! writer of each kind of element (text, outline, arrow, spin, surface).

use std::fmt::Write;

use crate::render::figure::{Ink, Section, Silhouette, P, V};

pub const WIDTH: f64 = 1280.0;
pub const HEIGHT: f64 = 720.0;
/// The drawing area (left, top, right, bottom); the legend is to its right.
pub const AREA: (f64, f64, f64, f64) = (24.0, 96.0, 880.0, 700.0);
pub const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";

pub const INK: &str = "#222222";
pub const BEFORE: &str = "#0072B2";
pub const AFTER: &str = "#009E73";
pub const IMPULSE: &str = "#D55E00";
pub const NORMAL: &str = "#CC79A7";
pub const ARM: &str = "#6E6E6E";
pub const MOVED: &str = "#E69F00";
pub const FILL: [&str; 3] = ["#EEEEEE", "#DCE9F5", "#F5E6CC"];
/// The colours an arrow head comes in (one marker each).
pub const HEADS: [&str; 6] = [BEFORE, AFTER, IMPULSE, NORMAL, ARM, MOVED];

/// The colour of an ink.
pub fn colour(ink: Ink) -> &'static str {
    match ink {
        Ink::Body | Ink::Ground => INK,
        Ink::Moved => MOVED,
        Ink::Point | Ink::Impulse => IMPULSE,
        Ink::Normal => NORMAL,
        Ink::Arm => ARM,
        Ink::Before => BEFORE,
        Ink::After => AFTER,
    }
}

/// Maps view-plane coordinates to the page.
pub struct View {
    pub scale: f64,
    centre: P,
}

impl View {
    /// Fits the finite `points` into 86 % of the drawing area.
    pub fn fit(points: &[P]) -> View {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points
            .iter()
            .filter(|p| p[0].is_finite() && p[1].is_finite())
        {
            lo = [lo[0].min(p[0]), lo[1].min(p[1])];
            hi = [hi[0].max(p[0]), hi[1].max(p[1])];
        }
        if !lo[0].is_finite() {
            (lo, hi) = ([-1.0, -1.0], [1.0, 1.0]);
        }
        let span = ((hi[0] - lo[0]).max(1e-9), (hi[1] - lo[1]).max(1e-9));
        let (w, h) = (AREA.2 - AREA.0, AREA.3 - AREA.1);
        let scale = (0.86 * w / span.0).min(0.86 * h / span.1);
        View {
            scale,
            centre: [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0],
        }
    }

    pub fn page(&self, p: P) -> P {
        [
            (AREA.0 + AREA.2) / 2.0 + (p[0] - self.centre[0]) * self.scale,
            (AREA.1 + AREA.3) / 2.0 - (p[1] - self.centre[1]) * self.scale,
        ]
    }
}

/// A page coordinate: one decimal, never `-0.0`.
pub fn c(x: f64) -> String {
    let s = format!("{x:.1}");
    if s == "-0.0" {
        "0.0".into()
    } else {
        s
    }
}

pub fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn dash(dashed: bool, pattern: &str) -> String {
    if dashed {
        format!(r#" stroke-dasharray="{pattern}""#)
    } else {
        String::new()
    }
}

/// Where an arrow's label goes.
#[derive(Clone, Copy, PartialEq)]
pub enum LabelAt {
    /// Beyond the head.
    Tip,
    /// Before the tail (for an arrow that ends on the contact point).
    Tail,
    /// Beside the middle.
    Middle,
}

/// An arrow from `from` to `to` (view coordinates), or a ⊙ / ⊗ when it
/// points along the view axis.
pub struct PageArrow {
    pub from: V,
    pub to: V,
    pub colour: &'static str,
    pub width: f64,
    pub dashed: bool,
    pub label: String,
    pub at: LabelAt,
    pub head: bool,
}

/// A label not yet placed.
pub struct Pending {
    pub at: P,
    pub size: f64,
    pub anchor: String,
    pub weight: String,
    pub fill: String,
    pub text: String,
    /// Other anchors to try, in order, after `at` and its nudges.
    pub elsewhere: Vec<P>,
}

/// A straight piece of a stroke on the page and half its width.
#[derive(Debug, Clone, Copy)]
pub struct Stroke {
    pub from: P,
    pub to: P,
    pub half_width: f64,
}

/// The SVG text being written.
pub struct Page {
    pub view: View,
    pub out: String,
    /// Boxes of the labels placed in the drawing so far, `[x0, y0, x1, y1]`.
    pub placed: Vec<[f64; 4]>,
    /// Labels waiting for [`Page::place_labels`].
    pub pending: Vec<Pending>,
    /// Every stroke drawn so far, for labels to keep clear of.
    pub strokes: Vec<Stroke>,
    /// Labels that found no free place: (marker drawn at the mark, or
    /// `None`; the label; its colour), listed in the legend.
    pub moved: Vec<(Option<String>, String, String)>,
}

impl Page {
    pub fn text(&mut self, at: P, size: f64, anchor: &str, weight: &str, fill: &str, s: &str) {
        let _ = writeln!(
            self.out,
            r#"  <text x="{}" y="{}" font-size="{size}" text-anchor="{anchor}" font-weight="{weight}" fill="{fill}" stroke="white" stroke-width="4" stroke-linejoin="round" paint-order="stroke">{}</text>"#,
            c(at[0]),
            c(at[1]),
            xml(s)
        );
    }

    pub fn silhouette(&mut self, s: &Silhouette, fill: &str, stroke: &str, dashed: bool) {
        let dash = dash(dashed, "10 6");
        match s {
            Silhouette::Circle { centre, radius } => {
                let p = self.view.page(*centre);
                let _ = writeln!(
                    self.out,
                    r#"  <circle cx="{}" cy="{}" r="{}" fill="{fill}" stroke="{stroke}" stroke-width="2.5"{dash}/>"#,
                    c(p[0]),
                    c(p[1]),
                    c(radius * self.view.scale)
                );
                self.stroke_circle(p, radius * self.view.scale, 2.5);
            }
            Silhouette::Polygon(points) => {
                let pts = self.points(points);
                let _ = writeln!(
                    self.out,
                    r#"  <polygon points="{pts}" fill="{fill}" stroke="{stroke}" stroke-width="2.5" stroke-linejoin="round"{dash}/>"#,
                );
                let ring: Vec<P> = points.iter().map(|p| self.view.page(*p)).collect();
                self.stroke_ring(&ring, 2.5);
            }
        }
    }

    /// `x,y x,y …` of view-plane points on the page.
    fn points(&self, points: &[P]) -> String {
        let pts: Vec<String> = points
            .iter()
            .map(|p| {
                let p = self.view.page(*p);
                format!("{},{}", c(p[0]), c(p[1]))
            })
            .collect();
        pts.join(" ")
    }

    pub fn arrow(&mut self, a: &PageArrow) {
        let p = self.view.page([a.from[0], a.from[1]]);
        let q = self.view.page([a.to[0], a.to[1]]);
        let along = [0, 1, 2].map(|i| a.to[i] - a.from[i]);
        let page_len = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2)).sqrt();
        if page_len < 6.0 {
            let length = crate::physics::scale::stable_norm_of(&along);
            if length * self.view.scale < 6.0 {
                return;
            }
            return self.end_on(q, along[2] > 0.0, a);
        }
        let head = if a.head {
            format!(r#" marker-end="url(#head-{})""#, &a.colour[1..])
        } else {
            String::new()
        };
        let _ = writeln!(
            self.out,
            r#"  <line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{}" stroke-width="{}" stroke-linecap="round"{}{head}/>"#,
            c(p[0]),
            c(p[1]),
            c(q[0]),
            c(q[1]),
            a.colour,
            a.width,
            dash(a.dashed, "9 6"),
        );
        self.stroke(p, q, a.width);
        if a.head {
            self.stroke_head(p, q, a.width);
        }
        let dir = ((q[0] - p[0]) / page_len, (q[1] - p[1]) / page_len);
        let at = match a.at {
            LabelAt::Tip => [q[0] + 22.0 * dir.0, q[1] + 22.0 * dir.1 + 7.0],
            LabelAt::Tail => [p[0] - 22.0 * dir.0, p[1] - 22.0 * dir.1 + 7.0],
            LabelAt::Middle => [
                (p[0] + q[0]) / 2.0 + 16.0 * dir.1,
                (p[1] + q[1]) / 2.0 - 16.0 * dir.0 + 7.0,
            ],
        };
        self.label(at, 20.0, "middle", "bold", a.colour, &a.label);
    }

    /// An arrow along the view axis, seen end on at `q`: ⊙ toward the viewer, ⊗ away.
    fn end_on(&mut self, q: P, toward: bool, a: &PageArrow) {
        self.stroke_circle(q, 11.0, a.width);
        let _ = writeln!(
            self.out,
            r#"  <circle cx="{}" cy="{}" r="11" fill="white" stroke="{}" stroke-width="{}"/>"#,
            c(q[0]),
            c(q[1]),
            a.colour,
            a.width
        );
        if toward {
            let _ = writeln!(
                self.out,
                r#"  <circle cx="{}" cy="{}" r="3.5" fill="{}"/>"#,
                c(q[0]),
                c(q[1]),
                a.colour
            );
        } else {
            let _ = writeln!(
                self.out,
                r#"  <path d="M{},{} L{},{} M{},{} L{},{}" stroke="{}" stroke-width="{}"/>"#,
                c(q[0] - 7.0),
                c(q[1] - 7.0),
                c(q[0] + 7.0),
                c(q[1] + 7.0),
                c(q[0] - 7.0),
                c(q[1] + 7.0),
                c(q[0] + 7.0),
                c(q[1] - 7.0),
                a.colour,
                a.width
            );
        }
        let at = [q[0] + 16.0, q[1] - 12.0];
        self.label(at, 20.0, "start", "bold", a.colour, &a.label);
    }

    /// A spin arrow about the view axis around `centre`, of `radius` px.
    pub fn spin(&mut self, centre: P, rate: f64, radius: f64, colour: &str, dashed: bool) {
        let p = self.view.page(centre);
        let r = radius;
        let ccw = rate > 0.0;
        let a0: f64 = 20f64.to_radians();
        let a1 = if ccw {
            a0 + 250f64.to_radians()
        } else {
            a0 - 250f64.to_radians()
        };
        let at = |a: f64| (p[0] + r * a.cos(), p[1] - r * a.sin());
        let (s, e) = (at(a0), at(a1));
        let _ = writeln!(
            self.out,
            r#"  <path d="M{},{} A{},{} 0 1 {} {},{}" fill="none" stroke="{colour}" stroke-width="2.5"{} marker-end="url(#head-{})"/>"#,
            c(s.0),
            c(s.1),
            c(r),
            c(r),
            if ccw { 0 } else { 1 },
            c(e.0),
            c(e.1),
            dash(dashed, "8 5"),
            &colour[1..]
        );
        // The arc as 24 pieces, and its head along the last one.
        let arc: Vec<P> = (0..=24)
            .map(|i| {
                let (x, y) = at(a0 + (a1 - a0) * f64::from(i) / 24.0);
                [x, y]
            })
            .collect();
        for w in arc.windows(2) {
            self.stroke(w[0], w[1], 2.5);
        }
        self.stroke_head(arc[23], arc[24], 2.5);
    }

    /// A surface seen edge on: its line in the view plane, hatched on the
    /// solid side, named.
    pub fn surface(&mut self, s: &Section, name: &str, reach: f64) {
        let (q, d) = (s.at, s.solid_side);
        let t = [-d[1], d[0]];
        let far = 10.0 * reach;
        let corners = [
            [q[0] + far * t[0], q[1] + far * t[1]],
            [q[0] - far * t[0], q[1] - far * t[1]],
            [
                q[0] - far * t[0] + far * d[0],
                q[1] - far * t[1] + far * d[1],
            ],
            [
                q[0] + far * t[0] + far * d[0],
                q[1] + far * t[1] + far * d[1],
            ],
        ];
        let pts = self.points(&corners);
        let (a, b) = (self.view.page(corners[0]), self.view.page(corners[1]));
        let _ = writeln!(
            self.out,
            r#"  <g clip-path="url(#area)">
    <polygon points="{pts}" fill="url(#hatch)" stroke="none"/>
    <line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{INK}" stroke-width="3"/>
  </g>"#,
            c(a[0]),
            c(a[1]),
            c(b[0]),
            c(b[1])
        );
        self.stroke(a, b, 3.0);
        // Its name inside the solid, a little along the line from q, else
        // further along on either side, or deeper.
        let at = |along: f64, deep: f64| {
            self.view.page([
                q[0] + along * reach * t[0] + deep * reach * d[0],
                q[1] + along * reach * t[1] + deep * reach * d[1],
            ])
        };
        let elsewhere = [0.25, 0.7, 1.2]
            .iter()
            .flat_map(|deep| [0.9, -0.9, 0.45, -0.45, 1.8, -1.8].map(|a| (a, *deep)))
            .skip(1)
            .map(|(a, deep)| at(a, deep))
            .collect();
        let name = format!("{name} (m = ∞)");
        self.label_or(at(0.9, 0.25), elsewhere, 20.0, INK, &name);
    }
}
