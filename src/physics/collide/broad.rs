//! Broad phase: axis-aligned bounding boxes and sort-and-sweep on the axis of
//! largest spread, so that 2,000 bodies are not tested all against all.

use nalgebra::Vector3;

use super::{c, Pose, Real, Shape};
use crate::physics::to_f64;

/// Axis-aligned bounding box in world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb<T: Real> {
    pub min: Vector3<T>,
    pub max: Vector3<T>,
}

impl<T: Real> Aabb<T> {
    /// The box from `centre - half` to `centre + half`.
    pub fn around(centre: &Vector3<T>, half: &Vector3<T>) -> Self {
        Aabb {
            min: centre - half,
            max: centre + half,
        }
    }

    /// Bounds of a shape at a pose, grown by `margin` on every side; `None`
    /// for a half-space (unbounded).
    pub fn of(shape: &Shape, pose: &Pose<T>, margin: T) -> Option<Self> {
        let r = &pose.rotation;
        let half = match *shape {
            Shape::Sphere { radius } | Shape::HollowSphere { radius } => Vector3::repeat(c(radius)),
            // Half extent along world axis k: Σ_j |R_kj| h_j.
            Shape::Box { sides } => Vector3::from_fn(|k, _| {
                (0..3).fold(T::zero(), |sum, j| {
                    sum + r[(k, j)].abs() * c::<T>(sides[j] / 2.0)
                })
            }),
            // Axis a = body y: |a_k| h/2 + radius·√(1 - a_k²) (the cap discs).
            Shape::Cylinder { radius, height } => Vector3::from_fn(|k, _| {
                let a = r[(k, 1)];
                a.abs() * c::<T>(height / 2.0)
                    + c::<T>(radius) * (T::one() - a * a).max(T::zero()).sqrt()
            }),
            // Axis a = body y: |a_k| h/2 + radius (the end balls).
            Shape::Capsule { radius, height } => {
                Vector3::from_fn(|k, _| r[(k, 1)].abs() * c::<T>(height / 2.0) + c::<T>(radius))
            }
            // Hull: half extent along world axis k = max over vertices of |(R v)_k|.
            Shape::Hull(ref hull) => hull.vertices().iter().fold(Vector3::zeros(), |m, v| {
                let w = r * v.map(c::<T>);
                m.sup(&w.abs())
            }),
            Shape::HalfSpace { .. } => return None,
        };
        Some(Aabb::around(&pose.position, &half.add_scalar(margin)))
    }

    /// True when the boxes overlap or touch.
    pub fn overlaps(&self, other: &Self) -> bool {
        (0..3).all(|k| self.min[k] <= other.max[k] && other.min[k] <= self.max[k])
    }
}

/// Sort-and-sweep state. The order of the last sweep is kept, so that a
/// scene that moved a little sorts an almost sorted list; the buffers are
/// reused from call to call.
#[derive(Debug, Clone, Default)]
pub struct BroadPhase {
    /// The bounds (as f64, side by side for the sweep), sorted by `min[axis]`.
    entries: Vec<Entry>,
    axis: usize,
    /// Scratch for sorting the pairs.
    counts: Vec<usize>,
    scratch: Vec<(usize, usize)>,
}

#[derive(Debug, Clone, Copy)]
struct Entry {
    min: [f64; 3],
    max: [f64; 3],
    index: usize,
}

impl Entry {
    fn new<T: Real>(index: usize, b: &Aabb<T>) -> Self {
        Entry {
            min: [0, 1, 2].map(|k| to_f64(b.min[k])),
            max: [0, 1, 2].map(|k| to_f64(b.max[k])),
            index,
        }
    }
}

impl BroadPhase {
    pub fn new() -> Self {
        Self::default()
    }

