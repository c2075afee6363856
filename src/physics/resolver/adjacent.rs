//! The deepest-first phases when the neighbour table would outgrow its
//! budget ([`super::Resolver::table_over_budget`]): the indexed order's
//! queue (largest first, lowest index on ties) with each taken contact's
//! neighbours found through the body → contacts adjacency
//! ([`super::indexed::each_neighbour`]), the scan's per-contact update
//! ([`PhaseWork::update`]). Memory grows with the contacts, not with one
//! body's contacts squared, and an iteration costs its bodies' contacts,
//! not every contact: on 1,000 coincident spheres (499,500 contacts on
//! bodies of 1,000 each) an iteration visits 2,000 contacts where the scan
//! visited every one of the 500,000 twice. The same contacts are taken in
//! the same order and updated by the same operations: the same results, bit
//! for bit (tests/physics/table_budget.rs).

use super::indexed::each_neighbour;
use super::observer::Observer;
use super::phase::{PhaseWork, Positions, Velocities};
use super::queue::{Queue, ScanQueue, TournamentTree, SCAN_BELOW};
use super::{PhaseOutcome, Resolver};
use crate::physics::Real;

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

/// The phase with the scan queue below [`SCAN_BELOW`] contacts, the
/// tournament tree from there on (as the indexed phases choose).
fn with_queue<T: Real, O: Observer<T>, W: PhaseWork<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    if r.contacts.len() < SCAN_BELOW {
        let mut queue: ScanQueue<T> = std::mem::take(&mut r.scan_queue);
        let outcome = phase::<T, O, W, _>(r, obs, &mut queue);
        r.scan_queue = queue;
        outcome
    } else {
        let mut queue: TournamentTree<T> = std::mem::take(&mut r.queue);
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
    queue.fill(r.contacts.iter().map(W::value));
    let mut changed = std::mem::take(&mut r.changed);
    let mut used = 0;
    while used < limit && !super::stop::asked(used) {
        let Some((k, value)) = queue.top().filter(|(_, v)| *v > epsilon) else {
            break;
        };
        let taken = r.contacts[k].bodies;
        let change = W::take(r, used, k, value, obs);
        let from = r.params.restitution_from;
        r.stamp += 1;
        let stamp = r.stamp;
        changed.clear();
        each_neighbour(r, taken, stamp, |r, j| {
            let (before, after) = W::update(&mut r.contacts[j], j, &taken, &change, from, obs);
            // As the indexed phases: a value left at or below epsilon is
            // never taken and never beats one above it.
            if !(Q::REPLAYS && before <= epsilon && after <= epsilon) {
                queue.set(j, after);
                if Q::REPLAYS {
                    changed.push(j);
                }
            }
        });
        if Q::REPLAYS {
            queue.replay(&mut changed);
        }
        used += 1;
    }
    r.changed = changed;
    r.finish(W::PHASE, used, obs)
}
