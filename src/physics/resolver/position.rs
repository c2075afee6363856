//! The position phase's two per-contact steps, shared by both implementations
//! so they perform the same floating-point operations:
//! - [`take`]: resolve one contact's penetration with the nonlinear (or
//!   linear) projection and the angular limit, and move its bodies;
//! - [`updated_penetration`]: a contact's penetration after the taken contact
//!   moved bodies it shares, `pen_j -= s·(Δp + Δθ × r_j)·n_j` (s = +1 for
//!   body 1 of contact j, -1 for body 2).

use nalgebra::Vector3;

use super::observer::PositionMoves;
use super::{ContactSetup, ResolverBody, ResolverContact};
use crate::physics::stages::orientation::add_scaled_rotation;
use crate::physics::stages::projection::body_projection;
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
    let depth = penetration * setup.relaxation;
    let mut moves = PositionMoves {
        slots: c.bodies,
        bodies: [None, None],
        orientations: [None, None],
    };
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
        if projection.angular_change != Vector3::zeros() {
            let turned = add_scaled_rotation(&body.orientation, &projection.angular_change);
            body.orientation = turned.normalize();
            moves.orientations[i] = Some(body.orientation);
        }
        moves.bodies[i] = Some(projection);
    }
    moves
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

/// True when contact `c` has a movable body in common with the slots `taken`.
pub fn shares_body<T: Real>(c: &ResolverContact<T>, taken: &[Option<usize>; 2]) -> bool {
    c.bodies
        .iter()
        .flatten()
        .any(|b| taken.iter().flatten().any(|t| t == b))
}
