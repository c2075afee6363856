//! Unit tests of the figure model: outlines, bounds, and the marks of
//! hand-made scenes (one contact, and five bodies with eight contacts).

use super::*;
use crate::physics::Shape;

const ID: [f64; 4] = [1.0, 0.0, 0.0, 0.0];

fn body(name: &str, shape: Option<Shape>, position: [f64; 3]) -> BodyView {
    BodyView {
        name: name.into(),
        movable: true,
        slot: 0,
        shape,
        position,
        orientation: ID,
        position_after: position,
        orientation_after: ID,
        velocity: [0.0; 3],
        velocity_after: [0.0; 3],
        angular_velocity: [0.0; 3],
        angular_velocity_after: [0.0; 3],
    }
}

fn floor() -> BodyView {
    BodyView {
        movable: false,
        ..body(
            "floor",
            Some(Shape::HalfSpace {
                normal: [0.0, 1.0, 0.0],
            }),
            [0.0; 3],
        )
    }
}

fn contact(number: usize, bodies: [Option<usize>; 2], point: [f64; 3]) -> ContactView {
    ContactView {
        number,
        bodies,
        point,
        normal: [0.0, 1.0, 0.0],
        penetration: 0.0,
        impulse: None,
    }
}

fn cube(side: f64) -> Option<Shape> {
    Some(Shape::Box { sides: [side; 3] })
}

#[test]
fn a_cube_seen_from_z_is_a_square_with_twelve_edges() {
    let o = outline(&cube(2.0).unwrap(), [0.0; 3], ID, Plane::Xy).unwrap();
    assert_eq!(
        o.silhouette,
        Silhouette::Polygon(vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])
    );
    assert_eq!(o.edges.len(), 12);
    // Every edge is one side long (the ones along z are seen end on).
    for [a, b] in &o.edges {
        let len = (a[0] - b[0]).hypot(a[1] - b[1]);
        assert!(len == 0.0 || len == 2.0, "{a:?} {b:?}");
    }
}

#[test]
fn outlines_in_each_plane_use_that_planes_axes() {
    let slab = Shape::Box {
        sides: [2.0, 4.0, 6.0],
    };
    let span = |plane| {
        let o = outline(&slab, [10.0, 20.0, 30.0], ID, plane).unwrap();
        let mut b = Bounds::default();
        o.silhouette.points().into_iter().for_each(|p| b.add(p));
        (b.lo, b.hi)
    };
    // yz: right is y, up is z.
    assert_eq!(span(Plane::Yz), ([18.0, 27.0], [22.0, 33.0]));
    // zx: right is z, up is x.
    assert_eq!(span(Plane::Zx), ([27.0, 9.0], [33.0, 11.0]));
}

#[test]
fn a_turned_box_outline_is_a_hexagon_within_its_bounding_radius() {
    // A cube turned about the diagonal (1, 1, 0) shows six corners.
    let h = (std::f64::consts::FRAC_PI_8 * 1.5).sin() / 2f64.sqrt();
    let q = [(std::f64::consts::FRAC_PI_8 * 1.5).cos(), h, h, 0.0];
    let shape = cube(2.0).unwrap();
    let o = outline(&shape, [0.0; 3], q, Plane::Xy).unwrap();
    let Silhouette::Polygon(p) = &o.silhouette else {
        panic!("{:?}", o.silhouette)
    };
    assert_eq!(p.len(), 6);
    let bound = shape.bounding_radius().unwrap();
    assert!(p.iter().all(|v| v[0].hypot(v[1]) <= bound + 1e-12));
}

#[test]
fn sphere_and_cylinder_outlines() {
    let ball = Shape::HollowSphere { radius: 2.0 };
    let o = outline(&ball, [1.0, 2.0, 3.0], ID, Plane::Yz).unwrap();
    assert_eq!(
        o.silhouette,
        Silhouette::Circle {
            centre: [2.0, 3.0],
            radius: 2.0
        }
    );
    // The rim (48 pieces) and one spoke, from the centre along body x
    // (toward the viewer in yz, so it has no length).
    assert_eq!(o.edges.len(), 49);
    assert_eq!(o.edges[48], [[2.0, 3.0], [2.0, 3.0]]);
    let can = Shape::Cylinder {
        radius: 1.0,
        height: 4.0,
    };
    let o = outline(&can, [0.0; 3], ID, Plane::Xy).unwrap();
    assert_eq!(o.edges.len(), 2 * 32 + 4);
    let mut b = Bounds::default();
    o.silhouette.points().into_iter().for_each(|p| b.add(p));
    assert_eq!((b.lo, b.hi), ([-1.0, -2.0], [1.0, 2.0]));
    // A capsule: two end circles (48 pieces each) and the axis; the
    // silhouette reaches a radius beyond each end.
    let pill = Shape::Capsule {
        radius: 1.0,
        height: 4.0,
    };
    let o = outline(&pill, [0.0; 3], ID, Plane::Xy).unwrap();
    assert_eq!(o.edges.len(), 2 * 48 + 1);
    let mut b = Bounds::default();
    o.silhouette.points().into_iter().for_each(|p| b.add(p));
    assert!((b.lo[1] + 3.0).abs() < 1e-12 && (b.hi[1] - 3.0).abs() < 1e-12);
    assert!((b.hi[0] - 1.0).abs() < 1e-12);
    let floor = Shape::HalfSpace {
        normal: [0.0, 1.0, 0.0],
    };
    assert!(outline(&floor, [0.0; 3], ID, Plane::Xy).is_none());
}

