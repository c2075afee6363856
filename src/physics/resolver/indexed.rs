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
use super::phase::{PhaseWork, Velocities};
use super::queue::{Queue, SCAN_BELOW};
use super::velocity::{VelocityRow, UNCHANGED};
use super::{position_table, Phase, PhaseOutcome, Resolver};
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
    with_queue(r, obs)
}

pub fn velocity_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    if r.contacts.len() < SCAN_BELOW {
        let mut queue = std::mem::take(&mut r.scan_queue);
        let outcome = velocity_rows::<T, O, _>(r, obs, &mut queue);
        r.scan_queue = queue;
        outcome
    } else {
        let mut queue = std::mem::take(&mut r.queue);
        let outcome = velocity_rows::<T, O, _>(r, obs, &mut queue);
        r.queue = queue;
        outcome
    }
}

/// Runs the position phase ([`position_table::phase`]) on the neighbour
/// table (built here, kept for the velocity phase) with the scan queue below
/// [`SCAN_BELOW`] contacts, the tournament tree from there on (both give the
/// same order).
fn with_queue<T: Real, O: Observer<T>>(r: &mut Resolver<T>, obs: &mut O) -> PhaseOutcome<T> {
    let mut table = std::mem::take(&mut r.neighbours);
    table.build(r);
    let outcome = if r.contacts.len() < SCAN_BELOW {
        let mut queue = std::mem::take(&mut r.scan_queue);
        let outcome = position_table::phase(r, obs, &mut queue, &table);
        r.scan_queue = queue;
        outcome
    } else {
        let mut queue = std::mem::take(&mut r.queue);
        let outcome = position_table::phase(r, obs, &mut queue, &table);
        r.queue = queue;
        outcome
    };
    r.neighbours = table;
    outcome
}

/// The velocity phase, its neighbour updates on the contacts'
/// hot rows ([`VelocityRow`]: copied in at the start, the velocities and
/// desired Δv written back at the end) through the neighbour table
/// ([`Neighbours`], built at the start: the same neighbours in the same
/// order as [`each_neighbour`], each with the slots the taken contact
/// changed); the same operations in the same order, so the same results
/// bit for bit.
fn velocity_rows<T: Real, O: Observer<T>, Q: Queue<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
    queue: &mut Q,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Velocity);
    let from = r.params.restitution_from;
    let mut rows = std::mem::take(&mut r.velocity_rows);
    rows.clear();
    rows.extend(r.contacts.iter().map(|c| VelocityRow::of(c, from)));
    let mut table = std::mem::take(&mut r.neighbours);
    table.build(r);
    queue.fill(rows.iter().map(|w| w.desired));
    let mut used = 0;
    while used < limit {
        let Some((k, value)) = queue.top().filter(|(_, v)| *v > epsilon) else {
            break;
        };
        // The taken contact's bookkeeping is its row's.
        let c = &mut r.contacts[k];
        c.velocity = rows[k].velocity;
        c.desired = rows[k].desired;
        let change = Velocities::take(r, used, k, value, obs);
        r.changed.clear();
        for n in table.of(k) {
            let j = n.contact as usize;
            let (before, after) = rows[j].update(n.slots, &change);
            obs.desired_updated(j, before, after);
            if !(before <= epsilon && after <= epsilon) {
                queue.set(j, after);
                if Q::REPLAYS {
                    r.changed.push(j);
                }
            }
        }
        if Q::REPLAYS {
            queue.replay(&mut r.changed);
        }
        used += 1;
    }
    for (c, w) in r.contacts.iter_mut().zip(&rows) {
        c.velocity = w.velocity;
        c.desired = w.desired;
    }
    r.velocity_rows = rows;
    r.neighbours = table;
    r.finish(Phase::Velocity, used, obs)
}

/// One neighbour of a contact: a contact sharing a body with it, and for
/// each of the neighbour's slots the contact's slot with the same body
/// ([`UNCHANGED`] for none).
#[derive(Debug, Clone, Copy)]
pub struct Neighbour {
    pub contact: u32,
    pub slots: [u8; 2],
}

