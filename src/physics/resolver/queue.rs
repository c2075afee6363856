//! The indexed resolver's priority queue: a tournament (winner) tree over
//! the contacts' values with the scan's tie rule — the largest value wins,
//! the lowest contact index among equal values. Leaves are the contacts
//! (padded to a power of two with unused leaves that never win); each inner
//! node holds the winner of its two children with its value, so the root is
//! the contact the scan would take. After an iteration changes some values,
//! [`TournamentTree::replay`] replays the matches above them level by level,
//! each match once however many of the changed contacts are below it, and
//! only where a result changed. A NaN value ranks below every number (the
//! scan never takes it). Storage is allocated once; filling, changing and
//! replaying allocate nothing.

use crate::physics::{c, Real};

/// A contact and its value, as a node of the tree holds its winner.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Entry<T> {
    key: T,
    contact: u32,
}

#[derive(Debug, Clone)]
pub struct TournamentTree<T: Real> {
    /// Contacts in use.
    n: usize,
    /// Leaf slots, a power of two ≥ n: leaf `i` is node `leaves + i`.
    leaves: usize,
    /// Node 1 is the root; node `p` holds the winner of nodes `2p`, `2p + 1`.
    nodes: Vec<Entry<T>>,
}

impl<T: Real> Default for TournamentTree<T> {
    /// An empty tree that has allocated nothing.
    fn default() -> Self {
        TournamentTree {
            n: 0,
            leaves: 1,
            nodes: Vec::new(),
        }
    }
}

impl<T: Real> TournamentTree<T> {
    pub fn with_capacity(n: usize) -> Self {
        let mut t = Self::default();
        t.reserve(n);
        t
    }

    /// Room for `n` contacts (allocates only if there is less).
    pub fn reserve(&mut self, n: usize) {
        assert!(n < u32::MAX as usize, "contacts are numbered in 32 bits");
        let need = 2 * n.next_power_of_two();
        self.nodes.reserve(need.saturating_sub(self.nodes.len()));
    }

    #[inline(always)]
    pub(super) fn key(x: T) -> T {
        // NaN (the one value not above -inf, bar -inf itself) ranks as -inf;
        // `x > -inf ? x : -inf` is one `maxsd`.
        let lowest = -c::<T>(f64::INFINITY);
        if x > lowest {
            x
        } else {
            lowest
        }
    }

    /// The winner of two entries: the larger value, the lower contact on ties
    /// (an unused leaf has the largest contact number and the lowest value).
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
        self.leaves = self.n.next_power_of_two();
        let unused = Entry {
            key: -c::<T>(f64::INFINITY),
            contact: u32::MAX,
        };
        self.nodes.clear();
        self.nodes.resize(self.leaves, unused);
        self.nodes.extend(values.enumerate().map(|(i, v)| Entry {
            key: Self::key(v),
            contact: i as u32,
        }));
        self.nodes.resize(2 * self.leaves, unused);
        for p in (1..self.leaves).rev() {
            self.nodes[p] = Self::play(self.nodes[2 * p], self.nodes[2 * p + 1]);
        }
    }

    /// The first contact and its value.
    pub fn top(&self) -> Option<(usize, T)> {
        // Node 1 is the root (for one contact, its leaf).
        let root = self.nodes.get(1)?;
        (self.n > 0).then_some((root.contact as usize, root.key))
    }

    /// Sets contact `k`'s value; the matches above it are replayed by
    /// [`TournamentTree::replay`].
    pub fn set(&mut self, k: usize, value: T) {
        self.nodes[self.leaves + k].key = Self::key(value);
    }

    /// Replays the matches above the contacts `changed` (their values set
    /// with [`TournamentTree::set`]), sorted ascending and without repeats;
    /// `changed` is used as scratch.
    pub fn replay(&mut self, changed: &mut [usize]) {
        // Leaves are all at one depth, so one level's nodes are never
        // ancestors of each other: replay level by level, bottom up.
        let mut len = 0;
        for i in 0..changed.len() {
            let p = (self.leaves + changed[i]) / 2;
            if len == 0 || changed[len - 1] != p {
                changed[len] = p;
                len += 1;
            }
        }
        while len > 0 {
            let mut next = 0;
            for i in 0..len {
                let p = changed[i];
                let now = Self::play(self.nodes[2 * p], self.nodes[2 * p + 1]);
                // Higher matches only change if this one did.
                if now != self.nodes[p] {
                    self.nodes[p] = now;
                    let q = p / 2;
                    if q >= 1 && (next == 0 || changed[next - 1] != q) {
                        changed[next] = q;
                        next += 1;
                    }
                }
            }
            len = next;
        }
    }

    /// Sets contact `k`'s value and replays the matches above it.
    pub fn update(&mut self, k: usize, value: T) {
        self.set(k, value);
        self.replay(&mut [k]);
    }
}

