//! The indexed resolver's priority queue: a tournament (winner) tree over
//! the contacts' values with the scan's tie rule — the largest value wins,
//! the lowest contact index among equal values. Leaves are the contacts;
//! each inner node holds the winner of its two children, so the root is the
//! contact the scan would take. Changing one value replays the matches on
//! its path to the root (at most log₂ n). A NaN value ranks below everything
//! (the scan never takes it). Storage is allocated once; filling and
//! updating allocate nothing.

use crate::physics::{c, Real};

/// A contact and its value, as a node of the tree holds its winner.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Entry<T> {
    key: T,
    contact: u32,
}

#[derive(Debug, Clone)]
pub struct TournamentTree<T: Real> {
    /// Contacts (leaves).
    n: usize,
    /// Node `p` holds the winner of its subtree with its value: inner nodes
    /// `1..n`, leaf `i` at `n + i`. A match reads one pair of siblings, side
    /// by side in memory.
    nodes: Vec<Entry<T>>,
}

impl<T: Real> Default for TournamentTree<T> {
    fn default() -> Self {
        Self::with_capacity(0)
    }
}

impl<T: Real> TournamentTree<T> {
    pub fn with_capacity(n: usize) -> Self {
        assert!(n < u32::MAX as usize, "contacts are numbered in 32 bits");
        TournamentTree {
            n: 0,
            nodes: Vec::with_capacity(2 * n),
        }
    }

    fn key(x: T) -> T {
        // NaN is the one value not ordered against itself.
        if x.partial_cmp(&x).is_none() {
            -c::<T>(f64::INFINITY)
        } else {
            x
        }
    }

    /// The winner of two entries: the larger value, the lower contact on ties.
    fn play(a: Entry<T>, b: Entry<T>) -> Entry<T> {
        if a.key > b.key || (a.key == b.key && a.contact < b.contact) {
            a
        } else {
            b
        }
    }

    /// Refills the tree with `values` (contact `i` has `values[i]`), in O(n).
    pub fn fill(&mut self, values: impl ExactSizeIterator<Item = T>) {
        self.n = values.len();
        self.nodes.clear();
        let filler = Entry {
            key: T::zero(),
            contact: 0,
        };
        self.nodes.resize(self.n, filler);
        self.nodes.extend(values.enumerate().map(|(i, v)| Entry {
            key: Self::key(v),
            contact: i as u32,
        }));
        for p in (1..self.n).rev() {
            self.nodes[p] = Self::play(self.nodes[2 * p], self.nodes[2 * p + 1]);
        }
    }

    /// The first contact and its value.
    pub fn top(&self) -> Option<(usize, T)> {
        // Node 1 is the root (for one contact, its leaf).
        let root = self.nodes.get(1).filter(|_| self.n > 0)?;
        Some((root.contact as usize, root.key))
    }

    /// Sets contact `k`'s value and replays its path to the root.
    pub fn update(&mut self, k: usize, value: T) {
        let mut p = self.n + k;
        self.nodes[p].key = Self::key(value);
        p /= 2;
        while p >= 1 {
            let now = Self::play(self.nodes[2 * p], self.nodes[2 * p + 1]);
            // Higher matches only change if this one did.
            if now == self.nodes[p] {
                break;
            }
            self.nodes[p] = now;
            p /= 2;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::TournamentTree;

    /// The scan's choice: the first of the largest non-NaN values.
    fn scan(values: &[f64]) -> Option<(usize, f64)> {
        let mut best: Option<(usize, f64)> = None;
        for (i, &v) in values.iter().enumerate() {
            if !v.is_nan() && best.is_none_or(|(_, b)| v > b) {
                best = Some((i, v));
            }
        }
        best
    }

    #[test]
    fn largest_first_lowest_index_on_ties_nan_last() {
        let mut t = TournamentTree::<f64>::with_capacity(5);
        t.fill([0.5, 2.0, f64::NAN, 2.0, 1.0].into_iter());
        assert_eq!(t.top(), Some((1, 2.0)));
        t.update(1, 0.0);
        assert_eq!(t.top(), Some((3, 2.0)));
        t.update(0, 2.0);
        assert_eq!(t.top(), Some((0, 2.0)));
        t.update(0, -1.0);
        t.update(3, -1.0);
        assert_eq!(t.top(), Some((4, 1.0)));
        t.update(4, -5.0);
        t.update(1, -5.0);
        // NaN ranks below every number: contact 0 (−1) comes first.
        assert_eq!(t.top(), Some((0, -1.0)));
    }

    #[test]
    fn agrees_with_the_scan_under_many_updates() {
        for n in [1usize, 2, 3, 7, 8, 13, 64, 100] {
            let mut values: Vec<f64> = (0..n).map(|i| ((i * 37) % 11) as f64).collect();
            let mut t = TournamentTree::<f64>::with_capacity(n);
            t.fill(values.iter().copied());
            let mut x = 12345u64;
            for _ in 0..500 {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let k = (x >> 33) as usize % n;
                // Few distinct values, so ties are frequent.
                let v = ((x >> 13) % 7) as f64 - 2.0;
                values[k] = v;
                t.update(k, v);
                let top = t.top().map(|(k, v)| (k, v));
                assert_eq!(top, scan(&values), "n = {n}");
            }
        }
    }
}
