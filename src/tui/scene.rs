//! The picture (Canvas, braille): the contact's bodies to scale in the chosen
//! plane, the contact point, the normal, the arms r₁ r₂, velocities before
//! and after and the impulse, zoomed to fit. Everything comes from the
//! trace's [`SceneView`](crate::trace::SceneView); only projection and
//! scaling for the screen happen here.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::Color;
use ratatui::symbols::Marker;
use ratatui::text::{Line as TextLine, Span};
use ratatui::widgets::canvas::{Canvas, Context, Line};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

use super::app::{App, Plane};
use super::theme::{Ink, Theme};
use crate::trace::{BodyView, SceneView, ShapeView};

type P = [f64; 2];

const SUB: [&str; 3] = ["", "₁", "₂"];

/// One thing to draw, in plane coordinates.
enum Mark {
    Seg(P, P, Ink),
    /// Text at a point; lower `rank` is placed first when labels compete for cells.
    Label(P, String, Ink, u8),
}

struct Picture {
    marks: Vec<Mark>,
    /// Points that must be in view.
    keep: Vec<P>,
}

fn v3(a: [f64; 3]) -> Vector3<f64> {
    Vector3::from(a)
}

fn rotation(q: [f64; 4]) -> nalgebra::Matrix3<f64> {
    let q = Quaternion::new(q[0], q[1], q[2], q[3]);
    if q.norm() > 0.0 && q.norm().is_finite() {
        UnitQuaternion::from_quaternion(q)
            .to_rotation_matrix()
            .into_inner()
    } else {
        nalgebra::Matrix3::identity()
    }
}

impl Picture {
    fn new() -> Self {
        Picture {
            marks: vec![],
            keep: vec![],
        }
    }
    fn seg(&mut self, a: P, b: P, ink: Ink) {
        self.marks.push(Mark::Seg(a, b, ink));
    }
    fn label(&mut self, at: P, text: impl Into<String>, ink: Ink, rank: u8) {
        self.marks.push(Mark::Label(at, text.into(), ink, rank));
    }

    /// An arrow from `from` along `along` with a head; a dot when it has no length.
    fn arrow(&mut self, from: P, along: P, head: f64, ink: Ink, label: &str, rank: u8) {
        let to = [from[0] + along[0], from[1] + along[1]];
        let len = along[0].hypot(along[1]);
        self.seg(from, to, ink);
        if len > 1e-12 {
            self.head(to, scale(along, 1.0 / len), head.min(0.4 * len), ink);
        }
        self.label(to, label, ink, rank);
        self.keep.push(to);
    }

    /// Two barbs of length `h` at `to`, for a line arriving along the unit vector `u`.
    fn head(&mut self, to: P, u: P, h: f64, ink: Ink) {
        for s in [-1.0, 1.0] {
            let (c, si) = (0.93f64, 0.37f64 * s);
            let dx = -(u[0] * c - u[1] * si) * h;
            let dy = -(u[0] * si + u[1] * c) * h;
            self.seg(to, [to[0] + dx, to[1] + dy], ink);
        }
    }
}

/// A radius for a body's spin arc: inside the body, a share of the view for a marker.
fn size(shape: ShapeView, extent: f64) -> f64 {
    match shape {
        ShapeView::Sphere { radius } => 0.5 * radius,
        ShapeView::Box { sides } => 0.3 * sides.iter().copied().fold(f64::INFINITY, f64::min),
        ShapeView::Cylinder { radius, height } => 0.5 * radius.min(height / 2.0),
        ShapeView::HalfSpace | ShapeView::Marker => 0.06 * extent,
    }
}

impl Picture {
    /// A ¾ circle around `c` with an arrowhead showing the sense of turning.
    fn spin(&mut self, c: P, radius: f64, ccw: bool, head: f64, ink: Ink, label: &str) {
        let sense = if ccw { 1.0 } else { -1.0 };
        let start = std::f64::consts::FRAC_PI_4;
        let n = 24;
        let at = |i: usize| {
            let a = start + sense * 1.5 * std::f64::consts::PI * i as f64 / n as f64;
            [c[0] + radius * a.cos(), c[1] + radius * a.sin()]
        };
        for i in 0..n {
            self.seg(at(i), at(i + 1), ink);
        }
        let (end, before) = (at(n), at(n - 1));
        let along = [end[0] - before[0], end[1] - before[1]];
        let len = along[0].hypot(along[1]);
        if len > 0.0 {
            self.head(end, scale(along, 1.0 / len), head.min(0.6 * radius), ink);
        }
        self.label(at(0), label, ink, 7);
    }
}