#[test]
fn surface_distance_turns_the_point_into_the_body_frame() {
    let cube = cube(12.0).unwrap();
    let d = surface_distance(&cube, [0.0; 3], ID, [0.0, 8.0, 0.0]).unwrap();
    assert!((d - 2.0).abs() < 1e-12);
    // Turned 45° about z, the corner direction (6√2, 0) is on a vertex.
    let (s, c) = std::f64::consts::FRAC_PI_8.sin_cos();
    let d = surface_distance(
        &cube,
        [0.0; 3],
        [c, 0.0, 0.0, s],
        [6.0 * 2f64.sqrt(), 0.0, 0.0],
    );
    assert!(d.unwrap().abs() < 1e-9, "{d:?}");
    let floor = Shape::HalfSpace {
        normal: [0.0, 1.0, 0.0],
    };
    assert_eq!(
        surface_distance(&floor, [0.0; 3], ID, [0.0, -1.0, 0.0]),
        None
    );
}

#[test]
fn bounds_skip_non_finite_points_and_default_to_the_unit_square() {
    let mut b = Bounds::default();
    assert!(b.is_empty());
    assert_eq!(b.or_unit(), ([-1.0, -1.0], [1.0, 1.0]));
    b.add([f64::NAN, 1.0]);
    b.add([f64::INFINITY, 0.0]);
    assert!(b.is_empty());
    b.add([2.0, -3.0]);
    b.add([-1.0, 5.0]);
    assert_eq!(b.or_unit(), ([-1.0, -3.0], [2.0, 5.0]));
}

