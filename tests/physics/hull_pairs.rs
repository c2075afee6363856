//! Convex hulls from lessons in contact: every pair kind keeps the contact
//! conventions, a hull box agrees with the analytic box, and the
//! `hull-stack` scene (three hulls on the floor) stands for 10 s.

use crate::collide_support::{check_pair, collide_all, pose};
use contact_lab::lesson::Lesson;
use contact_lab::physics::collide::BoxBoxMode;
use contact_lab::physics::detect::ConvexHull;
use contact_lab::physics::step::energy;
use contact_lab::physics::step::Simulation;
use contact_lab::physics::Shape;
use nalgebra::{UnitQuaternion, Vector3};
use std::sync::Arc;

/// A hull of the eight corners of a box of sides `s`.
fn hull_box(s: [f64; 3]) -> Shape {
    let mut pts = vec![];
    for i in 0..8 {
        let bit = |k: usize| if i >> k & 1 == 1 { 0.5 } else { -0.5 };
        pts.push([bit(0) * s[0], bit(1) * s[1], bit(2) * s[2]]);
    }
    Shape::Hull(Arc::new(ConvexHull::new(&pts).unwrap()))
}

fn tetra() -> Shape {
    let pts = [
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ];
    Shape::Hull(Arc::new(
        ConvexHull::new(&pts.map(|p| p.map(|x| 0.4 * x))).unwrap(),
    ))
}

#[test]
fn a_hull_collides_with_every_shape_and_keeps_the_conventions() {
    let turn = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    let hull = (tetra(), pose([0.1, 1.05, -0.05], turn));
    let others = [
        Shape::Box {
            sides: [2.0, 1.0, 2.0],
        },
        Shape::Sphere { radius: 0.5 },
        Shape::Cylinder {
            radius: 0.5,
            height: 1.0,
        },
        Shape::Capsule {
            radius: 0.3,
            height: 0.6,
        },
        hull_box([2.0, 1.0, 2.0]),
        Shape::HalfSpace {
            normal: [0.0, 1.0, 0.0],
        },
    ];
    for other in &others {
        // The floor through y = 0.5, where the box's top is.
        let lift = if other.is_finite() { 0.0 } else { 0.5 };
        let at = pose([0.0, lift, 0.0], UnitQuaternion::identity());
        // A ball on a vertex: the point is midway between the vertex and
        // the ball's deepest point (as box–sphere puts it; see the closed
        // form below), which lies outside the hull beside a sharp vertex by
        // up to half the depth (depth ≈ 0.08).
        let curved = matches!(other, Shape::Sphere { .. } | Shape::Capsule { .. });
        let extra = if curved { 0.05 } else { 0.0 };
        let out = check_pair(
            (&hull.0, &hull.1),
            (other, &at),
            BoxBoxMode::Manifold,
            extra,
        );
        assert!(!out.is_empty(), "tetrahedron–{other:?}: no contact");
    }
}

#[test]
fn a_hull_box_on_a_box_has_the_analytic_depth_and_normal() {
    let block = Shape::Box {
        sides: [2.0, 1.0, 2.0],
    };
    let brick = [1.0, 0.5, 1.0];
    let turn = UnitQuaternion::from_euler_angles(0.0, 0.4, 0.0);
    let top = pose([0.1, 0.73, 0.2], turn);
    let below = pose([0.0, 0.0, 0.0], UnitQuaternion::identity());
    let analytic = check_pair(
        (&Shape::Box { sides: brick }, &top),
        (&block, &below),
        BoxBoxMode::Manifold,
        0.0,
    );
    let hulled = check_pair(
        (&hull_box(brick), &top),
        (&block, &below),
        BoxBoxMode::Manifold,
        0.0,
    );
    let deepest = |c: &[contact_lab::physics::collide::ContactPoint<f64>]| {
        c.iter().map(|c| c.penetration).fold(f64::MIN, f64::max)
    };
    // The brick's bottom at 0.73 − 0.25 = 0.48, 2 cm into the top face.
    assert!((deepest(&analytic) - 0.02).abs() < 1e-9);
    assert!((deepest(&hulled) - 0.02).abs() < 1e-9, "{hulled:?}");
    for c in &hulled {
        assert!((c.normal - Vector3::y()).norm() < 1e-9, "{c:?}");
    }
    assert_eq!(
        hulled.len(),
        4,
        "a face–face manifold of the brick's corners"
    );
}

/// The scene with sleep off, so every step is simulated.
fn hull_stack() -> Simulation<f64> {
    let lesson = Lesson::load("hull-stack").unwrap();
    let mut params = lesson.sim_params().expect("a scene");
    params.sleep.enabled = false;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, params, lesson.simulation.unwrap().materials)
}

