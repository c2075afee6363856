//! The support feature of a shape along a direction, as a polygon: a box's
//! or hull's face most aligned with it; a cylinder's cap (a regular polygon
//! of [`CAP_SIDES`] sides inscribed in the rim, one corner at the rim's
//! support point) or its side (the segment of
//! its two rim points along the direction); a capsule's side segment (the
//! two end spheres' points along the direction) within about 11° of
//! perpendicular to its axis; otherwise the single support point.

use nalgebra::Vector3;

use super::support::{Convex, Support};
use crate::physics::pose::Pose;
use crate::physics::{c, to_f64, Real};

/// Sides of the polygon standing for a cylinder's cap.
pub const CAP_SIDES: usize = 16;

/// A support feature in world coordinates: 1 point, 2 (a segment) or a
/// convex polygon counter-clockwise seen from outside; its unit outward normal.
#[derive(Debug, Clone, PartialEq)]
pub struct SupportFace<T: Real> {
    pub points: Vec<Vector3<T>>,
    pub normal: Vector3<T>,
}

/// The support feature of `shape` at `pose` along world direction `dir`.
pub fn support_face<T: Real>(shape: &Convex, pose: &Pose<T>, dir: &Vector3<T>) -> SupportFace<T> {
    let d = pose.rotation.tr_mul(dir);
    let dn = d.try_normalize(T::zero()).unwrap_or_else(Vector3::y);
    let world = |local: Vec<Vector3<T>>, normal: Vector3<T>| SupportFace {
        points: local.iter().map(|p| pose.to_world(p)).collect(),
        normal: pose.rotation * normal,
    };
    match shape {
        Convex::Cuboid { half } => {
            let k = d.iamax();
            let s = if d[k] < T::zero() {
                -T::one()
            } else {
                T::one()
            };
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            let mut corners: Vec<Vector3<T>> = [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
                .iter()
                .map(|&(u, v)| {
                    let mut p = Vector3::zeros();
                    p[k] = s * c::<T>(half[k]);
                    p[i] = c::<T>(u * half[i]);
                    p[j] = c::<T>(v * half[j]);
                    p
                })
                .collect();
            if s < T::zero() {
                corners.reverse();
            }
            let mut normal = Vector3::zeros();
            normal[k] = s;
            world(corners, normal)
        }
        Convex::Hull(hull) => {
            let df = Vector3::new(to_f64(d.x), to_f64(d.y), to_f64(d.z));
            let face = hull
                .faces()
                .iter()
                .max_by(|f, g| f.normal.dot(&df).total_cmp(&g.normal.dot(&df)))
                .expect("a hull has faces");
            let local = face
                .vertices
                .iter()
                .map(|&i| hull.vertices()[i].map(c::<T>))
                .collect();
            world(local, face.normal.map(c::<T>))
        }
        Convex::Cylinder {
            radius,
            half_height,
        } => {
            let (r, h) = (c::<T>(*radius), c::<T>(*half_height));
            let radial = (dn.x * dn.x + dn.z * dn.z).sqrt();
            if dn.y.abs() >= radial {
                let s = if dn.y < T::zero() {
                    -T::one()
                } else {
                    T::one()
                };
                // The first corner is the rim's support point along d (its
                // direction in the cap's plane, at angle t₀ = atan2(d_x, d_z)),
                // so the polygon holds the rim's deepest point exactly and a
                // cap resting on a face gets a symmetric set of corners.
                let start = if radial > c(1e-9) {
                    dn.x.atan2(dn.z)
                } else {
                    T::zero()
                };
                let mut rim: Vec<Vector3<T>> = (0..CAP_SIDES)
                    .map(|m| {
                        let t = start + c::<T>(std::f64::consts::TAU * m as f64 / CAP_SIDES as f64);
                        Vector3::new(r * t.sin(), s * h, r * t.cos())
                    })
                    .collect();
                if s < T::zero() {
                    rim.reverse();
                }
                world(rim, Vector3::new(T::zero(), s, T::zero()))
            } else {
                let out = Vector3::new(dn.x / radial, T::zero(), dn.z / radial);
                let p = out * r;
                world(vec![p + Vector3::y() * h, p - Vector3::y() * h], out)
            }
        }
        Convex::Capsule(cap) => {
            let h = c::<T>(cap.height / 2.0);
            let side = dn.y.abs() <= c(0.2);
            let end = |y: T| Vector3::new(T::zero(), y, T::zero()) + dn * c::<T>(cap.radius);
            if side {
                world(vec![end(h), end(-h)], dn)
            } else {
                world(vec![shape.local_support(&d)], dn)
            }
        }
        Convex::Sphere { .. } => world(vec![shape.local_support(&d)], dn),
    }
}

/// How far world point `p` lies outside `shape` at `pose` (≤ 0: inside or
/// on it): a box's max_k |x_k| − h_k, a hull's max over its faces of
/// n·x − offset, a cylinder's max(|y| − h, √(x² + z²) − r), a sphere's or
/// capsule's distance to its core less the radius (x in the body frame).
/// Exact on the flat faces, a bound within the round edges.
pub fn outside_by<T: Real>(shape: &Convex, pose: &Pose<T>, p: &Vector3<T>) -> T {
    let x = pose.to_local(p);
    match shape {
        Convex::Cuboid { half } => (0..3)
            .map(|k| x[k].abs() - c::<T>(half[k]))
            .fold(T::min_value().unwrap_or(-T::one()), T::max),
        Convex::Hull(hull) => hull
            .faces()
            .iter()
            .map(|f| f.normal.map(c::<T>).dot(&x) - c::<T>(f.offset))
            .fold(T::min_value().unwrap_or(-T::one()), T::max),
        Convex::Cylinder {
            radius,
            half_height,
        } => {
            (x.y.abs() - c::<T>(*half_height)).max((x.x * x.x + x.z * x.z).sqrt() - c::<T>(*radius))
        }
        Convex::Sphere { radius } => x.norm() - c::<T>(*radius),
        Convex::Capsule(cap) => {
            let h = c::<T>(cap.height / 2.0);
            let core = Vector3::new(T::zero(), x.y.max(-h).min(h), T::zero());
            (x - core).norm() - c::<T>(cap.radius)
        }
    }
}
