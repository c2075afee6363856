//! GJK's simplex and its sub-algorithm: the point of the simplex closest to
//! the origin and the smallest sub-simplex that holds it.
//!
//! The signed-volumes method (Montanari, Petrinic & Barbieri 2017): the
//! origin's barycentric coordinates are ratios of signed volumes (lengths on
//! the axis where the segment is longest, areas on the coordinate plane where
//! the triangle's shadow is largest, volumes of tetrahedra). Where every
//! coordinate is positive the origin projects inside; otherwise the faces
//! opposite the non-positive coordinates are searched and the closest kept.
//! Chosen over Johnson's sub-algorithm because it never solves a linear
//! system through a near-zero determinant: a flat tetrahedron or a sliver
//! triangle falls through to its faces or edges instead of returning
//! garbage, which is what makes touching and parallel-face cases safe.

use nalgebra::Vector3;

use crate::physics::Real;

/// One simplex vertex: w = a − b, from the support points a of A and b of B.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vertex<T: Real> {
    pub w: Vector3<T>,
    pub a: Vector3<T>,
    pub b: Vector3<T>,
}

/// 1 to 4 vertices (point, segment, triangle, tetrahedron) with the
/// barycentric coordinates of the closest point `v = Σ λ_i w_i`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Simplex<T: Real> {
    pub vertices: [Vertex<T>; 4],
    pub lambdas: [T; 4],
    pub len: usize,
}

/// Result of the sub-algorithm on vertices `0..len`: the barycentric
/// coordinates (zero for a dropped vertex) and the bit mask of the kept ones.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projection<T: Real> {
    pub lambdas: [T; 4],
    pub kept: u8,
}

impl<T: Real> Simplex<T> {
    /// A one-point simplex.
    pub fn point(v: Vertex<T>) -> Self {
        Simplex {
            vertices: [v; 4],
            lambdas: [T::one(), T::zero(), T::zero(), T::zero()],
            len: 1,
        }
    }

    /// The vertices in use.
    pub fn points(&self) -> &[Vertex<T>] {
        &self.vertices[..self.len]
    }

    /// Appends a vertex (the caller keeps len ≤ 4).
    pub fn push(&mut self, v: Vertex<T>) {
        self.vertices[self.len] = v;
        self.len += 1;
    }

    /// Σ λ_i x_i for x = w, a or b.
    pub fn combine(&self, f: impl Fn(&Vertex<T>) -> Vector3<T>) -> Vector3<T> {
        (0..self.len).fold(Vector3::zeros(), |s, i| {
            s + f(&self.vertices[i]) * self.lambdas[i]
        })
    }

    /// Keeps the vertices of `p.kept` with their coordinates, in order.
    pub fn reduce(&mut self, p: &Projection<T>) {
        let mut n = 0;
        for i in 0..self.len {
            if p.kept >> i & 1 == 1 {
                self.vertices[n] = self.vertices[i];
                self.lambdas[n] = p.lambdas[i];
                n += 1;
            }
        }
        self.len = n;
    }
}

/// The signed-volumes sub-algorithm on `w[0..len]`.
pub fn project<T: Real>(w: &[Vector3<T>]) -> Projection<T> {
    match w.len() {
        1 => Projection {
            lambdas: [T::one(), T::zero(), T::zero(), T::zero()],
            kept: 1,
        },
        2 => on_segment(w, [0, 1]),
        3 => on_triangle(w, [0, 1, 2]),
        _ => on_tetrahedron(w),
    }
}

fn squared_distance<T: Real>(w: &[Vector3<T>], p: &Projection<T>) -> T {
    (0..w.len())
        .fold(Vector3::zeros(), |s, i| s + w[i] * p.lambdas[i])
        .norm_squared()
}

fn only<T: Real>(i: usize) -> Projection<T> {
    let mut lambdas = [T::zero(); 4];
    lambdas[i] = T::one();
    Projection {
        lambdas,
        kept: 1 << i,
    }
}

