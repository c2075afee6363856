//! Contact generation over random poses (proptest): the conventions of every
//! contact, exact depths for spheres and planes, the separating axis test
//! against a brute-force check, and the broad phase against all pairs.

use crate::collide_support;

use collide_support::{check_pair, collide_all, surface_distance};
use contact_lab::physics::collide::{
    candidate_pairs, collide, Aabb, BoxBoxMode, BroadPhase, ContactGenerator, Feature, Options,
    Pose,
};
use contact_lab::physics::{BodyId, Shape};
use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use proptest::prelude::*;

fn unit_quaternion() -> impl Strategy<Value = UnitQuaternion<f64>> {
    prop::array::uniform4(-1.0..1.0f64)
        .prop_filter("non-degenerate", |q| {
            q.iter().map(|x| x * x).sum::<f64>() > 1e-3
        })
        .prop_map(|q| UnitQuaternion::new_normalize(Quaternion::new(q[0], q[1], q[2], q[3])))
}

/// A pose near the origin; every fourth one unrotated (exact ties).
fn pose(range: f64) -> impl Strategy<Value = Pose<f64>> {
    let turn = prop_oneof![1 => Just(UnitQuaternion::identity()), 3 => unit_quaternion()];
    (prop::array::uniform3(-range..range), turn)
        .prop_map(|(p, q)| Pose::from_unit(Vector3::from(p), &q))
}

fn cuboid() -> impl Strategy<Value = Shape> {
    prop::array::uniform3(0.2..2.0f64).prop_map(|sides| Shape::Box { sides })
}

fn ball() -> impl Strategy<Value = Shape> {
    (0.1..1.5f64).prop_map(|radius| Shape::Sphere { radius })
}

/// Box axes and half sides in world coordinates.
fn frame(shape: &Shape, p: &Pose<f64>) -> ([Vector3<f64>; 3], Vector3<f64>) {
    ([0, 1, 2].map(|k| p.axis(k)), shape.half_extents().unwrap())
}

/// Gap between two boxes along unit `l` (negative: overlap).
fn gap_along(a: (&Shape, &Pose<f64>), b: (&Shape, &Pose<f64>), l: &Vector3<f64>) -> f64 {
    let radius = |s: &Shape, p: &Pose<f64>| {
        let (axes, h) = frame(s, p);
        (0..3).map(|k| h[k] * axes[k].dot(l).abs()).sum::<f64>()
    };
    (a.1.position - b.1.position).dot(l).abs() - radius(a.0, a.1) - radius(b.0, b.1)
}

/// Directions spread evenly over the sphere (Fibonacci lattice).
fn directions(n: usize) -> Vec<Vector3<f64>> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let y = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - y * y).sqrt();
            let phi = golden * i as f64;
            Vector3::new(r * phi.cos(), y, r * phi.sin())
        })
        .collect()
}

