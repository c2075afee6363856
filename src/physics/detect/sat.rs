//! Separating axes for convex polyhedra (boxes, hulls): the penetration
//! depth is the smallest overlap of the two projections over A's face
//! normals, B's face normals and the cross products of an edge of A with an
//! edge of B — exact for polyhedra, since those are the face normals of the
//! Minkowski difference. The analytic reference for EPA.

use nalgebra::Vector3;

use super::support::Convex;
use crate::physics::pose::Pose;

/// A polyhedron in world coordinates: vertices, unit face normals, unit edge directions.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyhedron {
    pub vertices: Vec<Vector3<f64>>,
    pub normals: Vec<Vector3<f64>>,
    pub edges: Vec<Vector3<f64>>,
}

impl Polyhedron {
    /// A box or hull at `pose`; `None` for curved shapes.
    pub fn of(shape: &Convex, pose: &Pose<f64>) -> Option<Polyhedron> {
        match shape {
            Convex::Cuboid { half } => {
                let vertices = (0..8)
                    .map(|i| {
                        let local =
                            Vector3::from_fn(
                                |k, _| if i >> k & 1 == 1 { half[k] } else { -half[k] },
                            );
                        pose.to_world(&local)
                    })
                    .collect();
                let axes: Vec<Vector3<f64>> = (0..3).map(|k| pose.axis(k)).collect();
                Some(Polyhedron {
                    vertices,
                    normals: axes.iter().flat_map(|a| [*a, -a]).collect(),
                    edges: axes,
                })
            }
            Convex::Hull(hull) => Some(Polyhedron {
                vertices: hull.vertices().iter().map(|v| pose.to_world(v)).collect(),
                normals: hull
                    .faces()
                    .iter()
                    .map(|f| pose.rotation * f.normal)
                    .collect(),
                edges: hull
                    .edges()
                    .iter()
                    .map(|&[i, j]| {
                        (pose.rotation * (hull.vertices()[j] - hull.vertices()[i])).normalize()
                    })
                    .collect(),
            }),
            _ => None,
        }
    }

    /// (min, max) of the vertices projected on `axis`.
    pub fn project(&self, axis: &Vector3<f64>) -> (f64, f64) {
        self.vertices
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                let x = v.dot(axis);
                (lo.min(x), hi.max(x))
            })
    }
}

/// Which axis gave the smallest overlap.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SatAxis {
    FaceA(usize),
    FaceB(usize),
    Edges(usize, usize),
}

/// The smallest overlap (negative: the pair is separated along `normal` by
/// at least that much), its unit normal from B toward A, and its axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SatResult {
    pub depth: f64,
    pub normal: Vector3<f64>,
    pub axis: SatAxis,
}

/// Overlap of A and B on unit `axis` and the normal from B toward A:
/// min(max_A − min_B, max_B − min_A), with A on the side the smaller term says.
fn overlap(a: &Polyhedron, b: &Polyhedron, axis: &Vector3<f64>) -> (f64, Vector3<f64>) {
    let (a0, a1) = a.project(axis);
    let (b0, b1) = b.project(axis);
    let (up, down) = (b1 - a0, a1 - b0);
    if up < down {
        (up, *axis) // A above B along the axis
    } else {
        (down, -axis)
    }
}

/// The separating-axis test over every face normal and edge–edge cross
/// product (skipping pairs of edges parallel within 1e-9).
pub fn sat(a: &Polyhedron, b: &Polyhedron) -> SatResult {
    let mut best = SatResult {
        depth: f64::INFINITY,
        normal: Vector3::y(),
        axis: SatAxis::FaceA(0),
    };
    let mut consider = |axis: &Vector3<f64>, which: SatAxis| {
        let (depth, normal) = overlap(a, b, axis);
        if depth < best.depth {
            best = SatResult {
                depth,
                normal,
                axis: which,
            };
        }
    };
    for (i, n) in a.normals.iter().enumerate() {
        consider(n, SatAxis::FaceA(i));
    }
    for (i, n) in b.normals.iter().enumerate() {
        consider(n, SatAxis::FaceB(i));
    }
    for (i, ea) in a.edges.iter().enumerate() {
        for (j, eb) in b.edges.iter().enumerate() {
            let axis = ea.cross(eb);
            let len = axis.norm();
            if len > 1e-9 {
                consider(&(axis / len), SatAxis::Edges(i, j));
            }
        }
    }
    best
}
