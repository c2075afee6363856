//! Mesh tests: mass properties against closed forms, the checks, the OBJ
//! reader, the tree against brute force (the mid phase: query.rs).

use nalgebra::{Matrix3, Vector3};

use super::bvh::overlaps;
use super::obj;
use super::{MeshError, TriMesh};
use crate::physics::Shape;

/// A box of full sides `s` centred at `c`, 12 triangles wound outward.
pub fn box_mesh(s: [f64; 3], c: [f64; 3]) -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let mut v = Vec::new();
    for i in 0..8 {
        let sign = |bit: usize| if i & bit != 0 { 0.5 } else { -0.5 };
        v.push([
            c[0] + sign(1) * s[0],
            c[1] + sign(2) * s[1],
            c[2] + sign(4) * s[2],
        ]);
    }
    let quads = [
        [0, 2, 3, 1], // -z
        [4, 5, 7, 6], // +z
        [0, 1, 5, 4], // -y
        [2, 6, 7, 3], // +y
        [0, 4, 6, 2], // -x
        [1, 3, 7, 5], // +x
    ];
    let t = quads
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect();
    (v, t)
}

/// An icosphere of radius r subdivided `level` times.
pub fn icosphere(r: f64, level: usize) -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let mut v: Vec<Vector3<f64>> = [
        [-1.0, g, 0.0],
        [1.0, g, 0.0],
        [-1.0, -g, 0.0],
        [1.0, -g, 0.0],
        [0.0, -1.0, g],
        [0.0, 1.0, g],
        [0.0, -1.0, -g],
        [0.0, 1.0, -g],
        [g, 0.0, -1.0],
        [g, 0.0, 1.0],
        [-g, 0.0, -1.0],
        [-g, 0.0, 1.0],
    ]
    .iter()
    .map(|p| Vector3::from(*p).normalize())
    .collect();
    let mut t: Vec<[usize; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..level {
        let mut mids = std::collections::HashMap::new();
        let mut mid = |a: usize, b: usize, v: &mut Vec<Vector3<f64>>| {
            *mids.entry((a.min(b), a.max(b))).or_insert_with(|| {
                v.push(((v[a] + v[b]) / 2.0).normalize());
                v.len() - 1
            })
        };
        let mut next = Vec::new();
        for [a, b, c] in t {
            let (ab, bc, ca) = (mid(a, b, &mut v), mid(b, c, &mut v), mid(c, a, &mut v));
            next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        t = next;
    }
    (v.iter().map(|p| (p * r).into()).collect(), t)
}

/// A wavy open terrain of n × n squares, side `h`, two triangles each.
pub fn terrain(n: usize, h: f64) -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let mut v = Vec::new();
    for i in 0..=n {
        for j in 0..=n {
            let (x, z) = (i as f64 * h, j as f64 * h);
            v.push([x, 0.3 * (x * 0.7).sin() * (z * 0.5).cos(), z]);
        }
    }
    let at = |i: usize, j: usize| i * (n + 1) + j;
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..n {
            // Counter-clockwise seen from +y.
            t.push([at(i, j), at(i, j + 1), at(i + 1, j)]);
            t.push([at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)]);
        }
    }
    (v, t)
}

#[test]
fn a_twelve_triangle_box_is_the_box() {
    for (s, c) in [
        ([1.0, 2.0, 3.0], [0.0; 3]),
        ([0.2, 5.0, 0.7], [3.0, -1.0, 2.5]),
    ] {
        let (v, t) = box_mesh(s, c);
        let mesh = TriMesh::new(&v, &t).unwrap();
        assert!(mesh.is_closed());
        let mp = mesh.mass_properties().unwrap();
        let volume = s[0] * s[1] * s[2];
        assert!((mp.volume - volume).abs() < 1e-12 * volume);
        assert!((mp.centroid - Vector3::from(c)).norm() < 1e-12);
        let m = 7.0;
        let want = Shape::Box { sides: s }.inertia(m).unwrap();
        let got = mp.unit_inertia * (m / mp.volume);
        assert!((got - want).norm() < 1e-12 * want.norm(), "{got} vs {want}");
    }
}

