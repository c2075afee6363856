//! The lecture's loop as written (and the reference engine's): each iteration
//! scans every contact for the largest value above epsilon (strictly; the
//! first in file order wins ties), resolves it, then scans every contact for
//! the ones sharing a body. O(contacts) per iteration: the readable reference.

use super::observer::Observer;
use super::{position, velocity, Phase, PhaseOutcome, Resolver};
use crate::physics::Real;

/// The first contact with the largest `value` strictly above `epsilon`.
fn worst<T: Real>(values: impl Iterator<Item = T>, epsilon: T) -> Option<(usize, T)> {
    let mut max = epsilon;
    let mut index = None;
    for (i, v) in values.enumerate() {
        if v > max {
            max = v;
            index = Some(i);
        }
    }
    index.map(|i| (i, max))
}

pub fn position_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Position);
    let mut used = 0;
    while used < limit {
        let Some((k, penetration)) = worst(r.contacts.iter().map(|c| c.penetration), epsilon)
        else {
            break;
        };
        obs.before_position(used, k, &r.bodies);
        let taken = r.contacts[k].bodies;
        let moves = position::take(&r.contacts[k], &r.setups[k], penetration, &mut r.bodies);
        obs.position_taken(used, k, penetration, &moves);
        for (j, c) in r.contacts.iter_mut().enumerate() {
            if position::shares_body(c, &taken) {
                let from = c.penetration;
                c.penetration = position::updated_penetration(c, &taken, &moves);
                obs.penetration_updated(j, from, c.penetration);
            }
        }
        used += 1;
    }
    r.finish(Phase::Position, used, obs)
}

pub fn velocity_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Velocity);
    let from = r.params.restitution_from;
    let mut used = 0;
    while used < limit {
        let Some((k, desired)) = worst(r.contacts.iter().map(|c| c.desired), epsilon) else {
            break;
        };
        obs.before_velocity(used, k, &r.bodies);
        let taken = r.contacts[k].bodies;
        let friction = r.setups[k].friction.map(|f| &r.friction[f]);
        let impulse = velocity::take(&r.contacts[k], &r.setups[k], friction, &mut r.bodies);
        obs.velocity_taken(used, k, desired, &impulse);
        for (j, c) in r.contacts.iter_mut().enumerate() {
            if position::shares_body(c, &taken) {
                let before = c.desired;
                c.velocity = velocity::updated_velocity(c, &taken, &impulse);
                c.desired = super::desired_of(c, from);
                obs.desired_updated(j, before, c.desired);
            }
        }
        used += 1;
    }
    r.finish(Phase::Velocity, used, obs)
}
