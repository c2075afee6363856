//! Contact generation: known cases (boxes resting on a plane and on a box,
//! crossing edges, separated pairs) and the conventions every contact keeps.

use crate::collide_support;

use collide_support::{check_pair, collide_all, moved, pose, FLOOR};
use contact_lab::physics::collide::{
    collide, BoxBoxMode, BoxPart, ContactPoint, Feature, Pose, Side,
};
use contact_lab::physics::Shape;
use nalgebra::{UnitQuaternion, Vector3};
use std::f64::consts::{FRAC_PI_4, SQRT_2};

const CUBE: Shape = Shape::Box { sides: [1.0; 3] };

fn floor() -> Pose<f64> {
    Pose::at(Vector3::zeros())
}

fn close(a: &Vector3<f64>, b: &Vector3<f64>) -> bool {
    (a - b).norm() < 1e-12
}

#[test]
fn unit_box_flat_on_the_floor_touches_at_its_four_bottom_corners() {
    let cube = pose([0.0, 0.49, 0.0], UnitQuaternion::identity());
    let out = collide_all((&CUBE, &cube), (&FLOOR, &floor()), BoxBoxMode::Single);
    assert_eq!(out.len(), 4);
    for k in &out {
        assert_eq!(k.normal, Vector3::y());
        assert!((k.penetration - 0.01).abs() < 1e-12);
        // At the corner, 0.01 below the floor.
        assert!((k.point.y + 0.01).abs() < 1e-12);
        assert!((k.point.x.abs() - 0.5).abs() < 1e-12 && (k.point.z.abs() - 0.5).abs() < 1e-12);
        assert!(
            matches!(k.feature, Feature::VertexPlane { cuboid: Side::A, vertex } if vertex & 2 == 0)
        );
    }
    check_pair((&CUBE, &cube), (&FLOOR, &floor()), BoxBoxMode::Single, 0.0);
}

#[test]
fn unit_box_on_an_edge_gives_two_contacts_and_on_a_corner_one() {
    let edge = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), FRAC_PI_4);
    let cube = pose([0.3, SQRT_2 / 2.0 - 0.01, 0.0], edge);
    let out = collide_all((&CUBE, &cube), (&FLOOR, &floor()), BoxBoxMode::Single);
    assert_eq!(out.len(), 2);
    for (k, z) in out.iter().zip([-0.5, 0.5]) {
        assert!((k.penetration - 0.01).abs() < 1e-12);
        assert!(
            close(&k.point, &Vector3::new(0.3, -0.01, z)),
            "{:?}",
            k.point
        );
    }
    check_pair((&CUBE, &cube), (&FLOOR, &floor()), BoxBoxMode::Single, 0.0);

    // The body diagonal (1, 1, 1) turned straight down: one corner, vertex 7.
    let corner = UnitQuaternion::rotation_between(&Vector3::repeat(1.0), &-Vector3::y()).unwrap();
    let cube = pose([1.0, 3f64.sqrt() / 2.0 - 0.01, 2.0], corner);
    let out = collide_all((&CUBE, &cube), (&FLOOR, &floor()), BoxBoxMode::Single);
    assert_eq!(out.len(), 1);
    assert!((out[0].penetration - 0.01).abs() < 1e-12);
    assert!(close(&out[0].point, &Vector3::new(1.0, -0.01, 2.0)));
    assert_eq!(
        out[0].feature,
        Feature::VertexPlane {
            cuboid: Side::A,
            vertex: 7
        }
    );
}

#[test]
fn floor_first_flips_the_normal_and_keeps_the_points() {
    let cube = pose([0.0, 0.49, 0.0], UnitQuaternion::identity());
    let out = collide_all((&FLOOR, &floor()), (&CUBE, &cube), BoxBoxMode::Single);
    assert_eq!(out.len(), 4);
    assert!(out.iter().all(|k| k.normal == -Vector3::y()));
    assert!(matches!(
        out[0].feature,
        Feature::VertexPlane {
            cuboid: Side::B,
            ..
        }
    ));
}

