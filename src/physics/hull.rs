//! Convex hull of a point cloud (incremental, with quickhull's conflicts:
//! each waiting point holds one face it sees): its vertices, polygon faces with outward normals, edges,
//! and the mass properties of the solid for uniform density.
//!
//! Robustness: every plane test has the tolerance ε = 1e-10 × the cloud's
//! extent, so duplicate points, points inside, and points on a face (within
//! ε) add nothing; points are added farthest from the first tetrahedron's
//! centre first, so the corners of a box come before points on its edges or
//! faces. Coplanar triangles are merged into one polygon face. A cloud with
//! fewer than 4 points that are not coplanar is rejected with a [`HullError`].

use std::collections::HashMap;

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
    /// Points so nearly coplanar that the incremental build cannot keep
    /// its faces closed, even at a tolerance widened 1,000 times.
    #[error("the points are too nearly coplanar to build a hull (its faces did not stay closed at tolerance {tolerance:e} m): round them or drop the points near the faces")]
    Tangled { tolerance: f64 },
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
    /// The tolerance the build needed when the first one (1e-10 of the
    /// points' extent) could not keep its faces closed (`None`: the first).
    widened: Option<f64>,
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
        let first = extent_eps(&pts);
        // Nearly coplanar points can tangle the build at the first
        // tolerance: widened tenfold at a time, at most 1,000 times, and said.
        let mut eps = first;
        loop {
            match build(&pts, eps) {
                Ok((tris, _)) => {
                    let mut hull = Self::from_triangles(&pts, &tris, eps);
                    hull.widened = (eps > first).then_some(eps);
                    return Ok(hull);
                }
                Err(HullError::Tangled { .. }) if eps < 999.0 * first => eps *= 10.0,
                Err(e) => return Err(e),
            }
        }
    }

    /// This hull, built again from `first`'s vertices (moved), keeping what
    /// `first`'s build had to widen its tolerance to.
    pub fn rebuilt_from(mut self, first: &ConvexHull) -> ConvexHull {
        self.widened = self.widened.or(first.widened);
        self
    }

    /// The tolerance the build was widened to for nearly coplanar points
    /// (`None`: built at the first, 1e-10 of the points' extent).
    pub fn widened_tolerance(&self) -> Option<f64> {
        self.widened
    }

    /// The number of plane tests building the hull of `points` takes (its
    /// work; debug builds only, for the tests that bound it).
    #[cfg(debug_assertions)]
    pub fn plane_tests(points: &[[f64; 3]]) -> Result<usize, HullError> {
        let pts: Vec<Vector3<f64>> = points.iter().map(|p| Vector3::from(*p)).collect();
        Ok(build(&pts, extent_eps(&pts))?.1)
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
            widened: None,
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

/// The plane tests' tolerance: 1e-10 × the cloud's extent.
fn extent_eps(pts: &[Vector3<f64>]) -> f64 {
    let (lo, hi) = pts
        .iter()
        .fold((pts[0], pts[0]), |(lo, hi), p| (lo.inf(p), hi.sup(p)));
    1e-10 * (hi - lo).amax()
}

/// The first tetrahedron (extreme points) and its four outward triangles,
/// then the other points, farthest from the tetrahedron's centre first.
fn start(pts: &[Vector3<f64>], eps: f64) -> Result<(Vec<Tri>, Vec<usize>), HullError> {
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
    let tris: Vec<Tri> = [[i0, i1, i2], [i0, i1, i3], [i0, i2, i3], [i1, i2, i3]]
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
    Ok((tris, order))
}

/// The hull's triangles, built point by point in the order of [`start`]: a
/// point that sees no triangle (n·p − d ≤ ε for all) adds nothing; one that
/// does replaces the triangles it sees by a cone from their horizon. Each
/// point waiting its turn holds one triangle it sees (its conflict), or none
/// when it is inside: the hull only grows, so it is never tested again. The
/// triangles a point sees are found from its conflict over the triangles'
/// edges; only the points whose conflict was removed are tested again, on
/// the new cone (quickhull's argument: a point beyond a removed triangle and
/// outside the new hull sees a triangle of the cone). Triangles live in a
/// slab in creation order, so the result is in the order of a list where
/// removed triangles are dropped and new ones appended. Also returns the
/// number of plane tests, the build's work.
fn build(pts: &[Vector3<f64>], eps: f64) -> Result<(Vec<Tri>, usize), HullError> {
    let (mut tris, order) = start(pts, eps)?;
    let mut tests = 0;
    let mut sees = |t: &Tri, p: &Vector3<f64>| {
        tests += 1;
        t.n.dot(p) - t.d > eps
    };
    // Per triangle: live, the points whose conflict it is; per directed edge
    // (a, b) the triangle that has it.
    let mut live = vec![true; 4];
    let mut outside: Vec<Vec<usize>> = vec![Vec::new(); 4];
    let mut by_edge: HashMap<[usize; 2], usize> = HashMap::new();
    for (k, t) in tris.iter().enumerate() {
        for e in directed(t) {
            by_edge.insert(e, k);
        }
    }
    let mut conflict = vec![usize::MAX; pts.len()];
    for &i in &order {
        if let Some(k) = (0..4).find(|&k| sees(&tris[k], &pts[i])) {
            conflict[i] = k;
            outside[k].push(i);
        }
    }
    let mut done = vec![false; pts.len()];
    let mut mark = vec![0u8; 4]; // 1 visible, 2 tested and not visible
    let (mut visible, mut tested, mut moved) = (Vec::new(), Vec::new(), Vec::new());
    for i in order {
        done[i] = true;
        let p = pts[i];
        let first = conflict[i];
        if first == usize::MAX {
            continue; // inside or on the hull
        }
        // The visible triangles: a search from the conflict over edges.
        visible.clear();
        tested.clear();
        visible.push(first);
        mark[first] = 1;
        let mut next = 0;
        while next < visible.len() {
            let k = visible[next];
            next += 1;
            for [a, b] in directed(&tris[k]) {
                let m = *by_edge
                    .get(&[b, a])
                    .ok_or(HullError::Tangled { tolerance: eps })?;
                if mark[m] == 0 {
                    if sees(&tris[m], &p) {
                        mark[m] = 1;
                        visible.push(m);
                    } else {
                        mark[m] = 2;
                        tested.push(m);
                    }
                }
            }
        }
        // In creation order: the horizon edges come as the old list's did.
        visible.sort_unstable();
        let mut horizon: Vec<[usize; 2]> = Vec::new();
        for [a, b] in visible.iter().flat_map(|&k| directed(&tris[k])) {
            let across = *by_edge
                .get(&[b, a])
                .ok_or(HullError::Tangled { tolerance: eps })?;
            if mark[across] != 1 {
                horizon.push([a, b]);
            }
        }
        moved.clear();
        for &k in &visible {
            live[k] = false;
            mark[k] = 0;
            for e in directed(&tris[k]) {
                by_edge.remove(&e);
            }
            moved.extend(
                std::mem::take(&mut outside[k])
                    .into_iter()
                    .filter(|&j| !done[j]),
            );
        }
        for &k in &tested {
            mark[k] = 0;
        }
        let cone = tris.len();
        for [a, b] in horizon {
            let t = tri(pts, [a, b, i]);
            for e in directed(&t) {
                by_edge.insert(e, tris.len());
            }
            tris.push(t);
            live.push(true);
            outside.push(Vec::new());
            mark.push(0);
        }
        for &j in &moved {
            conflict[j] = usize::MAX;
            if let Some(k) = (cone..tris.len()).find(|&k| sees(&tris[k], &pts[j])) {
                conflict[j] = k;
                outside[k].push(j);
            }
        }
    }
    // Closed: every live triangle's edge has its reverse (an overwritten
    // edge, from a tangled horizon, would leave one without).
    let closed = (tris.iter().zip(&live))
        .filter(|(_, l)| **l)
        .flat_map(|(t, _)| directed(t))
        .all(|[a, b]| by_edge.get(&[b, a]).is_some_and(|&m| live[m]));
    if !closed {
        return Err(HullError::Tangled { tolerance: eps });
    }
    let hull = tris
        .into_iter()
        .zip(live)
        .filter(|(_, l)| *l)
        .map(|(t, _)| t);
    Ok((hull.collect(), tests))
}

/// A triangle's directed edges (a, b), (b, c), (c, a).
fn directed(t: &Tri) -> [[usize; 2]; 3] {
    let [a, b, c] = t.v;
    [[a, b], [b, c], [c, a]]
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

#[cfg(test)]
#[path = "hull_tests.rs"]
mod tests;
