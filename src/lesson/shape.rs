//! The lesson file's shape table converted into the physics [`Shape`], and
//! its one-line description for warnings and the trace.
//!
//! A convex hull (`shape = { convex = [[x, y, z], …] }`) is re-centred: its
//! points are given in the body frame, the hull is built, and its points are
//! moved by −c (c, the solid's centroid) so that the body's origin is its
//! centre of mass. The body's `position` moves by R·c, so the hull stays
//! exactly where the file puts it (see docs/lesson-format.md).

use nalgebra::Vector3;

use super::raw::RawShape;
use crate::physics::detect::{ConvexHull, HullError};
use crate::physics::Shape;

/// The physics shape of a lesson's shape table, and the offset of the
/// body's centre of mass from the frame the file gives (a hull's centroid;
/// zero for every other shape). A degenerate hull is an error.
pub fn from_raw(raw: &RawShape) -> Result<(Shape, Vector3<f64>), HullError> {
    let shape = match raw {
        RawShape::Sphere(radius) => Shape::Sphere { radius: *radius },
        RawShape::HollowSphere(radius) => Shape::HollowSphere { radius: *radius },
        RawShape::Box(sides) => Shape::Box { sides: *sides },
        RawShape::Cylinder { radius, height } => Shape::Cylinder {
            radius: *radius,
            height: *height,
        },
        RawShape::Capsule { radius, height } => Shape::Capsule {
            radius: *radius,
            height: *height,
        },
        RawShape::Convex(points) => {
            let (hull, centroid) = centred_hull(points)?;
            return Ok((Shape::Hull(std::sync::Arc::new(hull)), centroid));
        }
        // A mesh is read by `lesson::mesh` (its file, the body's mobility)
        // before this is called; here it has no points.
        RawShape::Mesh(_) => return Err(HullError::TooFewPoints { count: 0 }),
        RawShape::HalfSpace => Shape::HalfSpace {
            normal: [0.0, 1.0, 0.0],
        },
    };
    Ok((shape, Vector3::zeros()))
}

/// The hull of `points` moved so that its centroid is at the origin, and
/// that centroid in the given frame. Refuses repeated points (the same
/// point twice is a typo in a lesson, not a shape). Only the hull's
/// vertices are kept (the points inside it or on its faces are dropped:
/// [`dropped_points`] says how many).
pub fn centred_hull(points: &[[f64; 3]]) -> Result<(ConvexHull, Vector3<f64>), HullError> {
    if points.len() >= 4 {
        // Each point's first index by its bits: one pass, not one per pair.
        let mut first = std::collections::HashMap::with_capacity(points.len());
        for (j, q) in points.iter().enumerate() {
            if q.iter().any(|x| !x.is_finite()) {
                continue; // the hull says which (never equal to another)
            }
            let bits = bits_of(q);
            if let Some(&i) = first.get(&bits) {
                return Err(HullError::Duplicate {
                    first: i,
                    second: j,
                });
            }
            first.insert(bits, j);
        }
    }
    let hull = ConvexHull::new(points)?;
    let centroid = hull.mass_properties().centroid;
    // Built again, moved, from its vertices only, in the order given.
    let vertices: std::collections::HashSet<[u64; 3]> = (hull.vertices().iter())
        .map(|v| bits_of(&[v.x, v.y, v.z]))
        .collect();
    let moved: Vec<[f64; 3]> = (points.iter())
        .filter(|p| vertices.contains(&bits_of(p)))
        .map(|p| (Vector3::from(*p) - centroid).into())
        .collect();
    Ok((ConvexHull::new(&moved)?.rebuilt_from(&hull), centroid))
}

/// A point's coordinates as bits, with −0 as 0 (equal points, equal bits).
fn bits_of(p: &[f64; 3]) -> [u64; 3] {
    p.map(|x| if x == 0.0 { 0 } else { x.to_bits() })
}

/// How many of a hull's `given` points it dropped (inside it, or on a
/// face or an edge between its vertices): the load warning's number.
pub fn dropped_points(given: usize, hull: &ConvexHull) -> usize {
    given.saturating_sub(hull.vertices().len())
}

/// The shape and its inertia formula, in words (numbers through
/// `format::exact`: tiny and huge sizes in scientific notation).
pub fn describe(shape: &Shape) -> String {
    let e = crate::format::exact;
    match *shape {
        Shape::Sphere { radius: r } => format!("solid sphere r = {} (I = 2/5 m r²)", e(r)),
        Shape::HollowSphere { radius: r } => {
            format!("hollow sphere r = {} (I = 2/3 m r²)", e(r))
        }
        Shape::Box { sides: [x, y, z] } => format!(
            "box {} × {} × {} (I_xx = m/12 (y² + z²), …)",
            e(x),
            e(y),
            e(z)
        ),
        Shape::Cylinder { radius, height } => format!(
            "cylinder r = {}, h = {} (I_yy = ½ m r², I_xx = m/12 (3r² + h²))",
            e(radius),
            e(height)
        ),
        Shape::Capsule { radius, height } => format!(
            "capsule r = {}, h = {} (a cylinder and two half balls)",
            e(radius),
            e(height)
        ),
        Shape::Hull(ref hull) => format!(
            "convex hull of {} vertices, {} faces, volume {} (I from the polyhedron's integrals)",
            hull.vertices().len(),
            hull.faces().len(),
            e(hull.mass_properties().volume)
        ),
        Shape::Mesh(ref mesh) => format!(
            "{} mesh of {} triangles, {} vertices{}",
            if mesh.is_closed() { "closed" } else { "open" },
            mesh.triangles().len(),
            mesh.vertices().len(),
            match mesh.mass_properties() {
                Some(p) => format!(
                    ", volume {} (I from the surface, divergence theorem)",
                    e(p.volume)
                ),
                None => String::new(),
            }
        ),
        Shape::HalfSpace { .. } => "half-space".to_string(),
    }
}
