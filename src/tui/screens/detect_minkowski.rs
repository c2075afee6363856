//! The detection screen's second picture, the lectures' one: the Minkowski
//! difference A - B seen in the view plane through the origin, with the
//! iteration on show's simplex (or EPA's closest face), its support point
//! w_k, closest point v_k and search direction d_k, and the origin O; at
//! the result, the penetration vector -δn or the distance v. The geometry
//! is `render::detect::minkowski`'s (the `detect --figure` SVG's): this
//! only draws it.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::text::Span;
use ratatui::widgets::{Block, Widget};

use super::picture::{draw, extent, fit, UNIT};
use crate::render::detect::minkowski::minkowski;
use crate::render::figure::P;
use crate::trace::detect::PairTrace;
use crate::trace::Plane;
use crate::tui::app::App;
use crate::tui::theme::Ink;

/// What the picture's legend says each mark is.
pub const LEGEND: &str = "• simplex ✗ dropped w=w_k v=v_k d=d_k";

/// Why a pair has no A - B to draw: a mesh is not convex (its mid phase
/// tests triangle by triangle), an analytic routine or a half-space has no
/// GJK iterations.
fn no_picture(p: &PairTrace) -> &'static str {
    match p.method {
        "mesh" => "a mesh is not convex: no single A - B (see its mid phase)",
        _ if p.gjk.is_none() && p.analytic.is_some() => "an analytic routine: no GJK iterations",
        _ => "a half-space has no support mapping",
    }
}

/// A - B of the selected pair (`pair`, its narrow phase) at `stop`, seen
/// in `plane`, in `area`; `toi`: the time of collision is on show.
pub fn render(
    app: &App,
    pair: Option<&PairTrace>,
    plane: Plane,
    stop: usize,
    toi: bool,
    area: Rect,
    buf: &mut Buffer,
) {
    let t = &app.theme;
    let (m, what) = match pair {
        Some(p) if !p.minkowski.is_empty() => (Some(minkowski(plane, p, stop)), stop_name(stop, p)),
        Some(p) => (None, no_picture(p).to_string()),
        None => (None, "no pair".to_string()),
    };
    // The time of collision moves the shapes, not this: say when it is of.
    let when = if toi { " (the step's start)" } else { "" };
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(" A - B{when} · {what} · {} plane ", plane.name()),
            t.title(),
        ))
        .title_bottom(Span::styled(format!(" {LEGEND} "), t.dim()));
    let inner = block.inner(area);
    block.render(area, buf);
    let Some(m) = m else {
        return;
    };
    if inner.width < 2 || inner.height < 2 {
        return;
    }
    let b = fit(
        extent(m.points()).unwrap_or(UNIT),
        inner.width,
        inner.height,
    );
    let size = (b[1] - b[0]).max(b[3] - b[2]);
    let mut segs: Vec<(P, P, Color)> = vec![];
    let n = m.hull.len();
    for k in 0..n {
        segs.push((m.hull[k], m.hull[(k + 1) % n], t.ink(Ink::Arm)));
    }
    for [a, c] in m.edges() {
        segs.push((a, c, t.ink(Ink::Impulse)));
    }
    let o = [0.0, 0.0];
    let mut labels: Vec<(P, String, Style, u8)> = vec![(o, "O".into(), t.title(), 0)];
    if let Some(tip) = m.direction {
        arrow(&mut segs, o, tip, size, t.ink(Ink::Normal));
        labels.push((tip, "d".into(), t.ink_style(Ink::Normal), 1));
    }
    if let Some((tip, label)) = m.arrow {
        arrow(&mut segs, o, tip, size, t.ink(Ink::VelocityAfter));
        labels.push((tip, label.into(), t.ink_style(Ink::VelocityAfter), 1));
    }
    if let Some(v) = m.closest {
        segs.push((o, v, t.ink(Ink::VelocityAfter)));
        labels.push((v, "v".into(), t.ink_style(Ink::VelocityAfter), 1));
    }
    if let Some(w) = m.support {
        labels.push((w, "w".into(), t.ink_style(Ink::Impulse), 1));
    }
    for (k, s) in m.simplex.iter().enumerate() {
        let mark = if m.dropped.contains(&k) { "✗" } else { "•" };
        labels.push((*s, mark.into(), t.ink_style(Ink::Point), 2));
    }
    draw(buf, inner, b, &segs, labels);
}

/// The stop on show in a few words: `GJK 2`, `EPA 1`, `result`.
fn stop_name(stop: usize, p: &PairTrace) -> String {
    use crate::render::detect::steps::{stops, Stop};
    match stops(p).get(stop) {
        Some(Stop::Gjk(k)) => format!("GJK iteration {}", k + 1),
        Some(Stop::Epa(k)) => format!("EPA iteration {}", k + 1),
        Some(Stop::Node(k)) => format!("tree node {}", k + 1),
        Some(Stop::Triangle(k)) => format!("triangle {}", k + 1),
        None => "result".into(),
    }
}

/// A line from `from` to `to` with a head of two short strokes.
fn arrow(segs: &mut Vec<(P, P, Color)>, from: P, to: P, size: f64, color: Color) {
    segs.push((from, to, color));
    let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
    let len = dx.hypot(dy);
    if !(len > 0.0 && len.is_finite()) {
        return;
    }
    let (ux, uy) = (dx / len, dy / len);
    let h = (0.05 * size).min(0.5 * len);
    for side in [1.0, -1.0] {
        let back = [
            to[0] - h * ux - side * 0.5 * h * uy,
            to[1] - h * uy + side * 0.5 * h * ux,
        ];
        segs.push((to, back, color));
    }
}
