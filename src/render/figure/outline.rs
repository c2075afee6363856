//! Body outlines projected onto a view plane (a filled silhouette and the
//! edges of a wire frame), convex hulls, and the drawing geometry taken from
//! the physics [`Shape`]: how far a point lies from a body as drawn.

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

use super::view::P;
use crate::physics::Shape;
use crate::trace::Plane;

/// A body at one pose, seen in the view plane.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    /// The region it covers (for filling).
    pub silhouette: Silhouette,
    /// The edges of its wire frame: a box's twelve edges; a sphere's rim and
    /// one spoke that shows its turn; a cylinder's two rims and four sides.
    pub edges: Vec<[P; 2]>,
}

#[derive(Debug, Clone, PartialEq)]
pub enum Silhouette {
    /// A convex polygon, counter-clockwise.
    Polygon(Vec<P>),
    Circle {
        centre: P,
        radius: f64,
    },
}

impl Silhouette {
    /// Points whose bounding box is the silhouette's.
    pub fn points(&self) -> Vec<P> {
        match self {
            Silhouette::Polygon(p) => p.clone(),
            Silhouette::Circle { centre, radius } => vec![
                [centre[0] - radius, centre[1] - radius],
                [centre[0] + radius, centre[1] + radius],
            ],
        }
    }
}

/// Rotation matrix of an orientation `[w, x, y, z]` (normalised; identity
/// for a zero or non-finite quaternion).
pub fn rotation(q: [f64; 4]) -> Matrix3<f64> {
    let q = Quaternion::new(q[0], q[1], q[2], q[3]);
    if q.norm() > 0.0 && q.norm().is_finite() {
        UnitQuaternion::from_quaternion(q)
            .to_rotation_matrix()
            .into_inner()
    } else {
        Matrix3::identity()
    }
}

fn project(plane: Plane, v: &Vector3<f64>) -> P {
    let (a, b, _) = plane.axes();
    [v[a], v[b]]
}

/// The outline of `shape` at a pose, seen in `plane`; `None` for a
/// half-space (drawn as a surface through the contact point).
pub fn outline(
    shape: &Shape,
    position: [f64; 3],
    orientation: [f64; 4],
    plane: Plane,
) -> Option<Outline> {
    let r = rotation(orientation);
    let c = Vector3::from(position);
    let at = |local: Vector3<f64>| project(plane, &(c + r * local));
    match *shape {
        Shape::Box { .. } => {
            let h = shape.half_extents()?;
            let corner = |i: usize| {
                let s = |bit: usize| if i & bit == 0 { -1.0 } else { 1.0 };
                at(Vector3::new(s(1) * h.x, s(2) * h.y, s(4) * h.z))
            };
            let mut edges = vec![];
            for i in 0..8 {
                for bit in [1, 2, 4] {
                    if i & bit == 0 {
                        edges.push([corner(i), corner(i | bit)]);
                    }
                }
            }
            Some(Outline {
                silhouette: Silhouette::Polygon(hull((0..8).map(corner).collect())),
                edges,
            })
        }
        Shape::Sphere { radius } | Shape::HollowSphere { radius } => {
            // The great circle facing the viewer, and a spoke to show the turn.
            let centre = project(plane, &c);
            let rim = |i: usize| {
                let a = std::f64::consts::TAU * i as f64 / 48.0;
                [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
            };
            let mut edges: Vec<[P; 2]> = (0..48).map(|i| [rim(i), rim(i + 1)]).collect();
            edges.push([centre, at(Vector3::new(radius, 0.0, 0.0))]);
            Some(Outline {
                silhouette: Silhouette::Circle { centre, radius },
                edges,
            })
        }
        Shape::Cylinder { radius, height } => {
            // A rim point at angle TAU·i/n of the end at body y = `y`.
            let rim = |i: usize, n: usize, y: f64| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                at(Vector3::new(radius * a.cos(), y, radius * a.sin()))
            };
            let ends = [height / 2.0, -height / 2.0];
            let mut edges = vec![];
            for y in ends {
                edges.extend((0..32).map(|i| [rim(i, 32, y), rim(i + 1, 32, y)]));
            }
            for i in [0, 8, 16, 24] {
                edges.push([rim(i, 32, ends[0]), rim(i, 32, ends[1])]);
            }
            let around = ends.iter().flat_map(|&y| (0..16).map(move |i| (i, y)));
            let silhouette =
                Silhouette::Polygon(hull(around.map(|(i, y)| rim(i, 16, y)).collect()));
            Some(Outline { silhouette, edges })
        }
        Shape::Capsule { radius, height } => {
            // The two end circles facing the viewer, the lines joining them,
            // and the axis; the silhouette is the hull of the two circles.
            let ends = [
                at(Vector3::new(0.0, height / 2.0, 0.0)),
                at(Vector3::new(0.0, -height / 2.0, 0.0)),
            ];
            let circle = |e: P, i: usize| {
                let a = std::f64::consts::TAU * i as f64 / 48.0;
                [e[0] + radius * a.cos(), e[1] + radius * a.sin()]
            };
            let mut edges: Vec<[P; 2]> = ends
                .iter()
                .flat_map(|&e| (0..48).map(move |i| [circle(e, i), circle(e, i + 1)]))
                .collect();
            edges.push([ends[0], ends[1]]);
            let silhouette = Silhouette::Polygon(hull(
                ends.iter()
                    .flat_map(|&e| (0..48).map(move |i| circle(e, i)))
                    .collect(),
            ));
            Some(Outline { silhouette, edges })
        }
        Shape::Hull(ref hull) => {
            // Every edge of the polygon faces; the silhouette is the 2-D
            // hull of the projected vertices.
            let corners: Vec<P> = hull.vertices().iter().map(|v| at(*v)).collect();
            let edges = hull
                .edges()
                .iter()
                .map(|&[i, j]| [corners[i], corners[j]])
                .collect();
            Some(Outline {
                silhouette: Silhouette::Polygon(self::hull(corners)),
                edges,
            })
        }
        Shape::Mesh(ref mesh) => {
            // Every triangle's edges (each shared edge once); the
            // silhouette is the 2-D hull of the projected vertices.
            let corners: Vec<P> = mesh.vertices().iter().map(|v| at(*v)).collect();
            let mut edges = vec![];
            for (n, t) in mesh.triangles().iter().enumerate() {
                for k in 0..3 {
                    let (i, j) = (t[k], t[(k + 1) % 3]);
                    if i < j || mesh.neighbours(n)[k].is_none() {
                        edges.push([corners[i], corners[j]]);
                    }
                }
            }
            Some(Outline {
                silhouette: Silhouette::Polygon(self::hull(corners)),
                edges,
            })
        }
        Shape::HalfSpace { .. } => None,
    }
}

