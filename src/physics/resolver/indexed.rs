//! The indexed resolver: the same contacts in the same order as the scan
//! ([`super::scan`]), found with a priority queue (a tournament tree:
//! largest value first, lowest index on ties, [`super::queue`]) and updated
//! through the body → contacts adjacency,
//! so an iteration touches only the contacts of the bodies it moved. The
//! per-contact steps are the scan's own functions, so the results are
//! bit-identical. Nothing is allocated per iteration.
//!
//! The contacts an iteration changed are replayed in the queue together
//! (each match above them once). A value that stays at or below epsilon is
//! not replayed: it can never be taken, and the queue's stale entry for it
//! is at or below epsilon too, so the first contact above epsilon is still
//! exact.

use super::observer::Observer;
use super::queue::{Queue, SCAN_BELOW};
use super::{position, velocity, Phase, PhaseOutcome, Resolver};
use crate::physics::Real;

/// Marks each contact of the taken contact's bodies once per iteration and
/// calls `visit` on it (a contact may belong to both bodies).
pub(super) fn each_neighbour<T: Real>(
    r: &mut Resolver<T>,
    taken: [Option<usize>; 2],
    stamp: usize,
    mut visit: impl FnMut(&mut Resolver<T>, usize),
) {
    for b in taken.into_iter().flatten() {
        for n in r.adjacency.offsets[b]..r.adjacency.offsets[b + 1] {
            let j = r.adjacency.contacts[n];
            if r.stamps[j] != stamp {
                r.stamps[j] = stamp;
                visit(r, j);
            }
        }
    }
}

/// Runs `phase` with the scan queue below [`SCAN_BELOW`] contacts, the
/// tournament tree from there on (both give the same order).
macro_rules! with_queue {
    ($r:expr, $obs:expr, $phase:ident) => {
        if $r.contacts.len() < SCAN_BELOW {
            let mut queue = std::mem::take(&mut $r.scan_queue);
            let outcome = $phase($r, $obs, &mut queue);
            $r.scan_queue = queue;
            outcome
        } else {
            let mut queue = std::mem::take(&mut $r.queue);
            let outcome = $phase($r, $obs, &mut queue);
            $r.queue = queue;
            outcome
        }
    };
}

pub fn position_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    with_queue!(r, obs, position_phase_with)
}

pub fn velocity_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    with_queue!(r, obs, velocity_phase_with)
}

fn position_phase_with<T: Real, O: Observer<T>, Q: Queue<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
    queue: &mut Q,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Position);
    queue.fill(r.contacts.iter().map(|c| c.penetration));
    let mut used = 0;
    while used < limit {
        let Some((k, penetration)) = queue.top().filter(|(_, v)| *v > epsilon) else {
            break;
        };
        obs.before_position(used, k, &r.bodies);
        let taken = r.contacts[k].bodies;
        let moves = position::take(&r.contacts[k], &r.setups[k], penetration, &mut r.bodies);
        obs.position_taken(used, k, penetration, &moves);
        r.stamp += 1;
        let stamp = r.stamp;
        let mut changed = std::mem::take(&mut r.changed);
        changed.clear();
        each_neighbour(r, taken, stamp, |r, j| {
            let c = &mut r.contacts[j];
            let from = c.penetration;
            c.penetration = position::updated_penetration(c, &taken, &moves);
            if !(from <= epsilon && c.penetration <= epsilon) {
                queue.set(j, c.penetration);
                changed.push(j);
            }
            obs.penetration_updated(j, from, c.penetration);
        });
        queue.replay(&mut changed);
        r.changed = changed;
        used += 1;
    }
    r.finish(Phase::Position, used, obs)
}

fn velocity_phase_with<T: Real, O: Observer<T>, Q: Queue<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
    queue: &mut Q,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Velocity);
    let from = r.params.restitution_from;
    queue.fill(r.contacts.iter().map(|c| c.desired));
    let mut used = 0;
    while used < limit {
        let Some((k, desired)) = queue.top().filter(|(_, v)| *v > epsilon) else {
            break;
        };
        obs.before_velocity(used, k, &r.bodies);
        let taken = r.contacts[k].bodies;
        let friction = r.setups[k].friction.map(|f| &r.friction[f]);
        let impulse = velocity::take(&r.contacts[k], &r.setups[k], friction, &mut r.bodies);
        obs.velocity_taken(used, k, desired, &impulse);
        r.stamp += 1;
        let stamp = r.stamp;
        let mut changed = std::mem::take(&mut r.changed);
        changed.clear();
        each_neighbour(r, taken, stamp, |r, j| {
            let c = &mut r.contacts[j];
            let before = c.desired;
            c.velocity = velocity::updated_velocity(c, &taken, &impulse);
            c.desired = super::desired_of(c, from);
            if !(before <= epsilon && c.desired <= epsilon) {
                queue.set(j, c.desired);
                changed.push(j);
            }
            obs.desired_updated(j, before, c.desired);
        });
        queue.replay(&mut changed);
        r.changed = changed;
        used += 1;
    }
    r.finish(Phase::Velocity, used, obs)
}
