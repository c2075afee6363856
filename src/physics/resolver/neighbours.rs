//! The neighbour table of the indexed phases: for every contact, the
//! contacts sharing a body with it (itself included), each with the slots the
//! contact changes of it, in the order [`super::indexed::each_neighbour`]
//! visits them, and the same neighbours grouped by those slots
//! ([`SLOT_PATTERNS`]) for the velocity phase's silent loop.

use super::velocity_row::UNCHANGED;
use super::Resolver;
use crate::physics::Real;

/// The slots a neighbour can have (for its slot 1, then its slot 2: the
/// taken contact's slot with the same body, [`UNCHANGED`] for none): both
/// bodies shared (either way round), or one of them.
const SLOT_PATTERNS: [[u8; 2]; 6] = [
    [0, 1],
    [1, 0],
    [0, UNCHANGED],
    [1, UNCHANGED],
    [UNCHANGED, 0],
    [UNCHANGED, 1],
];

/// One neighbour of a contact: a contact sharing a body with it, and for
/// each of the neighbour's slots the contact's slot with the same body
/// ([`UNCHANGED`] for none).
#[derive(Debug, Clone, Copy)]
pub struct Neighbour {
    pub contact: u32,
    pub slots: [u8; 2],
}

/// Every contact's neighbours (itself included), in the order
/// [`each_neighbour`](super::indexed::each_neighbour) visits them: the contacts of its body 1, then those of
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
    /// The same neighbours by the slots the taken contact changed
    /// ([`SLOT_PATTERNS`]): contact `k`'s pattern `p` ones are
    /// `grouped[bounds[k][p]..bounds[k][p + 1]]`.
    grouped: Vec<u32>,
    bounds: Vec<[u32; 7]>,
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
        self.grouped
            .reserve(most.saturating_sub(self.grouped.len()));
        self.bounds.reserve(n.saturating_sub(self.bounds.len()));
        self.slots.reserve(n.saturating_sub(self.slots.len()));
    }

    /// Lists every contact's neighbours (marks them with `r`'s stamps, as
    /// [`each_neighbour`](super::indexed::each_neighbour) does).
    pub(super) fn build<T: Real>(&mut self, r: &mut Resolver<T>) {
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
        self.group();
    }

    /// Sorts every contact's neighbours into [`SLOT_PATTERNS`]' groups (each
    /// group in the table's order).
    fn group(&mut self) {
        self.grouped.clear();
        self.bounds.clear();
        for k in 0..self.offsets.len() - 1 {
            let of = &self.entries[self.offsets[k] as usize..self.offsets[k + 1] as usize];
            let mut bounds = [self.grouped.len() as u32; 7];
            for (p, pattern) in SLOT_PATTERNS.into_iter().enumerate() {
                let members = of.iter().filter(|n| n.slots == pattern);
                self.grouped.extend(members.map(|n| n.contact));
                bounds[p + 1] = self.grouped.len() as u32;
            }
            debug_assert_eq!(
                bounds[6],
                self.offsets[k + 1],
                "every neighbour has a pattern"
            );
            self.bounds.push(bounds);
        }
    }

    /// The neighbours of contact `k`.
    #[inline(always)]
    pub fn of(&self, k: usize) -> &[Neighbour] {
        &self.entries[self.offsets[k] as usize..self.offsets[k + 1] as usize]
    }

    /// The neighbours of contact `k` by [`SLOT_PATTERNS`].
    #[inline(always)]
    pub(super) fn grouped(&self, k: usize) -> [&[u32]; 6] {
        let b = &self.bounds[k];
        let g = |p: usize| &self.grouped[b[p] as usize..b[p + 1] as usize];
        [g(0), g(1), g(2), g(3), g(4), g(5)]
    }
}
