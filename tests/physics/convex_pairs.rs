//! Every convex pair collides: pairs without an analytic routine (cylinder
//! with a box, a sphere, a cylinder) run GJK/EPA and the clipped manifold,
//! and `[world] narrow_phase = "gjk"` runs it for every pair. Scenes are
//! checked against invariants (rest on top of the support, no sinking).

use crate::collide_support::check_pair;
use contact_lab::lesson::validate::parse;
use contact_lab::physics::collide::BoxBoxMode;
use contact_lab::physics::collide::{collide_with, Options, Pose};
use contact_lab::physics::params::NarrowPhase;
use contact_lab::physics::step::Simulation;
use contact_lab::physics::Shape;
use nalgebra::{UnitQuaternion, Vector3};

/// A scene from lesson text, with its own parameters.
fn scene(text: &str) -> Simulation<f64> {
    let lesson = parse("convex_pairs.rs", text).expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

const CAN: Shape = Shape::Cylinder {
    radius: 0.3,
    height: 0.8,
};
const BOX: Shape = Shape::Box {
    sides: [2.0, 1.0, 2.0],
};

fn contacts(a: (&Shape, &Pose<f64>), b: (&Shape, &Pose<f64>), phase: NarrowPhase) -> Vec<f64> {
    let options = Options {
        narrow_phase: phase,
        ..Options::default()
    };
    let mut out = Vec::new();
    collide_with(a, b, &options, &mut out);
    out.iter().map(|c| c.penetration).collect()
}

#[test]
fn a_cylinder_standing_in_a_box_gets_a_manifold_along_the_box_normal() {
    // Cap 2 cm into the box's top face (y = 0.5): the cap's polygon clipped
    // against the face, every point 2 cm deep, normal +y (box → cylinder).
    let can = Pose::at(Vector3::new(0.1, 0.88, -0.2));
    let slab = Pose::at(Vector3::zeros());
    let options = Options::<f64>::default();
    let mut out = Vec::new();
    collide_with((&CAN, &can), (&BOX, &slab), &options, &mut out);
    assert!(out.len() >= 3, "a manifold, not one point: {out:?}");
    for c in &out {
        assert!((c.normal - Vector3::y()).norm() < 1e-9, "{c:?}");
        assert!((c.penetration - 0.02).abs() < 1e-9, "{c:?}");
        assert!((c.point - can.position).xz().norm() <= 0.3 + 1e-9);
    }
    // Swapping the bodies flips the normal and keeps the depths.
    let mut swapped = Vec::new();
    collide_with((&BOX, &slab), (&CAN, &can), &options, &mut swapped);
    assert_eq!(swapped.len(), out.len());
    assert!(swapped
        .iter()
        .all(|c| (c.normal + Vector3::y()).norm() < 1e-9));
}

#[test]
fn cylinder_pairs_no_longer_fall_through_silently() {
    let turned = UnitQuaternion::from_euler_angles(0.3, 0.0, 1.2);
    let here = Pose::at(Vector3::zeros());
    let near = Pose::from_unit(Vector3::new(0.35, 0.2, 0.0), &turned);
    let ball = Shape::Sphere { radius: 0.25 };
    for other in [CAN, BOX, ball] {
        let found = contacts((&CAN, &here), (&other, &near), NarrowPhase::Analytic);
        assert!(!found.is_empty(), "cylinder–{other:?} generated nothing");
        assert!(found.iter().all(|p| p.is_finite() && *p > 0.0), "{found:?}");
        if other != CAN {
            check_pair((&CAN, &here), (&other, &near), BoxBoxMode::Manifold, 0.0);
        }
    }
    // Two cylinders 47 cm deep into each other (above) are still 5e-4 into
    // each other after A moves by the depth along the manifold's normal (two
    // curved rims, polygonal caps: a known limit, left open); a shallow pair,
    // one can tilted on another's cap, keeps every convention.
    let tilted = UnitQuaternion::from_euler_angles(0.2, 0.0, 0.1);
    let on_top = Pose::from_unit(Vector3::new(0.05, 0.83, 0.0), &tilted);
    check_pair((&CAN, &on_top), (&CAN, &here), BoxBoxMode::Manifold, 0.0);
    // Apart: nothing, with no tolerance.
    let far = Pose::at(Vector3::new(5.0, 0.0, 0.0));
    assert!(contacts((&CAN, &here), (&CAN, &far), NarrowPhase::Analytic).is_empty());
}

#[test]
fn gjk_agrees_with_the_analytic_routines_on_depth() {
    // Sphere–sphere, box–sphere and box–box (face on face): the deepest
    // contact's depth is the same to 1e-9 either way.
    let ball = Shape::Sphere { radius: 0.5 };
    let cube = Shape::Box { sides: [1.0; 3] };
    let pairs = [
        (ball.clone(), Vector3::new(0.3, 0.7, 0.1), ball.clone()),
        (ball, Vector3::new(0.2, 0.9, -0.1), cube.clone()),
        (cube.clone(), Vector3::new(0.1, 0.97, 0.2), cube),
    ];
    for (sa, at, sb) in pairs {
        let (pa, pb) = (Pose::at(at), Pose::at(Vector3::zeros()));
        let deepest = |phase| {
            contacts((&sa, &pa), (&sb, &pb), phase)
                .into_iter()
                .fold(f64::NEG_INFINITY, f64::max)
        };
        let (analytic, gjk) = (deepest(NarrowPhase::Analytic), deepest(NarrowPhase::Gjk));
        assert!(analytic > 0.0);
        assert!(
            (analytic - gjk).abs() < 1e-9,
            "{sa:?}–{sb:?}: {analytic} vs {gjk}"
        );
    }
}

#[test]
fn a_gap_within_the_tolerance_is_a_negative_penetration() {
    let can = Pose::at(Vector3::new(0.0, 0.903, 0.0));
    let slab = Pose::at(Vector3::zeros());
    let options = Options::<f64> {
        tolerance: 0.005,
        ..Options::default()
    };
    let mut out = Vec::new();
    collide_with((&CAN, &can), (&BOX, &slab), &options, &mut out);
    assert!(out.len() >= 3, "{out:?}");
    for c in &out {
        assert!((c.penetration + 0.003).abs() < 1e-9, "{c:?}");
        assert!((c.normal - Vector3::y()).norm() < 1e-9);
    }
}

const CAN_ON_BOX: &str = r#"
id = "can-on-box"
title = "A cylinder dropped on a box"
source = "Lecture IV Collisions"
summary = "A cylinder falls 0.3 m onto a box resting on the floor."

[world]
restitution = 0.2
friction = 0.5

[step]
dt = 0.016666666666666666
steps = 300

[[body]]
name = "can"
mass = 1.0
shape = { cylinder = { radius = 0.3, height = 0.8 } }
position = [0.2, 1.3, -0.1]
orientation = [0.9990482, 0.0436194, 0.0, 0.0]

[[body]]
name = "box"
mass = 4.0
shape = { box = [2, 1, 2] }
position = [0, 0.5, 0]

[[body]]
name = "floor"
mass = inf
shape = "half_space"
position = [0, 0, 0]
"#;

#[test]
fn a_cylinder_dropped_on_a_box_comes_to_rest_on_it() {
    for phase in ["analytic", "gjk"] {
        let text = CAN_ON_BOX.replace("[world]", &format!("[world]\nnarrow_phase = \"{phase}\""));
        let mut sim = scene(&text);
        let mut lowest = f64::INFINITY;
        for step in 0..300 {
            sim.advance().expect("the scene does not blow up");
            if step >= 120 {
                lowest = lowest.min(sim.world.bodies[0].state.position.y);
            }
        }
        let can = &sim.world.bodies[0].state;
        // On the box's top (y = 1) with its cap: centre at 1 + 0.4.
        assert!(
            (can.position.y - 1.4).abs() < 0.02 && lowest > 1.38,
            "{phase}: centre at {} (lowest {lowest}) m",
            can.position.y
        );
        assert!(
            can.velocity.norm() < 0.05,
            "{phase}: {} m/s",
            can.velocity.norm()
        );
        let up = UnitQuaternion::new_normalize(can.orientation) * Vector3::y();
        assert!(up.y > 0.99, "{phase}: standing, axis {up}");
    }
}

#[test]
fn a_capsule_collides_with_every_shape() {
    let pill = Shape::Capsule {
        radius: 0.2,
        height: 1.0,
    };
    // Lying along x (body y turned onto world x), 5 cm into the floor: both
    // end balls touch, each 5 cm deep.
    let turn = UnitQuaternion::from_euler_angles(0.0, 0.0, std::f64::consts::FRAC_PI_2);
    let lying = Pose::from_unit(Vector3::new(0.0, 0.15, 0.0), &turn);
    let floor = Shape::HalfSpace {
        normal: [0.0, 1.0, 0.0],
    };
    let ground = Pose::at(Vector3::zeros());
    let on_floor = contacts((&pill, &lying), (&floor, &ground), NarrowPhase::Analytic);
    assert_eq!(on_floor.len(), 2);
    assert!(
        on_floor.iter().all(|p| (p - 0.05).abs() < 1e-12),
        "{on_floor:?}"
    );
    // On the box's top face (y = 0.5), 3 cm deep: the side segment clipped
    // against the face, two points 3 cm deep.
    let on_box = Pose::from_unit(Vector3::new(0.0, 0.67, 0.0), &turn);
    let found = contacts((&pill, &on_box), (&BOX, &ground), NarrowPhase::Analytic);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found.iter().all(|p| (p - 0.03).abs() < 1e-9), "{found:?}");
    for other in [CAN, Shape::Sphere { radius: 0.3 }, pill.clone()] {
        let near = Pose::at(Vector3::new(0.3, 0.35, 0.1));
        assert!(!contacts((&pill, &lying), (&other, &near), NarrowPhase::Analytic).is_empty());
        // The conventions every pair keeps (finite, unit normal, points
        // between the surfaces, swapping flips, moving A apart separates).
        check_pair((&pill, &lying), (&other, &near), BoxBoxMode::Manifold, 0.0);
    }
    check_pair(
        (&pill, &lying),
        (&floor, &ground),
        BoxBoxMode::Manifold,
        0.0,
    );
    check_pair((&pill, &on_box), (&BOX, &ground), BoxBoxMode::Manifold, 0.0);
}

