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
    /// last ones. `before` holds each contact's normal speed alone, and
    /// may be empty when no contact [`can_bounce`] (only a bouncy pair's
    /// closing speed is read).
    pub fn report<T: Real>(
        &mut self,
        contacts: &[Contact<T>],
        before: &[T],
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
        // before and the fastest separating after. A pair's points come one
        // after another (contact generation runs pair by pair): merged here
        // without a map; a pair met again later is the map's case below.
        pairs.clear();
        speeds.clear();
        for (i, k) in contacts.iter().enumerate() {
            let (vn0, slides, vn1, bouncy) = speeds_of(k, before.get(i).copied(), after[i]);
            match pairs.last_mut() {
                Some(p) if (p.0, p.1) == (k.body1, k.body2) => {
                    p.2 |= slides;
                    let s = speeds.last_mut().expect("one per pair");
                    *s = (s.0.max(-vn0), s.1.max(vn1), s.2 || bouncy);
                }
                _ => {
                    pairs.push((k.body1, k.body2, slides));
                    speeds.push((-vn0, vn1, bouncy));
                }
            }
        }
        // The same pairs as last step, in the same order (a resting scene):
        // nothing made or lost, and last step's index serves this step.
        let same = pairs.len() == touching.len()
            && (pairs.iter().zip(touching.iter())).all(|(p, q)| (p.0, p.1) == (q.0, q.1));
        if !same {
            // Pair → its index in `pairs` (the order of first appearance,
            // so the events come out as a linear search would give them,
            // in O(pairs)).
            pairs.clear();
            speeds.clear();
            index.clear();
            for (i, k) in contacts.iter().enumerate() {
                let (vn0, slides, vn1, bouncy) = speeds_of(k, before.get(i).copied(), after[i]);
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
        for (n, p) in pairs.iter().enumerate() {
            let slid = if same {
                Some(touching[n].2)
            } else {
                last.get(&(p.0, p.1)).map(|&j| touching[j].2)
            };
            match slid {
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
        for q in touching.iter().filter(|_| !same) {
            if !index.contains_key(&(q.0, q.1)) {
                events.push(Event::ContactLost {
                    body1: q.0,
                    body2: q.1,
                });
            }
        }
        events.append(bounces);
        std::mem::swap(touching, pairs);
        if !same {
            // (The same pairs: `last` already indexes them.)
            std::mem::swap(last, index);
        }
    }
}

/// A contact's speeds as the events read them: the normal speed before,
/// whether it slides after (faster than residual jitter of resting
/// contacts, 5 cm/s), the normal speed after, whether it can bounce.
fn speeds_of<T: Real>(k: &Contact<T>, before: Option<T>, after: (T, T)) -> (f64, bool, f64, bool) {
    // No normal speed before: no contact can bounce, and the closing
    // speed this gives is never read.
    let vn0 = before.map_or(0.0, to_f64);
    let (vn1, vt1) = (to_f64(after.0), to_f64(after.1));
    (vn0, vt1 > 0.05, vn1, can_bounce(k))
}

/// Whether a contact can bounce (restitution above zero): only then is a
/// pair's closing speed before the step read.
pub fn can_bounce<T: Real>(k: &Contact<T>) -> bool {
    k.input.restitution > T::zero()
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::{ContactInput, ContactParams, FrictionModel};
    use nalgebra::Vector3;

    fn contact(b1: usize, b2: Option<usize>, restitution: f64) -> Contact<f64> {
        Contact {
            body1: BodyId(b1),
            body2: b2.map(BodyId),
            input: ContactInput {
                point: Vector3::zeros(),
                normal: Vector3::y(),
                penetration: 0.0,
                restitution,
                static_friction: 0.5,
                dynamic_friction: 0.5,
                friction_model: FrictionModel::default(),
                settings: ContactParams::default(),
            },
            duration: None,
        }
    }

    /// A contact's (normal, tangential) speeds before and after.
    type Speeds = ((f64, f64), (f64, f64));

    /// The events by linear search (the definition the maps must match):
    /// pairs in the order of first appearance, last step's pairs looked up
    /// one by one.
    fn by_search(
        contacts: &[Contact<f64>],
        speeds: &[Speeds],
        last: &Touching,
    ) -> (Vec<Event>, Touching) {
        let mut pairs: Touching = Vec::new();
        let mut fast: Vec<(f64, f64, bool)> = Vec::new();
        for (k, ((vn0, _), (vn1, vt1))) in contacts.iter().zip(speeds) {
            let bouncy = k.input.restitution > 0.0;
            match pairs.iter().position(|p| (p.0, p.1) == (k.body1, k.body2)) {
                Some(j) => {
                    pairs[j].2 |= *vt1 > 0.05;
                    fast[j] = (
                        fast[j].0.max(-vn0),
                        fast[j].1.max(*vn1),
                        fast[j].2 || bouncy,
                    );
                }
                None => {
                    pairs.push((k.body1, k.body2, *vt1 > 0.05));
                    fast.push((-vn0, *vn1, bouncy));
                }
            }
        }
        let mut events = Vec::new();
        for p in &pairs {
            match last.iter().find(|q| (q.0, q.1) == (p.0, p.1)).map(|q| q.2) {
                None => events.push(Event::ContactMade {
                    body1: p.0,
                    body2: p.1,
                }),
                Some(true) if !p.2 => events.push(Event::Sticks {
                    body1: p.0,
                    body2: p.1,
                }),
                Some(false) if p.2 => events.push(Event::Slides {
                    body1: p.0,
                    body2: p.1,
                    speed: 0.0,
                }),
                _ => {}
            }
        }
        for q in last
            .iter()
            .filter(|q| !pairs.iter().any(|p| (p.0, p.1) == (q.0, q.1)))
        {
            events.push(Event::ContactLost {
                body1: q.0,
                body2: q.1,
            });
        }
        for (p, (closing, separating, bouncy)) in pairs.iter().zip(&fast) {
            if *bouncy && *closing > 1.0 && *separating > (0.05 * closing).max(1e-3) {
                events.push(Event::Bounce {
                    body1: p.0,
                    body2: p.1,
                    closing: *closing,
                    separating: *separating,
                });
            }
        }
        (events, pairs)
    }

    #[test]
    fn kept_maps_and_the_same_pairs_shortcut_give_the_linear_searchs_events() {
        // Steps: made; the same pairs resting, then sliding, then sticking;
        // a pair lost and one made; a pair's points apart in the list (the
        // map's case); a bounce; nothing.
        let rest = ((0.0, 0.0), (0.0, 0.0));
        let slide = ((0.0, 0.0), (0.0, 0.2));
        let bounce = ((-3.0, 0.0), (1.0, 0.0));
        let a = || contact(0, Some(1), 0.0);
        let b = || contact(2, None, 0.5);
        let c = || contact(3, Some(1), 0.0);
        let steps: Vec<(Vec<Contact<f64>>, Vec<_>)> = vec![
            (vec![a(), a(), b()], vec![rest, rest, rest]),
            (vec![a(), a(), b()], vec![rest, rest, rest]),
            (vec![a(), a(), b()], vec![rest, slide, rest]),
            (vec![a(), a(), b()], vec![rest, rest, rest]),
            (vec![a(), c()], vec![rest, rest]),
            (vec![a(), c(), a()], vec![slide, rest, rest]),
            (vec![a(), c(), b()], vec![rest, rest, bounce]),
            (vec![a(), c(), b()], vec![rest, rest, rest]),
            (vec![], vec![]),
        ];
        let mut state = ContactEvents::default();
        let mut last: Touching = Vec::new();
        let mut seen = Vec::new();
        for (contacts, speeds) in &steps {
            let (before, after): (Vec<(f64, f64)>, Vec<_>) = speeds.iter().copied().unzip();
            let before: Vec<f64> = before.iter().map(|b| b.0).collect();
            let mut events = Vec::new();
            state.report(contacts, &before, &after, 1.0, &mut events);
            let (expected, pairs) = by_search(contacts, speeds, &last);
            assert_eq!(events, expected);
            seen.extend(events);
            last = pairs;
        }
        // Every kind was met.
        let kind = |f: fn(&Event) -> bool| seen.iter().any(f);
        assert!(kind(|e| matches!(e, Event::ContactMade { .. })));
        assert!(kind(|e| matches!(e, Event::ContactLost { .. })));
        assert!(kind(|e| matches!(e, Event::Slides { .. })));
        assert!(kind(|e| matches!(e, Event::Sticks { .. })));
        assert!(kind(|e| matches!(e, Event::Bounce { .. })));
    }

    #[test]
    fn without_a_contact_that_can_bounce_the_speeds_before_are_not_read() {
        // The same steps with every restitution 0: the events from the
        // speeds before and from none at all (what the step passes then)
        // are the same, closing speeds of any size notwithstanding.
        let a = || contact(0, Some(1), 0.0);
        let c = || contact(3, Some(1), 0.0);
        let d = || contact(2, None, 0.0);
        let fast = ((-3.0, 0.4), (1.0, 0.0));
        let slide = ((-0.5, 0.0), (0.2, 0.3));
        let steps: Vec<(Vec<Contact<f64>>, Vec<_>)> = vec![
            (vec![a(), a(), d()], vec![fast, fast, slide]),
            (vec![a(), c(), a()], vec![slide, fast, fast]),
            (vec![c(), d()], vec![fast, fast]),
            (vec![], vec![]),
        ];
        let (mut read, mut unread) = (ContactEvents::default(), ContactEvents::default());
        let mut seen = 0;
        for (contacts, speeds) in &steps {
            assert!(!contacts.iter().any(can_bounce));
            let before: Vec<f64> = speeds.iter().map(|s| s.0 .0).collect();
            let after: Vec<(f64, f64)> = speeds.iter().map(|s| s.1).collect();
            let (mut with, mut without) = (Vec::new(), Vec::new());
            read.report(contacts, &before, &after, 0.05, &mut with);
            unread.report(contacts, &[], &after, 0.05, &mut without);
            assert_eq!(with, without);
            seen += with.len();
        }
        assert!(seen >= 4, "{seen}");
    }
}
