//! EPA (expanding polytope): from a polytope inside A − B that holds the
//! origin, split the face closest to the origin at the support point along
//! its normal until that point is no farther out than the face:
//! gap_k = n_k·w_k − δ_k ≤ ε. Then δ is the penetration depth, −n the normal
//! (from B toward A: moving A along it by δ separates the pair), and the
//! origin's projection on the face, δ·n, gives through its barycentric
//! coordinates the deepest point of A in B and of B in A.
//!
//! Stated tolerance: ε = [`EpaOptions::tolerance`] × the polytope's size
//! (the largest |w| of the first tetrahedron), 1e-10 by default; the result
//! carries the gap it ended with. At most [`EpaOptions::max_iterations`]
//! splits. GJK's terminal simplex is grown to a tetrahedron first
//! ([`super::epa_start`]).

use nalgebra::Vector3;

pub use super::epa_observer::{EpaIteration, EpaObserver, EpaRecord, EpaRecorder};
use super::epa_start::tetrahedron;
use super::features::{feature_pair, FeaturePair};
use super::gjk::Pair;
use super::simplex::{Simplex, Vertex};
use super::support::Support;
use crate::physics::pose::Pose;
use crate::physics::{c, Real};

/// Tolerance and cap of an EPA run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EpaOptions<T: Real> {
    pub max_iterations: usize,
    /// ε relative to the polytope's size.
    pub tolerance: T,
}

impl<T: Real> Default for EpaOptions<T> {
    fn default() -> Self {
        EpaOptions {
            max_iterations: 128,
            // 1e-10 in f64; 64 ulps of the float type where that is coarser (f32).
            tolerance: c::<T>(1e-10).max(T::default_epsilon() * c(64.0)),
        }
    }
}

/// Why EPA ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EpaEnd {
    /// gap ≤ ε: the closest face lies on the boundary of A − B.
    Converged,
    /// The cap was reached; the result is the closest face so far.
    IterationCap,
    /// A split would have broken the polytope or moved the closest face
    /// inward (the limit of the float precision): the closest face before it.
    Stalled,
    /// The simplex could not be grown to a solid tetrahedron, or a split
    /// left no face: the result is GJK's (depth 0).
    Degenerate,
}

impl EpaEnd {
    pub const ALL: [EpaEnd; 4] = [
        EpaEnd::Converged,
        EpaEnd::IterationCap,
        EpaEnd::Stalled,
        EpaEnd::Degenerate,
    ];
}

/// The penetration EPA found, world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EpaResult<T: Real> {
    pub end: EpaEnd,
    /// ≥ 0.
    pub depth: T,
    /// Unit, from B toward A.
    pub normal: Vector3<T>,
    /// A's deepest point in B, B's deepest point in A (point_a = point_b − depth·normal).
    pub point_a: Vector3<T>,
    pub point_b: Vector3<T>,
    /// Midway between them.
    pub point: Vector3<T>,
    pub feature: FeaturePair,
    /// The last gap, and ε it was held to.
    pub gap: T,
    pub tolerance: T,
    pub iterations: usize,
}

/// A face of the polytope: vertex indices counter-clockwise from outside.
#[derive(Debug, Clone, Copy)]
struct Face<T: Real> {
    v: [usize; 3],
    n: Vector3<T>,
    dist: T,
}

fn face<T: Real>(verts: &[Vertex<T>], v: [usize; 3]) -> Face<T> {
    let [a, b, c] = v.map(|i| verts[i].w);
    let n = (b - a).cross(&(c - a));
    let len = n.norm();
    if len > T::zero() {
        let n = n / len;
        Face {
            v,
            n,
            dist: n.dot(&a),
        }
    } else {
        // A sliver: never the closest, never seen.
        Face {
            v,
            n: Vector3::zeros(),
            dist: T::max_value().unwrap_or(T::one() / T::default_epsilon()),
        }
    }
}

/// EPA from GJK's terminal `simplex` (whole shapes, no margins).
pub fn epa<T, A, B, O>(
    a: &A,
    pose_a: &Pose<T>,
    b: &B,
    pose_b: &Pose<T>,
    simplex: &Simplex<T>,
    options: &EpaOptions<T>,
    observer: &mut O,
) -> EpaResult<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
    O: EpaObserver<T> + ?Sized,
{
    run(
        &Pair::new(a, pose_a, b, pose_b, false),
        simplex,
        options,
        observer,
    )
}