#[test]
fn a_capsule_from_a_lesson_lies_down_on_the_box() {
    // Dropped tilted onto the box: it ends lying on its side, its axis
    // level, its centre a radius above the box's top (y = 1).
    let text = CAN_ON_BOX
        .replace(
            "shape = { cylinder = { radius = 0.3, height = 0.8 } }",
            "shape = { capsule = { radius = 0.2, height = 0.8 } }",
        )
        .replace(
            "orientation = [0.9990482, 0.0436194, 0.0, 0.0]",
            "orientation = [0.8660254, 0.0, 0.0, 0.5]",
        );
    let mut sim = scene(&text);
    for _ in 0..300 {
        sim.advance().expect("the scene does not blow up");
    }
    let pill = &sim.world.bodies[0].state;
    let axis = UnitQuaternion::new_normalize(pill.orientation) * Vector3::y();
    assert!(
        (pill.position.y - 1.2).abs() < 0.02,
        "centre at {}",
        pill.position.y
    );
    assert!(axis.y.abs() < 0.05, "lying down, axis {axis}");
    assert!(pill.velocity.norm() < 0.05, "{} m/s", pill.velocity.norm());
}

/// A tetrahedron hull on its face on a box, tilted by `tilt` about z and
/// sunk `sink` at its lowest corner: the contacts within a 5 mm margin.
fn tetra_on_box(tilt: f64, sink: f64) -> Vec<f64> {
    use contact_lab::physics::detect::ConvexHull;
    let corners = [
        [0.5, -0.2, 0.0],
        [-0.25, -0.2, 0.4330127018922193],
        [-0.25, -0.2, -0.4330127018922193],
        [0.0, 0.6, 0.0],
    ];
    let tetra = Shape::Hull(std::sync::Arc::new(ConvexHull::new(&corners).unwrap()));
    let q = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), tilt);
    // The lowest corner at y = 0.5 − sink (the box's top face is y = 0.5).
    let lowest = corners
        .iter()
        .map(|p| (q * Vector3::from(*p)).y)
        .fold(f64::INFINITY, f64::min);
    let pa = Pose::from_unit(Vector3::new(0.0, 0.5 - sink - lowest, 0.0), &q);
    let pb = Pose::at(Vector3::zeros());
    let options = Options {
        tolerance: 0.005,
        ..Options::default()
    };
    let mut out = Vec::new();
    collide_with((&tetra, &pa), (&BOX, &pb), &options, &mut out);
    out.iter().map(|c| c.penetration).collect()
}

