//! Every broad-phase method against all-against-all: the same pairs in the
//! same order, over random, clustered, touching and broken sets of boxes
//! moved from call to call.

use super::*;
use crate::physics::collide::broad::all_pairs;
use nalgebra::Vector3;

const METHODS: [BroadPhaseMethod; 3] = [
    BroadPhaseMethod::Sweep,
    BroadPhaseMethod::Grid,
    BroadPhaseMethod::Bvh,
];

/// A small deterministic generator (SplitMix64) in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / 2f64.powi(64)
    }
}

fn cube(centre: [f64; 3], half: f64) -> Option<Aabb<f64>> {
    Some(Aabb::around(&Vector3::from(centre), &Vector3::repeat(half)))
}

/// `n` boxes of half sides 0.1 to 0.5 in a cube of side `span`.
fn scattered(rng: &mut Rng, n: usize, span: f64) -> Vec<Option<Aabb<f64>>> {
    (0..n)
        .map(|_| {
            let c = [rng.next() * span, rng.next() * span, rng.next() * span];
            let half = Vector3::new(rng.next(), rng.next(), rng.next()) * 0.4;
            Some(Aabb::around(&Vector3::from(c), &half.add_scalar(0.1)))
        })
        .collect()
}

/// Runs every method on `bounds` with `finders` (one per method, kept
/// between calls) and checks each against all-against-all.
fn check(finders: &mut [PairFinder; 3], bounds: &[Option<Aabb<f64>>], half: &[usize]) {
    let mut reference = Vec::new();
    all_pairs(bounds, half, &mut reference);
    for (finder, method) in finders.iter_mut().zip(METHODS) {
        let mut out = vec![(7, 7)];
        finder.candidate_pairs(method, bounds, half, &mut out);
        assert_eq!(out, reference, "{method:?}");
        let counts = finder.counts();
        assert_eq!(counts.kept, out.len());
        assert_eq!(counts.method, method);
        assert!(counts.tests >= reference.len().saturating_sub(half.len() * bounds.len()));
        finder.check_tree();
    }
}

#[test]
fn every_method_finds_all_against_alls_pairs_in_its_order_as_boxes_move() {
    let mut rng = Rng(42);
    let mut finders: [PairFinder; 3] = Default::default();
    for n in [0, 1, 2, 5, 40, 300] {
        let mut bounds = scattered(&mut rng, n, 6.0);
        bounds.push(None); // a half-space
        let half = [n];
        check(&mut finders, &bounds, &half);
        // A few calls of small moves (most boxes stay in their fat boxes),
        // then one of big moves.
        for call in 0..6 {
            let step = if call == 5 { 3.0 } else { 0.05 };
            for b in bounds.iter_mut().flatten() {
                let d = Vector3::new(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5) * step;
                b.min += d;
                b.max += d;
            }
            check(&mut finders, &bounds, &half);
        }
    }
}

#[test]
fn touching_clustered_huge_and_broken_boxes_are_found_alike() {
    let mut finders: [PairFinder; 3] = Default::default();
    // A 5 × 5 × 5 lattice of unit cubes that touch face to face.
    let lattice: Vec<_> = (0..125)
        .map(|i| cube([(i % 5) as f64, (i / 5 % 5) as f64, (i / 25) as f64], 0.5))
        .collect();
    check(&mut finders, &lattice, &[]);
    // A cluster: 200 small boxes in a 1 m cube, 20 far away, a floor box
    // spanning everything, an infinite box, a NaN box, bodies with no shape.
    let mut rng = Rng(7);
    let mut mixed = scattered(&mut rng, 200, 1.0);
    mixed.extend(scattered(&mut rng, 20, 1000.0));
    mixed.push(Some(Aabb {
        min: Vector3::new(-2000.0, -1.0, -2000.0),
        max: Vector3::new(2000.0, 0.0, 2000.0),
    }));
    mixed.push(Some(Aabb {
        min: Vector3::repeat(f64::NEG_INFINITY),
        max: Vector3::new(f64::INFINITY, 0.5, f64::INFINITY),
    }));
    mixed.push(cube([f64::NAN, 0.0, 0.0], 1.0));
    mixed.push(None);
    mixed.push(None);
    let n = mixed.len();
    check(&mut finders, &mixed, &[n - 1]);
    // The same set again (the tree keeps its leaves), then the NaN box healed.
    check(&mut finders, &mixed, &[n - 1]);
    mixed[n - 3] = cube([0.5, 0.5, 0.5], 0.2);
    check(&mut finders, &mixed, &[n - 1]);
    // Bodies lose and gain their boxes.
    for k in (0..n).step_by(3) {
        mixed[k] = None;
    }
    check(&mut finders, &mixed, &[]);
    let grown = scattered(&mut rng, n, 1.0);
    check(&mut finders, &grown, &[]);
    // Zero-size boxes only (points): the grid's side falls back to 1.
    let points: Vec<_> = (0..30)
        .map(|i| cube([(i % 4) as f64, 0.0, 0.0], 0.0))
        .collect();
    check(&mut finders, &points, &[]);
}

#[test]
fn a_tree_fed_a_sorted_row_box_by_box_stays_shallow() {
    // Bodies that appear one per call along a line (the worst order for a
    // tree grown by insertion): the height stays within the rebuild limit.
    let mut finder = PairFinder::new();
    let mut bounds: Vec<Option<Aabb<f64>>> = vec![None; 512];
    let mut out = Vec::new();
    for i in 0..512 {
        bounds[i] = cube([i as f64 * 0.9, 0.0, 0.0], 0.5);
        finder.candidate_pairs(BroadPhaseMethod::Bvh, &bounds, &[], &mut out);
        finder.check_tree();
    }
    assert_eq!(out.len(), 511);
    assert!(
        finder.counts().height <= 2 * 10 + 8,
        "{:?}",
        finder.counts()
    );
}

#[test]
fn every_method_tests_far_fewer_pairs_than_all_against_all_at_ten_thousand() {
    // 10,000 boxes at a density of one per 8 m³ (a 43 m cube).
    let mut rng = Rng(3);
    let n = 10_000;
    let bounds = scattered(&mut rng, n, (8.0 * n as f64).cbrt());
    let half_of_all = n * (n - 1) / 2;
    let mut reference = Vec::new();
    PairFinder::new().candidate_pairs(BroadPhaseMethod::Sweep, &bounds, &[], &mut reference);
    for method in METHODS {
        let mut finder = PairFinder::new();
        let mut out = Vec::new();
        finder.candidate_pairs(method, &bounds, &[], &mut out);
        assert_eq!(out, reference, "{method:?}");
        let counts = finder.counts();
        eprintln!("{counts:?}");
        // The sweep meets every box whose x-range meets (about 1 m of the
        // 43 m: one in 40 of all-against-all's ~5·10⁷ pairs); the grid and
        // the tree fewer than one in 2,000.
        let share = if method == BroadPhaseMethod::Sweep {
            20
        } else {
            2000
        };
        assert!(counts.tests * share < half_of_all, "{counts:?}");
        assert!(counts.tests >= counts.kept, "{counts:?}");
    }
}