/// Segment [w_i, w_j]: the origin's projection p on the line, coordinates
/// from lengths on the axis where the segment is longest (S1D).
fn on_segment<T: Real>(w: &[Vector3<T>], [i, j]: [usize; 2]) -> Projection<T> {
    let (a, b) = (w[i], w[j]);
    let t = b - a;
    let tt = t.norm_squared();
    if tt <= T::zero() {
        return only(i);
    }
    let p = a - t * (a.dot(&t) / tt);
    let k = t.iamax();
    let mu = t[k];
    let (la, lb) = ((b[k] - p[k]) / mu, (p[k] - a[k]) / mu);
    if la <= T::zero() {
        only(j)
    } else if lb <= T::zero() {
        only(i)
    } else {
        let mut lambdas = [T::zero(); 4];
        lambdas[i] = la;
        lambdas[j] = lb;
        Projection {
            lambdas,
            kept: 1 << i | 1 << j,
        }
    }
}

/// Triangle (w_i, w_j, w_k): the origin projected on its plane, coordinates
/// from signed areas on the coordinate plane of largest shadow (S2D).
fn on_triangle<T: Real>(w: &[Vector3<T>], v: [usize; 3]) -> Projection<T> {
    let [a, b, c] = v.map(|i| w[i]);
    let n = (b - a).cross(&(c - a));
    let nn = n.norm_squared();
    let edges = [[v[1], v[2]], [v[0], v[2]], [v[0], v[1]]];
    if nn > T::zero() {
        let p = n * (n.dot(&a) / nn);
        let k = n.iamax();
        let (x, y) = ((k + 1) % 3, (k + 2) % 3);
        // Twice the signed area of (q, r, s) on the plane (x, y).
        let area = |q: &Vector3<T>, r: &Vector3<T>, s: &Vector3<T>| {
            (r[x] - q[x]) * (s[y] - q[y]) - (s[x] - q[x]) * (r[y] - q[y])
        };
        let total = n[k];
        let l = [
            area(&p, &b, &c) / total,
            area(&a, &p, &c) / total,
            area(&a, &b, &p) / total,
        ];
        if l.iter().all(|&x| x > T::zero()) {
            let mut lambdas = [T::zero(); 4];
            for m in 0..3 {
                lambdas[v[m]] = l[m];
            }
            return Projection {
                lambdas,
                kept: 1 << v[0] | 1 << v[1] | 1 << v[2],
            };
        }
        best(
            w,
            (0..3)
                .filter(|&m| l[m] <= T::zero())
                .map(|m| on_segment(w, edges[m])),
        )
    } else {
        // A degenerate (flat) triangle: its closest point is on an edge.
        best(w, edges.into_iter().map(|e| on_segment(w, e)))
    }
}

/// Tetrahedron: the origin's coordinates are signed volumes over the whole
/// (S3D); outside (or flat), the faces opposite non-positive coordinates.
fn on_tetrahedron<T: Real>(w: &[Vector3<T>]) -> Projection<T> {
    let vol = |p: &Vector3<T>, q: &Vector3<T>, r: &Vector3<T>, s: &Vector3<T>| {
        (q - p).dot(&(r - p).cross(&(s - p)))
    };
    let o = Vector3::zeros();
    let total = vol(&w[0], &w[1], &w[2], &w[3]);
    let faces = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];
    if total != T::zero() {
        let l = [
            vol(&o, &w[1], &w[2], &w[3]) / total,
            vol(&w[0], &o, &w[2], &w[3]) / total,
            vol(&w[0], &w[1], &o, &w[3]) / total,
            vol(&w[0], &w[1], &w[2], &o) / total,
        ];
        if l.iter().all(|&x| x > T::zero()) {
            return Projection {
                lambdas: l,
                kept: 0b1111,
            };
        }
        best(
            w,
            (0..4)
                .filter(|&m| l[m] <= T::zero())
                .map(|m| on_triangle(w, faces[m])),
        )
    } else {
        best(w, faces.into_iter().map(|f| on_triangle(w, f)))
    }
}

/// The candidate closest to the origin (the first on ties).
fn best<T: Real>(
    w: &[Vector3<T>],
    candidates: impl Iterator<Item = Projection<T>>,
) -> Projection<T> {
    let mut out: Option<(T, Projection<T>)> = None;
    for p in candidates {
        let d = squared_distance(w, &p);
        if out.as_ref().is_none_or(|(best, _)| d < *best) {
            out = Some((d, p));
        }
    }
    out.map_or_else(|| only(0), |(_, p)| p)
}
