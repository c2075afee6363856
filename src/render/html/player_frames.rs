//! The player's frames as data: every recorded frame's movable bodies as
//! outlines in the picture's pixels (the figure model's outlines,
//! [`crate::render::figure::outline`], at one scale for the whole run), its
//! contact points, its label and energies. The page's script only sets
//! these on SVG elements: no geometry is computed in the browser.

use std::fmt::Write;

use serde_json::{json, Value as J};

use super::esc;
use crate::format::Fmt;
use crate::physics::Shape;
use crate::render::figure::{outline, Silhouette};
use crate::trace::run::{BodyFrame, Frame, RunTrace};
use crate::trace::Plane;

/// The picture's size in pixels.
pub const W: f64 = 800.0;
pub const H: f64 = 420.0;
const MARGIN: f64 = 24.0;
/// A body whose outline spans less than a pixel is a dot of this radius.
const TINY_R: f64 = 3.0;

/// Scene coordinates (in the plane) to the picture's pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    centre: (f64, f64),
    scale: f64,
}

impl View {
    pub fn px(&self, p: (f64, f64)) -> (f64, f64) {
        (
            W / 2.0 + (p.0 - self.centre.0) * self.scale,
            H / 2.0 - (p.1 - self.centre.1) * self.scale,
        )
    }
}

/// One scale for the whole run: the bounds of every body in every frame.
pub fn view(run: &RunTrace, plane: Plane) -> View {
    let (lo, hi) = crate::render::run_film::frames_bounds(run, 0..run.frames.len(), plane);
    let span = ((hi.0 - lo.0).max(1e-12), (hi.1 - lo.1).max(1e-12));
    View {
        centre: ((lo.0 + hi.0) / 2.0, (lo.1 + hi.1) / 2.0),
        scale: ((W - 2.0 * MARGIN) / span.0).min((H - 2.0 * MARGIN) / span.1),
    }
}

/// Body `i` at `b` as an SVG element: a polygon, or a circle with the
/// spoke that shows its turn, or (below a pixel) a ringed dot. `None` for
/// a half-space or a body without a shape.
pub fn body_svg(run: &RunTrace, i: usize, b: &BodyFrame, plane: Plane, v: &View) -> Option<String> {
    let o = outline(run.shapes[i].as_ref()?, b.position, b.orientation, plane)?;
    let fill = if !run.movable[i] {
        "#DDDDDD"
    } else if b.awake {
        "#DCE9F5"
    } else {
        "#EEEEEE"
    };
    let dash = if run.movable[i] && !b.awake {
        " stroke-dasharray=\"4 3\""
    } else {
        ""
    };
    let pts: Vec<(f64, f64)> = o
        .silhouette
        .points()
        .iter()
        .map(|q| v.px((q[0], q[1])))
        .collect();
    let (lo, hi) = pts.iter().fold(
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
    );
    if !(lo.0.is_finite() && hi.0.is_finite()) {
        return None;
    }
    if (hi.0 - lo.0).max(hi.1 - lo.1) < 1.0 {
        let (x, y) = ((lo.0 + hi.0) / 2.0, (lo.1 + hi.1) / 2.0);
        return Some(format!(
            "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"{TINY_R}\" fill=\"{fill}\" stroke=\"#222222\"/><circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"8\" fill=\"none\" stroke=\"#D55E00\"/>"
        ));
    }
    Some(match &o.silhouette {
        Silhouette::Polygon(_) => {
            let mut p = String::new();
            for (x, y) in &pts {
                let _ = write!(p, "{x:.1},{y:.1} ");
            }
            format!(
                "<polygon points=\"{}\" fill=\"{fill}\" stroke=\"#222222\"{dash}/>",
                p.trim_end()
            )
        }
        Silhouette::Circle { centre, radius } => {
            let (x, y) = v.px((centre[0], centre[1]));
            let spoke = o.edges.last().map_or(String::new(), |[_, s]| {
                let (sx, sy) = v.px((s[0], s[1]));
                format!("<line x1=\"{x:.1}\" y1=\"{y:.1}\" x2=\"{sx:.1}\" y2=\"{sy:.1}\" stroke=\"#222222\"/>")
            });
            format!(
                "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"{:.1}\" fill=\"{fill}\" stroke=\"#222222\"{dash}/>{spoke}",
                radius * v.scale
            )
        }
    })
}

/// What does not move: the immovable bodies at the first frame, and each
/// half-space as a line across the picture.
pub fn still_layer(run: &RunTrace, plane: Plane, v: &View) -> String {
    let Some(f) = run.frames.first() else {
        return String::new();
    };
    let mut out = String::new();
    for (i, b) in f.bodies.iter().enumerate() {
        if run.movable[i] {
            continue;
        }
        if let Some(Shape::HalfSpace { normal }) = run.shapes[i] {
            let (u, w) = plane.project(normal);
            let along = (-w, u);
            let p = plane.project(b.position);
            let reach = 4.0 * (W + H) / v.scale;
            let a = v.px((p.0 - along.0 * reach, p.1 - along.1 * reach));
            let z = v.px((p.0 + along.0 * reach, p.1 + along.1 * reach));
            let _ = write!(
                out,
                "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#555555\" stroke-width=\"2\"><title>{}</title></line>",
                a.0, a.1, z.0, z.1, esc(&run.names[i])
            );
        } else if let Some(svg) = body_svg(run, i, b, plane, v) {
            let _ = write!(out, "<g><title>{}</title>{svg}</g>", esc(&run.names[i]));
        }
    }
    out
}

/// The movable bodies and contact points of frame `f` (what the script
/// swaps in from frame to frame).
pub fn moving_layer(run: &RunTrace, f: &Frame, plane: Plane, v: &View) -> String {
    let mut out = String::new();
    for (i, b) in f.bodies.iter().enumerate() {
        if !run.movable[i] {
            continue;
        }
        if let Some(svg) = body_svg(run, i, b, plane, v) {
            out.push_str(&svg);
        }
    }
    for (q, _) in &f.contact_points {
        let (x, y) = v.px(plane.project(*q));
        let _ = write!(
            out,
            "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"2.5\" fill=\"#D55E00\"/>"
        );
    }
    out
}

/// The label the player shows for frame `k` of `n` (a test ties it to the
/// frame's numbers).
pub fn label(f: &Frame, k: usize, n: usize, fmt: &Fmt) -> String {
    format!(
        "frame {} of {n} · step {} · t = {} s · E = {} J",
        k + 1,
        f.step,
        fmt.num(f.time),
        fmt.num(f.kinetic_energy + f.potential_energy)
    )
}

/// Every frame as the script reads it: `{ step, t, label, svg }`.
pub fn frames_json(run: &RunTrace, plane: Plane, v: &View, fmt: &Fmt) -> J {
    let n = run.frames.len();
    J::Array(
        (run.frames.iter().enumerate())
            .map(|(k, f)| {
                json!({
                    "step": f.step,
                    "t": f.time,
                    "label": label(f, k, n, fmt),
                    "svg": moving_layer(run, f, plane, v),
                })
            })
            .collect(),
    )
}

/// JSON put inside a `<script>` element: `</` can end it, so it is written
/// `<\/` (the same string to JSON).
pub fn script_safe(json: &str) -> String {
    json.replace("</", "<\\/")
}
