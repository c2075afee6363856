//! The lecture's loop as written (and the reference engine's): each iteration
//! scans every contact for the largest value above epsilon (strictly; the
//! first in file order wins ties), resolves it, then scans every contact for
//! the ones sharing a body. O(contacts) per iteration: the readable reference.

use super::observer::Observer;
use super::phase::{PhaseWork, Positions, Velocities};
use super::{position, PhaseOutcome, Resolver};
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
    phase::<T, O, Positions>(r, obs)
}

pub fn velocity_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    phase::<T, O, Velocities>(r, obs)
}

fn phase<T: Real, O: Observer<T>, W: PhaseWork<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(W::PHASE);
    let mut used = 0;
    while used < limit && !super::stop::asked(used) {
        let Some((k, value)) = worst(r.contacts.iter().map(W::value), epsilon) else {
            break;
        };
        let taken = r.contacts[k].bodies;
        let change = W::take(r, used, k, value, obs);
        let from = r.params.restitution_from;
        for (j, c) in r.contacts.iter_mut().enumerate() {
            if position::shares_body(c, &taken) {
                W::update(c, j, &taken, &change, from, obs);
            }
        }
        used += 1;
    }
    r.finish(W::PHASE, used, obs)
}