#[test]
fn box_on_a_box_face_to_face_gives_four_manifold_points_or_one_single() {
    let slab = Shape::Box {
        sides: [4.0, 1.0, 4.0],
    };
    let below = pose([0.0, 0.0, 0.0], UnitQuaternion::identity());
    let above = pose([0.2, 0.98, -0.1], UnitQuaternion::identity());
    let manifold = collide_all((&CUBE, &above), (&slab, &below), BoxBoxMode::Manifold);
    assert_eq!(manifold.len(), 4);
    let mut corners: Vec<_> = manifold.iter().map(|k| (k.point.x, k.point.z)).collect();
    corners.sort_by(|p, q| p.partial_cmp(q).unwrap());
    let expected = [(-0.3, -0.6), (-0.3, 0.4), (0.7, -0.6), (0.7, 0.4)];
    for (k, (c, e)) in manifold.iter().zip(corners.iter().zip(expected)) {
        assert_eq!(k.normal, Vector3::y());
        assert!((k.penetration - 0.02).abs() < 1e-12);
        // The cube's corners (the incident face), 0.02 below the slab's top.
        assert!((k.point.y - 0.48).abs() < 1e-12);
        assert!(
            (c.0 - e.0).abs() < 1e-12 && (c.1 - e.1).abs() < 1e-12,
            "{c:?} vs {e:?}"
        );
        assert!(matches!(k.feature, Feature::FaceFace { axis: 1, .. }));
    }
    let single = collide_all((&CUBE, &above), (&slab, &below), BoxBoxMode::Single);
    assert_eq!(single.len(), 1);
    assert_eq!(single[0].normal, Vector3::y());
    assert!((single[0].penetration - 0.02).abs() < 1e-12);
    // One corner of the cube, midway between it and the slab's top.
    let corner = single[0].point - Vector3::new(0.0, 0.01, 0.0);
    assert!(
        manifold.iter().any(|k| close(&k.point, &corner)),
        "{:?}",
        single[0]
    );
    assert!(matches!(
        single[0].feature,
        Feature::VertexFace { axis: 1, .. }
    ));
    for mode in [BoxBoxMode::Single, BoxBoxMode::Manifold] {
        check_pair((&CUBE, &above), (&slab, &below), mode, 0.0);
    }
}

/// Cube A turned 45° about x (a bottom edge along x) above cube B turned 45°
/// about z (a top edge along z), the edges `overlap` deep, offset in the
/// horizontal plane.
fn crossing(overlap: f64, offset: [f64; 2]) -> (Pose<f64>, Pose<f64>) {
    let a = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_4);
    let b = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), FRAC_PI_4);
    (
        pose([offset[0], SQRT_2 - overlap, 0.0], a),
        pose([0.0, 0.0, offset[1]], b),
    )
}

#[test]
fn crossing_edges_give_one_edge_edge_contact_between_the_edges() {
    let (a, b) = crossing(0.02, [0.1, 0.2]);
    for mode in [BoxBoxMode::Single, BoxBoxMode::Manifold] {
        let out = collide_all((&CUBE, &a), (&CUBE, &b), mode);
        assert_eq!(out.len(), 1, "{mode:?}");
        let k = out[0];
        assert_eq!(
            k.feature,
            Feature::EdgeEdge {
                axis_a: 0,
                axis_b: 2
            }
        );
        assert!((k.normal - Vector3::y()).norm() < 1e-12);
        assert!((k.penetration - 0.02).abs() < 1e-12);
        // A's edge runs along x (x = 0.1 ± 0.5) at z = 0, B's along z
        // (z = 0.2 ± 0.5) at x = 0: they cross above x = z = 0, 0.02 apart.
        assert!(
            close(&k.point, &Vector3::new(0.0, SQRT_2 / 2.0 - 0.01, 0.0)),
            "{:?}",
            k.point
        );
        check_pair((&CUBE, &a), (&CUBE, &b), mode, 0.0);
    }
}

