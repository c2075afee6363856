//! A mesh against a convex shape and against a half-space.
//!
//! Convex shape (A) against a mesh (B): the mid phase ([`mesh_convex`]:
//! the shape's box down the mesh's tree, each candidate triangle's GJK/EPA,
//! the normal corrected on internal edges unless `[world] internal_edges =
//! "raw"`). Each triangle within the tolerance gives its contacts: when its
//! normal is the triangle's face normal, the shape's routine against the
//! triangle's plane (a box's vertices, a cylinder's rim points, a sphere's
//! lowest point…) keeping the points over the triangle; otherwise, or when
//! none is over it, the narrow phase's one point, midway. Points two
//! triangles share (on their seam) are kept once, the deepest.
//!
//! A mesh against a half-space: its vertices at or below the plane (the
//! deepest points of any solid are among its vertices).

use nalgebra::{Matrix3, Vector3};

use super::{c, narrow, ContactPoint, Feature, Options, Pose, Side};
use crate::physics::detect::Convex;
use crate::physics::mesh::query::mesh_convex;
use crate::physics::mesh::TriMesh;
use crate::physics::{to_f64, Real, Shape};

/// Appends the contacts of the convex `shape` (body A) against `mesh` (body B).
pub(super) fn convex_mesh<T: Real>(
    (shape, pa): (&Shape, &Pose<T>),
    (mesh, pb): (&TriMesh, &Pose<T>),
    options: &Options<T>,
    out: &mut Vec<ContactPoint<T>>,
) {
    let Some(convex) = Convex::from_shape(shape) else {
        return;
    };
    let tol = to_f64(options.tolerance).max(0.0);
    let fix = options.internal_edges == super::InternalEdges::Corrected;
    let (pose_a, pose_b) = (to_f64_pose(pa), to_f64_pose(pb));
    let q = mesh_convex(&convex, &pose_a, mesh, &pose_b, tol, fix);
    let start = out.len();
    let size = 1e-9 * (shape.bounding_radius().unwrap_or(1.0) + mesh.bounding_radius());
    for test in q
        .triangles
        .iter()
        .filter(|t| t.penetration > 0.0 || t.distance <= tol)
    {
        let corners = mesh.corners(test.triangle).map(|v| pose_b.to_world(&v));
        let face = pose_b.rotation * mesh.normal(test.triangle);
        let feature = Feature::Triangle {
            mesh: Side::B,
            triangle: test.triangle,
        };
        let mut found = vec![];
        if test.normal.dot(&face) > 1.0 - 1e-9 {
            // The shape against the triangle's plane, the points over it.
            let plane = Shape::HalfSpace {
                normal: face.into(),
            };
            let plane_pose = Pose::at(corners[0].map(c::<T>));
            narrow((shape, pa), (&plane, &plane_pose), options, &mut found);
            found.retain(|k| over(&to_f64_vec(&k.point), &corners, &face, size));
        }
        if found.is_empty() {
            let penetration = if test.penetration > 0.0 {
                test.penetration
            } else {
                -test.distance
            };
            found.push(ContactPoint {
                point: ((test.point_a + test.point_b) * 0.5).map(c::<T>),
                normal: test.normal.map(c::<T>),
                penetration: c(penetration),
                feature,
            });
        }
        for mut k in found {
            k.feature = feature;
            let same = out[start..]
                .iter_mut()
                .find(|o| to_f64_vec(&(o.point - k.point)).norm() <= size);
            match same {
                Some(o) if o.penetration < k.penetration => *o = k,
                Some(_) => {}
                None => out.push(k),
            }
        }
    }
}

/// Whether `p` lies over the triangle (its projection on the plane inside
/// it, with a rounding's slack).
fn over(p: &Vector3<f64>, [a, b, c]: &[Vector3<f64>; 3], n: &Vector3<f64>, slack: f64) -> bool {
    [(a, b), (b, c), (c, a)]
        .iter()
        .all(|(u, v)| (*v - *u).cross(&(p - *u)).dot(n) >= -slack * (*v - *u).norm())
}

/// The vertices of `mesh` (body A) at or below the half-space B.
pub(super) fn mesh_plane<T: Real>(
    mesh: &TriMesh,
    body: &Pose<T>,
    n: &Vector3<T>,
    plane: &Pose<T>,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let feature = |v: usize| Feature::Triangle {
        mesh: Side::A,
        triangle: vertex_triangle(mesh, v),
    };
    super::plane::vertices_plane(mesh.vertices(), body, n, plane, tol, feature, out);
}

/// A triangle that has vertex `v` (every vertex of a valid mesh has one).
fn vertex_triangle(mesh: &TriMesh, v: usize) -> usize {
    (mesh.triangles().iter())
        .position(|t| t.contains(&v))
        .unwrap_or(0)
}

fn to_f64_vec<T: Real>(v: &Vector3<T>) -> Vector3<f64> {
    v.map(to_f64)
}

fn to_f64_pose<T: Real>(p: &Pose<T>) -> Pose<f64> {
    Pose {
        position: to_f64_vec(&p.position),
        rotation: Matrix3::from_fn(|r, k| to_f64(p.rotation[(r, k)])),
    }
}
