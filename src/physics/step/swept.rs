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
    let radius = || Convex::from_shape(shape).map(|s| c::<T>(s.bounding_radius()));
    swept_aabb_with(shape, m, dt, radius)
}

/// [`swept_aabb`] with the bounding radius given (asked only for a turning
/// body). The box at either end is the shape's half extents about the
/// position there, `x₀ + v t`: a turning body's bounding radius, else the
/// extents of its one orientation (`exp(0·t) q₀ = q₀`), computed once for
/// both ends — the same numbers as the box of each end's pose.
fn swept_aabb_with<T: Real>(
    shape: &Shape,
    m: &Motion<T>,
    dt: T,
    radius: impl FnOnce() -> Option<T>,
) -> Option<Aabb<T>> {
    let turning = m.angular_velocity.norm() > T::zero();
    let half = if turning {
        Vector3::repeat(radius()?)
    } else {
        let turned = Pose::from_unit(Vector3::zeros(), &m.orientation);
        Aabb::of(shape, &turned, T::zero())?.max
    };
    let a = Aabb::around(&(m.position + m.velocity * T::zero()), &half);
    let b = Aabb::around(&(m.position + m.velocity * dt), &half);
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
    /// Whether body i's swept box leaves its earlier box (`find_reusing`).
    outside: Vec<bool>,
    /// The candidate pairs (i, j), i < j, of the last call.
    pub pairs: Vec<(usize, usize)>,
    /// Whether the last call took the earlier pairs instead of sweeping.
    pub reused: bool,
    /// The step's contact pairs (the tunnelling audit's storage, kept).
    pub touching: super::touching::ContactPairs,
}

impl<T: Real> Default for SweptPairs<T> {
    fn default() -> Self {
        SweptPairs {
            broad: BroadPhase::new(),
            bounds: Vec::new(),
            spheres: Vec::new(),
            outside: Vec::new(),
            pairs: Vec::new(),
            reused: false,
            touching: Default::default(),
        }
    }
}

/// The broad phase of an earlier call over the same bodies (contact
/// generation's, at the step's start): each body's box and the pairs of
/// boxes that overlap. [`SweptPairs::find_reusing`] takes its pairs instead
/// of sorting again where the swept boxes lie inside these boxes.
#[derive(Debug, Clone, Copy)]
pub struct Earlier<'a, T: Real> {
    pub bounds: &'a [Option<Aabb<T>>],
    pub pairs: &'a [(usize, usize)],
}

/// At most this many bodies whose swept box leaves its earlier box are
/// tested against every body one by one; more, and the broad phase sorts
/// and sweeps again.
const OUTSIDE_ONE_BY_ONE: usize = 16;

/// Whether `outer` holds all of `inner`.
fn holds<T: Real>(outer: &Aabb<T>, inner: &Aabb<T>) -> bool {
    (0..3).all(|k| outer.min[k] <= inner.min[k] && inner.max[k] <= outer.max[k])
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
        self.find_reusing(world, moving, dt, None);
    }

    /// [`Self::find`], the same pairs, taking the candidate pairs of an
    /// `earlier` broad phase where it can (docs/ccd.md, "Cost"): when body
    /// i's swept box lies inside its earlier box for every i, two swept
    /// boxes that overlap had earlier boxes that overlap, so every pair the
    /// sweep would find is among the earlier pairs, and those pairs whose
    /// swept boxes overlap are exactly the sweep's. A few bodies whose swept
    /// box leaves its earlier box are tested against every body; more, and
    /// the sweep runs again.
    pub fn find_reusing(
        &mut self,
        world: &World<T>,
        moving: &[bool],
        dt: T,
        earlier: Option<Earlier<'_, T>>,
    ) {
        let n = world.bodies.len();
        self.bounds.clear();
        self.spheres.clear();
        // Each body's motion, swept box and swept sphere once (not once per
        // pair it is in).
        for (i, b) in world.bodies.iter().enumerate() {
            let m = motion_of(world, i, moving[i]);
            let Some(shape) = b.shape.as_ref() else {
                self.bounds.push(None);
                self.spheres.push(None);
                continue;
            };
            let r: Option<T> = Convex::from_shape(shape).map(|s| c(s.bounding_radius()));
            self.bounds.push(swept_aabb_with(shape, &m, dt, || r));
            self.spheres.push(r.map(|r| swept_sphere(r, &m, dt)));
        }
        self.reused = earlier
            .filter(|e| e.bounds.len() == n)
            .is_some_and(|e| self.pairs_inside(e));
        if !self.reused {
            self.broad
                .candidate_pairs(&self.bounds, &[], &mut self.pairs);
        }
        let spheres = &self.spheres;
        self.pairs.retain(|&(i, j)| {
            (moving[i] || moving[j])
                && match (spheres[i], spheres[j]) {
                    (Some(a), Some(b)) => spheres_meet(a, b),
                    _ => false,
                }
        });
    }

    /// The swept pairs from the `earlier` pairs (see
    /// [`Self::find_reusing`]); false, nothing found, when too many swept
    /// boxes leave their earlier boxes.
    fn pairs_inside(&mut self, earlier: Earlier<'_, T>) -> bool {
        let bounds = &self.bounds;
        self.outside.clear();
        self.outside.extend(
            bounds
                .iter()
                .zip(earlier.bounds)
                .map(|(s, e)| match (s, e) {
                    (None, _) => false,
                    (Some(s), Some(e)) => !holds(e, s),
                    (Some(_), None) => true,
                }),
        );
        let leaving = self.outside.iter().filter(|o| **o).count();
        if leaving > OUTSIDE_ONE_BY_ONE {
            return false;
        }
        let overlap = |i: usize, j: usize| match (&bounds[i], &bounds[j]) {
            (Some(a), Some(b)) => a.overlaps(b),
            _ => false,
        };
        let outside = &self.outside;
        self.pairs.clear();
        self.pairs.extend(
            earlier
                .pairs
                .iter()
                .map(|&(i, j)| (i.min(j), i.max(j)))
                .filter(|&(i, j)| i != j && !outside[i] && !outside[j] && overlap(i, j)),
        );
        for (u, a) in bounds.iter().enumerate() {
            // (A body outside has a box: `outside` is false without one.)
            let (true, Some(a)) = (outside[u], a) else {
                continue;
            };
            // Each pair once: with a body inside, or a later body outside.
            for (j, b) in bounds.iter().enumerate() {
                if j == u || (outside[j] && j < u) {
                    continue;
                }
                if b.as_ref().is_some_and(|b| a.overlaps(b)) {
                    self.pairs.push((u.min(j), u.max(j)));
                }
            }
        }
        true
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
