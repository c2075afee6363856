//! One contact of a manifold: a leaf that `manifold.rs` and `segments.rs`
//! (two parallel sides) both build.

use nalgebra::Vector3;

use crate::physics::pose::Side;
use crate::physics::Real;

/// One manifold contact: the point on the incident body (`penetration` deep
/// in the reference body), the normal from B toward A, and which body held
/// the reference face (`None` for the penetration's single point, midway).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ManifoldPoint<T: Real> {
    pub point: Vector3<T>,
    pub normal: Vector3<T>,
    pub penetration: T,
    pub reference: Option<Side>,
}
