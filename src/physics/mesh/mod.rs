//! Triangle meshes: vertices and triangles in the body frame, checked on
//! construction (no degenerate triangle, every edge shared by at most two
//! triangles that wind it in opposite directions), an AABB tree over the
//! triangles ([`bvh`]), closest points on a triangle ([`triangle`]), the
//! internal-edge correction ([`edges`]) and the Wavefront OBJ reader
//! ([`obj`]). This folder imports nothing else of `physics` (a `Shape`
//! holds a mesh): the mass properties from the surface are
//! `physics::mesh_mass`, the mid phase against a convex shape (GJK/EPA)
//! `physics::collide::mesh_query`.

pub mod bvh;
pub mod edges;
pub mod obj;
pub mod topology;
pub mod triangle;

use nalgebra::Vector3;

pub use bvh::Bvh;
pub use topology::MeshError;

/// A triangle mesh in the body frame, with its tree and neighbours.
#[derive(Debug, Clone, PartialEq)]
pub struct TriMesh {
    vertices: Vec<Vector3<f64>>,
    triangles: Vec<[usize; 3]>,
    /// For triangle t and its edge k (from vertex k to k+1), the triangle
    /// across that edge, if any.
    neighbours: Vec<[Option<usize>; 3]>,
    closed: bool,
    bvh: Bvh,
}

impl TriMesh {
    /// A mesh from vertices and triangles (counter-clockwise seen from
    /// outside), or why it is refused.
    pub fn new(vertices: &[[f64; 3]], triangles: &[[usize; 3]]) -> Result<TriMesh, MeshError> {
        let vertices: Vec<Vector3<f64>> = vertices.iter().map(|v| Vector3::from(*v)).collect();
        let (neighbours, closed) = topology::check(&vertices, triangles)?;
        let bvh = Bvh::build(&vertices, triangles);
        Ok(TriMesh {
            vertices,
            triangles: triangles.to_vec(),
            neighbours,
            closed,
            bvh,
        })
    }

    pub fn vertices(&self) -> &[Vector3<f64>] {
        &self.vertices
    }

    pub fn triangles(&self) -> &[[usize; 3]] {
        &self.triangles
    }

    /// The triangle across each edge (k → k+1) of triangle `t`.
    pub fn neighbours(&self, t: usize) -> [Option<usize>; 3] {
        self.neighbours[t]
    }

    /// True when every edge has two triangles: the mesh bounds a solid.
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// Triangle `t`'s corners.
    pub fn corners(&self, t: usize) -> [Vector3<f64>; 3] {
        self.triangles[t].map(|i| self.vertices[i])
    }

    /// Triangle `t`'s unit normal (counter-clockwise: outward).
    pub fn normal(&self, t: usize) -> Vector3<f64> {
        let [a, b, c] = self.corners(t);
        (b - a).cross(&(c - a)).normalize()
    }

    /// The same mesh moved by `offset` (the lesson re-centres a movable
    /// mesh on its centroid).
    pub fn translated(&self, offset: &Vector3<f64>) -> TriMesh {
        let vertices: Vec<[f64; 3]> = (self.vertices.iter())
            .map(|v| (v + offset).into())
            .collect();
        TriMesh {
            vertices: vertices.iter().map(|v| Vector3::from(*v)).collect(),
            triangles: self.triangles.clone(),
            neighbours: self.neighbours.clone(),
            closed: self.closed,
            bvh: Bvh::build(
                &vertices
                    .iter()
                    .map(|v| Vector3::from(*v))
                    .collect::<Vec<_>>(),
                &self.triangles,
            ),
        }
    }

    /// Distance from a body-frame point to the nearest triangle, negative
    /// behind it (inside a closed mesh; under an open one). The side is the
    /// nearest triangle's, by the direction from its closest point (its
    /// face normal when the point is on it); at a shared edge or corner the
    /// triangle whose plane is farthest from the point decides.
    pub fn signed_distance(&self, p: &Vector3<f64>) -> f64 {
        let mut best = (f64::INFINITY, 1.0, f64::NEG_INFINITY);
        for t in 0..self.triangles.len() {
            let corners = self.corners(t);
            let (q, _) = triangle::closest_point(p, &corners);
            let d = (p - q).norm();
            let plane = (p - corners[0]).dot(&self.normal(t));
            let closer = d < best.0 * (1.0 - 1e-12);
            let tie = !closer && d <= best.0 * (1.0 + 1e-12) && plane.abs() > best.2.abs();
            if closer || tie {
                best = (d, if plane < 0.0 { -1.0 } else { 1.0 }, plane);
            }
        }
        best.0 * best.1
    }

    /// For a closed mesh, the distance from the body origin (its centroid)
    /// in to the nearest triangle, when the origin is inside; `None` for an
    /// open mesh or an origin outside the solid (an L-block's may be).
    pub fn inner_radius(&self) -> Option<f64> {
        let d = -self.signed_distance(&Vector3::zeros());
        (self.closed && d > 0.0).then_some(d)
    }

    /// Largest distance of a vertex from the body origin.
    pub fn bounding_radius(&self) -> f64 {
        self.vertices.iter().map(|v| v.norm()).fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests;
