//! The position phase's two per-contact steps, shared by both implementations
//! so they perform the same floating-point operations:
//! - [`take`]: resolve one contact's penetration with the nonlinear (or
//!   linear) projection and the angular limit, and move its bodies;
//! - [`updated_penetration`]: a contact's penetration after the taken contact
//!   moved bodies it shares, `pen_j -= s·(Δp + Δθ × r_j)·n_j` (s = +1 for
//!   body 1 of contact j, -1 for body 2).

use nalgebra::{Quaternion, Vector3};

use super::observer::PositionMoves;
use super::velocity_row::UNCHANGED;
use super::{ContactSetup, ResolverBody, ResolverContact};
use crate::physics::stages::orientation::add_scaled_rotation;
use crate::physics::stages::projection::{body_projection, BodyProjection};
use crate::physics::{Problem, Real};

/// Resolves `penetration` (times the relaxation) of contact `c`: computes each
/// slot's moves and applies them to the bodies (position `p + Δ_l d`,
/// orientation `θ + ½[0, Δθ]θ`, normalised as the reference engine's
/// `setOrientation` does).
pub fn take<T: Real>(
    c: &ResolverContact<T>,
    setup: &ContactSetup<T>,
    penetration: T,
    bodies: &mut [ResolverBody<T>],
) -> PositionMoves<T> {
    let mut moves = PositionMoves {
        slots: c.bodies,
        bodies: [None, None],
        orientations: [None, None],
    };
    project(c, setup, penetration, bodies, |i, _, projection, turned| {
        moves.orientations[i] = turned;
        moves.bodies[i] = Some(projection);
    });
    moves
}

/// [`take`] on the fast path (nothing records): the same moves applied to
/// the bodies by the same operations, only the compact [`BodyMoves`]
/// returned (no [`PositionMoves`] record built; the projection's record
/// fields nobody reads are not kept).
#[inline]
pub fn take_moves<T: Real>(
    c: &ResolverContact<T>,
    setup: &ContactSetup<T>,
    penetration: T,
    bodies: &mut [ResolverBody<T>],
) -> BodyMoves<T> {
    let mut moves = BodyMoves {
        bodies: [usize::MAX; 2],
        linear: [Vector3::zeros(); 2],
        angular: [Vector3::zeros(); 2],
    };
    project(c, setup, penetration, bodies, |i, b, projection, _| {
        moves.bodies[i] = b;
        moves.linear[i] = projection.linear_change;
        moves.angular[i] = projection.angular_change;
    });
    moves
}

/// Moves each body of contact `c` by its projection of `penetration` (times
/// the relaxation), handing `record` the slot, the resolver body, the
/// projection and the new orientation where the body turned.
#[inline(always)]
fn project<T: Real>(
    c: &ResolverContact<T>,
    setup: &ContactSetup<T>,
    penetration: T,
    bodies: &mut [ResolverBody<T>],
    mut record: impl FnMut(usize, usize, BodyProjection<T>, Option<Quaternion<T>>),
) {
    let depth = penetration * setup.relaxation;
    for i in 0..2 {
        let (Some(b), Some(inertia)) = (c.bodies[i], setup.projection[i].as_ref()) else {
            continue;
        };
        let body = &mut bodies[b];
        let projection = body_projection(
            inertia,
            Problem::<T>::sign(i),
            depth,
            setup.total_inertia,
            &c.normal,
            &body.position,
        );
        body.position = projection.position;
        let mut turned = None;
        if projection.angular_change != Vector3::zeros() {
            let orientation = add_scaled_rotation(&body.orientation, &projection.angular_change);
            body.orientation = orientation.normalize();
            turned = Some(body.orientation);
        }
        record(i, b, projection, turned);
    }
}

