//! Convex hull of a point cloud (incremental, the quickhull idea without its
//! outside sets): its vertices, polygon faces with outward normals, edges,
//! and the mass properties of the solid for uniform density.
//!
//! Robustness: every plane test has the tolerance ε = 1e-10 × the cloud's
//! extent, so duplicate points, points inside, and points on a face (within
//! ε) add nothing; points are added farthest from the first tetrahedron's
//! centre first, so the corners of a box come before points on its edges or
//! faces. Coplanar triangles are merged into one polygon face. A cloud with
//! fewer than 4 points that are not coplanar is rejected with a [`HullError`].

use nalgebra::{Matrix3, Vector3};

use super::hull_faces::{merge, HullFace};

/// Why a point cloud has no solid hull.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HullError {
    #[error("a convex hull needs at least 4 points, got {count}")]
    TooFewPoints { count: usize },
    #[error("points {first} and {second} are the same point")]
    Duplicate { first: usize, second: usize },
    #[error("point {index} is not finite")]
    NotFinite { index: usize },
    #[error("all points coincide: the hull has no size")]
    Coincident,
    #[error("all points lie on one line: the hull has no volume")]
    Collinear,
    #[error("all points lie in one plane: the hull has no volume")]
    Coplanar,
}

/// Volume, centroid and inertia tensor (about the centroid, body axes) of a
/// solid of density 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    pub volume: f64,
    pub centroid: Vector3<f64>,
    pub unit_inertia: Matrix3<f64>,
}

/// The convex hull of a set of body-frame points.
#[derive(Debug, Clone, PartialEq)]
pub struct ConvexHull {
    vertices: Vec<Vector3<f64>>,
    triangles: Vec<[usize; 3]>,
    faces: Vec<HullFace>,
    edges: Vec<[usize; 2]>,
    mass: MassProperties,
}

/// A triangle being built: vertex indices (into the input), outward normal, offset.
#[derive(Debug, Clone, Copy)]
struct Tri {
    v: [usize; 3],
    n: Vector3<f64>,
    d: f64,
}

fn tri(points: &[Vector3<f64>], v: [usize; 3]) -> Tri {
    let [a, b, c] = v.map(|i| points[i]);
    let n = (b - a).cross(&(c - a));
    let n = n / n.norm();
    Tri { v, n, d: n.dot(&a) }
}

impl ConvexHull {
    /// The hull of `points` (body frame).
    pub fn new(points: &[[f64; 3]]) -> Result<ConvexHull, HullError> {
        if points.len() < 4 {
            return Err(HullError::TooFewPoints {
                count: points.len(),
            });
        }
        if let Some(index) = points.iter().position(|p| p.iter().any(|x| !x.is_finite())) {
            return Err(HullError::NotFinite { index });
        }
        let pts: Vec<Vector3<f64>> = points.iter().map(|p| Vector3::from(*p)).collect();
        let (lo, hi) = pts
            .iter()
            .fold((pts[0], pts[0]), |(lo, hi), p| (lo.inf(p), hi.sup(p)));
        let eps = 1e-10 * (hi - lo).amax();
        let tris = build(&pts, eps)?;
        Ok(Self::from_triangles(&pts, &tris, eps))
    }

    /// Compacts the vertices, merges coplanar triangles, computes the mass.
    fn from_triangles(pts: &[Vector3<f64>], tris: &[Tri], eps: f64) -> ConvexHull {
        let mut map = vec![usize::MAX; pts.len()];
        let mut vertices = Vec::new();
        for t in tris {
            for &i in &t.v {
                if map[i] == usize::MAX {
                    map[i] = vertices.len();
                    vertices.push(pts[i]);
                }
            }
        }
        let triangles: Vec<[usize; 3]> = tris.iter().map(|t| t.v.map(|i| map[i])).collect();
        let normals: Vec<Vector3<f64>> = tris.iter().map(|t| t.n).collect();
        let faces = merge(&vertices, &triangles, &normals, eps);
        let mut edges: Vec<[usize; 2]> = faces
            .iter()
            .flat_map(|f| {
                let n = f.vertices.len();
                (0..n).map(move |k| {
                    let (a, b) = (f.vertices[k], f.vertices[(k + 1) % n]);
                    [a.min(b), a.max(b)]
                })
            })
            .collect();
        edges.sort_unstable();
        edges.dedup();
        let mass = mass_properties(&vertices, &triangles);
        ConvexHull {
            vertices,
            triangles,
            faces,
            edges,
            mass,
        }
    }

    /// The hull's vertices (body frame).
    pub fn vertices(&self) -> &[Vector3<f64>] {
        &self.vertices
    }

    /// The hull's boundary as triangles, counter-clockwise seen from outside.
    pub fn triangles(&self) -> &[[usize; 3]] {
        &self.triangles
    }

    /// The polygon faces (coplanar triangles merged).
    pub fn faces(&self) -> &[HullFace] {
        &self.faces
    }

    /// The edges of the polygon faces, each once (lower index first).
    pub fn edges(&self) -> &[[usize; 2]] {
        &self.edges
    }

