//! The scene picture of the run and resolver screens (Canvas, braille):
//! every body's outline in the view plane, half-spaces as hatched lines,
//! contact points numbered, normals, names; sleeping bodies dimmed. It
//! records where it put the bodies and contacts, for the mouse.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::{Color, Style};
use ratatui::symbols::Marker;
use ratatui::text::Span;
use ratatui::widgets::canvas::{Canvas, Line};
use ratatui::widgets::{Block, Widget};

use super::{Pick, Toggles};
use crate::physics::Shape;
use crate::render::figure::{outline, P};
use crate::trace::movement::Movement;
use crate::trace::{BodyView, ContactView, Plane};
use crate::tui::app::App;
use crate::tui::theme::Ink;

/// What to draw.
pub struct Scene<'a> {
    pub title: String,
    pub bodies: &'a [BodyView],
    /// Per body: asleep (drawn dimmed when the toggle is on).
    pub asleep: Vec<bool>,
    pub contacts: &'a [ContactView],
    /// The contact the next iteration takes, and the one selected.
    pub next: Option<usize>,
    pub selected: Option<usize>,
    pub toggles: Toggles,
    /// Bodies whose outlines set the view besides these (the run's first frame).
    pub also: &'a [BodyView],
    /// Each body's movement bounds over the step (empty: none recorded).
    pub movement: &'a [Option<Movement>],
}

fn flat(plane: Plane, v: [f64; 3]) -> P {
    let (a, b, _) = plane.axes();
    [v[a], v[b]]
}

/// `b` (x0, x1, y0, y1) grown to hold `p` when it is finite.
fn grow(b: [f64; 4], p: [f64; 2]) -> [f64; 4] {
    if !(p[0].is_finite() && p[1].is_finite()) {
        return b;
    }
    [
        b[0].min(p[0]),
        b[1].max(p[0]),
        b[2].min(p[1]),
        b[3].max(p[1]),
    ]
}

