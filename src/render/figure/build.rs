//! Building a [`Figure`] from the trace's bodies and contacts: projection
//! into view coordinates, outlines, the marks of each contact and body, the
//! legend and the bounds.

use super::model::*;
use nalgebra::Vector3;

use super::outline::{outline, rotation, spin_arc_radius, surface_distance};
use super::view::{flat, V};
use crate::physics::Shape;
use crate::trace::{BodyView, ContactView, Plane};

const SUB: [&str; 3] = ["", "₁", "₂"];

/// |v|, scale-invariant (no underflow below 1e-154, no overflow above 1e154).
fn norm(v: [f64; 3]) -> f64 {
    crate::physics::scale::stable_norm_of(&v)
}

fn minus(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Subscript digits of `n`.
fn subscript(n: usize) -> String {
    n.to_string()
        .chars()
        .map(|d| char::from_u32(0x2080 + d.to_digit(10).unwrap_or(0)).unwrap_or('?'))
        .collect()
}

/// The largest change of a position or orientation component.
fn pose_change(b: &BodyView) -> f64 {
    let dp = (0..3)
        .map(|i| (b.position_after[i] - b.position[i]).abs())
        .fold(0.0, f64::max);
    let dq = (0..4)
        .map(|i| (b.orientation_after[i] - b.orientation[i]).abs())
        .fold(0.0, f64::max);
    dp.max(dq)
}

pub(super) fn build(bodies: &[&BodyView], contacts: &[ContactView], plane: Plane) -> Figure {
    let marks: Vec<BodyMarks> = (0..bodies.len())
        .map(|i| body_marks(bodies[i], i, contacts, plane))
        .collect();
    let mut fig = Figure {
        plane,
        contacts: vec![],
        surfaces: vec![],
        arrows: vec![],
        spins: vec![],
        points: vec![],
        legend: vec![],
        corrected: None,
        bounds: Bounds::default(),
        scene_length: 1.0,
        top_speed: marks
            .iter()
            .flat_map(|b| [b.speed, b.speed_after])
            .fold(0.0, f64::max),
        bodies: marks,
    };
    for (k, c) in contacts.iter().enumerate() {
        contact_marks(&mut fig, k, c, bodies, contacts.len() == 1);
    }
    motion_marks(&mut fig, bodies);
    for (i, b) in fig.bodies.iter().enumerate() {
        if b.movable || b.shape.as_ref().is_none_or(|s| s.is_finite()) {
            let kind = PointKind::Centre { body: i };
            let label = format!("p{}", b.tag);
            fig.points.push(Point {
                kind,
                at: b.centre,
                label,
            });
        }
    }
    for (k, c) in fig.contacts.iter().enumerate() {
        let kind = PointKind::Contact { contact: k };
        let label = c.label.clone();
        fig.points.push(Point {
            kind,
            at: c.point,
            label,
        });
    }
    fig.bounds = bounds(&fig);
    fig.scene_length = scene_length(&fig, bodies, contacts);
    fig.legend = legend(&fig, bodies, contacts);
    fig
}

/// Where the plane through `on` with outward normal `outward` (world) meets
/// the view plane through `q`: the line `n_u u + n_v v = n·on - n_w q_w`,
/// its point nearest q, and the solid side (-n); `None` when the normal's
/// share in the view plane is below [`FACE_ON`] (the plane faces the viewer).
pub(super) fn section(
    plane: Plane,
    on: [f64; 3],
    outward: [f64; 3],
    q: [f64; 3],
) -> Option<Section> {
    let size = norm(outward);
    if !(size > 0.0 && size.is_finite()) {
        return None;
    }
    let n = view(plane, outward.map(|x| x / size));
    let (o, q) = (view(plane, on), view(plane, q));
    let len = n[0].hypot(n[1]);
    if len < FACE_ON {
        return None;
    }
    let c = n[0] * o[0] + n[1] * o[1] + n[2] * o[2] - n[2] * q[2];
    let off = (n[0] * q[0] + n[1] * q[1] - c) / (len * len);
    Some(Section {
        at: [q[0] - off * n[0], q[1] - off * n[1]],
        along: [-n[1] / len, n[0] / len],
        solid_side: [-n[0] / len, -n[1] / len],
    })
}

/// Projection of a world vector into view coordinates.
fn view(plane: Plane, x: [f64; 3]) -> V {
    let (u, v, w) = plane.axes();
    [x[u], x[v], x[w]]
}

/// Body `i`: its outlines before and after, its sizes and speeds; numbered
/// 1 or 2 when the figure has one contact.
fn body_marks(b: &BodyView, i: usize, contacts: &[ContactView], plane: Plane) -> BodyMarks {
    let slot = match contacts {
        [c] => c
            .bodies
            .iter()
            .position(|s| *s == Some(i))
            .map_or(0, |s| s + 1),
        _ => 0,
    };
    let pose_change = pose_change(b);
    let at = |p, q| b.shape.as_ref().and_then(|s| outline(s, p, q, plane));
    BodyMarks {
        name: b.name.clone(),
        movable: b.movable,
        slot,
        tag: SUB[slot.min(2)],
        shape: b.shape.clone(),
        centre: view(plane, b.position),
        centre_after: view(plane, b.position_after),
        outline: at(b.position, b.orientation),
        outline_after: if pose_change > 0.0 {
            at(b.position_after, b.orientation_after)
        } else {
            None
        },
        pose_change,
        travel: norm(minus(b.position_after, b.position)),
        bounding_radius: b
            .shape
            .as_ref()
            .and_then(|s| s.bounding_radius())
            .unwrap_or(0.0),
        spin_arc_radius: b.shape.as_ref().and_then(spin_arc_radius),
        speed: norm(b.velocity),
        speed_after: norm(b.velocity_after),
    }
}

/// Contact `k`: its marks, the surfaces through it, and its arrows: the
/// arms of its movable bodies (in body order), d̂, g and -g.
fn contact_marks(fig: &mut Figure, k: usize, c: &ContactView, bodies: &[&BodyView], one: bool) {
    let tag = if one {
        String::new()
    } else {
        subscript(c.number)
    };
    let point = view(fig.plane, c.point);
    let impulse = c.impulse.map(|g| view(fig.plane, g));
    fig.contacts.push(ContactMarks {
        number: c.number,
        bodies: c.bodies,
        point,
        normal: view(fig.plane, c.normal),
        penetration: c.penetration,
        impulse,
        impulse_size: c.impulse.map_or(0.0, norm),
        label: format!("q{tag}"),
    });
    // Half-spaces (solid on body 1's side, +d̂, or body 2's, -d̂), each
    // drawn as its own plane, then the world (through q, across d̂).
    for (i, b) in bodies.iter().enumerate() {
        if let Some(&Shape::HalfSpace { normal }) =
            b.shape.as_ref().filter(|_| c.bodies.contains(&Some(i)))
        {
            let solid = if c.bodies[0] == Some(i) { 1.0 } else { -1.0 };
            let outward = rotation(b.orientation) * Vector3::from(normal);
            let outward = [outward.x, outward.y, outward.z];
            fig.surfaces.push(Surface {
                contact: k,
                body: Some(i),
                solid,
                section: section(fig.plane, b.position, outward, c.point),
            });
        }
    }
    if c.bodies[1].is_none() {
        fig.surfaces.push(Surface {
            contact: k,
            body: None,
            solid: -1.0,
            section: section(fig.plane, c.point, c.normal, c.point),
        });
    }
    let mut arrows = vec![];
    let mut arrow = |kind, at, span, label: String, body| {
        let contact = Some(k);
        arrows.push(Arrow {
            kind,
            at,
            span,
            label,
            body,
            contact,
        });
    };
    for i in (0..bodies.len()).filter(|i| bodies[*i].movable && c.bodies.contains(&Some(*i))) {
        let (from, r) = (fig.bodies[i].centre, format!("r{}", fig.bodies[i].tag));
        arrow(ArrowKind::Arm, from, Span::To(point), r, Some(i));
    }
    let d = Span::Along(view(fig.plane, c.normal));
    arrow(ArrowKind::Normal, point, d, format!("d̂{tag}"), None);
    if let Some(g) = impulse {
        arrow(
            ArrowKind::Impulse,
            point,
            Span::Along(g),
            format!("g{tag}"),
            c.bodies[0],
        );
        if let Some(b2) = c.bodies[1].filter(|i| bodies[*i].movable) {
            let minus_g = Span::Along(g.map(|x| -x));
            arrow(
                ArrowKind::Reaction,
                point,
                minus_g,
                format!("-g{tag}"),
                Some(b2),
            );
        }
    }
    fig.arrows.extend(arrows);
}

/// Each movable body's velocity arrows (before, after) and its spins about
/// the view axis (positive: counter-clockwise, the view being right-handed).
fn motion_marks(fig: &mut Figure, bodies: &[&BodyView]) {
    let w = fig.plane.axes().2;
    for (i, b) in bodies.iter().enumerate().filter(|(_, b)| b.movable) {
        let (at, tag) = (fig.bodies[i].centre, fig.bodies[i].tag);
        for (kind, vel, prime) in [
            (ArrowKind::Velocity, b.velocity, ""),
            (ArrowKind::VelocityAfter, b.velocity_after, "′"),
        ] {
            fig.arrows.push(Arrow {
                kind,
                at,
                span: Span::Along(view(fig.plane, vel)),
                label: format!("v{tag}{prime}"),
                body: Some(i),
                contact: None,
            });
        }
        for (rate, after, prime) in [
            (b.angular_velocity[w], false, ""),
            (b.angular_velocity_after[w], true, "′"),
        ] {
            if rate != 0.0 {
                let label = format!("ω{tag}{prime}");
                let body = i;
                fig.spins.push(Spin {
                    body,
                    at,
                    rate,
                    after,
                    label,
                });
            }
        }
    }
}

/// The scene before it is resolved: every outline edge and centre (in body
/// order), then the contact points.
fn bounds(fig: &Figure) -> Bounds {
    let mut bounds = Bounds::default();
    for b in &fig.bodies {
        for e in b.outline.iter().flat_map(|o| &o.edges) {
            bounds.add(e[0]);
            bounds.add(e[1]);
        }
        bounds.add(flat(b.centre));
    }
    for c in &fig.contacts {
        bounds.add(flat(c.point));
    }
    bounds
}

/// The largest bounding radius, else the longest arm, else 1.
fn scene_length(fig: &Figure, bodies: &[&BodyView], contacts: &[ContactView]) -> f64 {
    let shapes = fig
        .bodies
        .iter()
        .map(|b| b.bounding_radius)
        .fold(0.0, f64::max);
    let arms = contacts
        .iter()
        .flat_map(|c| c.bodies.iter().flatten().map(move |i| (c, *i)))
        .filter(|(_, i)| bodies[*i].movable)
        .map(|(c, i)| norm(minus(c.point, bodies[i].position)))
        .fold(0.0, f64::max);
    [shapes, arms, 1.0]
        .into_iter()
        .find(|x| *x > 1e-9)
        .unwrap_or(1.0)
}

fn legend(fig: &Figure, bodies: &[&BodyView], contacts: &[ContactView]) -> Vec<LegendItem> {
    let mut items: Vec<LegendItem> = (0..bodies.len())
        .map(|body| LegendItem::Body { body })
        .collect();
    for (k, c) in contacts.iter().enumerate() {
        items.push(LegendItem::ContactPoint {
            contact: k,
            at: c.point,
        });
        items.push(LegendItem::Normal {
            contact: k,
            direction: c.normal,
        });
        if let Some(impulse) = c.impulse {
            items.push(LegendItem::Impulse {
                contact: k,
                impulse,
            });
            if c.bodies
                .iter()
                .flatten()
                .filter(|i| bodies[**i].movable)
                .count()
                == 2
            {
                items.push(LegendItem::Reaction { contact: k });
            }
        }
    }
    for (body, b) in bodies.iter().enumerate().filter(|(_, b)| b.movable) {
        for (contact, c) in contacts.iter().enumerate() {
            if c.bodies.contains(&Some(body)) {
                let arm = minus(c.point, b.position);
                items.push(LegendItem::Arm { contact, body, arm });
            }
        }
        let marks = &fig.bodies[body];
        if marks.speed > 0.0 || marks.speed_after > 0.0 {
            let (before, after) = (b.velocity, b.velocity_after);
            items.push(LegendItem::Velocity {
                body,
                before,
                after,
            });
        }
        let (before, after) = (b.angular_velocity, b.angular_velocity_after);
        // Any spin at all: the renderer's legend says which are worth a
        // line at the speeds its stage shows (`Figure::spin_line`).
        if [before, after].iter().any(|w| norm(*w) > 0.0) {
            items.push(LegendItem::Spin {
                body,
                before,
                after,
            });
        }
    }
    for (body, b) in fig.bodies.iter().enumerate() {
        if fig.beyond(b) {
            items.push(LegendItem::Travel {
                body,
                distance: b.travel,
            });
        }
    }
    if fig.bodies.iter().any(BodyMarks::moved) {
        items.push(LegendItem::Moved);
    }
    items.push(LegendItem::Scales);
    for (contact, c) in contacts.iter().enumerate() {
        for (body, b) in bodies.iter().enumerate() {
            if !c.bodies.contains(&Some(body)) {
                continue;
            }
            let Some(s) = &b.shape else { continue };
            let Some(distance) = surface_distance(s, b.position, b.orientation, c.point) else {
                continue;
            };
            if distance.abs() > c.penetration.max(0.0) + 0.02 * fig.scene_length {
                items.push(LegendItem::OffSurface {
                    contact,
                    body,
                    distance,
                });
            }
        }
    }
    items
}
