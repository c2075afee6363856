//! EPA's first polytope: GJK's terminal simplex (1–4 points holding the
//! origin) grown to a solid tetrahedron with support points, keeping every
//! point it had so that the origin stays inside:
//! a point gains a second along ±x, ±y, ±z; a segment a third along one of
//! six directions 60° apart about it; a triangle a fourth along ±its normal;
//! a flat tetrahedron is cut to the face holding the origin first.

use nalgebra::Vector3;

use super::gjk::Pair;
use super::simplex::{Simplex, Vertex};
use super::support::Support;
use crate::physics::{c, Real};

/// Four support points spanning a solid that holds the origin, or `None`
/// when the Minkowski difference is flat (or the simplex is degenerate).
pub(super) fn tetrahedron<T, A, B>(
    pair: &Pair<'_, T, A, B>,
    simplex: &Simplex<T>,
) -> Option<[Vertex<T>; 4]>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
{
    let mut pts: Vec<Vertex<T>> = simplex.points().to_vec();
    let size = pts.iter().map(|p| p.w.norm()).fold(T::zero(), T::max);
    let probe = [Vector3::x(), Vector3::y(), Vector3::z()];
    let size = probe
        .iter()
        .map(|d| pair.vertex(d).w.norm())
        .fold(size, T::max);
    let eps = c::<T>(1e-10).max(T::default_epsilon() * c(64.0)) * size;
    if pts.len() == 4 && volume(&pts).abs() <= eps * eps * eps {
        pts = best_face(&pts);
    }
    // Drop repeated points.
    let mut unique: Vec<Vertex<T>> = Vec::with_capacity(4);
    for p in pts {
        if unique.iter().all(|q| (q.w - p.w).norm() > eps) {
            unique.push(p);
        }
    }
    let mut pts = unique;
    if pts.len() == 1 {
        let dirs = probe.iter().flat_map(|d| [*d, -d]);
        let w0 = pts[0].w;
        pts.extend(
            dirs.map(|d| pair.vertex(&d))
                .find(|w| (w.w - w0).norm() > eps),
        );
    }
    if pts.len() == 2 {
        let e = pts[1].w - pts[0].w;
        let k = e.iamin();
        let perp = e.cross(&probe[k]).normalize();
        let other = e.normalize().cross(&perp);
        let w0 = pts[0].w;
        let off_line = |w: &Vector3<T>| (w - w0).cross(&e).norm() / e.norm();
        pts.extend(
            (0..6)
                .map(|i| {
                    let t = c::<T>(std::f64::consts::FRAC_PI_3 * i as f64);
                    pair.vertex(&(perp * t.cos() + other * t.sin()))
                })
                .find(|w| off_line(&w.w) > eps),
        );
    }
    if pts.len() == 3 {
        let n = (pts[1].w - pts[0].w).cross(&(pts[2].w - pts[0].w));
        if n.norm() <= eps * eps {
            return None;
        }
        let n = n.normalize();
        let w0 = pts[0].w;
        let up = pair.vertex(&n);
        let down = pair.vertex(&-n);
        let (hu, hd) = (n.dot(&(up.w - w0)), -n.dot(&(down.w - w0)));
        pts.push(if hu >= hd { up } else { down });
        if hu.max(hd) <= eps {
            return None;
        }
    }
    if pts.len() == 4 {
        Some([pts[0], pts[1], pts[2], pts[3]])
    } else {
        None
    }
}

fn volume<T: Real>(p: &[Vertex<T>]) -> T {
    (p[1].w - p[0].w).dot(&(p[2].w - p[0].w).cross(&(p[3].w - p[0].w)))
}

/// Of a flat tetrahedron's four faces, the one closest to the origin (it
/// holds the origin when the tetrahedron does).
fn best_face<T: Real>(p: &[Vertex<T>]) -> Vec<Vertex<T>> {
    let faces = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];
    let w: Vec<Vector3<T>> = p.iter().map(|v| v.w).collect();
    let mut best = (T::max_value().unwrap_or(T::one()), 0);
    for (i, f) in faces.iter().enumerate() {
        let tri = [w[f[0]], w[f[1]], w[f[2]]];
        let proj = super::simplex::project(&tri);
        let d = (0..3)
            .fold(Vector3::zeros(), |s, k| s + tri[k] * proj.lambdas[k])
            .norm();
        if d < best.0 {
            best = (d, i);
        }
    }
    faces[best.1].iter().map(|&i| p[i]).collect()
}
