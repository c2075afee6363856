//! Movement bounds ("Lecture IV Collisions": a bound on where a body can be
//! during the step rules collisions in or out over the whole step, not only
//! at its two poses). Motion over the step is the integrator's: constant
//! velocities, x(t) = x₀ + v t, q(t) = exp(ω t) q₀.
//!
//! - the swept AABB: the box around the shape's bounds at both ends of the
//!   step (a rotating body's bounds taken as its bounding sphere, which holds
//!   every orientation in between);
//! - the swept sphere (a capsule about the path): centre x₀ + v Δt/2,
//!   radius ρ + |v| Δt/2, ρ the bounding radius about the body origin.
//!
//! With continuous detection on, the broad phase sorts and sweeps the swept
//! AABBs; a pair it keeps must also have swept spheres that meet.

use nalgebra::{UnitQuaternion, Vector3};

use crate::physics::collide::{Aabb, BroadPhase, Pose};
use crate::physics::detect::{Convex, Motion};
use crate::physics::{c, Real, Shape, World};

/// Body `i`'s motion over the step: its velocities if it `moving`, at rest otherwise.
pub fn motion_of<T: Real>(world: &World<T>, i: usize, moving: bool) -> Motion<T> {
    let s = &world.bodies[i].state;
    let fixed = Motion {
        orientation: UnitQuaternion::new_normalize(s.orientation),
        ..Motion::fixed(s.position)
    };
    if moving {
        Motion {
            velocity: s.velocity,
            angular_velocity: s.angular_velocity,
            ..fixed
        }
    } else {
        fixed
    }
}

/// The AABB of a shape's motion over `dt` (module docs); `None` for a half-space.
pub fn swept_aabb<T: Real>(shape: &Shape, m: &Motion<T>, dt: T) -> Option<Aabb<T>> {
    let ends = [m.pose_at(T::zero()), m.pose_at(dt)];
    let turning = m.angular_velocity.norm() > T::zero();
    let bound = |pose: &Pose<T>| -> Option<Aabb<T>> {
        if turning {
            let r: T = c(Convex::from_shape(shape)?.bounding_radius());
            Some(Aabb::around(&pose.position, &Vector3::repeat(r)))
        } else {
            Aabb::of(shape, pose, T::zero())
        }
    };
    let (a, b) = (bound(&ends[0])?, bound(&ends[1])?);
    Some(Aabb {
        min: a.min.inf(&b.min),
        max: a.max.sup(&b.max),
    })
}

/// The swept sphere (module docs): centre and radius.
pub fn swept_sphere<T: Real>(radius: T, m: &Motion<T>, dt: T) -> (Vector3<T>, T) {
    let half = c::<T>(0.5) * dt;
    (
        m.position + m.velocity * half,
        radius + m.velocity.norm() * half,
    )
}

/// Whether two swept spheres meet.
pub fn spheres_meet<T: Real>(a: (Vector3<T>, T), b: (Vector3<T>, T)) -> bool {
    (a.0 - b.0).norm() <= a.1 + b.1
}

/// One body's movement bounds over a step (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MovementBound<T: Real> {
    pub aabb: Aabb<T>,
    /// The swept sphere's centre and radius.
    pub centre: Vector3<T>,
    pub radius: T,
}

/// Scratch of the swept broad phase, kept from step to step.
#[derive(Debug, Clone)]
pub struct SweptPairs<T: Real> {
    broad: BroadPhase,
    bounds: Vec<Option<Aabb<T>>>,
    spheres: Vec<Option<(Vector3<T>, T)>>,
    /// The candidate pairs (i, j), i < j, of the last call.
    pub pairs: Vec<(usize, usize)>,
}

impl<T: Real> Default for SweptPairs<T> {
    fn default() -> Self {
        SweptPairs {
            broad: BroadPhase::new(),
            bounds: Vec::new(),
            spheres: Vec::new(),
            pairs: Vec::new(),
        }
    }
}

impl<T: Real> SweptPairs<T> {
    /// Body `i`'s movement bounds of the last call (`None`: a half-space,
    /// a body without a shape, or no call yet).
    pub fn bound(&self, i: usize) -> Option<MovementBound<T>> {
        let aabb = (*self.bounds.get(i)?)?;
        let (centre, radius) = (*self.spheres.get(i)?)?;
        Some(MovementBound {
            aabb,
            centre,
            radius,
        })
    }

    /// The pairs whose movement bounds over `dt` meet, at least one of them
    /// moving (`moving[i]`).
    pub fn find(&mut self, world: &World<T>, moving: &[bool], dt: T) {
        self.bounds.clear();
        self.bounds
            .extend(world.bodies.iter().enumerate().map(|(i, b)| {
                let m = motion_of(world, i, moving[i]);
                swept_aabb(b.shape.as_ref()?, &m, dt)
            }));
        self.broad
            .candidate_pairs(&self.bounds, &[], &mut self.pairs);
        // Each body's swept sphere once (not once per pair it is in).
        self.spheres.clear();
        self.spheres
            .extend(world.bodies.iter().enumerate().map(|(k, b)| {
                let r: T = c(Convex::from_shape(b.shape.as_ref()?)?.bounding_radius());
                Some(swept_sphere(r, &motion_of(world, k, moving[k]), dt))
            }));
        let spheres = &self.spheres;
        self.pairs.retain(|&(i, j)| {
            (moving[i] || moving[j])
                && match (spheres[i], spheres[j]) {
                    (Some(a), Some(b)) => spheres_meet(a, b),
                    _ => false,
                }
        });
    }
}

/// Each body's movement bounds over `dt` (`None`: not `moving`, or no
/// convex shape): one swept broad phase, for a picture of one step.
pub fn movement_bounds<T: Real>(
    world: &World<T>,
    moving: &[bool],
    dt: T,
) -> Vec<Option<MovementBound<T>>> {
    let mut swept = SweptPairs::default();
    swept.find(world, moving, dt);
    (0..moving.len())
        .map(|i| if moving[i] { swept.bound(i) } else { None })
        .collect()
}