/// True when a grid point inside `a` lies strictly inside `b`.
fn sample_inside(a: (&Shape, &Pose<f64>), b: (&Shape, &Pose<f64>)) -> bool {
    let (axes, h) = frame(a.0, a.1);
    let steps = [-1.0, -0.5, 0.0, 0.5, 1.0];
    steps.iter().any(|&x| {
        steps.iter().any(|&y| {
            steps.iter().any(|&z| {
                let p =
                    a.1.position + axes[0] * (x * h.x) + axes[1] * (y * h.y) + axes[2] * (z * h.z);
                surface_distance(b, &p) < -1e-9
            })
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn box_box_keeps_the_conventions_and_agrees_with_brute_force(
        sa in cuboid(), pa in pose(1.5), sb in cuboid(), pb in pose(1.5),
    ) {
        let (a, b) = ((&sa, &pa), (&sb, &pb));
        let single = check_pair(a, b, BoxBoxMode::Single, 0.0);
        let manifold = check_pair(a, b, BoxBoxMode::Manifold, 0.0);
        prop_assert_eq!(single.len().min(1), manifold.len().min(1));
        prop_assert!(single.len() <= 1 && manifold.len() <= 4);
        let reach = sa.bounding_radius().unwrap() + sb.bounding_radius().unwrap();
        let apart = (pa.position - pb.position).norm() > reach;
        let sampled = directions(600);
        let widest_gap = sampled.iter().map(|l| gap_along(a, b, l)).fold(f64::MIN, f64::max);
        if single.is_empty() {
            prop_assert!(!sample_inside(a, b) && !sample_inside(b, a), "a point of one box is inside the other");
        } else {
            prop_assert!(!apart, "contact though the bounding spheres are apart");
            prop_assert!(widest_gap < 2e-3, "a sampled axis separates by {}", widest_gap);
            // The reported overlap is at most the least overlap seen, up to
            // the 5 % preference for face axes.
            let least = -widest_gap;
            prop_assert!(single[0].penetration <= least / 0.95 + 1e-9, "{:?} vs {}", single[0], least);
        }
    }

    #[test]
    fn single_precision_finds_the_same_box_box_contacts(
        sa in cuboid(), pa in pose(1.5), sb in cuboid(), pb in pose(1.5),
    ) {
        let cast = |p: &Pose<f64>| Pose::<f32> { position: p.position.cast(), rotation: p.rotation.cast() };
        let mut narrow = Vec::new();
        collide((&sa, &cast(&pa)), (&sb, &cast(&pb)), BoxBoxMode::Single, &mut narrow);
        let wide = collide_all((&sa, &pa), (&sb, &pb), BoxBoxMode::Single);
        let depth = wide.first().map_or(f64::MIN, |k| k.penetration);
        // Away from touching (|depth| ≥ 1e-4) and from ties between axes,
        // both agree on the contact.
        if depth >= 1e-4 && !near_tie((&sa, &pa), (&sb, &pb)) {
            prop_assert_eq!(narrow.len(), 1);
            prop_assert!((f64::from(narrow[0].penetration) - depth).abs() < 1e-5);
            prop_assert!((narrow[0].normal.cast::<f64>() - wide[0].normal).norm() < 1e-4);
            // A vertex at the edge of the reference face may fall beside it
            // in one precision: then the clipped face point is taken.
            let face = |f: Feature| match f {
                Feature::VertexFace { face, axis, .. } => Feature::FaceFace { reference: face, axis },
                f => f,
            };
            prop_assert_eq!(face(narrow[0].feature), face(wide[0].feature));
        } else if wide.is_empty() {
            prop_assert!(narrow.iter().all(|k| k.penetration < 1e-4));
        }
    }

    #[test]
    fn box_sphere_depth_is_the_radius_less_the_distance_to_the_box(
        sa in cuboid(), pa in pose(1.5), sb in ball(), pb in pose(1.5),
    ) {
        let out = check_pair((&sa, &pa), (&sb, &pb), BoxBoxMode::Single, 0.0);
        let r = sb.bounding_radius().unwrap();
        let distance = surface_distance((&sa, &pa), &pb.position);
        prop_assert_eq!(out.len(), usize::from(distance <= r));
        if let Some(k) = out.first() {
            prop_assert!((k.penetration - (r - distance)).abs() < 1e-12);
        }
    }

    #[test]
    fn sphere_sphere_depth_is_the_exact_overlap(sa in ball(), pa in pose(1.5), sb in ball(), pb in pose(1.5)) {
        let out = check_pair((&sa, &pa), (&sb, &pb), BoxBoxMode::Single, 0.0);
        let overlap = sa.bounding_radius().unwrap() + sb.bounding_radius().unwrap()
            - (pa.position - pb.position).norm();
        prop_assert_eq!(out.len(), usize::from(overlap >= 0.0));
        if let Some(k) = out.first() {
            prop_assert!((k.penetration - overlap).abs() < 1e-15);
        }
    }

    #[test]
    fn shapes_on_a_tilted_plane_touch_at_every_point_below_it(
        shape in prop_oneof![cuboid(), ball(), (0.1..1.0f64, 0.2..2.0f64)
            .prop_map(|(radius, height)| Shape::Cylinder { radius, height })],
        p in pose(1.0),
        normal in prop::array::uniform3(-1.0..1.0f64).prop_filter("non-zero", |n| n.iter().map(|x| x * x).sum::<f64>() > 1e-2),
        height in -0.5..0.5f64,
    ) {
        let n = Vector3::from(normal).normalize();
        let plane = Shape::HalfSpace { normal: n.into() };
        let at = Pose::at(n * height);
        let out = check_pair((&shape, &p), (&plane, &at), BoxBoxMode::Single, 0.0);
        // Deepest point: the support point against the normal, exactly.
        let deepest = p.to_world(&shape.support(&(p.rotation.transpose() * -n)).unwrap());
        let depth = -(deepest - at.position).dot(&n);
        let most = out.iter().map(|k| k.penetration).fold(f64::MIN, f64::max);
        if depth >= 1e-12 {
            prop_assert!((most - depth).abs() < 1e-12, "{} vs {}", most, depth);
        } else if depth < -1e-12 {
            prop_assert!(out.is_empty());
        }
        if let Shape::Box { .. } = shape {
            let (axes, h) = frame(&shape, &p);
            let below = (0..8).filter(|i| {
                let v = p.position + (0..3).map(|k| axes[k] * h[k] * if i >> k & 1 == 1 { 1.0 } else { -1.0 }).sum::<Vector3<f64>>();
                (v - at.position).dot(&n) <= 0.0
            }).count();
            prop_assert_eq!(out.len(), below);
        }
    }

    #[test]
    fn sweep_finds_exactly_the_overlapping_bounds(
        cells in prop::collection::vec((prop::array::uniform3(0i32..12), 1i32..4, any::<bool>()), 0..300),
        planes in prop::collection::vec(0usize..320, 0..3),
        shift in prop::array::uniform3(-0.3..0.3f64),
    ) {
        // Half-unit grid and sizes: many bounds touch exactly; repeats duplicate.
        let mut bounds: Vec<Option<Aabb<f64>>> = cells.iter().map(|&(c, size, keep)| {
            let centre = Vector3::from(c.map(|x| f64::from(x) * 0.5));
            keep.then(|| Aabb::around(&centre, &Vector3::repeat(f64::from(size) * 0.25)))
        }).collect();
        let half_spaces: Vec<usize> = planes.into_iter().filter(|&h| h < bounds.len()).collect();
        for &h in &half_spaces {
            bounds[h] = None;
        }
        let mut broad = BroadPhase::new();
        let mut out = Vec::new();
        broad.candidate_pairs(&bounds, &half_spaces, &mut out);
        prop_assert_eq!(&out, &brute_force(&bounds, &half_spaces));
        // A second sweep (kept order) after every box moved.
        for b in bounds.iter_mut().flatten() {
            let d = Vector3::from(shift);
            *b = Aabb { min: b.min + d, max: b.max + d * 2.0 };
        }
        broad.candidate_pairs(&bounds, &half_spaces, &mut out);
        prop_assert_eq!(&out, &brute_force(&bounds, &half_spaces));
        let mut fresh = Vec::new();
        candidate_pairs(&bounds, &half_spaces, &mut fresh);
        prop_assert_eq!(out, fresh);
    }
}

/// True when two face axes overlap alike, or the best edge axis is near the
/// 5 % preference for faces (within 1e-4): f32 round-off may choose either.
fn near_tie(a: (&Shape, &Pose<f64>), b: (&Shape, &Pose<f64>)) -> bool {
    let faces: Vec<f64> = (0..3)
        .flat_map(|k| [a.1.axis(k), b.1.axis(k)])
        .map(|l| -gap_along(a, b, &l))
        .collect();
    let edges = (0..9).filter_map(|k| {
        let l = a.1.axis(k / 3).cross(&b.1.axis(k % 3));
        (l.norm_squared() >= 1e-6).then(|| -gap_along(a, b, &l.normalize()))
    });
    let face = faces.iter().copied().fold(f64::MAX, f64::min);
    let edge = edges.fold(f64::MAX, f64::min);
    let alike = faces.iter().filter(|&&f| f - face < 1e-4).count() > 1;
    alike || (edge - 0.95 * face).abs() < 1e-4
}

/// Every pair (i < j) of overlapping or touching bounds, and every bounded
/// body with every half-space, sorted.
fn brute_force(bounds: &[Option<Aabb<f64>>], half_spaces: &[usize]) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    for (i, a) in bounds.iter().enumerate() {
        for (j, b) in bounds.iter().enumerate().skip(i + 1) {
            if let (Some(a), Some(b)) = (a, b) {
                if (0..3).all(|k| a.min[k] <= b.max[k] && b.min[k] <= a.max[k]) {
                    pairs.push((i, j));
                }
            }
        }
        if a.is_some() {
            pairs.extend(
                half_spaces
                    .iter()
                    .filter(|&&h| h != i)
                    .map(|&h| (i.min(h), i.max(h))),
            );
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    pairs
}

#[test]
fn generator_skips_immovable_pairs_and_shapeless_bodies() {
    let floor = Shape::HalfSpace {
        normal: [0.0, 1.0, 0.0],
    };
    let ball = Shape::Sphere { radius: 0.5 };
    let wall = Shape::Box {
        sides: [1.0, 1.0, 1.0],
    };
    // 0 floor (immovable), 1 ball resting on it, 2 no shape, 3 and 4 two
    // immovable boxes sunk into the floor and into each other.
    let shapes = [
        Some(floor),
        Some(ball),
        None,
        Some(wall.clone()),
        Some(wall),
    ];
    let poses = [
        [0.0, 0.0, 0.0],
        [0.0, 0.49, 0.0],
        [0.0, 0.49, 0.0],
        [5.0, 0.4, 0.0],
        [5.5, 0.4, 0.0],
    ]
    .map(|p| Pose::at(Vector3::from(p)));
    let movable = [false, true, true, false, false];
    let mut generator = ContactGenerator::<f64>::new();
    let mut out = Vec::new();
    generator.generate(&shapes, &poses, &movable, &Options::default(), &mut out);
    assert_eq!(out.len(), 1, "{out:?}");
    assert_eq!((out[0].body1, out[0].body2), (BodyId(1), BodyId(0)));
    assert_eq!(out[0].contact.normal, Vector3::y());
    assert!((out[0].contact.penetration - 0.01).abs() < 1e-12);
    assert!(generator.pairs().contains(&(3, 4)));
}

#[test]
fn generator_sweep_and_brute_force_agree_on_a_pile() {
    let mut shapes = vec![Some(Shape::HalfSpace {
        normal: [0.0, 1.0, 0.0],
    })];
    let mut poses = vec![Pose::at(Vector3::zeros())];
    let turn = UnitQuaternion::from_euler_angles(0.3, 0.2, 0.1);
    for i in 0..150 {
        let (x, z, y) = (
            (i % 5) as f64 * 0.9,
            (i / 5 % 5) as f64 * 0.9,
            (i / 25) as f64 * 0.9 + 0.48,
        );
        shapes.push(Some(if i % 3 == 0 {
            Shape::Box {
                sides: [0.9, 0.8, 1.0],
            }
        } else {
            Shape::Sphere { radius: 0.5 }
        }));
        poses.push(Pose::from_unit(Vector3::new(x, y, z), &turn));
    }
    let movable: Vec<bool> = (0..shapes.len()).map(|i| i > 0).collect();
    let (mut sweep, mut brute) = (ContactGenerator::new(), ContactGenerator::new());
    brute.brute_force = true;
    let (mut a, mut b) = (Vec::new(), Vec::new());
    sweep.generate(&shapes, &poses, &movable, &Options::default(), &mut a);
    brute.generate(&shapes, &poses, &movable, &Options::default(), &mut b);
    assert!(a.len() > 150, "a pile has contacts: {}", a.len());
    assert_eq!(a, b);
    // Every contact agrees with the pair's own generation.
    for k in a.iter().step_by(7) {
        let pair = collide_all(
            (shapes[k.body1.0].as_ref().unwrap(), &poses[k.body1.0]),
            (shapes[k.body2.0].as_ref().unwrap(), &poses[k.body2.0]),
            BoxBoxMode::Manifold,
        );
        assert!(pair.contains(&k.contact));
    }
}
