//! Manifolds of deep hull pairs (proptest): every contact point lies within
//! the pair's depth of both shapes — inside each or outside it by at most
//! the depth (a midway point beside a sharp vertex), never farther.

use crate::collide_support::{collide_all, surface_distance};
use contact_lab::physics::collide::{BoxBoxMode, Feature, Pose};
use contact_lab::physics::detect::ConvexHull;
use contact_lab::physics::Shape;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use proptest::prelude::*;
use std::sync::Arc;

fn unit_quaternion() -> impl Strategy<Value = UnitQuaternion<f64>> {
    prop::array::uniform4(-1.0..1.0f64)
        .prop_filter("non-degenerate", |q| {
            q.iter().map(|x| x * x).sum::<f64>() > 1e-3
        })
        .prop_map(|q| UnitQuaternion::new_normalize(Quaternion::new(q[0], q[1], q[2], q[3])))
}

/// A tetrahedron: the regular one's corners (±s, ±s, ±s with an even
/// number of minus signs), s in [0.15, 0.5], each moved by up to 0.4·s.
fn tetrahedron() -> impl Strategy<Value = Shape> {
    let corners = [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ];
    (
        0.15..0.5f64,
        prop::array::uniform4(prop::array::uniform3(-0.4..0.4f64)),
    )
        .prop_filter_map("a solid tetrahedron", move |(s, moves)| {
            let pts: Vec<[f64; 3]> = (0..4)
                .map(|i| [0, 1, 2].map(|k| s * (corners[i][k] + moves[i][k])))
                .collect();
            let h = ConvexHull::new(&pts).ok()?;
            (h.inner_radius() > 0.1 * s).then(|| Shape::Hull(Arc::new(h)))
        })
}

/// A hull of 5 to 8 random points in a box of half side 0.5, rejected when thin.
fn hull() -> impl Strategy<Value = Shape> {
    prop::collection::vec(prop::array::uniform3(-0.5..0.5f64), 5..9).prop_filter_map(
        "a solid hull",
        |pts| {
            let h = ConvexHull::new(&pts).ok()?;
            (h.inner_radius() > 0.05).then(|| Shape::Hull(Arc::new(h)))
        },
    )
}

fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![tetrahedron(), hull()]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn every_manifold_point_lies_within_the_depth_of_both_hulls(
        a in shape(),
        b in shape(),
        offset in prop::array::uniform3(-0.25..0.25f64),
        qa in unit_quaternion(),
        qb in unit_quaternion(),
    ) {
        // Centres at most 0.43 apart: deep overlaps, often through.
        let pa = Pose::from_unit(Vector3::from(offset), &qa);
        let pb = Pose::from_unit(Vector3::zeros(), &qb);
        let out = collide_all((&a, &pa), (&b, &pb), BoxBoxMode::Manifold);
        let depth = out.iter().map(|c| c.penetration).fold(0.0, f64::max);
        let eps = 1e-7;
        for c in &out {
            // A clipped point (a reference face) lies on its own body and
            // inside the other: inside or on both. The single midway point
            // may lie outside one beside a sharp vertex, by at most half the depth.
            let outside = match c.feature {
                Feature::Convex { reference: None } => 0.5 * depth,
                _ => 0.0,
            };
            for (name, body) in [("A", (&a, &pa)), ("B", (&b, &pb))] {
                let d = surface_distance(body, &c.point);
                prop_assert!(
                    d <= outside + eps && d >= -depth - eps,
                    "{name}: point {:?} is {d} from the surface (depth {depth}; {c:?})",
                    c.point
                );
            }
        }
    }
}
