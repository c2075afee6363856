//! A mesh's checks: finite vertices, indices in range, no degenerate
//! triangle, every edge shared by at most two triangles which wind it in
//! opposite directions (consistent orientation). Gives each triangle's
//! neighbours across its edges and whether the mesh is closed.

use std::collections::HashMap;

use nalgebra::Vector3;

/// Why a mesh is refused; `triangle` and `vertex` are 0-based indices.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeshError {
    #[error("a mesh needs at least one triangle")]
    Empty,
    #[error("vertex {vertex} is not finite")]
    NotFinite { vertex: usize },
    #[error("triangle {triangle} names vertex {vertex}, but there are {count} vertices")]
    OutOfRange {
        triangle: usize,
        vertex: usize,
        count: usize,
    },
    #[error("triangle {triangle} is degenerate: {why}")]
    Degenerate { triangle: usize, why: &'static str },
    #[error("the edge between vertices {a} and {b} is shared by more than two triangles ({triangles:?})")]
    NonManifold {
        a: usize,
        b: usize,
        triangles: Vec<usize>,
    },
    #[error("triangles {first} and {second} wind their shared edge ({a}, {b}) the same way: the mesh is not consistently oriented")]
    Inconsistent {
        first: usize,
        second: usize,
        a: usize,
        b: usize,
    },
    #[error("a movable mesh must be closed: the edge ({a}, {b}) of triangle {triangle} has no neighbour")]
    Open { triangle: usize, a: usize, b: usize },
    #[error("the closed mesh encloses no positive volume (its triangles wind clockwise seen from outside?)")]
    InsideOut,
}

impl MeshError {
    /// The triangle the error is about, if one (the OBJ reader maps it to its `f` line).
    pub fn triangle(&self) -> Option<usize> {
        match *self {
            MeshError::OutOfRange { triangle, .. }
            | MeshError::Degenerate { triangle, .. }
            | MeshError::Open { triangle, .. } => Some(triangle),
            MeshError::Inconsistent { second, .. } => Some(second),
            MeshError::NonManifold { ref triangles, .. } => triangles.last().copied(),
            _ => None,
        }
    }
}

/// The neighbours of each triangle across its edges k → k+1, and whether
/// every edge has two triangles.
#[allow(clippy::type_complexity)]
pub fn check(
    vertices: &[Vector3<f64>],
    triangles: &[[usize; 3]],
) -> Result<(Vec<[Option<usize>; 3]>, bool), MeshError> {
    if triangles.is_empty() {
        return Err(MeshError::Empty);
    }
    if let Some(vertex) = vertices
        .iter()
        .position(|v| !v.iter().all(|x| x.is_finite()))
    {
        return Err(MeshError::NotFinite { vertex });
    }
    let extent = vertices.iter().map(|v| v.amax()).fold(0.0, f64::max);
    for (t, tri) in triangles.iter().enumerate() {
        if let Some(&vertex) = tri.iter().find(|&&i| i >= vertices.len()) {
            return Err(MeshError::OutOfRange {
                triangle: t,
                vertex,
                count: vertices.len(),
            });
        }
        let [a, b, c] = *tri;
        if a == b || b == c || a == c {
            return Err(MeshError::Degenerate {
                triangle: t,
                why: "a vertex repeats",
            });
        }
        let (p, q, r) = (vertices[a], vertices[b], vertices[c]);
        let area2 = (q - p).cross(&(r - p)).norm();
        let longest = (q - p).norm().max((r - q).norm()).max((p - r).norm());
        if area2 <= 1e-12 * longest * longest || longest <= 1e-15 * extent {
            return Err(MeshError::Degenerate {
                triangle: t,
                why: "its corners lie on one line (no area)",
            });
        }
    }
    // Directed edge (from, to) → triangle and the edge's slot in it.
    let mut directed: HashMap<(usize, usize), (usize, usize)> = HashMap::new();
    let mut undirected: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (t, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            let users = undirected.entry((a.min(b), a.max(b))).or_default();
            users.push(t);
            if users.len() > 2 {
                return Err(MeshError::NonManifold {
                    a: a.min(b),
                    b: a.max(b),
                    triangles: users.clone(),
                });
            }
            if let Some(&(first, _)) = directed.get(&(a, b)) {
                return Err(MeshError::Inconsistent {
                    first,
                    second: t,
                    a,
                    b,
                });
            }
            directed.insert((a, b), (t, k));
        }
    }
    let mut closed = true;
    let mut neighbours = vec![[None; 3]; triangles.len()];
    for (t, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            match directed.get(&(b, a)) {
                Some(&(other, _)) => neighbours[t][k] = Some(other),
                None => closed = false,
            }
        }
    }
    Ok((neighbours, closed))
}

/// The first edge without a neighbour, as the error a movable mesh gets.
pub fn open_edge(triangles: &[[usize; 3]], neighbours: &[[Option<usize>; 3]]) -> Option<MeshError> {
    (0..triangles.len()).find_map(|t| {
        (0..3)
            .find(|&k| neighbours[t][k].is_none())
            .map(|k| MeshError::Open {
                triangle: t,
                a: triangles[t][k],
                b: triangles[t][(k + 1) % 3],
            })
    })
}
