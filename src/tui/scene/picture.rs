//! The figure model turned into what the canvas draws: line segments (with
//! arrow heads, spin arcs and hatching) and ranked labels, in view-plane
//! coordinates, for what predict mode has revealed so far.

use crate::render::figure::{self, flat, ArrowKind, Bounds, Figure, PointKind, P};
use crate::tui::theme::Ink;

/// One thing to draw, in plane coordinates.
#[derive(Debug)]
pub(super) enum Mark {
    Seg(P, P, Ink),
    /// Text at a point; lower `rank` is placed first when labels compete for
    /// cells; an arrow's label has the arrow's direction (a unit vector) and
    /// is put past its head, so two heads that meet keep their own labels.
    Label(P, String, Ink, u8, Option<P>),
}

pub(super) struct Picture {
    pub(super) marks: Vec<Mark>,
    /// Points that must be in view.
    keep: Bounds,
}

impl Picture {
    fn new(keep: Bounds) -> Self {
        Picture {
            marks: vec![],
            keep,
        }
    }
    fn seg(&mut self, a: P, b: P, ink: Ink) {
        self.marks.push(Mark::Seg(a, b, ink));
    }
    fn label(&mut self, at: P, text: impl Into<String>, ink: Ink, rank: u8) {
        self.marks
            .push(Mark::Label(at, text.into(), ink, rank, None));
    }

