//! GJK distance against closed forms, 1e-9 relative: sphere–sphere
//! (|c₁ − c₂| − r₁ − r₂), sphere–box (the box's surface distance from the
//! centre, minus r), capsule–capsule (segment–segment distance − r₁ − r₂).

use nalgebra::Vector3;

use super::reference::closest_segments;
use super::{relative, Rng};
use crate::physics::detect::{gjk, Capsule, Convex, GjkOptions, GjkVerdict};
use crate::physics::pose::Pose;
use crate::physics::Shape;

fn distance(
    a: &Convex,
    pa: &Pose<f64>,
    b: &Convex,
    pb: &Pose<f64>,
) -> (GjkVerdict, f64, Vector3<f64>, Vector3<f64>) {
    let r = gjk(a, pa, b, pb, &GjkOptions::default(), &mut ());
    assert!(r.distance.is_finite());
    (r.verdict, r.distance, r.closest_a, r.closest_b)
}

#[test]
fn sphere_sphere_distance_is_the_centre_gap_minus_the_radii() {
    let mut rng = Rng::new(1);
    for _ in 0..500 {
        let (r1, r2) = (rng.range(0.1, 2.0), rng.range(0.1, 2.0));
        let (pa, pb) = (rng.pose(5.0), rng.pose(5.0));
        let want = (pa.position - pb.position).norm() - r1 - r2;
        let (a, b) = (Convex::Sphere { radius: r1 }, Convex::Sphere { radius: r2 });
        let (verdict, got, ca, cb) = distance(&a, &pa, &b, &pb);
        if want > 1e-6 {
            assert_eq!(verdict, GjkVerdict::Separated);
            assert!(relative(got, want, 1e-12) < 1e-9, "{got} vs {want}");
            // The closest points lie on the spheres, `distance` apart.
            assert!(((ca - pa.position).norm() - r1).abs() < 1e-9);
            assert!(((cb - pb.position).norm() - r2).abs() < 1e-9);
            assert!(relative((ca - cb).norm(), want, 1e-12) < 1e-9);
        } else if want < -1e-6 {
            assert_eq!(verdict, GjkVerdict::Intersecting);
            assert_eq!(got, 0.0);
        }
    }
}

#[test]
fn sphere_box_distance_is_the_surface_distance_minus_the_radius() {
    let mut rng = Rng::new(2);
    let mut separated = 0;
    for _ in 0..500 {
        let sides = [
            rng.range(0.2, 3.0),
            rng.range(0.2, 3.0),
            rng.range(0.2, 3.0),
        ];
        let shape = Shape::Box { sides };
        let r = rng.range(0.1, 1.0);
        let (pa, pb) = (rng.pose(4.0), rng.pose(4.0));
        let want = shape.surface_distance(&pb.to_local(&pa.position)) - r;
        let (verdict, got, _, _) = distance(
            &Convex::Sphere { radius: r },
            &pa,
            &Convex::from_shape(&shape).unwrap(),
            &pb,
        );
        if want > 1e-6 {
            separated += 1;
            assert_eq!(verdict, GjkVerdict::Separated);
            assert!(relative(got, want, 1e-12) < 1e-9, "{got} vs {want}");
        } else if want < -1e-6 {
            assert_eq!(verdict, GjkVerdict::Intersecting);
        }
    }
    assert!(separated > 300, "{separated}");
}