/// Signed distance from the world point `point` to the surface of a body of
/// finite `shape` at a pose (negative inside); `None` for a half-space.
pub fn surface_distance(
    shape: &Shape,
    position: [f64; 3],
    orientation: [f64; 4],
    point: [f64; 3],
) -> Option<f64> {
    if !shape.is_finite() {
        return None;
    }
    let local =
        rotation(orientation).transpose() * (Vector3::from(point) - Vector3::from(position));
    Some(shape.surface_distance(&local))
}

/// A radius for a spin arc drawn well inside the body: half the radius of a
/// sphere, 0.3 of a box's shortest side, half the smaller of a cylinder's
/// radius and half height; `None` for a half-space.
pub fn spin_arc_radius(shape: &Shape) -> Option<f64> {
    match *shape {
        Shape::Sphere { radius } | Shape::HollowSphere { radius } => Some(0.5 * radius),
        Shape::Box { sides } => Some(0.3 * sides.iter().copied().fold(f64::INFINITY, f64::min)),
        Shape::Cylinder { radius, height } => Some(0.5 * radius.min(height / 2.0)),
        Shape::Capsule { radius, .. } => Some(0.5 * radius),
        Shape::Hull(ref hull) => Some(0.5 * hull.inner_radius()),
        Shape::Mesh(ref mesh) => mesh.inner_radius().map(|r| 0.5 * r),
        Shape::HalfSpace { .. } => None,
    }
}

/// Convex hull (Andrew's monotone chain), counter-clockwise.
pub fn hull(mut p: Vec<P>) -> Vec<P> {
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup_by(|a, b| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
    if p.len() < 3 {
        return p;
    }
    let cross = |o: P, a: P, b: P| (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    let chain = |points: &mut dyn Iterator<Item = &P>| {
        let mut out: Vec<P> = Vec::new();
        for &pt in points {
            while out.len() >= 2 && cross(out[out.len() - 2], out[out.len() - 1], pt) <= 1e-12 {
                out.pop();
            }
            out.push(pt);
        }
        out.pop();
        out
    };
    let mut lower = chain(&mut p.iter());
    lower.extend(chain(&mut p.iter().rev()));
    lower
}
