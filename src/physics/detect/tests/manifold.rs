//! Manifolds of resting pairs: the clipped support faces.

use nalgebra::{UnitQuaternion, Vector3};

use crate::physics::detect::{manifold, query, Convex, ConvexHull, ManifoldPoint, QueryOptions};
use crate::physics::pose::{Pose, Side};

fn contacts(a: &Convex, pa: &Pose<f64>, b: &Convex, pb: &Pose<f64>) -> Vec<ManifoldPoint<f64>> {
    let q = query(a, pa, b, pb, &QueryOptions::default(), &mut (), &mut ());
    manifold(a, pa, b, pb, &q.penetration.expect("overlapping"))
}

fn floor() -> (Convex, Pose<f64>) {
    (
        Convex::Cuboid {
            half: [5.0, 0.5, 5.0],
        },
        Pose::at(Vector3::new(0.0, -0.5, 0.0)),
    )
}

#[test]
fn a_box_resting_on_a_box_has_its_four_corners() {
    let (b, pb) = floor();
    let a = Convex::Cuboid {
        half: [0.5, 0.25, 0.75],
    };
    let pa = Pose::at(Vector3::new(1.0, 0.24, -2.0));
    let m = contacts(&a, &pa, &b, &pb);
    assert_eq!(m.len(), 4);
    for p in &m {
        assert!((p.penetration - 0.01).abs() < 1e-12, "{p:?}");
        assert!((p.normal - Vector3::y()).norm() < 1e-12);
        assert_eq!(p.reference, Some(Side::B));
        assert!((p.point.y + 0.01).abs() < 1e-12);
        assert!(((p.point.x - 1.0).abs() - 0.5).abs() < 1e-12);
        assert!(((p.point.z + 2.0).abs() - 0.75).abs() < 1e-12);
    }
}

#[test]
fn a_standing_cylinder_has_four_rim_points_spread_over_its_cap() {
    let (b, pb) = floor();
    let a = Convex::Cylinder {
        radius: 0.4,
        half_height: 0.6,
    };
    let pa = Pose::at(Vector3::new(0.0, 0.58, 0.0));
    let m = contacts(&a, &pa, &b, &pb);
    assert_eq!(m.len(), 4, "{m:?}");
    let centre: Vector3<f64> = m.iter().map(|p| p.point).sum::<Vector3<f64>>() / 4.0;
    assert!(
        Vector3::new(centre.x, 0.0, centre.z).norm() < 1e-9,
        "{centre}"
    );
    for p in &m {
        assert!((p.penetration - 0.02).abs() < 1e-9, "{p:?}");
        assert!((Vector3::new(p.point.x, 0.0, p.point.z).norm() - 0.4).abs() < 1e-9);
    }
    // A cylinder on its side touches along a line: both ends of it.
    let lying = Pose::from_unit(
        Vector3::new(0.0, 0.39, 0.0),
        &UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2),
    );
    let m = contacts(&a, &lying, &b, &pb);
    assert_eq!(m.len(), 2, "{m:?}");
    for p in &m {
        assert!((p.penetration - 0.01).abs() < 1e-9, "{p:?}");
        assert!((p.point.z.abs() - 0.6).abs() < 1e-9);
    }
}

#[test]
fn a_tetrahedron_on_its_point_has_one_contact_and_on_its_face_three() {
    let (b, pb) = floor();
    let tet = ConvexHull::new(&[
        [0.0, -0.5, 0.0],
        [0.6, 0.3, 0.0],
        [-0.3, 0.3, 0.5],
        [-0.3, 0.3, -0.5],
    ])
    .unwrap();
    let a = Convex::hull(tet);
    let m = contacts(&a, &Pose::at(Vector3::new(0.0, 0.49, 0.0)), &b, &pb);
    assert_eq!(m.len(), 1, "{m:?}");
    assert!((m[0].penetration - 0.01).abs() < 1e-9);
    // Upside down it rests on its top face (3 corners).
    let flipped = Pose::from_unit(
        Vector3::new(0.0, 0.29, 0.0),
        &UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI),
    );
    let m = contacts(&a, &flipped, &b, &pb);
    assert_eq!(m.len(), 3, "{m:?}");
    assert!(m.iter().all(|p| (p.penetration - 0.01).abs() < 1e-9));
}

#[test]
fn a_box_on_its_edge_touches_at_the_edge_ends() {
    let (b, pb) = floor();
    let a = Convex::Cuboid {
        half: [0.5, 0.5, 0.5],
    };
    let pa = Pose::from_unit(
        Vector3::new(0.0, 0.5 * 2f64.sqrt() - 0.01, 0.0),
        &UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4),
    );
    let m = contacts(&a, &pa, &b, &pb);
    assert_eq!(m.len(), 2, "{m:?}");
    for p in &m {
        assert!((p.penetration - 0.01).abs() < 1e-9);
        assert!((p.point.z.abs() - 0.5).abs() < 1e-9);
    }
}

