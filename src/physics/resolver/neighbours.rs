//! The neighbour table of the indexed phases: for every contact, the
//! contacts sharing a body with it (itself included), each with the slots the
//! contact changes of it, in the order [`super::indexed::each_neighbour`]
//! visits them, and the same neighbours grouped by those slots
//! ([`SLOT_PATTERNS`]), each group as whole blocks of four contacts (the
//! velocity rows' [`Block`](super::velocity_row)s, updated four lanes at a
//! time) and the rest, for the velocity phase's silent loop.

use super::velocity_row::UNCHANGED;
use super::Resolver;
use crate::physics::Real;

/// The slots a neighbour can have (for its slot 1, then its slot 2: the
/// taken contact's slot with the same body, [`UNCHANGED`] for none): both
/// bodies shared (either way round), or one of them.
pub(super) const SLOT_PATTERNS: [[u8; 2]; 6] = [
    [0, 1],
    [1, 0],
    [0, UNCHANGED],
    [1, UNCHANGED],
    [UNCHANGED, 0],
    [UNCHANGED, 1],
];

/// The most entries a neighbour table may hold (8 bytes each, and 4 more
/// for the grouped copy: about 800 MB): a table is the sum over the
/// contacts of the contacts of their bodies, so it grows as the square of
/// one body's contacts (70,000 on one body would ask for 4.9 × 10⁹, beyond
/// the 32-bit numbering and the memory). Beyond it the indexed phases
/// find each taken contact's neighbours through the body → contacts
/// adjacency instead ([`super::adjacent`]: the same contacts in the same
/// order, the same results), and the resolver says so
/// ([`super::Resolver::table_over_budget`]).
pub const TABLE_BUDGET: usize = 1 << 26;

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
    /// ([`SLOT_PATTERNS`]): contact `k`'s pattern `p` ones are the blocks
    /// `j..j + 4` for each `j` of `grouped[bounds[k][2p]..bounds[k][2p + 1]]`
    /// and the contacts `grouped[bounds[k][2p + 1]..bounds[k][2p + 2]]`.
    grouped: Vec<u32>,
    bounds: Vec<[u32; 13]>,
    /// Scratch for grouping (one pattern's members, those in no whole block).
    members: Vec<u32>,
    others: Vec<u32>,
    /// The entries the table of the last reserve's contacts would hold at
    /// most (its size, against [`TABLE_BUDGET`]).
    wanted: usize,
    /// The resolver bodies and contact slots the table was built for.
    bodies: usize,
    slots: Vec<[Option<usize>; 2]>,
}

impl Neighbours {
    /// Room for the table of `r`'s contacts (at most the contacts of both
    /// bodies of each contact).
    pub fn reserve<T: Real>(&mut self, r: &Resolver<T>) {
        // Each contact has at most the contacts of both its bodies.
        let width = |c: &super::ResolverContact<T>| -> usize {
            c.bodies
                .into_iter()
                .flatten()
                .map(|b| r.adjacency.of(b).len())
                .sum()
        };
        let most: usize = r.contacts.iter().map(width).sum();
        self.wanted = most;
        if most > TABLE_BUDGET {
            // Over the budget: the phases go through the adjacency (never built).
            return;
        }
        let widest = r.contacts.iter().map(width).max().unwrap_or(0);
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
        // Grouping scratch: one contact's neighbours at most.
        self.members.reserve(widest);
        self.others.reserve(widest);
    }

    /// The entries the table of the last reserve's contacts would hold.
    pub fn wanted(&self) -> usize {
        self.wanted
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

    /// Sorts every contact's neighbours into [`SLOT_PATTERNS`]' groups, each
    /// group (in the table's order) split into whole blocks of four
    /// contacts (`4b..4b + 4`, listed one after another) and the others.
    fn group(&mut self) {
        self.grouped.clear();
        self.bounds.clear();
        let (mut members, mut others) = (
            std::mem::take(&mut self.members),
            std::mem::take(&mut self.others),
        );
        for k in 0..self.offsets.len() - 1 {
            let of = &self.entries[self.offsets[k] as usize..self.offsets[k + 1] as usize];
            let mut bounds = [self.grouped.len() as u32; 13];
            for (p, pattern) in SLOT_PATTERNS.into_iter().enumerate() {
                members.clear();
                members.extend(of.iter().filter(|n| n.slots == pattern).map(|n| n.contact));
                others.clear();
                let mut rest = &members[..];
                while let Some(&j) = rest.first() {
                    let block = j % 4 == 0 && rest.get(..4) == Some(&[j, j + 1, j + 2, j + 3]);
                    if block {
                        self.grouped.push(j);
                        rest = &rest[4..];
                    } else {
                        others.push(j);
                        rest = &rest[1..];
                    }
                }
                bounds[2 * p + 1] = self.grouped.len() as u32;
                self.grouped.extend_from_slice(&others);
                bounds[2 * p + 2] = self.grouped.len() as u32;
            }
            debug_assert_eq!(
                (0..6)
                    .map(
                        |p| 4 * (bounds[2 * p + 1] - bounds[2 * p]) + bounds[2 * p + 2]
                            - bounds[2 * p + 1]
                    )
                    .sum::<u32>(),
                self.offsets[k + 1] - self.offsets[k],
                "every neighbour has a pattern"
            );
            self.bounds.push(bounds);
        }
        (self.members, self.others) = (members, others);
    }

    /// The neighbours of contact `k`.
    #[inline(always)]
    pub fn of(&self, k: usize) -> &[Neighbour] {
        &self.entries[self.offsets[k] as usize..self.offsets[k + 1] as usize]
    }

    /// The neighbours of contact `k` by [`SLOT_PATTERNS`], each pattern's as
    /// whole blocks of four contacts and the rest.
    #[inline(always)]
    pub(super) fn grouped(&self, k: usize) -> [Group<'_>; 6] {
        let b = &self.bounds[k];
        let g = |p: usize| Group {
            blocks: &self.grouped[b[2 * p] as usize..b[2 * p + 1] as usize],
            others: &self.grouped[b[2 * p + 1] as usize..b[2 * p + 2] as usize],
        };
        [g(0), g(1), g(2), g(3), g(4), g(5)]
    }
}

/// The neighbours with one slot pattern: contacts `j..j + 4` for each `j`
/// of `blocks` (a multiple of four), and each of `others`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Group<'a> {
    pub blocks: &'a [u32],
    pub others: &'a [u32],
}
