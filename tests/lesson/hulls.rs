//! Convex hulls in lesson files: `shape = { convex = [[x, y, z], …] }`. The
//! points are in the file's body frame; the hull is re-centred on its
//! centroid and the body's position moves to that centroid (x + R c), so the
//! hull stays where the file puts it and the body's origin is its centre of
//! mass. Degenerate hulls are refused through the binary in
//! `invalid_lessons.rs` (tests/invalid_lessons/hull-*.toml).

use contact_lab::lesson::validate::parse;
use contact_lab::physics::Shape;
use nalgebra::{UnitQuaternion, Vector3};

/// A corner tetrahedron (centroid (1/4, 1/4, 1/4)) at `position`, turned
/// by `orientation` ([w, x, y, z]).
fn tetra_lesson(position: [f64; 3], orientation: [f64; 4]) -> String {
    format!(
        r#"id = "tetra"
title = "A hull"
[world]
gravity = [0, -9.81, 0]
[[body]]
name = "tetra"
mass = 6.0
shape = {{ convex = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]] }}
position = {position:?}
orientation = {orientation:?}
[[body]]
name = "floor"
mass = inf
shape = "half_space"
position = [0, 0, 0]
"#
    )
}

#[test]
fn a_hull_is_recentred_on_its_centroid_and_stays_where_the_file_puts_it() {
    let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.3);
    let q = turn.into_inner();
    let lesson = parse(
        "tetra.toml",
        &tetra_lesson([1.0, 2.0, 3.0], [q.w, q.i, q.j, q.k]),
    )
    .unwrap();
    let body = &lesson.bodies[0];
    let Some(Shape::Hull(hull)) = &body.shape else {
        panic!("{:?}", body.shape)
    };
    // The hull's centroid is the body's origin.
    assert!(hull.mass_properties().centroid.norm() < 1e-12);
    // Volume 1/6; the body sits at x + R c with c = (1/4, 1/4, 1/4).
    assert!((hull.mass_properties().volume - 1.0 / 6.0).abs() < 1e-12);
    let c = Vector3::repeat(0.25);
    let expected = Vector3::new(1.0, 2.0, 3.0) + turn * c;
    assert!(
        (body.position - expected).norm() < 1e-12,
        "{}",
        body.position
    );
    // Every file point is a hull vertex at the same world place.
    for p in [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ] {
        let world = Vector3::new(1.0, 2.0, 3.0) + turn * Vector3::from(p);
        assert!(
            hull.vertices()
                .iter()
                .any(|v| (body.position + turn * v - world).norm() < 1e-12),
            "{p:?}"
        );
    }
    // Inertia from the hull, symmetric; for the unit corner tetrahedron
    // ⟨x²⟩ = 1/10, ⟨xy⟩ = 1/20 over the solid and c = 1/4 on each axis:
    // I_xx = m (⟨y²⟩ + ⟨z²⟩ − c_y² − c_z²), I_xy = −m (⟨xy⟩ − c_x c_y).
    let i = body.shape_inertia.unwrap();
    assert!((i - i.transpose()).norm() < 1e-12);
    assert!((i - hull.inertia(6.0)).norm() < 1e-12);
    let ixx = 6.0 * (0.2 - 0.125);
    assert!((i[(0, 0)] - ixx).abs() < 1e-12, "{i}");
    assert!((i[(0, 1)] + 6.0 * (0.05 - 0.0625)).abs() < 1e-12, "{i}");
}

#[test]
fn a_hull_at_its_centroid_keeps_its_position() {
    let text = tetra_lesson([0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0]).replace(
        "[[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]",
        "[[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]",
    );
    let lesson = parse("tetra.toml", &text).unwrap();
    assert_eq!(lesson.bodies[0].position, Vector3::new(0.0, 1.0, 0.0));
}

/// A hull's points are reduced to its vertices at load, and a load warning
/// says how many were dropped (a hull of 100,000 points used to keep them
/// all in the file's order through two builds, and say nothing).
#[test]
fn the_points_inside_a_hull_are_dropped_with_a_warning() {
    let cube: Vec<[f64; 3]> = (0..8)
        .map(|i| [i & 1, (i >> 1) & 1, (i >> 2) & 1].map(|b| f64::from(b as u8)))
        .collect();
    // The centre, a point on a face, a point on an edge: none is a vertex.
    let extra = [[0.5, 0.5, 0.5], [0.5, 0.5, 0.0], [0.5, 0.0, 0.0]];
    let points: Vec<String> = (cube.iter().chain(&extra))
        .map(|p| format!("[{}, {}, {}]", p[0], p[1], p[2]))
        .collect();
    let text = format!(
        "id = \"blob\"\ntitle = \"A hull\"\n[world]\n[[body]]\nname = \"blob\"\nmass = 1.0\nshape = {{ convex = [{}] }}\nposition = [0, 2, 0]\n",
        points.join(", ")
    );
    let lesson = parse("blob.toml", &text).expect("a valid lesson");
    let Some(Shape::Hull(hull)) = &lesson.bodies[0].shape else {
        panic!("a hull");
    };
    assert_eq!(hull.vertices().len(), 8);
    let warnings: Vec<&str> = (lesson.warnings.iter())
        .map(|w| w.message.as_str())
        .collect();
    assert_eq!(
        warnings,
        ["body 'blob': the convex hull of 11 points has 8 vertices; the 3 points inside it or on its faces were dropped"]
    );
    // A hull of its vertices only loads without a word.
    let only = text.replace(", [0.5, 0.5, 0.5], [0.5, 0.5, 0], [0.5, 0, 0]", "");
    let lesson = parse("cube.toml", &only).expect("a valid lesson");
    assert!(lesson.warnings.is_empty(), "{:?}", lesson.warnings);
}
