//! Support mappings: the convex variants of `Shape` give the points
//! `Shape::support` gives; a capsule's and a hull's supports are their
//! farthest points; the plane pair's deepest point and depth.

use nalgebra::{UnitQuaternion, Vector3};

use super::Rng;
use crate::physics::detect::{plane_depth, Capsule, Convex, Support};
use crate::physics::pose::Pose;
use crate::physics::Shape;

#[test]
fn convex_shapes_support_where_shape_does() {
    let shapes = [
        Shape::Sphere { radius: 0.7 },
        Shape::HollowSphere { radius: 1.3 },
        Shape::Box {
            sides: [1.0, 2.0, 3.0],
        },
        Shape::Cylinder {
            radius: 0.5,
            height: 2.0,
        },
    ];
    let mut rng = Rng::new(60);
    for shape in shapes {
        let convex = Convex::from_shape(&shape).unwrap();
        for _ in 0..50 {
            let d = rng.vector(1.0);
            let ours: Vector3<f64> = convex.local_support(&d);
            assert!(
                (ours - shape.support(&d).unwrap()).norm() < 1e-12,
                "{shape:?} {d}"
            );
        }
    }
    assert!(Convex::from_shape(&Shape::HalfSpace {
        normal: [0.0, 1.0, 0.0]
    })
    .is_none());
}

#[test]
fn capsule_and_hull_supports_are_their_farthest_points() {
    let cap = Capsule {
        radius: 0.3,
        height: 1.0,
    };
    let s: Vector3<f64> = cap.local_support(&Vector3::new(1.0, 1.0, 0.0));
    let want = Vector3::new(0.0, 0.5, 0.0) + Vector3::new(1.0, 1.0, 0.0).normalize() * 0.3;
    assert!((s - want).norm() < 1e-15);
    assert!((cap.volume() - std::f64::consts::PI * 0.09 * (1.0 + 0.4)).abs() < 1e-15);
    let mut rng = Rng::new(61);
    let hull = rng.hull(1.0);
    for _ in 0..50 {
        let d = rng.vector(1.0);
        let s: Vector3<f64> = hull.local_support(&d);
        let best = hull
            .vertices()
            .iter()
            .map(|v| v.dot(&d))
            .fold(f64::NEG_INFINITY, f64::max);
        assert_eq!(s.dot(&d), best);
    }
    // World support: x + R s(Rᵀ d).
    let pose = Pose::from_unit(
        Vector3::new(1.0, 2.0, 3.0),
        &UnitQuaternion::from_euler_angles(0.1, 0.2, 0.3),
    );
    let d = Vector3::new(0.3, -1.0, 0.2);
    let world = Support::support(&cap, &pose, &d);
    let local: Vector3<f64> = cap.local_support(&pose.rotation.tr_mul(&d));
    assert!((world - pose.to_world(&local)).norm() < 1e-15);
}

#[test]
fn a_plane_pair_uses_the_deepest_point_along_the_inward_normal() {
    let cube = Convex::Cuboid { half: [0.5; 3] };
    let pose = Pose::from_unit(
        Vector3::new(0.0, 0.6, 0.0),
        &UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4),
    );
    let (deepest, depth) = plane_depth(&cube, &pose, &Vector3::y(), &Vector3::zeros());
    // The lowest edge is 0.5·√2 below the centre.
    assert!((depth - (0.5 * 2f64.sqrt() - 0.6)).abs() < 1e-15);
    assert!((deepest.y + depth).abs() < 1e-15);
}
