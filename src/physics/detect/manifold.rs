//! A contact manifold for a resting pair: the two support faces along the
//! penetration normal; the one more aligned with it is the reference face,
//! the other (the incident face) is clipped against the reference face's side
//! planes (Sutherland–Hodgman), and the clipped points below the reference
//! face and inside the reference body are the contacts, each with its own
//! depth n_ref·(r₀ − q). More than 4 are reduced to 4: the deepest, the
//! farthest from it, the one making the largest triangle with them, and the
//! one adding the most area beyond that triangle. Boxes, hulls and cylinder
//! caps (see [`CAP_SIDES`]) are polygons; a cylinder's or capsule's side is
//! a segment, clipped the same way; two parallel sides get their overlap's
//! two ends (`segments.rs`). Where neither face is a polygon (spheres,
//! capsule ends, two sides not parallel), the single point of the
//! penetration is the manifold; so it is where no polygon face
//! lies within 1° of the normal (two edges crossing).

use nalgebra::Vector3;

pub use super::manifold_point::ManifoldPoint;
use super::query::Penetration;
use super::support::Convex;
pub use super::support_face::CAP_SIDES;
use super::support_face::{outside_by, support_face, SupportFace};
use crate::physics::pose::{Pose, Side};
use crate::physics::{c, Real};

/// The manifold of `a` at `pose_a` and `b` at `pose_b` overlapping as `pen` says.
pub fn manifold<T: Real>(
    a: &Convex,
    pose_a: &Pose<T>,
    b: &Convex,
    pose_b: &Pose<T>,
    pen: &Penetration<T>,
) -> Vec<ManifoldPoint<T>> {
    manifold_within(a, pose_a, b, pose_b, pen, T::zero())
}

/// [`manifold`] keeping, besides the points below the reference face, those
/// above it by a rounding error's worth (a millionth of the reference
/// face's size, at most `margin`; their penetration is then a tiny gap).
/// Without them a face resting on a face loses a corner whenever it tilts
/// by a rounding error (a tetrahedron on a box: its third corner 7e-13 m
/// up after one step) and the body tips about the corners left. Points
/// farther up, in the contact margin's gap, are still dropped: resolved as
/// touching they would let a kicked body climb into the margin; but the
/// ends of an incident segment (a side lying on a face) are kept up to the
/// margin, and two parallel sides get their overlap's two ends
/// (`segments.rs`).
pub fn manifold_within<T: Real>(
    a: &Convex,
    pose_a: &Pose<T>,
    b: &Convex,
    pose_b: &Pose<T>,
    pen: &Penetration<T>,
    margin: T,
) -> Vec<ManifoldPoint<T>> {
    let single = vec![ManifoldPoint {
        point: pen.point,
        normal: pen.normal,
        penetration: pen.depth,
        reference: None,
    }];
    let n = pen.normal;
    let fa = support_face(a, pose_a, &-n);
    let fb = support_face(b, pose_b, &n);
    let (align_a, align_b) = (fa.normal.dot(&-n), fb.normal.dot(&n));
    // No face lies across the normal (two boxes crossed edge to edge: each
    // support face is 45° off it): a face clipped anyway would give its own
    // tilted normal, so the penetration's point is the contact. A reference
    // face must be within 1° of the normal (cos 1° = 0.99985).
    let polygon = |f: &SupportFace<T>, align: T| f.points.len() >= 3 && align >= c(0.99985);
    if !polygon(&fa, align_a) && !polygon(&fb, align_b) {
        // Two sides (capsule or cylinder) lying parallel: their overlap's
        // two ends, so that the pair does not rest on one point and roll.
        if fa.points.len() == 2 && fb.points.len() == 2 {
            if let Some(two) = super::segments::parallel_sides(&fa.points, &fb.points, pen, margin)
            {
                return two;
            }
        }
        return single;
    }
    let (reference, incident, side) = match (fa.points.len() >= 3, fb.points.len() >= 3) {
        (true, true) if align_a > align_b + c(1e-9) => (fa, fb, Side::A),
        (_, true) => (fb, fa, Side::B),
        (true, false) => (fa, fb, Side::A),
        (false, false) => return single,
    };
    if incident.points.len() == 1 {
        return single;
    }
    let normal = if side == Side::B {
        reference.normal
    } else {
        -reference.normal
    };
    let (ref_shape, ref_pose) = match side {
        Side::A => (a, pose_a),
        Side::B => (b, pose_b),
    };
    let clipped = clip(&incident.points, &reference);
    let size = reference
        .points
        .iter()
        .map(|p| (p - reference.points[0]).norm())
        .fold(pen.depth, T::max);
    // An incident segment (a capsule's or cylinder's side on a face) keeps
    // both ends up to the margin: a line contact has no third point to
    // lean on, and with one end dropped at a tilt of a few µrad the body
    // tips over the other (a tetrahedron on a lying capsule rolled off).
    let keep = margin.max(T::zero());
    let keep = if incident.points.len() == 2 {
        keep
    } else {
        keep.min(c::<T>(1e-6) * size)
    };
    let tol = c::<T>(1e-9) * size + keep;
    let r0 = reference.points[0];
    let mut points: Vec<ManifoldPoint<T>> = clipped
        .into_iter()
        .map(|q| ManifoldPoint {
            point: q,
            normal,
            penetration: reference.normal.dot(&(r0 - q)),
            reference: Some(side),
        })
        .filter(|m| m.penetration >= -tol)
        // Below the reference face and within its side planes, a point can
        // still lie outside the reference body through a slanted side (a
        // hull's; a deep pair): it touches nothing there.
        .filter(|m| outside_by(ref_shape, ref_pose, &m.point) <= tol)
        .collect();
    if points.is_empty() {
        return single;
    }
    if points.len() > 4 {
        points = reduce(&points, &reference.normal);
    }
    points
}