/// Projection onto the view plane.
struct View {
    plane: Plane,
}

impl View {
    fn p(&self, v: Vector3<f64>) -> P {
        let (a, b, _) = self.plane.axes();
        [v[a], v[b]]
    }
}

/// The body's outline segments (none for a half-space, drawn separately).
fn outline(view: &View, shape: ShapeView, pos: [f64; 3], q: [f64; 4]) -> Vec<(P, P)> {
    let r = rotation(q);
    let c = v3(pos);
    let at = |local: Vector3<f64>| view.p(c + r * local);
    let ring = |radius: f64, y: f64, axis: usize| -> Vec<(P, P)> {
        let n = 32;
        (0..n)
            .map(|i| {
                let point = |i: usize| {
                    let a = std::f64::consts::TAU * i as f64 / n as f64;
                    let (s, co) = (a.sin() * radius, a.cos() * radius);
                    let local = match axis {
                        0 => Vector3::new(y, co, s),
                        1 => Vector3::new(co, y, s),
                        _ => Vector3::new(co, s, y),
                    };
                    at(local)
                };
                (point(i), point(i + 1))
            })
            .collect()
    };
    match shape {
        ShapeView::Box { sides } => {
            let h = v3(sides) / 2.0;
            let corner = |i: usize| {
                at(Vector3::new(
                    if i & 1 == 0 { -h.x } else { h.x },
                    if i & 2 == 0 { -h.y } else { h.y },
                    if i & 4 == 0 { -h.z } else { h.z },
                ))
            };
            let mut segs = vec![];
            for i in 0..8 {
                for bit in [1, 2, 4] {
                    if i & bit == 0 {
                        segs.push((corner(i), corner(i | bit)));
                    }
                }
            }
            segs
        }
        ShapeView::Sphere { radius } => {
            // The great circle facing the viewer, and a spoke to show the turn.
            let mut segs: Vec<(P, P)> = (0..48)
                .map(|i| {
                    let pt = |i: usize| {
                        let a = std::f64::consts::TAU * i as f64 / 48.0;
                        let cp = view.p(c);
                        [cp[0] + radius * a.cos(), cp[1] + radius * a.sin()]
                    };
                    (pt(i), pt(i + 1))
                })
                .collect();
            segs.push((view.p(c), at(Vector3::new(radius, 0.0, 0.0))));
            segs
        }
        ShapeView::Cylinder { radius, height } => {
            let mut segs = ring(radius, height / 2.0, 1);
            segs.extend(ring(radius, -height / 2.0, 1));
            for a in [0.0, 0.25, 0.5, 0.75].map(|f: f64| f * std::f64::consts::TAU) {
                let (x, z) = (radius * a.cos(), radius * a.sin());
                segs.push((
                    at(Vector3::new(x, height / 2.0, z)),
                    at(Vector3::new(x, -height / 2.0, z)),
                ));
            }
            segs
        }
        ShapeView::Marker | ShapeView::HalfSpace => vec![],
    }
}

fn add(a: P, b: P) -> P {
    [a[0] + b[0], a[1] + b[1]]
}

fn scale(a: P, s: f64) -> P {
    [a[0] * s, a[1] * s]
}

/// Largest length among `vs` (3D, so that the scale does not change with the plane).
fn longest<'a>(vs: impl Iterator<Item = &'a [f64; 3]>) -> f64 {
    vs.map(|v| crate::physics::scale::stable_norm(&v3(*v)))
        .filter(|x| x.is_finite())
        .fold(0.0, f64::max)
}

/// What to show, given which results predict mode still hides.
struct Show {
    impulse: bool,
    after_velocity: bool,
    after_pose: bool,
}