#[test]
fn edges_apart_give_nothing_though_every_face_axis_overlaps() {
    let (a, b) = crossing(-0.02, [0.1, 0.2]);
    let out = collide_all((&CUBE, &a), (&CUBE, &b), BoxBoxMode::Manifold);
    assert!(out.is_empty(), "{out:?}");
    // A contact margin of 0.03 reports the gap as a negative penetration.
    let mut near = Vec::new();
    let options = contact_lab::physics::collide::Options {
        box_box: BoxBoxMode::Single,
        tolerance: 0.03,
        ..Default::default()
    };
    contact_lab::physics::collide::collide_with((&CUBE, &a), (&CUBE, &b), &options, &mut near);
    assert_eq!(near.len(), 1);
    assert!((near[0].penetration + 0.02).abs() < 1e-12);
}

#[test]
fn separated_pairs_give_nothing() {
    let ball = Shape::Sphere { radius: 0.5 };
    let far = pose([3.0, 0.0, 0.0], UnitQuaternion::identity());
    let here = pose([0.0, 0.6, 0.0], UnitQuaternion::identity());
    let turned = pose(
        [0.0, 1.8, 0.0],
        UnitQuaternion::from_axis_angle(&Vector3::y_axis(), 0.3),
    );
    let cases: [(&Shape, &Pose<f64>, &Shape, &Pose<f64>); 6] = [
        (&ball, &here, &ball, &far),
        (&ball, &here, &CUBE, &far),
        (&CUBE, &here, &CUBE, &far),
        (&CUBE, &turned, &CUBE, &here),
        (&ball, &here, &FLOOR, &floor()),
        (&CUBE, &turned, &FLOOR, &floor()),
    ];
    for (sa, pa, sb, pb) in cases {
        for mode in [BoxBoxMode::Single, BoxBoxMode::Manifold] {
            assert!(
                collide_all((sa, pa), (sb, pb), mode).is_empty(),
                "{sa:?} {sb:?}"
            );
            assert!(collide_all((sb, pb), (sa, pa), mode).is_empty());
        }
    }
}

#[test]
fn sphere_in_a_box_corner_and_a_box_on_a_ball() {
    let ball = Shape::HollowSphere { radius: 1.0 };
    let cube = pose([0.0, 0.0, 0.0], UnitQuaternion::identity());
    let ball_pose = pose([1.0, 1.0, 0.0], UnitQuaternion::identity());
    let out = collide_all((&ball, &ball_pose), (&CUBE, &cube), BoxBoxMode::Single);
    assert_eq!(out.len(), 1);
    // Sphere first: the normal points from the box's edge toward the centre.
    let s = std::f64::consts::FRAC_1_SQRT_2;
    assert!((out[0].normal - Vector3::new(s, s, 0.0)).norm() < 1e-15);
    assert!((out[0].penetration - (1.0 - s)).abs() < 1e-15);
    assert_eq!(
        out[0].feature,
        Feature::SphereBox {
            sphere: Side::A,
            part: BoxPart::Edge
        }
    );
    check_pair((&ball, &ball_pose), (&CUBE, &cube), BoxBoxMode::Single, 0.0);
}

#[test]
fn cylinders_meet_every_convex_shape() {
    let can = Shape::Cylinder {
        radius: 0.5,
        height: 1.0,
    };
    let upright = pose([0.0, 0.45, 0.0], UnitQuaternion::identity());
    assert_eq!(
        collide_all((&can, &upright), (&FLOOR, &floor()), BoxBoxMode::Single).len(),
        4
    );
    check_pair(
        (&can, &upright),
        (&FLOOR, &floor()),
        BoxBoxMode::Single,
        0.0,
    );
    let inside = pose([0.0, 0.5, 0.0], UnitQuaternion::identity());
    // No analytic routine: GJK/EPA and the manifold (no longer nothing).
    for other in [CUBE, Shape::Sphere { radius: 1.0 }, can.clone()] {
        let out = collide_all((&can, &upright), (&other, &inside), BoxBoxMode::Manifold);
        assert!(!out.is_empty(), "cylinder–{other:?}");
        assert!(out.iter().all(|c| c.penetration > 0.0), "{out:?}");
    }
    assert!(collide_all((&FLOOR, &floor()), (&FLOOR, &upright), BoxBoxMode::Single).is_empty());
}

