//! Hulls: faces, edges and mass properties; degenerate clouds rejected.

use nalgebra::Vector3;

use super::{box_points, Rng};
use crate::physics::detect::{ConvexHull, HullError};
use crate::physics::Shape;

#[test]
fn a_box_given_as_8_points_has_the_box_inertia() {
    let sides = [2.0, 3.0, 5.0];
    let hull = ConvexHull::new(&box_points([1.0, 1.5, 2.5])).unwrap();
    let mass = hull.mass_properties();
    assert!((mass.volume - 30.0).abs() < 1e-12);
    assert!(mass.centroid.norm() < 1e-14);
    let want = Shape::Box { sides }.inertia(7.0).unwrap();
    assert!(
        (hull.inertia(7.0) - want).amax() < 1e-12,
        "{}",
        hull.inertia(7.0)
    );
    assert_eq!(hull.vertices().len(), 8);
    assert_eq!(hull.faces().len(), 6);
    assert_eq!(hull.edges().len(), 12);
    for face in hull.faces() {
        assert_eq!(face.vertices.len(), 4);
        // Outward: every vertex on or behind the face's plane.
        for v in hull.vertices() {
            assert!(face.normal.dot(v) <= face.offset + 1e-12);
        }
    }
}

#[test]
fn a_turned_offset_box_keeps_its_inertia_about_the_centroid() {
    let turn = nalgebra::UnitQuaternion::from_euler_angles(0.3, -0.7, 1.1);
    let shift = Vector3::new(10.0, -4.0, 2.0);
    let pts: Vec<[f64; 3]> = box_points([0.5, 1.0, 1.5])
        .into_iter()
        .map(|p| (turn * Vector3::from(p) + shift).into())
        .collect();
    let hull = ConvexHull::new(&pts).unwrap();
    let mass = hull.mass_properties();
    assert!((mass.centroid - shift).norm() < 1e-12);
    let r = turn.to_rotation_matrix().into_inner();
    let want = r
        * Shape::Box {
            sides: [1.0, 2.0, 3.0],
        }
        .inertia(2.0)
        .unwrap()
        * r.transpose();
    assert!((hull.inertia(2.0) - want).amax() < 1e-11);
}

#[test]
fn a_tetrahedron_has_its_known_volume_centroid_and_inertia() {
    // The corner tetrahedron (0, e1, e2, e3): V = 1/6, centroid (1/4, 1/4, 1/4).
    let hull =
        ConvexHull::new(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]).unwrap();
    let mass = hull.mass_properties();
    assert!((mass.volume - 1.0 / 6.0).abs() < 1e-15);
    assert!((mass.centroid - Vector3::repeat(0.25)).norm() < 1e-15);
    // About the origin, for mass m: I_xx = m/10 (y²+z² terms) = m/5, I_xy = −m/20.
    // About the centroid: I_xx = m/5 − m·(2/16) = 3m/40, I_xy = −m/20 + m/16 = m/80.
    let i = hull.inertia(1.0);
    assert!((i[(0, 0)] - 3.0 / 40.0).abs() < 1e-14, "{i}");
    assert!((i[(0, 1)] - 1.0 / 80.0).abs() < 1e-14, "{i}");
    assert_eq!(hull.faces().len(), 4);
    assert_eq!(hull.edges().len(), 6);
}

#[test]
fn duplicates_and_points_on_faces_and_edges_add_nothing() {
    let mut pts = box_points([1.0, 1.0, 1.0]);
    pts.extend(box_points([1.0, 1.0, 1.0])); // duplicates
    pts.extend([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.3, -1.0, 0.2]]); // on faces
    pts.extend([[1.0, 1.0, 0.0], [0.0, -1.0, 1.0], [1.0, 0.5, -1.0]]); // on edges
    pts.extend([[0.1, 0.2, 0.3], [1.0 - 1e-13, 1.0, 1.0]]); // inside, nearly a corner
    let hull = ConvexHull::new(&pts).unwrap();
    assert_eq!(hull.faces().len(), 6);
    assert_eq!(hull.edges().len(), 12);
    assert!(hull.faces().iter().all(|f| f.vertices.len() == 4));
    assert!((hull.mass_properties().volume - 8.0).abs() < 1e-10);
}

#[test]
fn random_hulls_hold_every_point_and_have_positive_volume() {
    let mut rng = Rng::new(30);
    for _ in 0..100 {
        let pts: Vec<[f64; 3]> = (0..30).map(|_| rng.vector(1.0).into()).collect();
        let hull = ConvexHull::new(&pts).unwrap();
        for p in &pts {
            for f in hull.faces() {
                assert!(f.normal.dot(&Vector3::from(*p)) <= f.offset + 1e-9);
            }
        }
        assert!(hull.mass_properties().volume > 0.0);
        // Euler: V − E + F = 2 for the polygon faces.
        let (v, e, f) = (
            hull.vertices().len(),
            hull.edges().len(),
            hull.faces().len(),
        );
        assert_eq!(v + f, e + 2);
    }
}

#[test]
fn degenerate_clouds_are_rejected_with_the_reason() {
    let e = |pts: &[[f64; 3]]| ConvexHull::new(pts).unwrap_err();
    assert_eq!(e(&[[0.0; 3]; 3]), HullError::TooFewPoints { count: 3 });
    assert_eq!(e(&[[1.0, 2.0, 3.0]; 6]), HullError::Coincident);
    let line: Vec<[f64; 3]> = (0..5).map(|i| [i as f64, 2.0 * i as f64, 0.0]).collect();
    assert_eq!(e(&line), HullError::Collinear);
    let flat: Vec<[f64; 3]> = (0..9)
        .map(|i| [(i % 3) as f64, (i / 3) as f64, 1.0])
        .collect();
    assert_eq!(e(&flat), HullError::Coplanar);
    assert_eq!(
        e(&[
            [0.0; 3],
            [1.0, 0.0, 0.0],
            [f64::NAN, 0.0, 0.0],
            [0.0, 0.0, 1.0]
        ]),
        HullError::NotFinite { index: 2 }
    );
    assert!(e(&flat).to_string().contains("one plane"));
}
