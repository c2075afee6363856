//! The contact events of a step (contact made or lost, bounce, sticks,
//! slides), matched to last step's touching pairs by a map keyed by body
//! pair: O(pairs), in the order of first appearance.

use std::collections::hash_map::{Entry, HashMap};
use std::collections::HashSet;
use std::hash::{BuildHasherDefault, Hasher};

use super::report::Event;
use crate::physics::{to_f64, BodyId, Contact, Real};

/// Touching pairs of a step and whether they slid.
pub type Touching = Vec<(BodyId, Option<BodyId>, bool)>;

/// The contact events' state from step to step: last step's touching pairs
/// and their index by pair, and this step's buffers (kept, so that a step
/// allocates nothing once the scene's pairs have been seen).
#[derive(Debug, Clone, Default)]
pub struct ContactEvents {
    /// Last step's touching pairs, in the order of first appearance, and
    /// whether they slid; `last` maps each to its index there.
    touching: Touching,
    last: PairMap<usize>,
    /// This step's pairs, their speeds and their index (become the above).
    pairs: Touching,
    speeds: Vec<(f64, f64, bool)>,
    index: PairMap<usize>,
    bounces: Vec<Event>,
}

impl ContactEvents {
    /// Contact made or lost, bounces, sticking and sliding, per touching
    /// pair: `before` and `after` are each contact's (normal, tangential)
    /// speeds across the step, `limit` the speed below which a closing is a
    /// resting micro-collision; this step's pairs become the next step's
    /// last ones.
    pub fn report<T: Real>(
        &mut self,
        contacts: &[Contact<T>],
        before: &[(T, T)],
        after: &[(T, T)],
        limit: f64,
        events: &mut Vec<Event>,
    ) {
        let Self {
            touching,
            last,
            pairs,
            speeds,
            index,
            bounces,
        } = self;
        // Per touching pair: whether any point slides, the fastest closing
        // before and the fastest separating after.
        pairs.clear();
        speeds.clear();
        // Pair → its index in `pairs` (the order of first appearance, so the
        // events come out as a linear search would give them, in O(pairs)).
        index.clear();
        for (i, k) in contacts.iter().enumerate() {
            let vn0 = to_f64(before[i].0);
            let (vn1, vt1) = (to_f64(after[i].0), to_f64(after[i].1));
            // Sliding: faster than residual jitter of resting contacts (5 cm/s).
            let slides = vt1 > 0.05;
            let bouncy = k.input.restitution > T::zero();
            match index.entry((k.body1, k.body2)) {
                Entry::Occupied(j) => {
                    let j = *j.get();
                    pairs[j].2 |= slides;
                    speeds[j] = (
                        speeds[j].0.max(-vn0),
                        speeds[j].1.max(vn1),
                        speeds[j].2 || bouncy,
                    );
                }
                Entry::Vacant(slot) => {
                    slot.insert(pairs.len());
                    pairs.push((k.body1, k.body2, slides));
                    speeds.push((-vn0, vn1, bouncy));
                }
            }
        }
        bounces.clear();
        for (p, (closing, separating, bouncy)) in pairs.iter().zip(speeds.iter()) {
            // A bounce: closing faster than the velocity limit, leaving at a
            // speed worth naming (not round-off, not a resting micro-collision).
            if *bouncy && *closing > limit && *separating > (0.05 * closing).max(1e-3) {
                bounces.push(Event::Bounce {
                    body1: p.0,
                    body2: p.1,
                    closing: *closing,
                    separating: *separating,
                });
            }
        }
        // Last step's pairs by key: a pair is in it at most once.
        for p in pairs.iter() {
            match last.get(&(p.0, p.1)).map(|&j| touching[j].2) {
                None => events.push(Event::ContactMade {
                    body1: p.0,
                    body2: p.1,
                }),
                Some(slid) if slid && !p.2 => events.push(Event::Sticks {
                    body1: p.0,
                    body2: p.1,
                }),
                Some(slid) if !slid && p.2 => events.push(Event::Slides {
                    body1: p.0,
                    body2: p.1,
                    speed: 0.0,
                }),
                _ => {}
            }
        }
        for q in touching.iter() {
            if !index.contains_key(&(q.0, q.1)) {
                events.push(Event::ContactLost {
                    body1: q.0,
                    body2: q.1,
                });
            }
        }
        events.append(bounces);
        std::mem::swap(touching, pairs);
        std::mem::swap(last, index);
    }
}

/// A set of body pairs (the pairs wholly inside one another).
pub type PairSet = HashSet<(BodyId, Option<BodyId>), BuildHasherDefault<PairHasher>>;

/// A map keyed by body pair, for the contact events.
pub type PairMap<V> = HashMap<(BodyId, Option<BodyId>), V, BuildHasherDefault<PairHasher>>;

/// A multiply-rotate hash of a few small integers (body indices): keys are
/// ours, not an attacker's, and SipHash cost a seventh of a 1,000-sphere step.
#[derive(Default)]
pub struct PairHasher(u64);

impl Hasher for PairHasher {
    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.write_u64(u64::from(*b));
        }
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
    fn write_usize(&mut self, x: usize) {
        self.write_u64(x as u64);
    }
    fn write_isize(&mut self, x: isize) {
        self.write_u64(x as u64);
    }
    fn finish(&self) -> u64 {
        self.0
    }
}
