//! The mid phase against a convex shape: the convex shape's box in the
//! mesh's frame (from its support mapping along the mesh's axes, grown by
//! `margin`), the tree walked with it, and each candidate triangle's narrow
//! phase (GJK/EPA with the triangle as a three-point hull; the sphere's
//! closed form when GJK's margins path gives it), with the normal corrected
//! on internal edges (`mesh::edges`) when asked.

use nalgebra::Vector3;

use crate::physics::detect::{query, QueryOptions, Support};
use crate::physics::mesh::bvh::{Aabb, Visit};
use crate::physics::mesh::edges::{correct, Rule};
use crate::physics::mesh::triangle::closest_point;
use crate::physics::mesh::TriMesh;
use crate::physics::pose::Pose;

/// One candidate triangle's narrow phase. `normal` points from the mesh
/// toward the convex shape (§7: from b toward a, the mesh being b).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleTest {
    pub triangle: usize,
    /// ≥ 0; 0 when touching or overlapping.
    pub distance: f64,
    /// Depth when overlapping, 0 otherwise.
    pub penetration: f64,
    pub normal: Vector3<f64>,
    pub raw_normal: Vector3<f64>,
    /// The rule that changed the normal (None: kept).
    pub rule: Option<Rule>,
    /// Closest (or deepest) points, world: on the convex shape, on the triangle.
    pub point_a: Vector3<f64>,
    pub point_b: Vector3<f64>,
}

impl TriangleTest {
    pub fn corrected(&self) -> bool {
        self.rule.is_some()
    }
}

/// The whole mid phase of a pair.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshQuery {
    /// The query box, mesh frame.
    pub bounds: Aabb,
    pub nodes: Vec<Visit>,
    pub candidates: Vec<usize>,
    pub triangles: Vec<TriangleTest>,
    /// The least distance over the candidates (infinite when none).
    pub distance: f64,
}

impl MeshQuery {
    /// The overlapping candidates: the contacts.
    pub fn contacts(&self) -> impl Iterator<Item = &TriangleTest> {
        self.triangles.iter().filter(|t| t.penetration > 0.0)
    }
}

/// The box of `shape` at `pose` in the mesh's frame, grown by `margin`.
pub fn bounds_in_mesh_frame<S: Support<f64> + ?Sized>(
    shape: &S,
    pose: &Pose<f64>,
    mesh_pose: &Pose<f64>,
    margin: f64,
) -> Aabb {
    let along = |i: usize, sign: f64| {
        let axis = mesh_pose.axis(i) * sign;
        mesh_pose.to_local(&shape.support(pose, &axis))[i]
    };
    [
        Vector3::from_fn(|i, _| along(i, -1.0) - margin),
        Vector3::from_fn(|i, _| along(i, 1.0) + margin),
    ]
}

/// The mid and narrow phase of `shape` against `mesh`; `fix` corrects
/// normals on internal edges.
pub fn mesh_convex<S: Support<f64> + ?Sized>(
    shape: &S,
    pose: &Pose<f64>,
    mesh: &TriMesh,
    mesh_pose: &Pose<f64>,
    margin: f64,
    fix: bool,
) -> MeshQuery {
    let bounds = bounds_in_mesh_frame(shape, pose, mesh_pose, margin);
    let (nodes, candidates) = mesh.bvh().traverse(&bounds);
    let options = QueryOptions::default();
    let mut triangles = Vec::with_capacity(candidates.len());
    let mut distance = f64::INFINITY;
    for &t in &candidates {
        let tri = Triangle(mesh.corners(t));
        let q = query(shape, pose, &tri, mesh_pose, &options, &mut (), &mut ());
        let (dist, depth, raw, pa, pb) = match q.penetration {
            Some(p) => (0.0, p.depth, p.normal, p.point_a, p.point_b),
            None => {
                let (pa, pb) = (q.gjk.closest_a, q.gjk.closest_b);
                let n = (pa - pb)
                    .try_normalize(0.0)
                    .unwrap_or_else(|| mesh_pose.rotation * mesh.normal(t));
                (q.gjk.distance, 0.0, n, pa, pb)
            }
        };
        // The feature of the triangle the contact is on, from its point.
        let local = mesh_pose.to_local(&pb);
        let (_, region) = closest_point(&local, &mesh.corners(t));
        let raw_local = mesh_pose.rotation.transpose() * raw;
        // A raw normal that is a nearby face's own (a closed mesh's bottom
        // face, met through a side triangle's corner) is the surface's:
        // kept, whatever region the contact point fell in.
        let (normal_local, rule) = if fix && !near_face_normal(mesh, t, &raw_local) {
            correct(mesh, t, region, &raw_local)
        } else {
            (raw_local, None)
        };
        let normal = mesh_pose.rotation * normal_local;
        // A corrected normal: the depth along it (the shape's support
        // against the triangle's plane when the normal is the face's).
        let depth = if rule.is_some() && depth > 0.0 {
            let deepest = shape.support(pose, &-normal);
            (pb - deepest).dot(&normal).max(0.0)
        } else {
            depth
        };
        distance = distance.min(dist);
        triangles.push(TriangleTest {
            triangle: t,
            distance: dist,
            penetration: depth,
            normal,
            raw_normal: raw,
            rule,
            point_a: pa,
            point_b: pb,
        });
    }
    MeshQuery {
        bounds,
        nodes,
        candidates,
        triangles,
        distance,
    }
}

/// Whether `raw` is the normal of a triangle within two edges of `t`
/// (its neighbours and theirs), other than `t` itself.
fn near_face_normal(mesh: &TriMesh, t: usize, raw: &Vector3<f64>) -> bool {
    let ring = (mesh.neighbours(t).into_iter().flatten())
        .flat_map(|u| std::iter::once(u).chain(mesh.neighbours(u).into_iter().flatten()));
    let n = mesh.normal(t);
    ring.filter(|&u| u != t)
        .map(|u| mesh.normal(u))
        .any(|m| m.dot(&n) < 1.0 - 1e-6 && m.dot(raw) >= 1.0 - 1e-9)
}

/// A triangle as a convex shape (its three corners, body frame of the mesh).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Triangle(pub [Vector3<f64>; 3]);

impl Support<f64> for Triangle {
    fn core_support(&self, d: &Vector3<f64>) -> Vector3<f64> {
        let mut best = self.0[0];
        for p in &self.0[1..] {
            if p.dot(d) > best.dot(d) {
                best = *p;
            }
        }
        best
    }
}
