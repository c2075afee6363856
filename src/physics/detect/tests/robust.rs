//! The classic failure points: touching contact, parallel faces, far from
//! the origin (1e6), large scale ratios (1e4), and a fuzz over random sizes
//! and places: finite results, bounded iterations, no NaN.

use nalgebra::{UnitQuaternion, Vector3};

use super::{relative, Rng};
use crate::physics::detect::{
    gjk, query, sat, Convex, EpaEnd, FeatureKind, GjkOptions, GjkVerdict, Polyhedron, QueryOptions,
};
use crate::physics::pose::Pose;

fn cube(h: f64) -> Convex {
    Convex::Cuboid { half: [h; 3] }
}

fn at(x: f64, y: f64, z: f64) -> Pose<f64> {
    Pose::at(Vector3::new(x, y, z))
}

#[test]
fn touching_shapes_end_at_distance_zero() {
    let turned = Pose::from_unit(
        Vector3::new(0.0, 1.0 + 0.5 * 2f64.sqrt(), 0.0),
        &UnitQuaternion::from_euler_angles(0.0, 0.0, std::f64::consts::FRAC_PI_4),
    );
    let cases = [
        (cube(0.5), at(1.0, 0.0, 0.0), cube(0.5), at(0.0, 0.0, 0.0)), // face on face
        (cube(0.5), at(1.0, 1.0, 0.0), cube(0.5), at(0.0, 0.0, 0.0)), // edge on edge
        (cube(0.5), at(1.0, 1.0, 1.0), cube(0.5), at(0.0, 0.0, 0.0)), // corner on corner
        (
            Convex::Sphere { radius: 0.5 },
            at(0.0, 1.0, 0.0),
            cube(0.5),
            at(0.0, 0.0, 0.0),
        ),
        (cube(0.5), turned, cube(1.0), at(0.0, 0.0, 0.0)), // an edge on a face
    ];
    for (k, (a, pa, b, pb)) in cases.iter().enumerate() {
        let q = query(a, pa, b, pb, &QueryOptions::default(), &mut (), &mut ());
        assert!(q.gjk.distance.abs() < 1e-12, "case {k}: {}", q.gjk.distance);
        assert!(q.gjk.iterations <= 128);
        if let Some(p) = q.penetration {
            assert!(p.depth >= 0.0 && p.depth < 1e-9, "case {k}: {}", p.depth);
            assert!(p.normal.iter().all(|x| x.is_finite()));
            assert!((p.normal.norm() - 1.0).abs() < 1e-9);
        }
    }
}

#[test]
fn parallel_faces_give_the_gap_and_the_face_face_depth() {
    let (a, b) = (
        cube(0.5),
        Convex::Cuboid {
            half: [2.0, 0.5, 2.0],
        },
    );
    let apart = gjk(
        &a,
        &at(0.3, 1.25, 0.2),
        &b,
        &at(0.0, 0.0, 0.0),
        &GjkOptions::default(),
        &mut (),
    );
    assert_eq!(apart.verdict, GjkVerdict::Separated);
    assert!((apart.distance - 0.25).abs() < 1e-15, "{}", apart.distance);
    let q = query(
        &a,
        &at(0.3, 0.9, 0.2),
        &b,
        &at(0.0, 0.0, 0.0),
        &QueryOptions::default(),
        &mut (),
        &mut (),
    );
    let epa = q.epa.unwrap();
    assert_eq!(epa.end, EpaEnd::Converged);
    assert!((epa.depth - 0.1).abs() < 1e-12);
    assert!((epa.normal - Vector3::y()).norm() < 1e-12);
    assert_eq!(
        (epa.feature.a, epa.feature.b),
        (FeatureKind::Face, FeatureKind::Face)
    );
}

#[test]
fn far_from_the_origin_the_answers_keep_their_digits() {
    let mut rng = Rng::new(50);
    let far = Vector3::new(1e6, -1e6, 1e6);
    for k in 0..300u64 {
        let (a, b) = (rng.shape(k), rng.shape(k / 6));
        let (pa, pb) = (rng.pose(2.0), rng.pose(2.0));
        let moved = |p: &Pose<f64>| Pose {
            position: p.position + far,
            ..*p
        };
        let near = query(&a, &pa, &b, &pb, &QueryOptions::default(), &mut (), &mut ());
        let away = query(
            &a,
            &moved(&pa),
            &b,
            &moved(&pb),
            &QueryOptions::default(),
            &mut (),
            &mut (),
        );
        // Positions 1e6 away carry ~1e-10 of rounding.
        assert!(
            (near.gjk.distance - away.gjk.distance).abs() < 1e-8,
            "pair {k} {a:?} {b:?}: {near:?} {away:?}"
        );
        assert_eq!(near.intersecting(), away.intersecting(), "pair {k}");
        if let (Some(x), Some(y)) = (near.penetration, away.penetration) {
            assert!(
                (x.depth - y.depth).abs() < 1e-7,
                "pair {k}: {} vs {}",
                x.depth,
                y.depth
            );
            // On a curved surface EPA's last face is a chord ε below it: its
            // point is known to about √(2Rε) ≈ 1e-5, not to ε.
            assert!(
                (x.point + far - y.point).norm() < 1e-4,
                "pair {k} {a:?} {b:?}: {x:?} {y:?}"
            );
        }
    }
}