/// What the indexed resolver asks of its priority queue: refill, the first
/// contact (largest value, lowest index on ties, NaN last), set a value,
/// and bring the order up to date after a batch of sets.
pub trait Queue<T: Real> {
    /// Whether [`Queue::replay`] needs the changed contacts (the scan queue
    /// does not: nothing to replay, so the loop need not list them).
    const REPLAYS: bool = true;
    fn fill(&mut self, values: impl ExactSizeIterator<Item = T>);
    fn top(&self) -> Option<(usize, T)>;
    fn set(&mut self, k: usize, value: T);
    /// `changed`: the contacts set since the last replay, without repeats
    /// (used as scratch).
    fn replay(&mut self, changed: &mut [usize]);
}

impl<T: Real> Queue<T> for TournamentTree<T> {
    fn fill(&mut self, values: impl ExactSizeIterator<Item = T>) {
        TournamentTree::fill(self, values)
    }
    fn top(&self) -> Option<(usize, T)> {
        TournamentTree::top(self)
    }
    fn set(&mut self, k: usize, value: T) {
        TournamentTree::set(self, k, value)
    }
    fn replay(&mut self, changed: &mut [usize]) {
        changed.sort_unstable();
        TournamentTree::replay(self, changed)
    }
}

/// Below [`SCAN_BELOW`] contacts a scan of the values, kept side by side,
/// finds the first contact faster than replaying the tree's matches: the
/// same order (largest first, lowest index on ties, NaN last), with nothing
/// to replay.
pub const SCAN_BELOW: usize = 64;

#[derive(Debug, Clone)]
pub struct ScanQueue<T: Real> {
    keys: Vec<T>,
}

impl<T: Real> Default for ScanQueue<T> {
    /// An empty queue that has allocated nothing.
    fn default() -> Self {
        ScanQueue { keys: Vec::new() }
    }
}

impl<T: Real> ScanQueue<T> {
    pub fn reserve(&mut self, n: usize) {
        self.keys.reserve(n.saturating_sub(self.keys.len()));
    }
}