#[test]
fn an_icosphere_converges_to_two_fifths_m_r_squared() {
    let mut last = f64::INFINITY;
    for level in 0..5 {
        let (v, t) = icosphere(2.0, level);
        let mesh = TriMesh::new(&v, &t).unwrap();
        let mp = mesh.mass_properties().unwrap();
        let per_mass = mp.unit_inertia / mp.volume / (2.0 * 2.0);
        let err = (per_mass - Matrix3::identity() * 0.4).amax();
        assert!(err < last, "level {level}: {err} not below {last}");
        assert!(mp.centroid.norm() < 1e-12);
        last = err;
    }
    assert!(last < 1e-3, "level 4 error {last}");
}

#[test]
fn bad_meshes_are_refused_with_the_triangle() {
    let (v, mut t) = box_mesh([1.0; 3], [0.0; 3]);
    t[3] = [t[3][0], t[3][2], t[3][1]];
    assert!(matches!(
        TriMesh::new(&v, &t),
        Err(MeshError::Inconsistent { .. })
    ));
    let (v, mut t) = box_mesh([1.0; 3], [0.0; 3]);
    t[5] = [0, 0, 1];
    assert_eq!(TriMesh::new(&v, &t).unwrap_err().triangle(), Some(5));
    t[5] = [0, 1, 9];
    assert!(matches!(
        TriMesh::new(&v, &t),
        Err(MeshError::OutOfRange { vertex: 9, .. })
    ));
    let line = [[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
    assert!(matches!(
        TriMesh::new(&line, &[[0, 1, 2]]),
        Err(MeshError::Degenerate { .. })
    ));
    let fan = [
        [0.0; 3],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, -1.0, 0.0],
    ];
    assert!(matches!(
        TriMesh::new(&fan, &[[0, 1, 2], [1, 0, 3], [0, 1, 4]]),
        Err(MeshError::NonManifold { .. } | MeshError::Inconsistent { .. })
    ));
    let (v, t) = box_mesh([1.0; 3], [0.0; 3]);
    let open = TriMesh::new(&v, &t[..11]).unwrap();
    assert!(!open.is_closed() && open.mass_properties().is_none());
    let inside_out: Vec<[usize; 3]> = t.iter().map(|&[a, b, c]| [a, c, b]).collect();
    assert!(TriMesh::new(&v, &inside_out)
        .unwrap()
        .mass_properties()
        .is_none());
}

#[test]
fn obj_fans_polygons_and_counts_what_it_ignores() {
    let text = "# a square\nv 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nvn 0 1 0\ng top\nf 1//1 2//1 3//1 4//1\nf -4 -2 -1\n";
    let o = obj::parse(text).unwrap();
    assert_eq!(o.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 2, 3]]);
    assert_eq!(o.triangle_at[2], (9, 1));
    assert_eq!(o.ignored, vec![("vn".to_string(), 1), ("g".to_string(), 1)]);
    let e = obj::parse("v 0 0 0\nv 1 0 0\n  f 1 2 x\n").unwrap_err();
    assert_eq!((e.line, e.column), (3, 9));
    let e = obj::parse("v 0 nan 0\n").unwrap_err();
    assert_eq!((e.line, e.column), (1, 5));
    let e = obj::parse("v 0 0 0\nf 1 2 3\n").unwrap_err();
    assert_eq!((e.line, e.column), (2, 5));
}

#[test]
fn the_tree_finds_what_brute_force_finds() {
    let (v, t) = terrain(20, 0.5);
    let mesh = TriMesh::new(&v, &t).unwrap();
    assert_eq!(mesh.bvh().nodes().len(), 2 * t.len() - 1);
    assert!(mesh.bvh().depth() <= 11, "depth {}", mesh.bvh().depth());
    for k in 0..50 {
        let x = (k as f64 * 0.37) % 10.0;
        let z = (k as f64 * 0.61) % 10.0;
        let q = [
            Vector3::new(x, -0.2, z),
            Vector3::new(x + 0.8, 0.3, z + 0.4),
        ];
        let (_, got) = mesh.bvh().traverse(&q);
        let want: Vec<usize> = (0..t.len())
            .filter(|&i| {
                let c = mesh.corners(i);
                let b = [c[0].inf(&c[1]).inf(&c[2]), c[0].sup(&c[1]).sup(&c[2])];
                overlaps(&b, &q)
            })
            .collect();
        assert_eq!(got, want);
    }
}

mod query;