/// EPA on `pair` (whole shapes, or cores when the pair says so) from a
/// world-coordinate simplex.
pub(super) fn run<T, A, B, O>(
    pair: &Pair<'_, T, A, B>,
    simplex: &Simplex<T>,
    options: &EpaOptions<T>,
    observer: &mut O,
) -> EpaResult<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
    O: EpaObserver<T> + ?Sized,
{
    let mut local = *simplex;
    for p in local.vertices.iter_mut().take(local.len) {
        p.a -= pair.origin;
        p.b -= pair.origin;
    }
    let Some(start) = tetrahedron(pair, &local) else {
        return degenerate(pair, &local);
    };
    let mut verts: Vec<Vertex<T>> = start.to_vec();
    let scale = verts.iter().map(|v| v.w.norm()).fold(T::zero(), T::max);
    let eps = options.tolerance * scale;
    let centre = verts.iter().fold(Vector3::zeros(), |s, v| s + v.w) / c::<T>(4.0);
    let mut faces: Vec<Face<T>> = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
        .into_iter()
        .map(|v| {
            let f = face(&verts, v);
            // Outward: the centre lies behind.
            if f.n.dot(&(centre - verts[v[0]].w)) > T::zero() {
                face(&verts, [v[0], v[2], v[1]])
            } else {
                f
            }
        })
        .collect();
    let want = observer.wants_faces();
    let (mut removed, mut added, mut horizon) = (Vec::new(), Vec::new(), Vec::<[usize; 2]>::new());
    let mut iterations = 0;
    let mut gap = T::zero();
    let mut end = EpaEnd::IterationCap;
    let mut best = closest(&faces);
    while iterations < options.max_iterations {
        let f = faces[best];
        let w = pair.vertex(&f.n);
        gap = f.n.dot(&w.w) - f.dist;
        iterations += 1;
        let mut record = EpaIteration {
            index: iterations - 1,
            face: f.v.map(|i| verts[i].w),
            normal: f.n,
            distance: f.dist,
            support: pair.world(&w),
            gap,
            removed: 0,
            added: 0,
        };
        if gap <= eps {
            observer.iteration(&record, &[], &[]);
            end = EpaEnd::Converged;
            break;
        }
        // The faces w sees, connected to the closest one, go; each horizon
        // edge (a removed face's edge whose twin stays) makes a new face with w.
        let k = verts.len();
        verts.push(w);
        let seen = visible_from(&faces, &verts, best, &w.w, eps);
        horizon.clear();
        for &i in &seen {
            let v = faces[i].v;
            horizon.extend([[v[0], v[1]], [v[1], v[2]], [v[2], v[0]]]);
        }
        let edges: Vec<[usize; 2]> = horizon
            .iter()
            .copied()
            .filter(|&[p, q]| !horizon.contains(&[q, p]))
            .collect();
        // A disc of removed faces has a horizon of removed + 2 edges; anything
        // else (a ring, at the limit of the precision) would break the polytope.
        if edges.len() != seen.len() + 2 {
            observer.iteration(&record, &[], &[]);
            end = EpaEnd::Stalled;
            break;
        }
        removed.clear();
        if want {
            removed.extend(seen.iter().map(|&i| faces[i].v.map(|j| verts[j].w)));
        }
        let mut index = 0;
        faces.retain(|_| {
            index += 1;
            !seen.contains(&(index - 1))
        });
        let before = faces.len();
        faces.extend(edges.iter().map(|&[p, q]| face(&verts, [p, q, k])));
        record.removed = seen.len();
        record.added = faces.len() - before;
        if want {
            added.clear();
            added.extend(faces[before..].iter().map(|g| g.v.map(|i| verts[i].w)));
        }
        observer.iteration(&record, &removed, &added);
        let next = closest(&faces);
        if faces[next].dist < f.dist - eps {
            // The closest distance never shrinks in exact arithmetic: keep f.
            faces.push(f);
            best = faces.len() - 1;
            end = EpaEnd::Stalled;
            break;
        }
        best = next;
    }
    let f = faces[best];
    result(pair, &verts, &f, end, gap, eps, iterations)
}

