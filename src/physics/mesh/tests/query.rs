//! The mid phase against an independent closest-point computation over
//! every triangle, and the internal-edge correction.

use nalgebra::Vector3;

use super::terrain;
use crate::physics::collide::mesh_query::{mesh_convex, MeshQuery};
use crate::physics::detect::Convex;
use crate::physics::mesh::triangle::closest_point;
use crate::physics::mesh::TriMesh;
use crate::physics::pose::Pose;
use crate::physics::Shape;

/// Distance from p to triangle abc without Voronoi regions: the plane's
/// foot if it is inside (all three edge tests), otherwise the nearest of
/// the three segments.
fn independent_distance(p: &Vector3<f64>, [a, b, c]: &[Vector3<f64>; 3]) -> f64 {
    let n = (b - a).cross(&(c - a)).normalize();
    let foot = p - n * (p - a).dot(&n);
    let inside = [(a, b), (b, c), (c, a)]
        .iter()
        .all(|(u, w)| (*w - *u).cross(&(foot - *u)).dot(&n) >= 0.0);
    if inside {
        return (p - foot).norm();
    }
    [(a, b), (b, c), (c, a)]
        .iter()
        .map(|(u, w)| {
            let e = *w - *u;
            let s = ((p - *u).dot(&e) / e.norm_squared()).clamp(0.0, 1.0);
            (p - (*u + e * s)).norm()
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn closest_points_agree_with_the_independent_distance() {
    let tri = [
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(2.0, 0.1, 0.0),
        Vector3::new(0.5, 0.2, 1.5),
    ];
    for i in 0..400 {
        let f = i as f64;
        let p = Vector3::new(
            (f * 0.731).sin() * 3.0,
            (f * 1.37).cos() * 2.0,
            (f * 0.419).sin() * 3.0,
        );
        let (q, _) = closest_point(&p, &tri);
        assert!(((p - q).norm() - independent_distance(&p, &tri)).abs() < 1e-12);
    }
}

#[test]
fn mesh_sphere_distance_agrees_with_every_triangle_to_1e_9() {
    let (v, t) = terrain(12, 0.5);
    let mesh = TriMesh::new(&v, &t).unwrap();
    let mesh_pose = Pose::at(Vector3::new(-1.0, 0.5, 2.0));
    let sphere = Convex::from_shape(&Shape::Sphere { radius: 0.3 }).unwrap();
    for k in 0..60 {
        let f = k as f64;
        let centre = Vector3::new(
            -1.0 + (f * 0.53) % 6.0,
            1.0 + 0.4 * (f * 0.9).sin(),
            2.0 + (f * 0.77) % 6.0,
        );
        let pose = Pose::at(centre);
        let q = mesh_convex(&sphere, &pose, &mesh, &mesh_pose, 0.5, true);
        let local = mesh_pose.to_local(&centre);
        let want = (0..t.len())
            .map(|i| independent_distance(&local, &mesh.corners(i)))
            .fold(f64::INFINITY, f64::min)
            - 0.3;
        if want > 0.0 && want < 0.5 {
            assert!(
                (q.distance - want).abs() < 1e-9,
                "{k}: {} vs {want}",
                q.distance
            );
        }
        assert!(q.candidates.len() < t.len() / 4, "the tree pruned nothing");
    }
}

#[test]
fn mesh_box_distance_agrees_with_every_triangle_to_1e_9() {
    let (v, t) = terrain(10, 0.5);
    let mesh = TriMesh::new(&v, &t).unwrap();
    let mesh_pose = Pose::at(Vector3::zeros());
    let cube = Convex::from_shape(&Shape::Box {
        sides: [0.4, 0.3, 0.5],
    })
    .unwrap();
    let mut checked = 0;
    for k in 0..60 {
        let f = k as f64;
        let rot = nalgebra::UnitQuaternion::from_euler_angles(f * 0.3, f * 0.7, f * 0.11);
        let pose = Pose::from_unit(
            Vector3::new(
                0.5 + (f * 0.53) % 4.0,
                0.55 + 0.2 * (f * 0.9).sin(),
                0.5 + (f * 0.77) % 4.0,
            ),
            &rot,
        );
        let q = mesh_convex(&cube, &pose, &mesh, &mesh_pose, 0.3, true);
        // Independent: box corners to each triangle, triangle corners to the
        // box, and the box's edges against the triangle's (segment pairs,
        // sampled finely then refined by the corners' minimum).
        let corners: Vec<Vector3<f64>> = (0..8)
            .map(|i| {
                let s = |bit: usize, h: f64| if i & bit != 0 { h } else { -h };
                pose.to_world(&Vector3::new(s(1, 0.2), s(2, 0.15), s(4, 0.25)))
            })
            .collect();
        let to_box = |p: &Vector3<f64>| {
            let l = pose.to_local(p);
            let h = Vector3::new(0.2, 0.15, 0.25);
            let d = l.abs() - h;
            d.sup(&Vector3::zeros()).norm()
        };
        let edges: Vec<(usize, usize)> = (0..8)
            .flat_map(|i| {
                [1, 2, 4]
                    .into_iter()
                    .filter(move |b| i & b == 0)
                    .map(move |b| (i, i | b))
            })
            .collect();
        let want = (0..t.len())
            .map(|i| {
                let c = mesh.corners(i);
                let mut d = corners
                    .iter()
                    .map(|p| independent_distance(p, &c))
                    .fold(f64::INFINITY, f64::min);
                d = d.min(c.iter().map(to_box).fold(f64::INFINITY, f64::min));
                for &(a, b) in &edges {
                    for k in 0..3 {
                        d = d.min(segment_distance(
                            corners[a],
                            corners[b],
                            c[k],
                            c[(k + 1) % 3],
                        ));
                    }
                    if segment_crosses_triangle(corners[a], corners[b], &c) {
                        d = 0.0;
                    }
                }
                let h = Vector3::new(0.2, 0.15, 0.25);
                for k in 0..3 {
                    let (p, q) = (pose.to_local(&c[k]), pose.to_local(&c[(k + 1) % 3]));
                    if segment_crosses_box(p, q, h) {
                        d = 0.0;
                    }
                }
                d
            })
            .fold(f64::INFINITY, f64::min);
        if want > 1e-6 && want < 0.3 {
            checked += 1;
            assert!(
                (q.distance - want).abs() < 1e-9,
                "{k}: {} vs {want}",
                q.distance
            );
        }
    }
    assert!(checked > 10, "only {checked} separated poses");
}

/// Whether segment pq passes through triangle c (plane crossing inside).
fn segment_crosses_triangle(p: Vector3<f64>, q: Vector3<f64>, c: &[Vector3<f64>; 3]) -> bool {
    let n = (c[1] - c[0]).cross(&(c[2] - c[0]));
    let (dp, dq) = ((p - c[0]).dot(&n), (q - c[0]).dot(&n));
    if dp * dq > 0.0 || dp == dq {
        return false;
    }
    let x = p + (q - p) * (dp / (dp - dq));
    (0..3).all(|k| (c[(k + 1) % 3] - c[k]).cross(&(x - c[k])).dot(&n) >= 0.0)
}

/// Whether segment pq meets the box of half sides h (slab clipping).
fn segment_crosses_box(p: Vector3<f64>, q: Vector3<f64>, h: Vector3<f64>) -> bool {
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for i in 0..3 {
        let d = q[i] - p[i];
        if d.abs() < 1e-300 {
            if p[i].abs() > h[i] {
                return false;
            }
            continue;
        }
        let (t0, t1) = ((-h[i] - p[i]) / d, (h[i] - p[i]) / d);
        lo = lo.max(t0.min(t1));
        hi = hi.min(t0.max(t1));
    }
    lo <= hi
}

/// Distance between segments pq and rs (Ericson 5.1.9, written out here).
fn segment_distance(p: Vector3<f64>, q: Vector3<f64>, r: Vector3<f64>, s: Vector3<f64>) -> f64 {
    let (d1, d2, w) = (q - p, s - r, p - r);
    let (a, e, f) = (d1.norm_squared(), d2.norm_squared(), d2.dot(&w));
    let (b, c) = (d1.dot(&d2), d1.dot(&w));
    let denom = a * e - b * b;
    let mut u = if denom > 1e-300 {
        ((b * f - c * e) / denom).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let mut v = (b * u + f) / e;
    if v < 0.0 {
        v = 0.0;
        u = (-c / a).clamp(0.0, 1.0);
    } else if v > 1.0 {
        v = 1.0;
        u = ((b - c) / a).clamp(0.0, 1.0);
    }
    ((p + d1 * u) - (r + d2 * v)).norm()
}

#[test]
fn a_flat_shared_edge_gets_the_face_normal_with_fix() {
    // Two coplanar triangles; a box corner over their shared diagonal,
    // sunk 1 cm: the raw EPA normal may lean, the fixed one is +y.
    let v = [
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 2.0],
        [2.0, 0.0, 0.0],
        [2.0, 0.0, 2.0],
    ];
    let t = [[0, 1, 2], [2, 1, 3]];
    let mesh = TriMesh::new(&v, &t).unwrap();
    let cube = Convex::from_shape(&Shape::Box { sides: [0.2; 3] }).unwrap();
    let pose = Pose::from_unit(
        Vector3::new(1.0, 0.1 * 3f64.sqrt() - 0.01, 1.0),
        &nalgebra::UnitQuaternion::rotation_between(&Vector3::new(1.0, 1.0, 1.0), &Vector3::y())
            .unwrap(),
    );
    let q = mesh_convex(&cube, &pose, &mesh, &Pose::at(Vector3::zeros()), 0.0, true);
    assert_eq!(q.candidates, vec![0, 1]);
    for test in &q.triangles {
        assert!((test.normal - Vector3::y()).norm() < 1e-12, "{:?}", test);
        assert!(
            (test.penetration - 0.01).abs() < 1e-9,
            "{}",
            test.penetration
        );
    }
}

#[test]
fn a_box_overlapping_the_next_triangle_by_a_sliver_is_pushed_back_raw_and_up_fixed() {
    // Two unit squares along x, two triangles each; a box sunk 1 cm whose
    // front reaches 5 mm over the shared edge x = 1: raw EPA on the next
    // triangle pushes it back along -x (the ghost bump), the fix lifts it.
    let v: Vec<[f64; 3]> = (0..3)
        .flat_map(|i| (0..2).map(move |j| [i as f64, 0.0, j as f64]))
        .collect();
    let at = |i: usize, j: usize| i * 2 + j;
    let t: Vec<[usize; 3]> = (0..2)
        .flat_map(|i| {
            [
                [at(i, 0), at(i, 1), at(i + 1, 0)],
                [at(i + 1, 0), at(i, 1), at(i + 1, 1)],
            ]
        })
        .collect();
    let mesh = TriMesh::new(&v, &t).unwrap();
    let cube = Convex::from_shape(&Shape::Box { sides: [0.2; 3] }).unwrap();
    let pose = Pose::at(Vector3::new(0.905, 0.09, 0.5));
    let origin = Pose::at(Vector3::zeros());
    let raw = mesh_convex(&cube, &pose, &mesh, &origin, 0.0, false);
    let fixed = mesh_convex(&cube, &pose, &mesh, &origin, 0.0, true);
    let next = |q: &MeshQuery| q.triangles.iter().find(|x| x.triangle == 2).cloned();
    let (r, f) = (next(&raw).unwrap(), next(&fixed).unwrap());
    assert!(r.normal.x < -0.99 && !r.corrected(), "raw {:?}", r.normal);
    assert!(
        (r.penetration - 0.005).abs() < 1e-9,
        "raw depth {}",
        r.penetration
    );
    assert!(f.corrected() && (f.normal - Vector3::y()).norm() < 1e-12);
    assert!(
        (f.penetration - 0.01).abs() < 1e-9,
        "fixed depth {}",
        f.penetration
    );
    assert_eq!(f.raw_normal, r.raw_normal);
}

#[test]
fn a_large_mesh_builds_a_balanced_tree() {
    // 80,000 triangles: median splits give depth ⌈log2 n⌉ + 1 = 18.
    let (v, t) = terrain(200, 0.1);
    let mesh = TriMesh::new(&v, &t).unwrap();
    assert_eq!(mesh.bvh().nodes().len(), 2 * t.len() - 1);
    assert_eq!(mesh.bvh().depth(), 18);
}