fn picture(scene: &SceneView, view: &View, show: &Show) -> (Picture, [f64; 4]) {
    let mut pic = Picture::new();
    let in_contact: Vec<&BodyView> = scene.bodies.iter().filter(|b| b.slot > 0).collect();
    let q = view.p(v3(scene.point));
    // The size of the scene: the contact's bodies and the contact point.
    let mut body_segs = vec![];
    for b in &in_contact {
        let segs = outline(view, b.shape, b.position, b.orientation);
        for (a, c) in &segs {
            pic.keep.push(*a);
            pic.keep.push(*c);
        }
        pic.keep.push(view.p(v3(b.position)));
        body_segs.push((b, segs));
    }
    pic.keep.push(q);
    let (lo, hi) = bounds(&pic.keep);
    let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let extent = if extent > 1e-9 && extent.is_finite() {
        extent
    } else {
        1.0
    };
    let head = 0.06 * extent;
    let arrow_len = 0.35 * extent;

    // Half-spaces, and the immovable world of a one-body contact: the
    // surface through q across the whole view, hatched on the solid side.
    let mut surfaces: Vec<(f64, String)> = in_contact
        .iter()
        .filter(|b| b.shape == ShapeView::HalfSpace)
        .map(|b| (if b.slot == 2 { 1.0 } else { -1.0 }, b.name.clone()))
        .collect();
    if !in_contact.iter().any(|b| b.slot == 2) {
        surfaces.push((1.0, "world".into()));
    }
    for (sign, name) in surfaces {
        let n = scale(view.p(v3(scene.normal)), sign);
        let len = n[0].hypot(n[1]);
        if len < 1e-9 {
            continue; // the surface faces the viewer
        }
        let n = scale(n, 1.0 / len);
        let along = [-n[1], n[0]];
        let far = 3.0 * extent;
        pic.seg(
            add(q, scale(along, -far)),
            add(q, scale(along, far)),
            Ink::Ground,
        );
        let step = extent / 8.0;
        for i in -24..=24 {
            let base = add(q, scale(along, i as f64 * step));
            let tip = add(base, scale(add(scale(n, -1.0), along), 0.35 * step));
            pic.seg(base, tip, Ink::Ground);
        }
        let at = add(q, scale(n, -0.15 * extent));
        pic.keep.push(at);
        pic.label(at, name, Ink::Ground, 9);
    }
    // Bodies, and where the projection moved them.
    for (b, segs) in &body_segs {
        let moved = b.position != b.position_after || b.orientation != b.orientation_after;
        if show.after_pose && moved {
            for (a, c) in outline(view, b.shape, b.position_after, b.orientation_after) {
                pic.seg(a, c, Ink::BodyAfter);
            }
        }
        for (a, c) in segs {
            pic.seg(*a, *c, Ink::Body);
        }
        let p = view.p(v3(b.position));
        if b.shape == ShapeView::Marker {
            let m = 0.03 * extent;
            pic.seg(add(p, [-m, -m]), add(p, [m, m]), Ink::Body);
            pic.seg(add(p, [-m, m]), add(p, [m, -m]), Ink::Body);
        }
    }
    // Arms r_i from each centre to q.
    for b in in_contact.iter().filter(|b| b.movable) {
        let p = view.p(v3(b.position));
        pic.seg(p, q, Ink::Arm);
        pic.label(
            [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0],
            format!("r{}", SUB[b.slot]),
            Ink::Arm,
            6,
        );
        pic.label(p, b.name.clone(), Ink::Body, 8);
    }
    // Velocities, one scale for all of them.
    let movers: Vec<&&BodyView> = in_contact.iter().filter(|b| b.movable).collect();
    let vmax = longest(movers.iter().flat_map(|b| [&b.velocity, &b.velocity_after]));
    if vmax > 0.0 {
        let s = arrow_len / vmax;
        for b in &movers {
            let p = view.p(v3(b.position));
            pic.arrow(
                p,
                scale(view.p(v3(b.velocity)), s),
                head,
                Ink::VelocityBefore,
                &format!("v{}", SUB[b.slot]),
                3,
            );
            if show.after_velocity {
                pic.arrow(
                    p,
                    scale(view.p(v3(b.velocity_after)), s),
                    head,
                    Ink::VelocityAfter,
                    &format!("v{}′", SUB[b.slot]),
                    4,
                );
            }
        }
    }
    // Spin about the axis out of the picture: an arc, counter-clockwise
    // for a positive component (the view axes are right-handed).
    let out_axis = view.plane.axes().2;
    for b in &movers {
        let p = view.p(v3(b.position));
        let r = size(b.shape, extent);
        let spins = [
            (
                b.angular_velocity[out_axis],
                r,
                Ink::VelocityBefore,
                "",
                true,
            ),
            (
                b.angular_velocity_after[out_axis],
                0.65 * r,
                Ink::VelocityAfter,
                "′",
                show.after_velocity,
            ),
        ];
        for (w, radius, ink, prime, shown) in spins {
            if shown && w.abs() > 1e-12 && w.is_finite() {
                let label = format!("ω{}{prime}", SUB[b.slot]);
                pic.spin(p, radius, w > 0.0, head, ink, &label);
            }
        }
    }
    // The normal at q.
    pic.arrow(
        q,
        scale(view.p(v3(scene.normal)), 0.25 * extent),
        head,
        Ink::Normal,
        "d̂",
        1,
    );
    // The impulse: g on body 1 at q, −g on body 2 when it can move.
    if let Some(g) = scene.impulse.filter(|_| show.impulse) {
        let gl = crate::physics::scale::stable_norm(&v3(g));
        if gl > 0.0 && gl.is_finite() {
            let along = scale(view.p(v3(g)), arrow_len / gl);
            pic.arrow(q, along, head, Ink::Impulse, "g", 2);
            if in_contact.iter().any(|b| b.slot == 2 && b.movable) {
                pic.arrow(q, scale(along, -1.0), head, Ink::Impulse, "−g", 2);
            }
        }
    }
    pic.label(q, "q", Ink::Point, 0);
    let (lo, hi) = bounds(&pic.keep);
    (pic, [lo[0], hi[0], lo[1], hi[1]])
}