#[test]
fn three_hulls_stacked_stand_for_ten_seconds_without_gaining_energy() {
    let mut sim = hull_stack();
    let g = sim.params.world.gravity;
    let start: Vec<Vector3<f64>> = sim.world.bodies.iter().map(|b| b.state.position).collect();
    let e0 = energy::total(&sim.world, &g);
    let mut highest = e0;
    for _ in 0..600 {
        sim.advance().expect("the stack does not blow up");
        highest = highest.max(energy::total(&sim.world, &g));
    }
    // No energy gain beyond round-off: the stack only settles.
    assert!(highest <= e0 + 1e-9 * e0.abs(), "{highest} > {e0}");
    for (i, b) in sim.world.bodies.iter().enumerate().take(3) {
        // Relative to the body below (the floor for the first): each hull
        // sinks into it by under the resolver's 1 cm position epsilon and
        // slides on it by under a centimetre: still stacked.
        let below = |k: usize| {
            if k == 0 {
                Vector3::zeros()
            } else {
                sim.world.bodies[k - 1].state.position - start[k - 1]
            }
        };
        let moved = b.state.position - start[i] - below(i);
        assert!(moved.y.abs() < 0.01, "body {i} moved {moved}");
        assert!(moved.xz().norm() < 0.01, "body {i} moved {moved}");
        let up = UnitQuaternion::new_normalize(b.state.orientation) * Vector3::y();
        assert!(up.y > 0.999, "body {i} tilted: {up}");
        // Awake (sleep off), a resting body keeps what the last step's
        // micro-collisions left: about a centimetre per second (g·dt = 16 cm/s).
        assert!(
            b.state.velocity.norm() < 0.02,
            "body {i}: {}",
            b.state.velocity
        );
    }
}

#[test]
fn a_sphere_on_a_hull_vertex_touches_on_the_line_through_the_vertex() {
    // Closed form: centre c, radius r, vertex v at distance d < r: depth
    // r − d along n = (c − v)/d (hull → sphere), the point midway between
    // the vertex and the sphere's deepest point c − r n, i.e. v − ½ depth n,
    // as box–sphere puts it (on the line of the normal through both).
    let ball = Shape::Sphere { radius: 0.5 };
    let turn = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    let (hull, at) = (tetra(), pose([0.0, 0.0, 0.0], turn));
    let top = [1.0, 1.0, 1.0].map(|x| 0.4 * x);
    let v = at.to_world(&Vector3::from(top));
    for (dir, d) in [
        (Vector3::new(0.3, 1.0, 0.2), 0.45),
        (Vector3::new(0.1, 0.6, 1.0), 0.3),
        (Vector3::new(1.0, 1.0, 1.0), 0.49),
    ] {
        // Keep the direction in the vertex's normal cone: the hull's point
        // nearest the centre must be the vertex.
        let n = (turn * dir).normalize();
        let c = v + n * d;
        let sphere = pose([c.x, c.y, c.z], UnitQuaternion::identity());
        let out = collide_all((&ball, &sphere), (&hull, &at), BoxBoxMode::Manifold);
        assert_eq!(out.len(), 1, "{out:?}");
        let k = out[0];
        let depth = 0.5 - d;
        assert!((k.penetration - depth).abs() < 1e-9, "{k:?} vs {depth}");
        assert!((k.normal - n).norm() < 1e-9, "{k:?} vs {n}");
        let expected = v - n * (0.5 * depth);
        assert!(
            (k.point - expected).norm() < 1e-9,
            "{:?} is {} from v − ½ depth n",
            k.point,
            (k.point - expected).norm()
        );
    }
    // The same at a box's corner: the analytic box–sphere routine and the
    // hull of the box's corners (GJK with the sphere's margin) agree.
    let sides = [1.0, 0.6, 0.8];
    let corner = Vector3::new(0.5, 0.3, 0.4);
    let at = pose([0.2, -0.1, 0.3], turn);
    let c = at.to_world(&(corner + Vector3::new(0.2, 0.25, 0.15).normalize() * 0.42));
    let sphere = pose([c.x, c.y, c.z], UnitQuaternion::identity());
    let analytic = collide_all(
        (&ball, &sphere),
        (&Shape::Box { sides }, &at),
        BoxBoxMode::Manifold,
    );
    let hulled = collide_all(
        (&ball, &sphere),
        (&hull_box(sides), &at),
        BoxBoxMode::Manifold,
    );
    assert_eq!((analytic.len(), hulled.len()), (1, 1));
    let (a, h) = (analytic[0], hulled[0]);
    assert!((a.penetration - 0.08).abs() < 1e-9, "{a:?}");
    assert!((a.penetration - h.penetration).abs() < 1e-9, "{a:?} {h:?}");
    assert!((a.normal - h.normal).norm() < 1e-9, "{a:?} {h:?}");
    assert!((a.point - h.point).norm() < 1e-9, "{a:?} {h:?}");
}