/// The faces that see `w` (beyond their plane by more than `eps`) reached
/// from face `start` through shared edges.
fn visible_from<T: Real>(
    faces: &[Face<T>],
    verts: &[Vertex<T>],
    start: usize,
    w: &Vector3<T>,
    eps: T,
) -> Vec<usize> {
    let sees = |g: &Face<T>| g.n.dot(&(w - verts[g.v[0]].w)) > eps;
    let mut seen = vec![start];
    let mut k = 0;
    while k < seen.len() {
        let g = faces[seen[k]].v;
        k += 1;
        for [p, q] in [[g[0], g[1]], [g[1], g[2]], [g[2], g[0]]] {
            let twin = faces.iter().position(|h| {
                h.v.iter()
                    .zip(h.v.iter().cycle().skip(1))
                    .any(|(&x, &y)| x == q && y == p)
            });
            if let Some(t) = twin {
                if !seen.contains(&t) && sees(&faces[t]) {
                    seen.push(t);
                }
            }
        }
    }
    seen
}

/// Index of the face with the smallest distance.
fn closest<T: Real>(faces: &[Face<T>]) -> usize {
    let mut best = 0;
    for (i, f) in faces.iter().enumerate() {
        if f.dist < faces[best].dist {
            best = i;
        }
    }
    best
}

/// Depth, normal and points from face `f`: the origin's projection δ n has
/// barycentric coordinates λ_i = area(opposite sub-triangle)/area(face).
fn result<T: Real, A: Support<T> + ?Sized, B: Support<T> + ?Sized>(
    pair: &Pair<'_, T, A, B>,
    verts: &[Vertex<T>],
    f: &Face<T>,
    end: EpaEnd,
    gap: T,
    eps: T,
    iterations: usize,
) -> EpaResult<T> {
    let [p, q, r] = f.v.map(|i| verts[i]);
    let x = f.n * f.dist;
    let whole = (q.w - p.w).cross(&(r.w - p.w)).dot(&f.n);
    let l = [
        (q.w - x).cross(&(r.w - x)).dot(&f.n) / whole,
        (r.w - x).cross(&(p.w - x)).dot(&f.n) / whole,
        (p.w - x).cross(&(q.w - x)).dot(&f.n) / whole,
    ];
    let point_a = p.a * l[0] + q.a * l[1] + r.a * l[2] + pair.origin;
    let point_b = p.b * l[0] + q.b * l[1] + r.b * l[2] + pair.origin;
    EpaResult {
        end,
        depth: f.dist.max(T::zero()),
        normal: -f.n,
        point_a,
        point_b,
        point: (point_a + point_b) * c::<T>(0.5),
        feature: feature_pair(&[p.a, q.a, r.a], &[p.b, q.b, r.b], eps),
        gap,
        tolerance: eps,
        iterations,
    }
}

/// No solid start: depth 0 at GJK's closest points, normal along A − B's centres.
fn degenerate<T: Real, A: Support<T> + ?Sized, B: Support<T> + ?Sized>(
    pair: &Pair<'_, T, A, B>,
    simplex: &Simplex<T>,
) -> EpaResult<T> {
    let point_a = simplex.combine(|p| p.a) + pair.origin;
    let point_b = simplex.combine(|p| p.b) + pair.origin;
    let normal = pair
        .a_pose
        .position
        .try_normalize(T::zero())
        .unwrap_or_else(Vector3::y);
    let pts = |f: &dyn Fn(&Vertex<T>) -> Vector3<T>| {
        let s = simplex.points();
        [f(&s[0]), f(&s[s.len().min(2) - 1]), f(&s[s.len() - 1])]
    };
    EpaResult {
        end: EpaEnd::Degenerate,
        depth: T::zero(),
        normal,
        point_a,
        point_b,
        point: (point_a + point_b) * c::<T>(0.5),
        feature: feature_pair(&pts(&|p| p.a), &pts(&|p| p.b), T::zero()),
        gap: T::zero(),
        tolerance: T::zero(),
        iterations: 0,
    }
}
