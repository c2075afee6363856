//! Mass properties of a closed mesh from its surface by the divergence
//! theorem (Mirtich 1996; Eberly, "Polyhedral Mass Properties"): the solid
//! is the signed sum of the tetrahedra (o, a, b, c) over the triangles, o the
//! vertex mean, each with V = det[a b c]/6, first moment V·(a+b+c)/4 and
//! second moment det/120 · (aaᵀ + bbᵀ + ccᵀ + ssᵀ), s = a + b + c. A
//! non-convex mesh works the same: the tetrahedra outside cancel.

use nalgebra::{Matrix3, Vector3};

use crate::physics::hull::MassProperties;

/// Volume, centroid and unit-density inertia about the centroid, or `None`
/// when the enclosed volume is not positive (inside out or flat).
pub fn mass_properties(
    vertices: &[Vector3<f64>],
    triangles: &[[usize; 3]],
) -> Option<MassProperties> {
    let o = vertices.iter().sum::<Vector3<f64>>() / vertices.len() as f64;
    let mut volume = 0.0;
    let mut first = Vector3::zeros();
    let mut second = Matrix3::zeros();
    for t in triangles {
        let [a, b, c] = t.map(|i| vertices[i] - o);
        let det = a.dot(&b.cross(&c));
        let s = a + b + c;
        volume += det / 6.0;
        first += s * (det / 24.0);
        second += (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose())
            * (det / 120.0);
    }
    let scale = vertices.iter().map(|v| (v - o).norm()).fold(0.0, f64::max);
    if volume.is_nan() || volume <= 1e-12 * scale.powi(3) {
        return None;
    }
    let g = first / volume;
    let central = second - g * g.transpose() * volume;
    Some(MassProperties {
        volume,
        centroid: o + g,
        unit_inertia: Matrix3::identity() * central.trace() - central,
    })
}