#[test]
fn hull_keeps_the_corners_counter_clockwise() {
    let h = hull(vec![
        [0.0, 0.0],
        [2.0, 0.0],
        [1.0, 1.0],
        [2.0, 2.0],
        [0.0, 2.0],
        [2.0, 0.0],
    ]);
    assert_eq!(h, vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
}

/// A cube falling onto the floor (lecture-2 shaped), seen in xy.
fn cube_on_floor() -> SceneView {
    let mut cube = body("cube", cube(12.0), [20.0, 16.0, 0.0]);
    cube.slot = 1;
    cube.velocity = [2.0, -1.0, 0.0];
    cube.velocity_after = [2.0, 0.5, 0.0];
    cube.angular_velocity_after = [0.0, 0.0, 0.2];
    cube.position_after = [20.0, 16.5, 0.0];
    let mut floor = floor();
    floor.slot = 2;
    floor.position = [0.0, 10.0, 0.0];
    SceneView {
        bodies: vec![body("lamp", None, [0.0, 50.0, 0.0]), cube, floor],
        contact: 0,
        point: [22.0, 10.0, 0.0],
        normal: [0.0, 1.0, 0.0],
        penetration: 0.5,
        impulse: Some([0.0, 18.0, 0.0]),
        corrected: None,
    }
}

#[test]
fn one_contact_figure_marks() {
    let fig = Figure::of_contact(&cube_on_floor(), Plane::Xy);
    // Only the contact's bodies, in scene order, numbered as in the lecture.
    let names: Vec<(&str, usize, &str)> = fig
        .bodies
        .iter()
        .map(|b| (b.name.as_str(), b.slot, b.tag))
        .collect();
    assert_eq!(names, [("cube", 1, "₁"), ("floor", 2, "₂")]);
    assert_eq!(fig.contacts[0].bodies, [Some(0), Some(1)]);
    assert_eq!(fig.contacts[0].label, "q");
    // The floor is a surface with its solid side below (-d̂), drawn
    // through q (the floor's plane y = 10); no world surface.
    assert_eq!(
        fig.surfaces,
        [Surface {
            contact: 0,
            body: Some(1),
            solid: -1.0,
            section: Some(Section {
                at: [22.0, 10.0],
                along: [-1.0, 0.0],
                solid_side: [0.0, -1.0]
            })
        }]
    );
    let arrows: Vec<(ArrowKind, &str)> = fig
        .arrows
        .iter()
        .map(|a| (a.kind, a.label.as_str()))
        .collect();
    assert_eq!(
        arrows,
        [
            (ArrowKind::Arm, "r₁"),
            (ArrowKind::Normal, "d̂"),
            (ArrowKind::Impulse, "g"),
            (ArrowKind::Velocity, "v₁"),
            (ArrowKind::VelocityAfter, "v₁′"),
        ]
    );
    assert_eq!(
        fig.arrows[0].tip(5.0),
        [22.0, 10.0, 0.0],
        "an arm reaches q"
    );
    assert_eq!(fig.arrows[4].tip(2.0), [24.0, 17.0, 0.0], "p + 2 v′");
    // Only the spin after is there (ω before is zero), counter-clockwise.
    assert_eq!(fig.spins.len(), 1);
    assert!(fig.spins[0].after && fig.spins[0].rate == 0.2 && fig.spins[0].label == "ω₁′");
    // The cube's centre and q; the half-space has no centre point.
    let labels: Vec<&str> = fig.points.iter().map(|p| p.label.as_str()).collect();
    assert_eq!(labels, ["p₁", "q"]);
    // Scene length: the cube's bounding radius, 6√3.
    assert!((fig.scene_length - 6.0 * 3f64.sqrt()).abs() < 1e-12);
    assert_eq!(fig.top_speed, 5f64.sqrt());
    // Bounds: the cube's square (14..26, 10..22), q, and every centre, the
    // floor's position (0, 10) too.
    assert_eq!((fig.bounds.lo, fig.bounds.hi), ([0.0, 10.0], [26.0, 22.0]));
    let cube = &fig.bodies[0];
    assert!(cube.moved() && cube.outline_after.is_some() && cube.travel == 0.5);
    assert!(!fig.beyond(cube));
    assert!((cube.bounding_radius - 6.0 * 3f64.sqrt()).abs() < 1e-12);
    assert!((cube.spin_arc_radius.unwrap() - 3.6).abs() < 1e-12);
    assert_eq!(fig.bodies[1].bounding_radius, 0.0);
    // q lies on the cube's bottom face (y = 10): nothing to warn about.
    assert!(fig
        .legend
        .iter()
        .all(|i| !matches!(i, LegendItem::OffSurface { .. })));
    assert!(fig.legend.contains(&LegendItem::Moved));
    assert!(fig.legend.contains(&LegendItem::Spin {
        body: 0,
        before: [0.0; 3],
        after: [0.0, 0.0, 0.2]
    }));
}

#[test]
fn a_point_off_the_body_and_a_far_move_go_to_the_legend() {
    let mut scene = cube_on_floor();
    scene.point = [22.0, 4.0, 0.0]; // 6 below the cube's face
    scene.bodies[1].position_after = [20.0, 116.0, 0.0];
    let fig = Figure::of_contact(&scene, Plane::Xy);
    assert!(fig.legend.contains(&LegendItem::OffSurface {
        contact: 0,
        body: 0,
        distance: 6.0
    }));
    assert!(fig.legend.contains(&LegendItem::Travel {
        body: 0,
        distance: 100.0
    }));
}

#[test]
fn a_one_body_contact_meets_the_world() {
    let mut scene = cube_on_floor();
    scene.bodies[2].slot = 0;
    let fig = Figure::of_contact(&scene, Plane::Xy);
    assert_eq!(fig.bodies.len(), 1);
    assert_eq!(fig.contacts[0].bodies, [Some(0), None]);
    assert_eq!(
        fig.surfaces,
        [Surface {
            contact: 0,
            body: None,
            solid: -1.0,
            section: Some(Section {
                at: [22.0, 10.0],
                along: [-1.0, 0.0],
                solid_side: [0.0, -1.0]
            })
        }]
    );
}

#[test]
fn a_figure_of_five_bodies_and_eight_contacts() {
    // A stack of three boxes on the floor, a ball against the top box and
    // the wall; contacts in file order, some against the world.
    let mut bodies = vec![
        floor(),
        body("low", cube(2.0), [0.0, 1.0, 0.0]),
        body("mid", cube(2.0), [0.0, 3.0, 0.0]),
        body("top", cube(2.0), [0.0, 5.0, 0.0]),
        body("ball", Some(Shape::Sphere { radius: 1.0 }), [2.0, 5.0, 0.0]),
    ];
    bodies[4].velocity = [-1.0, 0.0, 0.0];
    let contacts = vec![
        contact(0, [Some(1), Some(0)], [-1.0, 0.0, 0.0]),
        contact(1, [Some(1), Some(0)], [1.0, 0.0, 0.0]),
        contact(2, [Some(2), Some(1)], [-1.0, 2.0, 0.0]),
        contact(3, [Some(2), Some(1)], [1.0, 2.0, 0.0]),
        contact(4, [Some(3), Some(2)], [0.0, 4.0, 0.0]),
        ContactView {
            normal: [1.0, 0.0, 0.0],
            impulse: Some([0.5, 0.0, 0.0]),
            ..contact(5, [Some(4), Some(3)], [1.0, 5.0, 0.0])
        },
        ContactView {
            normal: [-1.0, 0.0, 0.0],
            ..contact(6, [Some(4), None], [3.0, 5.0, 0.0])
        },
        contact(7, [Some(4), Some(0)], [2.0, 4.0, 0.0]),
    ];
    let fig = Figure::of_scene(&bodies, &contacts, Plane::Xy);
    assert_eq!(fig.bodies.len(), 5);
    assert_eq!(fig.contacts.len(), 8);
    // Numbered contacts; bodies without the lecture's 1 and 2.
    let q: Vec<&str> = fig.contacts.iter().map(|c| c.label.as_str()).collect();
    assert_eq!(q, ["q₀", "q₁", "q₂", "q₃", "q₄", "q₅", "q₆", "q₇"]);
    assert!(fig.bodies.iter().all(|b| b.slot == 0 && b.tag.is_empty()));
    // One surface per floor contact (0, 1, 7) and the world's at contact 6.
    let surfaces: Vec<(usize, Option<usize>)> =
        fig.surfaces.iter().map(|s| (s.contact, s.body)).collect();
    assert_eq!(
        surfaces,
        [(0, Some(0)), (1, Some(0)), (6, None), (7, Some(0))]
    );
    // Arms: two per box-box contact, one per contact with the floor or the world.
    let arms = |k: usize| {
        fig.arrows
            .iter()
            .filter(|a| a.kind == ArrowKind::Arm && a.contact == Some(k))
            .count()
    };
    assert_eq!(
        (0..8).map(arms).collect::<Vec<_>>(),
        [1, 1, 2, 2, 2, 2, 1, 1]
    );
    // One normal per contact; the one impulse with its reaction on the top box.
    let count = |kind| fig.arrows.iter().filter(|a| a.kind == kind).count();
    assert_eq!(count(ArrowKind::Normal), 8);
    assert_eq!(count(ArrowKind::Impulse), 1);
    let reaction = fig
        .arrows
        .iter()
        .find(|a| a.kind == ArrowKind::Reaction)
        .unwrap();
    assert_eq!((reaction.body, reaction.label.as_str()), (Some(3), "-g₅"));
    assert_eq!(reaction.tip(2.0), [0.0, 5.0, 0.0]);
    // Velocity arrows for the four movable bodies, before and after.
    assert_eq!(
        count(ArrowKind::Velocity) + count(ArrowKind::VelocityAfter),
        8
    );
    // Four centres (not the floor's) and eight contact points.
    assert_eq!(fig.points.len(), 12);
    // Bounds: the boxes and the ball, x from -1 to 3, y from 0 to 6.
    assert_eq!((fig.bounds.lo, fig.bounds.hi), ([-1.0, 0.0], [3.0, 6.0]));
    assert!((fig.scene_length - 3f64.sqrt()).abs() < 1e-12);
    assert_eq!(fig.top_speed, 1.0);
    // Every contact is in the legend, each arm once.
    let legend_arms = fig
        .legend
        .iter()
        .filter(|i| matches!(i, LegendItem::Arm { .. }))
        .count();
    assert_eq!(legend_arms, 12);
    let points = fig
        .legend
        .iter()
        .filter(|i| matches!(i, LegendItem::ContactPoint { .. }))
        .count();
    assert_eq!(points, 8);
}

#[test]
fn a_hull_outline_has_every_edge_and_the_silhouette_of_its_vertices() {
    // A square pyramid: 5 vertices, 8 edges; seen along z, its silhouette is
    // the triangle of the apex and the base's two x extremes.
    let pts = [
        [-1.0, 0.0, -1.0],
        [1.0, 0.0, -1.0],
        [1.0, 0.0, 1.0],
        [-1.0, 0.0, 1.0],
        [0.0, 2.0, 0.0],
    ];
    let hull = crate::physics::detect::ConvexHull::new(&pts).unwrap();
    let shape = Shape::Hull(std::sync::Arc::new(hull));
    let o = outline(&shape, [0.0; 3], ID, Plane::Xy).unwrap();
    assert_eq!(o.edges.len(), 8);
    let mut b = Bounds::default();
    o.silhouette.points().into_iter().for_each(|p| b.add(p));
    assert_eq!((b.lo, b.hi), ([-1.0, 0.0], [1.0, 2.0]));
    assert_eq!(o.silhouette.points().len(), 3);
}
