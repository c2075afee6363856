//! Contacts against triangle meshes (`Shape::Mesh`): a convex shape on a
//! flat triangulated floor gets the contacts it gets on the half-space the
//! floor lies in (the same points, depths and normal, whichever triangles
//! its points are over; and the floor's corners inside it), keeps every convention (`check_pair`), and at the
//! seam of two coplanar triangles the raw normal bumps while the corrected
//! one is the face's. A mesh against a half-space: its vertices below it.

use std::sync::Arc;

use contact_lab::physics::collide::{
    collide_with, BoxBoxMode, ContactPoint, InternalEdges, Options, Pose,
};
use contact_lab::physics::mesh::TriMesh;
use contact_lab::physics::Shape;
use nalgebra::{UnitQuaternion, Vector3};

use crate::collide_support::{check_pair, pose, FLOOR};

/// A square floor of side `size` in the plane y = 0, `n` × `n` squares of
/// two triangles each, normals +y.
pub fn grid_floor(n: usize, size: f64) -> Shape {
    let s = size / n as f64;
    let mut vertices = vec![];
    for i in 0..=n {
        for j in 0..=n {
            vertices.push([-size / 2.0 + i as f64 * s, 0.0, -size / 2.0 + j as f64 * s]);
        }
    }
    let at = |i: usize, j: usize| i * (n + 1) + j;
    let mut triangles = vec![];
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            triangles.push([a, d, c]);
            triangles.push([a, c, b]);
        }
    }
    Shape::Mesh(Arc::new(TriMesh::new(&vertices, &triangles).unwrap()))
}

fn contacts(
    a: (&Shape, &Pose<f64>),
    b: (&Shape, &Pose<f64>),
    edges: InternalEdges,
) -> Vec<ContactPoint<f64>> {
    let options = Options {
        internal_edges: edges,
        ..Options::with_mode(BoxBoxMode::Manifold)
    };
    let mut out = vec![];
    collide_with(a, b, &options, &mut out);
    out
}

fn shapes() -> Vec<Shape> {
    let hull = contact_lab::physics::detect::ConvexHull::new(&[
        [0.3, -0.2, 0.1],
        [-0.3, -0.25, 0.2],
        [0.0, -0.2, -0.35],
        [0.05, 0.4, 0.0],
    ])
    .unwrap();
    vec![
        Shape::Sphere { radius: 0.4 },
        Shape::Box {
            sides: [0.6, 0.5, 0.7],
        },
        Shape::Cylinder {
            radius: 0.3,
            height: 0.5,
        },
        Shape::Capsule {
            radius: 0.2,
            height: 0.6,
        },
        Shape::Hull(Arc::new(hull)),
    ]
}

#[test]
fn a_flat_triangulated_floor_gives_the_half_spaces_contacts() {
    let floor = grid_floor(8, 8.0);
    let plane = pose([0.0; 3], UnitQuaternion::identity());
    let turns = [
        UnitQuaternion::identity(),
        UnitQuaternion::from_euler_angles(0.2, 0.7, -0.1),
        UnitQuaternion::from_euler_angles(1.4, 0.0, 0.3),
    ];
    for shape in shapes() {
        for (t, turn) in turns.iter().enumerate() {
            // The lowest point 3 mm under the floor, over several triangles.
            let low = shape.support(&(turn.inverse() * -Vector3::y())).unwrap();
            let y = -(turn * low).y - 0.003;
            let body = pose([0.13 + 0.41 * t as f64, y, 0.37 - 0.29 * t as f64], *turn);
            let on_mesh = contacts((&shape, &body), (&floor, &plane), InternalEdges::Corrected);
            let on_plane = contacts((&shape, &body), (&FLOOR, &plane), InternalEdges::Corrected);
            let at = format!("{shape:?} turn {t}: mesh {on_mesh:?}\nplane {on_plane:?}");
            // Beside the plane's points, the mesh keeps the floor's corners
            // inside the shape (the contact region's corners): up, on y = 0,
            // at a corner of the grid.
            for m in &on_mesh {
                if on_plane.iter().all(|k| (m.point - k.point).norm() >= 1e-9) {
                    let grid = |x: f64| (x - x.round()).abs() < 1e-12;
                    assert!(
                        m.point.y == 0.0 && grid(m.point.x) && grid(m.point.z),
                        "{m:?}: {at}"
                    );
                    assert!((m.normal - Vector3::y()).norm() < 1e-9, "{at}");
                }
            }
            for k in &on_plane {
                let same = on_mesh.iter().find(|m| (m.point - k.point).norm() < 1e-9);
                let m = same.unwrap_or_else(|| panic!("no mesh contact at {:?}: {at}", k.point));
                assert!((m.normal - k.normal).norm() < 1e-9, "{at}");
                assert!((m.penetration - k.penetration).abs() < 1e-9, "{at}");
            }
            check_pair((&shape, &body), (&floor, &plane), BoxBoxMode::Manifold, 0.0);
        }
    }
}

