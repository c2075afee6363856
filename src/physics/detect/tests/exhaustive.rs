//! GJK distance between boxes and hulls against an exhaustive search over
//! their feature pairs (vertex–triangle, edge–edge): 1e-9 relative.

use super::reference::polyhedron_distance;
use super::{relative, Rng};
use crate::physics::detect::{gjk, sat, Convex, GjkOptions, GjkVerdict, Polyhedron};

fn polyhedron(rng: &mut Rng, k: u64) -> Convex {
    if k.is_multiple_of(2) {
        Convex::Cuboid {
            half: [
                rng.range(0.1, 1.5),
                rng.range(0.1, 1.5),
                rng.range(0.1, 1.5),
            ],
        }
    } else {
        let size = rng.range(0.3, 1.5);
        Convex::hull(rng.hull(size))
    }
}

#[test]
fn gjk_distance_between_polyhedra_matches_the_feature_pair_search() {
    let mut rng = Rng::new(10);
    let mut separated = 0;
    for k in 0..400u64 {
        let (a, b) = (polyhedron(&mut rng, k), polyhedron(&mut rng, k / 2));
        let (pa, pb) = (rng.pose(3.5), rng.pose(3.5));
        let want = polyhedron_distance((&a, &pa), (&b, &pb));
        let r = gjk(&a, &pa, &b, &pb, &GjkOptions::default(), &mut ());
        // Surfaces apart but one inside the other: SAT finds the overlap.
        let overlap = sat(
            &Polyhedron::of(&a, &pa).unwrap(),
            &Polyhedron::of(&b, &pb).unwrap(),
        )
        .depth;
        if overlap > 1e-9 {
            assert_eq!(r.verdict, GjkVerdict::Intersecting, "pair {k}");
        } else if want > 1e-6 {
            separated += 1;
            assert_eq!(r.verdict, GjkVerdict::Separated, "pair {k}");
            assert!(
                relative(r.distance, want, 1e-12) < 1e-9,
                "pair {k}: {} vs {want}",
                r.distance
            );
            assert!(r.iterations < 40, "pair {k}: {} iterations", r.iterations);
        } else {
            assert!(r.distance < 1e-6, "pair {k}");
        }
    }
    assert!(separated > 200, "{separated}");
}