/// The incident polygon (or segment) clipped against each side plane of the
/// reference polygon: the plane through edge p→q with outward normal (q − p) × n.
fn clip<T: Real>(incident: &[Vector3<T>], reference: &SupportFace<T>) -> Vec<Vector3<T>> {
    let rp = &reference.points;
    let mut poly: Vec<Vector3<T>> = incident.to_vec();
    let closed = poly.len() >= 3;
    for k in 0..rp.len() {
        let (p, q) = (rp[k], rp[(k + 1) % rp.len()]);
        let side = (q - p).cross(&reference.normal);
        let dist = |x: &Vector3<T>| side.dot(&(x - p));
        let mut out = Vec::with_capacity(poly.len() + 1);
        let m = poly.len();
        let edges = if closed { m } else { m.saturating_sub(1) };
        if !closed && m == 1 && dist(&poly[0]) <= T::zero() {
            out.push(poly[0]);
        }
        for e in 0..edges {
            let (s, t) = (poly[e], poly[(e + 1) % m]);
            let (ds, dt) = (dist(&s), dist(&t));
            if ds <= T::zero() && (closed || e == 0) {
                out.push(s);
            }
            if (ds < T::zero()) != (dt < T::zero()) && ds != dt {
                out.push(s + (t - s) * (ds / (ds - dt)));
            }
            if !closed && dt <= T::zero() {
                out.push(t);
            }
        }
        poly = out;
        if poly.is_empty() {
            break;
        }
    }
    poly
}

/// Four of the points spanning the largest area, the deepest first.
fn reduce<T: Real>(points: &[ManifoldPoint<T>], n: &Vector3<T>) -> Vec<ManifoldPoint<T>> {
    let argmax = |f: &dyn Fn(&ManifoldPoint<T>) -> T| {
        (0..points.len())
            .max_by(|&i, &j| {
                f(&points[i])
                    .partial_cmp(&f(&points[j]))
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
            .unwrap_or(0)
    };
    let i0 = argmax(&|m| m.penetration);
    let p0 = points[i0].point;
    let i1 = argmax(&|m| (m.point - p0).norm_squared());
    let p1 = points[i1].point;
    // Signed area of (x, y, z) about the reference normal.
    let area = |x: &Vector3<T>, y: &Vector3<T>, z: &Vector3<T>| (y - x).cross(&(z - x)).dot(n);
    let i2 = argmax(&|m| area(&p0, &p1, &m.point).abs());
    let p2 = points[i2].point;
    let orient = if area(&p0, &p1, &p2) < T::zero() {
        -T::one()
    } else {
        T::one()
    };
    // The point farthest outside one of the triangle's edges.
    let i3 = argmax(&|m| {
        let q = m.point;
        [(p0, p1), (p1, p2), (p2, p0)]
            .iter()
            .map(|(x, y)| -orient * area(x, y, &q))
            .fold(T::min_value().unwrap_or(-T::one()), T::max)
    });
    let mut keep = vec![i0];
    for i in [i1, i2, i3] {
        if !keep.contains(&i) {
            keep.push(i);
        }
    }
    keep.into_iter().map(|i| points[i]).collect()
}
