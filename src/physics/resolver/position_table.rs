//! Twin of the scan's position phase ([`super::scan`]), held bit for bit by
//! `tests/physics/lean_position.rs` and `tests/physics/resolver_properties.rs`.
//!
//! The indexed position phase on the neighbour table ([`Neighbours`], built
//! at the phase's start and kept for the velocity phase while the contacts'
//! bodies are the same): each taken contact's neighbours in the order
//! [`super::indexed::each_neighbour`] visits them, each with the taken
//! contact's slot that moved each of its slots, so an iteration walks one
//! short list (no adjacency rows, no stamps, no body comparisons) and brings
//! each neighbour's penetration up to date with `pen_j -= s·(Δp + Δθ × r_j)·n_j`
//! ([`position::penetration_after_slots`]: the same operations in the same
//! order as [`position::penetration_after`]). The same contacts are taken in
//! the same order and the same reports made as by the adjacency loop and the
//! scan, so the results are bit for bit theirs.
//!
//! No compact rows: a neighbour update reads the contact's penetration, r
//! and normal, which a row would only copy (the same loads, plus the copies
//! in and out).

use super::neighbours::Neighbours;
use super::observer::Observer;
use super::phase::{PhaseWork, Positions};
use super::queue::Queue;
use super::{position, Phase, PhaseOutcome, Resolver};
use crate::physics::Real;

/// The position phase with `queue`, on `table` (built for `r`'s contacts).
pub(super) fn phase<T: Real, O: Observer<T>, Q: Queue<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
    queue: &mut Q,
    table: &Neighbours,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Position);
    queue.fill(r.contacts.iter().map(|c| c.penetration));
    let mut used = 0;
    while used < limit && !super::stop::asked(used) {
        let Some((k, value)) = queue.top().filter(|(_, v)| *v > epsilon) else {
            break;
        };
        let moves = Positions::take(r, used, k, value, obs);
        let Resolver {
            contacts, changed, ..
        } = &mut *r;
        let contacts = contacts.as_mut_slice();
        changed.clear();
        for n in table.of(k) {
            let j = n.contact as usize;
            let c = &mut contacts[j];
            let before = c.penetration;
            let after = position::penetration_after_slots(c, n.slots, &moves);
            c.penetration = after;
            obs.penetration_updated(j, before, after);
            // A queue that replays nothing (the scan's) is set every time:
            // a value left at or below epsilon is either way a key at or
            // below it, which is never taken and never beats one above it.
            if !(Q::REPLAYS && before <= epsilon && after <= epsilon) {
                queue.set(j, after);
                if Q::REPLAYS {
                    changed.push(j);
                }
            }
        }
        if Q::REPLAYS {
            queue.replay(changed);
        }
        used += 1;
    }
    r.finish(Phase::Position, used, obs)
}
