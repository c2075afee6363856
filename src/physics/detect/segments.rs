//! Two sides touching along a line: a capsule lying on a capsule, or on a
//! cylinder's side. Their support features are segments; the single point
//! of the penetration would let the pair rest on one point and roll (a
//! lying capsule on a lying capsule moved 6.6 mm in 5 s). Where the two
//! segments are parallel (within 1°, the reference face's rule), the
//! incident segment (A's) is clipped to the reference segment's (B's)
//! extent along it, and the overlap's two ends are the contacts, each with
//! its own depth along the pair's normal, as parry and Box2D v3 do for two
//! capsules.

use nalgebra::Vector3;

use super::manifold_point::ManifoldPoint;
use super::query::Penetration;
use crate::physics::pose::Side;
use crate::physics::{c, Real};

/// The two ends of the overlap of A's side segment `a` and B's side segment
/// `b` (their points on the surfaces, along −n and n) as contacts, or
/// `None` where the segments are not parallel, barely overlap, or no end
/// lies within `margin` (a rounding error's worth of the size at most) of
/// touching.
pub(super) fn parallel_sides<T: Real>(
    a: &[Vector3<T>],
    b: &[Vector3<T>],
    pen: &Penetration<T>,
    margin: T,
) -> Option<Vec<ManifoldPoint<T>>> {
    let (a0, a1, b0, b1) = (a[0], a[1], b[0], b[1]);
    let length_b = (b1 - b0).norm();
    let u = (b1 - b0).try_normalize(T::zero())?;
    let va = a1 - a0;
    let length_a = va.norm();
    if length_a <= T::zero() || va.dot(&u).abs() < c::<T>(0.99985) * length_a {
        return None;
    }
    let size = length_a.max(length_b).max(pen.depth);
    let tiny = c::<T>(1e-9) * size;
    // A's ends along B's direction, from b0; the overlap with [0, |b|].
    let (t0, t1) = (u.dot(&(a0 - b0)), u.dot(&(a1 - b0)));
    let lo = t0.min(t1).max(T::zero());
    let hi = t0.max(t1).min(length_b);
    if hi - lo <= tiny {
        return None;
    }
    let tol = tiny + margin.max(T::zero()).min(c::<T>(1e-6) * size);
    let n = pen.normal;
    let points: Vec<ManifoldPoint<T>> = [lo, hi]
        .into_iter()
        .map(|t| {
            // The point of A's segment at t along u, and B's there.
            let q = a0 + va * ((t - t0) / (t1 - t0));
            let p = b0 + u * t;
            ManifoldPoint {
                point: q,
                normal: n,
                penetration: n.dot(&(p - q)),
                reference: Some(Side::B),
            }
        })
        .filter(|m| m.penetration >= -tol)
        .collect();
    (!points.is_empty()).then_some(points)
}
