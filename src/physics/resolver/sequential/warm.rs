//! Warm starting: the accumulated impulses a step ends with, kept for the
//! next step, and matched to the next step's contacts by body pair and
//! contact point (the nearest within a distance). A resting contact then
//! starts from last step's impulse instead of zero, so few sweeps meet it.

use nalgebra::Vector3;

use super::super::Resolver;
use crate::physics::{c, BodyId, Real, World};

#[derive(Debug, Clone, PartialEq)]
struct Entry<T: Real> {
    pair: (usize, usize),
    point: Vector3<T>,
    /// World-space accumulated impulse on body 1.
    impulse: Vector3<T>,
}

/// Last step's accumulated impulses, sorted by body pair.
#[derive(Debug, Clone, PartialEq)]
pub struct WarmCache<T: Real> {
    entries: Vec<Entry<T>>,
}

impl<T: Real> Default for WarmCache<T> {
    fn default() -> Self {
        WarmCache {
            entries: Vec::new(),
        }
    }
}

/// A contact's pair as a sortable key (no second body sorts last).
fn key(body1: BodyId, body2: Option<BodyId>) -> (usize, usize) {
    (body1.0, body2.map_or(usize::MAX, |b| b.0))
}

/// How near a contact point must be to last step's to inherit its impulse (m).
pub const MATCH_DISTANCE: f64 = 0.05;

impl<T: Real> WarmCache<T> {
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    pub fn clear(&mut self) {
        self.entries.clear();
    }

    /// Hands `r` (prepared from `world`) the impulse of each contact that
    /// matches one of last step's; the velocity phase starts from them.
    ///
    /// A pair's entries are found once for its run of contacts, and where
    /// the contacts come in the entries' (pair) order, the next pair's
    /// entries start where the last pair's ended (no search); otherwise a
    /// binary search. Within the pair, the nearest point as before.
    pub fn stage(&self, world: &World<T>, r: &mut Resolver<T>) {
        if self.entries.is_empty() {
            return;
        }
        let limit = c::<T>(MATCH_DISTANCE);
        let entries = &self.entries[..];
        let mut group: Option<(usize, usize)> = None;
        let (mut start, mut end) = (0, 0);
        for (contact, warm) in world.contacts.iter().zip(r.sequential.warm.iter_mut()) {
            let pair = key(contact.body1, contact.body2);
            if group != Some(pair) {
                // Sorted entries: one of `pair` right after the last run is its first.
                start = if entries.get(end).is_some_and(|e| e.pair == pair) {
                    end
                } else {
                    entries.partition_point(|e| e.pair < pair)
                };
                end = start
                    + entries[start..]
                        .iter()
                        .take_while(|e| e.pair == pair)
                        .count();
                group = Some(pair);
            }
            let mut best: Option<(T, Vector3<T>)> = None;
            for e in &entries[start..end] {
                let d = (e.point - contact.input.point).norm();
                if d <= limit && best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, e.impulse));
                }
            }
            *warm = best.map(|(_, g)| g);
        }
    }

    /// Keeps the accumulated impulses `r` ended with for `world`'s contacts.
    pub fn store(&mut self, world: &World<T>, r: &Resolver<T>) {
        self.entries.clear();
        self.entries
            .extend(world.contacts.iter().enumerate().map(|(k, contact)| Entry {
                pair: key(contact.body1, contact.body2),
                point: contact.input.point,
                impulse: r.contacts[k].basis * r.sequential.accumulated[k],
            }));
        self.entries.sort_by_key(|e| e.pair);
    }

    /// Forgets the impulses of the pairs `keep` refuses (`keep(body1, body2)`).
    pub fn retain_pairs(&mut self, keep: impl Fn(BodyId, Option<BodyId>) -> bool) {
        self.entries.retain(|e| {
            let body2 = (e.pair.1 != usize::MAX).then_some(BodyId(e.pair.1));
            keep(BodyId(e.pair.0), body2)
        });
    }
}
