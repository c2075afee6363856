//! Contacts with a half-space: sphere, box (every vertex at or below the
//! plane) and cylinder (rim points). The shape is body A, the half-space B, so
//! the normal is the plane's normal. A sphere's contact lies midway between
//! the surfaces; a vertex's or rim point's at that point.

use nalgebra::Vector3;

use super::{c, vertex, ContactPoint, Feature, Pose, Real, Side};
use crate::physics::detect::ConvexHull;

/// Sphere of radius `r` against the half-space through `plane.position` with
/// unit world normal `n`: penetration `r - (x - x₀)·n` (the centre may even
/// be below the plane: it is a half-space, not a thin plane).
pub(super) fn sphere_plane<T: Real>(
    r: T,
    sphere: &Pose<T>,
    n: &Vector3<T>,
    plane: &Pose<T>,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let height = (sphere.position - plane.position).dot(n);
    let penetration = r - height;
    if penetration < -tol {
        return;
    }
    // The sphere's deepest point is x - r n; the plane is `penetration` above it.
    let deepest = sphere.position - n * r;
    out.push(ContactPoint {
        point: deepest + n * (penetration * c::<T>(0.5)),
        normal: *n,
        penetration,
        feature: Feature::SpherePlane { sphere: Side::A },
    });
}

/// Box of half sides `h` against a half-space: one contact per vertex at or
/// below the plane (4 when resting on a face, 2 on an edge, 1 on a corner),
/// as the reference engine's `boxAndHalfSpace`.
pub(super) fn box_plane<T: Real>(
    h: &Vector3<T>,
    cuboid: &Pose<T>,
    n: &Vector3<T>,
    plane: &Pose<T>,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let centre_height = (cuboid.position - plane.position).dot(n);
    // The box reaches Σ h_k |a_k·n| below its centre.
    let local_n = cuboid.rotation.tr_mul(n);
    let reach = h.x * local_n.x.abs() + h.y * local_n.y.abs() + h.z * local_n.z.abs();
    if centre_height - reach > tol {
        return;
    }
    for index in 0..8u8 {
        let offset = cuboid.rotation * vertex(h, index);
        push_below(
            cuboid.position + offset,
            centre_height + offset.dot(n),
            n,
            tol,
            Feature::VertexPlane {
                cuboid: Side::A,
                vertex: index,
            },
            out,
        );
    }
}

/// Convex hull against a half-space: every vertex at or below the plane
/// (exact for a polyhedron: its deepest points are vertices), as the box's
/// corners are. The plane is the reference face (side B).
pub(super) fn hull_plane<T: Real>(
    hull: &ConvexHull,
    body: &Pose<T>,
    n: &Vector3<T>,
    plane: &Pose<T>,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let feature = |_| Feature::Convex {
        reference: Some(Side::B),
    };
    vertices_plane(hull.vertices(), body, n, plane, tol, feature, out);
}

/// Body-frame `vertices` at `body` against a half-space: each at or below
/// the plane, with the feature `feature(index)`.
pub(super) fn vertices_plane<T: Real>(
    vertices: &[Vector3<f64>],
    body: &Pose<T>,
    n: &Vector3<T>,
    plane: &Pose<T>,
    tol: T,
    feature: impl Fn(usize) -> Feature,
    out: &mut Vec<ContactPoint<T>>,
) {
    let centre_height = (body.position - plane.position).dot(n);
    for (i, v) in vertices.iter().enumerate() {
        let offset = body.rotation * v.map(c::<T>);
        push_below(
            body.position + offset,
            centre_height + offset.dot(n),
            n,
            tol,
            feature(i),
            out,
        );
    }
}