/// Bounds (x0, x1, y0, y1) of the finite points, `None` when none is.
pub(super) fn extent(points: impl IntoIterator<Item = [f64; 2]>) -> Option<[f64; 4]> {
    let empty = [
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    let b = points.into_iter().fold(empty, grow);
    (b[0] <= b[1]).then_some(b)
}

/// The bounds drawn when there is nothing finite to draw.
pub(super) const UNIT: [f64; 4] = [-1.0, 1.0, -1.0, 1.0];

/// Bounds (x0, x1, y0, y1) of the finite bodies' outlines, or the unit box.
fn bounds(bodies: &[&BodyView], plane: Plane) -> [f64; 4] {
    let outlines = bodies.iter().filter_map(|v| {
        v.shape
            .as_ref()
            .and_then(|s| outline(s, v.position, v.orientation, plane))
    });
    let Some(mut b) = extent(outlines.flat_map(|o| o.silhouette.points())) else {
        return UNIT;
    };
    // A half-space in view too (a ball dropped from high above its floor,
    // up to 10 times the bodies' extent away):
    // the point of its line nearest the bodies, and a little of its solid
    // side for the hatching.
    let c = [(b[0] + b[1]) / 2.0, (b[2] + b[3]) / 2.0];
    let size = (b[1] - b[0]).max(b[3] - b[2]).max(1e-9);
    for v in bodies {
        let Some(Shape::HalfSpace { normal }) = v.shape else {
            continue;
        };
        let n = flat(plane, normal);
        let len = n[0].hypot(n[1]);
        if len.is_nan() || len <= 1e-9 {
            continue;
        }
        let n = [n[0] / len, n[1] / len];
        let q = flat(plane, v.position);
        let d = (c[0] - q[0]) * n[0] + (c[1] - q[1]) * n[1];
        // Not one so far away that the bodies would shrink to dots.
        if d.is_nan() || d.abs() > 10.0 * size {
            continue;
        }
        let p = [c[0] - d * n[0], c[1] - d * n[1]];
        // Already in view (a stack standing on its floor): nothing to add.
        let tol = 1e-6 * size;
        if p[0] >= b[0] - tol && p[0] <= b[1] + tol && p[1] >= b[2] - tol && p[1] <= b[3] + tol {
            continue;
        }
        let below = [p[0] - 0.05 * size * n[0], p[1] - 0.05 * size * n[1]];
        b = grow(grow(b, p), below);
    }
    b
}

/// Bounds with a margin, widened so a braille dot is as wide as it is tall.
pub(super) fn fit(b: [f64; 4], cols: u16, rows: u16) -> [f64; 4] {
    let (cx, cy) = ((b[0] + b[1]) / 2.0, (b[2] + b[3]) / 2.0);
    let mut w = (b[1] - b[0]).max(1e-9) * 1.25;
    let mut h = (b[3] - b[2]).max(1e-9) * 1.25;
    let (dx, dy) = (f64::from(cols.max(1)) * 2.0, f64::from(rows.max(1)) * 4.0);
    if w / dx > h / dy {
        h = w / dx * dy;
    } else {
        w = h / dy * dx;
    }
    [cx - w / 2.0, cx + w / 2.0, cy - h / 2.0, cy + h / 2.0]
}

pub fn render(app: &App, scene: &Scene, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let plane = app.plane;
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(" {} · {} plane (v) ", scene.title, plane.name()),
            t.title(),
        ));
    let inner = block.inner(area);
    block.render(area, buf);
    app.targets.picture.set(inner);
    app.targets.points.borrow_mut().clear();
    if inner.width < 2 || inner.height < 2 {
        return;
    }
    let all: Vec<&BodyView> = scene.bodies.iter().chain(scene.also).collect();
    let b = fit(bounds(&all, plane), inner.width, inner.height);
    app.targets.bounds.set(b);
    let extent = (b[1] - b[0]).max(b[3] - b[2]);
    let asleep = |i: usize| scene.toggles.sleep && scene.asleep.get(i).copied().unwrap_or(false);
    let body_ink = |i: usize| {
        if asleep(i) && t.color {
            Color::DarkGray
        } else {
            t.ink(Ink::Body)
        }
    };
    let mut segs: Vec<(P, P, Color)> = vec![];
    // Labels with a rank: lower is placed first when they compete for cells.
    let mut labels: Vec<(P, String, Style, u8)> = vec![];
    if scene.toggles.bounds {
        movement_bounds(scene.movement, plane, t.ink(Ink::Arm), &mut segs);
    }
    let mut points = app.targets.points.borrow_mut();
    for (i, v) in scene.bodies.iter().enumerate() {
        match v.shape {
            Some(Shape::HalfSpace { normal }) => {
                let n = flat(plane, normal);
                let len = n[0].hypot(n[1]);
                if len < 1e-9 {
                    continue;
                }
                let n = [n[0] / len, n[1] / len];
                let along = [-n[1], n[0]];
                let q = flat(plane, v.position);
                let far = 4.0 * extent;
                let ink = t.ink(Ink::Ground);
                segs.push((
                    [q[0] - along[0] * far, q[1] - along[1] * far],
                    [q[0] + along[0] * far, q[1] + along[1] * far],
                    ink,
                ));
                let step = extent / 16.0;
                for k in -64..=64 {
                    let base = [
                        q[0] + along[0] * step * k as f64,
                        q[1] + along[1] * step * k as f64,
                    ];
                    let tip = [
                        base[0] - (n[0] - along[0]) * 0.4 * step,
                        base[1] - (n[1] - along[1]) * 0.4 * step,
                    ];
                    segs.push((base, tip, ink));
                }
            }
            Some(ref s) => {
                if let Some(o) = outline(s, v.position, v.orientation, plane) {
                    for [a, c] in &o.edges {
                        segs.push((*a, *c, body_ink(i)));
                    }
                }
                let c = flat(plane, v.position);
                points.push((c, Pick::Body(i)));
                if scene.toggles.names && v.movable {
                    let name = if asleep(i) {
                        format!("{} (asleep)", v.name)
                    } else {
                        v.name.clone()
                    };
                    labels.push((c, name, Style::new().fg(body_ink(i)), 2));
                }
            }
            None => {}
        }
    }
    for c in scene.contacts {
        let q = flat(plane, c.point);
        points.push((q, Pick::Contact(c.number)));
        let chosen = scene.selected == Some(c.number);
        let next = scene.next == Some(c.number);
        if scene.toggles.normals {
            let d = flat(plane, c.normal);
            let tip = [q[0] + d[0] * 0.08 * extent, q[1] + d[1] * 0.08 * extent];
            segs.push((q, tip, t.ink(Ink::Normal)));
        }
        if let Some(g) = c.impulse {
            // The impulse the last iteration applied to body 1, its direction.
            let g = flat(plane, g);
            let len = g[0].hypot(g[1]);
            if len > 0.0 && len.is_finite() {
                let tip = [
                    q[0] + g[0] / len * 0.15 * extent,
                    q[1] + g[1] / len * 0.15 * extent,
                ];
                segs.push((q, tip, t.ink(Ink::Impulse)));
                labels.push((tip, "g".into(), t.ink_style(Ink::Impulse), 1));
            }
        }
        if scene.toggles.contacts || chosen || next {
            let style = if next {
                t.ink_style(Ink::Impulse)
            } else if chosen {
                t.selected()
            } else {
                t.ink_style(Ink::Point)
            };
            let text = if scene.next.is_some() || scene.selected.is_some() {
                c.number.to_string()
            } else {
                "•".to_string()
            };
            let rank = if next || chosen { 0 } else { 3 };
            labels.push((q, text, style, rank));
        }
    }
    drop(points);
    draw(buf, inner, b, &segs, labels);
}

