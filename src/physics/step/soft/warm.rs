//! Warm starting across steps: last step's impulses, matched to this
//! step's contacts by body pair and nearest point (within a tolerance),
//! the friction impulse kept as a world vector and projected on the new
//! tangents. Storage is kept from step to step.

use nalgebra::Vector3;

use super::prepare::SoftContact;
use crate::physics::{c, Contact, Real};

/// A point farther than this (m) from every point of last step's pair is new.
const MATCH_DISTANCE: f64 = 0.05;

#[derive(Debug, Clone, PartialEq)]
struct Stored<T: Real> {
    pair: (usize, usize),
    point: Vector3<T>,
    normal: T,
    friction: Vector3<T>,
}

/// Last step's impulses, sorted by pair.
#[derive(Debug, Clone)]
pub struct Kept<T: Real> {
    stored: Vec<Stored<T>>,
}

impl<T: Real> Default for Kept<T> {
    fn default() -> Self {
        Kept { stored: Vec::new() }
    }
}

fn pair<T: Real>(k: &Contact<T>) -> (usize, usize) {
    (k.body1.0, k.body2.map_or(usize::MAX, |b| b.0))
}

impl<T: Real> Kept<T> {
    /// Gives `contact` the impulses of last step's nearest point of its pair.
    pub fn restore(&self, k: &Contact<T>, contact: &mut SoftContact<T>) {
        let key = pair(k);
        let from = self.stored.partition_point(|s| s.pair < key);
        let limit = c::<T>(MATCH_DISTANCE * MATCH_DISTANCE);
        let nearest = self.stored[from..]
            .iter()
            .take_while(|s| s.pair == key)
            .map(|s| (s, (s.point - k.input.point).norm_squared()))
            .filter(|(_, d)| *d <= limit)
            .min_by(|a, b| a.1.partial_cmp(&b.1).unwrap_or(std::cmp::Ordering::Equal));
        if let Some((s, _)) = nearest {
            contact.normal_impulse = s.normal;
            contact.tangent_impulse = contact.tangents.map(|t| t.dot(&s.friction));
        }
    }

    /// Keeps this step's impulses for the next.
    pub fn store(&mut self, world: &[Contact<T>], contacts: &[SoftContact<T>]) {
        self.stored.clear();
        self.stored
            .extend(world.iter().zip(contacts).map(|(k, s)| Stored {
                pair: pair(k),
                point: k.input.point,
                normal: s.normal_impulse,
                friction: s.tangents[0] * s.tangent_impulse[0]
                    + s.tangents[1] * s.tangent_impulse[1],
            }));
        self.stored.sort_by_key(|s| s.pair);
    }
}