/// Cylinder (radius `r`, half height `hh`, axis body y) against a half-space:
/// on each cap, the rim point deepest below the plane and the three a quarter
/// turn from it, those at or below the plane. Standing on a cap gives 4
/// points, lying on its side 2, tilted on the rim 1. (The deepest point of a
/// cylinder in any direction is on a rim, so no contact is missed.)
pub(super) fn cylinder_plane<T: Real>(
    r: T,
    hh: T,
    cylinder: &Pose<T>,
    n: &Vector3<T>,
    plane: &Pose<T>,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let centre_height = (cylinder.position - plane.position).dot(n);
    let local_n = cylinder.rotation.tr_mul(n);
    let radial = (local_n.x * local_n.x + local_n.z * local_n.z).sqrt();
    if centre_height - (hh * local_n.y.abs() + r * radial) > tol {
        return;
    }
    // Rim direction of the deepest point: against n's part across the axis
    // (any direction, here body x, when the caps lie parallel to the plane).
    let (ux, uz) = if radial > c::<T>(1e-9) {
        (-local_n.x / radial, -local_n.z / radial)
    } else {
        (T::one(), T::zero())
    };
    let quarters = [(ux, uz), (-uz, ux), (-ux, -uz), (uz, -ux)];
    for cap in 0..2u8 {
        let y = if cap == 0 { -hh } else { hh };
        for (quarter, (dx, dz)) in quarters.iter().enumerate() {
            let offset = cylinder.rotation * Vector3::new(r * *dx, y, r * *dz);
            push_below(
                cylinder.position + offset,
                centre_height + offset.dot(n),
                n,
                tol,
                Feature::RimPlane {
                    cylinder: Side::A,
                    cap,
                    quarter: quarter as u8,
                },
                out,
            );
        }
    }
}

/// A body point `at` `height` above the plane: a contact when at or below
/// (within the tolerance), at the point itself. (Midway between it and the
/// plane, as the reference engine puts it, would leave the body for every
/// vertex but the deepest: moving along n enters a box only at its support
/// vertex.)
fn push_below<T: Real>(
    at: Vector3<T>,
    height: T,
    n: &Vector3<T>,
    tol: T,
    feature: Feature,
    out: &mut Vec<ContactPoint<T>>,
) {
    let penetration = T::zero() - height; // not -0 for a point on the plane
    if penetration >= -tol {
        out.push(ContactPoint {
            point: at,
            normal: *n,
            penetration,
            feature,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{UnitQuaternion, Vector3};

    const UP: Vector3<f64> = Vector3::new(0.0, 1.0, 0.0);

    #[test]
    fn sphere_below_its_radius() {
        let mut out = Vec::new();
        let floor = Pose::at(Vector3::new(0.0, 1.0, 0.0));
        sphere_plane(
            2.0,
            &Pose::at(Vector3::new(5.0, 2.5, 0.0)),
            &UP,
            &floor,
            0.0,
            &mut out,
        );
        assert_eq!(out.len(), 1);
        assert!((out[0].penetration - 0.5).abs() < 1e-15);
        // Sphere bottom at y = 0.5, plane at 1: midway 0.75, under the centre.
        assert!((out[0].point - Vector3::new(5.0, 0.75, 0.0)).norm() < 1e-15);
        sphere_plane(
            2.0,
            &Pose::at(Vector3::new(5.0, 3.01, 0.0)),
            &UP,
            &floor,
            0.0,
            &mut out,
        );
        assert_eq!(out.len(), 1);
    }

    #[test]
    fn cylinder_standing_lying_and_tilted() {
        let floor = Pose::at(Vector3::zeros());
        let count = |pose: Pose<f64>| {
            let mut out = Vec::new();
            cylinder_plane(0.5, 1.0, &pose, &UP, &floor, 1e-12, &mut out);
            out
        };
        // Standing on its cap, sunk 0.01: four rim points at depth 0.01.
        let standing = count(Pose::at(Vector3::new(0.0, 0.99, 0.0)));
        assert_eq!(standing.len(), 4);
        assert!(standing
            .iter()
            .all(|k| (k.penetration - 0.01).abs() < 1e-12));
        // Lying on its side (axis along x), sunk 0.01: one point on each cap rim.
        let side = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2);
        let lying = count(Pose::from_unit(Vector3::new(0.0, 0.49, 0.0), &side));
        assert_eq!(lying.len(), 2);
        assert!((lying[0].point.x + lying[1].point.x).abs() < 1e-12);
        assert!((lying[0].point.x.abs() - 1.0).abs() < 1e-12);
        // Tilted 30° about z: only the deepest rim point.
        let tilt = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.5);
        let pose = Pose::from_unit(Vector3::new(0.0, 1.0, 0.0), &tilt);
        let deepest = 1.0 - (0.5 * 0.5f64.sin() + 1.0 * 0.5f64.cos());
        let tilted = count(pose);
        assert_eq!(tilted.len(), 1);
        assert!((tilted[0].penetration + deepest).abs() < 1e-12);
    }
}