    /// Volume, centroid and unit-density inertia.
    pub fn mass_properties(&self) -> MassProperties {
        self.mass
    }

    /// Inertia tensor about the centroid for a body of mass `m`: m/V · I₁.
    pub fn inertia(&self, m: f64) -> Matrix3<f64> {
        self.mass.unit_inertia * (m / self.mass.volume)
    }

    /// The radius of the largest ball about the body origin inside the
    /// hull: min over faces of the plane offset (negative when the origin
    /// is outside). Twice it bounds the hull's width along any direction.
    pub fn inner_radius(&self) -> f64 {
        self.faces
            .iter()
            .map(|f| f.offset)
            .fold(f64::INFINITY, f64::min)
    }

    /// Index of the vertex with the largest d·v (the first on ties).
    pub fn support_index(&self, d: &Vector3<f64>) -> usize {
        let mut best = 0;
        let mut best_dot = f64::NEG_INFINITY;
        for (i, v) in self.vertices.iter().enumerate() {
            let dot = v.dot(d);
            if dot > best_dot {
                best = i;
                best_dot = dot;
            }
        }
        best
    }
}

/// The first tetrahedron (extreme points), then every other point added,
/// farthest from the tetrahedron's centre first.
fn build(pts: &[Vector3<f64>], eps: f64) -> Result<Vec<Tri>, HullError> {
    let far = |from: &dyn Fn(&Vector3<f64>) -> f64| {
        (0..pts.len())
            .map(|i| (i, from(&pts[i])))
            .fold((0, f64::NEG_INFINITY), |b, x| if x.1 > b.1 { x } else { b })
    };
    let i0 = far(&|p| -p.x).0;
    let (i1, d1) = far(&|p| (p - pts[i0]).norm());
    if d1 <= eps {
        return Err(HullError::Coincident);
    }
    let axis = (pts[i1] - pts[i0]).normalize();
    let (i2, d2) = far(&|p| {
        let r = p - pts[i0];
        (r - axis * axis.dot(&r)).norm()
    });
    if d2 <= eps {
        return Err(HullError::Collinear);
    }
    let n = (pts[i1] - pts[i0]).cross(&(pts[i2] - pts[i0])).normalize();
    let (i3, d3) = far(&|p| n.dot(&(p - pts[i0])).abs());
    if d3 <= eps {
        return Err(HullError::Coplanar);
    }
    let centre = (pts[i0] + pts[i1] + pts[i2] + pts[i3]) / 4.0;
    let mut tris: Vec<Tri> = [[i0, i1, i2], [i0, i1, i3], [i0, i2, i3], [i1, i2, i3]]
        .into_iter()
        .map(|v| {
            let t = tri(pts, v);
            // Outward: the centre lies behind every face.
            if t.n.dot(&centre) > t.d {
                tri(pts, [v[0], v[2], v[1]])
            } else {
                t
            }
        })
        .collect();
    let mut order: Vec<usize> = (0..pts.len())
        .filter(|i| ![i0, i1, i2, i3].contains(i))
        .collect();
    order.sort_by(|&a, &b| {
        let (da, db) = ((pts[a] - centre).norm(), (pts[b] - centre).norm());
        db.total_cmp(&da)
    });
    let mut edges: Vec<[usize; 2]> = Vec::new();
    for i in order {
        let p = pts[i];
        if tris.iter().all(|t| t.n.dot(&p) - t.d <= eps) {
            continue; // inside or on the hull
        }
        // Directed edges of the visible triangles; the horizon is those whose
        // reverse is not also visible.
        edges.clear();
        tris.retain(|t| {
            let visible = t.n.dot(&p) - t.d > eps;
            if visible {
                edges.extend([[t.v[0], t.v[1]], [t.v[1], t.v[2]], [t.v[2], t.v[0]]]);
            }
            !visible
        });
        for &[a, b] in &edges {
            if !edges.contains(&[b, a]) {
                tris.push(tri(pts, [a, b, i]));
            }
        }
    }
    Ok(tris)
}

/// Mass properties by the divergence theorem: the solid is the union of the
/// tetrahedra (o, a, b, c) over the boundary triangles, o the vertex mean.
/// Per tetrahedron (relative to o): V = det[a b c]/6, first moment V·(a+b+c)/4,
/// second moment C = det/120 · (aaᵀ + bbᵀ + ccᵀ + ssᵀ), s = a+b+c
/// (Blow & Binstock's canonical tetrahedron). Then I = tr(C)·1 − C about the
/// centroid (parallel-axis shift C_c = C − V·ggᵀ). A closed mesh's mass
/// comes from here too ([`crate::physics::mesh`], which refuses a
/// volume that is not positive).
pub(crate) fn mass_properties(
    vertices: &[Vector3<f64>],
    triangles: &[[usize; 3]],
) -> MassProperties {
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
    let g = first / volume;
    let central = second - g * g.transpose() * volume;
    MassProperties {
        volume,
        centroid: o + g,
        unit_inertia: Matrix3::identity() * central.trace() - central,
    }
}
