//! The tunnelling auditor ("Lecture IV Collisions", the time issue): looking
//! only at the poses at t and t + Δt misses a collision in between. Before
//! the positions are updated, each pair's swept motion over the step (the
//! velocities just resolved, held constant: x(t) = x₀ + v t, q(t) = exp(ω t) q₀)
//! is searched by conservative advancement ([`crate::physics::detect::toi`]);
//! a pair that meets inside the step, had no contact this step and is apart
//! again at the end crossed each other unseen: a [`Tunnelled`] report. It
//! only reports; it changes nothing.
//!
//! Cost: pairs are first ruled out by the swept broad phase (sort and sweep
//! over each body's movement bounds, then their motion spheres: centre the
//! midpoint of x₀ and x₁, radius ρ + |v| Δt / 2, ρ the bounding radius about
//! the body origin); pairs already in contact and pairs that do not move
//! are skipped, so a resting scene runs no GJK at all.

use nalgebra::Vector3;

use super::swept::{motion_of, Earlier, SweptPairs};
use super::touching::{contact_pairs_into, key};
use crate::physics::detect::gjk::{gjk, GjkOptions, GjkVerdict};
use crate::physics::detect::toi::{conservative_advancement, MovingPair, ToiEnd, ToiOptions};
use crate::physics::detect::Convex;
use crate::physics::{c, to_f64, BodyId, Real, World};

/// A pair that crossed during the step without a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tunnelled {
    pub body1: BodyId,
    pub body2: BodyId,
    /// Time into the step of the first touch (s).
    pub time: f64,
    /// Midway between the closest points at that time (world).
    pub point: [f64; 3],
}

/// The pairs of `world` whose swept motion over `dt` crossed without a
/// contact; `moving[i]` says whether body i's position is updated this
/// step. The candidates come from the swept broad phase (`swept`, its
/// scratch kept by the caller): sort and sweep over the movement bounds,
/// so a resting pile costs what its bounds' overlaps cost, not n² pairs;
/// or the pairs of an `earlier` broad phase (contact generation's) where
/// the swept boxes lie inside its boxes (the same pairs, docs/ccd.md).
pub fn tunnelled<T: Real>(
    world: &World<T>,
    dt: T,
    moving: &[bool],
    swept: &mut SweptPairs<T>,
    earlier: Option<Earlier<'_, T>>,
    out: &mut Vec<Tunnelled>,
) {
    swept.find_reusing(world, moving, dt, earlier);
    if swept.pairs.is_empty() {
        return;
    }
    let mut touching = std::mem::take(&mut swept.touching);
    contact_pairs_into(world, &mut touching);
    let from = out.len();
    for &(i, j) in &swept.pairs {
        if touching.contains(&key(i, j)) {
            continue;
        }
        if let Some(t) = pair(world, i, j, dt, moving) {
            out.push(t);
        }
    }
    swept.touching = touching;
    // In the order of the bodies, whatever order the sweep found them in.
    out[from..].sort_by_key(|t| (t.body1, t.body2));
}

fn pair<T: Real>(
    world: &World<T>,
    i: usize,
    j: usize,
    dt: T,
    moving: &[bool],
) -> Option<Tunnelled> {
    let a = Convex::from_shape(world.bodies[i].shape.as_ref()?)?;
    let b = Convex::from_shape(world.bodies[j].shape.as_ref()?)?;
    let (ma, mb) = (
        motion_of(world, i, moving[i]),
        motion_of(world, j, moving[j]),
    );
    // The swept broad phase has kept only pairs whose motion spheres meet.
    let (ra, rb): (T, T) = (c(a.bounding_radius()), c(b.bounding_radius()));
    let options = ToiOptions {
        tolerance: c::<T>(1e-4) * ra.min(rb),
        ..ToiOptions::default()
    };
    let toi = conservative_advancement(&MovingPair::new(&a, &ma, &b, &mb), dt, &options, &mut ());
    let time = match (toi.end, toi.time) {
        (ToiEnd::Converged, Some(t)) if t > T::zero() && t < dt => t,
        _ => return None,
    };
    let gjk_options = GjkOptions::default();
    let end = gjk(
        &a,
        &ma.pose_at(dt),
        &b,
        &mb.pose_at(dt),
        &gjk_options,
        &mut (),
    );
    if end.verdict != GjkVerdict::Separated {
        return None;
    }
    let hit = gjk(
        &a,
        &ma.pose_at(time),
        &b,
        &mb.pose_at(time),
        &gjk_options,
        &mut (),
    );
    let point: Vector3<T> = (hit.closest_a + hit.closest_b) * c::<T>(0.5);
    Some(Tunnelled {
        body1: BodyId(i),
        body2: BodyId(j),
        time: to_f64(time),
        point: [to_f64(point.x), to_f64(point.y), to_f64(point.z)],
    })
}
