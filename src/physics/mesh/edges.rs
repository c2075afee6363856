//! Internal edges (ghost collisions): a contact on an edge or a corner a
//! triangle shares with its neighbours must not push across the surface.
//! The normal is clamped to the feature's normal cone (the approach of
//! parry's TriMesh): on the face, the face normal; on an edge shared with
//! a coplanar or concave neighbour, the face normal; on a convex edge, the
//! raw normal kept when it lies between the two faces' normals, otherwise
//! the nearer of them; on a corner whose two edges are both flat or
//! concave, the face normal. A free edge (no neighbour) keeps the raw
//! normal turned to the front side.

use nalgebra::Vector3;

use super::triangle::Region;
use super::TriMesh;

/// The rule that changed a normal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rule {
    /// On the face: the face's normal.
    Face,
    /// On an edge shared with a coplanar or concave neighbour.
    FlatEdge,
    /// On a convex edge, outside the cone of the two faces' normals.
    ConvexEdge,
    /// On a corner between flat or concave edges.
    FlatVertex,
    /// Pointing to the back of the triangle: the face's normal.
    BackFace,
}

impl Rule {
    pub fn json_name(self) -> &'static str {
        match self {
            Rule::Face => "face",
            Rule::FlatEdge => "flat-edge",
            Rule::ConvexEdge => "convex-edge",
            Rule::FlatVertex => "flat-vertex",
            Rule::BackFace => "back-face",
        }
    }
}

/// Cosine above which two normals count as the same (about 0.08°).
const SAME: f64 = 1.0 - 1e-6;

/// Whether the edge k of triangle t is convex (the neighbour falls away).
fn convex_edge(mesh: &TriMesh, t: usize, k: usize) -> Option<bool> {
    let u = mesh.neighbours(t)[k]?;
    let (nt, nu) = (mesh.normal(t), mesh.normal(u));
    if nt.dot(&nu) >= SAME {
        return Some(false);
    }
    let tri = mesh.triangles()[t];
    let opposite = (mesh.triangles()[u].iter())
        .copied()
        .find(|i| !tri.contains(i))
        .unwrap_or(tri[0]);
    let a = mesh.vertices()[tri[k]];
    Some((mesh.vertices()[opposite] - a).dot(&nt) < 0.0)
}

/// The corrected normal (mesh frame) and the rule, if one applied.
pub fn correct(
    mesh: &TriMesh,
    t: usize,
    region: Region,
    raw: &Vector3<f64>,
) -> (Vector3<f64>, Option<Rule>) {
    let n = mesh.normal(t);
    let keep_or = |normal: Vector3<f64>, rule: Rule| {
        if (raw - normal).norm() <= 1e-12 {
            (*raw, None)
        } else {
            (normal, Some(rule))
        }
    };
    match region {
        Region::Face => keep_or(n, Rule::Face),
        Region::Edge(k) => match convex_edge(mesh, t, k) {
            Some(false) => keep_or(n, Rule::FlatEdge),
            Some(true) => {
                let m = mesh.normal(mesh.neighbours(t)[k].unwrap_or(t));
                // Inside the cone when raw is a non-negative mix of n and m.
                let e = n.cross(&m);
                let inside = raw.cross(&m).dot(&e) >= 0.0 && n.cross(raw).dot(&e) >= 0.0;
                if inside && raw.dot(&n) > -1e-12 {
                    (*raw, None)
                } else if raw.dot(&n) >= raw.dot(&m) {
                    (n, Some(Rule::ConvexEdge))
                } else {
                    (m, Some(Rule::ConvexEdge))
                }
            }
            None => back(raw, &n),
        },
        Region::Vertex(k) => {
            let flat = |edge| convex_edge(mesh, t, edge) == Some(false);
            if flat(k) && flat((k + 2) % 3) {
                keep_or(n, Rule::FlatVertex)
            } else {
                back(raw, &n)
            }
        }
    }
}

fn back(raw: &Vector3<f64>, n: &Vector3<f64>) -> (Vector3<f64>, Option<Rule>) {
    if raw.dot(n) < 0.0 {
        (*n, Some(Rule::BackFace))
    } else {
        (*raw, None)
    }
}
