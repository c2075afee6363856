//! The records: each GJK and EPA iteration holds what the lecture draws,
//! and watching a query does not change its answer.

use nalgebra::{UnitQuaternion, Vector3};

use crate::physics::detect::{
    gjk, query, Convex, EpaRecorder, GjkEnd, GjkOptions, GjkRecorder, QueryOptions,
};
use crate::physics::pose::Pose;
use crate::physics::Shape;

fn boxes() -> (Convex, Pose<f64>, Convex, Pose<f64>) {
    let a = Convex::from_shape(&Shape::Box {
        sides: [1.0, 2.0, 1.5],
    })
    .unwrap();
    let b = Convex::from_shape(&Shape::Box {
        sides: [2.0, 1.0, 1.0],
    })
    .unwrap();
    let pa = Pose::from_unit(
        Vector3::new(1.9, 0.7, 0.3),
        &UnitQuaternion::from_euler_angles(0.3, 0.2, 0.5),
    );
    let pb = Pose::from_unit(
        Vector3::new(0.0, 0.0, 0.0),
        &UnitQuaternion::from_euler_angles(-0.1, 0.4, 0.0),
    );
    (a, pa, b, pb)
}

#[test]
fn each_gjk_iteration_follows_from_the_one_before() {
    let (a, mut pa, b, pb) = boxes();
    pa.position.x += 1.0;
    let mut rec = GjkRecorder::default();
    let r = gjk(&a, &pa, &b, &pb, &GjkOptions::default(), &mut rec);
    assert_eq!(rec.runs, 1);
    assert_eq!(rec.iterations.len(), r.iterations);
    assert!(r.iterations >= 2);
    for (k, it) in rec.iterations.iter().enumerate() {
        assert_eq!(it.index, k);
        let w = it.support;
        assert!((w.w - (w.a - w.b)).norm() < 1e-12);
        // w_k's points are the supports along d_k and −d_k.
        assert!((w.a - Support::support(&a, &pa, &it.direction)).norm() < 1e-12);
        assert!((w.b - Support::support(&b, &pb, &-it.direction)).norm() < 1e-12);
        // One rule: the row's d_k, bound and v_k belong to the same pass,
        // and v_k is where the pass before it ended (v_{k+1} of row k − 1).
        assert_eq!(it.direction, -it.v);
        if k > 0 {
            assert_eq!(Some(it.v), rec.iterations[k - 1].next);
        }
        let v = it.v;
        assert!((it.bound - (v.norm_squared() - v.dot(&w.w))).abs() < 1e-12);
        assert!(it.simplex_len >= 1 && it.simplex_len <= 4);
        assert!(it.kept != 0 && it.kept >> it.simplex_len == 0);
    }
    let last = rec.iterations.last().unwrap();
    assert_eq!(r.end, GjkEnd::Converged);
    assert!(last.bound <= last.bound_limit);
    assert_eq!(last.next, None);
    assert!((last.v.norm() - r.distance).abs() < 1e-12);
    // Unwatched, the same answer.
    assert_eq!(gjk(&a, &pa, &b, &pb, &GjkOptions::default(), &mut ()), r);
}

use crate::physics::detect::Support;

#[test]
fn each_epa_split_removes_the_faces_it_sees_and_closes_the_horizon() {
    let (a, mut pa, b, pb) = boxes();
    pa.position = Vector3::new(1.0, 0.6, 0.2);
    let (mut g, mut e) = (GjkRecorder::default(), EpaRecorder::default());
    let q = query(&a, &pa, &b, &pb, &QueryOptions::default(), &mut g, &mut e);
    let epa = q.epa.unwrap();
    assert_eq!(e.iterations.len(), epa.iterations);
    let mut last_distance = f64::NEG_INFINITY;
    for rec in &e.iterations {
        let it = rec.iteration;
        assert_eq!(rec.removed.len(), it.removed);
        assert_eq!(rec.added.len(), it.added);
        // A split of a closed triangle mesh: the new faces are 2 more than the removed.
        if it.added > 0 {
            assert_eq!(it.added, it.removed + 2, "{it:?}");
        }
        assert!(it.distance >= last_distance - 1e-12);
        last_distance = it.distance;
        assert!((it.gap - (it.normal.dot(&it.support.w) - it.distance)).abs() < 1e-12);
    }
    let last = e.iterations.last().unwrap().iteration;
    assert!(last.gap <= epa.tolerance);
    assert!((epa.depth - last.distance).abs() < 1e-15);
    // The points: A's deepest point is depth·normal behind B's.
    assert!((epa.point_a - (epa.point_b - epa.normal * epa.depth)).norm() < 1e-9);
    let plain = query(&a, &pa, &b, &pb, &QueryOptions::default(), &mut (), &mut ());
    assert_eq!(plain, q);
}

