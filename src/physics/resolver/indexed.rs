//! The indexed resolver: the same contacts in the same order as the scan
//! ([`super::scan`]), found with a priority queue (below 64 contacts a scan
//! of the values kept side by side, from there on a tournament tree:
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
use super::phase::{PhaseWork, Positions, Velocities};
use super::queue::{Queue, SCAN_BELOW};
use super::{PhaseOutcome, Resolver};
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

pub fn position_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    with_queue::<T, O, Positions>(r, obs)
}

pub fn velocity_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    with_queue::<T, O, Velocities>(r, obs)
}

/// Runs the phase with the scan queue below [`SCAN_BELOW`] contacts, the
/// tournament tree from there on (both give the same order).
fn with_queue<T: Real, O: Observer<T>, W: PhaseWork<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    if r.contacts.len() < SCAN_BELOW {
        let mut queue = std::mem::take(&mut r.scan_queue);
        let outcome = phase::<T, O, W, _>(r, obs, &mut queue);
        r.scan_queue = queue;
        outcome
    } else {
        let mut queue = std::mem::take(&mut r.queue);
        let outcome = phase::<T, O, W, _>(r, obs, &mut queue);
        r.queue = queue;
        outcome
    }
}

fn phase<T: Real, O: Observer<T>, W: PhaseWork<T>, Q: Queue<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
    queue: &mut Q,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(W::PHASE);
    let from = r.params.restitution_from;
    queue.fill(r.contacts.iter().map(W::value));
    let mut used = 0;
    while used < limit {
        let Some((k, value)) = queue.top().filter(|(_, v)| *v > epsilon) else {
            break;
        };
        let taken = r.contacts[k].bodies;
        let change = W::take(r, used, k, value, obs);
        r.stamp += 1;
        let stamp = r.stamp;
        r.changed.clear();
        // The neighbours, as [`each_neighbour`] visits them, with the
        // adjacency, the stamps and the contacts borrowed apart (no closure,
        // no lookup through the resolver per contact).
        let Resolver {
            adjacency,
            stamps,
            contacts,
            changed,
            ..
        } = &mut *r;
        for b in taken.into_iter().flatten() {
            let row = &adjacency.contacts[adjacency.offsets[b]..adjacency.offsets[b + 1]];
            for &j in row {
                let seen = &mut stamps[j];
                if *seen == stamp {
                    continue;
                }
                *seen = stamp;
                let (before, after) = W::update(&mut contacts[j], j, &taken, &change, from, obs);
                if !(before <= epsilon && after <= epsilon) {
                    queue.set(j, after);
                    if Q::REPLAYS {
                        changed.push(j);
                    }
                }
            }
        }
        if Q::REPLAYS {
            queue.replay(changed);
        }
        used += 1;
    }
    r.finish(W::PHASE, used, obs)
}