#[test]
fn single_precision_gives_the_same_contacts() {
    let (a, b) = crossing(0.02, [0.1, 0.2]);
    let cast = |p: &Pose<f64>| Pose::<f32> {
        position: p.position.cast(),
        rotation: p.rotation.cast(),
    };
    let mut out32: Vec<ContactPoint<f32>> = Vec::new();
    collide(
        (&CUBE, &cast(&a)),
        (&CUBE, &cast(&b)),
        BoxBoxMode::Single,
        &mut out32,
    );
    let out64 = collide_all((&CUBE, &a), (&CUBE, &b), BoxBoxMode::Single);
    assert_eq!(out32.len(), 1);
    assert_eq!(out32[0].feature, out64[0].feature);
    assert!((out32[0].point.cast::<f64>() - out64[0].point).norm() < 1e-6);
    assert!((f64::from(out32[0].penetration) - 0.02).abs() < 1e-6);
    let cube = cast(&pose([0.0, 0.49, 0.0], UnitQuaternion::identity()));
    out32.clear();
    collide(
        (&CUBE, &cube),
        (&FLOOR, &cast(&floor())),
        BoxBoxMode::Manifold,
        &mut out32,
    );
    assert_eq!(out32.len(), 4);
}

#[test]
fn moving_a_along_the_normal_by_the_penetration_separates() {
    // A cube sunk into a ball: the centre is inside, pushed out through +y.
    let ball = Shape::Sphere { radius: 0.3 };
    let cube = pose([0.0, 0.0, 0.0], UnitQuaternion::identity());
    let ball_pose = pose([0.1, 0.35, 0.0], UnitQuaternion::identity());
    let out = collide_all((&CUBE, &cube), (&ball, &ball_pose), BoxBoxMode::Single);
    assert_eq!(out[0].normal, -Vector3::y());
    assert!((out[0].penetration - 0.45).abs() < 1e-15);
    let away = moved(&cube, &(out[0].normal * (out[0].penetration + 1e-9)));
    assert!(collide_all((&CUBE, &away), (&ball, &ball_pose), BoxBoxMode::Single).is_empty());
    let short = moved(&cube, &(out[0].normal * (out[0].penetration - 1e-6)));
    assert_eq!(
        collide_all((&CUBE, &short), (&ball, &ball_pose), BoxBoxMode::Single).len(),
        1
    );
}

#[test]
fn a_long_edge_across_a_face_touches_where_it_crosses_the_face() {
    // B: a 1×1×6 bar turned 45° about z, its bottom edge (along z) 0.01
    // into the top face of cube A. The reference engine's point–face vertex
    // is an end of that edge, at z = ±3, beside the unit face; the contact
    // is taken where the edge crosses the face instead.
    let bar = Shape::Box {
        sides: [1.0, 1.0, 6.0],
    };
    let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), FRAC_PI_4);
    let bar_pose = pose([0.0, 0.5 + SQRT_2 / 2.0 - 0.01, 0.0], turn);
    let cube = pose([0.0, 0.0, 0.0], UnitQuaternion::identity());
    let single = collide_all((&CUBE, &cube), (&bar, &bar_pose), BoxBoxMode::Single);
    assert_eq!(single.len(), 1);
    assert_eq!(
        single[0].feature,
        Feature::FaceFace {
            reference: Side::A,
            axis: 1
        }
    );
    assert_eq!(single[0].normal, -Vector3::y());
    assert!((single[0].penetration - 0.01).abs() < 1e-12);
    assert!((single[0].point.x.abs() < 1e-12) && (single[0].point.y - 0.49).abs() < 1e-12);
    assert!(
        (single[0].point.z.abs() - 0.5).abs() < 1e-12,
        "{:?}",
        single[0].point
    );
    let manifold = collide_all((&CUBE, &cube), (&bar, &bar_pose), BoxBoxMode::Manifold);
    assert_eq!(manifold.len(), 2);
    assert!((manifold[0].point.z + manifold[1].point.z).abs() < 1e-12);
    for mode in [BoxBoxMode::Single, BoxBoxMode::Manifold] {
        check_pair((&CUBE, &cube), (&bar, &bar_pose), mode, 0.0);
    }
}