fn bounds(points: &[P]) -> (P, P) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in points
        .iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
    {
        for i in 0..2 {
            lo[i] = lo[i].min(p[i]);
            hi[i] = hi[i].max(p[i]);
        }
    }
    if lo[0] > hi[0] {
        return ([-1.0, -1.0], [1.0, 1.0]);
    }
    (lo, hi)
}

/// Bounds with a margin, widened so a braille dot is as wide as it is tall
/// (a cell is 2 × 4 dots and about twice as tall as wide).
fn fit(b: [f64; 4], cols: u16, rows: u16) -> ([f64; 2], [f64; 2]) {
    let (cx, cy) = ((b[0] + b[1]) / 2.0, (b[2] + b[3]) / 2.0);
    let mut w = (b[1] - b[0]).max(1e-9) * 1.15;
    let mut h = (b[3] - b[2]).max(1e-9) * 1.15;
    let (dx, dy) = (f64::from(cols.max(1)) * 2.0, f64::from(rows.max(1)) * 4.0);
    if w / dx > h / dy {
        h = w / dx * dy;
    } else {
        w = h / dy * dx;
    }
    ([cx - w / 2.0, cx + w / 2.0], [cy - h / 2.0, cy + h / 2.0])
}

/// Puts each label in free cells near its point: first by rank, trying the cell itself,
/// then its neighbours; a label with no free place nearby is left out.
fn place_labels(
    marks: &[Mark],
    xb: [f64; 2],
    yb: [f64; 2],
    cols: u16,
    rows: u16,
) -> Vec<(P, String, Ink)> {
    let (w, h) = (i32::from(cols), i32::from(rows));
    let (xr, yr) = (xb[1] - xb[0], yb[1] - yb[0]);
    if w < 2 || h < 2 || xr <= 0.0 || yr <= 0.0 {
        return vec![];
    }
    let mut labels: Vec<(&P, &String, Ink, u8)> = marks
        .iter()
        .filter_map(|m| match m {
            Mark::Label(p, text, ink, rank) => Some((p, text, *ink, *rank)),
            Mark::Seg(..) => None,
        })
        .collect();
    labels.sort_by_key(|l| l.3);
    let mut taken = vec![false; (w * h) as usize];
    let mut out = vec![];
    for (p, text, ink, _) in labels {
        if !(xb[0]..=xb[1]).contains(&p[0]) || !(yb[0]..=yb[1]).contains(&p[1]) {
            continue;
        }
        // The cell of the braille dot the point is drawn at (2 × 4 dots a cell).
        let c = ((p[0] - xb[0]) * f64::from(2 * w - 1) / xr).round() as i32 / 2;
        let r = ((yb[1] - p[1]) * f64::from(4 * h - 1) / yr).round() as i32 / 4;
        let n = super::wrap::width(text) as i32;
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
            (2, 0),
            (-n - 1, 0),
        ];
        let free = |c: i32, r: i32| {
            r >= 0
                && r < h
                && c >= 0
                && c + n <= w
                && (c..c + n).all(|x| !taken[(r * w + x) as usize])
        };
        if let Some((c, r)) = tries
            .iter()
            .map(|(dc, dr)| (c + dc, r + dr))
            .find(|&(c, r)| free(c, r))
        {
            for x in c..c + n {
                taken[(r * w + x) as usize] = true;
            }
            // A point the canvas prints in cell (c, r): labels map with
            // (cells − 1) steps, unlike the dots.
            let x = (xb[0] + (f64::from(c) + 0.01) * xr / f64::from(w - 1)).min(xb[1]);
            let y = (yb[1] - (f64::from(r) + 0.01) * yr / f64::from(h - 1)).max(yb[0]);
            out.push(([x, y], text.clone(), ink));
        }
    }
    out
}

