//! Support mappings: s(d) = the point of a convex shape farthest along d.
//!
//! Every convex shape is a *core* inflated by a *margin* (a ball of that
//! radius): s(d) = s_core(d) + margin · d/|d|. A sphere is a point with its
//! radius as margin, a capsule a segment with its radius; boxes, cylinders
//! and hulls have no margin. GJK runs on the cores and adds the margins at the
//! end, which makes sphere and capsule distances exact (closed forms to
//! round-off) instead of a slow approach to a curved surface.
//!
//! A half-space is not a support shape (its support is at infinity for every
//! direction but one): a plane pair keeps the analytic routine, which needs
//! only the other shape's support along the plane's inward normal, the
//! deepest point `s(-n)`, and its depth `n·(p - s(-n))` ([`plane_depth`]).

use std::sync::Arc;

use nalgebra::Vector3;

use crate::physics::hull::ConvexHull;
use crate::physics::pose::Pose;
use crate::physics::{c, to_f64, Real, Shape};

/// A convex shape's support mapping in its body frame.
pub trait Support<T: Real> {
    /// The body-frame point of the core farthest along body-frame `d`.
    fn core_support(&self, d: &Vector3<T>) -> Vector3<T>;

    /// The radius by which the core is inflated (0 for shapes without one).
    fn margin(&self) -> T {
        T::zero()
    }

    /// The body-frame point of the whole shape farthest along `d`:
    /// s(d) = s_core(d) + margin · d/|d|.
    fn local_support(&self, d: &Vector3<T>) -> Vector3<T> {
        let core = self.core_support(d);
        let m = self.margin();
        let n = d.norm();
        if m > T::zero() && n > T::zero() {
            core + d * (m / n)
        } else {
            core
        }
    }

    /// The world point farthest along world `d` with the body at `pose`:
    /// s_world(d) = x + R s(Rᵀ d).
    fn support(&self, pose: &Pose<T>, d: &Vector3<T>) -> Vector3<T> {
        pose.to_world(&self.local_support(&pose.rotation.tr_mul(d)))
    }
}

/// A capsule: the points within `radius` of the segment of length `height`
/// along body y through the origin (height is between the two sphere centres).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Capsule {
    pub radius: f64,
    pub height: f64,
}

impl Capsule {
    /// Volume: a cylinder of height h and two half balls, π r² h + 4/3 π r³.
    pub fn volume(&self) -> f64 {
        let r = self.radius;
        std::f64::consts::PI * r * r * (self.height + 4.0 / 3.0 * r)
    }
}

impl<T: Real> Support<T> for Capsule {
    /// The segment's end on the side of d (the top one when d ⟂ the axis).
    fn core_support(&self, d: &Vector3<T>) -> Vector3<T> {
        let h: T = c(self.height / 2.0);
        Vector3::new(T::zero(), if d.y < T::zero() { -h } else { h }, T::zero())
    }

    fn margin(&self) -> T {
        c(self.radius)
    }
}

/// Every convex shape GJK and EPA take: the convex variants of [`Shape`]
/// (a hollow sphere has the surface of a solid one), a capsule and a hull.
#[derive(Debug, Clone, PartialEq)]
pub enum Convex {
    Sphere {
        radius: f64,
    },
    /// Half side lengths.
    Cuboid {
        half: [f64; 3],
    },
    /// Axis along body y, `half_height` from the centre to each cap.
    Cylinder {
        radius: f64,
        half_height: f64,
    },
    Capsule(Capsule),
    Hull(Arc<ConvexHull>),
}

impl Convex {
    /// The convex shape of a [`Shape`], `None` for a half-space.
    pub fn from_shape(shape: &Shape) -> Option<Convex> {
        match *shape {
            Shape::Sphere { radius } | Shape::HollowSphere { radius } => {
                Some(Convex::Sphere { radius })
            }
            Shape::Box { sides } => Some(Convex::Cuboid {
                half: [sides[0] / 2.0, sides[1] / 2.0, sides[2] / 2.0],
            }),
            Shape::Cylinder { radius, height } => Some(Convex::Cylinder {
                radius,
                half_height: height / 2.0,
            }),
            Shape::Capsule { radius, height } => Some(Convex::Capsule(Capsule { radius, height })),
            Shape::Hull(ref hull) => Some(Convex::Hull(Arc::clone(hull))),
            // A mesh is not convex: its pairs go through the mid phase.
            Shape::Mesh(_) | Shape::HalfSpace { .. } => None,
        }
    }

    /// A hull shape.
    pub fn hull(hull: ConvexHull) -> Convex {
        Convex::Hull(Arc::new(hull))
    }

    /// Radius of the smallest ball about the body origin holding the shape.
    pub fn bounding_radius(&self) -> f64 {
        match self {
            Convex::Sphere { radius } => *radius,
            Convex::Cuboid { half } => Vector3::from(*half).norm(),
            Convex::Cylinder {
                radius,
                half_height,
            } => radius.hypot(*half_height),
            Convex::Capsule(cap) => cap.height / 2.0 + cap.radius,
            Convex::Hull(hull) => hull.vertices().iter().map(|v| v.norm()).fold(0.0, f64::max),
        }
    }
}

impl<T: Real> Support<T> for Convex {
    fn core_support(&self, d: &Vector3<T>) -> Vector3<T> {
        let sign = |x: T, h: f64| if x < T::zero() { c::<T>(-h) } else { c::<T>(h) };
        match self {
            Convex::Sphere { .. } => Vector3::zeros(),
            // Box: s(d) = (sign(d_x) h_x, sign(d_y) h_y, sign(d_z) h_z).
            Convex::Cuboid { half } => {
                Vector3::new(sign(d.x, half[0]), sign(d.y, half[1]), sign(d.z, half[2]))
            }
            // Cylinder: the rim point r·(d_x, d_z)/|(d_x, d_z)| on the cap of sign(d_y).
            Convex::Cylinder {
                radius,
                half_height,
            } => {
                let radial = (d.x * d.x + d.z * d.z).sqrt();
                let r: T = c(*radius);
                let (x, z) = if radial > T::zero() {
                    (d.x * r / radial, d.z * r / radial)
                } else {
                    (r, T::zero())
                };
                Vector3::new(x, sign(d.y, *half_height), z)
            }
            Convex::Capsule(cap) => cap.core_support(d),
            Convex::Hull(hull) => hull.core_support(d),
        }
    }

    fn margin(&self) -> T {
        match self {
            Convex::Sphere { radius } => c(*radius),
            Convex::Capsule(cap) => c(cap.radius),
            _ => T::zero(),
        }
    }
}

impl<T: Real> Support<T> for ConvexHull {
    /// The vertex with the largest d·v (the first one on ties).
    fn core_support(&self, d: &Vector3<T>) -> Vector3<T> {
        let d = Vector3::new(to_f64(d.x), to_f64(d.y), to_f64(d.z));
        let best = self.support_index(&d);
        self.vertices()[best].map(c::<T>)
    }
}

/// A shape against the plane through `plane_point` with unit outward
/// `normal`: the shape's deepest point s(-n) and its depth below the plane,
/// n·(p - s(-n)) (negative when the shape is above it).
pub fn plane_depth<T: Real, S: Support<T> + ?Sized>(
    shape: &S,
    pose: &Pose<T>,
    normal: &Vector3<T>,
    plane_point: &Vector3<T>,
) -> (Vector3<T>, T) {
    let deepest = shape.support(pose, &-normal);
    (deepest, normal.dot(&(plane_point - deepest)))
}