#[test]
fn a_scale_ratio_of_ten_thousand_is_measured_exactly() {
    // A 2 cm cube on a 200 m block: gap, then overlap, against SAT.
    let (small, big) = (cube(0.01), cube(100.0));
    let apart = gjk(
        &small,
        &at(3.0, 100.02, -7.0),
        &big,
        &at(0.0, 0.0, 0.0),
        &GjkOptions::default(),
        &mut (),
    );
    assert!(
        relative(apart.distance, 0.01, 1e-12) < 1e-9,
        "{}",
        apart.distance
    );
    let turn = UnitQuaternion::from_euler_angles(0.2, 0.4, 0.1);
    let pa = Pose::from_unit(Vector3::new(3.0, 100.005, -7.0), &turn);
    let pb = at(0.0, 0.0, 0.0);
    let q = query(
        &small,
        &pa,
        &big,
        &pb,
        &QueryOptions::default(),
        &mut (),
        &mut (),
    );
    let want = sat(
        &Polyhedron::of(&small, &pa).unwrap(),
        &Polyhedron::of(&big, &pb).unwrap(),
    );
    let epa = q.epa.unwrap();
    assert!(
        relative(epa.depth, want.depth, 1e-12) < 1e-9,
        "{} vs {}",
        epa.depth,
        want.depth
    );
    assert!((epa.normal - Vector3::y()).norm() < 1e-9);
    // A 1 mm ball beside a 20 m box.
    let ball = Convex::Sphere { radius: 1e-3 };
    let r = gjk(
        &ball,
        &at(10.5, 2.0, 1.0),
        &cube(10.0),
        &pb,
        &GjkOptions::default(),
        &mut (),
    );
    assert!(relative(r.distance, 0.5 - 1e-3, 1e-12) < 1e-9);
}

#[test]
fn random_sizes_and_places_give_finite_bounded_answers() {
    let mut rng = Rng::new(51);
    for k in 0..3000u64 {
        let (a, b) = (rng.shape(k), rng.shape(k / 6));
        let scale = 10f64.powf(rng.range(-3.0, 3.0));
        let offset = rng.vector(1e6);
        let pa = Pose {
            position: rng.vector(2.0) * scale + offset,
            ..rng.pose(0.0)
        };
        let pb = Pose {
            position: rng.vector(2.0) * scale + offset,
            ..rng.pose(0.0)
        };
        let grow = |s: Convex| match s {
            Convex::Sphere { radius } => Convex::Sphere {
                radius: radius * scale,
            },
            Convex::Cuboid { half } => Convex::Cuboid {
                half: half.map(|h| h * scale),
            },
            // Only the height: a disc or a needle.
            Convex::Cylinder {
                radius,
                half_height,
            } => Convex::Cylinder {
                radius,
                half_height: half_height * scale,
            },
            other => other,
        };
        let (a, b) = (grow(a), grow(b));
        let q = query(&a, &pa, &b, &pb, &QueryOptions::default(), &mut (), &mut ());
        assert!(
            q.gjk.distance.is_finite() && q.gjk.distance >= 0.0,
            "pair {k}"
        );
        assert!(q.gjk.iterations <= 128);
        assert!(q
            .gjk
            .closest_a
            .iter()
            .chain(q.gjk.closest_b.iter())
            .all(|x| x.is_finite()));
        if let Some(p) = q.penetration {
            assert!(p.depth.is_finite() && p.depth >= 0.0, "pair {k}");
            assert!((p.normal.norm() - 1.0).abs() < 1e-9, "pair {k}");
            assert!(p.point.iter().all(|x| x.is_finite()));
        }
        if let Some(e) = q.epa {
            assert!(e.iterations <= 128);
        }
    }
}

#[test]
fn gjk_and_epa_run_in_f32_too() {
    let a = Convex::Cuboid { half: [0.5; 3] };
    let pa = Pose::<f32>::at(Vector3::new(0.2, 0.9, 0.1));
    let pb = Pose::<f32>::at(Vector3::zeros());
    let options = QueryOptions::default();
    let q = query(&a, &pa, &a, &pb, &options, &mut (), &mut ());
    let p = q.penetration.unwrap();
    assert!((p.depth - 0.1).abs() < 1e-5, "{}", p.depth);
    assert!((p.normal - Vector3::y()).norm() < 1e-5);
}