    /// An arrow from `from` along `along` with a head; a dot when it has no length.
    fn arrow(&mut self, from: P, along: P, head: f64, ink: Ink, label: &str, rank: u8) {
        let to = [from[0] + along[0], from[1] + along[1]];
        let len = along[0].hypot(along[1]);
        self.seg(from, to, ink);
        if len > 1e-12 {
            let u = scale(along, 1.0 / len);
            self.head(to, u, head.min(0.4 * len), ink);
            self.marks
                .push(Mark::Label(to, label.to_string(), ink, rank, Some(u)));
        } else {
            self.label(to, label, ink, rank);
        }
        self.keep.add(to);
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

fn add(a: P, b: P) -> P {
    [a[0] + b[0], a[1] + b[1]]
}

fn scale(a: P, s: f64) -> P {
    [a[0] * s, a[1] * s]
}

/// An arc's size as a share of the body's arc radius: from 0.3 (no spin)
/// to 1 (the fastest spin of the figure), in proportion to |ω| (|ω|/ω_max).
pub(super) fn spin_size(rate: f64, wmax: f64) -> f64 {
    if wmax > 0.0 && rate.is_finite() {
        0.3 + 0.7 * (rate.abs() / wmax).min(1.0)
    } else {
        1.0
    }
}

/// What to show, given which results predict mode still hides.
pub(super) struct Show {
    /// The stage works on the motion before the impulse.
    pub(super) before_velocity: bool,
    pub(super) impulse: bool,
    pub(super) after_velocity: bool,
    pub(super) after_pose: bool,
}

/// The theme's ink for a figure ink.
fn ink(i: figure::Ink) -> Ink {
    match i {
        figure::Ink::Body => Ink::Body,
        figure::Ink::Moved => Ink::BodyAfter,
        figure::Ink::Ground => Ink::Ground,
        figure::Ink::Point => Ink::Point,
        figure::Ink::Normal => Ink::Normal,
        figure::Ink::Arm => Ink::Arm,
        figure::Ink::Before => Ink::VelocityBefore,
        figure::Ink::After => Ink::VelocityAfter,
        figure::Ink::Impulse => Ink::Impulse,
    }
}

/// The quantity an arrow shows (zero for an arm, which reaches a point).
fn along(a: &figure::Arrow) -> P {
    match a.span {
        figure::Span::Along(v) => flat(v),
        figure::Span::To(_) => [0.0, 0.0],
    }
}

/// The marks of the figure for the screen, and the bounds they need
/// (left, right, bottom, top). Lengths are shares of the extent of the
/// bodies: heads 6 %, velocities and impulses 35 %, normals 25 %.
pub(super) fn picture(fig: &Figure, show: &Show) -> (Picture, [f64; 4]) {
    let mut pic = Picture::new(fig.bounds);
    let (lo, hi) = fig.bounds.or_unit();
    let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let extent = if extent > 1e-9 && extent.is_finite() {
        extent
    } else {
        1.0
    };
    let head = 0.06 * extent;
    let arrow_len = 0.35 * extent;

    // Half-spaces, and the immovable world of a one-body contact: where the
    // surface meets the view plane, across the whole view, hatched on the
    // solid side (none when the surface faces the viewer).
    for s in &fig.surfaces {
        let Some(section) = &s.section else {
            continue; // the surface faces the viewer
        };
        let (q, along) = (section.at, section.along);
        // n: away from the solid side, so the ticks below point into it.
        let n = scale(section.solid_side, -1.0);
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
        pic.keep.add(at);
        let name = s.body.map_or("world", |b| &fig.bodies[b].name);
        pic.label(at, name, Ink::Ground, 9);
    }
    // Bodies, and where the projection moved them.
    for b in &fig.bodies {
        if show.after_pose && b.pose_change > 0.0 {
            for [a, c] in b.outline_after.iter().flat_map(|o| &o.edges) {
                pic.seg(*a, *c, Ink::BodyAfter);
            }
        }
        for [a, c] in b.outline.iter().flat_map(|o| &o.edges) {
            pic.seg(*a, *c, Ink::Body);
        }
        if b.shape.is_none() {
            let (p, m) = (flat(b.centre), 0.03 * extent);
            pic.seg(add(p, [-m, -m]), add(p, [m, m]), Ink::Body);
            pic.seg(add(p, [-m, m]), add(p, [m, -m]), Ink::Body);
        }
    }
    let kind = |k: ArrowKind| fig.arrows.iter().filter(move |a| a.kind == k);
    // Arms r_i from each centre to q; the movable bodies' names.
    for a in kind(ArrowKind::Arm) {
        let (p, q) = (flat(a.at), flat(a.tip(1.0)));
        pic.seg(p, q, ink(a.kind.ink()));
        let middle = [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
        pic.label(middle, a.label.as_str(), ink(a.kind.ink()), 6);
    }
    for point in &fig.points {
        if let PointKind::Centre { body } = point.kind {
            if fig.bodies[body].movable {
                pic.label(flat(point.at), fig.bodies[body].name.as_str(), Ink::Body, 8);
            }
        }
    }
    // Velocities, one scale for all of them: the speeds after only once they
    // are shown (a scale set by a hidden answer would tell it in predict mode).
    let after = |x: f64| if show.after_velocity { x } else { 0.0 };
    let vmax = fig
        .bodies
        .iter()
        .filter(|b| b.movable)
        .flat_map(|b| [b.speed, after(b.speed_after)])
        .filter(|x| x.is_finite())
        .fold(0.0, f64::max);
    if vmax > 0.0 {
        let s = arrow_len / vmax;
        let velocities = fig.arrows.iter().filter(|a| match a.kind {
            ArrowKind::Velocity => true,
            ArrowKind::VelocityAfter => show.after_velocity,
            _ => false,
        });
        for a in velocities {
            let rank = if a.kind == ArrowKind::Velocity { 3 } else { 4 };
            let ink = ink(a.kind.ink());
            pic.arrow(flat(a.at), scale(along(a), s), head, ink, &a.label, rank);
        }
    }
    // Spin about the axis out of the picture: an arc, counter-clockwise
    // for a positive rate, its size growing with |ω| against the fastest
    // spin shown (the spins after count once they are revealed, as above).
    let wmax = fig
        .spins
        .iter()
        .filter(|s| show.after_velocity || !s.after)
        .map(|s| s.rate.abs())
        .filter(|w| w.is_finite())
        .fold(0.0, f64::max);
    for s in fig.spins.iter().filter(|s| show.after_velocity || !s.after) {
        let r =
            fig.bodies[s.body].spin_arc_radius.unwrap_or(0.06 * extent) * spin_size(s.rate, wmax);
        // The spin after a little inside the one before: equal rates stay apart.
        let (radius, ink) = if s.after {
            (0.85 * r, Ink::VelocityAfter)
        } else {
            (r, Ink::VelocityBefore)
        };
        if s.rate.abs() > 1e-12 && s.rate.is_finite() {
            pic.spin(flat(s.at), radius, s.rate > 0.0, head, ink, &s.label);
        }
    }
    // The normal at q.
    for a in kind(ArrowKind::Normal) {
        let d = scale(along(a), 0.25 * extent);
        pic.arrow(flat(a.at), d, head, ink(a.kind.ink()), &a.label, 1);
    }
    // The impulse: g on body 1 at q, -g on body 2 when it can move.
    if show.impulse {
        let impulses = fig
            .arrows
            .iter()
            .filter(|a| matches!(a.kind, ArrowKind::Impulse | ArrowKind::Reaction));
        for a in impulses {
            let gl = a.contact.map_or(0.0, |k| fig.contacts[k].impulse_size);
            if gl > 0.0 && gl.is_finite() {
                let g = scale(along(a), arrow_len / gl);
                pic.arrow(flat(a.at), g, head, ink(a.kind.ink()), &a.label, 2);
            }
        }
    }
    for point in &fig.points {
        if let PointKind::Contact { .. } = point.kind {
            pic.label(
                flat(point.at),
                point.label.as_str(),
                ink(figure::Ink::Point),
                0,
            );
        }
    }
    let (lo, hi) = pic.keep.or_unit();
    (pic, [lo[0], hi[0], lo[1], hi[1]])
}