#[test]
fn at_the_seam_of_two_coplanar_triangles_the_raw_normal_bumps_and_the_corrected_does_not() {
    // A box 1 mm into the floor whose front face has just crossed the
    // seam x = 0 (the floor's squares are 1 m): the triangle ahead overlaps
    // it by 0.5 mm along x, less than the 1 mm down.
    let floor = grid_floor(8, 8.0);
    let plane = pose([0.0; 3], UnitQuaternion::identity());
    let cube = Shape::Box { sides: [0.5; 3] };
    let body = pose([-0.2495, 0.249, 0.3], UnitQuaternion::identity());
    let raw = contacts((&cube, &body), (&floor, &plane), InternalEdges::Raw);
    let fixed = contacts((&cube, &body), (&floor, &plane), InternalEdges::Corrected);
    assert!(
        raw.iter().any(|k| k.normal.y < 0.9),
        "the raw normal of the triangle ahead is its edge's: {raw:?}"
    );
    assert!(!fixed.is_empty());
    for k in &fixed {
        assert!((k.normal - Vector3::y()).norm() < 1e-9, "{fixed:?}");
        assert!((k.penetration - 0.001).abs() < 1e-9, "{fixed:?}");
    }
}

#[test]
fn a_mesh_against_a_half_space_touches_with_its_vertices_below_it() {
    let tetra = TriMesh::new(
        &[
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ],
        &[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    )
    .unwrap();
    let mesh = Shape::Mesh(Arc::new(tetra));
    let plane = pose([0.0; 3], UnitQuaternion::identity());
    // Corner 0 and corners 1, 3 (y = 0) sunk 2 mm; corner 2 above.
    let body = pose([0.0, -0.002, 0.0], UnitQuaternion::identity());
    let out = check_pair((&mesh, &body), (&FLOOR, &plane), BoxBoxMode::Manifold, 0.0);
    assert_eq!(out.len(), 3, "{out:?}");
    assert!(out.iter().all(|k| (k.penetration - 0.002).abs() < 1e-12));
}

#[test]
fn a_ball_in_a_crease_touches_both_faces() {
    // Two faces meeting at 90° along the z axis (a V, opening upward); a
    // ball resting in it touches each along that face's normal.
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let v = TriMesh::new(
        &[
            [-1.0, 1.0, -1.0],
            [0.0, 0.0, -1.0],
            [1.0, 1.0, -1.0],
            [-1.0, 1.0, 1.0],
            [0.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
        ],
        &[[0, 3, 4], [0, 4, 1], [1, 4, 5], [1, 5, 2]],
    )
    .unwrap();
    let crease = Shape::Mesh(Arc::new(v));
    let ball = Shape::Sphere { radius: 0.5 };
    let at = pose([0.0, 0.5 / s - 0.001, 0.0], UnitQuaternion::identity());
    let plane = pose([0.0; 3], UnitQuaternion::identity());
    let out = contacts((&ball, &at), (&crease, &plane), InternalEdges::Corrected);
    assert_eq!(out.len(), 2, "{out:?}");
    for k in &out {
        assert!(
            (k.normal.y - s).abs() < 1e-9 && (k.normal.x.abs() - s).abs() < 1e-9,
            "{out:?}"
        );
        assert!((k.penetration - 0.001 * s).abs() < 1e-9, "{out:?}");
    }
}

#[test]
fn a_closed_mesh_cube_on_a_box_touches_as_a_box_does() {
    // A unit cube as a closed mesh of 12 triangles, centred, turned a
    // little, 2 mm into a wide box: the contacts keep every convention,
    // and the deepest is the box-on-box pair's.
    let c = [
        [-0.5, -0.5, -0.5],
        [0.5, -0.5, -0.5],
        [0.5, 0.5, -0.5],
        [-0.5, 0.5, -0.5],
        [-0.5, -0.5, 0.5],
        [0.5, -0.5, 0.5],
        [0.5, 0.5, 0.5],
        [-0.5, 0.5, 0.5],
    ];
    let faces = [
        [0, 3, 2, 1],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
    ];
    let triangles: Vec<[usize; 3]> = faces
        .iter()
        .flat_map(|f| [[f[0], f[1], f[2]], [f[0], f[2], f[3]]])
        .collect();
    let cube = Shape::Mesh(Arc::new(TriMesh::new(&c, &triangles).unwrap()));
    let slab = Shape::Box {
        sides: [6.0, 1.0, 6.0],
    };
    let below = pose([0.0, -0.5, 0.0], UnitQuaternion::identity());
    let turn = UnitQuaternion::from_euler_angles(0.0, 0.4, 0.0);
    let on = pose([0.1, 0.498, -0.2], turn);
    let out = check_pair((&cube, &on), (&slab, &below), BoxBoxMode::Manifold, 0.0);
    let boxed = Shape::Box { sides: [1.0; 3] };
    let reference = check_pair((&boxed, &on), (&slab, &below), BoxBoxMode::Manifold, 0.0);
    let deepest = |k: &[ContactPoint<f64>]| k.iter().map(|k| k.penetration).fold(0.0, f64::max);
    assert!(out.len() >= 4, "{out:?}");
    assert!(
        (deepest(&out) - deepest(&reference)).abs() < 1e-9,
        "{out:?}\n{reference:?}"
    );
    // Each of the cube's four bottom corners is a contact.
    for k in reference {
        assert!(
            out.iter().any(|m| (m.point - k.point).norm() < 1e-9),
            "{k:?} in {out:?}"
        );
    }
}
