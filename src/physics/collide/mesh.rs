//! A mesh against a convex shape and against a half-space.
//!
//! Convex shape (A) against a mesh (B): the mid phase ([`mesh_convex`]:
//! the shape's box down the mesh's tree, each candidate triangle's GJK/EPA,
//! the normal corrected on internal edges unless `[world] internal_edges =
//! "raw"`). Each triangle within the tolerance gives its contacts: when its
//! normal is the triangle's face normal, the shape's routine against the
//! triangle's plane (a box's vertices, a cylinder's rim points, a sphere's
//! lowest point…) keeping the points over the triangle, and the triangle's
//! corners inside the shape (each as deep as the shape reaches below it
//! along the normal): the contact region's corners, as a manifold's; a
//! triangle with neither touches only where its neighbours hold the
//! points. Otherwise (an edge's or a corner's normal) the narrow phase's
//! one point, midway. Points two triangles share (a seam, a corner) are
//! kept once, the deepest; a pair that overlaps but kept no point keeps
//! its deepest triangle's narrow-phase point.
//!
//! A mesh against a half-space: its vertices at or below the plane (the
//! deepest points of any solid are among its vertices).

use nalgebra::{Matrix3, Vector3};

use super::mesh_query::{mesh_convex, TriangleTest};
use super::{c, narrow, ContactPoint, Feature, Options, Pose, Side};
use crate::physics::detect::Convex;
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
    let touching = |t: &&TriangleTest| t.penetration > 0.0 || t.distance <= tol;
    for test in q.triangles.iter().filter(touching) {
        let corners = mesh.corners(test.triangle).map(|v| pose_b.to_world(&v));
        let face = pose_b.rotation * mesh.normal(test.triangle);
        let feature = Feature::Triangle {
            mesh: Side::B,
            triangle: test.triangle,
        };
        let mut found = vec![];
        if test.normal.dot(&face) > 1.0 - 1e-9 {
            // The shape against the triangle's plane, the points over it,
            // and the triangle's corners inside the shape.
            let plane = Shape::HalfSpace {
                normal: face.into(),
            };
            let plane_pose = Pose::at(corners[0].map(c::<T>));
            narrow((shape, pa), (&plane, &plane_pose), options, &mut found);
            found.retain(|k| over(&to_f64_vec(&k.point), &corners, &face, size));
            for corner in corners {
                if let Some(depth) = depth_below(shape, &pose_a, &corner, &face) {
                    found.push(ContactPoint {
                        point: corner.map(c::<T>),
                        normal: face.map(c::<T>),
                        penetration: c(depth),
                        feature,
                    });
                }
            }
        } else {
            found.push(narrow_point(test, feature));
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
    if out.len() == start {
        let deepest = (q.triangles.iter().filter(touching))
            .max_by(|x, y| (x.penetration - x.distance).total_cmp(&(y.penetration - y.distance)));
        if let Some(test) = deepest {
            let feature = Feature::Triangle {
                mesh: Side::B,
                triangle: test.triangle,
            };
            out.push(narrow_point(test, feature));
        }
    }
}

/// A triangle's narrow-phase contact: midway between its closest (or
/// deepest) points, along its normal (corrected or raw).
fn narrow_point<T: Real>(test: &TriangleTest, feature: Feature) -> ContactPoint<T> {
    let penetration = if test.penetration > 0.0 {
        test.penetration
    } else {
        -test.distance
    };
    ContactPoint {
        point: ((test.point_a + test.point_b) * 0.5).map(c::<T>),
        normal: test.normal.map(c::<T>),
        penetration: c(penetration),
        feature,
    }
}

/// How far the shape reaches below the world point `p` along `-n` (the
/// distance it must move along `n` for `p` to leave it), when `p` is inside
/// it: bisection on the shape's signed distance down the ray.
fn depth_below(shape: &Shape, pose: &Pose<f64>, p: &Vector3<f64>, n: &Vector3<f64>) -> Option<f64> {
    let inside = |q: &Vector3<f64>| shape.surface_distance(&pose.to_local(q)) < 0.0;
    if !inside(p) {
        return None;
    }
    let lowest = pose.to_world(&shape.support(&(pose.rotation.transpose() * -n))?);
    let (mut lo, mut hi) = (0.0, (p - lowest).dot(n).max(0.0));
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if inside(&(p - n * mid)) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (hi > 0.0).then_some(hi)
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