#[test]
fn spheres_keep_the_single_point() {
    let (b, pb) = floor();
    let ball = Convex::Sphere { radius: 0.5 };
    let m = contacts(&ball, &Pose::at(Vector3::new(0.0, 0.45, 0.0)), &b, &pb);
    assert_eq!(m.len(), 1);
    assert_eq!(m[0].reference, None);
    assert!((m[0].penetration - 0.05).abs() < 1e-12);
}

#[test]
fn hulls_and_boxes_rest_on_each_other_with_four_points() {
    let slab = ConvexHull::new(&super::box_points([2.0, 0.5, 2.0])).unwrap();
    let block = ConvexHull::new(&super::box_points([0.5, 0.5, 0.5])).unwrap();
    let (floor, pf) = (Convex::hull(slab), Pose::at(Vector3::new(0.0, -0.5, 0.0)));
    let turn = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 0.4);
    let on = Pose::from_unit(Vector3::new(0.2, 0.49, -0.1), &turn);
    for top in [Convex::hull(block), Convex::Cuboid { half: [0.5; 3] }] {
        let m = contacts(&top, &on, &floor, &pf);
        assert_eq!(m.len(), 4, "{m:?}");
        for p in &m {
            assert!((p.penetration - 0.01).abs() < 1e-12, "{p:?}");
            assert!((p.normal - Vector3::y()).norm() < 1e-12);
        }
    }
    // A box on a standing cylinder's cap: the cap is the reference face,
    // the box's bottom face is clipped to it.
    let can = Convex::Cylinder {
        radius: 1.0,
        half_height: 0.5,
    };
    let top = Convex::Cuboid { half: [0.4; 3] };
    let m = contacts(
        &top,
        &Pose::from_unit(Vector3::new(0.0, 0.89, 0.0), &turn),
        &can,
        &Pose::at(Vector3::zeros()),
    );
    assert_eq!(m.len(), 4, "{m:?}");
    assert!(m
        .iter()
        .all(|p| (p.penetration - 0.01).abs() < 1e-9 && p.reference == Some(Side::B)));
}

#[test]
fn a_tilted_cap_keeps_the_rims_deepest_point_and_a_balanced_set() {
    // A cap tilted 0.5° (its rim 7 mm higher on one side than on the
    // other, all of it below the face) about an axis that puts the rim's
    // lowest point between two corners of a fixed polygon: the polygon
    // starts at the rim's support point, so the manifold's deepest point is
    // EPA's, on the rim, and the four points are two opposite pairs
    // (centroid on the axis).
    let (b, pb) = floor();
    let (r, h) = (0.4, 0.6);
    let a = Convex::Cylinder {
        radius: r,
        half_height: h,
    };
    let axis = nalgebra::Unit::new_normalize(Vector3::new(1.0, 0.0, 0.37));
    let tilt = 0.5f64.to_radians();
    let turn = UnitQuaternion::from_axis_angle(&axis, tilt);
    // The lowest rim point sits h·cos θ + r·sin θ below the centre: 1 cm deep.
    let pa = Pose::from_unit(
        Vector3::new(0.1, h * tilt.cos() + r * tilt.sin() - 0.01, -0.2),
        &turn,
    );
    let q = query(&a, &pa, &b, &pb, &QueryOptions::default(), &mut (), &mut ());
    let pen = q.penetration.expect("overlapping");
    assert!((pen.depth - 0.01).abs() < 1e-9, "{pen:?}");
    let m = manifold(&a, &pa, &b, &pb, &pen);
    assert_eq!(m.len(), 4, "{m:?}");
    let deepest = m.iter().map(|p| p.penetration).fold(f64::MIN, f64::max);
    assert!(
        (deepest - pen.depth).abs() < 1e-9,
        "{deepest} vs {}",
        pen.depth
    );
    let local: Vec<Vector3<f64>> = m.iter().map(|p| pa.to_local(&p.point)).collect();
    for p in &local {
        assert!((p.y + h).abs() < 1e-9, "on the bottom cap: {p}");
        assert!((p.xz().norm() - r).abs() < 1e-9, "on the rim: {p}");
    }
    let centroid = local.iter().sum::<Vector3<f64>>() / 4.0;
    assert!(centroid.xz().norm() < 1e-9, "balanced: {centroid}");
}