#[test]
fn a_hull_face_on_a_box_keeps_its_corners_when_it_tilts_by_a_rounding_error() {
    // Flat: three corners, each 1 µm deep.
    let flat = tetra_on_box(0.0, 1e-6);
    assert_eq!(flat.len(), 3, "{flat:?}");
    // Tilted by 1e-9 rad (a rounding error's worth after a few steps): the
    // corners 0.75 nm up stay contacts (before, the manifold dropped them
    // and the tetrahedron tipped about the rest).
    for tilt in [1e-9, -1e-9, 1e-12] {
        let tilted = tetra_on_box(tilt, 1e-6);
        assert_eq!(tilted.len(), 3, "tilt {tilt}: {tilted:?}");
        let deepest = tilted.iter().cloned().fold(f64::MIN, f64::max);
        assert!((deepest - 1e-6).abs() < 1e-9, "{tilted:?}");
        assert!(tilted.iter().all(|d| *d >= -0.005), "{tilted:?}");
    }
    // Corners farther up (0.75 mm: in the contact margin's gap, beyond a
    // rounding error) are not contacts.
    let steep = tetra_on_box(1e-3, 1e-6);
    assert!(steep.len() < 3, "{steep:?}");
}

#[test]
fn two_parallel_capsules_touch_at_their_overlaps_two_ends() {
    // Two capsules lying along x (radius 0.25, core 1 m), the upper one
    // shifted 0.4 m along x and 1 cm into the lower: the overlap of their
    // sides runs x ∈ [−0.1, 0.5], each end 1 cm deep, normal +y (lower →
    // upper). One point (the penetration's) let the upper one roll.
    let lying = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2);
    let capsule = Shape::Capsule {
        radius: 0.25,
        height: 1.0,
    };
    let upper = Pose::from_unit(Vector3::new(0.4, 0.49, 0.0), &lying);
    let lower = Pose::from_unit(Vector3::zeros(), &lying);
    let mut out = Vec::new();
    collide_with(
        (&capsule, &upper),
        (&capsule, &lower),
        &Options::<f64>::default(),
        &mut out,
    );
    assert_eq!(out.len(), 2, "{out:?}");
    let mut xs: Vec<f64> = out.iter().map(|c| c.point.x).collect();
    xs.sort_by(f64::total_cmp);
    assert!(
        (xs[0] + 0.1).abs() < 1e-9 && (xs[1] - 0.5).abs() < 1e-9,
        "{xs:?}"
    );
    for c in &out {
        assert!((c.normal - Vector3::y()).norm() < 1e-9, "{c:?}");
        assert!((c.penetration - 0.01).abs() < 1e-9, "{c:?}");
    }
}
