//! Mass properties of a closed mesh ([`TriMesh::mass_properties`]) from its surface by the divergence
//! theorem (Mirtich 1996; Eberly, "Polyhedral Mass Properties"): the solid
//! is the signed sum of the tetrahedra (o, a, b, c) over the triangles, o the
//! vertex mean, each with V = det[a b c]/6, first moment V·(a+b+c)/4 and
//! second moment det/120 · (aaᵀ + bbᵀ + ccᵀ + ssᵀ), s = a + b + c. A
//! non-convex mesh works the same: the tetrahedra outside cancel.

use nalgebra::Vector3;

use crate::physics::hull::MassProperties;
use crate::physics::mesh::TriMesh;

/// Volume, centroid and unit-density inertia about the centroid, or `None`
/// when the enclosed volume is not positive (inside out or flat).
pub fn mass_properties(
    vertices: &[Vector3<f64>],
    triangles: &[[usize; 3]],
) -> Option<MassProperties> {
    let m = crate::physics::hull::mass_properties(vertices, triangles);
    let o = vertices.iter().sum::<Vector3<f64>>() / vertices.len() as f64;
    let scale = vertices.iter().map(|v| (v - o).norm()).fold(0.0, f64::max);
    (m.volume.is_finite() && m.volume > 1e-12 * scale.powi(3)).then_some(m)
}

impl TriMesh {
    /// The solid's volume, centroid and unit-density inertia (closed meshes
    /// only: `None` for an open one or one enclosing no volume).
    pub fn mass_properties(&self) -> Option<MassProperties> {
        if !self.is_closed() {
            return None;
        }
        mass_properties(self.vertices(), self.triangles())
    }
}
