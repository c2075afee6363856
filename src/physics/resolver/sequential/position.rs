//! One visit of the sequential position phase (a Gauss–Seidel sweep over the
//! penetrations): the contact's penetration as the sweep has left it so far is
//! resolved with the lecture's projection (linear or nonlinear, angular limit,
//! relaxation), and the penetration of every contact sharing a moved body is
//! updated as the lecture's resolver does, `pen_j -= s·(Δp + Δθ × r_j)·n_j`.
//!
//! Accumulated: the depth a contact has pushed its bodies apart in this phase
//! is kept, and a contact left separated by more than epsilon (others pushed
//! its bodies further apart) gives back up to that much, never more.

use super::super::indexed::each_neighbour;
use super::super::observer::Observer;
use super::super::{position, Resolver};
use crate::physics::Real;

/// Visits contact `k` (visit number `visit`); true when it moved a body.
pub fn visit<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    k: usize,
    visit: usize,
    epsilon: T,
    obs: &mut O,
) -> bool {
    let penetration = r.contacts[k].penetration;
    let pushed = r.sequential.pushed[k];
    let relaxation = r.setups[k].relaxation;
    // The penetration handed to the projection (which resolves it × relaxation).
    let value = if penetration > epsilon {
        penetration
    } else if penetration < -epsilon && pushed > T::zero() {
        penetration.max(-pushed / relaxation)
    } else {
        return false;
    };
    obs.before_position(visit, k, &r.bodies);
    r.sequential.pushed[k] = pushed + value * relaxation;
    let taken = r.contacts[k].bodies;
    let moves = position::take(&r.contacts[k], &r.setups[k], value, &mut r.bodies);
    obs.position_taken(visit, k, value, &moves);
    r.stamp += 1;
    let stamp = r.stamp;
    each_neighbour(r, taken, stamp, |r, j| {
        let c = &mut r.contacts[j];
        let from = c.penetration;
        c.penetration = position::updated_penetration(c, &taken, &moves);
        obs.penetration_updated(j, from, c.penetration);
    });
    true
}