/// The penetration of contact `c` after the taken contact (slots `taken`)
/// applied `moves`; every slot of `c` that is a moved body contributes, in the
/// reference engine's order (slot of `c`, then slot of the taken contact).
pub fn updated_penetration<T: Real>(
    c: &ResolverContact<T>,
    taken: &[Option<usize>; 2],
    moves: &PositionMoves<T>,
) -> T {
    let mut penetration = c.penetration;
    for (b, body) in c.bodies.iter().enumerate() {
        let Some(body) = body else { continue };
        for (d, moved) in taken.iter().enumerate() {
            if *moved != Some(*body) {
                continue;
            }
            let Some(m) = moves.bodies[d].as_ref() else {
                continue;
            };
            let delta = m.linear_change + m.angular_change.cross(&c.r[b]);
            // Moving body 1 along n reduces the penetration; moving body 2 increases it.
            let sign = if b == 0 { -T::one() } else { T::one() };
            penetration += delta.dot(&c.normal) * sign;
        }
    }
    penetration
}

/// The moves one taken contact made, by resolver body, compact for the
/// neighbour updates (a slot that moved nothing holds `usize::MAX`, which no
/// contact's body equals): the linear and angular change of each slot.
#[derive(Debug, Clone, Copy)]
pub struct BodyMoves<T: Real> {
    pub bodies: [usize; 2],
    pub linear: [Vector3<T>; 2],
    pub angular: [Vector3<T>; 2],
}

impl<T: Real> BodyMoves<T> {
    /// The moves `moves` records, by slot of the taken contact.
    pub fn of(moves: &PositionMoves<T>) -> Self {
        let mut out = BodyMoves {
            bodies: [usize::MAX; 2],
            linear: [Vector3::zeros(); 2],
            angular: [Vector3::zeros(); 2],
        };
        for d in 0..2 {
            if let (Some(b), Some(m)) = (moves.slots[d], moves.bodies[d].as_ref()) {
                out.bodies[d] = b;
                out.linear[d] = m.linear_change;
                out.angular[d] = m.angular_change;
            }
        }
        out
    }
}

/// [`updated_penetration`] from the compact moves: `pen_j -= s·(Δp + Δθ × r_j)·n_j`
/// for each slot of `c` whose body moved, slot 1 first (a body is in at most
/// one slot of the taken contact, so the same operations in the same order).
#[inline(always)]
pub fn penetration_after<T: Real>(c: &ResolverContact<T>, moves: &BodyMoves<T>) -> T {
    let mut penetration = c.penetration;
    for (b, body) in c.bodies.iter().enumerate() {
        let Some(body) = *body else { continue };
        let d = if moves.bodies[0] == body {
            0
        } else if moves.bodies[1] == body {
            1
        } else {
            continue;
        };
        let delta = moves.linear[d] + moves.angular[d].cross(&c.r[b]);
        let sign = if b == 0 { -T::one() } else { T::one() };
        penetration += delta.dot(&c.normal) * sign;
    }
    penetration
}

/// [`penetration_after`] with the slots looked up beforehand (the neighbour
/// table's, [`super::neighbours::Neighbour`]): `slots[s]` is the taken
/// contact's slot holding `c`'s slot-`s` body ([`UNCHANGED`] for none). A
/// taken slot that moved nothing (`usize::MAX` in `moves.bodies`) adds
/// nothing, as there. The same operations in the same order.
#[inline(always)]
pub fn penetration_after_slots<T: Real>(
    c: &ResolverContact<T>,
    slots: [u8; 2],
    moves: &BodyMoves<T>,
) -> T {
    // Slot 1 (sign -1), then slot 2 (sign +1), each as `penetration_after` does it.
    let mut penetration = c.penetration;
    if slots[0] != UNCHANGED {
        let d = usize::from(slots[0] & 1);
        if moves.bodies[d] != usize::MAX {
            let delta = moves.linear[d] + moves.angular[d].cross(&c.r[0]);
            penetration += delta.dot(&c.normal) * -T::one();
        }
    }
    if slots[1] != UNCHANGED {
        let d = usize::from(slots[1] & 1);
        if moves.bodies[d] != usize::MAX {
            let delta = moves.linear[d] + moves.angular[d].cross(&c.r[1]);
            penetration += delta.dot(&c.normal) * T::one();
        }
    }
    penetration
}

/// True when contact `c` has a movable body in common with the slots `taken`.
pub fn shares_body<T: Real>(c: &ResolverContact<T>, taken: &[Option<usize>; 2]) -> bool {
    c.bodies
        .iter()
        .flatten()
        .any(|b| taken.iter().flatten().any(|t| t == b))
}
