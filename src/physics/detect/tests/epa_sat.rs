//! EPA depth and normal against the separating-axis test, which is exact
//! for polyhedra: depth to 1e-9 relative, normal to 1e-9.

use super::{relative, Rng};
use crate::physics::detect::{query, sat, Convex, EpaEnd, Polyhedron, QueryOptions};
use crate::physics::pose::Pose;

fn polyhedron(rng: &mut Rng, k: u64) -> Convex {
    if k.is_multiple_of(2) {
        Convex::Cuboid {
            half: [
                rng.range(0.2, 1.5),
                rng.range(0.2, 1.5),
                rng.range(0.2, 1.5),
            ],
        }
    } else {
        let size = rng.range(0.5, 1.5);
        Convex::hull(rng.hull(size))
    }
}

#[test]
fn epa_depth_and_normal_match_sat_for_boxes_and_hulls() {
    let mut rng = Rng::new(20);
    let mut compared = 0;
    for k in 0..600u64 {
        let (a, b) = (polyhedron(&mut rng, k), polyhedron(&mut rng, k / 2));
        let pa = rng.pose(1.0);
        let pb = Pose::from_unit(rng.vector(1.0), &rng.rotation());
        let reference = sat(
            &Polyhedron::of(&a, &pa).unwrap(),
            &Polyhedron::of(&b, &pb).unwrap(),
        );
        if reference.depth < 1e-6 {
            continue;
        }
        let q = query(&a, &pa, &b, &pb, &QueryOptions::default(), &mut (), &mut ());
        let epa = q.epa.expect("overlapping polyhedra run EPA");
        assert_eq!(epa.end, EpaEnd::Converged, "pair {k}");
        assert!(
            relative(epa.depth, reference.depth, 1e-12) < 1e-9,
            "pair {k}: {} vs {}",
            epa.depth,
            reference.depth
        );
        // A tie between two axes leaves the normal open; count those apart.
        let err = (epa.normal - reference.normal).norm();
        assert!(
            err < 1e-9 || tie(&a, &pa, &b, &pb, &epa.normal, reference.depth),
            "pair {k}: normal off by {err}"
        );
        // Moving A by depth along the normal leaves the pair touching.
        let moved = Pose {
            position: pa.position + epa.normal * (epa.depth + 1e-7),
            ..pa
        };
        let again = sat(
            &Polyhedron::of(&a, &moved).unwrap(),
            &Polyhedron::of(&b, &pb).unwrap(),
        );
        assert!(again.depth < 0.0, "pair {k}");
        compared += 1;
    }
    assert!(compared > 250, "{compared}");
}

/// True when `normal` is another axis with the same smallest overlap.
fn tie(
    a: &Convex,
    pa: &Pose<f64>,
    b: &Convex,
    pb: &Pose<f64>,
    normal: &nalgebra::Vector3<f64>,
    depth: f64,
) -> bool {
    let (pa, pb) = (
        Polyhedron::of(a, pa).unwrap(),
        Polyhedron::of(b, pb).unwrap(),
    );
    let (a0, a1) = pa.project(normal);
    let (b0, b1) = pb.project(normal);
    let _ = a1;
    relative(b1 - a0, depth, 1e-12) < 1e-9 && b0 < a0
}
