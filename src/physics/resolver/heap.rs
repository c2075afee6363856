//! An indexed binary max-heap over contact values with the scan's tie rule:
//! the largest value first, the lowest contact index among equal values.
//! A value that is NaN ranks below everything (the scan never takes it).
//! Storage is allocated once; filling and updating allocate nothing.

use crate::physics::{c, Real};

#[derive(Debug, Clone)]
pub struct IndexedHeap<T: Real> {
    /// Heap order: contact indices.
    order: Vec<usize>,
    /// Where each contact sits in `order`.
    slot: Vec<usize>,
    keys: Vec<T>,
}

impl<T: Real> Default for IndexedHeap<T> {
    fn default() -> Self {
        Self::with_capacity(0)
    }
}

impl<T: Real> IndexedHeap<T> {
    pub fn with_capacity(n: usize) -> Self {
        IndexedHeap {
            order: Vec::with_capacity(n),
            slot: Vec::with_capacity(n),
            keys: Vec::with_capacity(n),
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

    /// True when contact `a` comes before contact `b`.
    fn before(&self, a: usize, b: usize) -> bool {
        let (ka, kb) = (self.keys[a], self.keys[b]);
        ka > kb || (ka == kb && a < b)
    }

    /// Refills the heap with `values` (contact `i` has `values[i]`), in O(n).
    pub fn fill(&mut self, values: impl Iterator<Item = T>) {
        self.keys.clear();
        self.keys.extend(values.map(Self::key));
        let n = self.keys.len();
        self.order.clear();
        self.order.extend(0..n);
        self.slot.clear();
        self.slot.extend(0..n);
        for i in (0..n / 2).rev() {
            self.sift_down(i);
        }
    }

    /// The first contact and its value.
    pub fn top(&self) -> Option<(usize, T)> {
        self.order.first().map(|&k| (k, self.keys[k]))
    }

    /// Sets contact `k`'s value and restores the heap order.
    pub fn update(&mut self, k: usize, value: T) {
        let old = self.keys[k];
        let value = Self::key(value);
        self.keys[k] = value;
        let at = self.slot[k];
        if value > old {
            self.sift_up(at);
        } else if value < old {
            self.sift_down(at);
        }
    }

    fn swap(&mut self, i: usize, j: usize) {
        self.order.swap(i, j);
        self.slot[self.order[i]] = i;
        self.slot[self.order[j]] = j;
    }

    fn sift_up(&mut self, mut i: usize) {
        while i > 0 {
            let parent = (i - 1) / 2;
            if self.before(self.order[i], self.order[parent]) {
                self.swap(i, parent);
                i = parent;
            } else {
                break;
            }
        }
    }

    fn sift_down(&mut self, mut i: usize) {
        let n = self.order.len();
        loop {
            let (l, r) = (2 * i + 1, 2 * i + 2);
            let mut best = i;
            if l < n && self.before(self.order[l], self.order[best]) {
                best = l;
            }
            if r < n && self.before(self.order[r], self.order[best]) {
                best = r;
            }
            if best == i {
                break;
            }
            self.swap(i, best);
            i = best;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::IndexedHeap;

    #[test]
    fn largest_first_lowest_index_on_ties_nan_last() {
        let mut h = IndexedHeap::<f64>::with_capacity(5);
        h.fill([0.5, 2.0, f64::NAN, 2.0, 1.0].into_iter());
        assert_eq!(h.top(), Some((1, 2.0)));
        h.update(1, 0.0);
        assert_eq!(h.top(), Some((3, 2.0)));
        h.update(0, 2.0);
        assert_eq!(h.top(), Some((0, 2.0)));
        h.update(0, -1.0);
        h.update(3, -1.0);
        assert_eq!(h.top(), Some((4, 1.0)));
        h.update(4, -5.0);
        h.update(1, -5.0);
        // NaN ranks below every number: contact 0 (−1) comes first.
        assert_eq!(h.top(), Some((0, -1.0)));
    }
}
