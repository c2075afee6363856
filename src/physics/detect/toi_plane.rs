//! A convex shape against a half-space over the step: the swept test is a
//! closed form. The plane is fixed (a half-space is immovable); the shape's
//! signed distance to it is that of its deepest point, the support point
//! along the plane's inward normal: d(t) = n·(s(−n, t) − p). Moving
//! straight, d is linear in time, d(t) = d₀ + (v·n) t, so the time of
//! collision is d₀ / (−v·n), and conservative advancement (t ← t + d/μ with
//! μ = −v·n) reaches it in one advance. Turning, the support point moves
//! over the shape, but no point of it moves along n faster than
//! |v·n| + |ω| ρ (ρ the farthest point from the centre of mass): the bound
//! advancement divides by. The half-space is solid all the way down, so a
//! pair is intersecting at the step's end whenever it met inside the step
//! (a turning shape can still dip in and out within one of bisection's
//! pieces: the scan cuts the step to the shape's own width).

use nalgebra::Vector3;

use super::gjk::GjkOptions;
use super::support::Support;
use super::toi::{bounding_radius, smallest_width, Motion, SweptPair};
use crate::physics::Real;

/// A convex shape `a` moving by `motion_a`, and the half-space below the
/// plane through `point` with unit outward `normal` (world).
pub struct PlanePair<'s, T: Real, A: ?Sized> {
    pub a: &'s A,
    pub motion_a: &'s Motion<T>,
    pub normal: Vector3<T>,
    pub point: Vector3<T>,
}

impl<'s, T: Real, A: Support<T> + ?Sized> PlanePair<'s, T, A> {
    pub fn new(a: &'s A, motion_a: &'s Motion<T>, normal: Vector3<T>, point: Vector3<T>) -> Self {
        PlanePair {
            a,
            motion_a,
            normal,
            point,
        }
    }

    /// The shape's deepest point at time t and its signed distance above
    /// the plane (negative: below it).
    pub fn signed_distance(&self, t: T) -> (Vector3<T>, T) {
        let deepest = self.a.support(&self.motion_a.pose_at(t), &-self.normal);
        (deepest, self.normal.dot(&(deepest - self.point)))
    }
}

impl<T: Real, A: Support<T> + ?Sized> SweptPair<T> for PlanePair<'_, T, A> {
    /// Intersecting when the deepest point is on or below the plane; the
    /// gap is along the normal (the plane's closest point is the deepest
    /// point's projection).
    fn distance_at(&self, t: T, _: &GjkOptions<T>) -> (bool, T, Vector3<T>) {
        let (_, d) = self.signed_distance(t);
        if d <= T::zero() {
            (true, T::zero(), Vector3::zeros())
        } else {
            (false, d, self.normal * d)
        }
    }

    fn relative_velocity(&self) -> Vector3<T> {
        self.motion_a.velocity
    }

    fn spin(&self) -> T {
        self.motion_a.angular_velocity.norm() * bounding_radius(self.a)
    }

    /// The shape's own smallest width (the half-space is deeper than any).
    fn width(&self) -> T {
        smallest_width(self.a)
    }

    /// The deepest point's speed along the normal.
    fn gap_rate(&self, t: T, _: &GjkOptions<T>) -> Option<T> {
        let (deepest, _) = self.signed_distance(t);
        Some(self.motion_a.point_velocity(t, &deepest).dot(&self.normal))
    }
}