/// The key to the picture's colours and labels; `compact` keeps to the symbols.
fn legend(t: &Theme, show: &Show, moved: bool, compact: bool) -> TextLine<'static> {
    let mut items = vec![(Ink::VelocityBefore, "v", "before")];
    if show.after_velocity {
        items.push((Ink::VelocityAfter, "v′", "after"));
    }
    if show.impulse {
        items.push((Ink::Impulse, "g", "impulse"));
    }
    items.push((Ink::Normal, "d̂", "normal"));
    items.push((Ink::Arm, "r", "arm"));
    if show.after_pose && moved {
        items.push((Ink::BodyAfter, "▒", "after projection"));
    }
    let mut spans = vec![];
    for (ink, sym, what) in items {
        spans.push(Span::styled(sym, t.ink_style(ink)));
        if compact {
            spans.push(Span::raw(" "));
        } else {
            spans.push(Span::raw(format!(" {what}  ")));
        }
    }
    TextLine::from(spans)
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let t = &app.theme;
    let block = Block::bordered()
        .border_style(t.border())
        .title(Span::styled(
            format!(" Scene · {} plane (v) ", app.plane.name()),
            t.title(),
        ));
    let inner = block.inner(area);
    block.render(area, buf);
    let show = Show {
        impulse: app.shown("impulse") && app.shown("friction_clamp"),
        after_velocity: app.shown("apply_impulse"),
        after_pose: app.shown("nonlinear_projection") && app.shown("orientation_update"),
    };
    let moved = app.trace.scene.bodies.iter().any(|b| {
        b.slot > 0 && (b.position != b.position_after || b.orientation != b.orientation_after)
    });
    let full = legend(t, &show, moved, false);
    let rows_for = |l: &TextLine| (l.width() as u16).div_ceil(inner.width.max(1));
    let (legend, legend_rows) = if inner.height >= rows_for(&full) + 8 {
        let r = rows_for(&full);
        (full, r)
    } else {
        let compact = legend(t, &show, moved, true);
        (compact, u16::from(inner.height >= 5))
    };
    let [canvas_area, legend_area] =
        Layout::vertical([Constraint::Fill(1), Constraint::Length(legend_rows)]).areas(inner);
    Paragraph::new(legend)
        .wrap(Wrap { trim: true })
        .render(legend_area, buf);
    if canvas_area.width < 2 || canvas_area.height < 2 {
        return;
    }
    let view = View { plane: app.plane };
    let (pic, b) = picture(&app.trace.scene, &view, &show);
    let (xb, yb) = fit(b, canvas_area.width, canvas_area.height);
    let color = |ink: Ink| t.ink(ink);
    let labels = place_labels(&pic.marks, xb, yb, canvas_area.width, canvas_area.height);
    let paint = |ctx: &mut Context| {
        for m in &pic.marks {
            if let Mark::Seg(a, c, ink) = m {
                ctx.draw(&Line::new(a[0], a[1], c[0], c[1], color(*ink)));
            }
        }
        ctx.layer();
        for (at, text, ink) in &labels {
            ctx.print(at[0], at[1], Span::styled(text.clone(), t.ink_style(*ink)));
        }
    };
    Canvas::default()
        .marker(Marker::Braille)
        .background_color(Color::Reset)
        .x_bounds(xb)
        .y_bounds(yb)
        .paint(paint)
        .render(canvas_area, buf);
}