/// Line segments, then labels placed in free cells (`place`) over them, on
/// a braille canvas spanning `b` (x min, x max, y min, y max).
pub(super) fn draw(
    buf: &mut Buffer,
    inner: Rect,
    b: [f64; 4],
    segs: &[(P, P, Color)],
    labels: Vec<(P, String, Style, u8)>,
) {
    let labels = place(labels, b, inner.width, inner.height);
    Canvas::default()
        .marker(Marker::Braille)
        .background_color(Color::Reset)
        .x_bounds([b[0], b[1]])
        .y_bounds([b[2], b[3]])
        .paint(|ctx| {
            for (a, c, color) in segs {
                ctx.draw(&Line::new(a[0], a[1], c[0], c[1], *color));
            }
            ctx.layer();
            for (p, text, style) in &labels {
                ctx.print(p[0], p[1], Span::styled(text.clone(), *style));
            }
        })
        .render(inner, buf);
}

/// Each body's swept AABB (a rectangle in the view plane) and swept
/// sphere (a circle), drawn under the bodies.
fn movement_bounds(
    movement: &[Option<Movement>],
    plane: Plane,
    ink: Color,
    segs: &mut Vec<(P, P, Color)>,
) {
    for m in movement.iter().flatten() {
        let (lo, hi) = (flat(plane, m.aabb[0]), flat(plane, m.aabb[1]));
        let corners = [lo, [hi[0], lo[1]], hi, [lo[0], hi[1]]];
        for k in 0..4 {
            segs.push((corners[k], corners[(k + 1) % 4], ink));
        }
        let c = flat(plane, m.centre);
        let n = 48;
        let at = |k: usize| {
            let a = std::f64::consts::TAU * k as f64 / n as f64;
            [c[0] + m.radius * a.cos(), c[1] + m.radius * a.sin()]
        };
        for k in 0..n {
            segs.push((at(k), at(k + 1), ink));
        }
    }
}

/// Labels put in free cells, by rank: each at its point's cell or beside it
/// (right, left, the rows above and below), left out when none is free, so
/// that no label is drawn over another (issue 28 item 5). A contact that is
/// neither selected nor next (rank 3) keeps to its own cell, with a free
/// cell after it: a number moved off its point would misplace it, and
/// coincident contacts in this view are one mark.
pub(super) fn place(
    mut labels: Vec<(P, String, Style, u8)>,
    b: [f64; 4],
    cols: u16,
    rows: u16,
) -> Vec<(P, String, Style)> {
    let (w, h) = (i32::from(cols), i32::from(rows));
    let (xr, yr) = (b[1] - b[0], b[3] - b[2]);
    if w < 2 || h < 2 || !(xr > 0.0 && yr > 0.0) {
        return vec![];
    }
    labels.sort_by_key(|l| l.3);
    let mut taken = vec![false; (w * h) as usize];
    let mut out = vec![];
    for (p, text, style, rank) in labels {
        if !((b[0]..=b[1]).contains(&p[0]) && (b[2]..=b[3]).contains(&p[1])) {
            continue;
        }
        // The cell the canvas prints a label at (it truncates).
        let c = ((p[0] - b[0]) * f64::from(w - 1) / xr) as i32;
        let r = ((b[3] - p[1]) * f64::from(h - 1) / yr) as i32;
        let n = crate::tui::wrap::width(&text) as i32;
        let free = |c: i32, r: i32| {
            (0..h).contains(&r)
                && c >= 0
                && c + n <= w
                && (c..c + n).all(|x| !taken[(r * w + x) as usize])
        };
        let tries = [
            (0, 0),
            (1, 0),
            (-n, 0),
            (0, -1),
            (0, 1),
            (1, -1),
            (1, 1),
            (-n, -1),
            (-n, 1),
        ];
        let tries = if rank >= 3 { &tries[..1] } else { &tries[..] };
        let gap = i32::from(rank >= 3);
        let Some((c, r)) = tries
            .iter()
            .map(|(dc, dr)| (c + dc, r + dr))
            .find(|&(c, r)| free(c, r))
        else {
            continue;
        };
        for x in c..(c + n + gap).min(w) {
            taken[(r * w + x) as usize] = true;
        }
        // The point the canvas prints in cell (c, r).
        let x = (b[0] + (f64::from(c) + 0.01) * xr / f64::from(w - 1)).min(b[1]);
        let y = (b[3] - (f64::from(r) + 0.01) * yr / f64::from(h - 1)).max(b[2]);
        out.push(([x, y], text, style));
    }
    out
}
