//! Detection for every convex pair: support mappings, GJK (distance and
//! intersection), EPA (depth, normal, contact point, feature pair), a
//! separating-axis reference for polyhedra, and a contact manifold for a
//! resting pair. Pure maths with complete records: each iteration goes to an
//! observer whose methods do nothing by default, so a query that nobody
//! watches builds no record and allocates nothing but EPA's polytope.
//!
//! - [`support`]: the [`Support`] trait, [`Convex`] (every convex [`Shape`]
//!   variant, a [`Capsule`], a [`ConvexHull`]), the plane's deepest point;
//! - [`hull`] (in `physics/hull.rs`, as a [`Shape`] holds one): the hull of a
//!   point cloud, its faces, its mass;
//! - [`simplex`]: the signed-volumes sub-algorithm; [`gjk`]; [`epa`]
//!   (+ `epa_start`, growing GJK's simplex to a tetrahedron, `epa_observer`);
//! - [`query`]: GJK then EPA (or the margins) for one pair;
//! - [`features`]: feature kinds; `names`: every identifier name;
//! - [`sat`]: exact depth and normal for polyhedra (the tests' reference);
//! - [`manifold`] (+ `support_face`): the clipped support faces of a resting pair;
//! - [`toi`]: time of collision over a step, by bisection and by conservative advancement.
//!
//! Conventions as in `collide`: the normal points from B (body 2) toward A
//! (body 1); moving A along it by the depth separates the pair.
//!
//! [`Shape`]: crate::physics::Shape

pub mod epa;
mod epa_observer;
mod epa_start;
pub mod features;
pub mod gjk;
/// The hull lives in `physics` (a body's shape holds one); re-exported here.
pub use crate::physics::hull;
pub mod manifold;
mod manifold_point;
mod names;
pub mod query;
pub mod sat;
mod segments;
pub mod simplex;
pub mod support;
mod support_face;
pub mod toi;
pub mod toi_plane;
pub mod toi_sweep;

#[cfg(test)]
mod tests;

pub use crate::physics::hull_faces::HullFace;
pub use epa::{epa, EpaEnd, EpaIteration, EpaObserver, EpaOptions, EpaRecorder, EpaResult};
pub use features::{FeatureKind, FeaturePair};
pub use gjk::{
    gjk, GjkEnd, GjkIteration, GjkObserver, GjkOptions, GjkRecorder, GjkResult, GjkVerdict,
};
pub use hull::{ConvexHull, HullError, MassProperties};
pub use manifold::{manifold, manifold_within, ManifoldPoint};
pub use query::{query, Penetration, PenetrationSource, Query, QueryOptions};
pub use sat::{sat, Polyhedron, SatResult};
pub use support::{plane_depth, Capsule, Convex, Support};
pub use toi::{
    toi, Motion, MovingPair, SweptPair, Toi, ToiEnd, ToiMethod, ToiObserver, ToiOptions,
    ToiRecorder, ToiStep,
};
pub use toi_plane::PlanePair;