#[test]
fn capsule_capsule_distance_is_the_segment_distance_minus_the_radii() {
    let mut rng = Rng::new(3);
    let mut separated = 0;
    for _ in 0..500 {
        let caps = [0, 1].map(|_| Capsule {
            radius: rng.range(0.05, 0.8),
            height: rng.range(0.0, 3.0),
        });
        let poses = [rng.pose(3.0), rng.pose(3.0)];
        let ends = |k: usize| {
            let h = caps[k].height / 2.0;
            (
                poses[k].to_world(&Vector3::new(0.0, h, 0.0)),
                poses[k].to_world(&Vector3::new(0.0, -h, 0.0)),
            )
        };
        let ((p1, q1), (p2, q2)) = (ends(0), ends(1));
        let (x, y) = closest_segments(&p1, &q1, &p2, &q2);
        let want = (x - y).norm() - caps[0].radius - caps[1].radius;
        let (verdict, got, _, _) = distance(
            &Convex::Capsule(caps[0]),
            &poses[0],
            &Convex::Capsule(caps[1]),
            &poses[1],
        );
        if want > 1e-6 {
            separated += 1;
            assert_eq!(verdict, GjkVerdict::Separated);
            assert!(relative(got, want, 1e-12) < 1e-9, "{got} vs {want}");
        } else if want < -1e-6 {
            assert_eq!(verdict, GjkVerdict::Intersecting);
        }
    }
    assert!(separated > 200, "{separated}");
}

#[test]
fn the_closest_points_are_the_distance_apart_for_every_shape() {
    let mut rng = Rng::new(4);
    for k in 0..600u64 {
        let (a, b) = (rng.shape(k), rng.shape(k / 6));
        let (pa, pb) = (rng.pose(4.0), rng.pose(4.0));
        let r = gjk(&a, &pa, &b, &pb, &GjkOptions::default(), &mut ());
        if r.verdict == GjkVerdict::Separated {
            assert!(relative((r.closest_a - r.closest_b).norm(), r.distance, 1e-12) < 1e-9);
        }
    }
}

/// True when segment pq (box frame) meets the box of half sides h
/// (Liang–Barsky: the parameter interval left after the three slabs).
fn crosses(p: &Vector3<f64>, q: &Vector3<f64>, h: &[f64; 3]) -> bool {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for k in 0..3 {
        let d = q[k] - p[k];
        if d.abs() < 1e-300 {
            if p[k].abs() > h[k] {
                return false;
            }
            continue;
        }
        let (a, b) = ((-h[k] - p[k]) / d, (h[k] - p[k]) / d);
        t0 = t0.max(a.min(b));
        t1 = t1.min(a.max(b));
    }
    t0 < t1
}

#[test]
fn capsule_box_distance_is_the_segment_to_box_distance_minus_the_radius() {
    let mut rng = Rng::new(5);
    let mut separated = 0;
    for _ in 0..300 {
        let cap = Capsule {
            radius: rng.range(0.05, 0.8),
            height: rng.range(0.0, 3.0),
        };
        let cuboid = Convex::Cuboid {
            half: [
                rng.range(0.1, 1.5),
                rng.range(0.1, 1.5),
                rng.range(0.1, 1.5),
            ],
        };
        let (pa, pb) = (rng.pose(3.0), rng.pose(3.0));
        let h = cap.height / 2.0;
        let (p, q) = (
            pa.to_world(&Vector3::new(0.0, h, 0.0)),
            pa.to_world(&Vector3::new(0.0, -h, 0.0)),
        );
        // Segment to box: its ends against the faces, the segment against the edges.
        let (_, tris, edges) = super::reference::mesh(&cuboid, &pb);
        let mut d = f64::INFINITY;
        for t in &tris {
            for e in [p, q] {
                d = d.min(
                    (super::reference::closest_on_triangle(&e, &t[0], &t[1], &t[2]) - e).norm(),
                );
            }
        }
        for e in &edges {
            let (x, y) = closest_segments(&p, &q, &e[0], &e[1]);
            d = d.min((x - y).norm());
        }
        let want = d - cap.radius;
        let (verdict, got, _, _) = distance(&Convex::Capsule(cap), &pa, &cuboid, &pb);
        let Convex::Cuboid { half } = cuboid else {
            unreachable!()
        };
        if crosses(&pb.to_local(&p), &pb.to_local(&q), &half) {
            assert_eq!(verdict, GjkVerdict::Intersecting);
        } else if want > 1e-6 {
            separated += 1;
            assert_eq!(verdict, GjkVerdict::Separated);
            assert!(relative(got, want, 1e-12) < 1e-9, "{got} vs {want}");
        }
    }
    assert!(separated > 150, "{separated}");
}