/// Every contact's neighbours (itself included), in the order
/// [`each_neighbour`] visits them: the contacts of its body 1, then those of
/// its body 2 not yet listed. Fixed while the phases run (the adjacency
/// is); storage sized at prepare. The adjacency is a function of the
/// number of bodies and the contacts' slots, so the table is kept from one
/// prepare to the next while they are the same (a resting stack's are,
/// step after step).
#[derive(Debug, Clone, Default)]
pub struct Neighbours {
    /// Contact `k`'s neighbours are `entries[offsets[k]..offsets[k + 1]]`.
    offsets: Vec<u32>,
    entries: Vec<Neighbour>,
    /// The resolver bodies and contact slots the table was built for.
    bodies: usize,
    slots: Vec<[Option<usize>; 2]>,
}

impl Neighbours {
    /// Room for the table of `r`'s contacts (at most the contacts of both
    /// bodies of each contact).
    pub fn reserve<T: Real>(&mut self, r: &Resolver<T>) {
        let most: usize = r
            .contacts
            .iter()
            .flat_map(|c| c.bodies.into_iter().flatten())
            .map(|b| r.adjacency.of(b).len())
            .sum();
        assert!(
            most < u32::MAX as usize,
            "neighbours are numbered in 32 bits"
        );
        let n = r.contacts.len();
        // Capacity for the largest table, kept as it is (it may be reused).
        self.offsets
            .reserve((n + 1).saturating_sub(self.offsets.len()));
        self.entries
            .reserve(most.saturating_sub(self.entries.len()));
        self.slots.reserve(n.saturating_sub(self.slots.len()));
    }

    /// Lists every contact's neighbours (marks them with `r`'s stamps, as
    /// [`each_neighbour`] does).
    fn build<T: Real>(&mut self, r: &mut Resolver<T>) {
        let same = self.bodies == r.bodies.len()
            && self.slots.len() == r.contacts.len()
            && self
                .slots
                .iter()
                .zip(&r.contacts)
                .all(|(s, c)| *s == c.bodies);
        if same {
            return;
        }
        self.bodies = r.bodies.len();
        self.slots.clear();
        self.slots.extend(r.contacts.iter().map(|c| c.bodies));
        self.offsets.clear();
        self.entries.clear();
        self.offsets.push(0);
        let Resolver {
            contacts,
            adjacency,
            stamps,
            stamp,
            ..
        } = r;
        for c in contacts.iter() {
            let taken = c.bodies;
            let slot = |body: Option<usize>| match body {
                Some(_) if body == taken[0] => 0,
                Some(_) if body == taken[1] => 1,
                _ => UNCHANGED,
            };
            *stamp += 1;
            for b in taken.into_iter().flatten() {
                for &j in adjacency.of(b) {
                    if stamps[j] == *stamp {
                        continue;
                    }
                    stamps[j] = *stamp;
                    let bodies = contacts[j].bodies;
                    self.entries.push(Neighbour {
                        contact: j as u32,
                        slots: [slot(bodies[0]), slot(bodies[1])],
                    });
                }
            }
            self.offsets.push(self.entries.len() as u32);
        }
    }

    /// The neighbours of contact `k`.
    #[inline(always)]
    pub fn of(&self, k: usize) -> &[Neighbour] {
        &self.entries[self.offsets[k] as usize..self.offsets[k + 1] as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::super::{row::sphere_row, Implementation, Resolver, Silent};
    use crate::physics::params::ResolverParams;

    /// A resolver prepared again for other worlds (its neighbour table kept
    /// when the contacts' bodies are the same, rebuilt when they are not)
    /// resolves each as a fresh scan does, bit for bit.
    #[test]
    fn a_reused_resolver_resolves_each_world_as_the_scan_does() {
        let params = ResolverParams::default();
        let mut reused = Resolver::prepare(&sphere_row::<f64>(3), &params);
        for n in [3usize, 3, 7, 2, 7, 40, 40] {
            let world = sphere_row::<f64>(n);
            reused.prepare_again(&world, &params);
            let position = reused.position_phase(Implementation::Indexed, &mut Silent);
            let velocity = reused.velocity_phase(Implementation::Indexed, &mut Silent);
            let (scan, outcomes) =
                Resolver::resolve(&world, &params, Implementation::Scan, &mut Silent);
            assert!(outcomes[1].iterations_used > 0, "row of {n}: {outcomes:?}");
            assert_eq!([position, velocity], outcomes, "row of {n}");
            assert_eq!(reused.bodies, scan.bodies, "row of {n}");
            assert_eq!(reused.contacts, scan.contacts, "row of {n}");
        }
    }
}