#[test]
fn a_sphere_centre_inside_a_box_runs_epa_on_the_cores_and_adds_the_radius() {
    let ball = Convex::Sphere { radius: 1.0 };
    let cube = Convex::Cuboid { half: [1.0; 3] };
    let (pa, pb) = (
        Pose::<f64>::at(Vector3::new(0.2, 0.5, 0.0)),
        Pose::at(Vector3::zeros()),
    );
    let mut g = GjkRecorder::default();
    let q = query(
        &ball,
        &pa,
        &cube,
        &pb,
        &QueryOptions::default(),
        &mut g,
        &mut (),
    );
    assert_eq!(g.runs, 1);
    let p = q.penetration.unwrap();
    // Out through the top face: (1 − 0.5) + 1, exactly.
    assert!((p.depth - 1.5).abs() < 1e-12, "{}", p.depth);
    assert!((p.normal - Vector3::y()).norm() < 1e-12);
    assert!((p.point_a - Vector3::new(0.2, -0.5, 0.0)).norm() < 1e-12);
    assert!((p.point_b - Vector3::new(0.2, 1.0, 0.0)).norm() < 1e-12);
}

#[test]
fn crossing_flat_cores_penetrate_by_the_sum_of_the_margins() {
    let (a, b) = (
        Convex::Sphere { radius: 1.0 },
        Convex::Sphere { radius: 0.5 },
    );
    let at = Pose::<f64>::at(Vector3::new(3.0, -1.0, 2.0));
    let mut g = GjkRecorder::default();
    let q = query(&a, &at, &b, &at, &QueryOptions::default(), &mut g, &mut ());
    assert_eq!(g.runs, 1);
    let p = q.penetration.unwrap();
    // Concentric: any direction will do; the depth is the sum of the radii.
    assert_eq!(p.depth, 1.5);
    assert!((p.normal.norm() - 1.0).abs() < 1e-12);
    // Two capsules crossing at right angles: out along the common normal.
    let cap = Convex::Capsule(crate::physics::detect::Capsule {
        radius: 0.3,
        height: 2.0,
    });
    let lying = Pose::from_unit(
        Vector3::new(0.0, 0.1, 0.0),
        &UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2),
    );
    let standing = Pose::from_unit(
        Vector3::zeros(),
        &UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_2),
    );
    let q = query(
        &cap,
        &lying,
        &cap,
        &standing,
        &QueryOptions::default(),
        &mut (),
        &mut (),
    );
    let p = q.penetration.unwrap();
    // Cores 0.1 apart along y: the margins path, 0.6 − 0.1.
    assert!((p.depth - 0.5).abs() < 1e-12 && (p.normal - Vector3::y()).norm() < 1e-12);
    let crossing = Pose {
        position: Vector3::zeros(),
        ..lying
    };
    let p = query(
        &cap,
        &crossing,
        &cap,
        &standing,
        &QueryOptions::default(),
        &mut (),
        &mut (),
    )
    .penetration
    .unwrap();
    assert!((p.depth - 0.6).abs() < 1e-12, "{}", p.depth);
    assert!(p.normal.y.abs() > 1.0 - 1e-12, "{}", p.normal);
}