impl<T: Real> Queue<T> for ScanQueue<T> {
    const REPLAYS: bool = false;
    fn fill(&mut self, values: impl ExactSizeIterator<Item = T>) {
        self.keys.clear();
        self.keys.extend(values.map(TournamentTree::key));
    }
    #[inline(always)]
    fn top(&self) -> Option<(usize, T)> {
        // Two short passes instead of one with a branch per key: the largest
        // value (keys hold no NaN), then the first key equal to it, which is
        // the first of the largest (the same contact as one pass taking a
        // key only when strictly larger; -0 and +0 are equal both ways).
        let first = *self.keys.first()?;
        // Four running maxima side by side: the largest value is the same
        // whatever the order of the comparisons (no NaN), but -0 and +0
        // may come out either way, which the second pass does not mind.
        let mut lanes = [first; 4];
        let chunks = self.keys.chunks_exact(4);
        let rest = chunks.remainder();
        for chunk in chunks {
            for (m, k) in lanes.iter_mut().zip(chunk) {
                *m = if *k > *m { *k } else { *m };
            }
        }
        let most = |a: T, b: T| if b > a { b } else { a };
        let largest = rest.iter().fold(
            most(most(lanes[0], lanes[1]), most(lanes[2], lanes[3])),
            |m, k| most(m, *k),
        );
        // The first key equal to it, without a branch per key (where it
        // lies comes and goes, so a search's exit would be mispredicted):
        // the first 64 keys' equality as bits of a mask, its lowest set bit;
        // past them (never below `SCAN_BELOW` contacts) a search.
        let mut equal = 0u64;
        for (i, k) in self.keys.iter().enumerate().take(64) {
            equal |= u64::from(*k == largest) << i;
        }
        let best = if equal != 0 {
            equal.trailing_zeros() as usize
        } else {
            64 + self.keys.get(64..)?.iter().position(|k| *k == largest)?
        };
        Some((best, self.keys[best]))
    }
    fn set(&mut self, k: usize, value: T) {
        self.keys[k] = TournamentTree::key(value);
    }
    fn replay(&mut self, _changed: &mut [usize]) {}
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
        // NaN ranks below every number: contact 0 (-1) comes first.
        assert_eq!(t.top(), Some((0, -1.0)));
    }

    #[test]
    fn a_batch_replay_is_the_same_as_one_update_at_a_time() {
        let n = 37;
        let values: Vec<f64> = (0..n).map(|i| ((i * 13) % 7) as f64).collect();
        let mut one = TournamentTree::<f64>::with_capacity(n);
        let mut batch = TournamentTree::<f64>::with_capacity(n);
        one.fill(values.iter().copied());
        batch.fill(values.iter().copied());
        let mut x = 99u64;
        for _ in 0..300 {
            let mut changed: Vec<usize> = (0..6)
                .map(|_| {
                    x = x
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    (x >> 33) as usize % n
                })
                .collect();
            changed.sort_unstable();
            changed.dedup();
            for &k in &changed {
                let v = ((x >> 7) % 9) as f64 - (k % 3) as f64;
                one.update(k, v);
                batch.set(k, v);
            }
            batch.replay(&mut changed);
            assert_eq!(one.top(), batch.top());
            assert_eq!(one.nodes, batch.nodes);
        }
    }

    #[test]
    fn the_scan_queue_and_the_tree_take_the_same_contact() {
        use super::{Queue, ScanQueue};
        for n in [1usize, 2, 5, 24, 63] {
            let values: Vec<f64> = (0..n).map(|i| ((i * 37) % 11) as f64).collect();
            let mut tree = TournamentTree::<f64>::with_capacity(n);
            let mut queue = ScanQueue::<f64>::default();
            Queue::fill(&mut tree, values.iter().copied());
            Queue::fill(&mut queue, values.iter().copied());
            let mut x = 777u64;
            for step in 0..500 {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let k = (x >> 33) as usize % n;
                // Few distinct values (ties), and now and then a NaN.
                let v = if step % 17 == 0 {
                    f64::NAN
                } else {
                    ((x >> 13) % 7) as f64 - 2.0
                };
                Queue::set(&mut tree, k, v);
                Queue::set(&mut queue, k, v);
                Queue::replay(&mut tree, &mut [k]);
                Queue::replay(&mut queue, &mut [k]);
                assert_eq!(Queue::top(&tree), Queue::top(&queue), "n = {n}");
            }
        }
    }

    /// The scan queue's passes (four running maxima and the rest, then the
    /// first 64 keys' mask and a search past them) give the first of the
    /// largest wherever it lies, signed zeros as equals.
    #[test]
    fn the_scan_queue_finds_the_first_of_the_largest_anywhere() {
        use super::{Queue, ScanQueue};
        for n in (1..14usize).chain([63, 64, 65, 70, 130]) {
            for at in 0..n {
                for top in [1.0, 0.0, -0.0] {
                    // The largest value at `at` and again after it.
                    let values: Vec<f64> = (0..n)
                        .map(|i| if i == at || i == n - 1 { top } else { -2.0 })
                        .collect();
                    let mut queue = ScanQueue::<f64>::default();
                    Queue::fill(&mut queue, values.iter().copied());
                    let (k, v) = Queue::top(&queue).unwrap();
                    assert_eq!((k, v.to_bits()), (at, top.to_bits()), "{values:?}");
                    assert_eq!(scan(&values).map(|(i, _)| i), Some(at));
                }
            }
        }
        // -0 first, +0 after it: the first.
        let mut queue = ScanQueue::<f64>::default();
        Queue::fill(&mut queue, [-1.0, -0.0, 0.0, -0.0, 0.0, -3.0].into_iter());
        assert_eq!(
            Queue::top(&queue).map(|(k, v)| (k, v.to_bits())),
            Some((1, (-0.0f64).to_bits()))
        );
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
                assert_eq!(t.top(), scan(&values), "n = {n}");
            }
        }
    }
}
