//! The sort and sweep of the broad phase ([`super::broad`]): boxes sorted
//! by their low end on the axis of largest spread (the last sweep's order
//! kept: an insertion sort of an almost sorted list), each box paired with
//! the later boxes that start before it ends and overlap it on the other
//! two axes; the pairs sorted by a counting sort.

use super::bounds::{push_half_space_pairs, Bounds};

/// The sweep's buffers.
#[derive(Debug, Clone, Default)]
pub(super) struct Sweep {
    /// The bounds (as f64, side by side for the sweep), sorted by `min[axis]`.
    entries: Vec<Entry>,
    axis: usize,
    /// Scratch for sorting the pairs.
    counts: Vec<usize>,
    scratch: Vec<(usize, usize)>,
    /// Box-against-box tests the last sweep made (boxes that start before
    /// the current one ends, compared on the other two axes).
    pub(super) tests: usize,
}

#[derive(Debug, Clone, Copy)]
struct Entry {
    min: [f64; 3],
    max: [f64; 3],
    index: usize,
}

impl Entry {
    fn new(index: usize, b: &Bounds) -> Self {
        Entry {
            min: b.min,
            max: b.max,
            index,
        }
    }
}

impl Sweep {
    /// Replaces `out` with the pairs of `boxes` that overlap or touch and
    /// the half-space pairs, sorted (sort and sweep).
    pub(super) fn pairs(
        &mut self,
        boxes: &[Option<Bounds>],
        half_spaces: &[usize],
        out: &mut Vec<(usize, usize)>,
    ) {
        out.clear();
        let axis = spread_axis(boxes);
        let count = boxes.iter().flatten().count();
        let coherent = axis == self.axis
            && self.entries.len() == count
            && self
                .entries
                .iter()
                .all(|e| boxes.get(e.index).is_some_and(Option::is_some));
        if coherent {
            for entry in &mut self.entries {
                let b = boxes[entry.index].as_ref().expect("checked above");
                *entry = Entry::new(entry.index, b);
            }
        } else {
            self.entries.clear();
            let finite = boxes
                .iter()
                .enumerate()
                .filter_map(|(i, b)| Some(Entry::new(i, b.as_ref()?)));
            self.entries.extend(finite);
            self.axis = axis;
        }
        let order = |p: &Entry, q: &Entry| {
            p.min[axis]
                .total_cmp(&q.min[axis])
                .then(p.index.cmp(&q.index))
        };
        // Last step's order is almost this one's: an insertion sort costs
        // O(n + swaps) (the order is total, so the result is the same).
        // A scene that scattered (more than 8 moves per box) sorts anew.
        let limit = 8 * self.entries.len();
        if !(coherent && insertion_sort_by(&mut self.entries, order, limit)) {
            self.entries.sort_unstable_by(order);
        }
        // Sweep: each box meets the later boxes that start before it ends;
        // of those, the ones that overlap on the other two axes too.
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        self.tests = 0;
        for (k, a) in self.entries.iter().enumerate() {
            for b in &self.entries[k + 1..] {
                if b.min[axis] > a.max[axis] {
                    break;
                }
                self.tests += 1;
                let across = |w: usize| a.min[w] <= b.max[w] && b.min[w] <= a.max[w];
                if across(u) && across(v) {
                    out.push((a.index.min(b.index), a.index.max(b.index)));
                }
            }
        }
        push_half_space_pairs(boxes, half_spaces, out);
        sort_pairs(out, boxes.len(), &mut self.counts, &mut self.scratch);
    }
}

/// Sorts pairs (i, j), i < `bodies`, by i then j and drops repeats: a
/// counting sort on i, O(pairs + bodies), then each run of one i by j (a
/// comparison sort of all the pairs cost a third of the sweep for 2,000
/// bodies).
pub(super) fn sort_pairs(
    pairs: &mut Vec<(usize, usize)>,
    bodies: usize,
    counts: &mut Vec<usize>,
    scratch: &mut Vec<(usize, usize)>,
) {
    counts.clear();
    counts.resize(bodies + 1, 0);
    for &(i, _) in pairs.iter() {
        counts[i + 1] += 1;
    }
    for k in 1..=bodies {
        counts[k] += counts[k - 1];
    }
    // counts[i] is where the run of i starts; after the scatter, where it ends.
    scratch.clear();
    scratch.resize(pairs.len(), (0, 0));
    for &pair in pairs.iter() {
        scratch[counts[pair.0]] = pair;
        counts[pair.0] += 1;
    }
    let mut start = 0;
    for &end in &counts[..bodies] {
        scratch[start..end].sort_unstable();
        start = end;
    }
    std::mem::swap(pairs, scratch);
    pairs.dedup();
}

/// Sorts `items` by `order` moving each item left past the larger ones:
/// O(n + inversions), for short or almost sorted slices. False (the slice
/// left a permutation, not sorted) once more than `limit` moves were made.
pub(super) fn insertion_sort_by<E: Copy>(
    items: &mut [E],
    order: impl Fn(&E, &E) -> std::cmp::Ordering,
    limit: usize,
) -> bool {
    let mut moves = 0;
    for i in 1..items.len() {
        let item = items[i];
        let mut j = i;
        while j > 0 && order(&items[j - 1], &item) == std::cmp::Ordering::Greater {
            items[j] = items[j - 1];
            j -= 1;
        }
        items[j] = item;
        moves += i - j;
        if moves > limit {
            return false;
        }
    }
    true
}

/// World axis along which the box centres spread most (first on ties).
fn spread_axis(bounds: &[Option<Bounds>]) -> usize {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for b in bounds.iter().flatten() {
        for k in 0..3 {
            let centre = b.min[k] + b.max[k];
            low[k] = low[k].min(centre);
            high[k] = high[k].max(centre);
        }
    }
    let spread = |k: usize| high[k] - low[k];
    (1..3).fold(0, |best, k| if spread(k) > spread(best) { k } else { best })
}
