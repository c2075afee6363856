//! Broad phase: axis-aligned bounding boxes and sort-and-sweep on the axis of
//! largest spread, so that 2,000 bodies are not tested all against all.

use nalgebra::Vector3;

use super::bounds::{push_half_space_pairs, Bounds};
use super::sweep::Sweep;
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
            // Mesh: the same over its vertices (the box of its hull).
            Shape::Mesh(ref mesh) => mesh.vertices().iter().fold(Vector3::zeros(), |m, v| {
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

/// Sort-and-sweep state, kept from call to call so that a scene that moved
/// a little costs little:
///
/// - the pairs are kept between calls for boxes grown by a margin (5 % of
///   each box's smallest half extent): while every box stays inside its
///   grown box, two boxes that overlap had grown boxes that overlap, so the
///   kept pairs whose boxes overlap now are exactly the sweep's pairs, in
///   the same (sorted) order — O(n + kept pairs), nothing sorted;
/// - when a box leaves its grown box, the grown boxes are made anew and
///   swept, the order of the last sweep kept (an almost sorted list sorts
///   in O(n + swaps)); the buffers are reused.
#[derive(Debug, Clone, Default)]
pub struct BroadPhase {
    sweep: Sweep,
    /// This call's boxes as f64 (what the sweep compares).
    exact: Vec<Option<Bounds>>,
    /// The grown boxes and their pairs (`valid` false: none kept).
    kept: Kept,
    /// Box-against-box tests the last call made: the sweep's, when it swept,
    /// and each kept pair's box test.
    pub(super) tests: usize,
    /// Whether the last call swept (false: the kept pairs were filtered).
    pub(super) swept: bool,
}

/// The grown boxes of the last sweep and its pairs.
#[derive(Debug, Clone, Default)]
struct Kept {
    valid: bool,
    grown: Vec<Option<Bounds>>,
    half_spaces: Vec<usize>,
    /// Whether body i is one of `half_spaces`.
    is_half: Vec<bool>,
    pairs: Vec<(usize, usize)>,
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
        self.exact.clear();
        self.exact
            .extend(bounds.iter().map(|b| b.as_ref().map(bounds_of)));
        self.tests = 0;
        self.swept = !self.kept_holds(half_spaces);
        if self.swept {
            self.keep(half_spaces);
            if self.kept.valid {
                self.tests += self.sweep.tests;
            }
        }
        out.clear();
        if !self.kept.valid {
            // Not finite: the sweep over the boxes themselves.
            self.sweep.pairs(&self.exact, half_spaces, out);
            self.tests += self.sweep.tests;
            return;
        }
        let (exact, is_half) = (&self.exact, &self.kept.is_half);
        out.reserve(self.kept.pairs.len());
        for &(i, j) in &self.kept.pairs {
            // Boxes that overlap, or a body with bounds and a half-space.
            let keep = match (&exact[i], &exact[j]) {
                (Some(_), Some(_)) if is_half[i] || is_half[j] => true,
                (Some(a), Some(b)) => {
                    self.tests += 1;
                    a.overlaps(b)
                }
                (Some(_), None) => is_half[j],
                (None, Some(_)) => is_half[i],
                (None, None) => false,
            };
            if keep {
                out.push((i, j));
            }
        }
    }

    /// Whether the kept pairs serve this call: the same bodies with bounds,
    /// the same half-spaces, every box inside its grown box.
    fn kept_holds(&self, half_spaces: &[usize]) -> bool {
        let kept = &self.kept;
        kept.valid
            && kept.grown.len() == self.exact.len()
            && kept.half_spaces == half_spaces
            && (kept.grown.iter().zip(&self.exact)).all(|(g, e)| match (g, e) {
                (Some(g), Some(e)) => g.holds(e),
                (None, None) => true,
                _ => false,
            })
    }

    /// Grows this call's boxes and sweeps them: the kept pairs (invalid
    /// when a box is not finite).
    fn keep(&mut self, half_spaces: &[usize]) {
        let kept = &mut self.kept;
        kept.grown.clear();
        kept.valid = true;
        for e in &self.exact {
            let g = match e {
                Some(e) => e.grown(),
                None => None,
            };
            kept.valid &= g.is_some() == e.is_some();
            kept.grown.push(g);
        }
        kept.half_spaces.clear();
        kept.half_spaces.extend_from_slice(half_spaces);
        kept.is_half.clear();
        kept.is_half.resize(self.exact.len(), false);
        for &h in half_spaces {
            kept.valid &= h < self.exact.len();
            if let Some(flag) = kept.is_half.get_mut(h) {
                *flag = true;
            }
        }
        if kept.valid {
            self.sweep.pairs(&kept.grown, half_spaces, &mut kept.pairs);
        }
    }
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

/// A box as f64.
pub(super) fn bounds_of<T: Real>(b: &Aabb<T>) -> Bounds {
    Bounds {
        min: [0, 1, 2].map(|k| to_f64(b.min[k])),
        max: [0, 1, 2].map(|k| to_f64(b.max[k])),
    }
}

fn overlap<T: Real>(bounds: &[Option<Aabb<T>>], i: usize, j: usize) -> bool {
    matches!((&bounds[i], &bounds[j]), (Some(a), Some(b)) if a.overlaps(b))
}

#[cfg(test)]
mod tests {
    use super::super::sweep::insertion_sort_by;
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
    fn kept_pairs_of_grown_boxes_are_the_sweeps_pairs_while_boxes_jitter_leave_and_break() {
        // A 6 × 6 grid of touching cubes and a floor (36), jittered a little
        // each call (inside the grown boxes: the kept pairs are filtered),
        // then one cube moved away (a box leaves: grown and swept anew),
        // then a non-finite box (swept as given, nothing kept).
        let grid = |jitter: f64, call: usize| -> Vec<Option<Aabb<f64>>> {
            let mut b: Vec<_> = (0..36)
                .map(|i| {
                    let wobble = jitter * (((i * 7 + call * 3) % 5) as f64 - 2.0);
                    cube((i % 6) as f64 + wobble, (i / 6) as f64 - wobble)
                })
                .collect();
            b.push(None);
            b
        };
        let mut broad = BroadPhase::new();
        let (mut out, mut reference) = (Vec::new(), Vec::new());
        let check = |broad: &mut BroadPhase, bounds: &[Option<Aabb<f64>>], out: &mut Vec<_>| {
            let mut reference = Vec::new();
            broad.candidate_pairs(bounds, &[36], out);
            all_pairs(bounds, &[36], &mut reference);
            assert_eq!(*out, reference);
        };
        for call in 0..6 {
            check(&mut broad, &grid(0.002 * call as f64, call), &mut out);
            assert!(broad.kept.valid);
        }
        // Touching neighbours come and go with the jitter; the floor pairs stay.
        assert!(out.contains(&(0, 36)) && out.contains(&(35, 36)));
        let mut moved = grid(0.0, 0);
        moved[14] = cube(20.0, 20.0);
        check(&mut broad, &moved, &mut out);
        assert!(!out.iter().any(|&(i, j)| (i == 14 || j == 14) && j != 36));
        assert!(broad.kept.valid && broad.kept.grown[14].unwrap().min[0] > 19.0);
        let mut broken = grid(0.0, 0);
        broken[3] = cube(f64::NAN, 0.0);
        broad.candidate_pairs(&broken, &[36], &mut out);
        assert!(!broad.kept.valid);
        all_pairs(&grid(0.0, 0), &[36], &mut reference);
        check(&mut broad, &grid(0.0, 0), &mut out);
        assert_eq!(out, reference);
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