#[test]
fn generated_contacts_agree_with_the_lessons_written_ones() {
    use contact_lab::lesson::Lesson;
    use contact_lab::physics::collide::{ContactGenerator, Options};
    use contact_lab::physics::BodyId;
    let generate = |id: &str, box_box: BoxBoxMode, tolerance: f64| {
        let world = Lesson::load(id).unwrap().world::<f64>();
        let mut out = Vec::new();
        let options = Options {
            box_box,
            tolerance,
            ..Default::default()
        };
        ContactGenerator::new().generate_world(&world.bodies, &options, &mut out);
        (world, out)
    };
    // lecture-2: the turned cube's lowest edge just touches the floor (the
    // lesson's numbers are rounded to 4 decimals: a gap of 4.5e-4 remains).
    // The lesson's one contact is the edge's middle; generation gives its ends.
    let (world, out) = generate("lecture-2", BoxBoxMode::Single, 1e-3);
    let written = &world.contacts[0].input;
    assert_eq!(out.len(), 2);
    for (k, z) in out.iter().zip([-6.0, 6.0]) {
        assert_eq!((k.body1, k.body2), (BodyId(0), BodyId(1)));
        assert_eq!(k.contact.normal, written.normal);
        assert!((k.contact.point - written.point - Vector3::new(0.0, 0.0, z)).norm() < 1e-3);
        assert!(k.contact.penetration.abs() < 5e-4);
    }
    assert!(generate("lecture-2", BoxBoxMode::Single, 0.0).1.is_empty());
    // two-boxes: the written normal and penetration, 4 points across the face.
    let (world, out) = generate("two-boxes", BoxBoxMode::Manifold, 0.0);
    let written = &world.contacts[0].input;
    assert_eq!(out.len(), 4);
    for k in &out {
        assert!((k.contact.normal - written.normal).norm() < 1e-12);
        assert!((k.contact.penetration - written.penetration).abs() < 1e-12);
    }
    // lecture-1: the two balls' line of centres is the written normal (to the
    // lesson's 4 decimals); with equal radii the point is the written one.
    let (world, out) = generate("lecture-1", BoxBoxMode::Single, 0.0);
    let written = &world.contacts[0].input;
    assert!((out[0].contact.normal - written.normal).norm() < 1e-4);
    assert!((out[0].contact.point - written.point).norm() < 1e-12);
}

#[test]
fn coincident_centres_push_along_y_and_still_flip_when_swapped() {
    let (small, big) = (Shape::Sphere { radius: 0.5 }, Shape::Sphere { radius: 1.0 });
    let here = pose([1.0, 2.0, 3.0], UnitQuaternion::identity());
    let out = check_pair((&small, &here), (&big, &here), BoxBoxMode::Single, 0.0);
    assert_eq!(out.len(), 1);
    assert_eq!(out[0].normal.y.abs(), 1.0);
    assert_eq!(out[0].penetration, 1.5);
    // (Two equal bodies at one pose cannot be told apart: swapping them
    // changes nothing, so that one case keeps its normal.)
    let twins = collide_all((&CUBE, &here), (&CUBE, &here), BoxBoxMode::Single);
    assert_eq!(
        twins,
        collide_all((&CUBE, &here), (&CUBE, &here), BoxBoxMode::Single)
    );
    assert_eq!(twins[0].normal, Vector3::x());
    assert_eq!(twins[0].penetration, 1.0);
}