    /// Replaces `out` with the candidate pairs (i, j), i < j, sorted: every
    /// two bodies with bounds whose boxes overlap or touch, and every body
    /// with bounds paired with every half-space in `half_spaces`. Bodies with
    /// `None` bounds and not in `half_spaces` (no shape) take part in nothing.
    /// Pairs of immovable bodies are the caller's to skip.
    pub fn candidate_pairs<T: Real>(
        &mut self,
        bounds: &[Option<Aabb<T>>],
        half_spaces: &[usize],
        out: &mut Vec<(usize, usize)>,
    ) {
        out.clear();
        let axis = spread_axis(bounds);
        let count = bounds.iter().flatten().count();
        let coherent = axis == self.axis
            && self.entries.len() == count
            && self
                .entries
                .iter()
                .all(|e| bounds.get(e.index).is_some_and(Option::is_some));
        if coherent {
            for entry in &mut self.entries {
                let b = bounds[entry.index].as_ref().expect("checked above");
                *entry = Entry::new(entry.index, b);
            }
        } else {
            self.entries.clear();
            let finite = bounds
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
        for (k, a) in self.entries.iter().enumerate() {
            for b in &self.entries[k + 1..] {
                if b.min[axis] > a.max[axis] {
                    break;
                }
                let across = |w: usize| a.min[w] <= b.max[w] && b.min[w] <= a.max[w];
                if across(u) && across(v) {
                    out.push((a.index.min(b.index), a.index.max(b.index)));
                }
            }
        }
        push_half_space_pairs(bounds, half_spaces, out);
        sort_pairs(out, bounds.len(), &mut self.counts, &mut self.scratch);
    }
}

/// Sorts pairs (i, j), i < `bodies`, by i then j and drops repeats: a
/// counting sort on i, O(pairs + bodies), then each run of one i by j (a
/// comparison sort of all the pairs cost a third of the sweep for 2,000
/// bodies).
fn sort_pairs(
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
fn insertion_sort_by<E: Copy>(
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

/// [`BroadPhase::candidate_pairs`] with a fresh state (allocates).
pub fn candidate_pairs<T: Real>(
    bounds: &[Option<Aabb<T>>],
    half_spaces: &[usize],
    out: &mut Vec<(usize, usize)>,
) {
    BroadPhase::new().candidate_pairs(bounds, half_spaces, out);
}

/// The same pairs by testing every two bounds (the O(n²) reference).
pub fn all_pairs<T: Real>(
    bounds: &[Option<Aabb<T>>],
    half_spaces: &[usize],
    out: &mut Vec<(usize, usize)>,
) {
    out.clear();
    for i in 0..bounds.len() {
        for j in i + 1..bounds.len() {
            if overlap(bounds, i, j) {
                out.push((i, j));
            }
        }
    }
    push_half_space_pairs(bounds, half_spaces, out);
    out.sort_unstable();
    out.dedup();
}

fn overlap<T: Real>(bounds: &[Option<Aabb<T>>], i: usize, j: usize) -> bool {
    matches!((&bounds[i], &bounds[j]), (Some(a), Some(b)) if a.overlaps(b))
}

/// Adds (body, half-space) for every body with bounds.
fn push_half_space_pairs<T: Real>(
    bounds: &[Option<Aabb<T>>],
    half_spaces: &[usize],
    out: &mut Vec<(usize, usize)>,
) {
    for (i, _) in bounds.iter().enumerate().filter(|(_, b)| b.is_some()) {
        for &h in half_spaces.iter().filter(|&&h| h != i) {
            out.push((i.min(h), i.max(h)));
        }
    }
}

/// World axis along which the box centres spread most (first on ties).
fn spread_axis<T: Real>(bounds: &[Option<Aabb<T>>]) -> usize {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for b in bounds.iter().flatten() {
        for k in 0..3 {
            let centre = to_f64(b.min[k]) + to_f64(b.max[k]);
            low[k] = low[k].min(centre);
            high[k] = high[k].max(centre);
        }
    }
    let spread = |k: usize| high[k] - low[k];
    (1..3).fold(0, |best, k| if spread(k) > spread(best) { k } else { best })
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::UnitQuaternion;

    fn cube(x: f64, y: f64) -> Option<Aabb<f64>> {
        Some(Aabb::around(
            &Vector3::new(x, y, 0.0),
            &Vector3::repeat(0.5),
        ))
    }

    #[test]
    fn sweep_finds_touching_and_overlapping_boxes_only() {
        // 0–1 touch on x, 1–2 overlap, 3 is far, 4 has no shape, 5 is a floor.
        let bounds = [
            cube(0.0, 0.0),
            cube(1.0, 0.0),
            cube(1.5, 0.2),
            cube(9.0, 0.0),
            None,
            None,
        ];
        let mut out = Vec::new();
        candidate_pairs(&bounds, &[5], &mut out);
        assert_eq!(out, [(0, 1), (0, 5), (1, 2), (1, 5), (2, 5), (3, 5)]);
        let mut reference = Vec::new();
        all_pairs(&bounds, &[5], &mut reference);
        assert_eq!(out, reference);
    }

    #[test]
    fn a_kept_order_sorted_again_finds_the_same_pairs_as_all_against_all() {
        // A row of boxes, then the same row moved a little (a few swap
        // places: the insertion sort), then scattered (too many moves: sorted anew).
        let row = |shift: &dyn Fn(usize) -> f64| -> Vec<_> {
            (0..40)
                .map(|i| cube(i as f64 * 0.7 + shift(i), (i % 3) as f64 * 0.4))
                .collect()
        };
        let mut broad = BroadPhase::new();
        let (mut out, mut reference) = (Vec::new(), Vec::new());
        let shifts: [&dyn Fn(usize) -> f64; 3] =
            [&|_| 0.0, &|i| if i % 5 == 0 { 0.9 } else { 0.0 }, &|i| {
                ((i * 17) % 40) as f64 * 0.9 - i as f64 * 0.7
            }];
        for shift in shifts {
            let bounds = row(shift);
            broad.candidate_pairs(&bounds, &[], &mut out);
            all_pairs(&bounds, &[], &mut reference);
            assert_eq!(out, reference);
            assert!(!out.is_empty());
        }
        let mut items = [5, 1, 4, 1, 3];
        assert!(insertion_sort_by(&mut items, |a, b| a.cmp(b), 10));
        assert_eq!(items, [1, 1, 3, 4, 5]);
        let mut backwards: Vec<usize> = (0..10).rev().collect();
        assert!(!insertion_sort_by(&mut backwards, |a, b| a.cmp(b), 8));
    }

    #[test]
    fn empty_and_single_sets() {
        let mut out = vec![(7, 8)];
        candidate_pairs::<f64>(&[], &[], &mut out);
        assert!(out.is_empty());
        candidate_pairs(&[cube(0.0, 0.0)], &[], &mut out);
        assert!(out.is_empty());
    }

    #[test]
    fn bounds_of_turned_shapes() {
        let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4);
        let pose = Pose::from_unit(Vector3::zeros(), &turn);
        let b = Aabb::of(
            &Shape::Box {
                sides: [2.0, 2.0, 4.0],
            },
            &pose,
            0.0,
        )
        .unwrap();
        assert!((b.max - Vector3::new(2f64.sqrt(), 2f64.sqrt(), 2.0)).norm() < 1e-15);
        // A cylinder lying along world -x after a quarter turn about z.
        let side = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2);
        let lying = Pose::from_unit(Vector3::zeros(), &side);
        let can = Shape::Cylinder {
            radius: 0.5,
            height: 3.0,
        };
        let b = Aabb::of(&can, &lying, 0.1).unwrap();
        assert!((b.max - Vector3::new(1.6, 0.6, 0.6)).norm() < 1e-12);
        assert!(Aabb::of(
            &Shape::HalfSpace {
                normal: [0.0, 1.0, 0.0]
            },
            &pose,
            0.0
        )
        .is_none());
    }
}
