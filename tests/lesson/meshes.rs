//! Triangle meshes in lesson files: `shape = { mesh = { vertices, triangles } }`
//! and `shape = { mesh = "file.obj" }` (next to the lesson). A movable mesh
//! is closed, re-centred on its solid's centroid, its inertia the solid's;
//! an OBJ file's errors name the file, its line and column. Bad inline
//! meshes are refused through the binary in `invalid_lessons.rs`
//! (tests/invalid_lessons/mesh-*.toml).

use contact_lab::lesson::validate::parse;
use contact_lab::lesson::Lesson;
use contact_lab::physics::Shape;
use nalgebra::Vector3;

use crate::common;

/// A unit cube's corners and its 12 triangles, outward.
const CUBE_OBJ: &str = "# a unit cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvn 0 0 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

fn lesson(shape: &str, mass: &str) -> String {
    format!(
        r#"id = "mesh"
title = "A mesh"
[world]
gravity = [0, -9.81, 0]
[[body]]
name = "block"
mass = {mass}
shape = {shape}
position = [1, 2, 3]
[[body]]
name = "floor"
mass = inf
shape = "half_space"
position = [0, 0, 0]
"#
    )
}

#[test]
fn a_movable_closed_mesh_is_recentred_and_its_inertia_is_the_solids() {
    // The corner tetrahedron: centroid (1/4, 1/4, 1/4), the same solid as
    // the convex hull of its corners.
    let tetra = "{ mesh = { vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], triangles = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] } }";
    let l = parse("mesh.toml", &lesson(tetra, "6.0")).unwrap();
    let b = &l.bodies[0];
    assert!((b.position - Vector3::new(1.25, 2.25, 3.25)).norm() < 1e-12);
    let Some(Shape::Mesh(mesh)) = &b.shape else {
        panic!("{:?}", b.shape)
    };
    assert!(mesh.is_closed());
    let hull = "{ convex = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]] }";
    let h = parse("hull.toml", &lesson(hull, "6.0")).unwrap();
    let (i_mesh, i_hull) = (b.inertia.unwrap(), h.bodies[0].inertia.unwrap());
    assert!(
        (i_mesh - i_hull).norm() < 1e-12 * i_hull.norm(),
        "{i_mesh} {i_hull}"
    );
}

#[test]
fn an_obj_file_next_to_the_lesson_is_read_and_its_ignored_lines_said() {
    let dir = common::scratch("mesh-obj");
    std::fs::write(dir.join("cube.obj"), CUBE_OBJ).unwrap();
    let path = dir.join("cube.toml");
    std::fs::write(&path, lesson("{ mesh = \"cube.obj\" }", "12.0")).unwrap();
    let l = Lesson::load(&path).unwrap();
    let b = &l.bodies[0];
    // A unit cube of 12 kg: I = m/6 about each axis; centroid (½, ½, ½).
    let i = b.inertia.unwrap();
    assert!(
        (i - nalgebra::Matrix3::identity() * 2.0).norm() < 1e-12,
        "{i}"
    );
    assert!((b.position - Vector3::new(1.5, 2.5, 3.5)).norm() < 1e-12);
    let said: Vec<String> = l.warnings.iter().map(|w| w.to_string()).collect();
    assert!(
        said.iter()
            .any(|w| w.contains("lines ignored") && w.contains("1 `vn`")),
        "{said:?}"
    );
}

#[test]
fn an_obj_error_names_the_obj_file_its_line_and_column() {
    let dir = common::scratch("mesh-obj-bad");
    let bad = CUBE_OBJ.replace("f 2 3 7 6", "f 2 3 x 6");
    std::fs::write(dir.join("cube.obj"), bad).unwrap();
    let path = dir.join("cube.toml");
    std::fs::write(&path, lesson("{ mesh = \"cube.obj\" }", "12.0")).unwrap();
    let e = Lesson::load(&path).unwrap_err().to_string();
    assert!(
        e.contains("cube.obj:14:7: 'x' is not a vertex reference"),
        "{e}"
    );
}

#[test]
fn an_open_immovable_mesh_loads_and_an_embedded_lesson_reads_no_file() {
    let sheet =
        "{ mesh = { vertices = [[-1, 0, -1], [1, 0, -1], [0, 0, 1]], triangles = [[0, 2, 1]] } }";
    let l = parse("open.toml", &lesson(sheet, "inf")).unwrap();
    let Some(Shape::Mesh(mesh)) = &l.bodies[0].shape else {
        panic!()
    };
    assert!(!mesh.is_closed());
    let e = parse(
        "lessons/x.toml (embedded)",
        &lesson("{ mesh = \"cube.obj\" }", "inf"),
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("an embedded lesson's mesh is written inline"),
        "{e}"
    );
}
