//! The pairs of bodies that have a contact this step ([`ContactPairs`]),
//! which the tunnelling auditor ([`super::ccd`]) and the substeps skip; the
//! swept broad phase ([`super::swept`]) keeps the set's storage.

use crate::physics::{BodyId, Real, World};

/// The pairs of bodies that have a contact this step, by [`key`].
pub fn contact_pairs<T: Real>(world: &World<T>) -> ContactPairs {
    let mut pairs = ContactPairs::default();
    contact_pairs_into(world, &mut pairs);
    pairs
}

/// [`contact_pairs`] into `pairs` (its storage reused).
pub fn contact_pairs_into<T: Real>(world: &World<T>, pairs: &mut ContactPairs) {
    let keys = &mut pairs.0;
    keys.clear();
    // Generated contacts come pair by pair in sorted order: a pair's
    // contacts follow one another (kept once as they come), and the keys
    // are sorted only when they are not (contacts given otherwise).
    let mut sorted = true;
    for k in &world.contacts {
        let Some(b2) = k.body2 else {
            continue;
        };
        let key = (k.body1.0.min(b2.0), k.body1.0.max(b2.0));
        match keys.last() {
            Some(&last) if last == key => continue,
            Some(&last) if last > key => sorted = false,
            _ => {}
        }
        keys.push(key);
    }
    if !sorted {
        keys.sort_unstable();
        keys.dedup();
    }
}

/// A set of body pairs, each as its [`key`]'s indices, sorted (building it
/// hashes nothing; a step's contacts are already in pair order).
#[derive(Debug, Clone, Default)]
pub struct ContactPairs(Vec<(usize, usize)>);

impl ContactPairs {
    #[inline]
    pub fn contains(&self, pair: &(BodyId, Option<BodyId>)) -> bool {
        let (a, Some(b)) = *pair else {
            return false;
        };
        self.0.binary_search(&(a.0, b.0)).is_ok()
    }
}

/// A pair of bodies in either order, as one key.
#[inline]
pub fn key(i: usize, j: usize) -> (BodyId, Option<BodyId>) {
    (BodyId(i.min(j)), Some(BodyId(i.max(j))))
}
